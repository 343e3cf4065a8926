"""asperity.jackson_green and jackson_green_fits: the published fits, Hertz below yield, continuity."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from asperity import jackson_green as jgc
from asperity import jackson_green_fits as jgf


class _Both:
    """The functions of both modules under one name, as the tests use them."""

    def __getattr__(self, name):
        return getattr(jgf, name) if hasattr(jgf, name) else getattr(jgc, name)


jg = _Both()

NU = [0.0, 0.2, 0.3, 0.44, 0.49]
E_Y = [1e-5, 1e-3, 5e-3, 0.03, 0.05]


# -- hand-written JG 2005 formulas (printed constants), independent of the module -------------------

def hand_C(nu):
    return 1.295 * math.exp(0.736 * nu)


def hand_area(w, ey):
    return w * (w / 1.9) ** (0.14 * math.exp(23.0 * ey))


def hand_load(w, ey, nu, area):
    a_over_R = math.pi * hand_C(nu) * ey / 2.0 * math.sqrt(area)
    HG = 2.84 * (1.0 - math.exp(-0.82 * a_over_R ** -0.7))
    return (math.exp(-0.25 * w ** (5 / 12)) * w**1.5
            + 4.0 * HG / hand_C(nu) * (1.0 - math.exp(-(w ** (5 / 9)) / 25.0)) * w)


def test_published_constants():
    assert (jg.C_PREFACTOR, jg.C_EXPONENT, jg.OMEGA_T) == (1.295, 0.736, 1.9)
    assert (jg.B_PREFACTOR, jg.B_EXPONENT) == (0.14, 23.0)
    assert (jg.HG_LIMIT, jg.HG_RATE, jg.HG_POWER) == (2.84, 0.82, 0.7)


@pytest.mark.parametrize("nu", np.linspace(0.0, 0.499, 11))
def test_C_fits_greens_exact_coefficient(nu):
    # Green (2005): C = 1.30075 + 0.87825 nu + 0.54373 nu^2, which JG's exponential fits to < 0.5 %.
    green = 1.30075 + 0.87825 * nu + 0.54373 * nu**2
    assert float(jg.jg_yield_coefficient(nu)) == pytest.approx(green, rel=5e-3)


def test_C_agrees_with_chang_etsion_bogy_at_nu_0_3():
    # CEB / Kogut-Etsion: K H / Y with K = 0.454 + 0.41 nu and H = 2.8 Y.
    assert float(jg.jg_yield_coefficient(0.3)) == pytest.approx(2.8 * (0.454 + 0.41 * 0.3), rel=1e-3)


def test_critical_values_by_hand():
    S_y, E, R, nu = 300e6, 200e9 / (1 - 0.3**2), 1e-4, 0.3
    C = hand_C(nu)
    w_c = (math.pi * C * S_y / (2 * E)) ** 2 * R
    assert float(jg.jg_critical_interference(S_y, E, R, nu)) == pytest.approx(w_c, rel=1e-14)
    # P_c and A_c are the Hertz load and area at omega_c.
    assert float(jg.jg_critical_load(S_y, E, R, nu)) == pytest.approx(4 / 3 * E * math.sqrt(R) * w_c**1.5, rel=1e-13)
    assert float(jg.jg_critical_area(S_y, E, R, nu)) == pytest.approx(math.pi * R * w_c, rel=1e-14)
    assert float(jg.jg_critical_load(S_y, E, R, nu)) == pytest.approx(
        4 / 3 * (R / E) ** 2 * (C * math.pi * S_y / 2) ** 3, rel=1e-13)


def test_yield_from_hardness_is_jg_small_contact_limit():
    assert float(jg.jg_yield_from_hardness(2.84e9)) == pytest.approx(1e9, rel=1e-15)
    assert float(jg.jg_hardness_ratio(0.0)) == 2.84
    assert float(jg.jg_hardness_ratio(1e-4)) == pytest.approx(2.84, rel=1e-12)


@pytest.mark.parametrize("w", [1.9, 2.5, 10.0, 110.0, 1000.0])
@pytest.mark.parametrize("ey", [1e-3, 5e-3, 0.02])
@pytest.mark.parametrize("nu", [0.2, 0.3, 0.45])
def test_published_fits_at_checkpoints(w, ey, nu):
    area = hand_area(w, ey)
    assert float(jg.jg_area_fit(w, ey)) == pytest.approx(area, rel=1e-13)
    assert float(jg.jg_area(w, ey)) == pytest.approx(area, rel=1e-13)
    assert float(jg.jg_load_fit(w, ey, nu)) == pytest.approx(hand_load(w, ey, nu, area), rel=1e-13)
    if w > 3.0:  # above every crossing for these nu: the law is the fit
        assert float(jg.jg_load(w, ey, nu)) == pytest.approx(hand_load(w, ey, nu, area), rel=1e-13)


def test_hardness_ratio_by_hand():
    for r in (0.01, 0.1, 0.3, 1.0):
        assert float(jg.jg_hardness_ratio(r)) == pytest.approx(2.84 * (1 - math.exp(-0.82 * r**-0.7)), rel=1e-14)


def test_radius_ratio_by_hand():
    assert float(jg.jg_radius_ratio(9.0, 0.002, 0.3)) == pytest.approx(math.pi * hand_C(0.3) * 0.002 / 2 * 3, rel=1e-14)


@pytest.mark.parametrize("nu", NU)
@pytest.mark.parametrize("ey", E_Y)
def test_hertz_below_the_critical_interference_exactly(nu, ey):
    w = np.linspace(0.0, 1.0, 101)
    assert np.array_equal(jg.jg_load(w, ey, nu), w**1.5)
    assert np.array_equal(jg.jg_area(w, ey), w)


@pytest.mark.parametrize("nu", NU)
@pytest.mark.parametrize("ey", E_Y)
def test_continuity_at_each_switch(nu, ey):
    wx = float(jg.jg_load_transition(ey, nu))
    assert 1.0 < wx < 4.2
    for w0, f in ((jg.OMEGA_T, lambda w: jg.jg_area(w, ey)), (wx, lambda w: jg.jg_load(w, ey, nu))):
        left, right = (float(f(w0 * (1 + s * 1e-12))) for s in (-1, 1))
        assert right == pytest.approx(left, rel=1e-10), (w0, left, right)
    # the load switches where the fit meets Hertz
    assert float(jg.jg_load_fit(wx, ey, nu)) == pytest.approx(wx**1.5, rel=1e-13)


@pytest.mark.parametrize("nu, expected_sign", [(0.0, 1), (0.2, 1), (0.3, 1), (0.44, -1), (0.49, -1)])
def test_the_jump_that_the_crossing_removes(nu, expected_sign):
    # JG switch at 1.9, where their load fit differs from Hertz (sign depends on nu through C).
    gap = float(jg.jg_load_fit(1.9, 1e-3, nu)) / 1.9**1.5 - 1.0
    assert np.sign(gap) == expected_sign and 0.001 < abs(gap) < 0.08
    wx = float(jg.jg_load_transition(1e-3, nu))
    assert (wx > 1.9) == (expected_sign > 0)


def test_crossing_by_bisection():
    # An independent bisection on the hand-written fit.
    ey, nu = 2e-3, 0.3

    def gap(w):
        return hand_load(w, ey, nu, hand_area(w, ey) if w > 1.9 else w) - w**1.5

    lo, hi = 1.9, 3.0
    assert gap(lo) > 0 > gap(hi)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if gap(mid) > 0 else (lo, mid)
    assert float(jg.jg_load_transition(ey, nu)) == pytest.approx(lo, rel=1e-12)


def test_slope_continuous_at_yield_and_jumps_at_1_9():
    ey, nu, h = 3e-3, 0.3, 1e-7
    for f, slope in ((lambda w: jg.jg_load(w, ey, nu), 1.5), (lambda w: jg.jg_area(w, ey), 1.0)):
        left = (float(f(1.0)) - float(f(1.0 - h))) / h
        right = (float(f(1.0 + h)) - float(f(1.0))) / h
        assert left == pytest.approx(slope, rel=1e-5) and right == pytest.approx(slope, rel=1e-5)
    B = float(jg.jg_area_exponent(ey))
    right = (float(jg.jg_area(1.9 + h, ey)) - 1.9) / h
    assert right == pytest.approx(1.0 + B, rel=1e-5)  # the area's slope is 1 + B past 1.9 (not continuous)


@settings(max_examples=60, deadline=None)
@given(nu=st.floats(0.0, 0.499), ey=st.floats(1e-5, 0.05), w=st.floats(1.0, 500.0))
def test_yielded_asperity_never_stiffer_than_hertz(nu, ey, w):
    assert float(jg.jg_load(w, ey, nu)) <= w**1.5 * (1 + 1e-12)
    assert float(jg.jg_area(w, ey)) >= w * (1 - 1e-15)


@settings(max_examples=40, deadline=None)
@given(nu=st.floats(0.0, 0.499), ey=st.floats(1e-5, 0.05))
def test_load_and_area_increase(nu, ey):
    w = np.geomspace(1e-3, 300.0, 2000)
    assert np.all(np.diff(jg.jg_load(w, ey, nu)) > 0)
    assert np.all(np.diff(jg.jg_area(w, ey)) > 0)


def test_broadcasting():
    w = np.linspace(0.5, 20, 12).reshape(3, 4)
    assert jg.jg_load(w, 1e-3, 0.3).shape == (3, 4)
    assert jg.jg_area(w, [[1e-3], [2e-3], [3e-3]]).shape == (3, 4)
    assert jg.jg_load_transition([1e-3, 2e-3], [[0.2], [0.3]]).shape == (2, 2)
    assert jg.jg_load([], 1e-3, 0.3).shape == (0,)


@pytest.mark.parametrize("call, match", [
    (lambda: jg.jg_yield_coefficient(-0.1), r"nu .*\[0, 0.5\)"),
    (lambda: jg.jg_yield_coefficient(0.5), r"nu"),
    (lambda: jg.jg_area(1.0, 0.06), r"e_y .*\(0, 0.05\]"),
    (lambda: jg.jg_area(1.0, 0.0), r"e_y \(yield strain S_y/E\*\) must lie in \(0, 0.05\]"),
    (lambda: jg.jg_load(-1.0, 1e-3, 0.3), r"omega_star must lie in \[0, 1e\+12\]"),
    (lambda: jg.jg_load(float("nan"), 1e-3, 0.3), r"omega_star must be finite"),
    (lambda: jg.jg_load(True, 1e-3, 0.3), r"omega_star must be a real number"),
    (lambda: jg.jg_critical_interference(1.0, -1.0, 1.0, 0.3), r"E_star must be > 0"),
    (lambda: jg.jg_hardness_ratio(-0.1), r"a_over_R must be >= 0"),
    (lambda: jg.jg_yield_from_hardness(None), r"H must be a real number"),
])
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()


@pytest.mark.parametrize("func", [jgc.jg_critical_interference, jgc.jg_critical_load, jgc.jg_critical_area])
@pytest.mark.parametrize("kwargs", [{"S_y": 1.0, "E_star": 6e-240, "R": 1.0},
                                    {"S_y": 1e200, "E_star": 1.0, "R": 1e200}])
def test_critical_values_that_overflow_are_named_errors(func, kwargs):
    with pytest.raises(ValueError, match="overflows double precision for .*(E_star|S_y)"):
        func(nu=0.3, **kwargs)  # and no RuntimeWarning before it (an error under pytest)


def test_huge_interferences_and_hardnesses_are_named_errors():
    """Found by tests/test_fuzz_api.py: overflow is a named error, never a RuntimeWarning."""
    from asperity.cos import cos_friction
    from asperity.elastic_plastic import critical_penetration
    from asperity.maugis_dugdale_load import md_contact_radius
    from asperity.nix_gao import ng_scaled_interference

    for call, needle in ((lambda: jgf.jg_load(1e300, 1e-3, 0.3), r"omega_star must lie in \[0, 1e\+12\]"),
                         (lambda: jgf.jg_area(1e13, 1e-3), r"omega_star must lie in"),
                         (lambda: critical_penetration(0.05, 0.3, 1e200), "H_over_E"),
                         (lambda: md_contact_radius([1e300], R=20e-9, w=0.1, E_star=1e11, lam=1.0), r"^P"),
                         (lambda: md_contact_radius([1e300], R=1e-300, w=1e-10, E_star=1e11, lam=1.0), r"P = "),
                         (lambda: ng_scaled_interference([1e154, 1e300], 1e-300, 2.0), "omega"),
                         (lambda: cos_friction(100.0, F0=1.2e308, Pc=-1.0, alpha_t=0.3), "F0")):
        with pytest.raises(ValueError, match=needle):
            call()
    assert float(jgf.jg_load(jgf.OMEGA_STAR_MAX, 1e-3, 0.3)) > 0  # finite up to the limit
    assert jgf.jg_area([], 1e-3).shape == jgf.jg_load_fit([], 1e-3, 0.3).shape == (0,)  # empty in, empty out
