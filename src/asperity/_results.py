"""Checks of computed results, shared by every public function: finite results named by their
inputs (:func:`check_finite_result`, :func:`check_overflow`), mean pressures of a map, and
NumPy scalars for scalar inputs (:func:`ufunc_result`).  Re-exported by
:mod:`asperity._validation`."""

from __future__ import annotations

import numpy as np

from ._validation_files import short_repr as _short_repr

__all__ = ["ufunc_result", "check_finite_result", "check_mean_pressure", "check_overflow"]


def ufunc_result(result):
    """``result`` as a ufunc returns it: a 0-d array becomes its NumPy scalar (``np.float64``),
    other arrays and non-arrays are unchanged (tuples element by element)."""
    if isinstance(result, tuple):
        return tuple(ufunc_result(r) for r in result)
    return result[()] if isinstance(result, np.ndarray) and result.ndim == 0 else result


def check_finite_result(result, what: str, **inputs):
    """``result`` unchanged if every element is finite; else a ValueError naming the inputs.

    Compute ``result`` under ``np.errstate(all="ignore")`` so that no warning precedes the
    error.  The message names the inputs ``inputs`` (name -> value) of extreme magnitude
    (beyond 1e100 or below 1e-100), or all of them if none is.
    """
    if np.all(np.isfinite(np.asarray(result, dtype=float))):
        return result

    def extreme(v):
        a = np.abs(np.asarray(v, dtype=float))
        return bool(np.any((a > 1e100) | ((a < 1e-100) & (a > 0))))

    named = {k: v for k, v in inputs.items() if extreme(v)} or inputs
    listed = ", ".join(f"{k} = {_short_repr(v)}" for k, v in named.items())
    raise ValueError(f"{what} overflows double precision for {listed}: give values of physical size")


def check_mean_pressure(P, E_star: float, A0: float, p_range: tuple[float, float]) -> None:
    """Refuse loads ``P`` (N) whose mean pressure over ``E_star`` (Pa) on the area ``A0`` (m^2) lies
    outside ``p_range``; the ValueError names P and E_star and gives the loads allowed."""
    lo, hi = p_range
    P = np.asarray(P, dtype=float)
    with np.errstate(all="ignore"):
        p_bar = P / E_star / A0
    bad = ~((p_bar >= lo) & (p_bar <= hi))
    if bad.any():
        raise ValueError(f"P/(E_star A0) (mean pressure over the contact modulus) must lie in [{lo:g}, {hi:g}]: "
                         f"for E_star = {E_star:.6g} Pa on this map (A0 = {A0:.6g} m^2) the loads P must lie in "
                         f"[{lo * E_star * A0:.6g}, {hi * E_star * A0:.6g}] N, got P = {float(P[bad][0]):.6g} N")


def check_overflow(result, name: str, limit, value, given: dict | None = None):
    """``result`` unchanged if every element is finite; else a ValueError for the input that overflowed.

    ``value`` is the input called ``name``; ``limit`` its largest valid value, or a function
    returning it (called only on overflow, with floating-point errors silenced), both broadcast
    with ``result``.  The message names the first element that overflowed, and the other
    inputs ``given`` (name -> value) the limit depends on.  Compute ``result``
    under ``np.errstate(over="ignore", invalid="ignore")`` so no warning precedes the error.
    """
    bad = ~np.isfinite(np.asarray(result))
    if bad.any():
        if callable(limit):
            with np.errstate(all="ignore"):
                limit = limit()
        i = np.flatnonzero(bad.ravel())[0]
        lim, got = (float(np.broadcast_to(x, bad.shape).ravel()[i]) for x in (limit, value))
        context = "" if not given else " for " + ", ".join(f"{k} = {_short_repr(v)}" for k, v in given.items())
        raise ValueError(f"{name} must be <= {lim:.6g}{context} (beyond, the result overflows double precision), "
                         f"got {got!r}")
    return result
