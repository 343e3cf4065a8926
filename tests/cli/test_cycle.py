"""``asperity cycle``: every route gives what the library gives; errors are one line, exit 2."""

import json

import numpy as np
import pytest

from asperity._json import json_safe
from asperity.cycle import cycle
from asperity.physical import PhysicalContact, Surface
from asperity.units import to_si

from .helpers import AU, one_line_error, rows_of, run, strict_json

#: Gold asperities this rough yield; the elastic cycle warns as every curve does (tested below).
pytestmark = pytest.mark.filterwarnings("ignore::asperity.plasticity.PlasticityWarning")

ABOVE = ["--alpha", "0.02", "--beta", "50", "--gamma", "0.02"]
P_ABOVE = (0.02, 50.0, 0.02)


def au():
    return PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6))


@pytest.mark.parametrize("dmin", ["--dmin", "--d-min"])
def test_csv_is_the_library_csv(capsys, dmin):
    code, out, _ = run(capsys, "cycle", *ABOVE, dmin, "-0.5", "--points", "7", "--format", "csv")
    assert code == 0
    assert out == cycle(*P_ABOVE, d_min=-0.5, n=7).to_csv()
    rows = rows_of(out)
    assert list(rows[0]) == ["branch", "d", "P", "F", "mu", "area", "pressure", "contacts"]
    assert [r["branch"] for r in rows] == ["approach"] * 7 + ["retract"] * 7


@pytest.mark.parametrize("dmax", ["--dmax", "--d-max"])  # pulloff's spelling too (a newcomer tried it)
def test_json_is_rows_pull_off_and_energy(capsys, dmax):
    code, out, _ = run(capsys, "cycle", *ABOVE, "--preload", "100", dmax, "6", "--points", "5",
                       "--format", "json")
    assert code == 0
    got = strict_json(out)
    res = cycle(*P_ABOVE, preload=100.0, d_max=6.0, n=5)
    assert set(got) >= {"rows", "pull_off", "energy"}
    assert got["pull_off"] == json_safe(res.to_dict()["pull_off"])
    assert got["energy"] == json_safe(res.to_dict()["energy"])
    assert [r["branch"] for r in got["rows"]] == ["approach"] * 5 + ["retract"] * 5
    np.testing.assert_array_equal([r["P"] for r in got["rows"]], np.concatenate([res.approach.P, res.retract.P]))
    assert got == json.loads(json.dumps(json_safe({"rows": got["rows"], **res.to_dict()})))


def test_spring_list_and_u_in(capsys):
    code, out, _ = run(capsys, "cycle", *ABOVE, "--preload", "100", "--stiffness", "100", "--u-in", "-0.1",
                       "--points", "60", "--format", "csv")
    assert code == 0
    assert out == cycle(*P_ABOVE, preload=100.0, stiffness=100.0, u_in=-0.1, n=60).to_csv()
    assert list(rows_of(out)[0])[:2] == ["branch", "d_base"] and "True" in out
    code, out, _ = run(capsys, "cycle", *ABOVE, "--dmin", "-0.5", "--d", "-0.5:1:4", "--format", "csv")
    assert code == 0 and out == cycle(*P_ABOVE, d_min=-0.5, d=np.linspace(-0.5, 1, 4)).to_csv()
    code, out, _ = run(capsys, "cycle", *ABOVE, "--dmin", "-0.5", "--stiffness", "inf", "--points", "4",
                       "--format", "csv")
    assert code == 0 and out == cycle(*P_ABOVE, d_min=-0.5, n=4).to_csv()


def test_table_has_the_summary(capsys):
    code, out, _ = run(capsys, "cycle", *ABOVE, "--dmin", "-0.5", "--points", "3", "--format", "table")
    res = cycle(*P_ABOVE, d_min=-0.5, n=3)
    assert code == 0 and "pull_off: force=" in out and f"energy={res.energy:.6g}" in out


def m(text):
    return to_si(text, "m", "length")


@pytest.mark.parametrize("argv, kwargs", [
    (["--preload", "1mN", "--points", "6"], {"preload": "1mN", "n": 6}),
    (["--preload", "1000uN", "--stiffness", "2000N/m", "--points", "30"],
     {"preload": "1000uN", "stiffness": 2e3, "n": 30}),
    (["--dmin", "2nm", "--dmax", "30nm", "--points", "6"], {"d_min": "2nm", "d_max": "30nm", "n": 6}),
    (["--dmin", "2nm", "--d", "2nm:10nm:5"], {"d_min": "2nm", "d": np.linspace(m("2nm"), m("10nm"), 5)}),
    (["--dmin", "2nm", "--d", "2nm,3nm", "--u-in", "-0.01nm"],
     {"d_min": "2nm", "d": ["2nm", "3nm"], "u_in": "-0.01nm"}),
])
def test_physical_routes_equal_the_library(capsys, argv, kwargs):
    code, out, _ = run(capsys, "cycle", *AU, *argv, "--format", "csv")
    assert code == 0, out
    contact = au()
    expected = contact.cycle(**kwargs).to_csv()
    # the contact computed, as the library states it, above the rows
    assert out == "".join(f"# {line}\n" for line in contact.describe().splitlines()) + expected
    assert list(rows_of(out)[0])[-1] in ("contacts", "jump")
    code, out, _ = run(capsys, "cycle", *AU, *argv, "--format", "csv", "--no-comments")
    assert code == 0 and out == expected


@pytest.mark.parametrize("spelling", ["inf", "Inf", "infinity", "+inf", "infN/m", "inf N/m", "inf nN/nm", " inf "])
def test_physical_infinite_stiffness_is_displacement_control_in_every_spelling(capsys, spelling):
    """Found by a user trial: the help says '--stiffness ... default inf (displacement control)',
    but with a physical contact 'inf' was refused for lacking a unit and 'infN/m' as not finite
    (only 'inf N/m' worked)."""
    code, out, err = run(capsys, "cycle", *AU, "--preload", "1mN", "--points", "4", "--stiffness", spelling,
                         "--format", "csv", "--no-comments")
    assert code == 0, err
    assert out == au().cycle(preload=1e-3, n=4).to_csv() == au().cycle(preload=1e-3, n=4, stiffness=np.inf).to_csv()


@pytest.mark.parametrize("spelling, needle", [("infkg", "'kg' is not a unit compatible with N/m"),
                                              ("infx", "'x' is not a unit compatible with N/m"),
                                              ("-inf", "--stiffness")])
def test_physical_infinite_stiffness_with_a_wrong_unit_is_one_line(capsys, spelling, needle):
    code, out, err = run(capsys, "cycle", *AU, "--preload", "1mN", "--stiffness", spelling)
    assert one_line_error(code, err, needle) and out == ""


def test_physical_json(capsys):
    code, out, _ = run(capsys, "cycle", *AU, "--preload", "1mN", "--points", "4", "--format", "json")
    got = strict_json(out)
    res = au().cycle(preload=1e-3, n=4)
    assert code == 0 and got["energy"]["energy_J"] == res.energy_J and got["pull_off"]["force_N"] == res.pull_off.force
    assert "P_N" in got["rows"][0]
    assert got["contact"] == strict_json(json.dumps(au().to_dict()))


def test_plastic_cycle_equals_the_library_and_says_it_has_no_unloading(capsys):
    from asperity import AsperityWarning

    argv = ["--material", "Au", "--sigma-s", "2nm", "--R", "100nm", "--eta", "2e14/m^2", "--area", "1um^2"]
    code, out, err = run(capsys, "cycle", *argv, "--preload", "5uN", "--points", "12", "--law", "jackson-green",
                         "--no-adhesion", "--format", "json")
    got = strict_json(out)
    contact = PhysicalContact("Au", Surface(2e-9, 100e-9, 2e14, 1e-12), plasticity="jackson-green", adhesion=False)
    with pytest.warns(AsperityWarning, match="no unloading"):
        res = contact.cycle(preload=5e-6, n=12)
    assert code == 0 and "asperity: note: the jackson-green law has no unloading" in err
    assert [r["plastic"] for r in got["rows"]] == [float(x) for b in (res.approach, res.retract) for x in b.plastic]


def test_plot(capsys, tmp_path):
    png = tmp_path / "cycle.png"
    code, _, _ = run(capsys, "cycle", *ABOVE, "--preload", "100", "--stiffness", "100", "--points", "80",
                     "--plot", str(png), "-o", str(tmp_path / "c.csv"))
    assert code == 0 and png.read_bytes()[:4] == b"\x89PNG"
    code, _, _ = run(capsys, "cycle", *AU, "--preload", "1mN", "--points", "20", "--plot", str(tmp_path / "au.png"),
                     "-o", str(tmp_path / "au.csv"))
    assert code == 0 and (tmp_path / "au.png").exists()


@pytest.mark.parametrize("argv, needle", [
    (["cycle", *ABOVE, "--points", "5"], "exactly one of --dmin (the closest approach) and --preload"),
    (["cycle", *ABOVE, "--dmin", "1", "--preload", "5"], "exactly one of --dmin"),
    (["cycle", *AU, "--points", "5"], "exactly one of --dmin"),
    (["cycle", *ABOVE, "--dmin", "3", "--dmax", "2"], "d_min"),
    (["cycle", *ABOVE, "--dmin", "0", "--stiffness", "-1"], "stiffness"),
    (["cycle", *ABOVE, "--preload", "-5"], "preload"),
    (["cycle", *ABOVE, "--preload", "1e300"], "preload"),
    (["cycle", *ABOVE, "--dmin", "2nm"], "--dmin"),
    (["cycle", *ABOVE, "--dmin", "0", "--d", "1,,2"], "--d"),
    (["cycle", *ABOVE, "--dmin", "0", "--d", "1", "--stiffness", "10"], "give --points instead of --d"),
    (["cycle", *AU, "--dmin", "0nm", "--d", "1nm", "--stiffness", "10N/m"], "give --points instead of --d"),
    (["cycle", "--alpha", "0.02", "--beta", "50", "--dmin", "0"], "--gamma"),
    (["cycle", *AU, "--preload", "-1mN"], "preload"),
    (["cycle", *AU, "--preload", "1mN", "--stiffness", "-0.1N/m"], "stiffness"),
    (["cycle", *AU, "--dmin", "2"], "--dmin"),
])
def test_errors_are_one_line(capsys, argv, needle):
    code, out, err = run(capsys, *argv)
    assert one_line_error(code, err, needle), err
    assert out == ""


def test_help_explains_every_option(capsys):
    from asperity.cli import main

    with pytest.raises(SystemExit) as exc:
        main(["cycle", "--help"])
    assert exc.value.code == 0
    out = " ".join(capsys.readouterr().out.split())
    for word in ("--dmin", "--preload", "--dmax", "--stiffness", "--u-in", "--d", "--points", "--plot", "branch",
                 "N/m", "displacement control", "energy", "pull_off", "d_base", "jump"):
        assert word in out, word
