"""asperity.materials: the materials table, Material, pairs and as_material."""

import csv
import io
import math
import re

import pint
import pytest
from hypothesis import given
from hypothesis import strategies as st

from asperity.materials import (
    Material,
    _check_effective_poisson,
    as_material,
    material,
    material_names,
    material_table,
    pair,
)

u = pint.UnitRegistry()


# -- the materials table ---------------------------------------------------------------------

NUMERIC = ["E_Pa", "nu", "G_Pa", "lattice_constant_m", "b_m", "surface_energy_J_m2", "work_of_adhesion_J_m2",
           "hardness_Pa", "ise_H0_Pa", "ise_h_star_m"]


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


# -- as_material and the shared validation ---------------------------------------------------

def test_as_material():
    gold = material("Au")
    assert as_material(gold) is gold
    assert as_material(" au ") == gold
    assert as_material("Au/Au") == material("Au/Au")
    with pytest.raises(TypeError, match=r"body must be an asperity.materials.Material .* got float 3.0"):
        as_material(3.0)
    with pytest.raises(TypeError, match="second must be"):
        pair("Au", None)
    with pytest.raises(ValueError, match="unknown material 'Xx'"):
        as_material("Xx")


@pytest.mark.parametrize("kwargs, message", [
    ({"E": True}, r"E must be a real number, got a boolean"), ({"E": 1e11 + 0j}, r"E must be a real number"),
    ({"E": None}, r"E must be a real number"), ({"E": "79"}, r"E needs a unit compatible with Pa"),
    ({"E": [1e11, 2e11]}, r"E must be a scalar"), ({"nu": float("inf")}, r"nu must be finite"),
    ({"b": -1 * u.nm}, r"b must be > 0 m or None"), ({"sigma0": 0.0}, r"sigma0 must be > 0 Pa or None"),
    ({"w": "1 N"}, r"w must have units compatible with J/m\^2"),
])
def test_material_rejects_bad_types(kwargs, message):
    base = {"name": "x", "E": 1e11, "nu": 0.3, "b": 2.5e-10, "w": 1.0}
    with pytest.raises(ValueError, match=message):
        Material(**{**base, **kwargs})


def test_material_accepts_strings_with_units():
    m = Material("x", E="79 GPa", nu="0.3", b="0.25 nm", w="1 J/m^2", h="0.5 nm")
    assert (m.E, m.nu, m.b, m.w, m.h) == pytest.approx((79e9, 0.3, 2.5e-10, 1.0, 5e-10), rel=1e-14)


def test_table_row_is_a_copy_and_names_unknowns_none():
    from asperity.material_table import material_table, table_row
    row = table_row("  au ")
    assert row["name"] == "Au" and row == next(r for r in material_table() if r["name"] == "Au")
    row["E_Pa"] = -1.0  # the caller's copy: the cached table must not change
    assert table_row("Au")["E_Pa"] > 0 and material("Au").E > 0
    assert table_row("unobtainium") is None
    with pytest.raises(TypeError, match="name must be a string"):
        table_row(3)
