"""The reference height densities (asperity.reference.heights) against closed forms."""

import math

import mpmath as mp
import pytest

from asperity.reference.heights import gw_moment_ref, moments_ref, reference_density


def test_exponential_moments_are_gw_closed_forms():
    e = reference_density("exponential")
    assert moments_ref(e) == pytest.approx((1.0, 0.0, 1.0, 2.0, 9.0), abs=1e-12)
    for d in (-0.5, 0.0, 2.0):  # above the edge: Gamma(n+1) e^-(d+1)  (Greenwood & Williamson 1966)
        for n in (0, 1, 1.5, 2):
            assert gw_moment_ref(e, d, n) == pytest.approx(math.gamma(n + 1) * math.exp(-(d + 1)), rel=1e-13)
    # below the edge: int_0^inf (y + D)^n e^-y dy = sum_k C(n,k) D^(n-k) k! for integer n
    D = 2.5
    assert gw_moment_ref(e, -1 - D, 2) == pytest.approx(D**2 + 2 * D + 2, rel=1e-13)


@pytest.mark.parametrize("skew", [-0.8, 0.0, 0.5, 1.8])
def test_weibull_is_standardised_with_its_skewness(skew):
    w = reference_density("weibull", skew=skew)
    total, mean, var, s, _ = moments_ref(w)
    assert (total, mean, var, s) == pytest.approx((1.0, 0.0, 1.0, skew), abs=1e-10)


@pytest.mark.parametrize("skew", [-1.2, 0.4, 2.0])
def test_pearson3_has_the_gamma_moments(skew):
    p = reference_density("pearson3", skew=skew)
    assert moments_ref(p) == pytest.approx((1.0, 0.0, 1.0, skew, 3 + 1.5 * skew**2), abs=1e-10)


def test_johnson_su_matches_johnsons_closed_form_moments():
    """Johnson (1949): with w = exp(1/delta^2), O = gamma/delta, the S_U skewness and kurtosis."""
    j = reference_density("johnson", skew=0.5, kurt=4.0)
    total, mean, var, s, k = moments_ref(j)
    assert (total, mean, var, s, k) == pytest.approx((1.0, 0.0, 1.0, 0.5, 4.0), abs=1e-9)
    # the closed form at a shape of our choosing, against the reference's quadrature of the density
    delta, gamma = 1.7, -0.8
    w, O = math.exp(1 / delta**2), gamma / delta
    V = (w * math.cosh(2 * O) + 1) / 2
    sk = -0.25 * math.sqrt(w * (w - 1)) * (w * (w + 2) * math.sinh(3 * O) + 3 * math.sinh(O)) / V**1.5
    with mp.workdps(30):
        c = 1 / mp.sqrt(2 * mp.pi)
        f = lambda x, p: mp.sinh((x - gamma) / delta) ** p * c * mp.exp(-x * x / 2)  # noqa: E731
        m = [mp.quad(lambda x, p=p: f(x, p), [-mp.inf, -3, 0, 3, mp.inf]) for p in (1, 2, 3)]
        var_q = m[1] - m[0] ** 2
        sk_q = (m[2] - 3 * m[0] * m[1] + 2 * m[0] ** 3) / var_q**1.5
    assert float(sk_q) == pytest.approx(sk, rel=1e-12)


def test_johnson_sb_is_fitted_to_its_moments():
    j = reference_density("johnson", skew=-0.5, kurt=3.2)
    assert math.isfinite(j.lo) and math.isfinite(j.hi)
    assert moments_ref(j) == pytest.approx((1.0, 0.0, 1.0, -0.5, 3.2), abs=1e-9)


def test_mixture_moments_and_closed_form_gw():
    m = reference_density("mixture", w=0.8, m1=0.5, s1=0.5, m2=-2.0, s2=1.2)
    total, mean, var, _, _ = moments_ref(m)
    assert (total, mean, var) == pytest.approx((1.0, 0.0, 1.0), abs=1e-12)
    # the parabolic-cylinder sum against the quadrature of the same density
    for d, n in ((-1.0, 1.5), (0.7, 2.0), (2.5, 0.0)):
        with mp.workdps(30):
            q = mp.quad(lambda z: (z - d) ** n * m.mp_pdf(z), [d, d + 1, d + 3, d + 8, mp.inf])
        assert gw_moment_ref(m, d, n) == pytest.approx(float(q), rel=1e-12)


def test_gaussian_and_bad_names():
    g = reference_density("gaussian")
    assert gw_moment_ref(g, 0.0, 1) == pytest.approx(1 / math.sqrt(2 * math.pi), rel=1e-14)
    with pytest.raises(ValueError, match="unknown reference density"):
        reference_density("lognormal")
