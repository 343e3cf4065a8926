"""Physical units, materials table and the SI front end (asperity.units, .materials, .physical)."""

import csv
import io
import math
import re

import mpmath as mp
import numpy as np
import pint
import pytest
from hypothesis import given
from hypothesis import strategies as st

import asperity
from asperity import ConstantShear, units
from asperity.materials import (
    Material,
    _check_effective_poisson,
    material,
    material_names,
    material_table,
    pair,
)
from asperity.maugis_dugdale import md_lambda
from asperity.physical import (
    PHYSICAL_COLUMNS,
    PhysicalContact,
    Surface,
    adhesion_regime,
    fuller_tabor_parameter,
    maugis_parameter,
    surface_from_groups,
    tabor_parameter,
    work_of_adhesion_from_gamma,
)

u = pint.UnitRegistry()

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


# -- units -----------------------------------------------------------------------------------

def test_to_si_passes_numbers_and_converts_quantities():
    assert units.to_si(2e-9, "m", "sigma_s") == 2e-9
    assert units.to_si(2 * u.nm, "m", "sigma_s") == pytest.approx(2e-9, rel=1e-15)
    assert units.to_si(79 * u.GPa, "Pa", "E") == pytest.approx(79e9, rel=1e-15)
    np.testing.assert_allclose(units.to_si([1, 2] * u.mN, "N", "P"), [1e-3, 2e-3], rtol=1e-15)
    assert units.to_si(0.3 * u.dimensionless, "", "nu") == pytest.approx(0.3)


def test_to_si_wrong_dimension_names_parameter_and_unit():
    with pytest.raises(ValueError, match=r"sigma_s must have units compatible with m"):
        units.to_si(2 * u.GPa, "m", "sigma_s")


@pytest.mark.parametrize("text, unit, expected", [
    ("2nm", "m", 2e-9), ("1um", "m", 1e-6), ("1e12/m^2", "1/m^2", 1e12), ("1mm^2", "m^2", 1e-6),
    ("1mN", "N", 1e-3), ("79GPa", "Pa", 79e9), ("1.2J/m^2", "J/m^2", 1.2), (" 2 nm ", "m", 2e-9),
    ("0.3", "", 0.3),
])
def test_parse_quantity(text, unit, expected):
    assert units.parse_quantity(text, unit, "x") == pytest.approx(expected, rel=1e-14)


def test_parse_quantity_bare_number_needs_a_unit():
    with pytest.raises(ValueError, match=r"sigma_s needs a unit compatible with m"):
        units.parse_quantity("2", "m", "sigma_s")
    assert units.parse_quantity("2e-9", "m", "sigma_s", require_unit=False) == 2e-9


@pytest.mark.parametrize("text", ["2 GPa", "2 furlongs_per_bogus", "nm nm (", ""])
def test_parse_quantity_rejects_bad_strings(text):
    with pytest.raises(ValueError, match="sigma_s"):
        units.parse_quantity(text, "m", "sigma_s")


def test_parse_quantity_without_pint(monkeypatch):
    def missing():
        raise ImportError("no pint")

    monkeypatch.setattr(units, "unit_registry", missing)
    with pytest.raises(ValueError, match=r"asperity\[units\]"):
        units.parse_quantity("2nm", "m", "sigma_s")
    assert units.parse_quantity("2e-9", "m", "sigma_s", require_unit=False) == 2e-9


def test_to_si_parses_strings():
    assert units.to_si("79GPa", "Pa", "E") == pytest.approx(79e9)


# -- the materials table ---------------------------------------------------------------------

NUMERIC = ["E_Pa", "nu", "G_Pa", "lattice_constant_m", "b_m", "surface_energy_J_m2", "work_of_adhesion_J_m2"]


def _source_keys(sources):
    keys = set()
    for entry in filter(None, (e.strip() for e in sources.split(" | "))):
        head, sep, citation = entry.partition(": ")
        assert sep and citation.strip(), f"source entry without a citation: {entry!r}"
        keys |= {k.strip() for k in head.split(",")}
    return keys


def test_table_has_the_required_rows():
    names = {n.lower() for n in material_names()}
    assert {"au", "ag", "cu", "al", "ni", "pt", "si", "diamond", "mica", "si/si", "au/au", "au/mica"} <= names


@pytest.mark.parametrize("row", material_table(), ids=lambda r: r["name"])
def test_every_number_has_a_source(row):
    keys = _source_keys(row["sources"])
    assert keys <= set(NUMERIC), f"unknown column in sources: {keys - set(NUMERIC)}"
    for column in NUMERIC:
        if row[column] is not None:
            assert column in keys, f"{row['name']}: {column} = {row[column]} has no source"


@pytest.mark.parametrize("row", [r for r in material_table() if r["G_Pa"] is not None], ids=lambda r: r["name"])
def test_listed_shear_modulus_is_isotropic(row):
    assert row["G_Pa"] == pytest.approx(row["E_Pa"] / (2 * (1 + row["nu"])), rel=0.02)


@pytest.mark.parametrize("row", [r for r in material_table() if r["b_m"] is not None], ids=lambda r: r["name"])
def test_burgers_vector_matches_lattice_and_slip_system(row):
    # a/2<110> perfect dislocation of the fcc and diamond-cubic {111}<110> slip systems.
    assert re.fullmatch(r"(fcc|diamond cubic) \{111\}<110>", row["slip_system"])
    assert row["b_m"] == pytest.approx(row["lattice_constant_m"] / math.sqrt(2), rel=5e-4)


def test_self_adhesion_is_twice_the_surface_energy():
    by_name = {r["name"]: r for r in material_table()}
    for row in by_name.values():
        if row["kind"] == "element" and row["surface_energy_J_m2"] is not None:
            assert row["work_of_adhesion_J_m2"] == pytest.approx(2 * row["surface_energy_J_m2"], rel=1e-12)
    assert by_name["Au/Au"]["work_of_adhesion_J_m2"] == pytest.approx(2 * by_name["Au"]["surface_energy_J_m2"])
    assert by_name["Si/Si"]["work_of_adhesion_J_m2"] == pytest.approx(2 * by_name["Si"]["surface_energy_J_m2"])


def test_table_file_parses_with_the_csv_module():
    from importlib import resources

    text = resources.files("asperity").joinpath("data/materials.csv").read_text(encoding="utf-8")
    assert text.startswith("#") and "Units" in text
    rows = list(csv.DictReader(line for line in io.StringIO(text) if not line.startswith("#")))
    assert [r["name"] for r in rows] == material_names()
    for r in rows:
        if r["kind"] == "pair":
            assert all(c in material_names() for c in r["components"].split(";"))


def test_material_lookup_is_case_insensitive():
    assert material("au") == material("AU") == material(" Au ")
    gold = material("Au")
    assert (gold.E, gold.nu, gold.b, gold.w) == (78e9, 0.44, 2.885e-10, 3.012)


def test_unknown_material_lists_the_known_ones():
    with pytest.raises(ValueError, match=r"unknown material 'unobtainium'; known: Au, Ag"):
        material("unobtainium")


def test_missing_values_stay_missing():
    assert material("diamond").w is None
    assert material("mica").b is None
    assert material("Au/mica").w is None


# -- Material and pairs ----------------------------------------------------------------------

@pytest.mark.parametrize("kwargs, message", [
    ({"E": -1.0}, r"E must be > 0"), ({"E": float("nan")}, r"E must be finite"),
    ({"nu": 0.5}, r"nu \(Poisson's ratio\) must lie in \(-1, 0.5\)"), ({"nu": -1.0}, r"nu"),
    ({"b": 0.0}, r"b must be > 0"), ({"w": -0.1}, r"w must be >= 0"), ({"h": -1e-10}, r"h must be > 0"),
    ({"w": None, "sigma0": 1e9}, r"sigma0 \(Dugdale stress\) needs a positive work of adhesion"),
    ({"h": 1e-10, "sigma0": 1e9}, r"h and sigma0 disagree"), ({"E": 1 * u.m}, r"E must have units"),
])
def test_material_validation(kwargs, message):
    base = {"name": "x", "E": 1e11, "nu": 0.3, "b": 2.5e-10, "w": 1.0}
    with pytest.raises(ValueError, match=message):
        Material(**{**base, **kwargs})


def test_material_moduli_and_dugdale_stress():
    m = Material("x", E=79 * u.GPa, nu=0.3, b=0.25 * u.nm, w=1.0 * u.J / u.m**2, sigma0=2 * u.GPa)
    assert m.E == pytest.approx(79e9) and m.b == pytest.approx(2.5e-10)
    assert m.h == pytest.approx(1.0 / 2e9)
    assert m.G == pytest.approx(79e9 / 2.6) and m.E_star == pytest.approx(79e9 / 0.91)
    assert m.G_star == pytest.approx(2 * m.G)


def test_pair_of_identical_bodies():
    gold = material("Au")
    p = pair(gold, "au")
    assert p.nu == pytest.approx(gold.nu, rel=1e-14)
    assert p.E_star == pytest.approx(gold.E / (2 * (1 - gold.nu**2)), rel=1e-14)
    assert p.G_star == pytest.approx(gold.G, rel=1e-14)
    assert p.w == gold.w and p.b == gold.b and p.components == ("Au", "Au")
    assert material("Au/Au") == pair("Au", "Au", name="Au/Au")


def test_pair_with_a_nearly_rigid_body_is_the_body():
    si = material("Si")
    p = pair(si, Material("rigid", E=1e30, nu=0.2))
    assert p.nu == pytest.approx(si.nu, rel=1e-12)
    assert p.E_star == pytest.approx(si.E_star, rel=1e-12)
    assert p.G_star == pytest.approx(si.G_star, rel=1e-12)


@given(E1=st.floats(1e8, 1e13), E2=st.floats(1e8, 1e13),
       nu1=st.floats(-0.99, 0.499), nu2=st.floats(-0.99, 0.499))
def test_pair_reproduces_composite_moduli(E1, E2, nu1, nu2):
    one, two = Material("a", E1, nu1, b=3e-10), Material("b", E2, nu2, b=3e-10)
    p = pair(one, two)
    e_star = 1 / ((1 - nu1**2) / E1 + (1 - nu2**2) / E2)
    g_star = 2 * one.G * two.G / (one.G + two.G)
    assert -1 < p.nu < 0.5
    assert p.nu == pytest.approx(1 - g_star / e_star, abs=1e-12)
    assert p.E_star == pytest.approx(e_star, rel=1e-11)
    assert p.G_star == pytest.approx(g_star, rel=1e-12)
    assert p.E_star / p.G == pytest.approx(2 / (1 - p.nu), rel=1e-12)  # the model's E*/G


def test_pair_burgers_vector_rule():
    assert material("Au/mica").b == material("Au").b  # mica has none
    with pytest.raises(ValueError, match=r"different Burgers vectors .* pass b= explicitly"):
        pair("Au", "Cu")
    assert pair("Au", "Cu", b=2.7e-10, w=2.0).b == 2.7e-10


def test_pair_rejects_an_effective_poisson_ratio_out_of_range():
    with pytest.raises(ValueError, match=r"effective Poisson's ratio nu_eff = 1 - G\*/E\* = 0.5 lies outside"):
        _check_effective_poisson(0.5, "a/b")
    assert _check_effective_poisson(0.3, "a/b") == 0.3


# -- Surface, groups and round trips ---------------------------------------------------------

def test_surface(surface):
    assert surface.N == pytest.approx(1e6)
    assert surface.alpha == pytest.approx(math.sqrt(2e-3))


@pytest.mark.parametrize("kwargs, message", [
    ({"sigma_s": -1e-9}, r"sigma_s must be > 0"), ({"R": 0.0}, r"R must be > 0"),
    ({"eta": [1e12, 1e13]}, r"eta must be a scalar"), ({"area": 1 * u.m}, r"area must have units compatible with m\^2"),
    ({"sigma_s": 2 * u.GPa}, r"sigma_s must have units compatible with m"),
])
def test_surface_validation(kwargs, message):
    base = {"sigma_s": SIGMA, "R": RADIUS, "eta": ETA, "area": AREA}
    with pytest.raises(ValueError, match=message):
        Surface(**{**base, **kwargs})


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
    assert c.lam == pytest.approx(md_lambda(w / c.h, w, R, c.E_star), rel=1e-12)


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
    with pytest.raises(ValueError, match="alpha must be > 0"):
        surface_from_groups(0.0, 100.0, 2.5e-10, 1e12, 1e-6)


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
    with pytest.raises(ValueError, match="surface must be"):
        PhysicalContact("Au", (SIGMA, RADIUS, ETA, AREA))


def test_load_errors_are_stated_in_newtons(surface):
    c = PhysicalContact("Au", surface)
    limit = c.pull_off().force
    with pytest.raises(ValueError, match=r"N G b\^2 = [0-9.e-]+ N"):
        c.load_curve(-2 * limit)
    with pytest.raises(ValueError, match=r"P \(load\) must be > 0 without adhesion"):
        PhysicalContact("Au", surface, adhesion=False).load_curve(0.0)
    with pytest.raises(ValueError, match=r"d \(separation\) must lie in \[.*\] m"):
        c.separation_curve(1e-6)


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

def test_tabor_parameter():
    R, w, E, z0 = 1e-6, 0.1, 1e11, 0.3e-9
    assert tabor_parameter(R, w, E, z0) == pytest.approx((R * w**2 / (E**2 * z0**3)) ** (1 / 3), rel=1e-14)
    assert tabor_parameter(1 * u.um, 0.1 * u.J / u.m**2, 100 * u.GPa, 0.3 * u.nm) == pytest.approx(
        tabor_parameter(R, w, E, z0), rel=1e-13)
    out = tabor_parameter([1e-6, 8e-6], w, E, z0)
    assert out.shape == (2,) and out[1] == pytest.approx(2 * out[0])
    with pytest.raises(ValueError, match="z0 must be > 0"):
        tabor_parameter(R, w, E, 0.0)


def test_maugis_parameter_is_eq14():
    R, w, E, s0 = 1e-6, 0.1, 1e11, 3e8
    K = 4 / 3 * E
    assert maugis_parameter(R, w, E, s0) == pytest.approx(2 * s0 * (R / (math.pi * w * K**2)) ** (1 / 3), rel=1e-14)
    lam = maugis_parameter(R, w, E, s0)
    np.testing.assert_allclose(maugis_parameter(R, w, E, [s0, 2 * s0]), [lam, 2 * lam], rtol=1e-14)
    with pytest.raises(ValueError, match="w must have units"):
        maugis_parameter(R, 1 * u.Pa, E, s0)


def test_adhesion_regime():
    assert adhesion_regime(0.05) == "DMT"
    assert adhesion_regime(0.1) == "Maugis-Dugdale"
    assert adhesion_regime(5.0) == "Maugis-Dugdale"
    assert adhesion_regime(5.1) == "JKR"
    assert list(adhesion_regime([0.0, 1.0, 100.0])) == ["DMT", "Maugis-Dugdale", "JKR"]
    assert adhesion_regime(0.5, dmt_below=1.0, jkr_above=3.0) == "DMT"
    with pytest.raises(ValueError, match="dmt_below must be < jkr_above"):
        adhesion_regime(1.0, dmt_below=5.0, jkr_above=0.1)
    with pytest.raises(ValueError, match="lam must be >= 0"):
        adhesion_regime(-1.0)


def test_fuller_tabor_parameter():
    sigma, R, w, E = 2e-9, 1e-6, 0.1, 1e11
    theta = fuller_tabor_parameter(sigma, R, w, E)
    assert theta == pytest.approx(E * sigma**1.5 / (math.sqrt(R) * w), rel=1e-14)
    hertz_over_adhesion = (4 / 3) * E * math.sqrt(R) * sigma**1.5 / (math.pi * w * R)
    assert hertz_over_adhesion == pytest.approx(4 / (3 * math.pi) * theta, rel=1e-14)
    assert fuller_tabor_parameter(2 * u.nm, 1 * u.um, w, E) == pytest.approx(theta, rel=1e-13)
    assert fuller_tabor_parameter([sigma, 4 * sigma], R, w, E)[1] == pytest.approx(8 * theta)
