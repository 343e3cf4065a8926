"""The worked examples run and their numbers are the library's."""

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


def test_afm_cycle_example(tmp_path, capsys):
    from asperity.physical import PhysicalContact, Surface

    example = load_example("afm_cycle")
    surface_only, measured, sweep = example.main(["--out", str(tmp_path)])
    assert (tmp_path / "afm_cycle.png").read_bytes()[:4] == b"\x89PNG"
    assert (tmp_path / "cycle.csv").read_text().startswith("branch,d_base_m,d_m,P_N")
    assert (tmp_path / "preload.csv").exists()
    out = capsys.readouterr().out
    assert "pull-off force" in out and "jump out of contact" in out and "J/m^2" in out
    # The same numbers straight from the library
    contact = PhysicalContact("Au", Surface(2e-9, 100e-9, 2e14, 1e-12))
    ref = contact.cycle(preload=5e-6, n=400, stiffness=10.0)
    assert measured.energy_J == ref.energy_J and measured.pull_off.force == ref.pull_off.force
    assert surface_only.energy_J == contact.cycle(preload=5e-6, n=400).energy_J
    assert sweep.pull_off_N[-1] == pytest.approx(contact.pull_off().force, rel=1e-10)
    assert any(j["branch"] == "retract" for j in measured.jumps)
