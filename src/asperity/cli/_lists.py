"""Lists and quantities on the command line: ``a,b,c``, ``start:stop:count``, ``2nm``, ``1mN:1N:50``.

* :func:`parse_list`: ``a,b,c`` or ``start:stop:count`` -> a float array; malformed
  lists (an empty item, a wrong number of ``:`` fields, a count that is not a positive
  integer, a non-finite value) are errors, never repaired, and no list may hold more than
  :data:`MAX_POINTS` points (checked before anything is allocated).
* :func:`quantity` and :func:`quantity_list`: the same with units (``2nm``, ``1mN:1N:50``).
* :func:`join_negative_lists`: ``--d -1,0`` is a value, not an option.

Nothing here imports NumPy or pint at module level.
"""

from __future__ import annotations

from .._numbers import strict_float

__all__ = [
    "MAX_POINTS",
    "UsageError",
    "OutputClosed",
    "parse_list",
    "quantity",
    "optional_quantity",
    "quantity_items",
    "quantity_list",
    "join_negative_lists",
]

#: Largest number of points a list or a ``start:stop:count`` range may hold.
MAX_POINTS = 10**6

class UsageError(Exception):
    """A problem with the command line or its values: one line, exit status 2."""


class OutputClosed(Exception):
    """Standard output's reader left ('asperity load ... | head -1'): the command ends quietly."""


def _show(text: str, limit: int = 60) -> str:
    """``repr`` of a user's text, shortened (a list may hold a million items)."""
    return repr(text) if len(text) <= limit else repr(text[:limit]) + "..."


def _too_many(name: str, count: int) -> UsageError:
    return UsageError(f"{name}: {count} points is more than the limit of {MAX_POINTS} (MAX_POINTS)")


def _items(text: str, name: str) -> list[str]:
    """The comma-separated items of ``text``; an empty item or too many items is an error."""
    if text.count(",") + 1 > MAX_POINTS:
        raise _too_many(name, text.count(",") + 1)
    items = text.split(",")
    if any(not item.strip() for item in items):
        raise UsageError(f"{name}: empty item in {_show(text)}; give numbers separated by single commas "
                         "'a,b,c' or a range 'start:stop:count'")
    return items


def _range_parts(text: str, name: str) -> tuple[str, str, int]:
    """``start``, ``stop`` (texts) and ``count`` of ``start:stop:count``, count checked."""
    parts = text.split(":")
    if len(parts) != 3:
        raise UsageError(f"{name}: expected a range 'start:stop:count' (three fields), got {_show(text)}")
    count = int(parts[2]) if parts[2].strip().isascii() and parts[2].strip().isdigit() else None
    if count is None or count < 1:
        raise UsageError(f"{name}: count in start:stop:count must be a positive integer, got {parts[2]!r}")
    if count > MAX_POINTS:
        raise _too_many(name, count)
    return parts[0], parts[1], count


def _spaced(start: float, stop: float, count: int, *, log: bool, name: str, text: str):
    """``count`` points from ``start`` to ``stop``, log-spaced if ``log``, else linear."""
    import math

    import numpy as np

    if not (math.isfinite(start) and math.isfinite(stop)):
        raise UsageError(f"{name}: values must be finite, got {_show(text)}")
    if count == 1 and start != stop:  # a review: the stop was silently dropped
        raise UsageError(f"{name}: a range of one point would drop its stop ({_show(text)}): give count >= 2, "
                         "or the one value alone")
    if log:
        if start <= 0 or stop <= 0:
            raise UsageError(f"{name}: a log-spaced range start:stop:count needs start, "
                             f"stop > 0 (use a comma list for zero or negative values)")
        return np.geomspace(start, stop, count)
    with np.errstate(over="ignore", invalid="ignore"):
        values = np.linspace(start, stop, count)
        if not np.all(np.isfinite(values)):  # stop - start beyond the float range: weigh the ends
            t = np.linspace(0.0, 1.0, count)
            values = start * (1.0 - t) + stop * t
    return values


def parse_list(text: str, *, log: bool, name: str):
    """``a,b,c`` or ``start:stop:count`` (log-spaced if ``log``, else linear) as a float array.

    Parameters
    ----------
    text : str
        Finite numbers separated by single commas, or ``start:stop:count`` with a
        positive integer count.  At most :data:`MAX_POINTS` points.
    log : bool
        Space a range logarithmically (start and stop must then be > 0).
    name : str
        The option, for messages (``'--P'``).

    Returns
    -------
    numpy.ndarray
        1-D float array.

    Raises
    ------
    UsageError
        For an empty item (``0,,1``, ``1,``), a range without exactly three fields, a count
        that is not a positive integer, a non-finite value, or more than
        :data:`MAX_POINTS` points.
    """
    import numpy as np

    bad = UsageError(f"{name}: expected numbers 'a,b,c' or 'start:stop:count', got {_show(text)}")
    if ":" in text:
        start, stop, count = _range_parts(text, name)
        try:
            lo, hi = strict_float(start), strict_float(stop)
        except ValueError:
            raise bad from None
        return _spaced(lo, hi, count, log=log, name=name, text=text)
    items = _items(text, name)
    try:
        values = np.array([strict_float(v) for v in items])
    except ValueError:
        raise bad from None
    if not np.all(np.isfinite(values)):
        raise UsageError(f"{name}: values must be finite, got {_show(text)}")
    return values


def quantity(text: str, unit: str, name: str) -> float:
    """One quantity with a unit (``'2nm'``) in the SI unit ``unit`` (needs pint)."""
    from .._optional import require

    require("pint", purpose="quantities with units", extra="units")
    from ..units import parse_quantity

    return parse_quantity(text, unit, name)


def optional_quantity(text: str | None, unit: str, name: str) -> float | None:
    """:func:`quantity` of ``text``, or None when the option was not given."""
    return None if text is None else quantity(text, unit, name)


def quantity_items(text: str, unit: str, name: str) -> list[float]:
    """A comma list of quantities (``'10um,5um'``) in ``unit``; empty and non-finite items are errors."""
    return [_finite_quantity(x, unit, name) for x in _items(text, name)]


def _finite_quantity(text: str, unit: str, name: str) -> float:
    """:func:`quantity`, refusing NaN and infinities by the option's name and the text given."""
    import math

    value = quantity(text, unit, name)
    if not math.isfinite(value):
        raise UsageError(f"{name}: {text.strip()!r} is not a finite quantity (NaN, infinite or beyond double "
                         "precision)")
    return value


def quantity_list(text: str, unit: str, *, log: bool, name: str):
    """``a,b,c`` or ``start:stop:count`` of quantities with units (``1mN:1N:50``), in ``unit``.

    The same rules as :func:`parse_list`.
    """
    import numpy as np

    if ":" in text:
        start, stop, count = _range_parts(text, name)
        lo, hi = _finite_quantity(start, unit, name), _finite_quantity(stop, unit, name)
        return _spaced(lo, hi, count, log=log, name=name, text=text)
    return np.array(quantity_items(text, unit, name), dtype=float)


def join_negative_lists(argv):
    """``--d -1,0,2`` -> ``--d=-1,0,2``: argparse would take ``-1,0,2`` (or ``-inf``) for an option.

    A value is a word that starts with a minus sign and then a digit, a point, ``inf`` or
    ``nan`` (any case): it is joined to the option before it, which then receives it (and
    checks it: ``--profile-budget -inf`` is refused by name, not as a missing argument).
    """
    out = list(argv)
    i = 0
    while i < len(out) - 1:
        nxt = out[i + 1]
        number = nxt[1:2] in tuple("0123456789.") or nxt[1:4].lower() in ("inf", "nan")
        if out[i].startswith("--") and "=" not in out[i] and nxt[:1] == "-" and number:
            out[i:i + 2] = [f"{out[i]}={nxt}"]
        i += 1
    return out
