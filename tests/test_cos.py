"""The COS transition equation (asperity.cos): exact JKR and DMT at alpha_t = 1, 0, and the
published conversions measured against the exact Maugis-Dugdale solution.

Measured here (0.01 <= lambda <= 100, 41 values): the critical load P_c-hat of COS Eq (12a)
is within 1.7 % of the exact load-controlled pull-off, the zero-load radius a0-hat of
Eq (12b) within 1.4 %, the transition parameter of Eq (10) within 0.04 of the alpha_t that
best fits the exact a(P), and that best COS curve is within 0.9 % (rms) of the exact one."""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from scipy import optimize

from asperity import cos, dmt, jkr
from asperity import maugis_dugdale as md
from asperity.maugis_dugdale_load import md_solve_load

R, W, E_STAR = 20e-9, 0.3, 1e11
K = 4 / 3 * E_STAR


def test_alpha_one_is_jkr_exactly():
    P = np.linspace(-1.5 * math.pi * W * R, 1e-7, 60)
    a0 = (6 * math.pi * W * R**2 / K) ** (1 / 3)
    a = cos.cos_contact_radius(P, a0=a0, Pc=-1.5 * math.pi * W * R, alpha_t=1.0)
    np.testing.assert_allclose(a, jkr.jkr_contact_radius(P, R=R, w=W, E_star=E_STAR), rtol=1e-13)


def test_alpha_zero_is_dmt_exactly():
    P = np.linspace(-2 * math.pi * W * R, 1e-7, 60)
    a0 = (2 * math.pi * W * R**2 / K) ** (1 / 3)
    a = cos.cos_contact_radius(P, a0=a0, Pc=-2 * math.pi * W * R, alpha_t=0.0)
    np.testing.assert_allclose(a, dmt.dmt_contact_radius(P, R=R, w=W, E_star=E_STAR), rtol=1e-13, atol=1e-22)


def test_friction_is_tau_pi_a_squared():
    P = np.linspace(-1.0, 4.0, 11)
    a = cos.cos_contact_radius(P, a0=2.0, Pc=-1.0, alpha_t=0.4)
    np.testing.assert_allclose(cos.cos_friction(P, F0=3.0 * math.pi * 4.0, Pc=-1.0, alpha_t=0.4),
                               3.0 * math.pi * a * a, rtol=1e-14)
    assert float(cos.cos_friction(-1.0, F0=1.0, Pc=-1.0, alpha_t=0.0)) == 0.0  # DMT: no contact at pull-off


def test_limits_of_the_fitted_constants():
    assert float(cos.cos_pull_off_hat(0.0)) == -2.0
    assert float(cos.cos_pull_off_hat(1e12)) == pytest.approx(-1.5, rel=1e-12)
    assert float(cos.cos_radius_hat(0.0)) == pytest.approx(2 ** (1 / 3), rel=2e-3)  # 1.261 vs 1.2599
    assert float(cos.cos_radius_hat(1e12)) == pytest.approx(6 ** (1 / 3), rel=2e-3)  # 1.819 vs 1.8171
    # a lambda so large that lambda^1.4 overflows: the JKR limits, without an overflow warning
    assert float(cos.cos_pull_off_hat(1e300)) == -1.5
    assert float(cos.cos_radius_hat(1e300)) == pytest.approx(1.819, rel=1e-12)
    assert float(cos.cos_lambda(0.0)) == 0.0
    assert float(cos.cos_lambda(cos.ALPHA_T_MAX * (1 - 1e-12))) > 20


@given(st.floats(0.0, 10.0))  # beyond, alpha_t is within rounding of 1/1.02
def test_lambda_alpha_round_trip(lam):
    assert float(cos.cos_lambda(cos.cos_alpha(lam))) == pytest.approx(lam, rel=1e-9, abs=1e-12)


LAMS = np.geomspace(0.01, 100, 41)


def _best_alpha(lam):
    po = md.md_pull_off(lam, "load")
    A0 = md_solve_load([0.0], lam)[0][0]
    P = np.linspace(po.P, 10.0, 400)
    A = md_solve_load(P, lam)[0]

    def rms(alpha):
        return np.sqrt(np.mean((cos.cos_contact_radius(P, a0=A0, Pc=po.P, alpha_t=alpha) / A - 1) ** 2))

    best = optimize.minimize_scalar(rms, bounds=(0.0, 1.0), method="bounded", options={"xatol": 1e-10})
    return po.P, A0, best.x, best.fun


def test_conversions_against_the_exact_maugis_dugdale_solution():
    worst = np.zeros(4)
    for lam in LAMS:
        Pc, A0, alpha, rms = _best_alpha(lam)
        worst = np.maximum(worst, [abs(cos.cos_pull_off_hat(lam) / Pc - 1), abs(cos.cos_radius_hat(lam) / A0 - 1),
                                   abs(cos.cos_alpha(lam) - alpha), rms])
    # COS fitted these to Maugis' solution "to within about a percent"; measured here:
    assert worst[0] < 0.017  # P_c-hat, Eq (12a)
    assert worst[1] < 0.014  # a0-hat, Eq (12b)
    assert worst[2] < 0.04  # alpha_t(lambda), Eq (10)
    assert worst[3] < 0.009  # the shape of a(P) itself
    # and a misquoted constant would show: 0.924 -> 0.294 moves alpha_t by far more
    assert abs((1 - math.exp(-1.0 / 0.294)) / 1.02 - _best_alpha(1.0)[2]) > 0.2


@pytest.mark.parametrize("func, kwargs, match", [
    (cos.cos_contact_radius, {"a0": 1.0, "Pc": 1.0, "alpha_t": 0.5}, r"^Pc \(critical load"),
    (cos.cos_contact_radius, {"a0": 1.0, "Pc": -1.0, "alpha_t": 1.5}, r"^alpha_t must lie in \[0, 1\]"),
    (cos.cos_contact_radius, {"a0": -1.0, "Pc": -1.0, "alpha_t": 0.5}, "^a0 must be > 0"),
    (cos.cos_friction, {"F0": 1.0, "Pc": -1.0, "alpha_t": np.nan}, "^alpha_t must be finite"),
])
def test_bad_input(func, kwargs, match):
    with pytest.raises(ValueError, match=match):
        func([0.0], **kwargs)
    with pytest.raises(ValueError, match=r"^P \(load\) must be >= Pc"):
        cos.cos_friction([-2.0], F0=1.0, Pc=-1.0, alpha_t=0.5)
    with pytest.raises(ValueError, match=r"alpha_t must lie in \[0, 1/1.02"):
        cos.cos_lambda(0.99)
    with pytest.raises(ValueError, match=r"^lam \(Maugis parameter\) must be >= 0"):
        cos.cos_pull_off_hat(-1.0)


def test_shapes_that_do_not_broadcast_are_named():
    """Found by tests/test_fuzz_api.py (random runs): a named error, not NumPy's message."""
    for call, needle in ((lambda: cos.cos_contact_radius([1.0, 2.0], a0=1.0, Pc=[-1.0, -1.0, -1.0], alpha_t=0.5),
                          "^P, Pc, alpha_t must have shapes that broadcast"),
                         (lambda: cos.cos_contact_radius([1.0, 2.0], a0=[1.0, 1.0, 1.0], Pc=-1.0, alpha_t=0.5),
                          "^a0, P must have shapes that broadcast"),
                         (lambda: cos.cos_friction([1.0, 2.0], F0=[1.0, 1.0, 1.0], Pc=-1.0, alpha_t=0.5),
                          "^F0, P must have shapes that broadcast")):
        with pytest.raises(ValueError, match=needle):
            call()
