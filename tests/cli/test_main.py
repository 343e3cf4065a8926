"""``asperity.cli``: the parser, main's error contract, the entry point and start-up cost."""

import os
import subprocess
import sys
import textwrap

import pytest

import asperity
from asperity.cli import COMMANDS, build_parser, main

from .helpers import AU, MODEL, one_line_error, rows_of, run


@pytest.mark.parametrize("argv, needle", [
    (["load", "--alpha", "-1", "--beta", "10", "--P", "1"], "alpha"),
    (["load", "--alpha", "0.01", "--beta", "10", "--P", "0,1"], "P"),
    (["load", "--alpha", "0.01", "--beta", "10", "--P", "a,b"], "--P"),
    (["load", "--alpha", "0.01", "--beta", "10", "--P", "0:1:5"], "--P"),
    (["separation", "--alpha", "0.01", "--beta", "10", "--d", "0,nan"], "--d"),
    (["separation", "--alpha", "0.01", "--beta", "10", "--nu", "0.7", "--d", "0"], "nu"),
    (["separation", "--alpha", "0.01", "--beta", "10", "--d", "0", "--bogus"], "bogus"),
    (["pulloff", "--alpha", "0.01", "--beta", "10"], "gamma"),
    (["md", "--lam", "-1", "--pulloff"], "lam"),
    (["md", "--lam", "1", "--delta", "-5"], "delta"),
    (["separation", "--alpha", "x", "--beta", "10", "--d", "0"], "alpha"),
    (["separation", "--alpha", "0.01", "--beta", "10", "--d", "0", "-o", "/nonexistent/dir/f"],
     "does not exist"),
    (["nosuchcommand"], "nosuchcommand"),
])
def test_errors_one_line_status_2(capsys, argv, needle):
    code, out, err = run(capsys, *argv)
    assert code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("asperity: error:") and needle in lines[0]
    assert "Traceback" not in err


def test_help_explains_every_parameter(capsys):
    for cmd in ("separation", "load", "pulloff", "md", "reproduce"):
        with pytest.raises(SystemExit) as exc:
            main([cmd, "--help"])
        assert exc.value.code == 0
        out = " ".join(capsys.readouterr().out.split())
        for word in {"separation": ["--alpha", "--beta", "--gamma", "--nu", "--h-over-b",
                                    "linearly", "N G b^2"],
                     "load": ["logarithmically", "--plot", "contacts"],
                     "pulloff": ["--d-max"], "md": ["--lam", "--delta", "--pulloff"],
                     "reproduce": ["--out"]}[cmd]:
            assert word in out, (cmd, word)


def test_every_command_module_is_registered():
    # The registry is the parser: one subcommand per module, each with the module's interface.
    parser = build_parser()
    sub = next(a for a in parser._actions if a.dest == "command")
    assert list(sub.choices) == list(COMMANDS)
    assert set(COMMANDS) == {"reproduce", "separation", "load", "pulloff", "cycle", "surface", "materials", "md",
                             "bem", "explore", "sweep", "plot", "fit"}
    for name, module in COMMANDS.items():
        assert module.NAME == name and module.HELP and callable(module.add_arguments) and callable(module.run)


def test_no_command_prints_help(capsys):
    code, out, _ = run(capsys)
    assert code == 2 and "COMMAND" in out


def test_subprocess_entry_point(tmp_path):
    version = subprocess.run([sys.executable, "-m", "asperity.cli", "--version"],
                             capture_output=True, text=True, check=True)
    assert version.stdout.strip() == f"asperity {asperity.__version__}"
    res = subprocess.run([sys.executable, "-m", "asperity.cli", "load", *MODEL, "--P", "10"],
                         capture_output=True, text=True, check=True)
    row = rows_of(res.stdout)[0]  # not a terminal: CSV by default
    assert float(row["P"]) == 10.0
    bad = subprocess.run([sys.executable, "-m", "asperity.cli", "load", "--alpha", "0",
                          "--beta", "1", "--P", "1"], capture_output=True, text=True)
    assert bad.returncode == 2 and bad.stderr.count("\n") == 1 and "Traceback" not in bad.stderr


HEAVY = ("numpy", "scipy", "matplotlib", "pint", "SurfaceTopography", "pandas")


@pytest.mark.parametrize("code", [
    "import asperity",
    "import asperity.cli",
    "from asperity.cli import main\ntry:\n    main(['--version'])\nexcept SystemExit:\n    pass",
    "from asperity.cli import main\nfor cmd in ([], ['load'], ['surface'], ['md'], ['reproduce']):\n"
    "    try:\n        main([*cmd, '--help'])\n    except SystemExit:\n        pass",
])
def test_startup_imports_no_numerics(code):
    # --help and --version must not pay for NumPy/SciPy/matplotlib (well under 0.3 s).
    probe = code + textwrap.dedent(f"""
        import sys
        print(sorted(m for m in sys.modules if m.split('.')[0] in {HEAVY!r}))
    """)
    res = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True)
    assert res.stdout.strip().splitlines()[-1] == "[]", res.stdout


@pytest.mark.parametrize("argv, module, extra", [
    (["load", *MODEL, "--P", "1", "--plot", "{tmp}/c.png"], "matplotlib", "plot"),
    (["reproduce", "--out", "{tmp}/paper"], "matplotlib", "plot"),
    (["load", *AU, "--load", "1mN"], "pint", "units"),
    (["surface", "{tmp}/scan.x3p"], "SurfaceTopography", "topography"),
    (["sweep", *MODEL, "--P", "1", "--out", "{tmp}/m.nc"], "xarray", "sweep"),
    (["sweep", *MODEL, "--P", "1", "--out", "{tmp}/m.nc", "--scheduler", "serial"], "netCDF4", "sweep"),
    (["plot", "{tmp}", "--x", "alpha", "--y", "gamma", "--z", "mu"], "xarray", "sweep"),
])
def test_missing_optional_dependency_is_one_line(capsys, monkeypatch, tmp_path, argv, module, extra):
    monkeypatch.setitem(sys.modules, module, None)  # makes "import module" fail
    code, out, err = run(capsys, *(a.replace("{tmp}", str(tmp_path)) for a in argv))
    assert one_line_error(code, err, f"needs {module}: pip install 'asperity[{extra}]'")
    assert out == "" and list(tmp_path.iterdir()) == []


def test_library_warnings_become_one_note_line_each(capsys):
    """Every command prints the library's warnings (AsperityWarning) as notes, once each; others pass on."""
    import warnings

    from asperity import AsperityWarning, PlasticityWarning
    from asperity.cli import run_with_notes

    def run(args):
        warnings.warn(PlasticityWarning("yielded"), stacklevel=1)
        warnings.warn(PlasticityWarning("yielded"), stacklevel=1)
        warnings.warn(AsperityWarning("other note"), stacklevel=1)

    run_with_notes(run, None)
    err = capsys.readouterr().err.splitlines()
    assert err == ["asperity: note: yielded", "asperity: note: other note"]

    def foreign(args):
        warnings.warn("not ours", RuntimeWarning, stacklevel=1)

    with pytest.raises(RuntimeWarning, match="not ours"):  # filterwarnings=error still applies to others
        run_with_notes(foreign, None)


def test_sigterm_interrupts_like_ctrl_c(tmp_path):
    """Found by a review: SIGTERM ended a sweep with Python's default (no line of ours; on a local
    cluster a 'leaked semaphore' warning).  It now unwinds as Ctrl-C does: one line, status 143,
    and the partial store resumes."""
    import os
    import signal
    import time
    from pathlib import Path

    import asperity

    out = tmp_path / "map.nc"
    env = {**os.environ, "PYTHONPATH": str(Path(asperity.__file__).parents[1])}
    argv = [sys.executable, "-m", "asperity.cli", "sweep", "--alpha", "1e-3:0.1:60", "--beta", "1000", "--gamma",
            "1e-5:1e-2:60", "--P", "1e-2:1e3:20", "--out", str(out), "--scheduler", "serial", "--chunk-sets", "50"]
    proc = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    partial = Path(str(out) + ".partial")
    deadline = time.monotonic() + 60
    while not partial.exists() and time.monotonic() < deadline and proc.poll() is None:
        time.sleep(0.05)
    time.sleep(0.5)
    proc.send_signal(signal.SIGTERM)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == 143 and err.strip().splitlines()[-1] == "asperity: interrupted (SIGTERM)", err
    assert partial.exists() and not out.exists()
    done = subprocess.run(argv + ["--resume"], capture_output=True, text=True, env=env, timeout=300)
    assert done.returncode == 0 and out.exists() and not partial.exists(), done.stderr


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="no /dev/full on this system")
def test_standard_output_full_or_closed_is_one_line_not_a_traceback(tmp_path):
    """A CLI check: '> /dev/full' and a reader that leaves ('| true') ended in Python tracebacks
    with status 1.  Now a full output is one error line (status 2) and a closed pipe ends
    quietly (141, as a shell tool killed by SIGPIPE)."""
    argv = [sys.executable, "-m", "asperity.cli", "load", *MODEL, "--P", "1:1e5:20000", "--format", "csv"]
    with open("/dev/full", "w") as full:
        res = subprocess.run(argv, stdout=full, stderr=subprocess.PIPE, text=True)
    assert res.returncode == 2 and res.stderr == ("asperity: error: cannot write to standard output: No space left "
                                                  "on device\n"), res.stderr
    proc = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    proc.stdout.close()  # the reader leaves before the first byte
    _, err = proc.communicate()
    assert proc.returncode == 141 and err == "", err


class _Failing:
    """A standard output whose writes fail with ``error``."""

    def __init__(self, error):
        self.error = error

    def write(self, text):
        raise self.error

    def flush(self):
        pass


def test_only_writes_to_standard_output_are_judged_as_such(monkeypatch, capsys):
    """A review: a catch-all OSError handler called any OSError (a Dask comm, a worker's
    directory) 'cannot write the output', and a BrokenPipeError from anywhere ended quietly.
    Now only standard output's own failures are so reported; in a caller's process its
    standard output is left as it is."""
    from asperity.cli import load

    argv = ["load", *MODEL, "--P", "10", "--format", "csv"]
    monkeypatch.setattr(sys, "stdout", _Failing(BrokenPipeError()))
    assert main(argv) == 141
    monkeypatch.setattr(sys, "stdout", _Failing(OSError(28, "No space left on device")))
    assert main(argv) == 2
    monkeypatch.undo()
    assert capsys.readouterr().err == "asperity: error: cannot write to standard output: No space left on device\n"

    def boom(args):
        raise ConnectionResetError(104, "a worker's connection")

    monkeypatch.setattr(load, "run", boom)
    with pytest.raises(ConnectionResetError):
        main(argv)
