"""asperity.topography.detected: summit parameters from the summits found on the grid."""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from asperity.topography import detected_summits, spectral_summits
from asperity.topography.detected import local_maxima_1d, local_maxima_2d, summit_curvatures

from .synthetic import DX, ST, mccool, paraboloid_lattice, synthetic_profile


def test_detected_agrees_with_spectral_on_large_surface(large_surface):
    """~870 summits: eta, R and sigma_s agree within 10 % (observed: 0.1 %, 3 %, 1 %)."""
    result, exact = large_surface
    s, d = result.spectral, result.detected
    assert d.n_summits > 500
    assert d.eta == pytest.approx(s.eta, rel=0.10)
    assert d.R == pytest.approx(s.R, rel=0.10)
    assert d.sigma_s == pytest.approx(s.sigma_s, rel=0.10)
    assert d.mean_summit_height == pytest.approx(s.mean_summit_height, rel=0.10)
    assert d.eta == pytest.approx(mccool(exact["m0"], exact["m2"], exact["m4"])[2], rel=0.10)



@given(cells=st.integers(2, 6), half=st.integers(2, 8), radius=st.floats(1e-7, 1e-4))
def test_paraboloid_lattice_exact(cells, half, radius):
    spacing_px = 2 * half + 1  # odd: the apex is a grid point
    p = detected_summits(paraboloid_lattice(cells, spacing_px, radius))
    assert p.n_summits == cells**2
    assert p.R == pytest.approx(radius, rel=1e-9)
    assert p.eta == pytest.approx(1 / (spacing_px * DX) ** 2, rel=1e-12)
    assert p.sigma_s == pytest.approx(0.0, abs=1e-9 * (spacing_px * DX) ** 2 / radius)


def test_single_paraboloid_bump():
    n, radius = 41, 3e-6
    r = (np.arange(n) - n // 2) * DX
    x, y = np.meshgrid(r, r, indexing="ij")
    p = detected_summits(ST.Topography(-(x**2 + y**2) / (2 * radius), (n * DX, n * DX), unit="m"))
    assert p.n_summits == 1
    assert p.R == pytest.approx(radius, rel=1e-9)
    assert p.eta == pytest.approx(1 / ((n - 2) * DX) ** 2)


def test_elliptic_bump_uses_mean_curvature():
    n, rx, ry = 41, 2e-6, 6e-6
    r = (np.arange(n) - n // 2) * DX
    x, y = np.meshgrid(r, r, indexing="ij")
    p = detected_summits(ST.Topography(-x**2 / (2 * rx) - y**2 / (2 * ry), (n * DX, n * DX), unit="m"))
    assert 1 / p.R == pytest.approx((1 / rx + 1 / ry) / 2, rel=1e-9)


def _regional_maxima_by_flood_fill(h, periodic=False):
    """Regional maxima from the definition: flood each plateau of equal heights (8 neighbours,
    wrapping round a periodic map); it is a summit if no point next to it is higher and, on a
    free map, it does not reach the border.  Returns the first point of each, in row order."""
    n, m = h.shape
    seen = np.zeros(h.shape, dtype=bool)
    found = []
    for i in range(n) if periodic else range(1, n - 1):
        for j in range(m) if periodic else range(1, m - 1):
            if seen[i, j]:
                continue
            stack, plateau, ok = [(i, j)], [], True
            seen[i, j] = True
            while stack:
                a, b = stack.pop()
                plateau.append((a, b))
                ok &= periodic or (0 < a < n - 1 and 0 < b < m - 1)
                for x in range(a - 1, a + 2):
                    for y in range(b - 1, b + 2):
                        if not periodic and not (0 <= x < n and 0 <= y < m):
                            continue
                        x, y = x % n, y % m
                        if h[x, y] > h[a, b]:
                            ok = False
                        elif h[x, y] == h[a, b] and not seen[x, y]:
                            seen[x, y] = True
                            stack.append((x, y))
            if ok:
                found.append(min(plateau))
    return sorted(found)


@pytest.mark.parametrize("step", [0.0, 0.3, 1.0])
def test_quantized_maps_count_each_regional_maximum_once(step):
    # A review: a 1 nm-quantized Gaussian map gave 2517 summits for 586 regional maxima.
    from scipy import ndimage

    g = ndimage.gaussian_filter(np.random.default_rng(0).normal(size=(120, 100)), 3)
    h = 3 * g / g.std()
    h = np.round(h / step) * step if step else h
    assert [(i + 1, j + 1) for i, j in np.argwhere(local_maxima_2d(h))] == _regional_maxima_by_flood_fill(h)
    g = ndimage.gaussian_filter(np.random.default_rng(1).normal(size=(90, 70)), 3, mode="wrap")
    h = 3 * g / g.std()
    h = np.round(h / step) * step if step else h
    assert [tuple(p) for p in np.argwhere(local_maxima_2d(h, periodic=True))] == \
        _regional_maxima_by_flood_fill(h, periodic=True)


def test_l_shaped_plateau_once_and_a_shoulder_never():
    h = np.zeros((6, 5))
    h[2, 1:4] = 1.0
    h[3, 1] = h[3, 3] = 1.0
    assert local_maxima_2d(h).sum() == 1
    h = np.zeros((6, 5))
    h[1, 2], h[2, 2], h[3, 2] = 2.0, 1.0, 1.0
    assert local_maxima_2d(h).sum() == 1 and local_maxima_2d(h)[0, 1]
    assert local_maxima_1d(np.array([0.0, 2.0, 1.0, 1.0, 0.0])).sum() == 1
    assert local_maxima_1d(np.array([0.0, 1.0, 1.0, 1.0])).sum() == 0  # reaches the border


def test_plateau_counts_once():
    h = np.zeros((7, 7))
    h[3, 3] = h[3, 4] = 1.0
    assert local_maxima_2d(h).sum() == 1
    assert local_maxima_1d(np.array([0.0, 1.0, 1.0, 0.0])).sum() == 1


def test_line_scan_spectral_and_detected_agree():
    """2^17-point profile, ~1800 peaks: both methods agree within 5 % (observed < 2 %)."""
    heights, exact = synthetic_profile(2**17, roll_px=512, min_px=16, seed=2)
    line = ST.UniformLineScan(heights, heights.size * DX, periodic=True, unit="m")
    s, d = spectral_summits(line), detected_summits(line)
    for key in ("m0", "m2", "m4"):
        assert getattr(s, key) == pytest.approx(exact[key], rel=0.03)
    assert (s.sigma_s, s.R, s.eta) == pytest.approx(mccool(s.m0, s.m2, s.m4), rel=1e-12)
    assert s.source == d.source == "line scan"
    assert d.n_summits > 1000
    assert d.eta == pytest.approx(s.eta, rel=0.05)
    assert d.R == pytest.approx(s.R, rel=0.05)
    assert d.sigma_s == pytest.approx(s.sigma_s, rel=0.05)
    # the mean summit height too (a review: the peaks' own mean, 1.8 times lower, was reported)
    assert d.mean_summit_height == pytest.approx(s.mean_summit_height, rel=0.05)


def test_line_scan_peak_conversion():
    """A sine of wavelength L: one peak per L, curvature k^2 A -> eta = 2pi/(3 sqrt3) / L^2."""
    n, period_px, amp = 1002, 20, 1e-9
    x = (np.arange(n) - 1 - period_px // 2) * DX  # crests at interior points 11, 31, ..., 991
    k = 2 * np.pi / (period_px * DX)
    line = ST.UniformLineScan(amp * np.cos(k * x), n * DX, periodic=False, unit="m")
    d = detected_summits(line)
    assert d.n_summits == (n - 2) // period_px
    assert d.eta == pytest.approx(2 * math.pi / (3 * math.sqrt(3)) / (period_px * DX) ** 2, rel=1e-9)
    kappa = amp * (2 - 2 * math.cos(k * DX)) / DX**2  # central-difference curvature at a crest
    assert d.R == pytest.approx(3 * math.pi / (8 * math.sqrt(2) * kappa), rel=1e-6)


@pytest.mark.parametrize(("function", "bad", "message"), [
    (local_maxima_2d, np.zeros(9), r"h must be a 2-d array .* got shape \(9,\)"),
    (local_maxima_2d, np.zeros((2, 9)), "at least 3 points"),
    (local_maxima_1d, np.zeros((3, 3)), r"h must be a 1-d array"),
    (local_maxima_1d, [0.0, np.nan, 1.0], "finite"),
])
def test_local_maxima_validate(function, bad, message):
    with pytest.raises(ValueError, match=message):
        function(bad)


def test_summit_curvatures_of_a_paraboloid():
    r = (np.arange(9) - 4) * DX
    x, y = np.meshgrid(r, r, indexing="ij")
    h = -x**2 / (2 * 1e-6) - y**2 / (2 * 3e-6)
    peak = local_maxima_2d(h)
    assert peak.sum() == 1 and peak[3, 3]
    np.testing.assert_allclose(summit_curvatures(h, peak, DX, DX), [(1 / 1e-6 + 1 / 3e-6) / 2], rtol=1e-9)
    with pytest.raises(ValueError, match="peak must have shape"):
        summit_curvatures(h, peak[:-1], DX, DX)
    with pytest.raises(ValueError, match="dx must be > 0"):
        summit_curvatures(h, peak, 0.0, DX)
