"""Property-based fuzzing of the command line: every command line ends in status 0 or 2, cleanly.

Command lines are built from each command's own options, read from the parser (so an
option added later is fuzzed too: it needs valid values in :data:`VALID` or the coverage
test fails): a valid base command line, then one to three options set to a valid value, an
invalid value or removed.  The contract:

* exit status 0 or 2, never a traceback (an exception escaping :func:`asperity.cli.main`
  fails the test, as does any Python warning: pytest turns them into errors);
* status 2: exactly one stderr line, ``asperity: error: ...``, and nothing on stdout;
* status 0: every stderr line is an ``asperity: note: ...``; JSON output is strict (no NaN
  or Infinity) and CSV output has a header and rows.

Twenty command lines per command by default, the same on every run (``ASPERITY_FUZZ_RANDOM=1``
draws new ones); ``ASPERITY_FUZZ_EXAMPLES=N`` draws N.
``asperity reproduce`` is left out (a valid run takes seconds; its bad values are tested in
tests/cli/test_args.py), and so is ``--plot`` (drawing; tests/cli/test_plot.py).  A few
options keep their base value (:data:`FIXED`): those that start worker processes, wait
for a network address or print a progress report.  ``asperity explore`` runs with its
server stopped as soon as it has started and without a browser (:func:`_no_serving`).
"""

from __future__ import annotations

import argparse
import functools
import os

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from asperity.cli import build_parser

from .helpers import rows_of, run, strict_json

pytest.importorskip("pint")

#: Options never fuzzed, with the reason.
SKIPPED_OPTIONS = {"help": "prints the help", "plot": "draws a figure (tests/cli/test_plot.py)",
                   "version": "prints the version"}
SKIPPED_COMMANDS = {"reproduce": "a valid run takes seconds; its bad values are in tests/cli/test_args.py"}
#: command -> {dest: value} options never changed nor removed (value None: a flag kept), with the reason.
FIXED = {
    "sweep": {"scheduler": "serial"},  # 'local' starts worker processes, an address waits for a scheduler
    "bem": {"quiet": None},  # without it the progress report is on stderr (tests/cli/test_bem.py)
}


@functools.cache
def _files(tmp: str) -> dict[str, str]:
    """A small scan (heights in nm, no size stored), a directory, an empty and a missing file."""
    from SurfaceTopography.Generation import fourier_synthesis

    topo = fourier_synthesis((48, 48), (2e-6, 2e-6), 0.8, rms_height=5e-9, short_cutoff=0.2e-6, long_cutoff=1e-6,
                             rng=np.random.default_rng(5))
    scan = os.path.join(tmp, "scan.npy")
    np.save(scan, topo.heights() * 1e9)
    empty = os.path.join(tmp, "empty.txt")
    open(empty, "w").close()
    friction = os.path.join(tmp, "friction.csv")  # friction F against load P (dimensionless)
    with open(friction, "w") as fh:
        fh.write("P,F\n" + "".join(f"{p},{0.3 * (p + 1.0)}\n" for p in np.linspace(0.5, 5.0, 8).tolist()))
    summits = os.path.join(tmp, "summits.txt")  # measured summit heights in metres, one per line
    np.savetxt(summits, 2e-9 * np.random.default_rng(3).standard_normal(300) ** 2)
    sets = os.path.join(tmp, "sets.csv")
    with open(sets, "w") as fh:
        fh.write("alpha,beta,gamma\n0.01,1000,0.001\n0.003,1000,0\n")
    from asperity.sweeps import sweep

    store = os.path.join(tmp, "map.nc")
    sweep(alpha=[0.003, 0.01], beta=1000.0, gamma=[0.0, 1e-3], P=[1.0, 10.0], scheduler="serial",
          out=store).close()
    return {"scan": scan, "dir": tmp, "empty": empty, "missing": os.path.join(tmp, "missing.npy"),
            "out": os.path.join(tmp, "out.txt"), "friction": friction, "sets": sets, "store": store, "summits": summits}


def valid_values(tmp: str) -> dict[str, list[str]]:
    """``dest`` -> valid values (texts) for every option of every fuzzed command."""
    f = _files(tmp)
    return {
        "alpha": ["0.01", "0.003"], "beta": ["1000", "300"], "gamma": ["1e-3", "0"], "nu": ["0.3", "0.44"],
        "h_over_b": ["1", "2"], "material": ["Au", "Au/Au", "Si", "Au/Si"], "E": ["70GPa"], "material2": ["Si", "Au"],
        "E2": ["160GPa"], "nu2": ["0.22"], "b": ["0.25nm", "2.885Å"], "w": ["0.1J/m^2", "50mJ/m^2"], "h": ["0.3nm"],
        "sigma0": ["1GPa"], "no_adhesion": [None], "sigma_s": ["2nm", "0.002um"], "rms": ["5nm"], "alpha_n": ["10"],
        "R": ["1um"], "eta": ["1e12/m^2", "1/um^2"], "area": ["1mm^2"], "surface": [f["scan"]], "size": ["2um,2um"],
        "unit": ["nm"], "method": ["spectral", "detected"], "tau": ["50MPa"], "tau_f1": ["0.02"],
        "tau_f2": ["0.001"], "a1": ["30"], "a2": ["1e5"], "no_comments": [None], "P": ["1,10", "1:1e3:4"],
        "load": ["1mN,10mN", "1mN:1N:4"], "d": ["0,1,2", "-1:3:5"], "separation": ["0nm,2nm", "-1nm:3nm:4"],
        "d_max": ["5", "8"], "lam": ["1", "0.5"], "delta": ["0,1", "-0.5:1:4"], "pulloff": [None],
        "format": ["json", "csv", "table"], "output": [f["out"]], "sources": [None], "file": [f["scan"]],
        "fill_undefined": [None],
        # plasticity (every physical command): dimensionless H/E* and h*/sigma, or with units
        "law": ["elastic", "jackson-green"], "hardness": ["0.005", "1GPa"], "h_star": ["0.4", "1.6um"],
        "size_effect": [None], "plastic_threshold": ["0.01", "0.2"],
        # cycle (dimensionless, or with units for a physical contact)
        "dmin": ["0", "-0.5", "0.5nm"], "preload": ["10", "5mN"], "dmax": ["8", "10nm"],
        "stiffness": ["10", "1e4N/m"], "u_in": ["0", "0.5"], "points": ["20", "40"],
        # fit
        "data": [f["friction"]], "model": ["amontons", "cos"], "compare": ["amontons,cos"], "vary": ["mu0"],
        "fix": ["P0=0"], "start": ["mu0=0.5"], "bounds": ["mu0=0:2", "mu0=:"], "shared": ["mu0"],
        "weights": ["auto", "none", "relative"], "loss": ["linear", "soft_l1", "huber"],
        "ci": ["auto", "wald", "profile"], "kind": ["friction"], "load_unit": ["nN", "N"],
        "friction_unit": ["nN"], "separation_unit": ["nm"], "drop_nan": [None],
        # bem
        "grid": ["16", "24"], "periodic": [None], "interaction": ["none", "cgp2008"], "quiet": [None],
        "tolerance": ["1e-4", "1e-5"], "maxiter": ["10000", "5000"],
        # sweep and plot
        "out": [os.path.join(tmp, "sweep.nc")], "resume": [None], "scheduler": ["serial"],
        "chunk_sets": ["1", "64"], "progress": [None], "store": [f["store"]], "x": ["alpha", "gamma"],
        "y": ["gamma", "alpha"], "z": ["pull_off", "mu"], "at": ["P=10", "P=1"],
        # summit heights (every model and physical command), fit restarts, surface summits
        "heights": ["gaussian", "weibull:skew=0.5", "exponential", f"empirical:{f['summits']}",
                    f"best:{f['summits']}"],
        "restarts": ["auto", "never"], "profile_budget": ["5", "inf", "1e-9"],
        "summits": [os.path.join(tmp, "summits_out.txt")],
        # explore (served and stopped at once: _no_serving)
        "port": ["0"], "host": ["127.0.0.1"], "no_browser": [None],
    }


#: command -> {dest: valid values} where a command's option takes other values than the same dest elsewhere.
def command_values(tmp: str) -> dict[str, dict[str, list[str]]]:
    f = _files(tmp)
    return {"sweep": {"points": [f["sets"]], "material": ["Au", "Au,Si"], "sigma_s": ["2nm", "1nm,2nm"],
                      "alpha": ["0.01", "0.003,0.01"], "gamma": ["1e-3", "0,1e-3"]},
            "fit": {"format": ["json", "table"]},
            "bem": {"load": ["1mN,10mN", "1mN:10mN:3"], "model": ["gw", "gw,persson,bgt", "icha"]},
            "plot": {"output": [os.path.join(tmp, "map.png")]}}


def values_for(tmp: str, command: str) -> dict[str, list[str]]:
    return {**valid_values(tmp), **command_values(tmp).get(command, {})}


def invalid_values(tmp: str) -> list[str]:
    """Texts no option accepts as they stand (each may still be valid for a few: the contract holds anyway)."""
    f = _files(tmp)
    return ["", " ", "nan", "inf", "-inf", "-1", "0", "abc", "1e400", "-1e400", "0,,1", "1,", ",1", "1:2", "1:2:0",
            "1:2:-3", "1:2:x", "1:2:2000000", "2nm", "1N", "1 GPa/m", "1e-400", "1/0", "2**2000", "(1", "\x01",
            "1e12/m^2", "1J", "NaN nm", "1e308GPa", "-5nm", "10 parsec", "1.5.2", "0x10", "Au/Au/Au", "Xx",
            f["dir"], f["empty"], f["missing"], "--", "-1nm:-2nm:3", "1mN:-1N:3", "0N:1N:3"]


def commands() -> dict[str, argparse.ArgumentParser]:
    parser = build_parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    return {name: p for name, p in sub.choices.items() if name not in SKIPPED_COMMANDS}


def options(parser: argparse.ArgumentParser) -> dict[str, argparse.Action]:
    """``dest`` -> action for every fuzzed option of a command (positional arguments too)."""
    return {a.dest: a for a in parser._actions if a.dest not in SKIPPED_OPTIONS}


#: A valid base command line per command (texts; fuzzing changes some of its options).
PHYSICAL = ["--material", "Au", "--sigma-s", "2nm", "--R", "1um", "--eta", "1e12/m^2", "--area", "1mm^2"]
MODEL = ["--alpha", "0.01", "--beta", "1000", "--gamma", "1e-3"]


def bases(tmp: str) -> dict[str, list[list[str]]]:
    f = _files(tmp)
    scan = f["scan"]
    return {
        "load": [[*MODEL, "--P", "1,10"], [*PHYSICAL, "--load", "1mN,10mN"]],
        "separation": [[*MODEL, "--d", "0,1"], [*PHYSICAL, "--separation", "0nm,2nm"]],
        "pulloff": [[*MODEL], [*PHYSICAL, "--no-adhesion"]],
        "md": [["--lam", "1", "--delta", "0,1"], ["--lam", "1", "--pulloff"]],
        "surface": [[scan, "--size", "2um,2um", "--unit", "nm"]],
        "materials": [[]],
        "cycle": [[*MODEL, "--preload", "10", "--points", "20"], [*PHYSICAL, "--preload", "5mN", "--points", "20"]],
        "fit": [[f["friction"], "--model", "amontons"], [f["friction"], "--model", "cos", "--format", "json"]],
        "bem": [[scan, "--size", "2um,2um", "--unit", "nm", "--material", "Au", "--load", "1mN,10mN", "--grid",
                 "16", "--quiet"]],
        "sweep": [["--alpha", "0.003,0.01", "--beta", "1000", "--gamma", "1e-3", "--P", "1,10", "--out",
                   os.path.join(tmp, "sweep.nc"), "--scheduler", "serial"],
                  ["--material", "Au", "--sigma-s", "1nm,2nm", "--R", "1um", "--eta", "1e12/m^2", "--area", "1mm^2",
                   "--load", "1mN,10mN", "--out", os.path.join(tmp, "physical.nc"), "--scheduler", "serial"]],
        "plot": [[f["store"], "--x", "alpha", "--y", "gamma", "--z", "pull_off"],
                 [f["store"], "--x", "gamma", "--y", "alpha", "--z", "mu", "--at", "P=10"]],
        "explore": [["--no-browser", "--port", "0"]],
    }


def _as_dict(argv: list[str], acts: dict[str, argparse.Action]) -> dict[str, str | None]:
    """A base command line as dest -> value (None for flags); positional first."""
    by_flag = {flag: a for a in acts.values() for flag in a.option_strings}
    out, i = {}, 0
    while i < len(argv):
        action = by_flag.get(argv[i])
        if action is None:  # a positional argument
            out[next(d for d, a in acts.items() if not a.option_strings)] = argv[i]
            i += 1
        elif action.nargs == 0:
            out[action.dest] = None
            i += 1
        else:
            out[action.dest] = argv[i + 1]
            i += 2
    return out


def _argv(command: str, values: dict[str, str | None], acts: dict[str, argparse.Action]) -> list[str]:
    argv = [command]
    for dest, value in values.items():
        action = acts[dest]
        if not action.option_strings:
            argv.append(value)
        elif action.nargs == 0:
            argv.append(action.option_strings[-1])
        else:
            argv += [action.option_strings[0], value]
    return argv


#: Examples per test (ASPERITY_FUZZ_EXAMPLES overrides).
#: The same examples on every run (a suite that passes keeps passing); ASPERITY_FUZZ_RANDOM=1 draws new ones.
DERANDOMIZE = not os.environ.get("ASPERITY_FUZZ_RANDOM")
EXAMPLES = int(os.environ.get("ASPERITY_FUZZ_EXAMPLES", 20))


@pytest.fixture(scope="module")
def tmp(tmp_path_factory):
    pytest.importorskip("SurfaceTopography")
    return str(tmp_path_factory.mktemp("cli-fuzz"))


def test_every_option_has_valid_values(tmp):
    missing = [f"{name} {dest}" for name, parser in commands().items() for dest in options(parser)
               if dest not in values_for(tmp, name)]
    assert not missing, f"add valid values to valid_values() in tests/cli/test_fuzz_cli.py for: {missing}"
    assert set(bases(tmp)) == set(commands()), "add a valid base command line for each command to bases()"


@pytest.mark.parametrize("command", sorted(set(commands())))
@settings(max_examples=EXAMPLES, deadline=None, derandomize=DERANDOMIZE,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(data=st.data())
def test_command_lines_end_cleanly(capsys, monkeypatch, tmp, command, data):
    monkeypatch.chdir(tmp)  # -o with a strange (valid) name writes a file here, not in the clone
    if command == "explore":
        _no_serving(monkeypatch)
    parser = commands()[command]
    acts = options(parser)
    fixed = FIXED.get(command, {})
    values = _as_dict(data.draw(st.sampled_from(bases(tmp)[command]), label="base"), acts)
    valid, invalid = values_for(tmp, command), invalid_values(tmp)
    for _ in range(data.draw(st.integers(1, 3), label="changes")):
        dest = data.draw(st.sampled_from(sorted(set(acts) - set(fixed))), label="option")
        if acts[dest].nargs == 0:
            change = data.draw(st.sampled_from(["add", "remove"]), label=dest)
            if change == "add":
                values[dest] = None
            else:
                values.pop(dest, None)
            continue
        change = data.draw(st.sampled_from(["valid", "invalid", "remove"] if acts[dest].option_strings
                                           else ["valid", "invalid"]), label=dest)
        if change == "remove":
            values.pop(dest, None)
        else:
            values[dest] = data.draw(st.sampled_from(valid[dest] if change == "valid" else invalid), label=dest)
    values.update(fixed)
    if command == "sweep":  # each example a new sweep (an existing file of other arguments is refused)
        for name in ("sweep.nc", "physical.nc"):
            if os.path.exists(os.path.join(tmp, name)):
                os.remove(os.path.join(tmp, name))
    argv = _argv(command, values, acts)
    code, out, err = run(capsys, *argv)
    lines = err.strip().splitlines()
    assert "Traceback" not in err, (argv, err)
    assert code in (0, 2), (argv, code, err)
    if code == 2:
        assert len(lines) == 1 and lines[0].startswith("asperity: error: "), (argv, err)
        assert out == "", (argv, out)
        return
    assert all(line.startswith("asperity: note: ") for line in lines), (argv, err)
    if "format" not in acts:  # sweep, plot, explore write files or serve: a line saying so
        assert out.strip(), (argv, out)
        return
    if "output" in values:
        with open(values["output"], encoding="utf-8") as fh:
            out = fh.read()
    fmt = values.get("format", acts["format"].default or ("json" if command == "surface" else "csv"))
    if fmt == "json":
        strict_json(out)
    elif fmt == "csv":
        assert rows_of(out) or command == "materials", (argv, out)


def _no_serving(monkeypatch) -> None:
    """``asperity explore`` without a browser, stopping its server as soon as it has started."""
    pytest.importorskip("bokeh")
    import webbrowser

    from asperity.explorer import server

    start = server.start_server

    def start_and_stop(port, host):
        started = start(port, host)
        started.io_loop.add_callback(started.io_loop.stop)
        return started

    monkeypatch.setattr(server, "start_server", start_and_stop)
    monkeypatch.setattr(server, "_warm_up", lambda: None)
    monkeypatch.setattr(webbrowser, "open", lambda url: True)
