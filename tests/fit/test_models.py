"""The fit models predict exactly what the library computes; their parameters come from the registry."""

import math

import numpy as np
import pytest

import asperity
from asperity import dmt, hertz, jkr
from asperity.cos import cos_friction
from asperity.fit import force_separation_data, friction_load_data, get_model, pull_off_data
from asperity.maugis_dugdale_load import md_contact_radius, md_normal_force, md_pull_off_force
from asperity.quantities import quantity

from .conftest import E_STAR, SIGMA0, TAU, R, W, loads

V = {"R_m": R, "w_J_m2": W, "tau_Pa": TAU, "E_star_Pa": E_STAR, "sigma0_Pa": SIGMA0, "d0_m": 0.0}


@pytest.mark.parametrize("name, radius", [
    ("hertz", lambda P: hertz.hertz_contact_radius(np.maximum(P, 0), R=R, E_star=E_STAR)),
    ("jkr", lambda P: jkr.jkr_contact_radius(P, R=R, w=W, E_star=E_STAR)),
    ("dmt", lambda P: dmt.dmt_contact_radius(P, R=R, w=W, E_star=E_STAR)),
    ("md", lambda P: md_contact_radius(P, R=R, w=W, E_star=E_STAR, sigma0=SIGMA0)),
])
def test_law_friction_is_tau_pi_a_squared(name, radius):
    P = loads(12, lo=-1.2) if name != "hertz" else np.linspace(1e-9, 5e-8, 12)
    model = get_model(name)
    F, clamped = model.friction(P, V)
    np.testing.assert_allclose(F, TAU * math.pi * radius(P) ** 2, rtol=1e-13)
    assert clamped == 0
    mu, _ = model.predict(friction_load_data(P[P > 0], mu=np.ones(np.sum(P > 0)), physical=True), V)
    np.testing.assert_allclose(mu, TAU * math.pi * radius(P[P > 0]) ** 2 / P[P > 0], rtol=1e-13)


def test_loads_below_the_pull_off_are_clamped_and_counted():
    model = get_model("jkr")
    floor = -jkr.jkr_pull_off_force(R=R, w=W)
    F, clamped = model.friction(np.array([2 * floor, floor, 0.0]), V)
    assert clamped == 1 and F[0] == F[1]
    F, clamped = get_model("md").friction(np.array([-1e-6, 1e-9]), V)
    assert clamped == 1
    assert F[0] == pytest.approx(TAU * math.pi * md_contact_radius(
        -md_pull_off_force(R=R, w=W, E_star=E_STAR, sigma0=SIGMA0), R=R, w=W, E_star=E_STAR, sigma0=SIGMA0) ** 2)


def test_force_and_pull_off_of_the_laws():
    delta = np.linspace(0.0, 1e-9, 5)
    np.testing.assert_allclose(get_model("jkr").force(-delta, V)[0], jkr.jkr_normal_force(delta, R=R, w=W,
                                                                                          E_star=E_STAR))
    np.testing.assert_allclose(get_model("md").force(-delta, V)[0],
                               md_normal_force(delta, R=R, w=W, E_star=E_STAR, sigma0=SIGMA0), rtol=1e-14)
    np.testing.assert_allclose(get_model("dmt").force(0.5e-9 - delta, {**V, "d0_m": 0.5e-9})[0],
                               dmt.dmt_normal_force(delta, R=R, w=W, E_star=E_STAR))
    radii = np.array([1e-8, 3e-8])
    data = pull_off_data([1.0, 1.0], conditions={"R_m": radii}, physical=True)
    np.testing.assert_allclose(get_model("jkr").pull_off(data, V), 1.5 * math.pi * W * radii)
    np.testing.assert_allclose(get_model("md").pull_off(data, V),
                               [md_pull_off_force(R=r, w=W, E_star=E_STAR, sigma0=SIGMA0) for r in radii])


def test_gw_predicts_the_library():
    P = np.geomspace(1.0, 1e3, 8)
    model = get_model("gw")
    v = {"alpha": 0.01, "beta": 1000.0, "gamma": 1e-3, "nu": 0.3, "h_over_b": 1.0, "tau_f1": 1 / 43,
         "tau_f2": 1 / 43 / 30, "a1": 28.0, "a2": 8e4, "d0": 0.0}
    np.testing.assert_allclose(model.friction(P, v)[0], asperity.load_curve(P, 0.01, 1000.0, 1e-3).F, rtol=1e-13)
    d = np.linspace(-1.0, 3.0, 7)
    np.testing.assert_allclose(model.force(d, v)[0], asperity.separation_curve(d, 0.01, 1000.0, 1e-3).P, rtol=1e-13)
    po = asperity.pull_off(0.01, 1000.0, 1e-3).force
    floor_F = asperity.Model(0.01, 1000.0, 1e-3).load_curve([-po * (1 - 1e-12)]).F[0]
    F, clamped = model.friction(np.array([-2 * po, 1.0]), v)
    assert clamped == 1 and F[0] == pytest.approx(floor_F, rel=1e-9)
    hertz_v = {**v, "gamma": 0.0}
    F, clamped = model.friction(np.array([-1.0, 0.0, 1.0]), hertz_v)
    assert clamped == 2 and F[0] == F[1] == 0.0


@pytest.mark.filterwarnings("ignore::asperity.plasticity.PlasticityWarning")  # gold yields
def test_gw_physical_predicts_the_contact():
    from asperity.physical import PhysicalContact, Surface

    contact = PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6))
    model = get_model("gw", contact=contact)
    specs = model.specs(friction_load_data([1e-3], [1e-4], physical=True))
    v = {k: s.value for k, s in specs.items()}
    P = np.geomspace(1e-3, 1.0, 6)
    np.testing.assert_allclose(model.friction(P, v)[0], contact.load_curve(P).F, rtol=1e-12)
    assert v["tau1_Pa"] == pytest.approx(contact.G_star / 43)
    d = np.array([0.0, 2e-9, 5e-9])
    data = force_separation_data(d, [1.0, 1.0, 1.0], physical=True)
    assert "d0_m" in model.specs(data)
    np.testing.assert_allclose(model.force(d, {**v, "d0_m": 0.0})[0], contact.separation_curve(d).P, rtol=1e-12)


def test_parameter_specs_come_from_the_registry():
    phys = friction_load_data([1e-9], [1e-10], physical=True)
    dim = friction_load_data([1.0], [0.1])
    jkr_specs = get_model("jkr").specs(phys)
    assert list(jkr_specs) == ["R_m", "E_star_Pa", "w_J_m2", "tau_Pa"]
    assert [n for n, s in jkr_specs.items() if s.vary] == ["w_J_m2", "tau_Pa"]
    assert jkr_specs["w_J_m2"].log == quantity("w").log and jkr_specs["w_J_m2"].unit == "J/m^2"
    assert list(get_model("cos").specs(phys)) == ["F0_N", "Pc_N", "alpha_t"]
    assert list(get_model("cos").specs(dim)) == ["F0", "Pc", "alpha_t"]
    assert get_model("cos").specs(dim)["Pc"].hi == 0.0 and get_model("cos").specs(dim)["alpha_t"].hi == 1.0
    gw = get_model("gw").specs(dim)
    assert [n for n, s in gw.items() if s.vary] == ["alpha", "beta", "gamma"]
    assert all(gw[n].log for n in ("alpha", "beta", "gamma", "tau_f1", "a2")) and not gw["nu"].log


def test_data_driven_starts():
    P = loads(20)
    data = friction_load_data(P, TAU * math.pi * jkr.jkr_contact_radius(P, R=R, w=W, E_star=E_STAR) ** 2,
                              physical=True)
    start = get_model("jkr").start(data, {"R_m": R, "E_star_Pa": E_STAR, "w_J_m2": None, "tau_Pa": None})
    assert 0.5 * W < start["w_J_m2"] < 2 * W and 0.3 * TAU < start["tau_Pa"] < 3 * TAU
    cos = get_model("cos").start(data, {"F0_N": None, "Pc_N": None, "alpha_t": 0.5})
    assert cos["Pc_N"] < P.min() and cos["F0_N"] > 0
    F = cos_friction(P, F0=1e-9, Pc=2 * P.min(), alpha_t=0.5)
    assert F.shape == P.shape


@pytest.mark.filterwarnings("ignore::asperity.PlasticityWarning")
@pytest.mark.parametrize("kwargs", [{"adhesion": False, "plasticity": "jackson-green"},
                                    {"adhesion": False, "interaction": "cgp2008"},
                                    {"adhesion": False, "plasticity": "jackson-green", "h_star": 1e-6,
                                     "hardness": 188e6},
                                    {"heights": "weibull:skew=0.5"}])
def test_gw_fit_model_keeps_every_setting_of_the_contact(kwargs):
    """At the contact's own values the fit model's friction is the contact's: nothing is dropped."""
    from asperity.heights import parse_heights
    from asperity.physical import PhysicalContact, Surface

    if "heights" in kwargs:
        kwargs = {"heights": parse_heights(kwargs["heights"])}
    contact = PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6), **kwargs)
    model = get_model("gw", contact=contact)
    P = np.geomspace(1e-4, 1e-1, 5)
    values = {k: s.value for k, s in model.specs(friction_load_data(P, np.ones(5), physical=True)).items()}
    F, clamped = model.friction(P, values)
    np.testing.assert_allclose(F, contact.load_curve(P).F, rtol=1e-12)
    assert not clamped


def test_gw_with_other_heights_predicts_the_library():
    """GWFit(heights=...) evaluates the dimensionless Model with those heights; a physical fit
    refuses them (the contact's are used)."""
    from asperity.fit.gw import GWFit
    from asperity.heights import PearsonIII

    h = PearsonIII(skew=0.8)
    P = np.geomspace(1.0, 1e3, 6)
    v = {"alpha": 0.01, "beta": 1000.0, "gamma": 1e-3, "nu": 0.3, "h_over_b": 1.0, "tau_f1": 1 / 43,
         "tau_f2": 1 / 43 / 30, "a1": 28.0, "a2": 8e4}
    got = GWFit(heights=h).friction(P, v)[0]
    np.testing.assert_allclose(got, asperity.Model(0.01, 1000.0, 1e-3, heights=h).load_curve(P).F, rtol=1e-13)
    assert not np.allclose(got, asperity.load_curve(P, 0.01, 1000.0, 1e-3).F, rtol=1e-3)
    from asperity.physical import PhysicalContact, Surface

    contact = PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6))
    with pytest.raises(ValueError, match="^heights: a physical fit takes the contact's summit heights"):
        GWFit(contact=contact, heights=h)
    with pytest.raises((TypeError, ValueError), match="^heights must be a HeightDistribution"):
        GWFit(heights=3.0)
    with pytest.raises(ValueError, match="missing parameter"):  # a spec string is read, as on the command line
        GWFit(heights="weibull")


def test_gw_with_the_jackson_green_law_predicts_the_library_and_recovers_the_hardness():
    """GWFit(law=JacksonGreen(...)): no gamma, H_over_E and h_star_over_sigma fixed at the law's
    values unless varied; the friction is Model(..., law=...)'s, and a fit of noisy data from a
    known hardness brackets it."""
    from asperity.elastic_plastic import Elastic, JacksonGreen
    from asperity.fit import fit_friction_load, friction_load_data
    from asperity.fit.gw import GWFit

    law = JacksonGreen(0.004, 2.0)
    gw = GWFit(law=law)
    data = friction_load_data(np.geomspace(1.0, 1e4, 30), np.ones(30))
    specs = gw.specs(data)
    assert "gamma" not in specs and (specs["H_over_E"].value, specs["h_star_over_sigma"].value) == (0.004, 2.0)
    assert not specs["H_over_E"].vary and gw.name == "gw (jackson-green H/E*=0.004 h*/sigma=2)"
    v = {k: s.value for k, s in specs.items()} | {"alpha": 0.05, "beta": 1000.0}
    P = np.geomspace(1.0, 1e4, 30)
    np.testing.assert_allclose(gw.friction(P, v)[0], asperity.Model(0.05, 1000.0, law=law).load_curve(P).F,
                               rtol=1e-13)
    assert GWFit(law=Elastic()).name == "gw" and "gamma" in GWFit(law=Elastic()).specs(data)
    truth = asperity.Model(0.05, 1000.0, law=JacksonGreen(0.004, 0.0)).load_curve(P).F
    F = truth * (1 + 0.02 * np.random.default_rng(1).standard_normal(P.size))
    r = fit_friction_load(friction_load_data(P, F, F_err=0.02 * F), GWFit(law=JacksonGreen(0.006, 0.0)),
                          vary=["alpha", "beta", "H_over_E"], start={"alpha": 0.05, "beta": 1000.0}, ci="wald")
    lo, hi = r.parameters["H_over_E"].ci95
    assert lo < 0.004 < hi and r.values["H_over_E"] != 0.006 and r.redchi < 2.0


@pytest.mark.parametrize("kwargs, needle", [
    ({"law": "jackson-green"}, "law must be asperity.elastic_plastic.Elastic"),
    ({"law": 0.01}, "law must be"),
])
def test_gw_law_refusals(kwargs, needle):
    from asperity.fit.gw import GWFit

    with pytest.raises(ValueError, match=needle):
        GWFit(**kwargs)


def test_a_physical_fit_takes_the_contacts_law():
    from asperity.elastic_plastic import JacksonGreen
    from asperity.fit.gw import GWFit
    from asperity.physical import PhysicalContact
    from asperity.surface import Surface

    contact = PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6), adhesion=False)
    with pytest.raises(ValueError, match="^law: a physical fit takes the contact's per-asperity law"):
        GWFit(contact=contact, law=JacksonGreen(0.01))
