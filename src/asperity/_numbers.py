"""Reading a plain decimal number strictly (no NumPy: the command line imports it at start).

:func:`strict_float` is Python's ``float`` for text without its surprises: ``'1_0'`` (10),
other scripts' digits (``'١'``, 1) and numbers that underflow to 0 (``'1e-400'``) are refused.
:mod:`asperity.units` re-exports it.
"""

from __future__ import annotations

import math
import re

__all__ = ["strict_float", "is_number", "apart", "FloatUnderflow"]

#: A decimal number as written in ASCII: what :func:`strict_float` reads (with nan, inf).
_DECIMAL = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?", re.ASCII)
_SPECIAL = {"nan": math.nan, "+nan": math.nan, "-nan": math.nan, "inf": math.inf, "+inf": math.inf,
            "-inf": -math.inf, "infinity": math.inf, "+infinity": math.inf, "-infinity": -math.inf}


class FloatUnderflow(ValueError):
    """A nonzero number too small for a double (:func:`strict_float`): its message says so,
    where a number that is not one at all gets ``float``'s own words."""


def strict_float(text: str) -> float:
    """``float(text)`` for a plain decimal number only: ASCII digits, an optional sign, point and
    exponent, or nan/inf; surrounding spaces are allowed.

    Python's ``float`` also reads ``'1_0'`` as 10 and other scripts' digits (``'١'`` as 1): a
    review found both in data files read silently.  A nonzero number too small for a double
    (``'1e-400'``, which ``float`` makes 0) is refused too.

    Raises
    ------
    ValueError
        For anything else, with a message in ``float``'s words; :class:`FloatUnderflow` for a
        number too small for a double.
    """
    if not isinstance(text, str):
        raise ValueError(f"could not convert {type(text).__name__} to float: {text!r}")
    stripped = text.strip()
    special = _SPECIAL.get(stripped.lower())
    if special is not None:
        return special
    if not _DECIMAL.fullmatch(stripped):
        raise ValueError(f"could not convert string to float: {text!r}")
    value = float(stripped)
    if value == 0.0 and re.search(r"[1-9]", stripped.split("e")[0].split("E")[0]):
        raise FloatUnderflow(f"{text!r} is smaller than the smallest double (about 5e-324): it would be read as 0")
    return value


def is_number(text: str) -> bool:
    """Whether :func:`strict_float` reads ``text`` (a cell of a data file, say)."""
    try:
        strict_float(text)
    except ValueError:
        return False
    return True


def apart(a: float, b: float) -> int:
    """The significant digits, 6 to 17, that print ``a`` and ``b`` differently (a limit and the
    value beyond it in a message: 'must be >= -6.43759e-05 ... got -6.43759e-05' said nothing)."""
    k = 6
    while k < 17 and f"{a:.{k}g}" == f"{b:.{k}g}":
        k += 1
    return k
