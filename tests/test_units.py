"""asperity.units: pint quantities and unit strings to SI floats."""

import math
import re

import numpy as np
import pint
import pytest
from hypothesis import given
from hypothesis import strategies as st

from asperity import units
from asperity.units import parse_quantity

u = pint.UnitRegistry()


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


@given(st.integers(min_value=-(2**53), max_value=2**53),
       st.sampled_from([("pm", -12), ("nm", -9), ("um", -6), ("µm", -6), ("mm", -3), ("km", 3), ("GPa", 9)]))
def test_si_prefixes_scale_integers_exactly(m, prefixed):
    """Found by a review: '60nm' read as 6.000000000000001e-08 (times the rounded 1e-9) and was
    refused at the bound 6e-8 m; a decimal prefix now divides by the exact power of ten, so an
    integer count of the unit is the correctly rounded SI value, as the decimal literal is."""
    unit, k = prefixed
    target = "Pa" if unit == "GPa" else "m"
    assert parse_quantity(f"{m}{unit}", target, "x") == float(f"{m}e{k}")


@given(st.integers(min_value=-(2**53), max_value=2**53),
       st.sampled_from([("/um^2", 12), (" 1/um^2", 12), (" um^-2", 12), ("/nm^2", 18), ("/mm^2", 6),
                        (" 1/cm^2", 4), ("/um**2", 12), (" µm^-2", 12)]))
def test_inverse_prefixed_units_scale_integers_exactly(m, inverse):
    """Found by a review: '1/um^2' read as 1.0000000000000001e12 (pint's factor is a few ulps
    off 10**12); a factor that close to a power of ten is taken as that power."""
    unit, k = inverse
    assert parse_quantity(f"{m}{unit}", "1/m^2", "eta") == float(f"{m}e{k}")


def test_a_positive_exponent_before_a_unit_is_a_number_not_a_complex_literal():
    assert parse_quantity("1e0J/m^2", "J/m^2", "w") == 1.0
    assert parse_quantity("1e10J/m^2", "J/m^2", "w") == 1e10
    assert parse_quantity("1e12/m^2", "1/m^2", "eta") == 1e12
    assert parse_quantity("2.885Å", "m", "b") == pytest.approx(2.885e-10, rel=1e-15)
    with pytest.raises(ValueError, match="x must have units compatible with m"):
        parse_quantity("3J", "m", "x")


def test_expressions_and_wrong_dimensions_keep_the_whole_texts_meaning():
    assert parse_quantity("3 m + 2 m", "m", "x") == 5.0  # not 3 * (m + 2 m)
    with pytest.raises(ValueError, match="got 3 joule"):
        parse_quantity("3J", "m", "x")


@pytest.mark.parametrize("text, unit, needle", [
    ("0,5J/m^2", "J/m^2", "did you mean '0.5J/m^2'?"),   # pint read 0 (adhesion silently off)
    ("1,5nm", "m", "did you mean '1.5nm'?"),              # pint read 15 nm
    ("2,0nm", "m", "',' and ';' are not part of a quantity"),
    ("1;2 nN", "N", "',' and ';' are not part of a quantity"),
    ("1 nN, 2", "N", "',' and ';'"),
    ("1 nN 2", "N", "numbers set side by side are not read"),  # pint read 2 nN
    ("2 1 nN", "N", "numbers set side by side"),
    ("2 m 3", "m", "numbers set side by side"),
])
def test_a_quantity_pint_would_misread_is_refused(text, unit, needle):
    """Found by a review: pint multiplies juxtaposed terms and reads ',' as nothing."""
    with pytest.raises(ValueError, match=re.escape(needle)):
        parse_quantity(text, unit, "x")


@pytest.mark.parametrize("text, unit, value", [("5 1/um^2", "1/m^2", 5e12), ("3 m + 2 m", "m", 5.0),
                                                ("1e+12 1/m^2", "1/m^2", 1e12), ("0.5 J / m ** 2", "J/m^2", 0.5),
                                                ("2 * 3 m", "m", 6.0)])
def test_explicit_expressions_are_still_read(text, unit, value):
    assert parse_quantity(text, unit, "x") == pytest.approx(value, rel=1e-15)


def test_quantities_are_converted_where_units_are_taken_and_refused_where_not():
    """A review: NumPy dropped pint units (with pint's UnitStrippedWarning): a 1 um radius was
    read as 1 m by the single-asperity functions, nN friction data as newtons times 1e9, and
    the dimensionless model took alpha in metres."""
    import warnings

    import asperity
    from asperity.dmt import dmt_pull_off_force
    from asperity.fit import friction_load_data
    from asperity.hertz import hertz_contact_radius
    from asperity.jkr import jkr_contact_radius
    from asperity.maugis_dugdale_load import md_contact_radius, md_normal_force

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert hertz_contact_radius(1 * u.nN, R=1 * u.um, E_star=100 * u.GPa) == \
            hertz_contact_radius(1e-9, R=1e-6, E_star=100e9)
        np.testing.assert_array_equal(
            jkr_contact_radius(np.array([1.0, 2.0]) * u.nN, R=1 * u.um, w=0.1 * u.J / u.m**2, E_star=100 * u.GPa),
            jkr_contact_radius(np.array([1e-9, 2e-9]), R=1e-6, w=0.1, E_star=100e9))
        assert dmt_pull_off_force(R=1 * u.um, w=0.1 * u.J / u.m**2) == dmt_pull_off_force(R=1e-6, w=0.1)
        assert md_contact_radius(1 * u.nN, R=1 * u.um, w=0.1 * u.J / u.m**2, E_star=100 * u.GPa, sigma0=1 * u.GPa) \
            == md_contact_radius(1e-9, R=1e-6, w=0.1, E_star=100e9, sigma0=1e9)
        assert md_normal_force(1 * u.nm, R=1 * u.um, w=0.1 * u.J / u.m**2, E_star=100 * u.GPa, lam=1.0) == \
            md_normal_force(1e-9, R=1e-6, w=0.1, E_star=100e9, lam=1.0)
        data = friction_load_data(np.array([1.0, 2, 3]) * u.nN, np.array([2.0, 3, 4]) * u.nN, physical=True)
        np.testing.assert_allclose(data.y, [2e-9, 3e-9, 4e-9], rtol=1e-15)
        data = friction_load_data([1 * u.nN, 2 * u.nN, "3nN"], [2 * u.nN, 3 * u.nN, 4 * u.nN], physical=True)
        np.testing.assert_allclose(data.x, [1e-9, 2e-9, 3e-9], rtol=1e-15)
        # a dimensionless quantity is its number
        loads = np.array([1.0, 2.0]) * u.dimensionless
        np.testing.assert_array_equal(asperity.Model(0.05, 1000, 1e-3).load_curve(loads).P, [1.0, 2.0])
    for call, needle in [(lambda: asperity.Model(0.05 * u.m, 1000, 1e-3), "alpha is a number in the model's own units"),
                         (lambda: asperity.Model(0.05, 1000, 1e-3).load_curve(1.0 * u.N), "P is a number"),
                         (lambda: asperity.cycle(0.05, 1000, 1e-3, d_min=0, stiffness=1 * u.N / u.m), "stiffness is"),
                         (lambda: friction_load_data(np.array([1.0, 2]) * u.nN, np.array([2.0, 3]) * u.nN),
                          "pass physical=True"),
                         (lambda: hertz_contact_radius(1 * u.m, R=1 * u.um, E_star=1 * u.GPa), "compatible with N")]:
        with pytest.raises(ValueError, match=re.escape(needle)):
            call()


@pytest.mark.parametrize("text, needle", [("1_0 nN", "digits 0-9"), ("\u0661 nN", "digits 0-9"),
                                          ("nN", "has no number"), ("\u00b5N", "has no number"),
                                          ("1e-400 N", "smaller than the smallest double")])
def test_numbers_python_would_misread_are_refused(text, needle):
    """A review: '1_0' read as 10, an Arabic-Indic digit as 1, a bare unit as 1 of it, and
    1e-400 N as 0 N (then mu = nan)."""
    with pytest.raises(ValueError, match=re.escape(needle)):
        parse_quantity(text, "N", "load")


def test_strict_float_reads_decimals_only():
    from asperity.units import strict_float

    assert [strict_float(t) for t in ("1", " -2.5e3 ", ".5", "5.", "1e-320")] == [1.0, -2500.0, 0.5, 5.0, 1e-320]
    assert math.isnan(strict_float("NaN")) and strict_float("-inf") == -math.inf
    for bad in ("1_0", "\u0661", "0x10", "1e-400", "", "1 2", "infinit"):
        with pytest.raises(ValueError):
            strict_float(bad)


@pytest.mark.parametrize("text, unit, value", [("2 nm\u00b2", "m^2", 2e-18), ("1/\u00b5m\u00b2", "1/m^2", 1e12),
                                                ("5 \u00b5m\u207b\u00b2", "1/m^2", 5e12), ("1 m\u00b3", "m^3", 1.0)])
def test_superscript_units_are_read(text, unit, value):
    """A second review: the check for other scripts' digits refused superscripts ('nm²')."""
    assert parse_quantity(text, unit, "x") == pytest.approx(value, rel=1e-15)


@pytest.mark.parametrize("text, unit, needle", [
    ("1 nN\u00a02", "N", "side by side"),       # a no-break space hid the juxtaposition
    ("1 (nm) 2", "m", "one number with its unit"), ("(1) 2 nm", "m", "side by side"), ("1 nm (2)", "m", "side by side"),
    ("2 1/2 nm", "m", "side by side"),          # pint: 1 nm; a user may mean 2.5
    ("1e-9 N 1/2", "N", "side by side"),
    ("1e-320 nm", "m", "below the smallest double in m"), ("(1e-400) nm", "m", "smaller than the smallest double"),
    ("nanometer", "m", "has no number"), ("1 \u00b10.1 nm", "m", "one number with its unit"),
    ("nanGPa", "Pa", "no NaN or infinity"), ("-infnm", "m", "no NaN or infinity"),  # not "e.g. '1 nanGPa'"
    ("nan\u00b5m", "m", "no NaN or infinity"), ("inf\u00c5", "m", "no NaN or infinity"),
])
def test_second_review_misreadings_are_refused(text, unit, needle):
    with pytest.raises(ValueError, match=re.escape(needle)):
        parse_quantity(text, unit, "x")


@pytest.mark.parametrize("text", ["2'5nm", "1'000 nN", "2\u00b75 nm", "1\u20132 nm", "2:5nm", "2\u00bd nm",
                                  "1 um & 2", "3 nm#2", "2.5.3 nm", "1..2 nm", "(2)(3) nm", "1 % nm", "2(3) nm"])
def test_characters_pint_would_drop_are_refused(text):
    """A third review: pint drops characters it does not know and multiplies the rest ("2'5nm"
    was 10 nm, "1'000 nN" 0 N, '1 % nm' 0.01 nm)."""
    with pytest.raises(ValueError, match="cannot be part of a quantity|one number with its unit"):
        parse_quantity(text, "N" if "N" in text else "m", "x")


@pytest.mark.parametrize("text, unit, value", [("\u22125 nN", "N", -5e-9), ("- 5 nN", "N", -5e-9),
                                                ("10 N m^\u22121", "N/m", 10.0), ("2e14 m^\u22122", "1/m^2", 2e14)])
def test_the_typeset_minus_sign_is_a_minus(text, unit, value):
    assert parse_quantity(text, unit, "x") == pytest.approx(value, rel=1e-15)


@pytest.mark.parametrize("text, unit", [("1e-200*1e-200 m", "m"), ("1e-200 m * 1e-200", "m"),
                                        ("-1e-200*1e-200 nN", "N"), ("1e-200*-1e-200 m", "m"),
                                        ("1e-160 nm*1e-160", "m"), ("1e-200 m / 1e200", "m")])
def test_a_product_that_underflows_is_refused(text, unit):
    """Each literal was checked, but arithmetic of nonzero numbers could still round to 0 m."""
    with pytest.raises(ValueError, match="product of its nonzero numbers is below the smallest double"):
        parse_quantity(text, unit, "x")


@pytest.mark.parametrize("text, value", [("0*5 nm", 0.0), ("(1 - 1) nm", 0.0), ("3 m - 3 m", 0.0),
                                         ("1e-5*1e-5 nm", 1e-19), ("2 Angstrom", 2e-10), ("2 angstrom", 2e-10),
                                         ("2\u00c5", 2e-10)])
def test_zeros_that_are_meant_and_the_angstrom_spellings(text, value):
    assert parse_quantity(text, "m", "x") == pytest.approx(value, rel=1e-15, abs=0.0)


def test_every_si_function_takes_quantities():
    """A review: md_lambda, persson/bgt's p, cgp_shift's p, plasticity_index and the groups
    refused pint quantities ('a number in the model's own units') though documented in SI."""
    import warnings

    from asperity.groups import adhesion_gamma, regime_beta, roughness_alpha
    from asperity.interaction import cgp_shift
    from asperity.maugis_dugdale import md_lambda
    from asperity.persson import bgt_area_fraction, persson_area_fraction
    from asperity.plasticity import plasticity_index

    J_m2 = u.J / u.m**2
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        pairs = [
            (md_lambda(20 * u.nm, 0.1 * J_m2, 100 * u.GPa, 1 * u.GPa), md_lambda(20e-9, 0.1, 100e9, 1e9)),
            (persson_area_fraction(100 * u.MPa, 100 * u.GPa, 0.1), persson_area_fraction(1e8, 1e11, 0.1)),
            (bgt_area_fraction(100 * u.MPa, 100 * u.GPa, 0.1), bgt_area_fraction(1e8, 1e11, 0.1)),
            (cgp_shift(1 * u.MPa, 1 * u.mm**2, 100 * u.GPa), cgp_shift(1e6, 1e-6, 1e11)),
            (plasticity_index(100 * u.GPa, 1 * u.GPa, 4 * u.nm, 1 * u.um), plasticity_index(1e11, 1e9, 4e-9, 1e-6)),
            (adhesion_gamma(0.1 * J_m2, 100 * u.GPa, 0.25 * u.nm), adhesion_gamma(0.1, 1e11, 0.25e-9)),
            (regime_beta(4 * u.nm, 1 * u.um, 0.25 * u.nm), regime_beta(4e-9, 1e-6, 0.25e-9)),
            (roughness_alpha(4 * u.nm, 1 * u.um), roughness_alpha(4e-9, 1e-6)),
        ]
    for got, expected in pairs:
        np.testing.assert_allclose(got, expected, rtol=1e-14)
    assert adhesion_gamma(0.0, 1e11, 0.25e-9) == 0.0  # no adhesion is gamma = 0, as its inverse says
    # a ratio of lengths: plain numbers are in any one unit, so a quantity beside them is refused
    # (a second review: roughness_alpha(4 nm, 1.0) divided metres by nanometres)
    for call in (lambda: roughness_alpha(4 * u.nm, 1000.0), lambda: regime_beta(4.0, 1 * u.um, 0.25),
                 lambda: roughness_alpha("4nm", 1000.0), lambda: roughness_alpha(["4 nm"], 1000.0),
                 lambda: regime_beta(4.0, 1000.0, ("2 nm",)),
                 lambda: roughness_alpha([4 * u.nm, 4.0], [1 * u.um, 1 * u.um])):  # a third review: lists
        with pytest.raises(ValueError, match="must be all quantities or all plain numbers"):
            call()
    assert roughness_alpha(4.0, 1000.0) == pytest.approx(roughness_alpha(4 * u.nm, 1 * u.um), rel=1e-15)
    np.testing.assert_allclose(roughness_alpha(["4nm", "9nm"], [1 * u.um, "1um"]), np.sqrt([4e-3, 9e-3]),
                               rtol=1e-15)


@given(st.decimals(min_value="0.001", max_value="100000", places=6, allow_nan=False, allow_infinity=False),
       st.sampled_from([("nm", -9, "m"), ("um", -6, "m"), ("pm", -12, "m"), ("mN", -3, "N"), ("uN", -6, "N"),
                        ("GPa", 9, "Pa"), ("mJ/m^2", -3, "J/m^2")]))
def test_a_prefixed_unit_reads_as_the_number_with_its_exponent(number, prefixed):
    """Found by a review: '3.3nm' was 3.2999999999999998e-09 (3.3 rounded, then divided by
    1e9), '3.3e-9m' 3.3e-09; a quarter of the spellings sampled were one ulp off."""
    unit_text, k, unit = prefixed
    assert parse_quantity(f"{number}{unit_text}", unit, "x") == float(f"{number}e{k}")


@pytest.mark.parametrize("value, text", [(999.95, "1 kPa"), (999960.0, "1 MPa"), (-999.95, "-1 kPa"),
                                         (999.94, "999.9 Pa"), (1e-20, "1e-20 Pa"), (1e15, "1e+15 Pa"),
                                         (1e-15, "1 fPa"), (7.8e10, "78 GPa"), (0.0, "0 Pa")])
def test_format_si_at_the_prefix_edges(value, text):
    """A user trial: 999.95 Pa printed as '1000 Pa', 1e-20 Pa as '1e-05 fPa'."""
    from asperity.units import format_si

    assert format_si(value, "Pa") == text


@given(st.floats(1e-15, 9.9e14) | st.floats(-9.9e14, -1e-15))
def test_format_si_reads_back_to_four_digits_with_a_mantissa_below_1000(value):
    from asperity.units import _PREFIXES, format_si

    number, unit = format_si(value, "Pa").split(" ")
    scale = {f"{p}Pa": 10.0**e for e, p in _PREFIXES.items()}[unit]
    assert 1 <= abs(float(number)) < 1000
    assert float(number) * scale == pytest.approx(value, rel=5e-4)


def test_a_word_that_is_no_unit_is_not_offered_back_as_one():
    """A CLI check: '--fix R_m=abc' suggested "(e.g. '1 abc')"."""
    with pytest.raises(ValueError, match=r"^x = 'abc' is not a number with a unit \(e\.g\. '2\.5nm', '70GPa'\)$"):
        parse_quantity("abc", "m", "x")
    with pytest.raises(ValueError, match=r"has no number: give one before the unit \(e\.g\. '1 nm'\)"):
        parse_quantity("nm", "m", "x")
