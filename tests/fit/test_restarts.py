"""Restarts of a fit stuck in a local minimum: the starts, when they run, and that they find the truth."""

import dataclasses
import math

import numpy as np
import pytest

lmfit = pytest.importorskip("lmfit")
# gold on this surface is past yield by design (the example's synthetic probe): the elastic model is what is tested
pytestmark = pytest.mark.filterwarnings("ignore::asperity.PlasticityWarning")

import asperity  # noqa: E402
from asperity.fit import fit_friction_load, friction_load_data  # noqa: E402
from asperity.fit.restarts import RESTART_DECADES, restart_points  # noqa: E402
from asperity.materials import material  # noqa: E402
from asperity.physical import PhysicalContact, Surface  # noqa: E402


def test_restart_points_move_each_free_parameter_both_ways():
    params = lmfit.Parameters()
    params.add("log10_w", value=-0.5, min=-300, max=300)
    params.add("log10_tau", value=9.0, min=-300, max=9.5)  # +1 decade leaves the bound: left out
    params.add("x", value=2.0, min=0, max=10)  # linear, bounded: a tenth in from each bound
    params.add("y", value=-4.0)  # linear, open: half its value either way
    params.add("z", value=0.0, min=-1.0)  # linear, open side, at 0: left
    params.add("log10_fixed", value=1.0, vary=False)
    params.add("w", expr="10**log10_w")
    starts = restart_points(params)
    moved = sorted((name, round(p[name].value, 12))
                   for p in starts for name in ("log10_w", "log10_tau", "x", "y", "z", "log10_fixed")
                   if p[name].value != params[name].value)
    assert moved == [("log10_tau", 9.0 - RESTART_DECADES), ("log10_w", -0.5 - RESTART_DECADES),
                     ("log10_w", -0.5 + RESTART_DECADES), ("x", 1.0), ("x", 9.0), ("y", -6.0), ("y", -2.0)]
    assert all(sum(p[n].value != params[n].value for n in params if params[n].expr is None) == 1 for p in starts)
    assert params["log10_w"].value == -0.5  # the original is not touched


def test_a_cos_fit_stuck_in_a_local_minimum_is_restarted_out_of_it():
    """Found by a review: COS data of alpha_t = 0 fitted from the default start stopped at
    alpha_t = 0.3 with chi-square 69 for 37 degrees of freedom; restarts moved only the
    log-scaled F0 and stayed there.  Moving alpha_t and Pc too reaches the truth."""
    from asperity.cos import cos_friction

    P = np.linspace(-14e-9, 100e-9, 40)
    F = cos_friction(P, F0=20e-9, Pc=-15e-9, alpha_t=0.0)
    noise = np.random.default_rng(2).normal(size=(37, 40))[-1]
    data = friction_load_data(P, F * (1 + 0.03 * noise), F_err=0.03 * F, physical=True)
    stuck = fit_friction_load(data, "cos", restarts="never")
    res = fit_friction_load(data, "cos")
    assert res.chisqr < 0.6 * stuck.chisqr
    assert res.values["Pc_N"] == pytest.approx(-15e-9, rel=0.03) and res.values["alpha_t"] < 0.05
    assert any("a restart from another start reached" in w for w in res.warnings)


SURFACE = Surface(sigma_s=2e-9, R=300e-9, eta=3e13, area=4e-12)
TRUE_W, TAU1 = 0.5, 0.015


@pytest.fixture(scope="module")
def rough_data():
    """Friction against load from the rough-surface model with w = 0.5 J/m^2, 3 % noise, stated errors."""
    gold = dataclasses.replace(material("Au"), w=TRUE_W)
    truth = PhysicalContact(gold, SURFACE, friction=asperity.HurtadoKim(TAU1, TAU1 / 30))
    with pytest.warns(asperity.AsperityWarning, match="no pull-off"):  # 120 summits: the model's expectation
        pull = truth.pull_off().force
    P = np.concatenate([np.linspace(-0.8 * pull, 0.0, 6)[:-1], np.geomspace(0.05 * pull, 20 * pull, 25)])
    F = truth.load_curve(P).F
    rng = np.random.default_rng(11)
    F_noisy = F * (1 + 0.03 * rng.standard_normal(P.size))
    return friction_load_data(P, F_noisy, F_err=0.03 * np.abs(F), physical=True)


@pytest.mark.parametrize("w_start", [0.2, 0.05, 3.0])
def test_restarts_reach_the_generating_work_of_adhesion(rough_data, w_start):
    gold = dataclasses.replace(material("Au"), w=w_start)
    contact = PhysicalContact(gold, SURFACE)
    kws = {"contact": contact, "vary": ["w_J_m2", "tau1_Pa"], "expr": {"tau2_Pa": "tau1_Pa / 30"}, "ci": "wald"}
    auto = fit_friction_load(rough_data, "gw", **kws)
    never = fit_friction_load(rough_data, "gw", restarts="never", **kws)
    always = fit_friction_load(rough_data, "gw", restarts="always", **kws)
    assert auto.chisqr <= never.chisqr * (1 + 1e-9) and always.chisqr <= auto.chisqr * (1 + 1e-6)
    # within 4 standard errors of the truth (a 95 % interval misses it one time in 20: this seed is one;
    # 19 of seeds 0-19 cover it, measured when this test was written)
    w = auto.parameters["w_J_m2"]
    assert abs(w.value - TRUE_W) < 4 * w.stderr and w.stderr < 0.01
    # a good fit with 28 degrees of freedom: chi-square near 28
    assert auto.chisqr < 60
    if never.chisqr > auto.chisqr * 1.01:  # a restart won: the result says so
        assert any("restart" in w for w in auto.warnings)
    else:
        assert not any("restart" in w for w in auto.warnings)


def test_a_good_fit_does_not_restart(rough_data):
    gold = dataclasses.replace(material("Au"), w=0.6)
    kws = {"contact": PhysicalContact(gold, SURFACE), "vary": ["w_J_m2", "tau1_Pa"],
           "expr": {"tau2_Pa": "tau1_Pa / 30"}, "ci": "wald"}
    auto = fit_friction_load(rough_data, "gw", **kws)
    never = fit_friction_load(rough_data, "gw", restarts="never", **kws)
    assert auto.nfev == never.nfev and math.isclose(auto.chisqr, never.chisqr, rel_tol=0, abs_tol=0)
