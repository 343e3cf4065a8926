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


VALIDATE = pathlib.Path(__file__).parents[1] / "examples" / "validate_surface.py"


def test_validate_surface_example(tmp_path, capsys):
    pytest.importorskip("ContactMechanics")
    pytest.importorskip("matplotlib")
    from asperity.validation import validate_surface
    from asperity.validation.surfaces import synthetic_surface

    spec = importlib.util.spec_from_file_location("validate_surface", VALIDATE)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    result = module.main(["--grid", "48", "--loads", "3", "--out", str(tmp_path)])
    assert (tmp_path / "validation.png").read_bytes()[:4] == b"\x89PNG"
    assert (tmp_path / "validation.csv").read_text().splitlines()[0].startswith("P_N,")
    out = capsys.readouterr().out
    assert "largest |A_GW/A_BEM - 1|" in out and "cost:" in out
    # The same numbers straight from the library
    topo = synthetic_surface("self-affine", 4e-6, 48, short_cutoff=4e-6 * 4 / 48, hurst=0.8, seed=0)
    again = validate_surface(topo, result.columns()["P_N"], material="Au")
    np.testing.assert_allclose(again.columns()["area_bem_m2"], result.columns()["area_bem_m2"], rtol=1e-12)
    np.testing.assert_allclose(again.columns()["area_spectral_m2"], result.columns()["area_spectral_m2"],
                               rtol=1e-12)
