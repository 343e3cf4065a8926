"""The library's advice in the page's words (asperity.explorer.wording), on messages the
library itself raises or warns, and in a session."""

import dataclasses
import re
import warnings

import pytest

from asperity import PlasticityWarning
from asperity.explorer.app import attempt
from asperity.explorer.state import fields, state_from_query
from asperity.explorer.wording import page_wording
from asperity.materials import material
from asperity.physical import PhysicalContact
from asperity.surface import Surface

SURFACE = Surface(2e-9, 1e-6, 1e12, 1e-6)
#: What the page must not show: the API's keywords and the command line's options.
API = re.compile(r"adhesion=|hardness=|h_star=|plasticity=|size_effect=|interaction=|dataclasses|asperity\.|"
                 r"command line|--\w")


def _error(**kwargs) -> str:
    with pytest.raises(ValueError) as info:
        PhysicalContact(kwargs.pop("material", "Au"), SURFACE, **kwargs)
    return str(info.value)


CASES = [  # (library message, words of the page it must then contain)
    (lambda: _error(interaction="cgp2008"), ("untick adhesion", "interaction none")),
    (lambda: _error(plasticity="jackson-green"), ("untick adhesion",)),
    (lambda: _error(material=dataclasses.replace(material("Au"), w=None)),
     ("choose the material custom and give its w", "untick adhesion")),
    (lambda: _error(material="mica"), ("choose the material custom and give its b",)),
    (lambda: _error(material=dataclasses.replace(material("Au"), H=None), plasticity="jackson-green",
                    adhesion=False), ("choose the material custom and give its hardness H",)),
    (lambda: _error(material=dataclasses.replace(material("Au"), H0=None), plasticity="jackson-green",
                    size_effect=True, adhesion=False), ("the size effect", "H0 (size effect) and h*")),
    (lambda: _error(material=dataclasses.replace(material("Cu"), H0=None), plasticity="jackson-green",
                    size_effect=True, adhesion=False), ("give its H0 (size effect), or untick the size effect",)),
    (lambda: _error(material=dataclasses.replace(material("Cu"), h_star=None), plasticity="jackson-green",
                    size_effect=True, adhesion=False), ("give its h*, or untick the size effect",)),
]


@pytest.mark.parametrize("case", range(len(CASES)))
def test_library_errors_are_shown_with_the_pages_controls(case):
    produce, words = CASES[case]
    raw = produce()
    assert API.search(raw), raw  # the library's own wording names its keywords
    shown = page_wording(raw)
    assert not API.search(shown), shown
    for w in words:
        assert w in shown, shown
    labels = {f.label for f in fields().values()} | set(fields())
    assert {"adhesion", "interaction", "material", "H", "h*", "w", "b", "H0 (size effect)"} <= labels


def test_the_plasticity_warning_is_shown_with_the_pages_controls():
    contact = PhysicalContact("Au", Surface(20e-9, 0.2e-6, 1e12, 1e-6), adhesion=False)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        contact.load_curve([1e-3])
    raw = next(str(w.message) for w in caught if issubclass(w.category, PlasticityWarning))
    shown = page_wording(raw)
    assert not API.search(shown) and "choose the asperity law jackson-green" in shown, shown


def test_a_message_no_rule_matches_is_shown_as_it_is():
    text = "alpha must be positive, got -1"
    assert page_wording(text) == text


def test_a_session_shows_the_pages_words():
    state, notes = state_from_query("mode=physical&material=Au&interaction=cgp2008")
    assert not notes
    shown = attempt(state)
    assert isinstance(shown, str) and "untick adhesion or choose the interaction none" in shown
    assert not API.search(shown)


def test_fit_file_and_missing_value_advice_in_the_pages_words(tmp_path):
    """Found by a review of the page: the fit panel advised drop_nan=True / --drop-nan, and a
    material value read 'must be > 0 m or None (missing)'."""
    from asperity.bodies import contact_material
    from asperity.fit import read_data

    path = tmp_path / "nan.csv"
    path.write_text("P,F\n1,0.5\n2,nan\n3,1.5\n")
    with pytest.raises(ValueError) as info:
        read_data(path)
    shown = page_wording(str(info.value))
    assert "drop_nan" not in shown and "--drop-nan" not in shown and "remove such rows from the file" in shown
    with pytest.raises(ValueError) as info:
        contact_material(E=7e10, nu=0.3, b=0.0)
    assert "None" in str(info.value) and "None" not in page_wording(str(info.value))


def test_the_two_curves_notes_that_differ_in_numbers_are_shown_once():
    state, _ = state_from_query("mode=physical")
    result = attempt(state)
    assert sum(w.startswith("PlasticityWarning") for w in result.warnings) == 1
