"""Shared pieces of the reference implementation: mpmath and scalar input checks.

Imports nothing from the rest of :mod:`asperity` (the reference is an independent oracle).
"""

from __future__ import annotations

import math

try:
    import mpmath
except ImportError:  # pragma: no cover - depends on the environment
    raise ImportError("asperity.reference needs mpmath: pip install 'asperity[reference]'") from None

__all__ = ["MP", "finite", "positive", "mpmath"]

#: The mpmath context (working precision is set locally with ``MP.workdps``).
MP = mpmath.mp


def finite(name, value):
    """``value`` as a finite float; ValueError naming ``name`` otherwise."""
    if value is None or isinstance(value, bool | str | bytes | complex):
        raise ValueError(f"{name} must be a real number, got {value!r}")
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a real number, got {value!r}") from None
    if not math.isfinite(v):
        raise ValueError(f"{name} must be finite, got {value!r}")
    return v


def positive(name, value):
    """``value`` as a float > 0; ValueError naming ``name`` otherwise."""
    v = finite(name, value)
    if not v > 0.0:
        raise ValueError(f"{name} must be > 0, got {value!r}")
    return v
