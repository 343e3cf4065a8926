"""The worked examples run and their numbers are the library's."""

import importlib.util
import pathlib

import numpy as np
import pytest

EXAMPLES = pathlib.Path(__file__).parents[1] / "examples"
EXAMPLE = EXAMPLES / "afm_gold.py"


def load_example(path=EXAMPLE):
    spec = importlib.util.spec_from_file_location(path.stem, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_afm_gold_example(tmp_path, capsys):
    pytest.importorskip("SurfaceTopography")
    from asperity.physical import PhysicalContact
    from asperity.topography import analyse_surface

    example = load_example()
    curve, pull = example.main(["--out", str(tmp_path)])
    assert (tmp_path / "afm_gold.png").read_bytes()[:4] == b"\x89PNG"
    assert (tmp_path / "mu_vs_load.csv").exists()
    out = capsys.readouterr().out
    assert "pull-off force" in out and "spectral" in out and "detected" in out
    # The same numbers straight from the library
    analysis = analyse_surface(tmp_path / "gold_scan.x3p")
    contact = PhysicalContact("Au", analysis.spectral.surface(1e-6))
    assert pull.force == pytest.approx(contact.pull_off().force, rel=1e-12)
    np.testing.assert_allclose(curve.mu[:3], contact.load_curve(np.geomspace(1e-4, 10.0, 60)[:3]).mu,
                               rtol=1e-12)
    assert np.all(curve.area < 1e-6)  # the real area stays below the nominal area


def test_fit_afm_friction_example(tmp_path, capsys):
    pytest.importorskip("lmfit")
    pytest.importorskip("matplotlib")
    example = load_example(EXAMPLES / "fit_afm_friction.py")
    gw, ranked = example.main(["--out", str(tmp_path)])
    assert (tmp_path / "fit_afm_friction.png").read_bytes()[:4] == b"\x89PNG"
    out = capsys.readouterr().out
    assert "best single-asperity law" in out and "dAIC" in out
    # ranked by AIC, every model of the example in it, the rough-surface model among them
    aics = [r.aic for r in ranked.results]
    assert aics == sorted(aics) and {r.model for r in ranked.results} == {"gw", "jkr", "dmt", "md", "cos", "amontons"}
    # the generating work of adhesion lies in the rough-surface fit's 95 % interval
    maker = load_example(EXAMPLES / "data" / "make_afm_friction.py")
    lo, hi = gw.parameters["w_J_m2"].ci95
    assert lo < maker.TRUTH["w_J_m2"] < hi
    # the shipped data file is exactly what the script beside it writes
    fresh = maker.main(tmp_path / "regenerated.csv")
    assert fresh.read_text() == (EXAMPLES / "data" / "afm_friction_synthetic.csv").read_text()
    assert fresh.read_text().startswith("# SYNTHETIC DATA - not a measurement.")
