"""Physical units at the edge of the library: pint quantities and unit strings to SI floats.

Inside asperity every physical number is a plain float (or NumPy array) in SI units:
metres, pascals, newtons, J/m^2, 1/m^2, m^2.  Two helpers convert at the boundary:

* :func:`to_si` takes what a Python caller passes -- a number (taken as SI already) or a
  `pint <https://pint.readthedocs.io>`_ ``Quantity`` -- and returns the SI magnitude.
* :func:`parse_quantity` takes what a command line passes -- a string such as ``"2nm"``,
  ``"1um"``, ``"1e12/m^2"``, ``"1mm^2"``, ``"1mN"``, ``"79GPa"`` or ``"1.2J/m^2"``.

pint is optional (``pip install 'asperity[units]'``).  Without it, numbers work as before
and any unit raises a :class:`ValueError` that says how to install it.  Every error names
the parameter and the unit expected.
"""

from __future__ import annotations

import functools
import math
import re
import unicodedata
from decimal import Decimal

import numpy as np

from ._numbers import strict_float

__all__ = ["to_si", "parse_quantity", "is_quantity", "unit_registry", "format_si", "strict_float"]

_INSTALL = "pip install 'asperity[units]'"


def is_quantity(value) -> bool:
    """True if ``value`` looks like a pint ``Quantity`` (duck-typed; pint need not be installed)."""
    return all(hasattr(value, attr) for attr in ("magnitude", "units", "dimensionality", "to"))


@functools.cache
def unit_registry():
    """The shared :class:`pint.UnitRegistry` used to parse strings.

    Raises
    ------
    ImportError
        If pint is not installed (``pip install 'asperity[units]'``).
    """
    try:
        import pint
    except ImportError:  # pragma: no cover - depends on the environment
        raise ImportError(f"units need pint: {_INSTALL}") from None
    registry = pint.UnitRegistry()
    registry.define("@alias angstrom = Angstrom")  # the capitalised spelling of instrument files
    return registry


def _unit_label(unit: str) -> str:
    return unit if unit else "dimensionless"


def _convert(quantity, unit: str, name: str):
    """Magnitude of a pint quantity in ``unit``; ValueError naming ``name`` if incompatible."""
    try:
        converted = quantity.to(unit or "dimensionless")
    except Exception as err:  # pint.DimensionalityError, UndefinedUnitError, ...
        try:
            unit_registry().parse_units(unit or "dimensionless")
        except Exception:  # the target unit itself is not a unit: the caller's mistake
            raise ValueError(f"unit {unit!r} is not a unit pint knows (for {name})") from None
        raise ValueError(f"{name} must have units compatible with {_unit_label(unit)}, got "
                         f"{quantity!s} ({type(err).__name__}: {err})") from None
    magnitude = converted.magnitude
    try:
        return float(magnitude) if np.ndim(magnitude) == 0 else np.asarray(magnitude, dtype=float)
    except (TypeError, ValueError):  # e.g. '1 ±0.1 nm', a value with an uncertainty
        raise ValueError(f"{name} must be one number with its unit, got {quantity!s}") from None


def to_si(value, unit: str, name: str):
    """Return ``value`` in the SI unit ``unit``: pint quantities converted, numbers unchanged.

    Parameters
    ----------
    value : float, array_like, pint.Quantity or str
        A plain number or array is taken to be in ``unit`` already and returned as is.
        A pint ``Quantity`` is converted.  A string is parsed by :func:`parse_quantity`
        (a unit is then required).  A list or tuple holding quantities or strings is
        converted element by element to an array.
    unit : str
        Target SI unit in pint syntax, e.g. ``"m"``, ``"Pa"``, ``"N"``, ``"J/m^2"``,
        ``"1/m^2"``, ``"m^2"``; ``""`` for a dimensionless number.
    name : str
        Parameter name used in error messages.

    Returns
    -------
    float or ndarray or the input
        The magnitude in ``unit``.

    Raises
    ------
    ValueError
        If a quantity's dimensionality does not match ``unit`` (the message names
        ``name`` and the expected unit).

    Examples
    --------
    >>> to_si(2e-9, "m", "sigma_s")
    2e-09
    """
    _check_labels(unit, name)
    if isinstance(value, str):
        return parse_quantity(value, unit, name)
    if is_quantity(value):
        return _convert(value, unit, name)
    if isinstance(value, list | tuple) and any(is_quantity(v) or isinstance(v, str) for v in value):
        return np.array([to_si(v, unit, name) for v in value], dtype=float)
    return value


def _check_labels(unit, name) -> None:
    """``unit`` and ``name`` are strings (a unit in pint syntax, a parameter name)."""
    for value, label in ((unit, "unit"), (name, "name")):
        if not isinstance(value, str):
            raise TypeError(f"{label} must be a string, got {type(value).__name__} {value!r}")


def _plain_number(text: str, name: str = "value", original: str | None = None):
    """``text`` as a plain number, or None if it is not one; a number that underflows is an error."""
    try:
        return strict_float(text)
    except ValueError as err:
        if "smallest double" in str(err):
            raise ValueError(f"{name} = {text if original is None else original!r}: {err}") from None
        return None


def parse_quantity(text: str, unit: str, name: str, *, require_unit: bool = True) -> float:
    """Parse a command-line quantity such as ``"2nm"`` or ``"79GPa"`` to a float in ``unit``.

    Parameters
    ----------
    text : str
        A number with a unit (``"2nm"``, ``"1 um"``, ``"1e12/m^2"``, ``"1mm^2"``,
        ``"1mN"``, ``"79GPa"``, ``"1.2J/m^2"``) or, if ``require_unit`` is False or
        ``unit`` is dimensionless, a bare number taken to be in ``unit``.
    unit : str
        SI unit of the result (pint syntax); ``""`` for dimensionless.
    name : str
        Parameter name used in error messages.
    require_unit : bool
        If True (default) a bare number for a dimensional quantity is an error, so
        ``--sigma 2`` cannot silently mean 2 metres.

    Returns
    -------
    float
        The value in ``unit``.

    Raises
    ------
    ValueError
        If the unit is missing (when required), unknown or of the wrong dimension, or if
        a unit is given but pint is not installed.  The message names ``name`` and the
        expected unit.

    Examples
    --------
    >>> parse_quantity("2nm", "m", "sigma_s")
    2e-09
    """
    _check_labels(unit, name)
    if not isinstance(text, str):
        raise ValueError(f"{name} must be a string such as '2nm', got {text!r}")
    # any Unicode space (a no-break space too) is one space; the minus sign U+2212 of typeset
    # text ('−5 nN', 'm^−1') is '-'
    stripped = " ".join(text.split()).replace("\u2212", "-")
    number = _plain_number(stripped, name, text)
    if number is not None:
        if require_unit and unit:
            example = stripped if math.isfinite(number) else "1"
            raise ValueError(f"{name} needs a unit compatible with {unit} (e.g. '{example} {unit}'), "
                             f"got the bare number {text!r}")
        return number
    _check_one_number(stripped, text, name)
    try:
        registry = unit_registry()
    except ImportError:
        raise ValueError(f"{name} = {text!r} has a unit; reading units needs pint: {_INSTALL} "
                         f"(or give a plain number in {_unit_label(unit)})") from None
    split = _NUMBER_UNIT.match(stripped)
    if split is not None:  # '60nm', '1e0J/m^2': the number read by Python, the unit by pint
        number = _plain_number(split.group(1), name, text)
        scaled = _decimal_scaled(number, split.group(2), unit, name, registry)
        if scaled is not None:
            if scaled == 0.0 and number != 0.0:  # '1e-320 nm': below the smallest double in metres
                raise ValueError(f"{name} = {text!r} is {number:g} {split.group(2)}, below the smallest double in "
                                 f"{_unit_label(unit)} (about 5e-324): it would be read as 0")
            return scaled
    try:
        quantity = registry.parse_expression(stripped)
    except Exception as err:
        raise ValueError(f"{name} = {text!r} is not a quantity with a unit compatible with "
                         f"{_unit_label(unit)} ({type(err).__name__}: {err})") from None
    if not is_quantity(quantity):  # pint returns a plain number for e.g. '2*3'
        _check_no_underflow(float(quantity), stripped, text, name, unit)
        return parse_quantity(repr(float(quantity)), unit, name, require_unit=require_unit)
    value = float(_convert(quantity, unit, name))
    _check_no_underflow(value, stripped, text, name, unit)
    return value


def _check_no_underflow(value: float, stripped: str, text: str, name: str, unit: str) -> None:
    """Refuse an expression of nonzero factors that rounds to 0 ('1e-200*1e-200 m'), as a single
    literal that does ('1e-400 m') is; a zero factor ('0*5 nm') or a sum or difference, which may
    cancel ('(1 - 1) nm'), is left alone."""
    if value != 0.0 or re.search(r"(?<![eE(*/^\s])\s*[+-]", stripped[1:]):
        return
    if all(float(token) != 0.0 for token in _NUMBER_TOKEN.findall(stripped)):
        raise ValueError(f"{name} = {text!r} is 0 {_unit_label(unit)}: the product of its nonzero numbers is "
                         "below the smallest double (about 5e-324); give a value of physical size")


#: Two terms side by side with only spaces between, the second a number (pint would multiply
#: them: '1 nN 2' is 2 nN, '2 1 nN' too); '5 1/um^2' (five per square micrometre) is the exception.
_JUXTAPOSED = re.compile(r"[A-Za-z\u00b5\u03bc\u00c5\u212b\d.)]\s+(?!1\s*/\s*[A-Za-z\u00b5\u03bc\u00c5\u212b(])"
                         r"(?:\d|\.\d|\()", re.ASCII)
#: Non-ASCII characters a unit may hold: micro (two code points), angstrom (two), superscripts.
_UNIT_CHARACTERS = frozenset("\u00b5\u03bc\u00c5\u212b\u00b2\u00b3\u00b9\u2070\u2074\u2075\u2076\u2077\u2078"
                             "\u2079\u207b")
#: The number literals of a text (their exponents included).
_NUMBER_TOKEN = re.compile(r"(?<![A-Za-z_])(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?", re.ASCII)


def _is_unit(text: str) -> bool:
    """Whether ``text`` (not empty) is a unit pint knows."""
    try:
        unit_registry().parse_units(text)
    except Exception:  # pint's errors for text that is no unit are of several kinds
        return False
    return bool(text.strip())


def _check_one_number(stripped: str, text: str, name: str) -> None:
    """Refuse what pint would read as something else: a decimal comma ('0,5J/m^2' is 5 J/m^2
    to pint, '1,5nm' 15 nm), ';', and numbers set side by side ('1 nN 2' is 2 nN)."""
    if "," in stripped or ";" in stripped:
        mean = (f"; did you mean {stripped.replace(',', '.', 1)!r}?" if re.match(r"^[+-]?\d+,\d+[^,;]*$", stripped)
                else "")
        raise ValueError(f"{name} = {text!r}: one number with its unit, '.' the decimal point; ',' and ';' are "
                         f"not part of a quantity{mean}")
    # digits of other scripts (not superscripts: 'nm²' is a unit) and '1_0' (Python's 10)
    if any(not ch.isascii() and unicodedata.decimal(ch, None) is not None for ch in stripped) or \
            re.search(r"\d_\d", stripped):
        raise ValueError(f"{name} = {text!r}: write the number with the digits 0-9 (no '_' between them)")
    # pint drops characters it does not know and multiplies what is left ("2'5nm" is 10 nm,
    # '1 % nm' 0.01 nm): only those of numbers, units and arithmetic may reach it
    stray = sorted({ch for ch in stripped if not (ch.isascii() and (ch.isalnum() or ch in " .+-*/^()_"))
                    and ch not in _UNIT_CHARACTERS})
    if stray:
        raise ValueError(f"{name} = {text!r}: {', '.join(map(repr, stray))} cannot be part of a quantity (one "
                         "number with its unit, e.g. '2.5nm', '1e12/m^2')")
    if re.search(r"\d*\.\d*\.", stripped) or re.search(r"[\d.)]\s*\(", stripped):
        raise ValueError(f"{name} = {text!r}: one number with its unit (two decimal points, or a number "
                         "directly before '(', are not read)")
    if not re.match(r"[+-]?\s*(?:\d|\.\d|\(|(?:nan|inf(?:inity)?)(?![A-Za-z\u00b5\u03bc\u00c5\u212b]))", stripped,
                    re.ASCII | re.IGNORECASE):
        glued = re.match(r"[+-]?(?:nan|inf(?:inity)?)", stripped, re.IGNORECASE)
        if glued and _is_unit(stripped[glued.end():]):  # 'nanGPa': NaN glued to its unit ('nanometer' is not)
            raise ValueError(f"{name} = {text!r}: must be a finite number with its unit (no NaN or infinity)")
        if re.match(r"[A-Za-z\u00b5\u03bc\u00c5\u212b]", stripped) and not _is_unit(stripped):  # 'abc'
            raise ValueError(f"{name} = {text!r} is not a number with a unit (e.g. '2.5nm', '70GPa')")
        example = stripped if re.match(r"[A-Za-z\u00b5\u03bc\u00c5\u212b]", stripped) else "nm"
        raise ValueError(f"{name} = {text!r} has no number: give one before the unit (e.g. '1 {example}')")
    if _JUXTAPOSED.search(stripped):
        raise ValueError(f"{name} = {text!r}: one number with its unit (e.g. '2nm'), or an expression with "
                         "explicit operators ('3 m + 2 m'); numbers set side by side are not read")
    for token in _NUMBER_TOKEN.findall(stripped):  # each literal: none may underflow to 0
        _plain_number(token, name, text)


#: A number followed by a unit that starts with a letter, '/' or '1/' ('1/um^2', '5 1/um^2'; '*', '^' go to pint).
_NUMBER_UNIT = re.compile(r"^([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)\s*(?![eE][+-]?\d)"
                          r"((?:[A-Za-z\u00b5\u03bc\u00c5\u212b/]|1\s*/).*)$", re.ASCII)


def _decimal_scaled(number: float, unit_text: str, unit: str, name: str, registry) -> float | None:
    """``number`` times the unit ``unit_text`` in ``unit``, or None if ``unit_text`` is not one
    plain unit (an expression such as 'm + 2 m': the whole text then goes to pint).  A decimal
    factor (an SI prefix: 1e-9 for nm; 1e12 for um^-2) divides by the exact power of ten
    instead of multiplying by its rounded reciprocal: the decimal digits of the number get the
    prefix's exponent, so that '60nm' is 6e-08 as '6e-8m' is (not 6.000000000000001e-08),
    '3.3nm' is 3.3e-09 as '3.3e-9m' is, and '1/um^2' is 1e12."""
    try:
        one = registry.parse_expression("1" + unit_text if unit_text.startswith("/") else unit_text)
    except Exception:  # noqa: BLE001 - pint's parser raises many kinds: the whole text decides
        return None
    if not is_quantity(one) or one.magnitude != 1:
        return None
    try:
        factor = float(_convert(one, unit, name))
    except ValueError:  # a wrong dimension: the whole text's message names the value given
        return None
    if factor > 0 and math.isfinite(factor):
        k = round(math.log10(factor))
        # pint's factor of a decimal unit may be a few ulps off its power of ten ('um^-2':
        # 1.0000000000000001e12); no unit of the registry lies that close to one without being it
        if abs(k) <= 22 and abs(factor / float(f"1e{k}") - 1.0) < 1e-14:  # 10**|k| is exact up to 1e22
            # in decimal: the shortest digits of the number with its exponent moved, so that '3.3nm'
            # is float('3.3e-9'), not the rounded 3.3 divided by 1e9 (one ulp off: found by a review)
            return float(Decimal(repr(float(number))).scaleb(k))
    return float(_convert(number * one, unit, name))


#: SI prefixes by power of ten, for :func:`format_si`.
_PREFIXES = {12: "T", 9: "G", 6: "M", 3: "k", 0: "", -3: "m", -6: "u", -9: "n", -12: "p", -15: "f"}


def format_si(value, unit: str) -> str:
    """``value`` (in the SI unit ``unit``) as text with an SI prefix and 4 significant digits.

    Parameters
    ----------
    value : float
        A real number in ``unit``.
    unit : str
        The unit's symbol, e.g. ``'Pa'``, ``'m'``, ``'J/m^2'`` (the prefix multiplies the whole unit).

    Returns
    -------
    str
        E.g. ``'78 GPa'``; zero, NaN, infinity and values beyond the prefixes f..T (below
        1e-15, from 1000 T) without a prefix, in exponent notation.

    Raises
    ------
    TypeError
        If ``value`` is not a real number or ``unit`` not a string.

    References
    ----------
    BIPM, *The International System of Units (SI)*, 9th ed. (2019), Table 7 (SI prefixes).

    Examples
    --------
    >>> format_si(7.8e10, "Pa"), format_si(2.885e-10, "m"), format_si(0.05, "J/m^2")
    ('78 GPa', '288.5 pm', '50 mJ/m^2')
    """
    import math

    if isinstance(value, bool) or not isinstance(value, int | float | np.integer | np.floating):
        raise TypeError(f"value must be a real number, got {type(value).__name__} {value!r}")
    if not isinstance(unit, str):
        raise TypeError(f"unit must be a string, got {type(unit).__name__} {unit!r}")
    value = float(value)
    if value == 0 or not math.isfinite(value) or not 1e-15 <= abs(value) < 999.95e12:  # beyond f..T: 1e-20 Pa
        return f"{value:.4g} {unit}"
    exponent = min(max(3 * math.floor(math.log10(abs(value)) / 3), -15), 12)
    if exponent < 12 and abs(float(f"{value / 10.0**exponent:.4g}")) >= 1000:  # 999.95 rounds to 1000: '1 k'
        exponent += 3
    return f"{value / 10.0**exponent:.4g} {_PREFIXES[exponent]}{unit}"
