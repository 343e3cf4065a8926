"""Dimensionless groups (Eqs 7, 15-17, 20) checked against their physical definitions."""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from asperity import groups


def physical(sigma, R, b, E, nu, w, h):
    """Maugis' scales (Eq 14) straight from physical quantities."""
    E_star = E / (1 - nu**2)
    G = E / (2 * (1 + nu))
    K = 4 / 3 * E_star
    sigma0 = w / h
    return {
        "E_star": E_star, "G": G,
        "lam": 2 * sigma0 * (R / (math.pi * w * K**2)) ** (1 / 3),
        # u = Delta * (pi^2 w^2 R / K^2)^(1/3); u_bar = u / sigma
        "delta_hat": (math.pi**2 * w**2 * R / K**2) ** (1 / 3) / sigma,
        # P = P_M pi w R; P_bar = P / (G b^2)
        "P_hat": G * b**2 / (math.pi * w * R),
        # a = A (pi w R^2 / K)^(1/3); a_bar = a / b
        "A_hat": b / (math.pi * w * R**2 / K) ** (1 / 3),
    }


@given(
    sigma=st.floats(1e-10, 1e-6), R=st.floats(1e-8, 1e-3), b=st.floats(1e-10, 5e-10),
    E=st.floats(1e9, 1e12), nu=st.floats(-0.5, 0.49), w=st.floats(1e-3, 5.0),
    h_over_b=st.floats(0.2, 5.0),
)
def test_scales_match_physical_definitions(sigma, R, b, E, nu, w, h_over_b):
    ref = physical(sigma, R, b, E, nu, w, h_over_b * b)
    alpha = groups.roughness_alpha(sigma, R)
    beta = groups.regime_beta(sigma, R, b)
    gamma = groups.adhesion_gamma(w, ref["E_star"], b)
    assert groups.maugis_lambda(alpha, beta, gamma, h_over_b) == pytest.approx(ref["lam"], rel=1e-12)
    assert groups.penetration_scale(alpha, beta, gamma) == pytest.approx(ref["delta_hat"], rel=1e-12)
    assert groups.load_scale(alpha, beta, gamma, nu) == pytest.approx(ref["P_hat"], rel=1e-12)
    assert groups.radius_scale(alpha, beta, gamma) == pytest.approx(ref["A_hat"], rel=1e-12)
    assert groups.sigma_over_b(alpha, beta) == pytest.approx(sigma / b, rel=1e-12)
    assert groups.radius_over_b(alpha, beta) == pytest.approx(R / b, rel=1e-12)
    assert groups.modulus_ratio(nu) == pytest.approx(ref["E_star"] / ref["G"], rel=1e-12)


def test_printed_p_hat_breaks_the_gamma_to_zero_limit():
    # DMT per asperity: P_M = Delta^(3/2) - 2 -> Delta^(3/2).  Converting with the derived
    # P_hat reproduces Eq 6's Hertz force; the printed one is off by a factor 1/alpha.
    alpha, beta, gamma, nu, u = 0.01, 1000.0, 1e-9, 0.3, 0.7
    delta = u / groups.penetration_scale(alpha, beta, gamma)
    hertz = (8 / 3) / (1 - nu) * alpha * beta**2 * u**1.5
    derived = delta**1.5 / groups.load_scale(alpha, beta, gamma, nu)
    printed = delta**1.5 / groups.load_scale(alpha, beta, gamma, nu, form="printed")
    assert derived == pytest.approx(hertz, rel=1e-12)
    assert printed == pytest.approx(hertz / alpha, rel=1e-12)


def test_paper_default_lambda():
    # alpha 1e-2, beta 1e3, gamma 1e-3, h = b: (9e-3/(2 pi 1e-2))^(1/3)
    assert groups.maugis_lambda(0.01, 1000, 1e-3) == pytest.approx((0.009 / (0.02 * math.pi)) ** (1 / 3))


def test_arrays_broadcast():
    out = groups.maugis_lambda(np.array([0.01, 0.02]), 1000, np.array([[1e-3], [2e-3]]))
    assert out.shape == (2, 2)


@pytest.mark.parametrize("call, name", [
    (lambda: groups.roughness_alpha(-1, 1), "sigma"),
    (lambda: groups.maugis_lambda(0.01, 0, 1e-3), "beta"),
    (lambda: groups.maugis_lambda(0.01, 10, 1e-3, h_over_b=np.nan), "h_over_b"),
    (lambda: groups.load_scale(0.01, 10, 1e-3, nu=0.5), "nu"),
    (lambda: groups.load_scale(0.01, 10, 1e-3, form="x"), "form"),
    (lambda: groups.adhesion_gamma(1.0, np.inf, 1e-10), "E_star"),
])
def test_bad_input(call, name):
    with pytest.raises(ValueError, match=name):
        call()
