"""asperity.physical: a material and a surface in SI units, forces in newtons."""

import json
import math
import warnings

import mpmath as mp
import numpy as np
import pint
import pytest
from hypothesis import given
from hypothesis import strategies as st

import asperity
from asperity import ConstantShear, physical, regimes
from asperity import surface as surface_module
from asperity.materials import Material, material, pair
from asperity.maugis_dugdale import md_lambda
from asperity.physical import (
    PHYSICAL_COLUMNS,
    PhysicalContact,
    work_of_adhesion_from_gamma,
)
from asperity.surface import Surface, surface_from_groups

u = pint.UnitRegistry()

#: Gold asperities of these surfaces yield (plasticity index psi = 23): the elastic model
#: warns (asperity.PlasticityWarning).  The warning itself is tested in tests/test_plasticity.py.
pytestmark = pytest.mark.filterwarnings("ignore::asperity.plasticity.PlasticityWarning")

SIGMA, RADIUS, ETA, AREA = 2e-9, 1e-6, 1e12, 1e-6  # the hand-calculation surface


@pytest.fixture
def surface():
    return Surface(sigma_s=SIGMA, R=RADIUS, eta=ETA, area=AREA)


def gw_moment(k, d):
    """I_k(d) = int_d^inf (z-d)^k phi(z) dz for Gaussian phi, by mpmath (independent of asperity)."""
    with mp.workdps(30):
        d = mp.mpf(d)
        f = lambda z: (z - d) ** k * mp.exp(-z * z / 2) / mp.sqrt(2 * mp.pi)  # noqa: E731
        return float(mp.quad(f, [d, d + 2, d + 6, mp.inf]))


def test_pint_inputs_equal_si_floats(surface):
    q = Surface(sigma_s=2 * u.nm, R=1 * u.um, eta=1e12 / u.m**2, area=1 * u.mm**2)
    for name in ("sigma_s", "R", "eta", "area"):
        assert getattr(q, name) == pytest.approx(getattr(surface, name), rel=1e-15)
    a = PhysicalContact("Au", surface, h=0.3 * u.nm, friction=100 * u.MPa)
    b = PhysicalContact("Au", q, h=0.3e-9, friction=1e8)
    for name in ("alpha", "beta", "gamma", "lam", "force_scale", "area_scale", "h"):
        assert getattr(a, name) == pytest.approx(getattr(b, name), rel=1e-14)
    ca, cb = a.separation_curve([1 * u.nm, 2 * u.nm]), b.separation_curve([1e-9, 2e-9])
    np.testing.assert_allclose(ca.P, cb.P, rtol=1e-12)
    np.testing.assert_allclose(a.load_curve(1 * u.mN).F, b.load_curve(1e-3).F, rtol=1e-10)


def test_wrong_dimensionality_of_curve_inputs(surface):
    c = PhysicalContact("Au", surface, adhesion=False)
    with pytest.raises(ValueError, match=r"P must have units compatible with N"):
        c.load_curve(1 * u.m)
    with pytest.raises(ValueError, match=r"d must have units compatible with m"):
        c.separation_curve(1 * u.N)
    with pytest.raises(ValueError, match=r"h must have units compatible with m"):
        PhysicalContact("Au", surface, h=1 * u.Pa)


positive = dict(allow_nan=False, allow_infinity=False)


@given(sigma=st.floats(1e-10, 1e-6), R=st.floats(1e-8, 1e-3), b=st.floats(2e-10, 5e-10),
       eta=st.floats(1e8, 1e16), area=st.floats(1e-12, 1e-2), E=st.floats(1e9, 1.2e12),
       nu=st.floats(-0.5, 0.49), w=st.floats(1e-3, 10.0), h_over_b=st.floats(0.2, 5.0))
def test_round_trip_physical_to_groups_to_physical(sigma, R, b, eta, area, E, nu, w, h_over_b):
    body = Material("x", E=E, nu=nu, b=b, w=w)
    c = PhysicalContact(body, Surface(sigma, R, eta, area), h=h_over_b * b)
    back = surface_from_groups(c.alpha, c.beta, b, eta, area)
    assert back.sigma_s == pytest.approx(sigma, rel=1e-13)
    assert back.R == pytest.approx(R, rel=1e-13)
    assert (back.eta, back.area) == (eta, area)
    assert work_of_adhesion_from_gamma(c.gamma, c.E_star, b) == pytest.approx(w, rel=1e-13)
    # Eq (15) from the groups equals Eq (14) with sigma0 = w/h.
    assert c.lam == pytest.approx(md_lambda(R, w, c.E_star, w / c.h), rel=1e-12)


@given(alpha=st.floats(1e-4, 0.5), beta=st.floats(1.0, 1e6), gamma=st.floats(1e-8, 0.2),
       b=st.floats(2e-10, 5e-10), E_star=st.floats(1e9, 1e12), nu=st.floats(-0.5, 0.49))
def test_round_trip_groups_to_physical_to_groups(alpha, beta, gamma, b, E_star, nu):
    w = work_of_adhesion_from_gamma(gamma, E_star, b)
    body = Material("x", E=E_star * (1 - nu**2), nu=nu, b=b, w=w)
    c = PhysicalContact(body, surface_from_groups(alpha, beta, b, 1e12, 1e-6))
    assert c.alpha == pytest.approx(alpha, rel=1e-13)
    assert c.beta == pytest.approx(beta, rel=1e-13)
    assert c.gamma == pytest.approx(gamma, rel=1e-12)
    assert c.h_over_b == 1.0  # the paper's h = b


def test_inverse_conversions_validate_and_vectorise():
    np.testing.assert_allclose(work_of_adhesion_from_gamma([0.0, 1e-3], 1e11, 2.5e-10), [0.0, 0.025])
    with pytest.raises(ValueError, match="gamma must be >= 0"):
        work_of_adhesion_from_gamma(-1e-3, 1e11, 2.5e-10)


# -- the model in newtons --------------------------------------------------------------------

def test_hertz_hand_calculation(surface):
    """Au, sigma = 2 nm, R = 1 um, eta = 1e12/m^2, A = 1 mm^2, no adhesion, d = sigma."""
    tau = 50e6  # Pa
    c = PhysicalContact("Au", surface, adhesion=False, friction=tau)
    E_star = 78e9 / (1 - 0.44**2)
    N = ETA * AREA
    curve = c.separation_curve(SIGMA)
    P = N * (4 / 3) * E_star * math.sqrt(RADIUS) * SIGMA**1.5 * gw_moment(1.5, 1.0)
    F = N * math.pi * tau * RADIUS * SIGMA * gw_moment(1.0, 1.0)
    assert c.gamma == 0.0 and c.lam == 0.0
    assert curve.P[0] == pytest.approx(P, rel=1e-10)
    assert curve.F[0] == pytest.approx(F, rel=1e-10)
    assert curve.area[0] == pytest.approx(N * math.pi * RADIUS * SIGMA * gw_moment(1.0, 1.0), rel=1e-10)
    assert curve.contacts[0] == pytest.approx(N * float(mp.ncdf(-1)), rel=1e-10)
    assert curve.pressure[0] == pytest.approx(curve.P[0] / curve.area[0], rel=1e-14)
    assert curve.mu[0] == pytest.approx(F / P, rel=1e-10)
    assert curve.d[0] == SIGMA
    # ConstantShear(tau) is normalised by G* = 2G.
    assert c.model.params.friction == ConstantShear(tau / (2 * c.G))


def test_gold_with_adhesion(surface):
    c = PhysicalContact(material("Au"), surface)
    assert c.gamma > 0 and c.lam > 0
    curve = c.load_curve([1e-3, 1e-2])
    assert np.all(np.isfinite(curve.mu)) and np.all(curve.mu > 0)
    np.testing.assert_array_equal(curve.P, [1e-3, 1e-2])
    po = c.pull_off()
    expected = asperity.pull_off(c.alpha, c.beta, c.gamma, nu=c.nu).force
    assert po.exists and po.force > 0
    assert po.force == pytest.approx(c.force_scale * expected, rel=1e-12)
    assert po.d == pytest.approx(po.dimensionless.d * SIGMA, rel=1e-15)
    assert c.force_scale == pytest.approx(ETA * AREA * c.G * c.b**2, rel=1e-15)
    assert c.area_scale == pytest.approx(ETA * AREA * math.pi * c.b**2, rel=1e-15)


def test_model_parameters_match_the_contact(surface):
    c = PhysicalContact(pair("Au", "Au", name="Au/Au"), surface, h=0.5e-9)
    p = c.model.params
    assert (p.alpha, p.beta, p.gamma, p.nu) == (c.alpha, c.beta, c.gamma, c.nu)
    assert p.h_over_b == pytest.approx(0.5e-9 / c.b)
    assert c.E_star / c.G == pytest.approx(2 / (1 - c.nu), rel=1e-14)


def test_adhesion_switch(surface):
    with pytest.raises(ValueError, match=r"'diamond' has no work of adhesion .* adhesion=False"):
        PhysicalContact("diamond", surface)
    assert PhysicalContact("diamond", surface, adhesion=False).gamma == 0.0
    assert PhysicalContact("Au", surface, adhesion=False).gamma == 0.0
    no_w = Material("x", E=1e11, nu=0.3, b=2.5e-10, w=0.0)
    hertz = PhysicalContact(no_w, surface)
    assert hertz.gamma == 0.0 and not hertz.model.params.adhesive
    assert hertz.pull_off().force == 0.0 and not hertz.pull_off().exists
    with pytest.raises(ValueError, match=r"'mica' has no Burgers vector"):
        PhysicalContact("mica", surface, adhesion=False)
    with pytest.raises(TypeError, match="surface must be"):
        PhysicalContact("Au", (SIGMA, RADIUS, ETA, AREA))


def test_load_errors_are_stated_in_newtons(surface):
    """A user trial: the limits were stated in N G b^2 units ('got min -0.443615 (loads in units
    of N G b^2 = 0.00225421 N)' for -1 mN); now the limit and the load are in newtons."""
    from asperity.load_control import LoadOutOfRange

    c = PhysicalContact("Au", surface)
    limit = c.pull_off().force
    with pytest.raises(LoadOutOfRange, match=r"^P \(load\) must be >= (\S+) N \(minus the pull-off force\): no "
                       r"equilibrium under a smaller load; got min (\S+) N$") as info:
        c.load_curve([1e-3, -2 * limit])
    assert float(str(info.value).split(">= ")[1].split(" N")[0]) == pytest.approx(-limit, rel=1e-5)
    assert info.value.got == -2 * limit and info.value.floor == pytest.approx(-limit, rel=1e-12)
    with pytest.raises(ValueError, match=r"^P \(load\) must be > 0 N \(without adhesion, gamma = 0\): .* got min "
                                         r"-0.001 N$"):
        PhysicalContact("Au", surface, adhesion=False).load_curve([1e-3, -1e-3])
    with pytest.raises(ValueError, match=r"got min 0 N$"):
        PhysicalContact("Au", surface, adhesion=False).load_curve(0.0)
    with pytest.raises(ValueError, match=r"d \(separation\) must lie in \[.*\] m"):
        c.separation_curve(1e-6)


def test_a_floor_at_the_end_of_the_branch_is_stated_in_metres():
    """A review: an adhesive contact without a pull-off (sigma_s = 100 nm) stated its floor as
    'the force at d/sigma = 30.02'; now at d in metres, sigma_s times the model's."""
    from asperity.load_control import LoadOutOfRange

    contact = PhysicalContact("Au", Surface(1e-7, 1e-6, 1e12, 1e-6))
    with pytest.raises(LoadOutOfRange) as model:
        contact.model.load_curve([1.0, -1e-6 / contact.force_scale])
    with pytest.raises(LoadOutOfRange, match=r"\(the force at d = (\S+) m\): .* got min -1e-06 N$") as phys:
        contact.load_curve([1e-3, -1e-6])
    assert model.value.d_end is not None and "d/sigma" in str(model.value)
    assert phys.value.d_end == pytest.approx(model.value.d_end * 1e-7, rel=1e-12)
    assert f"d = {phys.value.d_end:.4g} m" in str(phys.value)


def test_the_refusals_with_numbers_pickle_and_copy():
    """A review: their __init__ took more than the message, so pickle (a process pool sends
    errors between processes) and copy failed with a TypeError instead of the message."""
    import copy
    import pickle

    from asperity.instrument import UnstableClosestApproach
    from asperity.load_control import LoadOutOfRange

    for err in (LoadOutOfRange(-1.5, -2.0, "minus the pull-off force"),
                LoadOutOfRange(0.0, -1e-3, "without adhesion, gamma = 0", True, " N"),
                LoadOutOfRange(1e-9, -1.0, "the force at d = 6e-08 m", False, " N", 6e-8),
                UnstableClosestApproach(3.2, 1.0, 10.0), UnstableClosestApproach(6e-9, 2e-9, 100.0, " m", " N/m")):
        for back in (pickle.loads(pickle.dumps(err)), copy.copy(err), copy.deepcopy(err)):
            assert type(back) is type(err) and str(back) == str(err) and back.args == err.args
            assert isinstance(back, ValueError) and vars(back) == vars(err)


def test_curve_export(surface, tmp_path):
    c = PhysicalContact("Au", surface, adhesion=False)
    curve = c.separation_curve([0.0, 1e-9, 2e-9, 5e-8])
    assert len(curve) == 4
    header = [col for col, _, _ in PHYSICAL_COLUMNS.values()]
    assert header == ["d_m", "P_N", "F_N", "mu", "area_m2", "pressure_Pa", "contacts"]
    text = curve.to_csv()
    assert text.splitlines()[0] == ",".join(header)
    curve.to_csv(tmp_path / "c.csv")
    assert (tmp_path / "c.csv").read_text() == text
    frame = curve.to_dataframe()
    assert list(frame.columns) == header
    assert frame.attrs["units"]["P_N"] == "N" and frame.attrs["material"] == "Au"
    np.testing.assert_allclose(frame["P_N"], curve.P)
    assert curve.contacts[-1] < 1e-100  # 25 sigma out: the Gaussian tail only
    np.testing.assert_allclose(curve.contacts, curve.dimensionless.contacts * c.N, rtol=1e-15)


# -- regime helpers --------------------------------------------------------------------------


# -- compatibility and boundary checks -------------------------------------------------------

def test_moved_names_are_re_exported():
    """Surface and the regime helpers moved out of physical.py; the old imports still work."""
    assert physical.Surface is surface_module.Surface
    assert physical.surface_from_groups is surface_module.surface_from_groups
    for name in ("tabor_parameter", "maugis_parameter", "adhesion_regime", "fuller_tabor_parameter"):
        assert getattr(physical, name) is getattr(regimes, name)
        assert name in physical.__all__


def test_material_by_name_or_object(surface):
    assert PhysicalContact("au", surface).material == material("Au")
    with pytest.raises(TypeError, match=r"material must be an asperity.materials.Material .* got int"):
        PhysicalContact(3, surface)
    with pytest.raises(ValueError, match="unknown material 'unobtainium'"):
        PhysicalContact("unobtainium", surface)


@pytest.mark.parametrize("h, message", [
    (True, "h must be a real number, got a boolean"), (1j, "h must be a real number"),
    (float("nan"), "h must be finite"), ([1e-10, 2e-10], "h must be a scalar"), (-1e-10, r"h must be > 0 m"),
    ("0.3 GPa", "h must have units compatible with m"),
])
def test_bad_dugdale_range(surface, h, message):
    with pytest.raises(ValueError, match=message):
        PhysicalContact("Au", surface, h=h)


def test_shear_strength_as_string(surface):
    a = PhysicalContact("Au", surface, friction="100 MPa", adhesion=False)
    assert a.model.params.friction == ConstantShear(1e8 / a.G_star)
    with pytest.raises(ValueError, match=r"friction \(shear strength tau\) must be > 0 Pa"):
        PhysicalContact("Au", surface, friction=0.0)


# -- what the contact states about itself ------------------------------------------------------

def test_to_dict_states_the_contact_computed(surface):
    E, nu, b, w = 78e9, 0.44, 2.885e-10, 3.012
    for name, e_star, g_star in (("Au", E / (1 - nu**2), E / (1 + nu)),
                                 ("Au/Au", E / (2 * (1 - nu**2)), E / (2 * (1 + nu)))):
        c = PhysicalContact(name, surface)
        d = c.to_dict()
        assert d["E_star_Pa"] == pytest.approx(e_star, rel=1e-14)
        assert d["G_star_Pa"] == pytest.approx(g_star, rel=1e-14)
        assert (d["w_J_m2"], d["b_m"], d["h_m"]) == (w, b, b)
        assert (d["sigma_s_m"], d["R_m"], d["eta_per_m2"], d["area_m2"], d["N"]) == (SIGMA, RADIUS, ETA, AREA,
                                                                                      ETA * AREA)
        assert d["alpha"] == pytest.approx(math.sqrt(SIGMA / RADIUS), rel=1e-15)
        assert d["beta"] == pytest.approx(math.sqrt(SIGMA * RADIUS) / b, rel=1e-15)
        assert d["gamma"] == pytest.approx(w / (e_star * b), rel=1e-14)
        assert d["lambda"] == pytest.approx(md_lambda(RADIUS, w, e_star, w / b), rel=1e-12)  # Eq 14, h = b
        lam = d["lambda"]
        assert d["regime"] == ("DMT" if lam < 0.1 else "JKR" if lam > 5 else "Maugis-Dugdale")
        assert d["body1"] == {"name": "Au", "E_Pa": E, "nu": nu, "rigid": False}
        assert d["friction"] == {"law": "Hurtado-Kim", "tau_f1": 1 / 43, "tau_f2": 1 / 43 / 30, "a1": 28.0,
                                 "a2": 8e4}
        json.dumps(d, allow_nan=False)
    assert PhysicalContact("Au", surface).to_dict()["body2"]["rigid"] is True
    assert PhysicalContact("Au/Au", surface).to_dict()["body2"] == {"name": "Au", "E_Pa": E, "nu": nu,
                                                                     "rigid": False}


def test_gold_on_gold_differs_from_gold_on_a_flat(surface):
    # The "1.6x": the same surface and load give different forces for the two forms.
    one, two = PhysicalContact("Au", surface), PhysicalContact("Au/Au", surface)
    assert two.E_star == pytest.approx(one.E_star / 2, rel=1e-14)
    f1, f2 = one.load_curve([1e-2]).F[0], two.load_curve([1e-2]).F[0]
    assert f1 / f2 > 1.2 and one.describe() != two.describe()


def test_describe_names_every_quantity(surface):
    text = PhysicalContact("Au/Au", surface, friction=5e7).describe()
    lines = text.splitlines()
    assert lines[0] == "contact: Au (E 78 GPa, nu 0.44) on Au (E 78 GPa, nu 0.44)"
    for needle in ("E* = 48.36 GPa", "G* = 27.08 GPa", "w = 3.012 J/m^2", "h = 288.5 pm", "b = 288.5 pm",
                   "sigma_s = 2 nm", "R = 1 um", "N = 1e+06 summits", "alpha = 0.04472", "beta = 155",
                   "lambda = ", "(JKR)", "tau = 50 MPa"):
        assert needle in text, needle
    hertz = PhysicalContact("Au", surface, adhesion=False).describe()
    assert "w = 0 (no adhesion: Hertz)" in hertz and "lambda = 0 (no adhesion: Hertz)" in hertz
    plastic = PhysicalContact("Au", surface, adhesion=False, plasticity="jackson-green").describe()
    assert "w = 0 (no adhesion: Jackson-Green)" in plastic and "(no adhesion: Jackson-Green)," in plastic


def test_constant_shear_is_stated_in_pascals(surface):
    c = PhysicalContact("Au", surface, friction="50MPa")
    assert c.to_dict()["friction"] == {"law": "constant shear", "tau": pytest.approx(5e7 / c.G_star, rel=1e-15),
                                       "tau_Pa": pytest.approx(5e7, rel=1e-15)}


def test_contact_rejects_wrong_types(surface):
    with pytest.raises(TypeError, match="adhesion must be True or False"):
        PhysicalContact("Au", surface, adhesion="no")
    with pytest.raises(ValueError, match="heights must be"):  # asperity.heights.check_heights
        PhysicalContact("Au", surface, heights=None)


def test_gold_on_gold_pulls_off_harder(surface):
    # Two bodies halve E* (and G*): a more compliant contact sticks more.  The docs quote the ratio.
    one, two = PhysicalContact("Au", surface).pull_off(), PhysicalContact("Au/Au", surface).pull_off()
    assert 1.5 < two.force / one.force < 1.8


def test_validity_warnings_above_ten_percent_of_the_nominal_area():
    contact = PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6), plastic_threshold=1.0)  # no yield note
    with pytest.warns(physical.AreaFractionWarning, match="above 10 % from P = 1000 N") as record:
        curve = contact.load_curve([1.0, 1e3, 3e3])
    assert len(record) == 1 and str(record[0].message) == curve.validity_warnings()[0]
    fraction = curve.area / 1e-6  # real over nominal area, from the columns
    assert fraction[0] < 0.1 < fraction[1] < fraction[2]
    (message,) = curve.validity_warnings()
    assert f"{100 * fraction[2]:.3g} %" in message and "from P = 1000 N" in message
    assert physical.AREA_FRACTION_CAUTION == 0.1
    assert contact.load_curve([1.0, 10.0]).validity_warnings() == []
    assert curve.validity_warnings(limit=0.99) == []
    assert len(curve.validity_warnings(limit=fraction[0] / 2)) == 1
    with pytest.raises(ValueError, match="limit"):
        curve.validity_warnings(limit=-0.1)


def test_three_bodies_and_overflowing_summit_counts_are_refused():
    """Found by a review: 'Au/Au/Au' was read as gold on the pair Au/Au (E* of three bodies),
    and an area of 1e300 m^2 gave inf results with no error."""
    from asperity.bodies import contact_material

    for name in ("Au/Au/Au", "Au/Si/Ni"):
        with pytest.raises(ValueError, match=r"material must name one body \('Au'\) or two \('A/B'\)"):
            contact_material(name, w=1.0)
    with pytest.raises(ValueError, match=r"eta \* area \(the number of summits N\) must be finite"):
        Surface("2nm", "1um", "1e12/m^2", "1e300m^2")
    with pytest.raises(ValueError, match=r"the force unit N G b\^2 = .* is not finite"):
        PhysicalContact(contact_material(E=1e300, nu=0.3, b=1e-10), Surface("2nm", "1um", "1e12/m^2", "1e18m^2"),
                        adhesion=False)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        big = PhysicalContact("Au", Surface("2nm", "1um", "1e12/m^2", "1e290m^2")).load_curve([1e-3])
    assert np.all(np.isfinite([big.F[0], big.area[0], big.contacts[0]]))


def test_groups_out_of_range_name_the_surface_values_they_come_from():
    """A review: Surface(sigma_s=1e-320) was refused as 'beta must be > 0', a name the user never gave."""
    with pytest.raises(ValueError, match=r"beta must be > 0 .*; from sigma_s = 9\.99989e-321 m, R = 1e-06 m, b = "):
        PhysicalContact("Au", Surface(sigma_s=1e-320, R=1e-6, eta=1e12, area=1e-6)).load_curve([1e-3])


def test_a_pull_off_search_ending_short_of_it_says_so():
    """A user trial: pull_off(d_max=20e-9), metres meant, searched up to 2e-8 sigma_s and said
    'no pull-off' without a word; '20nm' found it."""
    from asperity import AsperityWarning
    from asperity.physical import PhysicalContact, Surface

    c = PhysicalContact("Au", Surface(sigma_s=5e-9, R=1e-6, eta=1e13, area=1e-8))
    with pytest.warns(AsperityWarning, match=r"no tensile force for d <= d_max = 2e-08 sigma_s: a pull-off, if "
                                             r"any, lies beyond; a plain number is in units of sigma_s, a length "
                                             r"needs its unit \('20nm'\)"):
        assert not c.pull_off(20e-9).exists
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert c.pull_off("20nm").force == pytest.approx(c.pull_off().force, rel=1e-12)
