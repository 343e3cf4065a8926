"""Gaussian height statistics (Eq 19) and the GW moments' closed form."""

import mpmath as mp
import numpy as np
import pytest

from asperity.heights import GAUSSIAN, Gaussian, HeightDistribution


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
