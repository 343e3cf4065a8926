"""Multi-asperity integrals (Eqs 5, 6, 9, 10, 18, 21) against closed forms and properties."""

import math

import mpmath as mp
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import asperity
from asperity.friction_stress import ConstantShear, HurtadoKim, hk_friction_stress
from asperity.multi_asperity import (
    contact_fraction,
    friction_coefficient,
    friction_force,
    mean_pressure,
    normal_force,
    real_contact_area,
)


def moment(d, k):
    with mp.workdps(40):
        d = mp.mpf(d)
        return float(mp.gamma(k + 1) * mp.exp(-d * d / 4) * mp.pcfd(-k - 1, d) / mp.sqrt(2 * mp.pi))


D = np.array([-3.0, -1.0, 0.0, 0.5, 2.0, 3.5, 5.0])
CASES = [(0.01, 1000.0), (0.001, 10.0), (0.3, 1e6), (0.05, 37.0)]


@pytest.mark.parametrize("alpha, beta", CASES)
def test_hertz_closed_forms(alpha, beta):
    nu = 0.3
    c = asperity.separation_curve(D, alpha, beta, 0.0, nu=nu)
    m0 = np.array([moment(x, 0) for x in D])
    m1 = np.array([moment(x, 1) for x in D])
    m32 = np.array([moment(x, 1.5) for x in D])
    np.testing.assert_allclose(c.contacts, m0, rtol=1e-12)
    np.testing.assert_allclose(c.area, beta**2 * m1, rtol=1e-12)
    np.testing.assert_allclose(c.P, (8 / 3) / (1 - nu) * alpha * beta**2 * m32, rtol=1e-12)


@pytest.mark.parametrize("law, tau", [
    (HurtadoKim(a1=1e12, a2=1e13), 1 / 43),          # all contacts in region 1
    (HurtadoKim(a1=1e-8, a2=1e-7), 1 / 43 / 30),     # all in region 3
    (ConstantShear(0.05), 0.05),
])
def test_friction_closed_form_single_region(law, tau):
    beta = 300.0
    F = friction_force(D, 0.02, beta, 0.0, friction=law)
    expected = 2 * math.pi * tau * beta**2 * np.array([moment(x, 1) for x in D])
    np.testing.assert_allclose(F, expected, rtol=1e-12)


def friction_mp(d, beta):
    """Eq 10 for Hertz contacts by mpmath quadrature, split at the HK radii."""
    with mp.workdps(30):
        def f(u):
            a = beta * mp.sqrt(u)
            tau = float(hk_friction_stress(float(a)))
            return 2 * mp.pi * tau * a**2 * mp.exp(-(d + u) ** 2 / 2) / mp.sqrt(2 * mp.pi)
        pts = [0] + [(a / beta) ** 2 for a in (28.0, 8e4) if (a / beta) ** 2 < 30] + [30]
        return float(mp.quad(f, pts))


@pytest.mark.parametrize("beta", [10.0, 100.0, 1e3, 1e5])
def test_friction_hurtado_kim_against_mpmath(beta):
    d = np.array([-2.0, 0.0, 1.5, 3.0])
    F = friction_force(d, 0.01, beta, 0.0)
    np.testing.assert_allclose(F, [friction_mp(x, beta) for x in d], rtol=1e-10)


def test_alpha_is_a_scaling_factor_without_adhesion():
    # Eqs 6, 10: P ~ alpha, F independent of alpha: alpha*mu vs P/alpha depends on beta only.
    a = asperity.separation_curve(D, 0.01, 500.0)
    b = asperity.separation_curve(D, 0.04, 500.0)
    np.testing.assert_allclose(b.P, 4 * a.P, rtol=1e-13)
    np.testing.assert_allclose(b.F, a.F, rtol=1e-13)
    np.testing.assert_allclose(0.04 * b.mu, 0.01 * a.mu, rtol=1e-13)


def test_gamma_to_zero_is_continuous():
    d = np.array([-1.0, 0.5, 2.0])
    base = asperity.separation_curve(d, 0.01, 1000.0, 0.0)
    diffs = []
    for gamma in [1e-4, 1e-7, 1e-10, 1e-13]:
        c = asperity.separation_curve(d, 0.01, 1000.0, gamma)
        diffs.append(max(np.max(np.abs(getattr(c, k) / getattr(base, k) - 1))
                         for k in ("P", "F", "area", "contacts")))
    assert all(x > y for x, y in zip(diffs, diffs[1:]))
    assert diffs[-1] < 1e-3


params = st.tuples(st.floats(1e-3, 0.3), st.floats(10.0, 1e6), st.floats(1e-6, 5e-2))


@given(params, st.floats(-3.0, 5.0))
def test_adhesion_enlarges_contact_and_lowers_force(p, d):
    alpha, beta, gamma = p
    hz = asperity.separation_curve([d], alpha, beta, 0.0)
    ad = asperity.separation_curve([d], alpha, beta, gamma)
    assert ad.contacts[0] >= hz.contacts[0] * (1 - 1e-12)
    assert ad.area[0] >= hz.area[0] * (1 - 1e-12)
    assert ad.P[0] <= hz.P[0] * (1 + 1e-12)


@given(st.floats(1e-3, 0.3), st.floats(10.0, 1e6), st.floats(-3.0, 6.0), st.floats(0.01, 2.0))
def test_hertz_monotone_in_separation(alpha, beta, d, step):
    c = asperity.separation_curve([d, d + step], alpha, beta, 0.0)
    for k in ("P", "F", "area", "contacts"):
        v = getattr(c, k)
        assert v[1] < v[0]
    assert 0 < c.contacts[1] < c.contacts[0] < 1


@given(params, st.floats(-3.0, 6.0))
def test_adhesive_outputs_are_finite_and_signed(p, d):
    c = asperity.separation_curve([d], *p)
    assert np.isfinite(c.P[0]) and c.F[0] > 0 and c.area[0] > 0 and 0 < c.contacts[0] <= 1 + 1e-12


def test_equation_functions_agree_with_curve():
    args = (0.005, 1000.0, 1e-3)
    c = asperity.separation_curve(D, *args)
    np.testing.assert_array_equal(normal_force(D, *args), c.P)
    np.testing.assert_array_equal(friction_force(D, *args), c.F)
    np.testing.assert_array_equal(real_contact_area(D, *args), c.area)
    np.testing.assert_array_equal(contact_fraction(D, *args), c.contacts)
    np.testing.assert_allclose(c.pressure, c.P * 0.7 / (2 * np.pi * c.area), rtol=1e-15)


def test_mu_and_pressure_undefined_cases():
    assert np.isnan(friction_coefficient(1.0, 0.0)) and np.isnan(friction_coefficient(1.0, -2.0))
    assert friction_coefficient(1.0, 4.0) == 0.25
    assert np.isnan(mean_pressure(1.0, 0.0))


def test_shape_preserved():
    d = np.linspace(0, 2, 6).reshape(2, 3)
    assert normal_force(d, 0.01, 100.0).shape == (2, 3)
    # a scalar separation gives a NumPy scalar, as a ufunc does (a review: 0-d arrays before)
    assert type(normal_force(0.5, 0.01, 100.0)) is np.float64


@pytest.mark.parametrize("func", [contact_fraction, normal_force, friction_force, real_contact_area])
def test_the_integrals_broadcast_over_the_parameters(func):
    """d (4,), alpha (3, 1), gamma (4,), nu and h/b scalars or arrays: the loop of scalar calls
    (a review: alpha, beta, gamma, nu, h/b were scalar-only, so Fig 3's sweep needed a loop)."""
    d = np.array([-1.0, 0.0, 1.0, 2.5])
    alpha = np.array([[0.01], [0.02], [0.05]])
    gamma = np.array([0.0, 1e-4, 1e-3, 1e-3])
    nu = np.array([0.25, 0.3, 0.3, 0.35])
    got = func(d, alpha, 1000.0, gamma, nu=nu, h_over_b=2.0)
    assert got.shape == (3, 4)
    for i, j in np.ndindex(got.shape):
        expected = func(d[j], float(alpha[i, 0]), 1000.0, gamma[j], nu=nu[j], h_over_b=2.0)
        assert got[i, j] == pytest.approx(float(expected), rel=1e-13, abs=1e-300)
    assert func(0.0, [0.01, 0.02], [100.0, 1000.0]).shape == (2,)
    assert func(0.0, (0.01, 0.02), range(100, 102)).shape == (2,)  # any array-like


def test_parameters_that_do_not_broadcast_or_leave_their_range_are_named():
    with pytest.raises(ValueError, match="^d, alpha, beta, gamma, nu, h_over_b must have shapes"):
        normal_force([0.0, 1.0], [0.01, 0.02, 0.03], 1000.0)
    with pytest.raises(ValueError, match="^alpha must be"):
        normal_force([0.0, 1.0], [0.01, -0.02], 1000.0)
    with pytest.raises(ValueError, match="^gamma must be finite"):
        normal_force(0.0, 0.01, 1000.0, [1e-3, np.nan])
    with pytest.raises(ValueError, match="^nu"):
        normal_force(0.0, 0.01, 1000.0, nu=[0.3, 0.7])
    with pytest.raises(ValueError, match="^P, area, nu must have shapes"):
        mean_pressure([1.0, 2.0], [1.0, 2.0], nu=[0.3, 0.3, 0.3])


class PlainGaussian(asperity.HeightDistribution):
    """The Gaussian through the generic interface only (no factorised sums)."""

    def pdf(self, z):
        z = np.asarray(z, dtype=float)
        return np.exp(-0.5 * z * z) / math.sqrt(2 * math.pi)

    def pdf_derivative(self, z, order):
        z = np.asarray(z, dtype=float)
        return (-z if order == 1 else z * z - 1.0) * self.pdf(z)

    def sf(self, z):
        return 0.5 * np.vectorize(math.erfc)(np.asarray(z) / math.sqrt(2))


def test_a_user_distribution_runs_through_the_generic_interface():
    P = np.geomspace(0.1, 1e4, 30)
    ref = asperity.load_curve(P, 0.01, 1000, 1e-3)
    got = asperity.load_curve(P, 0.01, 1000, 1e-3, heights=PlainGaussian())
    for key in ("d", "F", "area", "contacts"):
        np.testing.assert_allclose(getattr(got, key), getattr(ref, key), rtol=1e-11)
    assert asperity.pull_off(0.003, 1000, 1e-3, heights=PlainGaussian()).force == pytest.approx(
        asperity.pull_off(0.003, 1000, 1e-3).force, rel=1e-11)
