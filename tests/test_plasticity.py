"""asperity.plasticity and the plasticity of a PhysicalContact: psi, omega_c, the warning, the law."""

import math
import warnings

import numpy as np
import pint
import pytest

import asperity
from asperity import JacksonGreen, Model, PlasticityWarning
from asperity.materials import Material, material, pair
from asperity.physical import PhysicalContact, Surface
from asperity.plasticity import PLASTIC_THRESHOLD, plastic_share, plasticity_index

u = pint.UnitRegistry()
GOLD_SURFACE = Surface(2e-9, 1e-6, 1e12, 1e-6)  # sigma_s = 2 nm, R = 1 um: psi = 23, very plastic
DISK = Surface(0.5e-9, 50e-6, 1e10, 1e-6)  # a polished surface of large summits


def test_plasticity_index_by_hand():
    # Au: E* = 78 GPa / (1 - 0.44^2) = 96.726 GPa, H = 188 MPa: psi = 514.50 sqrt(2e-3) = 23.009
    c = PhysicalContact("Au", GOLD_SURFACE, adhesion=False)
    assert c.hardness == 188e6
    assert c.plasticity_index == pytest.approx(23.009, rel=1e-4)
    assert plasticity_index(100e9, 1e9, 4e-9, 1e-6) == pytest.approx(100 * math.sqrt(4e-3), rel=1e-15)
    assert c.parameters()["psi"] == c.plasticity_index


def test_critical_interference_by_hand():
    c = PhysicalContact("Au", GOLD_SURFACE, adhesion=False)
    C = 1.295 * math.exp(0.736 * 0.44)
    S_y = 188e6 / 2.84
    w_c = (math.pi * C * S_y / (2 * c.E_star)) ** 2 * 1e-6  # JG: (pi C S_y / 2E*)^2 R
    assert c.critical_interference == pytest.approx(w_c, rel=1e-12)
    assert c.critical_interference == pytest.approx(3.70e-12, rel=1e-2)  # 3.7 pm: gold asperities yield at once


def test_elastic_model_warns_when_asperities_yield():
    c = PhysicalContact("Au", GOLD_SURFACE)  # Maugis-Dugdale, elastic
    with pytest.warns(PlasticityWarning, match=r"of the asperities in contact are past the critical interference"):
        c.load_curve([1e-3, 0.1])
    with pytest.warns(PlasticityWarning, match=r"psi = 23"):
        c.separation_curve([2e-9])


def test_the_warning_is_filterable_and_its_threshold_adjustable():
    c = PhysicalContact("Au", GOLD_SURFACE, adhesion=False)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        warnings.simplefilter("ignore", asperity.PlasticityWarning)
        c.load_curve([1e-3])
        PhysicalContact("Au", GOLD_SURFACE, adhesion=False, plastic_threshold=1.0).load_curve([1e-3])
    assert issubclass(PlasticityWarning, UserWarning) and PLASTIC_THRESHOLD == 0.01


def test_threshold_is_a_share_of_the_contacts():
    # Hard, smooth, large summits (diamond, psi ~ 0.1): a few asperities yield at high loads only.
    c = PhysicalContact("diamond", DISK, adhesion=False)
    assert c.plasticity_index < 0.2
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        c.load_curve([1e-3])  # hardly anything yields: no warning
    share = plastic_share(np.array([0.0, 0.02, 0.3]), np.array([0.0, 1.0, 1.0]))
    assert share.tolist() == [0.0, 0.02, 0.3]


def test_no_hardness_no_check():
    mat = Material("soft", E=1e9, nu=0.4, b=3e-10, w=0.05)
    c = PhysicalContact(mat, GOLD_SURFACE)
    assert c.hardness is None and c.critical_interference is None and c.parameters()["psi"] is None
    with pytest.raises(ValueError, match="has no hardness: give hardness="):
        _ = c.plasticity_index
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        c.load_curve([1e-6])


def test_jackson_green_contact_is_the_model_with_the_law():
    c = PhysicalContact("Au", GOLD_SURFACE, plasticity="jackson-green", adhesion=False)
    loads = np.array([1e-3, 0.1])
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the plastic law does not warn
        curve = c.load_curve(loads)
    E_star = c.E_star
    m = Model(c.alpha, c.beta, nu=c.nu, law=JacksonGreen(188e6 / E_star))
    ref = m.load_curve(loads / c.force_scale)
    np.testing.assert_allclose(curve.area, ref.area * c.area_scale, rtol=1e-13)
    np.testing.assert_allclose(curve.plastic, ref.plastic * c.N, rtol=1e-13)
    assert list(curve.columns())[-1] == "plastic" and "plastic" in curve.to_csv().splitlines()[0]
    # gold asperities are fully plastic: the mean pressure is close to the hardness
    assert np.all(np.abs(curve.pressure / 188e6 - 1) < 0.1)
    assert c.parameters()["law"] == "jackson-green"


def test_plasticity_lowers_the_friction_coefficient_of_gold():
    el = PhysicalContact("Au", GOLD_SURFACE, adhesion=False, plastic_threshold=1.0)
    pl = PhysicalContact("Au", GOLD_SURFACE, adhesion=False, plasticity="jackson-green")
    loads = [1e-3, 1e-1]
    e, p = el.load_curve(loads), pl.load_curve(loads)
    assert np.all(p.area > 2 * e.area) and np.all(p.F > e.F) and np.all(p.pressure < e.pressure)


def test_adhesion_with_the_plastic_law_is_refused():
    with pytest.raises(ValueError, match=r"has no adhesion.*pass adhesion=False"):
        PhysicalContact("Au", GOLD_SURFACE, plasticity="jackson-green")


def test_size_effect_from_the_table_and_explicit():
    cu = material("Cu")
    assert (cu.H, cu.H0, cu.h_star) == (343e6, 0.5831e9, 1.60e-6)
    plain = PhysicalContact("Cu", GOLD_SURFACE, adhesion=False)
    sized = PhysicalContact("Cu", GOLD_SURFACE, adhesion=False, size_effect=True)
    assert (sized.hardness, sized.h_star) == (0.5831e9, 1.60e-6)
    assert sized.critical_interference > 100 * plain.critical_interference
    explicit = PhysicalContact("Cu", GOLD_SURFACE, adhesion=False, hardness=0.5831 * u.GPa, h_star=1.6 * u.um)
    assert explicit.critical_interference == pytest.approx(sized.critical_interference, rel=1e-12)
    gold = PhysicalContact("Au", GOLD_SURFACE, adhesion=False, hardness="300MPa", h_star="1um",
                           plasticity="jackson-green")
    assert gold.model.law.h_star == pytest.approx(1e-6 / 2e-9, rel=1e-15)
    assert gold.model.law.H_over_E == pytest.approx(300e6 / gold.E_star, rel=1e-15)


@pytest.mark.parametrize("kwargs, match", [
    ({"size_effect": True}, r"size_effect=True \(the size effect\) needs the Nix-Gao pair H0 and h_star"),
    ({"size_effect": False, "h_star": 1e-6}, r"h_star \(Nix-Gao length\) needs size_effect=True"),
    ({"size_effect": "yes"}, r"size_effect must be True, False or None"),
    ({"plasticity": "kogut-etsion"}, r"plasticity must be a law name, one of elastic, jackson-green"),
    ({"hardness": -1.0}, r"hardness must be > 0 Pa"),
    ({"hardness": "2nm"}, r"hardness"),
    ({"plastic_threshold": 2.0}, r"plastic_threshold must lie in \[0, 1\]"),
    ({"plastic_threshold": float("nan")}, r"plastic_threshold must be finite"),
])
def test_bad_plasticity_input(kwargs, match):
    with pytest.raises(ValueError, match=match):
        PhysicalContact("Au", GOLD_SURFACE, adhesion=False, **kwargs)


def test_plastic_law_needs_a_hardness():
    mat = Material("soft", E=1e9, nu=0.4, b=3e-10)
    with pytest.raises(ValueError, match=r"plasticity='jackson-green' needs a hardness"):
        PhysicalContact(mat, GOLD_SURFACE, adhesion=False, plasticity="jackson-green")


def test_table_hardness_and_pairs():
    assert material("Au").H == 188e6 and material("Si").H == 9.6301e9 and material("mica").H is None
    assert material("Au/Au").H == 188e6  # a pair of one material keeps its hardness
    assert material("Au/mica").H is None  # which body yields is not guessed
    assert pair("Au", "mica", H=188e6).H == 188e6
    with pytest.raises(ValueError, match=r"H must be > 0 Pa"):
        Material("x", E=1e9, nu=0.3, H=0.0)


def test_physical_plastic_column_in_every_export():
    pytest.importorskip("pandas")
    c = PhysicalContact("Au", GOLD_SURFACE, adhesion=False, plasticity="jackson-green").separation_curve([1e-9, 2e-9])
    frame = c.to_dataframe()
    assert list(frame.columns)[-1] == "plastic" and frame.attrs["units"]["plastic"] == "1"
    np.testing.assert_array_equal(frame["plastic"], c.plastic)
    assert np.all(c.plastic <= c.contacts)


def test_out_of_range_hardness_is_refused_at_construction():
    with pytest.raises(ValueError, match=r"H_over_E .* \(0, 0.142\]"):
        PhysicalContact("Au", GOLD_SURFACE, adhesion=False, plasticity="jackson-green", hardness="20GPa")


def test_h_star_zero_is_no_size_effect_and_the_message_names_only_what_lacks():
    """Found by a review: ``--h-star 0um`` (the help: '0 = no size effect') was refused as a
    size effect without the Nix-Gao pair, and the message asked for h_star when it was given."""
    S = Surface("2nm", "1um", "1e12/m^2", "1mm^2")
    plain = PhysicalContact("Au", S, adhesion=False, plasticity="jackson-green")
    zero = PhysicalContact("Au", S, adhesion=False, plasticity="jackson-green", h_star="0um")
    assert zero.hardness == plain.hardness and zero.h_star == 0.0
    np.testing.assert_array_equal(zero.load_curve([1e-3]).F, plain.load_curve([1e-3]).F)
    with pytest.raises(ValueError, match=r"give hardness= \(H0, Pa\) \(command line: --hardness\)$"):
        PhysicalContact("Au", S, adhesion=False, plasticity="jackson-green", h_star="1um")
    with pytest.raises(ValueError, match=r"give h_star= \(m\) \(command line: --h-star\)$"):
        PhysicalContact("Au", S, adhesion=False, plasticity="jackson-green", size_effect=True, hardness="200MPa")


def test_the_documented_ceb_factor_is_the_computed_one():
    """A review: the docs said u_c^(-1/2) = 0.89 psi at nu = 0.3 (the reciprocal); the library's
    critical penetration gives 2 * 2.84 / (pi C(0.3)) = 1.12."""
    import re
    from pathlib import Path

    from asperity.elastic_plastic import critical_penetration

    alpha, H_over_E = 0.01, 0.002
    psi = alpha / H_over_E  # (E*/H)(sigma_s/R)^(1/2), alpha = (sigma_s/R)^(1/2)
    factor = critical_penetration(alpha, 0.3, H_over_E) ** -0.5 / psi
    doc = (Path(__file__).resolve().parents[1] / "docs" / "plasticity.md").read_text()
    documented = float(re.search(r"i\.e\. \$([\d.]+)\\,\\psi\$ at", doc).group(1))
    assert factor == pytest.approx(documented, abs=0.005)
    assert factor == pytest.approx(2 * 2.84 / (math.pi * 1.295 * math.exp(0.736 * 0.3)), rel=1e-12)
