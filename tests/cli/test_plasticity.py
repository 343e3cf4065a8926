"""``--law``, ``--hardness``, ``--h-star``, ``--size-effect``, ``--plastic-threshold``: CLI against the API."""

import warnings

import numpy as np
import pytest

from asperity import JacksonGreen, Model
from asperity.physical import PhysicalContact, Surface

from .helpers import AU, comment_lines, one_line_error, rows_of, run

DIMLESS = ["--alpha", "0.05", "--beta", "1000"]
CU = ["--material", "Cu", "--sigma", "2nm", "--radius", "1um", "--density", "1e12/m^2", "--area", "1mm^2"]
SURFACE = Surface(2e-9, 1e-6, 1e12, 1e-6)


def quiet(call):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", category=UserWarning)
        return call()


@pytest.mark.parametrize("command, option, values, kw", [
    ("load", "--P", "1:1e4:4", "load_curve"), ("separation", "--d", "-1,0.5,2", "separation_curve")])
@pytest.mark.parametrize("extra, law", [
    (["--law", "jackson-green", "--hardness", "0.005"], JacksonGreen(0.005)),
    (["--law", "Jackson-Green", "--hardness", "5e-3", "--h-star", "0.4"], JacksonGreen(0.005, 0.4)),
])
def test_dimensionless_law_is_the_library(capsys, command, option, values, kw, extra, law):
    code, out, err = run(capsys, command, *DIMLESS, *extra, option, values, "--format", "csv")
    assert code == 0 and err == ""
    x = np.geomspace(1, 1e4, 4) if command == "load" else [-1, 0.5, 2]
    assert out == getattr(Model(0.05, 1000.0, law=law), kw)(x).to_csv()
    assert list(rows_of(out)[0])[-1] == "plastic"


def test_elastic_is_the_default(capsys):
    code, out, _ = run(capsys, "load", *DIMLESS, "--law", "elastic", "--P", "1,10", "--format", "csv")
    assert code == 0 and out == Model(0.05, 1000.0).load_curve([1, 10]).to_csv()


@pytest.mark.parametrize("extra, kwargs", [
    (["--law", "jackson-green"], {"plasticity": "jackson-green"}),
    (["--law", "jackson-green", "--hardness", "0.3GPa"], {"plasticity": "jackson-green", "hardness": 0.3e9}),
    (["--law", "jackson-green", "--hardness", "300 MPa", "--h-star", "0.5um"],
     {"plasticity": "jackson-green", "hardness": 3e8, "h_star": 5e-7}),
])
def test_physical_law_is_the_library(capsys, extra, kwargs):
    code, out, err = run(capsys, "load", *AU, "--no-adhesion", *extra, "--load", "1mN:1N:3", "--format", "csv",
                         "--no-comments")
    assert code == 0 and err == ""
    contact = PhysicalContact("Au", SURFACE, adhesion=False, **kwargs)
    ref = contact.load_curve(np.geomspace(1e-3, 1, 3))
    assert out == ref.to_csv()
    assert list(rows_of(out)[0])[-1] == "plastic"
    # the description above the rows names the law and the hardness used
    code, out, err = run(capsys, "load", *AU, "--no-adhesion", *extra, "--load", "1mN:1N:3", "--format", "csv")
    assert code == 0 and comment_lines(out) == contact.describe().splitlines()
    assert comment_lines(out)[-1].startswith("law: jackson-green, H = ")


def test_size_effect_from_the_table(capsys):
    code, out, _ = run(capsys, "separation", *CU, "--no-adhesion", "--law", "jackson-green", "--size-effect",
                       "--separation", "0nm,2nm", "--format", "csv", "--no-comments")
    ref = PhysicalContact("Cu", SURFACE, adhesion=False, plasticity="jackson-green", size_effect=True)
    assert code == 0 and out == ref.separation_curve([0.0, 2e-9]).to_csv()


def test_elastic_gold_notes_the_yield_on_stderr(capsys):
    code, out, err = run(capsys, "load", *AU, "--load", "1mN,10mN", "--format", "csv", "--no-comments")
    assert code == 0
    lines = [x for x in err.splitlines() if "critical interference" in x]
    assert len(lines) == 1 and lines[0].startswith("asperity: note: up to")
    assert "--law jackson-green --no-adhesion" in lines[0]
    assert out == quiet(lambda: PhysicalContact("Au", SURFACE).load_curve([1e-3, 1e-2])).to_csv()
    code, out, err = run(capsys, "load", *AU, "--plastic-threshold", "1", "--load", "1mN", "--format", "csv")
    assert code == 0 and "critical interference" not in err


def test_elastic_gold_with_a_hardness_option(capsys):
    # A (much) harder gold: the check uses the hardness given.
    code, _, err = run(capsys, "load", *AU, "--no-adhesion", "--hardness", "50GPa", "--load", "1mN", "--format",
                       "csv")
    c = PhysicalContact("Au", SURFACE, adhesion=False, hardness=50e9)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        c.load_curve([1e-3])
    assert code == 0 and ("critical interference" in err) == bool(caught)


@pytest.mark.parametrize("argv, needle", [
    (["load", *DIMLESS, "--law", "kogut", "--P", "1"], "unknown law 'kogut'; known: elastic, jackson-green"),
    (["load", *DIMLESS, "--law", "elastic", "--hardness", "0.01", "--P", "1"], "elastic law takes no hardness"),
    (["load", *DIMLESS, "--law", "jackson-green", "--P", "1"], "needs the hardness H_over_E"),
    (["load", *DIMLESS, "--law", "jackson-green", "--hardness", "hard", "--P", "1"], "--hardness: expected a number"),
    (["load", *DIMLESS, "--law", "jackson-green", "--hardness", "0.5", "--P", "1"], "H_over_E"),
    (["load", *DIMLESS, "--gamma", "1e-3", "--law", "jackson-green", "--hardness", "0.01", "--P", "1"],
     "no adhesion"),
    (["load", *DIMLESS, "--size-effect", "--P", "1"], "--size-effect applies to a physical contact"),
    (["load", *DIMLESS, "--plastic-threshold", "0.1", "--P", "1"], "--plastic-threshold applies"),
    (["load", *AU, "--law", "jackson-green", "--load", "1mN"], "pass adhesion=False"),
    (["load", *AU, "--no-adhesion", "--hardness", "200", "--load", "1mN"], "--hardness needs a unit"),
    (["load", *AU, "--no-adhesion", "--size-effect", "--load", "1mN"], "needs the Nix-Gao pair"),
    (["separation", *AU, "--no-adhesion", "--plastic-threshold", "2", "--separation", "1nm"],
     "plastic_threshold must lie in [0, 1]"),
])
def test_errors_are_one_line(capsys, argv, needle):
    code, _, err = run(capsys, *argv)
    assert one_line_error(code, err, needle), err


def test_help_lists_every_law(capsys):
    from asperity import LAWS

    with pytest.raises(SystemExit):
        run(capsys, "load", "--help")
    out = capsys.readouterr().out
    assert all(name in out for name in LAWS) and "--hardness" in out and "--h-star" in out
    assert "plastic" in out  # the optional column is listed with the units


def test_pulloff_with_the_plastic_law(capsys):
    # No adhesion, no pull-off: the command reports the library's zero force.
    code, out, _ = run(capsys, "pulloff", *AU, "--no-adhesion", "--law", "jackson-green", "--format", "json")
    po = PhysicalContact("Au", SURFACE, adhesion=False, plasticity="jackson-green").pull_off()
    assert code == 0 and po.force == 0.0 and '"pull_off_N": 0.0' in out
    code, out, _ = run(capsys, "pulloff", *DIMLESS, "--gamma", "0", "--law", "jackson-green", "--hardness", "0.01",
                       "--format", "json")
    assert code == 0 and Model(0.05, 1000.0, law=JacksonGreen(0.01)).pull_off().force == 0.0
    assert '"pull_off": 0.0' in out


def test_plot_of_a_plastic_curve(capsys, tmp_path):
    pytest.importorskip("matplotlib")
    png = tmp_path / "jg.png"
    code, _, _ = run(capsys, "load", *DIMLESS, "--law", "jackson-green", "--hardness", "0.005", "--P", "1:1e3:5",
                     "--plot", str(png), "-o", str(tmp_path / "jg.csv"))
    assert code == 0 and png.read_bytes()[:4] == b"\x89PNG"
