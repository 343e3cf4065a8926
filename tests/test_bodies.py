"""asperity.bodies.contact_material: the body a contact computes, from the table or one's own values."""

import math

import pint
import pytest
from hypothesis import given
from hypothesis import strategies as st

from asperity.bodies import contact_material
from asperity.materials import Material, material, pair

u = pint.UnitRegistry()


def test_a_table_name_is_the_table_body_on_a_rigid_flat():
    gold = material("Au")
    m = contact_material("Au")
    assert m == gold and m.bodies == () and not m.is_pair
    assert "on a rigid flat" in m.describe()


def test_a_pair_name_is_two_bodies_with_half_the_composite_moduli():
    # Two identical bodies: 1/E* = 2(1-nu^2)/E and G* = 2G^2/(2G) = G, by hand.
    E, nu = 78e9, 0.44
    one, two = contact_material("Au"), contact_material("Au/Au")
    assert two.is_pair and two.components == ("Au", "Au")
    assert one.E_star == pytest.approx(E / (1 - nu**2), rel=1e-14)
    assert two.E_star == pytest.approx(E / (2 * (1 - nu**2)), rel=1e-14)
    assert two.G_star == pytest.approx(E / (2 * (1 + nu)), rel=1e-14)
    assert two.w == 3.012 and two.b == one.b
    assert contact_material("Au", material2="Au") == two
    assert [b.name for b in two.bodies] == ["Au", "Au"] and two.describe().count("Au (E 78 GPa") == 2


def test_overrides_replace_the_table_values():
    m = contact_material("Au", w=0.1, b=0.3 * u.nm, h="0.5nm", E="70GPa", nu=0.4)
    assert (m.E, m.nu, m.w, m.b, m.h) == pytest.approx((70e9, 0.4, 0.1, 3e-10, 5e-10), rel=1e-14)
    assert m.sigma0 is None and m.name == "Au"
    s = contact_material("Au", w=0.1, sigma0=1e9)
    assert s.h == pytest.approx(0.1 / 1e9, rel=1e-15) and s.sigma0 == 1e9


def test_a_body_not_in_the_table():
    m = contact_material(E=70e9, nu=0.2, b=2.5e-10, w=0.05)
    assert m.E_star == pytest.approx(70e9 / (1 - 0.04), rel=1e-15)
    assert (m.b, m.w, m.bodies) == (2.5e-10, 0.05, ())


def test_second_body_of_ones_own_or_overridden():
    si = material("Si")
    m = contact_material("Au", E2=si.E, nu2=si.nu, b=2.9e-10)
    ref = pair("Au", si, b=2.9e-10)
    assert m.E_star == pytest.approx(ref.E_star, rel=1e-15) and m.G_star == pytest.approx(ref.G_star, rel=1e-15)
    assert m.w is None  # two different bodies: the interface energy is unknown
    stiffer = contact_material("Au", material2="Si", E2=2 * si.E, b=2.9e-10)
    e_star = 1 / ((1 - 0.44**2) / 78e9 + (1 - si.nu**2) / (2 * si.E))
    assert stiffer.E_star == pytest.approx(e_star, rel=1e-14)


def test_a_b_of_two_table_names_needs_a_common_burgers_vector():
    with pytest.raises(ValueError, match=r"different Burgers vectors"):
        contact_material("Au/Si")
    m = contact_material("Au/Si", b=3e-10, w=0.5)
    assert m.components == ("Au", "Si") and (m.b, m.w) == (3e-10, 0.5)
    assert m.E_star == pytest.approx(pair("Au", "Si", b=3e-10).E_star, rel=1e-15)
    with pytest.raises(ValueError, match=r"contact_material\('Au/Si', b=...\)"):
        material("Au/Si")


def test_a_table_pair_keeps_its_work_of_adhesion_under_overrides():
    m = contact_material("Au/Au", E=70e9)
    assert m.w == 3.012 and m.bodies[0].E == 70e9 and m.bodies[1].E == 78e9


@given(E=st.floats(1e8, 1e13), nu=st.floats(-0.99, 0.499), E2=st.floats(1e8, 1e13), nu2=st.floats(-0.99, 0.499))
def test_own_pair_equals_the_library_pair(E, nu, E2, nu2):
    m = contact_material(E=E, nu=nu, E2=E2, nu2=nu2, b=3e-10, w=1.0)
    e_star = 1 / ((1 - nu**2) / E + (1 - nu2**2) / E2)
    assert m.E_star == pytest.approx(e_star, rel=1e-11)
    assert m.G_star == pytest.approx(2 / (2 * (1 + nu) / E + 2 * (1 + nu2) / E2), rel=1e-12)


@pytest.mark.parametrize("kwargs, error, message", [
    ({}, ValueError, r"give a material"),
    ({"E": 1e9}, ValueError, r"^nu is needed"),
    ({"nu": 0.3}, ValueError, r"^E is needed"),
    ({"material": "Au", "E2": 1e9}, ValueError, r"^nu2 is needed"),
    ({"material": "Au", "nu2": 0.3}, ValueError, r"^E2 is needed"),
    ({"material": "Au/Au", "material2": "Si"}, ValueError, r"already a pair"),
    ({"material": "Au", "material2": "Au/Au"}, ValueError, r"material2 must be one body"),
    ({"material": 3}, TypeError, r"^material must be"),
    ({"material": "Au", "material2": 3.0}, TypeError, r"^material2 must be"),
    ({"material": "Xx"}, ValueError, r"unknown material 'Xx'"),
    ({"material": "Au", "E": -1.0}, ValueError, r"^E must be > 0"),
    ({"material": "Au", "E2": True, "nu2": 0.3}, ValueError, r"^E2 must be a real number"),
    ({"material": "Au", "nu": 0.5}, ValueError, r"^nu \(Poisson's ratio\)"),
    ({"material": "Au", "E2": 1e9, "nu2": -1.0}, ValueError, r"^nu2 \(Poisson's ratio\)"),
    ({"material": "Au", "w": -0.1}, ValueError, r"^w must be >= 0"),
    ({"material": "Au", "b": "1 N"}, ValueError, r"^b must have units compatible with m"),
    ({"material": "Au", "h": math.nan}, ValueError, r"^h must be finite"),
    ({"material": "Au", "sigma0": [1e9, 2e9]}, ValueError, r"^sigma0 must be a scalar"),
    ({"material": "Au", "h": 1e-10, "sigma0": 1e9}, ValueError, r"h and sigma0 disagree"),
])
def test_errors_name_the_parameter(kwargs, error, message):
    with pytest.raises(error, match=message):
        contact_material(**kwargs)


def test_materials_of_ones_own_are_accepted_as_is():
    m = Material("film", E=5e9, nu=0.35, b=3e-10, w=0.04, sigma0=1e8)
    assert contact_material(m) == m
    # A new w keeps the Dugdale stress and re-derives h = w/sigma0.
    assert contact_material(m, w=0.08).h == pytest.approx(0.08 / 1e8, rel=1e-15)
