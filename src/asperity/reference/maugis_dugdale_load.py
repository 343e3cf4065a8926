"""Reference for :mod:`asperity.maugis_dugdale_load`: the contact radius at a given load, by brute force.

Under load control one asperity sits on the part of the Maugis-Dugdale curve (Eqs 11-13)
from ``A_M = inf`` (``t -> 0``) to the first minimum of ``P_M(t)``.  Here that minimum is
found by scanning ``y = log t`` upward from deep in the Hertz-like part until ``dP/dt``
turns non-negative, and the load is matched by multiple-precision bisection in ``y``:
no Newton step, no table, nothing shared with the fast path.
"""

from __future__ import annotations

import functools

from .common import MP, finite, mpmath, positive
from .maugis_dugdale import Y_SCAN_MAX, Y_STEP, bisect_mp, dps_for, md_mp
from .maugis_dugdale_branch import scan_start

__all__ = ["md_load_point"]


def _curve(y, lam):
    with MP.workdps(dps_for(y)):
        return md_mp(mpmath.mpf(y), mpmath.mpf(lam))


@functools.cache
def _first_minimum(lam):
    """(y_lo, y_hi) bracketing the first minimum of P_M(e^y), or (y, inf) if P_M only decreases."""
    y = scan_start(lam)
    while y <= Y_SCAN_MAX:
        if _curve(y, lam)[4] >= 0:  # dP/dt
            return y - Y_STEP, y
        y += Y_STEP / 4
    return y, float("inf")


def md_load_point(P, lam):
    """Contact radius ``A_M`` and penetration ``Delta_M`` on the load-stable branch at load ``P_M``.

    Parameters
    ----------
    P : float
        Load ``P/(pi w R)``, above the load-controlled pull-off.
    lam : float
        Maugis parameter (> 0).

    Returns
    -------
    tuple of float
        ``(A_M, Delta_M)``.
    """
    P = finite("P", P)
    lam = positive("lam", lam)
    lo, hi = _first_minimum(lam)
    # The minimum lies in [lo, hi]; refine its position so the bisection interval is monotone.
    with MP.workdps(40):
        y_min = bisect_mp(lambda yy: _curve(yy, lam)[4], lo, hi, -1) if hi != float("inf") else mpmath.mpf(lo)
    if _curve(y_min, lam)[1] > P:
        raise ValueError(f"P={P!r} is below the load-controlled pull-off of lambda={lam!r}")
    y_lo = scan_start(lam)
    while _curve(y_lo, lam)[1] < P:
        y_lo -= 2.0
    target = mpmath.mpf(P)
    with MP.workdps(40):
        y = bisect_mp(lambda yy: _curve(yy, lam)[1] - target, y_lo, y_min, 1)
    A, _, D = _curve(y, lam)[:3]
    return float(A), float(D)
