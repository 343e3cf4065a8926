"""asperity.persson: Persson's area and the BGT asymptote against their closed-form limits."""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from scipy import integrate, special

from asperity.persson import KAPPA_BGT, KAPPA_PERSSON, bgt_area_fraction, persson_area_fraction, rms_slope

E = 1e11


def test_light_load_slope_and_full_contact():
    assert KAPPA_PERSSON == pytest.approx(1.5957691216057308, rel=1e-15)   # sqrt(8/pi)
    assert KAPPA_BGT == pytest.approx(2.5066282746310002, rel=1e-15)       # sqrt(2 pi)
    slope = 0.1
    p = E * slope * np.array([1e-8, 1e-5, 1e-3])
    np.testing.assert_allclose(persson_area_fraction(p, E, slope) / (KAPPA_PERSSON * p / (E * slope)), 1.0,
                               rtol=1e-5)
    assert persson_area_fraction(100 * E * slope, E, slope) == pytest.approx(1.0, abs=1e-15)
    assert persson_area_fraction(0.0, E, slope) == 0.0


@given(st.floats(1e-6, 10.0), st.floats(1e-6, 10.0))
def test_monotone_below_one_and_below_its_slope(x, y):
    lo, hi = sorted((x, y))
    a, b = persson_area_fraction([lo * E, hi * E], E, 1.0)
    assert 0 < a <= b <= 1
    assert a <= KAPPA_PERSSON * lo * (1 + 1e-12)                            # erf is concave


def test_equals_persson_G_from_a_power_spectrum():
    # G = (pi/4) E*^2 int q^3 C dq over a self-affine spectrum, A/A0 = erf(p / 2 sqrt(G)),
    # with the slope from h'^2 = 2 pi int q^3 C dq: the two routes must agree.
    H, q0, q1, C0 = 0.8, 1e6, 5e7, 1e-36

    def C(q):
        return C0 * (q / q0) ** (-2 - 2 * H) if q >= q0 else C0

    m = integrate.quad(lambda q: q**3 * C(q), 1e4, q1, points=[q0], limit=200)[0]
    slope = math.sqrt(2 * math.pi * m)
    G = math.pi / 4 * E**2 * m
    p = np.array([1e6, 1e7, 1e8, 1e9])
    np.testing.assert_allclose(persson_area_fraction(p, E, slope), special.erf(p / (2 * np.sqrt(G))), rtol=1e-13)


def test_bgt_in_profile_moments():
    slope, p = 0.08, 3e7
    m2 = slope**2 / 2
    assert bgt_area_fraction(p, E, slope) == pytest.approx(math.sqrt(math.pi / m2) * p / E, rel=1e-14)


def test_rms_slope_of_maps():
    st_ = pytest.importorskip("SurfaceTopography")
    n, L = 64, 2e-6
    x = np.arange(n) * L / n
    h = 3e-9 * np.sin(2 * math.pi * 4 * x / L)[:, None] * np.ones(n) + 2e-9 * np.cos(2 * math.pi * 3 * x / L)[None, :]
    exact = math.sqrt((3e-9 * 2 * math.pi * 4 / L) ** 2 / 2 + (2e-9 * 2 * math.pi * 3 / L) ** 2 / 2)
    assert rms_slope(st_.Topography(h, (L, L), periodic=True, unit="m")) == pytest.approx(exact, rel=1e-12)
    in_nm = st_.Topography(h * 1e9, (L * 1e9, L * 1e9), periodic=True, unit="nm")
    assert rms_slope(in_nm) == pytest.approx(exact, rel=1e-12)
    free = st_.Topography(h, (L, L), periodic=False, unit="m")
    assert rms_slope(free) == pytest.approx(exact, rel=0.02)                # finite differences, 16 px/wavelength


@pytest.mark.parametrize("args, message", [((-1.0, E, 0.1), "p \\(nominal pressure\\)"),
                                           ((1.0, 0.0, 0.1), "E_star"), ((1.0, E, 0.0), "rms_slope"),
                                           ((np.nan, E, 0.1), "finite"), ((True, E, 0.1), "boolean")])
def test_bad_input(args, message):
    for law in (persson_area_fraction, bgt_area_fraction):
        with pytest.raises(ValueError, match=message):
            law(*args)
    with pytest.raises(TypeError, match="SurfaceTopography"):
        rms_slope(np.zeros((4, 4)))


def test_the_laws_broadcast_over_modulus_and_slope():
    """A review: E_star and rms_slope were scalar-only; now every input broadcasts like a ufunc."""
    from asperity.interaction import cgp_shift

    p = np.array([1e6, 1e7, 1e8])
    E = np.array([[5e10], [1e11]])
    slope = np.array([0.05, 0.1, 0.2])
    for law in (persson_area_fraction, bgt_area_fraction):
        got = law(p, E, slope)
        assert got.shape == (2, 3)
        for i, j in np.ndindex(got.shape):
            assert got[i, j] == law(p[j], E[i, 0], slope[j])
        assert type(law(1e6, 1e11, 0.1)) is np.float64
        with pytest.raises(ValueError, match="^p, E_star, rms_slope must have shapes"):
            law(p, [1e11, 2e11], 0.1)
    shift = cgp_shift(1e6, np.array([1e-6, 4e-6]), [1e11, 2e11])
    np.testing.assert_allclose(shift, [cgp_shift(1e6, 1e-6, 1e11), cgp_shift(1e6, 4e-6, 2e11)], rtol=1e-15)
