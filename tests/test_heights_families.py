"""Each height family: a standardised density with the stated shape, its GW moments, its derivatives.

Checked against what the code does not compute itself: mpmath quadrature of the density,
the independent reference densities (asperity.reference.heights, built from the
definitions), SciPy's distributions, finite differences and closed forms.
"""

import dataclasses
import math

import mpmath as mp
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import stats

from asperity.heights import GAUSSIAN, Exponential, Gaussian, Johnson, Mixture, PearsonIII, Weibull
from asperity.reference.heights import gw_moment_ref

from .heights_cases import CASES, fast, reference

#: Stated (skewness, kurtosis) of the cases; None where only the family fixes it.
STATED = {"exponential": (2.0, 9.0), "weibull+0.5": (0.5, None), "weibull-0.8": (-0.8, None),
          "weibull+1.8": (1.8, None), "pearson3+1": (1.0, 4.5), "pearson3-1.2": (-1.2, 5.16),
          "pearson3+0.3": (0.3, 3.135), "johnsonSU": (0.5, 4.0), "johnsonSB": (-0.5, 3.2)}


def mp_moments(dist):
    """Total, mean, variance, skewness, kurtosis of dist.pdf by mpmath.quad (split at unit steps)."""
    lo = max(dist.support[0], dist.z_bottom)
    hi = min(dist.support[1], dist.z_top)
    pts = sorted({lo, hi, *[float(k) for k in range(math.ceil(lo), math.floor(hi) + 1) if lo < k < hi]})
    with mp.workdps(20):
        f = lambda z, k: z**k * float(dist.pdf(float(z)))  # noqa: E731
        m = [mp.quad(lambda z, k=k: f(z, k), pts) for k in range(5)]
    mean = m[1] / m[0]
    var = m[2] / m[0] - mean**2
    mu3 = m[3] / m[0] - 3 * mean * m[2] / m[0] + 2 * mean**3
    mu4 = m[4] / m[0] - 4 * mean * m[3] / m[0] + 6 * mean**2 * m[2] / m[0] - 3 * mean**4
    return float(m[0]), float(mean), float(var), float(mu3 / var**1.5), float(mu4 / var**2)


@pytest.mark.parametrize("case", list(CASES))
def test_density_is_standardised_with_the_stated_shape(case):
    dist = fast(case)
    total, mean, var, skew, kurt = mp_moments(dist)
    assert total == pytest.approx(1.0, abs=1e-11)
    assert mean == pytest.approx(0.0, abs=1e-11)
    assert var == pytest.approx(1.0, abs=1e-10)
    s, k = STATED.get(case, (None, None))
    if s is not None:
        assert skew == pytest.approx(s, abs=1e-9)
    if k is not None:
        assert kurt == pytest.approx(k, abs=1e-9)
    # the closed-form stats() agree with the quadrature
    np.testing.assert_allclose(dist.stats(), [0.0, 1.0, skew, kurt], atol=2e-9)


@pytest.mark.parametrize("case", list(CASES))
def test_density_equals_the_reference_definition(case):
    dist, ref = fast(case), reference(case)
    lo = max(dist.support[0], dist.z_bottom) + 1e-3
    hi = min(dist.support[1], dist.z_top) - 1e-3
    z = np.linspace(lo, hi, 41)
    expected = np.array([ref.pdf(x) for x in z])
    np.testing.assert_allclose(dist.pdf(z), expected, rtol=1e-11, atol=1e-300)
    assert dist.pdf(dist.support[0] - 0.5) == 0.0 if math.isfinite(dist.support[0]) else True


@pytest.mark.parametrize("case, order", [(c, n) for c in CASES for n in (0, 1, 1.5, 2)])
def test_gw_moments_against_mpmath(case, order):
    dist, ref = fast(case), reference(case)
    ds = np.array([-4.0, -2.0, -1.0, -0.3, 0.4, 1.5, 3.0, 5.0])
    got = dist.moment(ds, order)
    expected = np.array([gw_moment_ref(ref, d, order) for d in ds])
    np.testing.assert_allclose(got, expected, rtol=1e-10, atol=1e-280)


@pytest.mark.parametrize("case", list(CASES))
def test_density_derivatives_against_mpmath(case):
    dist, ref = fast(case), reference(case)
    lo = max(dist.support[0], dist.z_bottom) + 0.3
    hi = min(dist.support[1], dist.z_top, 6.0) - 0.3
    for z in np.linspace(lo, hi, 9):
        with mp.workdps(30):
            d1 = float(mp.diff(ref.mp_pdf, mp.mpf(z), 1))
            d2 = float(mp.diff(ref.mp_pdf, mp.mpf(z), 2))
        scale = float(dist.pdf(z)) + 1e-300
        assert float(dist.pdf_derivative(z, 1)) == pytest.approx(d1, rel=1e-9, abs=1e-9 * scale), z
        assert float(dist.pdf_derivative(z, 2)) == pytest.approx(d2, rel=1e-8, abs=1e-8 * scale), z
    with pytest.raises(ValueError, match="order"):
        dist.pdf_derivative(0.0, 3)


@pytest.mark.parametrize("case", list(CASES))
def test_survival_function_is_the_integral_of_the_density(case):
    dist, ref = fast(case), reference(case)
    for z in (-1.5, -0.2, 0.7, 2.5):
        assert float(dist.sf(z)) == pytest.approx(gw_moment_ref(ref, z, 0), rel=1e-11, abs=1e-300)
        assert float(dist.moment(z, 0)) == pytest.approx(float(dist.sf(z)), rel=1e-11, abs=1e-300)


def test_scipy_agrees():
    z = np.linspace(-1.5, 4.0, 23)
    w = Weibull(skew=0.5)
    ref = stats.weibull_min(w.c, loc=-w.mean_w / w.sd_w, scale=1.0 / w.sd_w)
    np.testing.assert_allclose(w.pdf(z), ref.pdf(z), rtol=1e-12)
    np.testing.assert_allclose(w.sf(z), ref.sf(z), rtol=1e-12)
    for s in (1.3, -0.7, 0.05):
        np.testing.assert_allclose(PearsonIII(s).pdf(z), stats.pearson3(s).pdf(z), rtol=1e-10, atol=1e-300)
        np.testing.assert_allclose(PearsonIII(s).sf(z), stats.pearson3(s).sf(z), rtol=1e-10, atol=1e-300)
    su, sb = Johnson(0.5, 4.0), Johnson(-0.5, 3.2)
    assert (su.kind, sb.kind) == ("SU", "SB")
    for j, family in ((su, stats.johnsonsu), (sb, stats.johnsonsb)):
        ref = family(j.gamma, j.delta, loc=j.xi, scale=j.lam)
        np.testing.assert_allclose(j.pdf(z), ref.pdf(z), rtol=1e-11, atol=1e-300)
        np.testing.assert_allclose(j.sf(z), ref.sf(z), rtol=1e-11, atol=1e-300)
    np.testing.assert_allclose(Exponential().pdf(z), stats.expon(loc=-1).pdf(z), rtol=1e-14)


def test_exponential_closed_form_far_below_its_edge():
    # D^(n+1) U(1, n+2, D) for D > 500 (SciPy's U) against the integral with mpmath
    for d, n in ((-800.0, 1.5), (-2000.0, 0.5), (-600.0, 2.0)):
        D = -1.0 - d
        with mp.workdps(30):
            ref = mp.quad(lambda y: (y + D) ** n * mp.exp(-y), [0, 1, 10, mp.inf])
        assert float(Exponential().moment(d, n)) == pytest.approx(float(ref), rel=1e-12)


def test_pearson_closed_form_through_tricomi_u():
    from asperity.heights.pearson import pearson3_moment

    ref = reference("pearson3+1")  # integer shape k = 4: SciPy's U is exact, the closed form is used
    for d in (-3.0, -2.0, -1.0, 0.5, 4.0):
        for n in (0, 1.5):
            assert float(pearson3_moment(d, n, 1.0)) == pytest.approx(gw_moment_ref(ref, d, n), rel=1e-12)


def test_weibull_at_skewness_two_is_the_exponential():
    w, e = Weibull(skew=2.0), Exponential()
    z = np.linspace(-0.99, 6.0, 15)
    assert w.c == 1.0
    np.testing.assert_allclose(w.pdf(z), e.pdf(z), rtol=1e-14)


def test_pearson_at_zero_skewness_is_the_gaussian():
    p = PearsonIII(skew=0.0)
    z = np.linspace(-5, 5, 11)
    np.testing.assert_array_equal(p.pdf(z), GAUSSIAN.pdf(z))
    # a small skewness: the Edgeworth series to O(s^2) (excess kurtosis 1.5 s^2), error O(s^3)
    s, x = 1e-3, np.linspace(-3, 3, 13)
    he3, he4, he6 = x**3 - 3 * x, x**4 - 6 * x**2 + 3, x**6 - 15 * x**4 + 45 * x**2 - 15
    edgeworth = GAUSSIAN.pdf(x) * (1 + s * he3 / 6 + s * s * (he6 / 72 + 1.5 * he4 / 24))
    np.testing.assert_allclose(PearsonIII(skew=s).pdf(x), edgeworth, rtol=1e-7)
    with pytest.raises(ValueError, match="must be 0 \\(the Gaussian\\) or at least 0.001"):
        PearsonIII(skew=1e-5)


def test_two_identical_gaussians_are_the_gaussian():
    m = Mixture(w=0.3, m1=1.0, s1=2.0, m2=1.0, s2=2.0)  # any unit: standardised
    assert (m.m1, m.s1, m.m2, m.s2) == (0.0, 1.0, 0.0, 1.0) and m.fast_sums
    z = np.linspace(-8, 8, 33)
    np.testing.assert_allclose(m.pdf(z), GAUSSIAN.pdf(z), rtol=1e-15)
    np.testing.assert_allclose(m.moment(z, 1.5), GAUSSIAN.moment(z, 1.5), rtol=1e-14)


def test_distributions_are_frozen_values():
    w = Weibull(skew=0.25)
    assert w == Weibull(skew=np.float64(0.25)) and hash(w) == hash(Weibull(0.25)) and w != Weibull(0.3)
    assert repr(w) == "Weibull(skew=0.25)" and eval(repr(w)) == w  # noqa: S307 - our own repr
    assert repr(Johnson(0.5, 4)) == "Johnson(skew=0.5, kurt=4.0)"
    assert Gaussian() == GAUSSIAN and repr(Exponential()) == "Exponential()"
    with pytest.raises(dataclasses.FrozenInstanceError):
        w.skew = 1.0
    for d in (w, Johnson(0.5, 4), Mixture(), Exponential(), PearsonIII(0.2)):
        assert " at 0x" not in repr(d)


@pytest.mark.parametrize("make, message", [
    (lambda: Weibull(skew=2.5), "Weibull skewness"),
    (lambda: Weibull(skew=-1.05), "Weibull skewness"),
    (lambda: Weibull(skew=True), "boolean"),
    (lambda: Weibull(skew=float("nan")), "finite"),
    (lambda: PearsonIII(skew="0.5"), "skew"),
    (lambda: PearsonIII(skew=[0.1, 0.2]), "scalar"),
    (lambda: Johnson(skew=1.0, kurt=1.5), "exceed 1 \\+ skew"),
    (lambda: Johnson(skew=0.0, kurt=40.0), "Johnson kurtosis"),
    (lambda: Mixture(w=0.0), "weight"),
    (lambda: Mixture(s1=-1.0), "deviation"),
    (lambda: Mixture(w=0.5, m1=0, s1=1e-4, m2=0, s2=1), "narrower"),
])
def test_bad_parameters_are_refused(make, message):
    with pytest.raises(ValueError, match=message):
        make()


@settings(max_examples=25, deadline=None)
@given(st.floats(-1.0, 2.0))
def test_weibull_skewness_property(skew):
    w = Weibull(skew=skew)
    mean, var, s, _ = w.stats()
    assert (mean, var) == (0.0, 1.0) and s == skew
    from asperity.heights.weibull import weibull_skewness

    assert float(weibull_skewness(w.c)) == pytest.approx(skew, abs=1e-10)
    assert w.support[0] < 0 and w.sf(w.support[0]) == 1.0


@settings(max_examples=25, deadline=None)
@given(st.sampled_from(list(CASES)), st.floats(-3.0, 4.0), st.floats(0.05, 1.0))
def test_moment_properties(case, d, step):
    dist = fast(case)
    F0, F1 = (float(dist.moment(d, n)) for n in (0, 1))
    assert F0 == pytest.approx(float(dist.sf(d)), rel=1e-10, abs=1e-300)
    assert float(dist.moment(d + step, 1)) <= F1  # the moments fall with the separation
    h = 1e-5  # dF_1/dd = -F_0
    slope = (float(dist.moment(d + h, 1)) - float(dist.moment(d - h, 1))) / (2 * h)
    assert slope == pytest.approx(-F0, rel=1e-5, abs=1e-8)


def test_two_identical_gaussians_give_the_gaussians_curves_to_rounding():
    import asperity

    m = Mixture(0.5, 0.0, 1.0, 0.0, 1.0)
    for gamma in (0.0, 1e-3):
        a = asperity.load_curve([0.1, 10.0, 1e3], 0.01, 1000.0, gamma, heights=m)
        b = asperity.load_curve([0.1, 10.0, 1e3], 0.01, 1000.0, gamma)
        for key in ("d", "F", "area", "contacts"):
            np.testing.assert_allclose(getattr(a, key), getattr(b, key), rtol=4e-16, atol=0)
    assert asperity.pull_off(0.003, 1000.0, 1e-3, heights=m).force == asperity.pull_off(0.003, 1000.0, 1e-3).force
