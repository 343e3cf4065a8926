"""asperity.topography.analysis: both methods on one surface, warnings and groups."""

import json
import math
import re

import numpy as np
import pytest

from asperity.topography import SummitParameters, SurfaceAnalysis, analyse_surface

from .synthetic import DX, ST, as_map, paraboloid_lattice


def test_analyse_well_resolved_surface_has_no_warnings(large_surface):
    result, _ = large_surface
    assert result.warnings == []
    assert result.spectral.alpha_n > 15
    assert result.nb_grid_pts == (1024, 1024)
    assert result.pixel_size == pytest.approx((DX, DX))
    assert result.physical_sizes == pytest.approx((1024 * DX, 1024 * DX))
    assert result.n_points == 1024**2



def test_white_noise_is_flagged_as_under_resolved():
    rng = np.random.default_rng(3)
    result = analyse_surface(as_map(rng.standard_normal((96, 96)) * 1e-9, periodic=False))
    text = " ".join(result.warnings)
    assert "pixels apart" in text
    assert "alpha_N" in text  # white noise has alpha_N ~ 1.5


def test_narrow_band_and_disagreement_warnings(wide_band):
    heights, _, _ = wide_band
    result = analyse_surface(as_map(heights))
    assert any("alpha_N" in w for w in result.warnings)
    lattice = analyse_surface(paraboloid_lattice(3, 11, 1e-6))
    text = " ".join(lattice.warnings)
    assert "too few" in text and "differ" in text


def test_anisotropic_map_is_flagged(wide_band):
    heights, _, _ = wide_band
    n = heights.shape[0]
    stretched = ST.Topography(heights, (n * DX, 2 * n * DX), periodic=True, unit="m")
    result = analyse_surface(stretched)
    assert result.spectral.anisotropy == pytest.approx(4.0, rel=0.05)
    assert any("anisotropic" in w for w in result.warnings)


def test_a_wrong_height_unit_is_flagged_by_the_rms_slope(wide_band, tmp_path):
    """A user trial: heights in nm read with --unit m gave sigma_s = 4.8 m on a 10 um scan, with
    no note naming the unit.  Now an rms slope above 1 is noted, naming unit and size; the
    slope equals the rms of NumPy's periodic central-difference gradient to 2 %."""
    heights, _, _ = wide_band
    n = heights.shape[0]
    gy, gx = (np.roll(heights, -1, a) - np.roll(heights, 1, a) for a in (0, 1))
    rms_slope = float(np.sqrt(np.mean((gx / (2 * DX)) ** 2 + (gy / (2 * DX)) ** 2)))
    for scale, noted in ((1.0, rms_slope > 1.0), (0.5 / rms_slope, False), (3.0 / rms_slope, True)):
        result = analyse_surface(ST.Topography(heights * scale, (n * DX, n * DX), periodic=True, unit="m"))
        notes = [w for w in result.warnings if w.startswith("rms slope")]
        assert len(notes) == noted
        if noted:
            slope = float(notes[0].split()[2])
            assert slope == pytest.approx(rms_slope * scale, rel=0.02) and "--unit" in notes[0] and "--size" in notes[0]
    np.save(tmp_path / "nm.npy", heights / DX * 10.0)  # slopes of 0.01 x rms_slope in nm over n x 1000 nm
    good = analyse_surface(tmp_path / "nm.npy", physical_sizes=(f"{n}um", f"{n}um"), unit="nm")
    wrong = analyse_surface(tmp_path / "nm.npy", physical_sizes=(f"{n}um", f"{n}um"), unit="m")
    assert not any(w.startswith("rms slope") for w in good.warnings)
    assert any(w.startswith("rms slope") for w in wrong.warnings)


def test_groups_and_outputs(large_surface):
    result, _ = large_surface
    assert result.b == 2.5e-10
    for p in (result.spectral, result.detected):
        g = result.groups[p.method]
        assert g["alpha"] == pytest.approx(math.sqrt(p.sigma_s / p.R))
        assert g["beta"] == pytest.approx(math.sqrt(p.R * p.sigma_s) / 2.5e-10)
    data = json.loads(json.dumps(result.to_dict()))
    assert data["spectral"]["eta"] == pytest.approx(result.spectral.eta)
    assert data["detected"]["n_summits"] == result.detected.n_summits
    assert data["groups"]["detected"]["beta"] == pytest.approx(result.groups["detected"]["beta"])
    assert data["warnings"] == [] and data["nb_grid_pts"] == [1024, 1024]
    text = result.summary()
    assert "spectral" in text and "detected" in text and "beta" in text
    assert isinstance(result, SurfaceAnalysis) and isinstance(result.spectral, SummitParameters)


def test_burgers_vector_from_material():
    class Material:
        b = 2.5e-10

    lattice = paraboloid_lattice(3, 11, 1e-6)
    assert analyse_surface(lattice, material=Material()).b == 2.5e-10
    assert analyse_surface(lattice, material=Material(), b=5e-10).b == 5e-10
    assert analyse_surface(lattice).groups is None
    no_b = analyse_surface(lattice, material=type("M", (), {"b": None, "name": "Au"})())
    assert no_b.groups is None and any("'Au' has no Burgers vector" in w for w in no_b.warnings)
    r = (np.arange(21) - 10) * DX
    x, y = np.meshgrid(r, r, indexing="ij")
    bump = ST.Topography(-(x**2 + y**2) / 2e-6, (21 * DX, 21 * DX), unit="m")
    identical = analyse_surface(bump, b=2.5e-10)  # one summit: sigma_s = 0, no alpha or beta
    assert identical.detected.sigma_s == 0.0 and "detected" not in identical.groups
    assert "detected" in identical.summary()
    with pytest.raises(ValueError, match="Burgers"):
        analyse_surface(lattice, b=-1.0)
    with pytest.raises(TypeError, match="attribute 'b'"):
        analyse_surface(lattice, material=object())



def test_analyse_file_path(tmp_path, wide_band):
    heights, _, fd = wide_band
    path = tmp_path / "surface.nc"
    as_map(heights[:256, :256] * 1e9, periodic=False, unit="nm", pixel=DX * 1e9).to_netcdf(str(path))
    result = analyse_surface(path, b=2.5e-10)
    assert result.source == str(path)
    assert result.physical_sizes == pytest.approx((256 * DX, 256 * DX))
    assert result.spectral.m2 == pytest.approx(fd["m2"], rel=0.15)  # a quarter of the surface
    with pytest.raises(TypeError, match="only apply"):
        analyse_surface(as_map(heights), unit="nm")


def test_material_by_name_and_pint_burgers_vector():
    from asperity.materials import material

    lattice = paraboloid_lattice(3, 11, 1e-6)
    assert analyse_surface(lattice, material="Au").b == material("Au").b
    assert analyse_surface(lattice, b="0.25 nm").b == pytest.approx(2.5e-10)
    no_b = analyse_surface(lattice, material="mica")
    assert no_b.groups is None and any("'mica' has no Burgers vector" in w for w in no_b.warnings)
    with pytest.raises(ValueError, match="unknown material"):
        analyse_surface(lattice, material="unobtainium")
    with pytest.raises(ValueError, match=r"b \(Burgers vector\) must have units compatible with m"):
        analyse_surface(lattice, b="1 GPa")


@pytest.mark.parametrize("bad", [3, None, b"scan.npy", np.zeros((16, 16))])
def test_neither_path_nor_topography(bad):
    with pytest.raises(TypeError, match="path_or_topography must be a file path"):
        analyse_surface(bad)


def test_degenerate_file_errors_name_the_file(tmp_path):
    x, y = np.meshgrid(np.arange(20.0), np.arange(16.0), indexing="ij")
    path = tmp_path / "tilted.npy"
    np.save(path, 0.4 * x - 0.2 * y + 7.0)  # a tilted plane, heights in nm
    with pytest.raises(ValueError, match=re.escape(str(path)) + ": the surface is flat"):
        analyse_surface(path, physical_sizes=("2um", "1.6um"), unit="nm")


def test_json_output_is_strict(large_surface):
    result, _ = large_surface
    text = json.dumps(result.to_dict(), allow_nan=False)
    data = json.loads(text)
    assert data["spectral"]["R"] == result.spectral.R and data["detected"]["eta"] == result.detected.eta


def test_surface_of_either_method(tmp_path, wide_band):
    from asperity.surface import Surface

    heights, _, _ = wide_band
    path = tmp_path / "surface.nc"
    as_map(heights[:128, :128] * 1e9, periodic=False, unit="nm", pixel=DX * 1e9).to_netcdf(str(path))
    result = analyse_surface(path)
    for method in ("spectral", "detected"):
        p = getattr(result, method)
        s = result.surface("1mm^2", method)
        assert s == Surface(p.sigma_s, p.R, p.eta, 1e-6)
        assert s.source.startswith(f"{path}, {method} summits")
    assert result.surface(1e-6) == result.surface(1e-6, "spectral")
    assert result.spectral.surface(1e-6).source == "spectral summits (Nayak/McCool)"
    with pytest.raises(ValueError, match="method must be one of 'spectral', 'detected'"):
        result.surface(1e-6, "nayak")
    with pytest.raises(ValueError, match="area must be > 0"):
        result.surface(-1.0)
