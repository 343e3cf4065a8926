"""Hurtado-Kim law (Eqs 2-4) and the constant-stress law."""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from asperity.friction_stress import (
    A1,
    A2,
    TAU_F1,
    TAU_F2,
    ConstantShear,
    FrictionLaw,
    HurtadoKim,
    hk_friction_force,
    hk_friction_stress,
    hk_slope_intercept,
)


def test_paper_constants():
    assert TAU_F1 == 1 / 43 and TAU_F2 == TAU_F1 / 30 and A1 == 28 and A2 == 8e4


def test_slope_intercept_pass_through_both_corners():
    M, B = hk_slope_intercept()
    # The line of Eq 2 must pass through (a1, tau1) and (a2, tau2): Eq 3 solved by hand.
    assert M * math.log10(A1) + B == pytest.approx(math.log10(TAU_F1), rel=1e-14)
    assert M * math.log10(A2) + B == pytest.approx(math.log10(TAU_F2), rel=1e-14)
    assert M == pytest.approx(-math.log10(30) / math.log10(8e4 / 28), rel=1e-14)


def test_plateaus_and_region_two():
    a = np.array([0.0, 1.0, 27.9, 8.1e4, 1e9])
    tau = hk_friction_stress(a)
    np.testing.assert_allclose(tau, [TAU_F1, TAU_F1, TAU_F1, TAU_F2, TAU_F2], rtol=1e-14)
    # geometric midpoint of region 2 has the geometric mean stress
    mid = math.sqrt(A1 * A2)
    assert hk_friction_stress(mid) == pytest.approx(math.sqrt(TAU_F1 * TAU_F2), rel=1e-13)


@pytest.mark.parametrize("corner", [A1, A2])
def test_continuity_at_breakpoints(corner):
    eps = 1e-9
    lo, hi = hk_friction_stress([corner * (1 - eps), corner * (1 + eps)])
    assert hi == pytest.approx(lo, rel=1e-8)


@given(st.floats(0.0, 1e7), st.floats(0.0, 1e7))
def test_stress_non_increasing(a, b):
    lo, hi = sorted((a, b))
    t_lo, t_hi = hk_friction_stress([lo, hi])
    assert t_hi <= t_lo * (1 + 1e-14)


def test_force_has_pi():
    a = np.array([3.0, 300.0, 3e5])
    np.testing.assert_allclose(hk_friction_force(a), math.pi * hk_friction_stress(a) * a**2,
                               rtol=1e-15)
    assert hk_friction_force(10.0) == pytest.approx(math.pi * 100 / 43, rel=1e-14)


def test_law_objects_share_interface():
    for law in (HurtadoKim(), ConstantShear(0.01)):
        assert isinstance(law, FrictionLaw)
    np.testing.assert_allclose(ConstantShear(0.01).stress([1.0, 1e6]), [0.01, 0.01])
    assert HurtadoKim().breakpoints() == (A1, A2)
    assert ConstantShear().breakpoints() == ()


@pytest.mark.parametrize("kwargs, name", [
    ({"tau_f1": -1}, "tau_f1"), ({"a1": 0}, "a1"), ({"a2": float("nan")}, "a2"),
    ({"a1": 100, "a2": 10}, "a2"),
])
def test_bad_constants(kwargs, name):
    with pytest.raises(ValueError, match=name):
        HurtadoKim(**kwargs)


def test_bad_radius():
    with pytest.raises(ValueError, match="a_bar"):
        hk_friction_stress([-1.0])
    with pytest.raises(ValueError, match="a_bar"):
        hk_friction_stress([np.nan])


@pytest.mark.parametrize("tau, match", [(np.array([0.1, 0.2]), "tau must be a scalar"), (-0.1, "tau"),
                                        (float("nan"), "tau"), ("0.1", "tau"), (None, "tau")])
def test_constant_shear_takes_one_positive_number(tau, match):
    """A user trial: an array was accepted and failed later in NumPy's words."""
    with pytest.raises(ValueError, match=match):
        ConstantShear(tau)
    assert ConstantShear(np.float64(0.02)) == ConstantShear(0.02)
