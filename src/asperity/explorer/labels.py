r"""Plain-text labels from the quantity registry (:mod:`asperity.quantities`).

The registry writes symbols in LaTeX (``r'\bar\tau_{f1}'``, ``'P/NGb^2'``).  Widget titles
are plain text, and the page loads no TeX renderer, so :func:`plain` turns a symbol into
Unicode (``'τ̄_f1'``, ``'P/NGb²'``); :func:`axis_label` and :func:`title` give the axis
labels and plot titles of a curve column in either mode.
"""

from __future__ import annotations

import re

from ..quantities import Quantity

__all__ = ["plain", "axis_label", "title", "unit_text"]

_GREEK = {"alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "Delta": "Δ", "eta": "η", "lambda": "λ",
          "mu": "μ", "nu": "ν", "pi": "π", "phi": "φ", "sigma": "σ", "tau": "τ", "theta": "θ"}
_SUPER = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")
_SUB = dict(zip("0123456789aehijklmnoprstuvx", "₀₁₂₃₄₅₆₇₈₉ₐₑₕᵢⱼₖₗₘₙₒₚᵣₛₜᵤᵥₓ", strict=True))


def _subscript(text: str) -> str:
    return "".join(_SUB[c] for c in text) if all(c in _SUB for c in text) else "_" + text


def plain(symbol: str) -> str:
    r"""A registry symbol (LaTeX, no dollars) as plain Unicode text.

    >>> plain(r"\alpha"), plain(r"\bar\tau_{f1}"), plain(r"P/NGb^2"), plain(r"\sigma_s"), plain(r"E^*")
    ('α', 'τ̄_f1', 'P/NGb²', 'σₛ', 'E*')
    """
    text = re.sub(r"\\([A-Za-z]+)", lambda m: _GREEK.get(m.group(1), "\\" + m.group(1)), symbol)
    text = re.sub(r"\\bar\s*(\{[^}]*\}|\S)", lambda m: m.group(1).strip("{}") + "\u0304", text)
    text = re.sub(r"\^\{?\*\}?", "*", text)
    text = re.sub(r"\^\{([^}]*)\}|\^(\S)", lambda m: (m.group(1) or m.group(2)).translate(_SUPER), text)
    text = re.sub(r"_\{([^}]*)\}|_(\S)", lambda m: _subscript(m.group(1) or m.group(2)), text)
    return text.replace(" ", "")


def unit_text(unit: str) -> str:
    """An SI unit as plain text: ``'m^2'`` -> ``'m²'``, ``'1/m^2'`` -> ``'1/m²'``, ``'J/m^2'`` -> ``'J/m²'``."""
    return re.sub(r"\^(-?\d+)", lambda m: m.group(1).translate(_SUPER), unit)


def axis_label(q: Quantity, physical: bool) -> str:
    """Axis label of a curve column: the symbol in dimensionless mode, name and SI unit in physical mode.

    >>> from asperity.quantities import CURVE_COLUMNS as C
    >>> axis_label(C["P"], False), axis_label(C["P"], True), axis_label(C["contacts"], True), axis_label(C["mu"], True)
    ('P/NGb²', 'P (N)', 'n', 'μ')
    """
    if not physical or not q.si_unit:
        return plain(q.symbol)
    if q.si_unit == "1":  # a count in physical mode (n, not n/N); mu stays mu
        return plain(q.symbol).split("/")[0]
    return f"{q.name} ({unit_text(q.si_unit)})"


def title(q: Quantity, physical: bool) -> str:
    """A short title from the registry's meaning (up to its first parenthesis or comma)."""
    meaning = (q.si_meaning if physical and q.si_meaning else q.meaning)
    text = re.split(r" \((?!N |E\*)|,", meaning)[0]
    return re.sub(r"\bpi\b", "π", unit_text(text)).replace("sigma", "σ")
