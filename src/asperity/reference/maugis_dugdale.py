"""Reference for :mod:`asperity.maugis_dugdale`: the Maugis-Dugdale curve (Eqs 11-13) in mpmath.

Evaluated at an adaptive working precision (34 digits plus about one per decade that
``t = sqrt(m**2 - 1)`` is away from 1), so the cancellation near ``m -> 1`` and near
``A_M -> 0`` is harmless.  :func:`md_mp`, :func:`md_eval`, :func:`dps_for`, :func:`end_x`
and :func:`bisect_mp` serve :mod:`asperity.reference.maugis_dugdale_branch`.
"""

from __future__ import annotations

import functools
import math

from .common import MP, mpmath, positive

__all__ = ["md_curve", "md_lambda_c"]

#: Log-t range used when scanning the MD curve (t = sqrt(m^2 - 1)).
Y_SCAN_MAX = math.log(1e25)
Y_STEP = 0.25


def dps_for(y):
    """Working decimal digits for the MD relations at ``t = exp(y)``."""
    return 34 + int(math.ceil(0.87 * abs(float(y))))


def md_mp(y, lam):
    """MD curve at ``t = sqrt(m^2-1) = exp(y)`` (caller sets the precision).

    Returns ``(A, P, D, dA, dP, dD)`` with derivatives with respect to ``t``.
    Eq. 11 is the quadratic ``c2 A^2 + c1 A - 1 = 0`` with
    ``c2 = lam/2 [t + (m^2-2) atan t]`` and ``c1 = 4 lam^2/3 [t atan t - m + 1]``
    whose positive root is ``A = 2/(c1 + sqrt(c1^2 + 4 c2))``.
    """
    t = mpmath.exp(y)
    t2 = t * t
    m2 = 1 + t2
    m = mpmath.sqrt(m2)
    at = mpmath.atan(t)
    b1 = t + (t2 - 1) * at  # first bracket of Eq. 11
    b2 = t * at - t2 / (1 + m)  # second bracket: t atan t - (m - 1)
    db1 = 2 * t * at + 2 * t2 / m2
    db2 = at + t / m2 - t / m
    c2 = lam * b1 / 2
    c1 = 4 * lam * lam * b2 / 3
    dc2 = lam * db1 / 2
    dc1 = 4 * lam * lam * db2 / 3
    A = 2 / (c1 + mpmath.sqrt(c1 * c1 + 4 * c2))
    dA = -(dc2 * A * A + dc1 * A) / (2 * c2 * A + c1)
    cp = t + m2 * at  # bracket of Eq. 12
    dcp = 2 + 2 * t * at
    P = A**3 - lam * A * A * cp  # Eq. 12
    dP = 3 * A * A * dA - lam * (2 * A * dA * cp + A * A * dcp)
    D = A * A - 4 * A * lam * t / 3  # Eq. 13
    dD = 2 * A * dA - 4 * lam * (dA * t + A) / 3
    return A, P, D, dA, dP, dD


def md_eval(y, lam):
    """:func:`md_mp` at adaptive precision; ``y``, ``lam`` floats or mpf."""
    with MP.workdps(dps_for(y)):
        return md_mp(mpmath.mpf(y), mpmath.mpf(lam))


def md_curve(t, lam):
    """Maugis-Dugdale curve point for a given ``t = sqrt(m^2 - 1) > 0`` (Eqs. 11-13).

    Parameters
    ----------
    t : float
        ``sqrt(m**2 - 1)`` with ``m = c/a`` the ratio of the adhesion radius to
        the contact radius.
    lam : float
        Maugis parameter ``lambda`` (Eq. 14/15), > 0.

    Returns
    -------
    tuple of float
        ``(A_M, P_M, Delta_M)``.
    """
    t = positive("t", t)
    lam = positive("lam", lam)
    A, P, D = md_eval(math.log(t), lam)[:3]
    return float(A), float(P), float(D)


@functools.cache
def md_lambda_c():
    """Critical Maugis parameter below which the stable branch reaches ``A_M = 0``.

    For ``A_M -> 0`` (``t -> inf``) with ``x = A_M t`` and ``s = A_M^2`` Eq. 11
    becomes ``(lam/2)[(pi/2) x^2 - (pi/2) s] + (4 lam^2/3)[(pi/2 - 1) x - s/(2x)] = 1 + O(A^3)``
    and Eq. 13 ``Delta = s - (4/3) lam x``.  ``dDelta/ds`` at ``s = 0`` is
    ``1 - (4/3) lam x'(0)``; ``lambda_c`` is where it vanishes (about 0.938).

    Returns
    -------
    float
    """
    with MP.workdps(40):

        def slope(lam):
            x = end_x(lam)
            xp = (lam * mpmath.pi / 4 + 2 * lam**2 / (3 * x)) / (
                lam * mpmath.pi * x / 2 + 4 * lam**2 / 3 * (mpmath.pi / 2 - 1)
            )
            return 1 - 4 * lam * xp / 3

        lam_c = mpmath.findroot(slope, (mpmath.mpf("0.9"), mpmath.mpf("0.98")), solver="anderson")
        return float(lam_c)


def end_x(lam):
    """``x* = lim A_M t`` for ``t -> inf``.

    Root of ``(lam pi/4) x^2 + (4 lam^2/3)(pi/2 - 1) x = 1`` (Eq. 11 as ``A_M -> 0``).
    """
    c2 = lam * mpmath.pi / 4
    c1 = 4 * lam**2 / 3 * (mpmath.pi / 2 - 1)
    return 2 / (c1 + mpmath.sqrt(c1 * c1 + 4 * c2))


def bisect_mp(f, lo, hi, flo):
    """Bisection in multiple precision on ``[lo, hi]`` (floats/mpf), ``flo = sign(f(lo))``."""
    lo = mpmath.mpf(lo)
    hi = mpmath.mpf(hi)
    for _ in range(200):
        mid = (lo + hi) / 2
        if mid == lo or mid == hi or hi - lo < mpmath.mpf(10) ** (-32):
            break
        if (f(mid) > 0) == (flo > 0):
            lo = mid
        else:
            hi = mid
    return (lo + hi) / 2
