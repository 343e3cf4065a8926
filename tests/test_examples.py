"""The worked example runs and its numbers are the library's."""

import importlib.util
import pathlib

import numpy as np
import pytest

pytest.importorskip("SurfaceTopography")

EXAMPLE = pathlib.Path(__file__).parents[1] / "examples" / "afm_gold.py"


def load_example():
    spec = importlib.util.spec_from_file_location("afm_gold", EXAMPLE)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_afm_gold_example(tmp_path, capsys):
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


def test_skewed_surface_example(tmp_path, capsys):
    from asperity.heights import GAUSSIAN, parse_heights
    from asperity.physical import PhysicalContact
    from asperity.topography import analyse_surface

    spec = importlib.util.spec_from_file_location("skewed_surface", EXAMPLE.parent / "skewed_surface.py")
    example = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(example)
    analysis, curves, pulls = example.main(["--out", str(tmp_path)])
    assert (tmp_path / "skewed_surface.png").read_bytes()[:4] == b"\x89PNG"
    assert (tmp_path / "mu_gaussian_vs_measured.csv").read_text().startswith("P_N,mu_gaussian,mu_measured")
    out = capsys.readouterr().out
    assert "skewness" in out and "pull-off" in out
    # The worn top gives negatively skewed summits; the same numbers straight from the library
    ref = analyse_surface(tmp_path / "worn_scan.x3p")
    assert ref.heights.skewness < -0.2 and ref.heights.skewness == analysis.heights.skewness
    best = parse_heights(ref.heights.best.spec)
    surface = ref.detected.surface(1e-6)
    gauss, measured = (PhysicalContact("Au", surface, heights=h) for h in (GAUSSIAN, best))
    (name_g, pull_g), (name_m, pull_m) = pulls.items()
    assert pull_g.force == pytest.approx(gauss.pull_off().force, rel=1e-12)
    assert pull_m.force == pytest.approx(measured.pull_off().force, rel=1e-12)
    loads = np.geomspace(1e-2, 1e3, 60)[::20]
    np.testing.assert_allclose(curves[name_m].mu[::20], measured.load_curve(loads).mu, rtol=1e-12)
    assert pull_m.force != pytest.approx(pull_g.force, rel=0.05)  # the shape matters
