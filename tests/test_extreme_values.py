"""Extreme magnitudes (1e300, 1e-300, the smallest subnormal) are named errors, never warnings or inf.

Found by running every public callable of the API fuzz (tests/test_fuzz_api.py) with each
parameter set to such values, one at a time; each case below failed before its fix (a
RuntimeWarning, a ZeroDivisionError or OverflowError, an infinite result, a message that did
not name the parameter, or a solver that never returned).
"""

from __future__ import annotations

import re
import warnings

import numpy as np
import pytest

from asperity import dmt, hertz, jkr, maugis_dugdale_load, persson, plasticity
from asperity.friction_stress import hk_slope_intercept
from asperity.heights.johnson import Johnson
from asperity.interaction import cgp_compliance, cgp_shift
from asperity.materials import Material

TINY, HUGE, SUB = 1e-300, 1e300, 5e-324
LAW = {"R": 1e-6, "w": 0.1, "E_star": 1e11}


def _named(call, name):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises((ValueError, TypeError)) as info:
            call()
    assert re.search(rf"(?<![A-Za-z0-9_]){re.escape(name)}(?![A-Za-z0-9_])", str(info.value)), str(info.value)


@pytest.mark.parametrize("call, name", [
    (lambda: hertz.hertz_normal_force(HUGE, R=1e-6, E_star=1e11), "delta"),
    (lambda: dmt.dmt_normal_force(HUGE, **LAW), "delta"),
    (lambda: dmt.dmt_contact_radius(1e-9, R=HUGE, w=0.1, E_star=1e11), "R"),
    (lambda: dmt.dmt_contact_radius(1e-9, R=1e-6, w=0.1, E_star=SUB), "E_star"),
    (lambda: jkr.jkr_contact_radius(1e-9, R=1e-6, w=HUGE, E_star=1e11), "w"),
    (lambda: jkr.jkr_normal_force(1e-9, R=1e-6, w=0.1, E_star=TINY), "E_star"),
    (lambda: jkr.jkr_normal_force(1e-9, R=1e-6, w=TINY, E_star=1e11), "w"),
    (lambda: jkr.jkr_normal_force(HUGE, **LAW), "delta"),
    (lambda: maugis_dugdale_load.md_normal_force(1e-9, R=1e-6, w=0.1, E_star=TINY, lam=1.0), "E_star"),
    (lambda: maugis_dugdale_load.md_normal_force(1e-9, R=1e-6, w=TINY, E_star=1e11, lam=1.0), "w"),
    (lambda: maugis_dugdale_load.md_normal_force(HUGE, **LAW, lam=1.0), "delta"),
    (lambda: maugis_dugdale_load.md_contact_radius([1e-9], R=HUGE, w=0.1, E_star=1e11, lam=1.0), "R"),
    (lambda: persson.persson_area_fraction(1e6, E_star=SUB, rms_slope=0.1), "E_star"),
    (lambda: persson.bgt_area_fraction(1e6, E_star=1e11, rms_slope=SUB), "rms_slope"),
    (lambda: plasticity.plasticity_index(1e11, TINY, 1e-9, 1e-6), "H"),
    (lambda: cgp_compliance(1e12, 1e-6, HUGE, 1e-9), "b"),
    (lambda: cgp_compliance(1e12, 1e-6, 3e-10, 1e-9, nu=[0.3]), "nu"),
    (lambda: cgp_shift(1e6, 1e-6, SUB), "E_star"),
    (lambda: Material("x", E=1e11, nu=0.3, b=3e-10, w=1.0, sigma0=SUB), "sigma0"),
])
def test_extreme_values_are_named_errors(call, name):
    _named(call, name)


def test_tiny_skewness_is_the_symmetric_curve():
    """A skewness below rounding (1e-20, a subnormal) fits like skewness 0, for S_U and S_B."""
    for kurt in (4.0, 2.5):
        j0, j = Johnson(skew=0.0, kurt=kurt), Johnson(skew=1e-20, kurt=kurt)
        assert j.kind == j0.kind and j.gamma == pytest.approx(j0.gamma, abs=1e-15)
        assert Johnson(skew=SUB, kurt=kurt).delta == pytest.approx(j0.delta, rel=1e-12)


def test_hurtado_kim_constants_of_any_magnitude_give_a_finite_line():
    from asperity.friction_stress import A1, A2, TAU_F1

    slope, intercept = hk_slope_intercept(tau_f2=SUB)
    assert np.isfinite(slope) and np.isfinite(intercept)
    # the line still passes through (log a1, log tau_f1) and (log a2, log tau_f2)
    assert slope * np.log10(A1) + intercept == pytest.approx(np.log10(TAU_F1), rel=1e-12)
    assert slope * np.log10(A2) + intercept == pytest.approx(np.log10(SUB), rel=1e-12)


def test_soft_springs_are_refused_by_name():
    from asperity.cycle import cycle

    _named(lambda: cycle(0.02, 50.0, 0.02, preload=10.0, n=20, stiffness=1e-300), "stiffness")


def test_icha_and_bem_refuse_pressures_out_of_range():
    pytest.importorskip("ContactMechanics")
    from asperity.icha import icha_contact
    from asperity.validation.bem import bem_contact
    from asperity.validation.surfaces import synthetic_surface

    topo = synthetic_surface("self-affine", 4e-6, 16, short_cutoff=1e-6, seed=1)
    for func in (icha_contact, lambda t, P, E_star: bem_contact(t, P, E_star=E_star, progress=False)):
        _named(lambda f=func: f(topo, [1e-3], E_star=3.0), "E_star")      # mean pressure 2e7 E*
        _named(lambda f=func: f(topo, [TINY], E_star=1e11), "P")          # 6e-301 E*: never returned


@pytest.mark.parametrize("alpha, beta", [(1e-101, 1000.0), (1e100, 1.0), (0.01, 1e101), (0.01, 1e-101),
                                         (1e-60, 1e-100)])
def test_alpha_and_beta_outside_the_documented_domain_are_refused(alpha, beta):
    """docs/numerics.md says alpha and beta lie between 1e-100 and 1e100; a docs check found
    alpha = 1e-101 answered (mu = 7.7e98) by separation_curve without adhesion."""
    import asperity

    with pytest.raises(ValueError, match=r"alpha and beta between 1e-100 and 1e100"):
        asperity.separation_curve([0.0], alpha, beta, 0.0)
