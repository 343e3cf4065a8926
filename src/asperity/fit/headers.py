"""Header cells of measured data files: which column a header names, and its unit.

A header is a name (a role: load, friction, separation, pull-off, a friction coefficient,
or a pull-off condition such as R) and optionally a unit: in brackets (``load [nN]``), in
parentheses (``load (nN)``) or after a slash between blanks (``load / nN``), where the text
is a unit symbol; or an SI suffix (``P_N``, ``d_m``).  :func:`classify_header` reads one
cell; :func:`unit_factor` and :func:`to_si_exact` turn values into SI units (decimal
prefixes exactly).  Used by :mod:`asperity.fit.read`.
"""

from __future__ import annotations

import math
import re
from decimal import Decimal, InvalidOperation

from ..quantities import FIT_PARAMETERS, MODEL_PARAMETERS, PHYSICAL_PARAMETERS
from ..units import is_quantity, parse_quantity, unit_registry

__all__ = ["ROLES", "SI_UNITS", "UNIT_FLAGS", "classify_header", "condition_names", "header_role", "unit_factor",
           "to_si_exact"]

#: Column roles and their spellings (lower case).  The first is the dimensionless symbol.
ROLES = {
    "load": ("p", "load", "normal_force", "normal_load", "force"),
    "friction": ("f", "friction", "friction_force", "lateral_force"),
    "mu": ("mu", "friction_coefficient", "coefficient_of_friction", "cof", "\u00b5", "\u03bc"),
    "separation": ("d", "separation", "distance", "gap"),
    "pull_off": ("p_off", "pull_off", "pull_off_force", "adhesion_force"),
}
SI_UNITS = {"load": "N", "friction": "N", "separation": "m", "pull_off": "N", "mu": ""}
UNIT_FLAGS = {"load": "load", "pull_off": "load", "friction": "friction", "separation": "separation"}
_SUFFIX = {"_n": "N", "_m": "m"}
#: A header cell: a name and, optionally, its unit in brackets ('load [nN]'), in parentheses
#: ('load (nN)', as spreadsheets write it) or after a slash between blanks ('load / nN', ISO 80000-1;
#: 'F/P' is a name).
_HEADER = re.compile(r"^\s*(?P<base>[^\[\]()/]*?)\s*(?:\[(?P<unit>[^\[\]]*)\]|\((?P<paren>[^()]*)\)"
                     r"|(?<=\s)/\s+(?P<slash>[^\[\]()]*?))?\s*$")
#: What a unit symbol in parentheses or after a slash looks like ('nN', 'um', 'µN', 'J/m^2', 'Å').
_UNIT_TEXT = re.compile(r"^[^\W\d_][\w^*/·\-]*$")


def condition_names() -> dict:
    """Header base (lower case) -> (fit name, SI unit or '' if dimensionless)."""
    out = {}
    for registry in (MODEL_PARAMETERS, FIT_PARAMETERS):
        for q in registry.values():
            out[q.name.lower()] = (q.name, "")
    for q in PHYSICAL_PARAMETERS.values():
        if q.si_name is None:  # a dimensionless physical quantity (alpha_n)
            out[q.name.lower()] = (q.name, "")
            continue
        out[q.name.lower()] = (q.si_name, q.si_unit)
        out[q.si_name.lower()] = (q.si_name, q.si_unit)
    for alias in ("radius", "tip_radius"):  # 'Tip radius (nm)' (a user trial: ignored, with a note)
        out[alias] = out["r_m"]
    return out


def classify_header(header: str):
    """(role, is_err, unit or None, SI-suffix unit or None) of one header cell; role None if unknown."""
    m = _HEADER.match(header)
    base = (m.group("base") if m else header).strip().lower().replace(" ", "_").replace("-", "_")
    given = next((m.group(g) for g in ("unit", "paren", "slash") if m.group(g) is not None), None) if m else None
    unit = given.strip() if given is not None else None
    if m and given is not None and m.group("unit") is None and not _is_unit_of(base, unit):
        # 'F/P', 'friction/load', 'mu (-)', 'friction (a.u.)': a name, not a name and its unit
        # (read as units they made files that were read before ambiguous: found by a review)
        base, unit = header.strip().lower().replace(" ", "_").replace("-", "_"), None
    suffix_unit = None
    for suffix, si in _SUFFIX.items():
        stem = base[: -len(suffix)]
        if base.endswith(suffix) and header_role(stem.removesuffix("_err"))[0]:
            base, suffix_unit = stem, si
            break
    is_err = False
    for tail in ("_err", "_error", "_sigma"):
        if base.endswith(tail):
            base, is_err = base[: -len(tail)], True
            break
    role, symbol = header_role(base)
    return role, is_err, unit, suffix_unit, symbol, base


def _is_unit_of(base: str, unit: str) -> bool:
    """Whether ``unit`` (from 'name (unit)' or 'name / unit') is to be read as the unit of the
    column ``base`` names: the name takes a physical unit (a load, friction, separation or
    pull-off column, or a pull-off condition such as R) and the text is a unit with a
    dimension.  A text of the wrong dimension ('load (nm)') then gets the bracket form's
    error; a text that is no unit ('a.u.', '-', '%', a typo) leaves the column ignored."""
    stem = base.removesuffix("_err").removesuffix("_error").removesuffix("_sigma")
    role = header_role(stem)[0]
    si = SI_UNITS[role] if role is not None else condition_names().get(stem, (None, ""))[1]
    if not si or not _UNIT_TEXT.match(unit):  # 'a.u.', 'arb. units': no unit symbol
        return False
    try:
        quantity = unit_registry().parse_expression(unit)
    except Exception:  # noqa: BLE001 - pint's parser raises many kinds: no unit
        return False
    return is_quantity(quantity) and not quantity.dimensionless


def header_role(base: str) -> tuple[str | None, bool]:
    """(role, is the dimensionless symbol) of a header's normalised name, or (None, False)."""
    for role, names in ROLES.items():
        if base in names:
            return role, base == names[0]
    return None, False


def to_si_exact(value: float, factor: float, text: str) -> float:
    """``value`` (read from the cell ``text``) times ``factor``; for a decimal prefix (``factor``
    a power of ten: 1e-9 for nN) the cell's decimal digits get its exponent, so that 3.3 nN is
    3.3e-09 as the API's 3.3e-9 and the command line's '3.3nN' are (3.3 * 1e-9 is one ulp off:
    found by a review; the digits are the cell's, not the float's, which long texts round)."""
    if factor > 0 and math.isfinite(value):
        k = round(math.log10(factor))
        if abs(k) <= 22 and factor == float(f"1e{k}"):
            try:
                exact = Decimal(text.strip())
            except InvalidOperation:  # a spelling only strict_float reads (a typeset minus)
                exact = Decimal(repr(value))
            return float(exact.scaleb(k))
    return value * factor


def unit_factor(unit_text: str, role: str, header: str) -> float:
    si = SI_UNITS[role]
    if unit_text in ("", "1", "-") and si == "":
        return 1.0
    if si == "":
        raise ValueError(f"column {header!r}: a friction coefficient is dimensionless, got the unit {unit_text!r}")
    value = parse_quantity(f"1 {unit_text}", si, f"column {header!r}")
    if not value > 0:
        raise ValueError(f"column {header!r}: unit {unit_text!r} is not a positive multiple of {si}")
    return value
