"""Reference for :mod:`asperity.maugis_dugdale_branch`: the stable branch, its end, points on it
(:func:`md_point`) and pull-off, by scanning and bracketed solves in multiple precision.

Every asperity is solved individually: for each penetration the stable
displacement-controlled branch is found by a bracketed root solve in ``log t`` followed
by Newton polishing in multiple precision.  Nothing is tabulated or interpolated.
Results are cached on the exact floating-point inputs only (no rounding of keys).
"""

from __future__ import annotations

import functools
import math

import numpy as np
from scipy import optimize

from .common import MP, finite, mpmath, positive
from .maugis_dugdale import Y_SCAN_MAX, Y_STEP, bisect_mp, dps_for, end_x, md_eval, md_mp

__all__ = ["md_branch_end", "md_point", "md_pull_off"]


@functools.cache
def scan_start(lam):
    """A log-t value deep in the Hertz-like part of the curve (``A_M >= 1e4``)."""
    y = 0.0
    while md_eval(y, lam)[0] < 1e4:
        y -= 1.0
    return y


@functools.cache
def branch_end(lam):
    """Branch end of the stable displacement-controlled MD branch (cached per lambda).

    Returns ``(y_end, A_end, D_end, P_end)``; ``y_end`` is ``math.inf`` (and
    ``A_end = 0``) when the branch runs to ``A_M -> 0``.  The mp values are
    returned at >= 34 digits.
    """
    y0 = scan_start(lam)
    y = y0
    prev = y
    found = False
    while y <= Y_SCAN_MAX:
        dD = md_eval(y, lam)[5]
        if dD >= 0:  # dDelta/dt >= 0  <=>  dDelta/dA <= 0  (dA/dt < 0)
            found = True
            break
        prev = y
        y += Y_STEP
    if found:

        def dDfun(yy):
            with MP.workdps(dps_for(yy)):
                return md_mp(yy, mpmath.mpf(lam))[5]

        with MP.workdps(dps_for(y)):
            y_end = bisect_mp(dDfun, prev, y, -1)
        A, P, D = md_eval(y_end, lam)[:3]
        return y_end, A, D, P
    # lambda <= lambda_c: the branch runs to A_M -> 0 (t -> inf), closed-form end.
    with MP.workdps(40):
        lm = mpmath.mpf(lam)
        x = end_x(lm)
        D_end = -4 * lm * x / 3
        P_end = -mpmath.pi * lm * x * x / 2
        return math.inf, mpmath.mpf(0), D_end, P_end


def md_branch_end(lam):
    """End of the stable displacement-controlled Maugis-Dugdale branch.

    The stable branch is the part of the curve (Eqs. 11-13) with
    ``dDelta_M/dA_M > 0``.  Above ``lambda_c`` (:func:`md_lambda_c`, ~0.938)
    ``Delta_M(A_M)`` has an interior minimum which ends the branch; below it the
    branch runs to ``A_M -> 0`` where (with ``x*`` from :func:`end_x`)
    ``Delta_end = -(4/3) lam x*`` and ``P_end = -(pi/2) lam x*^2``.

    Parameters
    ----------
    lam : float
        Maugis parameter (> 0).

    Returns
    -------
    tuple of float
        ``(A_end, Delta_end, P_end)``; ``A_end == 0.0`` below ``lambda_c``.
    """
    lam = positive("lam", lam)
    _, A, D, P = branch_end(lam)
    return float(A), float(D), float(P)


def _float_D(y, lam):
    """Double-precision Delta_M(t = e^y) (only used for a starting guess)."""
    t = math.exp(y)
    at = math.atan(t)
    if t < 0.25:  # t - atan(t) by its alternating series (avoid cancellation)
        tma = 0.0
        term = t**3
        k = 1
        while True:
            add = term / (2 * k + 1)
            tma += add if k % 2 == 1 else -add
            if add < 1e-18 * tma:
                break
            term *= t * t
            k += 1
    else:
        tma = t - at
    b1 = tma + t * t * at
    b2 = t * at - t * t / (1.0 + math.sqrt(1.0 + t * t))
    c2 = 0.5 * lam * b1
    c1 = 4.0 / 3.0 * lam * lam * b2
    A = 2.0 / (c1 + math.sqrt(c1 * c1 + 4.0 * c2))
    return A * A - 4.0 / 3.0 * lam * A * t


def _float_guess(lam, target, y_end):
    """Double-precision guess of log t on the stable branch for Delta = target, or None."""
    g = lambda y: _float_D(y, lam) - target  # noqa: E731
    try:
        if math.isfinite(y_end):
            hi = float(y_end)
            if not g(hi) < 0:
                return None
        else:
            hi = 0.0
            while not g(hi) < 0:
                hi += 2.0
                if hi > Y_SCAN_MAX:
                    return None
        lo = min(hi - 1.0, 0.0)
        while not g(lo) > 0:
            lo -= 2.0
            if lo < -200:
                return None
        return optimize.brentq(g, lo, hi, xtol=1e-15, rtol=4e-16, maxiter=200)
    except (OverflowError, ZeroDivisionError, ValueError):
        return None


def _solve_branch(lam, target):
    """Stable-branch MD state for ``Delta_M = target`` (mpf, > Delta_end).

    Returns ``(A, P)`` as mpf (>= 34 digits).  Double-precision bracketing guess
    followed by Newton in multiple precision; falls back to a pure mp
    bracketed Newton/bisection if the fast guess does not converge.
    """
    y_end = branch_end(lam)[0]
    y0 = _float_guess(lam, float(target), y_end)
    if y0 is not None:
        res = _newton_polish(lam, target, mpmath.mpf(y0), y_end)
        if res is not None:
            return res
    return _robust_solve(lam, target, y_end)


def _newton_polish(lam, target, y, y_end):
    """Newton iterations on ``Delta(e^y) = target`` in mp; None if not converged."""
    for _ in range(8):
        with MP.workdps(dps_for(y)):
            A, P, D, dA, dP, dD = md_mp(y, mpmath.mpf(lam))
            t = mpmath.exp(y)
            if dD >= 0:
                return None
            dt = (target - D) / dD
            if abs(dt) <= t * mpmath.mpf(10) ** (-24):
                # first-order correction is exact to far below double precision
                return A + dA * dt, P + dP * dt
            ynew = y + mpmath.log1p(dt / t) if dt / t > -1 else None
            if ynew is None or (math.isfinite(y_end) and ynew >= y_end):
                return None
            y = ynew
    return None


def _robust_solve(lam, target, y_end):
    """Bracketed safeguarded Newton/bisection in log t, all in multiple precision."""
    lm = mpmath.mpf(lam)

    def g(yy):
        with MP.workdps(dps_for(yy)):
            return md_mp(mpmath.mpf(yy), lm)[2] - target

    if math.isfinite(y_end):
        hi = mpmath.mpf(y_end)
    else:
        hi = mpmath.mpf(0)
        while not g(hi) < 0:
            hi += 2
            if hi > 3 * Y_SCAN_MAX:
                raise ArithmeticError("could not bracket the MD stable branch")
    lo = hi - 1
    while not g(lo) > 0:
        lo -= 2
    with MP.workdps(dps_for(max(abs(lo), abs(hi)))):
        y = (lo + hi) / 2
        for _ in range(400):
            with MP.workdps(dps_for(y)):
                A, P, D, dA, dP, dD = md_mp(y, lm)
                t = mpmath.exp(y)
                gy = D - target
                if gy > 0:
                    lo = y
                else:
                    hi = y
                dt = -gy / dD if dD != 0 else mpmath.mpf(0)
                if dD < 0 and abs(dt) <= t * mpmath.mpf(10) ** (-24):
                    return A + dA * dt, P + dP * dt
                ynew = None
                if dD < 0 and dt / t > -1:
                    ynew = y + mpmath.log1p(dt / t)
                if ynew is None or not lo < ynew < hi:
                    ynew = (lo + hi) / 2
                if hi - lo < mpmath.mpf(10) ** (-30) * (1 + abs(y)):
                    return A, P
                y = ynew
    raise ArithmeticError("MD stable-branch solve did not converge")


@functools.lru_cache(maxsize=500_000)
def branch_point_offset(lam, dd):
    """Stable-branch ``(A_M, P_M)`` floats at ``Delta_M = Delta_end + dd`` (``dd >= 0``)."""
    y_end, A_end, D_end, P_end = branch_end(lam)
    if dd == 0.0:
        return float(A_end), float(P_end)
    with MP.workdps(40):
        target = D_end + mpmath.mpf(dd)
    A, P = _solve_branch(lam, target)
    return float(A), float(P)


@functools.lru_cache(maxsize=100_000)
def _md_point_cached(delta, lam):
    y_end, A_end, D_end, P_end = branch_end(lam)
    target = mpmath.mpf(delta)
    if target < D_end:
        raise ValueError(
            f"delta={delta!r} is below the end of the stable Maugis-Dugdale branch "
            f"(Delta_end={float(D_end)!r} for lambda={lam!r})"
        )
    if target == D_end:
        return float(A_end), float(P_end)
    A, P = _solve_branch(lam, target)
    return float(A), float(P)


def md_point(delta, lam):
    """Stable-branch Maugis-Dugdale contact radius and load for one penetration.

    Solves Eqs. 11-13 for the unique point of the stable displacement-controlled
    branch (``dDelta_M/dA_M > 0``) with penetration ``Delta_M = delta``.

    Parameters
    ----------
    delta : float
        Maugis penetration ``Delta_M`` (Eq. 14); must be ``>= Delta_end``
        (see :func:`md_branch_end`).
    lam : float
        Maugis parameter ``lambda`` (> 0).

    Returns
    -------
    tuple of float
        ``(A_M, P_M)``.

    Raises
    ------
    ValueError
        If ``delta`` lies below the end of the stable branch, or inputs are invalid.
    """
    delta = finite("delta", delta)
    lam = positive("lam", lam)
    return _md_point_cached(delta, lam)


@functools.cache
def _md_pull_off_load(lam):
    lm = mpmath.mpf(lam)
    y = scan_start(lam)
    prev_dP = md_eval(y, lam)[4]
    best = None
    while y <= Y_SCAN_MAX:
        ynext = y + Y_STEP
        dP = md_eval(ynext, lam)[4]
        # dP/dt < 0 -> > 0 : P has a local minimum in t (in between)
        if prev_dP < 0 <= dP:

            def dPfun(yy):
                with MP.workdps(dps_for(yy)):
                    return md_mp(yy, lm)[4]

            with MP.workdps(dps_for(ynext)):
                ym = bisect_mp(dPfun, y, ynext, -1)
            val = md_eval(ym, lam)[1]
            best = val if best is None or val < best else best
        prev_dP = dP
        y = ynext
    with MP.workdps(40):
        x = end_x(lm)
        p_inf = -mpmath.pi * lm * x * x / 2  # limit t -> inf (A_M -> 0)
    if best is None or p_inf < best:
        best = p_inf
    return float(best)


def md_pull_off(lam, control="load"):
    """Maugis-Dugdale single-asperity pull-off load ``P_M`` (negative).

    Parameters
    ----------
    lam : float
        Maugis parameter (> 0).
    control : {'load', 'displacement'}
        ``'load'``: minimum of ``P_M`` over the whole curve (Eqs. 11-13, all
        ``m > 1`` including the limit ``A_M -> 0``).  ``'displacement'``:
        ``P_M`` at the end of the stable branch (:func:`md_branch_end`).

    Returns
    -------
    float
    """
    lam = positive("lam", lam)
    if control == "load":
        return _md_pull_off_load(lam)
    if control == "displacement":
        return float(branch_end(lam)[3])
    raise ValueError(f"control must be 'load' or 'displacement', got {control!r}")


@functools.cache
def branch_D_for_A(lam, A_target):
    """``Delta_M - Delta_end`` (mpf) at the stable-branch point with ``A_M = A_target``.

    Returns None when ``A_target <= A_end`` (no such point on the stable branch).
    """
    y_end, A_end, D_end, _ = branch_end(lam)
    if not A_target > A_end:
        return None
    lm = mpmath.mpf(lam)
    At = mpmath.mpf(A_target)

    def f(yy):  # A decreasing in t
        with MP.workdps(dps_for(yy)):
            return md_mp(mpmath.mpf(yy), lm)[0] - At

    lo = 0.0
    while not f(lo) > 0:
        lo -= 2.0
    hi = lo + 2.0
    while not f(hi) < 0:
        hi += 2.0
    with MP.workdps(dps_for(max(abs(lo), abs(hi)))):
        y = bisect_mp(f, lo, hi, 1)
    with MP.workdps(dps_for(y)):
        return md_mp(y, lm)[2] - D_end


@functools.cache
def branch_P_zeros(lam):
    """``Delta_M - Delta_end`` (mpf list) where ``P_M`` changes sign on the stable branch."""
    y_end, A_end, D_end, _ = branch_end(lam)
    lm = mpmath.mpf(lam)
    y_hi = float(y_end) if math.isfinite(y_end) else Y_SCAN_MAX
    ys = list(np.arange(scan_start(lam), y_hi, Y_STEP)) + [y_hi]
    vals = [md_eval(y, lam)[1] for y in ys]

    def f(yy):
        with MP.workdps(dps_for(yy)):
            return md_mp(mpmath.mpf(yy), lm)[1]

    out = []
    for i in range(len(ys) - 1):
        if (vals[i] > 0) != (vals[i + 1] > 0):
            with MP.workdps(dps_for(max(abs(ys[i]), abs(ys[i + 1])))):
                y = bisect_mp(f, ys[i], ys[i + 1], 1 if vals[i] > 0 else -1)
            with MP.workdps(dps_for(y)):
                out.append(md_mp(y, lm)[2] - D_end)
    return tuple(out)
