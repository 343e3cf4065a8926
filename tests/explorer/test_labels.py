"""Plain-text labels from the registry's LaTeX symbols; the explorer's doctests."""

import doctest

import pytest

from asperity.explorer import labels, state
from asperity.explorer.labels import axis_label, plain, title, unit_text
from asperity.quantities import CURVE_COLUMNS, MODEL_PARAMETERS, PHYSICAL_PARAMETERS


@pytest.mark.parametrize("module", [labels, state])
def test_doctests(module):
    result = doctest.testmod(module)
    assert result.attempted > 0 and result.failed == 0


@pytest.mark.parametrize("symbol, text", [
    (r"\alpha", "α"), (r"\beta", "β"), (r"\gamma", "γ"), (r"\nu", "ν"), ("h/b", "h/b"),
    (r"\bar\tau_{f1}", "τ̄_f1"), (r"\bar a_1", "a\u0304₁"), (r"\sigma_s", "σₛ"), ("A_0", "A₀"), ("E^*", "E*"),
    (r"d/\sigma", "d/σ"), ("P/NGb^2", "P/NGb²"), (r"A/N\pi b^2", "A/Nπb²"), ("P/E^*A", "P/E*A"), ("n/N", "n/N"),
])
def test_plain_symbols(symbol, text):
    assert plain(symbol) == text


def test_every_registry_symbol_becomes_plain_text():
    for registry in (MODEL_PARAMETERS, PHYSICAL_PARAMETERS, CURVE_COLUMNS):
        for q in registry.values():
            text = plain(q.symbol)
            assert text and not any(c in text for c in "\\{}^$"), (q.name, text)


def test_units_axes_and_titles():
    assert (unit_text("m^2"), unit_text("1/m^2"), unit_text("J/m^2")) == ("m²", "1/m²", "J/m²")
    assert axis_label(CURVE_COLUMNS["pressure"], True) == "pressure (Pa)"
    assert axis_label(CURVE_COLUMNS["d"], False) == "d/σ"
    assert title(CURVE_COLUMNS["area"], False) == "real contact area A/(N π b²)"
    assert title(CURVE_COLUMNS["P"], True) == "total normal force"
