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
    from asperity import PlasticityWarning
    from asperity.physical import PhysicalContact
    from asperity.topography import analyse_surface

    example = load_example()
    with pytest.warns(PlasticityWarning, match="past the critical interference"):  # gold asperities yield
        curve, pull = example.main(["--out", str(tmp_path)])
    assert (tmp_path / "afm_gold.png").read_bytes()[:4] == b"\x89PNG"
    assert (tmp_path / "mu_vs_load.csv").exists()
    out = capsys.readouterr().out
    assert "pull-off force" in out and "spectral" in out and "detected" in out
    # The same numbers straight from the library
    analysis = analyse_surface(tmp_path / "gold_scan.x3p")
    contact = PhysicalContact("Au", analysis.spectral.surface(1e-6))
    assert pull.force == pytest.approx(contact.pull_off().force, rel=1e-12)
    with pytest.warns(PlasticityWarning):
        again = contact.load_curve(np.geomspace(1e-4, 10.0, 60)[:3])
    np.testing.assert_allclose(curve.mu[:3], again.mu, rtol=1e-12)
    assert np.all(curve.area < 1e-6)  # the real area stays below the nominal area
