"""``--heights SPEC`` on every model command, and ``asperity surface --summits``, against the library."""

import json

import numpy as np
import pytest

import asperity
from asperity.heights import SPELLINGS, Exponential, Johnson, PearsonIII, Weibull, parse_heights, write_samples

from .helpers import AU, MODEL, one_line_error, rows_of, run


def test_help_lists_every_spelling(capsys):
    from asperity.cli._args import HEIGHTS_HELP

    for spelling in SPELLINGS.values():
        name, _, params = spelling.partition(":")
        assert name in HEIGHTS_HELP
        for p in params.split(","):
            if "=" in p:
                assert p.split("=")[0] + "=" in HEIGHTS_HELP, p
    from asperity.cli import main

    for command in ("load", "separation", "pulloff"):
        with pytest.raises(SystemExit):
            main([command, "--help"])
        assert "--heights SPEC" in capsys.readouterr().out


@pytest.mark.parametrize("spec, dist", [("weibull:skew=0.5", Weibull(0.5)),
                                        ("johnson:skew=0.5,kurt=4", Johnson(0.5, 4.0)),
                                        ("exponential", Exponential()),
                                        ("gaussian", asperity.GAUSSIAN)])
def test_load_with_heights_is_the_library(capsys, spec, dist):
    code, out, _ = run(capsys, "load", *MODEL, "--P", "0.5,3,1e3", "--heights", spec, "--format", "csv")
    assert code == 0
    assert out == asperity.load_curve([0.5, 3, 1e3], 0.01, 1000, 1e-3, heights=dist).to_csv()


def test_separation_and_pulloff_with_heights(capsys):
    code, out, _ = run(capsys, "separation", *MODEL, "--d", "-1,0,1.5", "--heights", "pearson3:skew=-0.3",
                       "--format", "csv")
    assert code == 0
    assert out == asperity.separation_curve([-1, 0, 1.5], 0.01, 1000, 1e-3, heights=PearsonIII(-0.3)).to_csv()
    code, out, _ = run(capsys, "pulloff", "--alpha", "0.003", "--beta", "1000", "--gamma", "1e-3",
                       "--heights", "weibull:skew=-0.5", "--format", "json")
    assert code == 0
    ref = asperity.pull_off(0.003, 1000, 1e-3, heights=Weibull(-0.5))
    assert json.loads(out) == ref.to_dict()


@pytest.mark.filterwarnings("ignore::asperity.PlasticityWarning")  # gold this rough yields; the CLI notes it
def test_physical_contact_with_heights(capsys):
    pytest.importorskip("pint")
    from asperity.physical import PhysicalContact, Surface

    code, out, err = run(capsys, "load", *AU, "--load", "1mN,10mN", "--heights", "exponential", "--format", "csv")
    assert code == 0 and "asperity: note: up to" in err
    ref = PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6), heights=Exponential()).load_curve([1e-3, 1e-2])
    rows = rows_of(out)
    np.testing.assert_allclose([float(r["mu"]) for r in rows], ref.mu, rtol=1e-15)


def test_heights_from_a_file_of_summits(capsys, tmp_path):
    path = tmp_path / "summits.txt"
    write_samples(path, np.random.default_rng(5).gamma(3.0, size=600) * 1e-9, header="z_m")
    for spec in (f"empirical:{path}", f"best:{path}"):
        code, out, _ = run(capsys, "load", *MODEL, "--P", "1,100", "--heights", spec, "--format", "csv")
        assert code == 0
        assert out == asperity.load_curve([1, 100], 0.01, 1000, 1e-3, heights=parse_heights(spec)).to_csv()


@pytest.mark.parametrize("spec, needle", [
    ("nonsense", "unknown distribution 'nonsense'; valid: gaussian, exponential, weibull:skew=SKEW"),
    ("weibull:skew=9", "Weibull skewness"),
    ("weibull", "missing parameter(s) skew"),
    ("johnson:skew=0,kurt=1", "must exceed 1 + skew^2"),
    ("empirical:/no/such/file", "cannot read summit heights"),
])
def test_bad_heights_are_one_line_errors(capsys, spec, needle):
    code, out, err = run(capsys, "load", *MODEL, "--P", "1", "--heights", spec)
    assert one_line_error(code, err, needle) and out == ""


def test_surface_reports_and_writes_summit_heights(capsys, tmp_path):
    pytest.importorskip("SurfaceTopography")
    from asperity.topography import analyse_surface

    from ..topography.synthetic import as_map, synthetic_map

    h, _, _ = synthetic_map(256, roll_px=64, min_px=8, seed=2)
    scan = tmp_path / "scan.x3p"
    as_map(h).to_x3p(str(scan))
    out_file = tmp_path / "summits.txt"
    code, out, _ = run(capsys, "surface", str(scan), "--summits", str(out_file), "--format", "json")
    assert code == 0
    got = json.loads(out)
    ref = analyse_surface(scan)
    assert got["heights"] == json.loads(json.dumps(ref.to_dict()["heights"]))
    np.testing.assert_array_equal(np.loadtxt(out_file, skiprows=1), ref.summit_heights)
    code, out, _ = run(capsys, "surface", str(scan), "--format", "table")
    assert code == 0 and "skewness" in out and f"--heights {ref.heights.best.spec}" in out
