"""The explorer's state: fields from the registries, the query string round trip, robust links."""

import dataclasses
import math

import pytest
from hypothesis import given
from hypothesis import strategies as st

from asperity import heights
from asperity.explorer.state import (
    CUSTOM,
    MAX_POINTS,
    MODES,
    START,
    State,
    default_state,
    fields,
    number_text,
    parse_value,
    state_from_query,
)
from asperity.materials import material, material_names
from asperity.quantities import CURVE_COLUMNS, MODEL_PARAMETERS, PHYSICAL_PARAMETERS


def test_fields_come_from_the_registries():
    spec = fields()
    for name in ("alpha", "beta", "gamma", "nu", "h_over_b", "tau_f1", "tau_f2", "a1", "a2"):
        q = MODEL_PARAMETERS[name]
        assert spec[name].quantity is q and spec[name].help == q.help()
        expected = q.default if q.default not in (None, 0.0) else START[name]
        assert spec[name].default == expected
    for name in ("sigma_s", "R", "eta", "area", "b", "w", "E"):
        q = PHYSICAL_PARAMETERS[name]
        f = spec[q.si_name if name not in ("E",) else "E_Pa"]
        assert f.quantity is q and f.unit == q.si_unit
    assert spec["P_min"].quantity is CURVE_COLUMNS["P"] and spec["d_max"].quantity is CURVE_COLUMNS["d"]
    assert spec["material"].choices == (*material_names(), CUSTOM)
    assert spec["mode"].choices == MODES
    au = material(START["material"])
    assert (spec["E_Pa"].default, spec["material_nu"].default, spec["b_m"].default, spec["w_J_m2"].default) == \
        (au.E, au.nu, au.b, au.w)


def test_gaussian_only_without_a_distribution_registry(monkeypatch):
    monkeypatch.delattr(heights, "DISTRIBUTIONS", raising=False)
    assert fields()["heights"].choices == ("gaussian",)


@dataclasses.dataclass(frozen=True)
class ShiftedGaussian(heights.Gaussian):
    """A test distribution with one parameter (its density is irrelevant here)."""

    shift: float = 0.5
    label: str = "not a number field"


def test_a_distribution_registry_appears_with_its_parameters(monkeypatch):
    monkeypatch.setattr(heights, "DISTRIBUTIONS", {"gaussian": heights.Gaussian, "shifted": ShiftedGaussian},
                        raising=False)
    spec = fields()
    assert spec["heights"].choices == ("gaussian", "shifted")
    assert spec["shifted_shift"].default == 0.5 and spec["shifted_shift"].group == "shifted"
    assert "shifted_label" not in spec
    s = default_state()
    assert "shifted_shift" not in s.to_query()  # only with its distribution
    chosen = s.replace(heights="shifted", shifted_shift=1.25)
    assert "heights=shifted" in chosen.to_query() and "shifted_shift=1.25" in chosen.to_query()
    back, messages = state_from_query(chosen.to_query())
    assert back == chosen and messages == []


@given(st.floats(allow_nan=False, allow_infinity=False))
def test_number_text_reads_back_exactly(x):
    text = number_text(x)
    assert float(text) == x and math.copysign(1, float(text)) == math.copysign(1, x)
    assert "+" not in text and len(text) <= len(repr(x)) + 1


def _values():
    """Random views: any mode, material, and numbers of any magnitude for the numeric fields."""
    spec = fields()
    number = st.floats(min_value=-1e300, max_value=1e300, allow_nan=False)
    entries = {}
    for key, f in spec.items():
        if f.kind == "number":
            entries[key] = number
        elif f.kind == "integer":
            entries[key] = st.integers(2, MAX_POINTS)
        elif f.kind == "choice":
            entries[key] = st.sampled_from(f.choices)
        else:
            entries[key] = st.booleans()
    return st.fixed_dictionaries(entries)


@given(_values())
def test_query_string_round_trip(values):
    state = State(values)
    back, messages = state_from_query(state.to_query())
    assert messages == []
    for key in state.shown():
        assert back[key] == state[key] and type(back[key]) is type(state[key]), key
    assert back.to_query() == state.to_query()
    if state["material"] != CUSTOM:
        assert "E_Pa" not in state.to_query()


def test_every_field_and_the_mode_are_in_the_query():
    s = default_state().replace(material=CUSTOM, mode="physical")
    keys = [pair.split("=")[0] for pair in s.to_query().split("&")]
    law_only = {"H_over_E", "h_star_over_sigma"}   # the Jackson-Green law's parameters
    # a distribution's parameters only with it chosen; the custom material's H and h* with it
    assert keys == [k for k, f in fields().items() if f.group in (None, s["heights"]) and k not in law_only]
    assert "H_Pa" in keys and "h_star_m" in keys and "gamma" in keys
    chosen = s.replace(heights="johnson")
    keys = [pair.split("=")[0] for pair in chosen.to_query().split("&")]
    assert keys == [k for k, f in fields().items() if f.group in (None, "johnson") and k not in law_only]
    assert "johnson_kurt" in keys and "weibull_skew" not in keys and "law=elastic" in chosen.to_query()
    # with the elastic-plastic law: its parameters, and no gamma (it has no adhesion)
    plastic = chosen.replace(law="jackson-green", H_over_E=0.02)
    keys = [pair.split("=")[0] for pair in plastic.to_query().split("&")]
    assert keys == [k for k, f in fields().items() if f.group in (None, "johnson") and k != "gamma"]
    back, messages = state_from_query(plastic.to_query())
    assert messages == [] and back.to_query() == plastic.to_query()
    # a table material: none of the custom fields
    table = s.replace(material="Si")
    assert not {"E_Pa", "material_nu", "b_m", "w_J_m2", "H_Pa", "h_star_m"} & set(table.shown())


def test_tornado_arguments_are_read():
    # the Bokeh server hands the query over as {str: [bytes]}
    state, messages = state_from_query({"alpha": [b"0.01"], "mode": [b"physical"], "sigma_s_m": [b"3nm"],
                                        "n": [b"40", b"50"]})
    assert messages == ["link: n given 2 times; the last, '50', is used"]
    assert (state["alpha"], state.mode, state["n"]) == (0.01, "physical", 50)
    assert state["sigma_s_m"] == pytest.approx(3e-9, rel=1e-15)


@pytest.mark.parametrize("query, needle, key", [
    ("alpha=abc", "alpha: expected a number, got 'abc'", "alpha"),
    ("alpha=nan", "expected a finite number", "alpha"),
    ("mode=3d", "mode: unknown choice '3d'", "mode"),
    ("n=1", "from 2 to 2000", "n"),
    ("n=2.5", "from 2 to 2000", "n"),
    ("n=100000", "from 2 to 2000", "n"),
    ("adhesion=maybe", "expected 1 or 0", "adhesion"),
    ("sigma_s_m=2s", "sigma_s", "sigma_s_m"),
    ("material=unobtainium", "unknown choice", "material"),
    ("foo=1", "unknown parameter 'foo'", None),
])
def test_bad_links_keep_defaults_and_say_why(query, needle, key):
    state, messages = state_from_query(query)
    assert len(messages) == 1 and needle in messages[0], messages
    assert state == default_state()


def test_parse_value_with_units_and_errors():
    spec = fields()
    assert parse_value(spec["sigma_s_m"], "2 nm") == pytest.approx(2e-9, rel=1e-15)
    assert parse_value(spec["E_Pa"], "79GPa") == pytest.approx(79e9, rel=1e-15)
    assert parse_value(spec["P_max_N"], "10 mN") == pytest.approx(1e-2, rel=1e-15)
    assert parse_value(spec["sigma_s_m"], "2e-9") == 2e-9  # a bare number is SI
    assert parse_value(spec["alpha"], " 0.01 ") == 0.01
    assert parse_value(spec["adhesion"], "0") is False
    # found by a review: pint's exception text (DimensionalityError, 'got 1 dimensionless' for an
    # empty field) reached the page; now one sentence naming the field, its unit and an example
    for text in ("2 s", "79 kg", "lots", "", "nan"):
        with pytest.raises(ValueError, match=rf"^sigma_s_m: expected a number in m or a quantity with a unit such "
                                             rf"as 2nm, got '{text}'$"):
            parse_value(spec["sigma_s_m"], text)
    with pytest.raises(ValueError, match=r"^E: expected a number in Pa .* such as 79GPa, got '79 kg'$"):
        parse_value(spec["E_Pa"], "79 kg")
    with pytest.raises(ValueError, match=r"beta: expected a number, got ''"):
        parse_value(spec["beta"], "")


def test_replace_rejects_unknown_fields():
    with pytest.raises(KeyError, match="nosuch"):
        default_state().replace(nosuch=1)


@pytest.mark.parametrize("query, needle", [
    ("mode=physical&E_Pa=1e11", "E (E_Pa) is not used in this view (it applies to the custom material; the "
                                "link's material is Au); ignored"),
    ("gamma=0.01&law=jackson-green", "gamma is not used in this view (it applies with law = elastic, not "
                                     "jackson-green); ignored"),
    ("H_over_E=0.005", "(it applies with law = jackson-green, not elastic); ignored"),
    ("mode=physical&plasticity=jackson-green&adhesion=1", "adhesion is not used in this view"),
])
def test_a_link_value_the_view_does_not_use_is_said_to_be_ignored(query, needle):
    """Found by a review: such values vanished from the address without a word."""
    _, messages = state_from_query(query)
    assert messages == [f"link: {needle}"] or any(needle in m for m in messages), messages


def test_the_pages_own_addresses_carry_no_ignored_values():
    for query in ("", "mode=physical", "mode=physical&material=custom&E_Pa=1e11", "law=jackson-green"):
        state, messages = state_from_query(query)
        assert not messages
        again, messages = state_from_query(state.to_query())
        assert again == state and not messages


def test_a_repeated_parameter_of_a_link_is_named():
    """Found by a review: '?alpha=0.01&alpha=0.5' showed alpha = 0.5 with no word."""
    state, messages = state_from_query("alpha=0.01&alpha=0.5")
    assert state.values["alpha"] == 0.5
    assert messages == ["link: alpha given 2 times; the last, '0.5', is used"]
