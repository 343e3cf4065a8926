"""asperity.elastic_plastic: the Jackson-Green law in the model's units, the registry, the Model with it."""

import math

import numpy as np
import pytest
from scipy import special

import asperity
from asperity import Model, reference
from asperity.asperity_law import AsperityLaw, ContactLaw, ModelParameters
from asperity.elastic_plastic import (
    LAWS,
    Elastic,
    JacksonGreen,
    JacksonGreenLaw,
    critical_penetration,
    make_law,
    plastic_fraction,
)
from asperity.friction_stress import ConstantShear
from asperity.hertz import hertz_force, hertz_radius
from asperity.jackson_green_fits import jg_area, jg_load, jg_load_transition
from asperity.nix_gao import ng_critical_interference

#: (alpha, beta, nu, H/E*, h*/sigma): plastic soon (psi = 10), gold-like (nu = 0.44), hard and
#: smooth with a size effect, and a nano-asperity whose size effect dominates.
CASES = [(0.05, 1000.0, 0.3, 0.005, 0.0), (0.01, 300.0, 0.44, 0.002, 0.0), (0.02, 1e4, 0.2, 0.01, 0.5),
         (0.1, 50.0, 0.3, 0.003, 20.0)]


def law(alpha=0.05, beta=1000.0, nu=0.3, H=0.005, h=0.0, **kw):
    return JacksonGreenLaw(ModelParameters(alpha, beta, nu=nu, **kw), H, h)


def test_is_a_contact_law_with_its_regime_boundaries_as_breakpoints():
    jgl = law()
    assert isinstance(jgl, ContactLaw)
    assert jgl.u_end == 0.0 and jgl.scale == 1.0
    assert list(jgl.breakpoints) == sorted(jgl.breakpoints)
    for u in (jgl.u_c, jgl.u_x, jgl.u_t):
        assert u in jgl.breakpoints
    # the Hurtado-Kim radii a1 = 28 and a2 = 8e4 mapped through the law's radius
    for a_k in (28.0, 8e4):
        hits = [u for u in jgl.breakpoints if abs(jgl.evaluate([u])[0][0] / a_k - 1) < 1e-10]
        assert len(hits) == 1


def test_units_by_hand():
    alpha, beta, nu, H = 0.05, 1000.0, 0.3, 0.005
    jgl = law(alpha, beta, nu, H)
    C = 1.295 * math.exp(0.736 * nu)
    u_c = (math.pi * C * H / 2.84 / 2) ** 2 / alpha**2  # omega_c / sigma = (pi C e_y / 2)^2 R / sigma
    assert jgl.u_c == pytest.approx(u_c, rel=1e-14)
    assert jgl.u_t == pytest.approx(1.9 * u_c, rel=1e-14)
    assert jgl.u_x == pytest.approx(float(jg_load_transition(H / 2.84, nu)) * u_c, rel=1e-14)
    # beyond the switches: a = beta sqrt(u_c A/A_c), P = (8/3)/(1 - nu) alpha beta^2 u_c^1.5 P/P_c
    u = np.array([3.0 * u_c, 50.0 * u_c])
    a, P = jgl.evaluate(u)
    w = u / u_c
    np.testing.assert_allclose(a, beta * np.sqrt(u_c * jg_area(w, H / 2.84)), rtol=1e-14)
    np.testing.assert_allclose(P, 8 / 3 / (1 - nu) * alpha * beta**2 * u_c**1.5 * jg_load(w, H / 2.84, nu),
                               rtol=1e-14)


@pytest.mark.parametrize("case", CASES)
def test_hertz_below_the_critical_interference_exactly(case):
    alpha, beta, nu, H, h = case
    jgl = law(alpha, beta, nu, H, h)
    u = np.concatenate([[-1.0, 0.0], np.linspace(0.0, jgl.u_c, 50)[1:]])
    a, P = jgl.evaluate(u)
    assert np.array_equal(a, hertz_radius(u, beta)) and np.array_equal(P, hertz_force(u, alpha, beta, nu))


@pytest.mark.parametrize("case", CASES)
def test_continuity_at_each_regime_boundary(case):
    jgl = law(*case)
    for u0 in (jgl.u_c, jgl.u_x, jgl.u_t):
        (a1, a2), (P1, P2) = jgl.evaluate([u0 * (1 - 1e-12), u0 * (1 + 1e-12)])
        assert a2 == pytest.approx(a1, rel=1e-10) and P2 == pytest.approx(P1, rel=1e-10), u0


@pytest.mark.parametrize("case", CASES)
def test_softer_than_hertz_and_increasing(case):
    alpha, beta, nu, H, h = case
    jgl = law(alpha, beta, nu, H, h)
    u = np.geomspace(jgl.u_c * 1e-3, max(20.0, 1e3 * jgl.u_c), 3000)
    a, P = jgl.evaluate(u)
    assert np.all(np.diff(a) > 0) and np.all(np.diff(P) > 0)
    assert np.all(P <= hertz_force(u, alpha, beta, nu) * (1 + 1e-12))
    assert np.all(a >= hertz_radius(u, beta) * (1 - 1e-15))


def test_size_effect_off_is_the_plain_law():
    plain, off = law(h=0.0), law(h=1e-14)
    u = np.geomspace(1e-4, 30.0, 400)
    for x, y in zip(plain.evaluate(u), off.evaluate(u), strict=True):
        np.testing.assert_allclose(y, x, rtol=1e-9)
    assert JacksonGreen(0.005) == JacksonGreen(0.005, 0.0)


def test_size_effect_raises_the_critical_interference():
    plain, sized = law(h=0.0), law(h=2.0)
    assert sized.u_c == pytest.approx(float(ng_critical_interference(plain.u_c, 2.0)), rel=1e-14)
    assert sized.u_c > 10 * plain.u_c


@pytest.mark.parametrize("case", CASES)
def test_model_against_the_reference(case):
    alpha, beta, nu, H, h = case
    m = Model(alpha, beta, nu=nu, law=JacksonGreen(H, h))
    d = [-1.0, 0.3, 2.5]
    curve = m.separation_curve(d)
    for i, di in enumerate(d):
        ref = reference.jg_separation_point(di, alpha, beta, nu, H, h)
        for key in ("contacts", "P", "F", "area", "plastic"):
            assert getattr(curve, key)[i] == pytest.approx(ref[key], rel=1e-8), (key, di)


def test_load_curve_against_the_reference():
    alpha, beta, nu, H, h = CASES[1]
    curve = Model(alpha, beta, nu=nu, law=JacksonGreen(H, h)).load_curve([0.1, 30.0])
    for i, P in enumerate((0.1, 30.0)):
        ref = reference.jg_load_point(P, alpha, beta, nu, H, h)
        assert curve.d[i] == pytest.approx(ref["d"], rel=1e-8, abs=1e-10)
        for key in ("F", "area", "contacts", "plastic"):
            assert getattr(curve, key)[i] == pytest.approx(ref[key], rel=1e-8)


def test_friction_law_is_passed_on():
    alpha, beta, nu, H, h = CASES[0]
    m = Model(alpha, beta, nu=nu, friction=ConstantShear(0.01), law=JacksonGreen(H))
    c = m.separation_curve([0.5])
    assert c.F[0] == pytest.approx(2 * math.pi * 0.01 * c.area[0], rel=1e-12)  # F = 2 pi tau A


def test_very_hard_asperities_are_elastic():
    # H/E* = 0.142 (the largest accepted) with alpha = 0.005, psi = 0.035: yield would need
    # u_c ~ 640 sigma, beyond every asperity that matters (H -> inf in effect).
    kw = {"nu": 0.3}
    hard = Model(0.005, 1000.0, law=JacksonGreen(0.142), **kw)
    assert hard.law.u_c > 500.0
    elastic = Model(0.005, 1000.0, **kw)
    P = np.geomspace(1e-2, 1e4, 9)
    a, b = hard.load_curve(P), elastic.load_curve(P)
    for key in ("d", "F", "area", "pressure", "contacts"):
        np.testing.assert_allclose(getattr(a, key), getattr(b, key), rtol=1e-12)
    assert np.all(a.plastic < 1e-300)
    # and the difference shrinks as the hardness grows
    gaps = [abs(Model(0.05, 1000.0, law=JacksonGreen(H), **kw).load_curve([100.0]).area[0]
                / Model(0.05, 1000.0, **kw).load_curve([100.0]).area[0] - 1) for H in (0.01, 0.03, 0.1)]
    assert gaps[0] > gaps[1] > gaps[2]


@pytest.mark.parametrize("case", CASES)
def test_plastic_column_is_the_tail_beyond_the_critical_interference(case):
    alpha, beta, nu, H, h = case
    m = Model(alpha, beta, nu=nu, law=JacksonGreen(H, h))
    c = m.separation_curve([-2.0, 0.0, 1.0, 3.0])
    np.testing.assert_allclose(c.plastic, special.ndtr(-(c.d + m.law.u_c)), rtol=1e-14)
    assert np.all(c.plastic <= c.contacts)
    assert list(c.columns()) == ["d", "P", "F", "mu", "area", "pressure", "contacts", "plastic"]
    assert c.parameters["law"] == "jackson-green" and c.parameters["H_over_E"] == H


def test_plasticity_lowers_pressure_and_raises_area_at_the_same_load():
    alpha, beta, nu, H = 0.05, 1000.0, 0.3, 0.005
    P = np.geomspace(1.0, 1e5, 6)
    plastic = Model(alpha, beta, nu=nu, law=JacksonGreen(H)).load_curve(P)
    elastic = Model(alpha, beta, nu=nu).load_curve(P)
    assert np.all(plastic.area > elastic.area) and np.all(plastic.pressure < elastic.pressure)
    # Most contacts have yielded: the mean pressure over the real area is near the hardness.
    assert np.all(plastic.plastic / plastic.contacts > 0.9)
    assert np.all((plastic.pressure > 0.5 * H) & (plastic.pressure < 1.2 * H))


def test_adhesion_is_refused():
    with pytest.raises(ValueError, match="no adhesion: gamma must be 0.*Maugis-Dugdale"):
        Model(0.01, 1000.0, 1e-3, law=JacksonGreen(0.01))


def test_model_accepts_the_built_law_or_the_spec():
    params = ModelParameters(0.05, 1000.0)
    built = JacksonGreenLaw(params, 0.005)
    a = Model(0.05, 1000.0, law=built).separation_curve([0.5])
    b = Model(0.05, 1000.0, law=JacksonGreen(0.005)).separation_curve([0.5])
    assert a.P[0] == b.P[0]
    assert isinstance(Model(0.05, 1000.0, law=Elastic()).law, AsperityLaw)


def test_registry_and_make_law():
    assert set(LAWS) == {"elastic", "jackson-green"}
    assert asperity.LAWS is LAWS
    assert make_law("Jackson-Green", H_over_E=0.01, h_star_over_sigma=2.0) == JacksonGreen(0.01, 2.0)
    assert make_law("elastic") == Elastic()
    from asperity.cli._args import LAW_NAMES
    assert LAW_NAMES == tuple(LAWS)


@pytest.mark.parametrize("call, match", [
    (lambda: make_law("kogut"), r"unknown law 'kogut'; known: elastic, jackson-green"),
    (lambda: make_law("elastic", H_over_E=0.01), r"elastic law takes no hardness"),
    (lambda: make_law("jackson-green"), r"needs the hardness H_over_E"),
    (lambda: JacksonGreen(0.0), r"H_over_E \(hardness H/E\*\) must lie in \(0, 0.142\] for the Jackson-Green law"),
    (lambda: JacksonGreen(0.2), r"H_over_E .* \(0, 0.142\]"),
    (lambda: JacksonGreen(float("nan")), r"H_over_E must be finite"),
    (lambda: JacksonGreen(0.01, -1.0), r"h_star_over_sigma must be >= 0"),
    (lambda: JacksonGreen([0.01, 0.02]), r"H_over_E must be a scalar"),
    (lambda: law(nu=-0.2), r"nu .* \[0, 0.5\) for the Jackson-Green law"),
    (lambda: law(alpha=0.3, H=0.05, h=1e4), r"yield strain at the onset of yield"),
    (lambda: JacksonGreenLaw("params", 0.01), r"params must be ModelParameters"),
    (lambda: critical_penetration(0.01, 0.3, -1.0), r"H_over_E must be > 0"),
    (lambda: plastic_fraction([0.0], 0.0), r"u_c must be > 0"),
    (lambda: plastic_fraction([0.0], 1.0, heights=0.5), r"heights must be a HeightDistribution"),
    (lambda: plastic_fraction([0.0], 1.0, heights="gauss"), r"unknown distribution 'gauss'"),
])
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()


def test_critical_penetration_and_plasticity_index():
    # u_c = (pi C / (2 * 2.84))^2 / psi^2 with psi = alpha / (H/E*)
    alpha, H, nu = 0.02, 0.004, 0.25
    psi = alpha / H
    C = 1.295 * math.exp(0.736 * nu)
    assert critical_penetration(alpha, nu, H) == pytest.approx((math.pi * C / 5.68) ** 2 / psi**2, rel=1e-14)
    assert critical_penetration(alpha, nu, H, 3.0) == pytest.approx(
        reference.jg_critical_penetration(alpha, nu, H, 3.0), rel=1e-12)


def test_critical_penetration_and_plastic_fraction_broadcast_like_ufuncs():
    alpha = np.array([[0.005], [0.02], [0.08]])
    nu, H, h = np.array([0.0, 0.25, 0.45]), 0.004, np.array([[0.0], [3.0], [0.5]])
    u_c = critical_penetration(alpha, nu, H, h)
    assert u_c.shape == (3, 3)
    for i in range(3):
        for j in range(3):
            want = reference.jg_critical_penetration(float(alpha[i, 0]), float(nu[j]), H, float(h[i, 0]))
            assert u_c[i, j] == pytest.approx(want, rel=1e-12)
            assert u_c[i, j] == critical_penetration(float(alpha[i, 0]), float(nu[j]), H, float(h[i, 0]))
    assert isinstance(critical_penetration(0.01, 0.3, 0.002), np.float64)
    d = np.linspace(-2.0, 3.0, 4)[:, None]
    share = plastic_fraction(d, np.array([0.1, 1.0, 2.5]))
    assert share.shape == (4, 3)
    assert share == pytest.approx(0.5 * special.erfc((d + np.array([0.1, 1.0, 2.5])) / math.sqrt(2.0)), rel=1e-13)
    with pytest.raises(ValueError, match=r"d, u_c must have shapes that broadcast together"):
        plastic_fraction([0.0, 1.0], [1.0, 2.0, 3.0])
    with pytest.raises(ValueError, match=r"alpha, nu, H_over_E, h_star_over_sigma must have shapes that broadcast"):
        critical_penetration([0.01, 0.02], [0.1, 0.2, 0.3], 0.002)


def test_nanometre_summits_whose_contacts_never_reach_a_friction_breakpoint():
    """Found by a review: with a small beta (R = 10 nm on gold) the Hurtado-Kim radius a2 b
    (23 um) lies beyond any contact of these asperities, and the law failed at every load
    ("omega_star must lie in [0, 1e+12]").  The breakpoint is now left out, and the model
    equals the reference path, which knows nothing of breakpoints."""
    alpha, beta, nu, H = 0.447, 15.5, 0.44, 0.00194
    m = Model(alpha, beta, nu=nu, law=JacksonGreen(H))
    assert len(m.law.breakpoints) < len(JacksonGreenLaw(ModelParameters(alpha, 1000.0, nu=nu), H).breakpoints)
    d = [-2.0, 0.0, 1.5]
    curve = m.separation_curve(d)
    for i, di in enumerate(d):
        ref = reference.jg_separation_point(di, alpha, beta, nu, H)
        for key in ("contacts", "P", "F", "area", "plastic"):
            assert getattr(curve, key)[i] == pytest.approx(ref[key], rel=1e-8), (key, di)


def test_law_names_with_underscores_and_capitals():
    from asperity.elastic_plastic import make_law

    assert type(make_law("Jackson_Green", H_over_E=0.01)) is type(make_law("jackson-green", H_over_E=0.01))
