"""Tests of asperity.topography: GW summit parameters of measured surfaces.

Synthetic surfaces are built here by Fourier synthesis with deterministic amplitudes
and random phases, so their spectral moments are known exactly:

* continuous moments  m0 = sum C,  m2 = sum C kx^2,  m4 = sum C kx^4  (averaged over x, y);
* the moments of SurfaceTopography's finite differences (upwind slope, central
  curvature) of a periodic surface are exact sums over the same spectrum with the
  difference operators' symbols  4 sin^2(k dx/2)/dx^2  in place of k^2.
"""

import json
import math
import re
import sys
import warnings

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from asperity import topography as tp
from asperity.topography import (
    SummitParameters,
    SurfaceAnalysis,
    analyse_surface,
    detected_summits,
    read_topography,
    spectral_summits,
)

ST = tp._surface_topography()
DX = 10e-9  # pixel size [m]
RMS = 2e-9  # rms height [m]


# --------------------------------------------------------------------------- synthesis
def _isotropic_psd(q, q_roll, q_max, hurst):
    """Flat below q_roll, self-affine C ~ q^-2(1+H) up to q_max, zero above (unnormalised)."""
    c = (np.maximum(q, q_roll) / q_roll) ** (-2 * (1 + hurst))
    return np.where(q > q_max, 0.0, c)


def synthetic_map(n, *, roll_px, min_px, hurst=0.8, seed=0):
    """Periodic isotropic Gaussian-like surface and its exact moments.

    Returns heights (n, n) [m] and dicts of continuous and finite-difference moments.
    """
    k = 2 * np.pi * np.fft.fftfreq(n, d=DX)
    kx, ky = np.meshgrid(k, k, indexing="ij")
    q = np.hypot(kx, ky)
    c = _isotropic_psd(q, 2 * np.pi / (roll_px * DX), 2 * np.pi / (min_px * DX), hurst)
    c[0, 0] = 0.0
    c *= RMS**2 / c.sum()  # c[k] = |h_k|^2, so sum c = <h^2>
    r = np.random.default_rng(seed).random((n, n))
    r -= np.roll(r[::-1, ::-1], 1, axis=(0, 1))  # phase(-k) = -phase(k): real heights
    heights = (np.fft.ifft2(np.sqrt(c) * np.exp(2j * np.pi * r)) * n * n).real
    sx, sy = (4 / DX**2 * np.sin(kk * DX / 2) ** 2 for kk in (kx, ky))
    exact = {"m0": c.sum(), "m2": (c * (kx**2 + ky**2)).sum() / 2, "m4": (c * (kx**4 + ky**4)).sum() / 2}
    # finite differences: <|grad h|^2>/2 and 3/8 <(discrete Laplacian)^2>, as in the module
    fd = {"m0": c.sum(), "m2": (c * (sx + sy)).sum() / 2, "m4": 3 / 8 * (c * (sx + sy) ** 2).sum()}
    return heights, exact, fd


def synthetic_profile(n, *, roll_px, min_px, hurst=0.8, seed=0):
    """Periodic 1D Gaussian-like profile and its exact continuous moments."""
    k = 2 * np.pi * np.fft.rfftfreq(n, d=DX)
    c = _isotropic_psd(k, 2 * np.pi / (roll_px * DX), 2 * np.pi / (min_px * DX), hurst)
    c[0] = 0.0
    c *= RMS**2 / c.sum()  # h = sum sqrt(2 c_k) cos(k x + phi_k)
    phase = np.exp(2j * np.pi * np.random.default_rng(seed).random(k.size))
    heights = np.fft.irfft(np.sqrt(2 * c) * phase * n / 2, n)
    return heights, {"m0": c.sum(), "m2": (c * k**2).sum(), "m4": (c * k**4).sum()}


def mccool(m0, m2, m4):
    """McCool (1986) summit parameters: (sigma_s, R, eta)."""
    alpha = m0 * m4 / m2**2
    return (math.sqrt(1 - 0.8968 / alpha) * math.sqrt(m0), 0.375 * math.sqrt(math.pi / m4),
            m4 / (6 * math.pi * math.sqrt(3) * m2))


def as_map(heights, periodic=True, unit="m", pixel=DX):
    nx, ny = heights.shape
    return ST.Topography(heights, (nx * pixel, ny * pixel), periodic=periodic, unit=unit)


@pytest.fixture(scope="module")
def wide_band():
    """512^2 map, wavelengths 16 px .. 64 px roll-off (alpha_N ~ 4)."""
    return synthetic_map(512, roll_px=64, min_px=16, seed=1)


@pytest.fixture(scope="module")
def large_surface():
    """1024^2 map, wavelengths 16 px .. 256 px roll-off (alpha_N ~ 19), ~870 summits; analysed once."""
    heights, exact, _ = synthetic_map(1024, roll_px=256, min_px=16, seed=1)
    return analyse_surface(as_map(heights), b=2.5e-10), exact


# --------------------------------------------------------------------------- spectral
def test_spectral_moments_are_the_exact_finite_difference_moments(wide_band):
    heights, exact, fd = wide_band
    p = spectral_summits(as_map(heights))
    for key in ("m0", "m2", "m4"):
        assert getattr(p, key) == pytest.approx(fd[key], rel=1e-9)
        # the grid resolves the spectrum: FD and continuous moments agree to a few per cent
        assert getattr(p, key) == pytest.approx(exact[key], rel=0.03)
    assert p.alpha_n == pytest.approx(fd["m0"] * fd["m4"] / fd["m2"] ** 2, rel=1e-9)
    assert p.sigma == pytest.approx(RMS, rel=1e-9)


def test_spectral_summits_follow_mccool(wide_band):
    heights, exact, fd = wide_band
    p = spectral_summits(as_map(heights))
    sigma_s, radius, eta = mccool(fd["m0"], fd["m2"], fd["m4"])
    assert (p.sigma_s, p.radius, p.density) == pytest.approx((sigma_s, radius, eta), rel=1e-9)
    assert (p.sigma_s, p.radius, p.density) == pytest.approx(mccool(exact["m0"], exact["m2"], exact["m4"]), rel=0.03)
    assert p.mean_summit_height == pytest.approx(4 * math.sqrt(fd["m0"] / (math.pi * p.alpha_n)), rel=1e-9)
    assert p.method == "spectral" and p.n_summits is None and p.source == "map"
    assert p.anisotropy == pytest.approx(1.0, abs=0.02)


def test_spectral_moments_are_unit_and_tilt_invariant(wide_band):
    heights, _, fd = wide_band
    n = heights.shape[0]
    x, y = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    tilted = heights * 1e9 + 0.02 * x - 0.01 * y + 5.0  # nm, tilted and offset: not periodic
    p = spectral_summits(as_map(tilted, periodic=False, unit="nm", pixel=DX * 1e9))
    assert p.m0 == pytest.approx(fd["m0"], rel=1e-3)
    assert p.m2 == pytest.approx(fd["m2"], rel=0.01)  # the trimmed border costs < 1 %
    assert p.m4 == pytest.approx(fd["m4"], rel=0.01)


# --------------------------------------------------------------------------- detection
def test_detected_agrees_with_spectral_on_large_surface(large_surface):
    """~870 summits: eta, R and sigma_s agree within 10 % (observed: 0.1 %, 3 %, 1 %)."""
    result, exact = large_surface
    s, d = result.spectral, result.detected
    assert d.n_summits > 500
    assert d.density == pytest.approx(s.density, rel=0.10)
    assert d.radius == pytest.approx(s.radius, rel=0.10)
    assert d.sigma_s == pytest.approx(s.sigma_s, rel=0.10)
    assert d.mean_summit_height == pytest.approx(s.mean_summit_height, rel=0.10)
    assert d.density == pytest.approx(mccool(exact["m0"], exact["m2"], exact["m4"])[2], rel=0.10)


def test_analyse_well_resolved_surface_has_no_warnings(large_surface):
    result, _ = large_surface
    assert result.warnings == []
    assert result.spectral.alpha_n > 15
    assert result.nb_grid_pts == (1024, 1024)
    assert result.pixel_size == pytest.approx((DX, DX))
    assert result.physical_sizes == pytest.approx((1024 * DX, 1024 * DX))
    assert result.n_points == 1024**2


def paraboloid_lattice(cells, spacing_px, radius, pixel=DX):
    """Identical paraboloids -r^2/2R on a square lattice; interior = whole cells.

    The grid has cells * spacing_px + 2 points per side, so the interior points (the
    border rows and columns excluded) are exactly ``cells**2`` lattice cells.
    """
    n = cells * spacing_px + 2
    rel = ((np.arange(n) - 1) % spacing_px - (spacing_px - 1) / 2) * pixel
    x, y = np.meshgrid(rel, rel, indexing="ij")
    return ST.Topography(-(x**2 + y**2) / (2 * radius), (n * pixel, n * pixel), unit="m")


@given(cells=st.integers(2, 6), half=st.integers(2, 8), radius=st.floats(1e-7, 1e-4))
def test_paraboloid_lattice_exact(cells, half, radius):
    spacing_px = 2 * half + 1  # odd: the apex is a grid point
    p = detected_summits(paraboloid_lattice(cells, spacing_px, radius))
    assert p.n_summits == cells**2
    assert p.radius == pytest.approx(radius, rel=1e-9)
    assert p.density == pytest.approx(1 / (spacing_px * DX) ** 2, rel=1e-12)
    assert p.sigma_s == pytest.approx(0.0, abs=1e-9 * (spacing_px * DX) ** 2 / radius)


def test_single_paraboloid_bump():
    n, radius = 41, 3e-6
    r = (np.arange(n) - n // 2) * DX
    x, y = np.meshgrid(r, r, indexing="ij")
    p = detected_summits(ST.Topography(-(x**2 + y**2) / (2 * radius), (n * DX, n * DX), unit="m"))
    assert p.n_summits == 1
    assert p.radius == pytest.approx(radius, rel=1e-9)
    assert p.density == pytest.approx(1 / ((n - 2) * DX) ** 2)


def test_elliptic_bump_uses_mean_curvature():
    n, rx, ry = 41, 2e-6, 6e-6
    r = (np.arange(n) - n // 2) * DX
    x, y = np.meshgrid(r, r, indexing="ij")
    p = detected_summits(ST.Topography(-x**2 / (2 * rx) - y**2 / (2 * ry), (n * DX, n * DX), unit="m"))
    assert 1 / p.radius == pytest.approx((1 / rx + 1 / ry) / 2, rel=1e-9)


def test_plateau_counts_once():
    h = np.zeros((7, 7))
    h[3, 3] = h[3, 4] = 1.0
    assert tp._local_maxima_2d(h).sum() == 1
    assert tp._local_maxima_1d(np.array([0.0, 1.0, 1.0, 0.0])).sum() == 1


def test_line_scan_spectral_and_detected_agree():
    """2^17-point profile, ~1800 peaks: both methods agree within 5 % (observed < 2 %)."""
    heights, exact = synthetic_profile(2**17, roll_px=512, min_px=16, seed=2)
    line = ST.UniformLineScan(heights, heights.size * DX, periodic=True, unit="m")
    s, d = spectral_summits(line), detected_summits(line)
    for key in ("m0", "m2", "m4"):
        assert getattr(s, key) == pytest.approx(exact[key], rel=0.03)
    assert (s.sigma_s, s.radius, s.density) == pytest.approx(mccool(s.m0, s.m2, s.m4), rel=1e-12)
    assert s.source == d.source == "line scan"
    assert d.n_summits > 1000
    assert d.density == pytest.approx(s.density, rel=0.05)
    assert d.radius == pytest.approx(s.radius, rel=0.05)
    assert d.sigma_s == pytest.approx(s.sigma_s, rel=0.05)


def test_line_scan_peak_conversion():
    """A sine of wavelength L: one peak per L, curvature k^2 A -> eta = 2pi/(3 sqrt3) / L^2."""
    n, period_px, amp = 1002, 20, 1e-9
    x = (np.arange(n) - 1 - period_px // 2) * DX  # crests at interior points 11, 31, ..., 991
    k = 2 * np.pi / (period_px * DX)
    line = ST.UniformLineScan(amp * np.cos(k * x), n * DX, periodic=False, unit="m")
    d = detected_summits(line)
    assert d.n_summits == (n - 2) // period_px
    assert d.density == pytest.approx(2 * math.pi / (3 * math.sqrt(3)) / (period_px * DX) ** 2, rel=1e-9)
    kappa = amp * (2 - 2 * math.cos(k * DX)) / DX**2  # central-difference curvature at a crest
    assert d.radius == pytest.approx(3 * math.pi / (8 * math.sqrt(2) * kappa), rel=1e-6)


# --------------------------------------------------------------------------- warnings
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


def test_groups_and_outputs(large_surface):
    result, _ = large_surface
    assert result.b == 2.5e-10
    for p in (result.spectral, result.detected):
        g = result.groups[p.method]
        assert g["alpha"] == pytest.approx(math.sqrt(p.sigma_s / p.radius))
        assert g["beta"] == pytest.approx(math.sqrt(p.radius * p.sigma_s) / 2.5e-10)
    data = json.loads(json.dumps(result.to_dict()))
    assert data["spectral"]["density"] == pytest.approx(result.spectral.density)
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


def test_flat_surface_rejected():
    flat = ST.Topography(np.zeros((16, 16)), (1e-6, 1e-6), unit="m")
    with pytest.raises(ValueError, match="flat"):
        spectral_summits(flat)
    with pytest.raises(ValueError, match="no summits"):
        detected_summits(flat)


# --------------------------------------------------------------------------- files
@pytest.fixture()
def small_map():
    heights = np.random.default_rng(4).standard_normal((12, 10))  # nm
    return heights, ST.Topography(heights, (1.2, 1.0), unit="µm")


def _check_map(topo, heights, height_scale=1e-9, sizes=(1.2e-6, 1.0e-6)):
    assert topo.unit == "m"
    assert topo.nb_grid_pts == heights.shape
    assert tuple(topo.physical_sizes) == pytest.approx(sizes, rel=1e-12)
    np.testing.assert_allclose(topo.heights(), heights * height_scale, rtol=1e-12)


def test_read_handwritten_text_matrix(tmp_path):
    heights = np.arange(12.0).reshape(3, 4)  # rows along y, columns along x
    path = tmp_path / "afm.txt"
    path.write_text("# Channel: Height\n# Width: 4 µm\n# Height: 3 µm\n# Value units: nm\n"
                    + "\n".join(" ".join(f"{v:g}" for v in row) for row in heights) + "\n", encoding="utf-8")
    _check_map(read_topography(path), heights.T, sizes=(4e-6, 3e-6))


@pytest.mark.parametrize(("writer", "suffix"), [("to_matrix", "txt"), ("to_x3p", "x3p"), ("to_netcdf", "nc")])
def test_read_written_formats(tmp_path, small_map, writer, suffix):
    heights, topo = small_map
    path = tmp_path / f"map.{suffix}"
    getattr(topo.scale(1e-3), writer)(str(path))  # heights in µm, as the unit says
    _check_map(read_topography(path), heights)


def test_read_npy_needs_sizes_and_unit(tmp_path, small_map):
    heights, _ = small_map
    path = tmp_path / "map.npy"
    np.save(path, heights)
    with pytest.raises(ValueError, match=re.escape(str(path)) + ".*physical_sizes="):
        read_topography(path)
    with pytest.raises(ValueError, match="unit="):
        read_topography(path, physical_sizes=(1.2, 1.0))
    _check_map(read_topography(path, physical_sizes=(1200, 1000), unit="nm"), heights)


@pytest.mark.parametrize(("kwargs", "message"), [
    ({"physical_sizes": (1, 1), "unit": "V"}, "not a length unit"),
    ({"physical_sizes": (1, 1), "unit": "furlong"}, "not a length unit"),
    ({"physical_sizes": (1, 1, 1), "unit": "nm"}, "2 positive number"),
    ({"physical_sizes": (1, -1), "unit": "nm"}, "2 positive number"),
    ({"physical_sizes": (1, "a"), "unit": "nm"}, "2 positive number"),
    ({"physical_sizes": (1, 1), "unit": "nm", "channel_index": 3}, "no channel 3"),
])
def test_bad_read_arguments(tmp_path, small_map, kwargs, message):
    path = tmp_path / "map.npy"
    np.save(path, small_map[0])
    with pytest.raises(ValueError, match=re.escape(str(path)) + ".*" + message):
        read_topography(path, **kwargs)


def test_file_metadata_cannot_be_overridden(tmp_path, small_map):
    _, topo = small_map
    path = tmp_path / "map.txt"
    topo.to_matrix(str(path))
    with pytest.raises(ValueError, match="already stores the unit"):
        read_topography(path, unit="nm")
    with pytest.raises(ValueError, match="already stores the scan size"):
        read_topography(path, physical_sizes=(1, 1))


def test_read_line_scan(tmp_path):
    heights = np.sin(np.linspace(0, 20, 200))  # nm
    path = tmp_path / "profile.txt"
    ST.UniformLineScan(heights, 50.0, unit="µm").scale(1e-3).to_matrix(str(path))
    line = read_topography(path)
    assert line.dim == 1 and line.unit == "m"
    assert tuple(line.physical_sizes) == pytest.approx((50e-6,))
    np.testing.assert_allclose(line.heights(), heights * 1e-9, rtol=1e-12)
    result = analyse_surface(path)
    assert result.dim == 1 and result.source == str(path)
    assert any("line scan" in w for w in result.warnings)


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


def test_undefined_data(tmp_path, small_map):
    heights, _ = small_map
    holes = heights.copy()
    holes[4, 5] = np.nan
    path = tmp_path / "holes.txt"
    np.savetxt(path, holes.T, header="Width: 1.2 um\nHeight: 1.0 um\nValue units: nm")
    with pytest.raises(ValueError, match=re.escape(str(path)) + ".*1 of 120 heights are undefined"):
        read_topography(path)
    filled = read_topography(path, fill_undefined=True)
    assert not filled.has_undefined_data
    # harmonic fill of one hole on a square grid: the mean of its 4 neighbours
    neighbours = heights[3, 5] + heights[5, 5] + heights[4, 4] + heights[4, 6]
    assert filled.heights()[4, 5] == pytest.approx(neighbours / 4 * 1e-9, rel=1e-6)


@pytest.mark.parametrize("content", [None, b"", np.random.default_rng(5).bytes(3001),
                                     b"this is not\na topography\n"])
def test_bad_files_raise_value_error_naming_file(tmp_path, content):
    path = tmp_path / "bad.dat"
    if content is not None:
        path.write_bytes(content)
    with pytest.raises(ValueError, match=re.escape(str(path))) as info:
        read_topography(path)
    assert info.value.__cause__ is None and (info.value.__context__ is None or info.value.__suppress_context__)
    with pytest.raises(ValueError, match=re.escape(str(path))):
        analyse_surface(path)


def test_reader_warnings_are_reissued_with_file_name(tmp_path, small_map, monkeypatch):
    _, topo = small_map
    path = tmp_path / "map.txt"
    topo.to_matrix(str(path))
    original = ST.open_topography

    def noisy(fobj, *args, **kwargs):
        warnings.warn("odd header", UserWarning, stacklevel=2)
        return original(fobj, *args, **kwargs)

    monkeypatch.setattr(ST, "open_topography", noisy)
    with pytest.warns(UserWarning, match=re.escape(f"{path}: odd header")):
        read_topography(path)


def test_missing_surface_topography(monkeypatch):
    monkeypatch.setitem(sys.modules, "SurfaceTopography", None)
    with pytest.raises(ImportError, match=re.escape("pip install 'asperity[topography]'")):
        tp._surface_topography()


def test_rejects_non_topography():
    with pytest.raises(TypeError, match="SurfaceTopography"):
        spectral_summits(np.zeros((8, 8)))
