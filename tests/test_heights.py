"""Gaussian height statistics (Eq 19) and the GW moments' closed form."""

import re

import mpmath as mp
import numpy as np
import pytest

from asperity.heights import GAUSSIAN, Exponential, Gaussian, HeightDistribution, Johnson, Mixture, PearsonIII, Weibull
from asperity.heights.base import gw_moment_quadrature
from asperity.heights.exponential import exponential_moment
from asperity.heights.gaussian import gaussian_moment
from asperity.heights.pearson import pearson3_moment


def moment_mp(d, k):
    """Closed form Gamma(k+1) e^(-d^2/4) D_{-k-1}(d) / sqrt(2 pi), at 40 digits."""
    with mp.workdps(40):
        d = mp.mpf(d)
        return float(mp.gamma(k + 1) * mp.exp(-d * d / 4) * mp.pcfd(-k - 1, d) / mp.sqrt(2 * mp.pi))


def moment_quad_mp(d, k):
    with mp.workdps(40):
        f = lambda z: (z - d) ** k * mp.exp(-z * z / 2) / mp.sqrt(2 * mp.pi)  # noqa: E731
        return float(mp.quad(f, [d, d + 5, d + 15, mp.inf]))


@pytest.mark.parametrize("k", [0, 1, 1.5, 0.7857])
@pytest.mark.parametrize("d", [-3.0, 0.0, 1.3, 4.0])
def test_closed_form_is_the_integral(d, k):
    assert moment_mp(d, k) == pytest.approx(moment_quad_mp(d, k), rel=1e-14)


@pytest.mark.parametrize("k", [0, 1, 1.5])
def test_pbdv_moment(k):
    d = np.array([-3.0, -1.0, 0.0, 2.0, 5.0])
    expected = [moment_mp(x, k) for x in d]
    np.testing.assert_allclose(GAUSSIAN.moment(d, k), expected, rtol=1e-9)


def test_density_and_derivatives():
    z = np.linspace(-5, 5, 11)
    g = Gaussian()
    np.testing.assert_allclose(g.pdf(z), np.exp(-z**2 / 2) / np.sqrt(2 * np.pi), rtol=1e-15)
    h = 1e-5
    num1 = (g.pdf(z + h) - g.pdf(z - h)) / (2 * h)
    num2 = (g.pdf(z + h) - 2 * g.pdf(z) + g.pdf(z - h)) / h**2
    np.testing.assert_allclose(g.pdf_derivative(z, 1), num1, atol=1e-10)
    np.testing.assert_allclose(g.pdf_derivative(z, 2), num2, atol=1e-5)
    assert g.sf(0.0) == 0.5


def test_factorised_sums_equal_generic():
    g = GAUSSIAN
    d = np.linspace(-8, 12, 37)
    centers = np.arange(0.5, 20.5)
    offsets = np.linspace(-0.5, 0.5, 7)
    W = np.random.default_rng(1).random((centers.size, offsets.size, 3))
    fast = g.panel_sums(d, centers, offsets, W, order=2)
    slow = HeightDistribution.panel_sums(g, d, centers, offsets, W, order=2)
    for f, s in zip(fast, slow):  # derivatives cancel: compare to the column's scale
        np.testing.assert_allclose(f, s, rtol=1e-12, atol=1e-12 * np.abs(s).max())


def test_bad_order():
    with pytest.raises(ValueError, match="order"):
        GAUSSIAN.moment(0.0, -1.5)


# -- the moments far in the tails, and their orders (a review: NaN, inf and stray exceptions) ----
@pytest.mark.parametrize("dist", [Gaussian(), Mixture(), Exponential(), PearsonIII(0.5), PearsonIII(-0.5),
                                  Weibull(0.5), Johnson(0.5, 4.0)], ids=repr)
def test_moments_far_in_the_tails_are_their_limits(dist):
    """Far above every summit F_n = 0 (the Gaussian gave NaN at d = 2500); far below, F_0 = 1 and
    F_n = |d|^n to leading order (Pearson III's closed form overflowed to inf at -1e19)."""
    for d in (2500.0, 1e300):  # F_0 is the survival function (Johnson S_U's tail is heavy: 6e-88 at 2500)
        assert dist.moment(d, 0) == pytest.approx(float(dist.sf(d)), rel=1e-8, abs=1e-300)
        assert 0.0 <= dist.moment(d, 1.5) < 1e-80
    assert dist.moment(-1e19, 0) == pytest.approx(1.0, rel=1e-12)
    assert dist.moment(-1e19, 1.5) == pytest.approx(1e19**1.5, rel=1e-12)
    with pytest.raises(ValueError, match=re.escape("overflows double precision at d = [-1e+19]")):
        dist.moment(-1e19, 20)  # named as the caller gave it (the mixtures named their scaled x)


@pytest.mark.parametrize("order", [171, 20.5, np.inf, -1.0, np.nan, [1.0, 2.0], True, "1"])
def test_moment_orders_out_of_range_are_named(order):
    with pytest.raises(ValueError, match="^order must"):
        Gaussian().moment(1.0, order)
    with pytest.raises(ValueError, match="^order must"):
        gaussian_moment(1.0, order)


def test_a_0d_order_is_a_number_and_derivative_orders_are_checked():
    assert Gaussian().moment(1.0, np.array(1.5)) == Gaussian().moment(1.0, 1.5)
    for dist in (Gaussian(), Mixture(), Exponential(), PearsonIII(0.5), Weibull(0.5), Johnson(0.5, 4.0)):
        for bad in (np.array([1, 2]), 3, 1.0, True):
            with pytest.raises(ValueError, match="^order .*must be 1 or 2"):
                dist.pdf_derivative(1.0, bad)
    assert Gaussian().pdf(1e308) == 0.0 and Gaussian().pdf_derivative(1e308, 2) == 0.0


def test_the_closed_forms_check_their_inputs():
    with pytest.raises(ValueError, match="^d must be finite"):
        pearson3_moment(np.nan, 1.5, 0.5)
    with pytest.raises(ValueError, match="^skew must lie in"):
        pearson3_moment(1.0, 1.5, 1e-320)
    with pytest.raises(ValueError, match="^x must be a real number"):
        gaussian_moment(True, 1.0)
    with pytest.raises(ValueError, match="^d must be finite"):
        exponential_moment([0.0, np.inf], 1.0)
    assert gaussian_moment([], 1.5).shape == (0,)
    # the closed forms still equal the quadrature of the definition
    d = np.array([-2.0, 0.3, 3.0])
    np.testing.assert_allclose(pearson3_moment(d, 1.5, 1.0), gw_moment_quadrature(PearsonIII(1.0), d, 1.5),
                               rtol=1e-11)


@pytest.mark.parametrize("dist", [Gaussian(), Exponential(), PearsonIII(2.0), PearsonIII(-0.5), Weibull(0.5),
                                  Weibull(-0.8), Weibull(-1.0), Johnson(0.5, 4.0), Johnson(-0.5, 3.2), Mixture()],
                         ids=repr)
def test_densities_far_out_are_their_limits_and_nan_is_refused(dist):
    """A review: overflow warnings (z^2, w^c) and NaN (0 * inf) far out; NaN heights passed through;
    a second review: Weibull(-1) raised between 1e10 and 1e150."""
    far = np.geomspace(1e3, 1e308, 300)
    for method, args in (("pdf", ()), ("sf", ()), ("pdf_derivative", (1,)), ("pdf_derivative", (2,))):
        assert np.all(np.isfinite(getattr(dist, method)(np.concatenate([-far, far]), *args)))
    assert type(dist.pdf_derivative(1e200, 2)) is np.float64  # the limit's path too
    assert dist.pdf_derivative(np.array([0.5]), order=1) == dist.pdf_derivative(np.array([0.5]), 1)  # keywords
    z = np.array([-1e308, -1e19, 1e19, 1e308])
    np.testing.assert_array_equal(dist.pdf(np.array([1e308, 1e308])), 0.0)  # their sum overflows, quietly
    with pytest.raises(ValueError, match="^z must be finite"):
        dist.sf(np.array([np.inf, -np.inf]))
    np.testing.assert_array_equal(dist.pdf(z), 0.0)
    np.testing.assert_array_equal(dist.sf(z), [1.0, 1.0, 0.0, 0.0])
    for order in (1, 2):
        np.testing.assert_array_equal(dist.pdf_derivative(z, order), 0.0)
    for method, args in (("pdf", ()), ("sf", ()), ("pdf_derivative", (1,))):
        with pytest.raises(ValueError, match="^z must be finite"):
            getattr(dist, method)(np.array([0.0, np.nan]), *args)
        with pytest.raises(ValueError, match="^z must be"):
            getattr(dist, method)("1", *args)


def test_gw_moment_quadrature_checks_its_arguments():
    """A user trial: the public quadrature checked nothing (NaN gave 0, order -2 gave 8e18,
    d = -inf gave inf, None an AttributeError)."""
    g = Gaussian()
    for kwargs, error, match in (({"d": np.nan}, ValueError, "^d"), ({"d": -np.inf}, ValueError, "^d"),
                                 ({"d": "a"}, ValueError, "^d"), ({"order": -2}, ValueError, r"order must lie in"),
                                 ({"dist": None}, TypeError, "dist must be an asperity.heights.HeightDistribution")):
        args = {"dist": g, "d": 0.5, "order": 1.0, **kwargs}
        with pytest.raises(error, match=match):
            gw_moment_quadrature(args["dist"], args["d"], args["order"])
    assert gw_moment_quadrature(g, np.array([]), 1.0).shape == (0,)
    assert float(gw_moment_quadrature(g, 0.5, 1.0)) == pytest.approx(float(g.moment(0.5, 1.0)), rel=1e-12)
