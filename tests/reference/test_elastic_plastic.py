"""The reference Jackson-Green asperity and its integrals against closed forms."""

import math

import pytest
from scipy import special

from asperity.reference import gw_moment, jg_asperity, jg_critical_penetration, jg_load_point, jg_separation_point


def test_hertz_below_yield():
    alpha, beta, nu, H = 0.02, 500.0, 0.3, 0.01
    u_c = jg_critical_penetration(alpha, nu, H)
    for u in (0.1 * u_c, 0.99 * u_c):
        got = jg_asperity(u, alpha, beta, nu, H)
        assert got["a"] == beta * math.sqrt(u)
        assert got["P"] == pytest.approx(8 / 3 / (1 - nu) * alpha * beta**2 * u**1.5, rel=1e-15)


def test_critical_penetration_closed_form():
    alpha, nu, H = 0.03, 0.35, 0.004
    C = 1.295 * math.exp(0.736 * nu)
    u_c0 = (math.pi * C * H / 2.84 / 2) ** 2 / alpha**2
    assert jg_critical_penetration(alpha, nu, H) == pytest.approx(u_c0, rel=1e-14)
    h = 0.7  # the quadratic u^2 = u_c0 (u + h), solved here by a root search
    assert jg_critical_penetration(alpha, nu, H, h) == pytest.approx(
        0.5 * (u_c0 + math.sqrt(u_c0**2 + 4 * u_c0 * h)), rel=1e-12)


def test_transitions_are_ordered_and_continuous():
    alpha, beta, nu, H = 0.05, 1000.0, 0.44, 0.005
    got = jg_asperity(1.0, alpha, beta, nu, H)
    assert got["u_c"] < got["u_x"] < got["u_t"]  # nu = 0.44: the load leaves Hertz before 1.9
    for u0 in (got["u_x"], got["u_t"]):
        lo, hi = (jg_asperity(u0 * (1 + s * 1e-12), alpha, beta, nu, H) for s in (-1, 1))
        assert hi["P"] == pytest.approx(lo["P"], rel=1e-10) and hi["a"] == pytest.approx(lo["a"], rel=1e-10)


def test_integrals_of_a_hard_asperity_are_the_hertz_moments():
    # alpha small and H/E* large: u_c ~ 640 sigma, nothing yields.
    alpha, beta, nu, H = 0.005, 1000.0, 0.3, 0.142
    for d in (-1.0, 0.0, 2.0):
        ref = jg_separation_point(d, alpha, beta, nu, H, tau_f1=0.01, tau_f2=0.01)
        assert ref["contacts"] == pytest.approx(special.ndtr(-d), rel=1e-11)
        assert ref["area"] == pytest.approx(beta**2 * gw_moment(d, 1.0), rel=1e-10)
        assert ref["P"] == pytest.approx(8 / 3 / (1 - nu) * alpha * beta**2 * gw_moment(d, 1.5), rel=1e-10)
        assert ref["F"] == pytest.approx(2 * math.pi * 0.01 * ref["area"], rel=1e-10)


def test_plastic_fraction_is_the_gaussian_tail():
    alpha, beta, nu, H = 0.05, 1000.0, 0.3, 0.005
    u_c = jg_critical_penetration(alpha, nu, H)
    for d in (-1.0, 1.0):
        assert jg_separation_point(d, alpha, beta, nu, H)["plastic"] == pytest.approx(special.ndtr(-(d + u_c)),
                                                                                      rel=1e-10)


def test_load_point_inverts_the_separation_point():
    args = (0.05, 1000.0, 0.3, 0.005, 0.3)
    point = jg_load_point(250.0, *args)
    assert jg_separation_point(point["d"], *args)["P"] == pytest.approx(250.0, rel=1e-12)
