"""Strict JSON: NaN and infinity become ``null``, never the non-standard ``NaN``/``Infinity``.

Python's :mod:`json` writes ``NaN`` and ``Infinity`` by default, which strict parsers
(JavaScript's ``JSON.parse``, jq, most other languages) reject.  :func:`json_safe` turns a
result (dicts, lists, tuples, NumPy scalars and arrays) into plain JSON values with
``None`` for every non-finite number; :func:`dumps` serialises it with ``allow_nan=False``,
so a non-finite number that slipped through would raise rather than be written.
"""

from __future__ import annotations

import json
import math

import numpy as np

__all__ = ["json_safe", "dumps"]


def json_safe(value):
    """``value`` with NaN/inf -> None, NumPy scalars/arrays -> Python numbers/lists, tuples -> lists.

    Dict keys are kept as given; other objects are returned unchanged (``json`` decides).
    """
    if isinstance(value, dict):
        return {k: json_safe(v) for k, v in value.items()}
    if isinstance(value, list | tuple):
        return [json_safe(v) for v in value]
    if isinstance(value, np.ndarray):
        return [json_safe(v) for v in value.tolist()] if value.ndim else json_safe(value.item())
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def dumps(value, *, indent: int | None = None) -> str:
    """Strict JSON text of ``value`` (see :func:`json_safe`), without a trailing newline."""
    return json.dumps(json_safe(value), indent=indent, allow_nan=False)
