"""The worked example runs and its numbers are the library's."""

import importlib.util
import pathlib

import numpy as np
import pytest

EXAMPLES = pathlib.Path(__file__).parents[1] / "examples"


def load_example(name="afm_gold"):
    spec = importlib.util.spec_from_file_location(name, EXAMPLES / f"{name}.py")
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


def test_sweep_map_example(tmp_path, capsys):
    pytest.importorskip("xarray")
    pytest.importorskip("netCDF4")
    pytest.importorskip("matplotlib")
    import asperity

    example = load_example("sweep_map")
    ds = example.main(["--out", str(tmp_path), "--scheduler", "serial", "--n", "3"])
    assert (tmp_path / "pull_off.png").read_bytes()[:4] == b"\x89PNG"
    assert "9 parameter sets" in capsys.readouterr().out
    # A cell of the map, straight from the library
    m = asperity.Model(float(ds.alpha[1]), 1000.0, float(ds.gamma[2]))
    np.testing.assert_array_equal(ds.mu.values[1, 2], m.load_curve(ds.P.values).mu)
    assert ds.pull_off.values[1, 2] == m.pull_off().force
    ds.close()
