"""Independent, slow, high-precision reference implementation of the model.

This module re-derives the multi-asperity contact / adhesion / friction model of
the paper ("A Nano-Scale Multi-Asperity Contact and Friction Model", section
*Development of the Model*, Eqs. 2-18 and 21) directly from the equations.  It
deliberately shares **no code** with the fast path of :mod:`asperity`; it
imports only :mod:`numpy`, :mod:`scipy`, :mod:`mpmath`, :mod:`math` and
:mod:`functools`.  Its purpose is to serve as an oracle against which the fast
(vectorised, tabulated / interpolated) implementation can be tested.

How it differs from the fast path
---------------------------------
* The Maugis-Dugdale (MD) relations (Eqs. 11-13) are evaluated with
  :mod:`mpmath` at an adaptive working precision (34 digits plus two digits per
  decade that ``t = sqrt(m**2 - 1)`` is away from 1), so the cancellation near
  ``m -> 1`` (where the first bracket of Eq. 11 is ``(4/3) t**3``) and near
  ``A_M -> 0`` is harmless.
* Every asperity is solved *individually*: for each penetration the stable
  displacement-controlled branch is found by a bracketed root solve in
  ``log t`` followed by Newton polishing in multiple precision.  Nothing is
  tabulated or interpolated.  Results are cached on the exact floating-point
  inputs only (no rounding of keys).
* The Greenwood-Williamson integrals (Eqs. 5, 6, 10, 18, 21) are computed with
  adaptive Gauss-Kronrod quadrature (:func:`scipy.integrate.quad`,
  ``epsabs=0``, ``epsrel=1e-11``) in the variable ``s`` with
  ``u = u_end + s**2``, which removes the square-root behaviour of the MD
  solution at the end of the stable branch, and with the integration range
  split at every kink: the Hurtado-Kim transition radii ``a_bar = a1, a2``
  and the sign change(s) of the per-asperity MD load.
* Load-controlled quantities (:func:`load_point`, :func:`pull_off`) are found
  by scanning and bracketing root solves / bounded minimisation on top of
  :func:`separation_point`, i.e. by brute force.

Conventions (all quantities per asperity, i.e. divided by ``N``)
----------------------------------------------------------------
* ``d`` is the separation in units of ``sigma``; asperity heights ``z`` have the
  standard normal density ``phi`` (Eq. 19); penetration ``u = z - d``.
* Hertz (``gamma == 0``): ``a_bar = beta*sqrt(u)`` (Eq. 8) and
  ``P_bar = (4/3) (2/(1-nu)) alpha beta**2 u**1.5`` (Eq. 6) for ``u > 0``.
* Adhesion (``gamma > 0``): Maugis-Dugdale with ``lambda`` from Eq. 15 and the
  conversions of Eq. 17, with the corrected load scale
  ``P_hat = (1-nu) alpha / (2 pi beta gamma)`` (the paper prints ``alpha**2``;
  see :func:`conversion_factors`).  Only the stable displacement-controlled
  branch (``dDelta_M/dA_M > 0``) carries load; asperities beyond its end carry
  nothing.
* Friction per asperity: ``F_f/(G b**2) = 2 pi tau_bar(a_bar) a_bar**2``
  (the integrand of Eq. 10) with the Hurtado-Kim law of Eq. 2.
"""

from __future__ import annotations

import functools
import math

import numpy as np
from scipy import integrate, optimize

try:
    import mpmath
except ImportError:  # pragma: no cover - depends on the environment
    raise ImportError("asperity.reference needs mpmath: pip install 'asperity[reference]'") from None

__all__ = [
    "conversion_factors",
    "gw_moment",
    "hk_tau",
    "load_point",
    "md_branch_end",
    "md_curve",
    "md_lambda_c",
    "md_point",
    "md_pull_off",
    "pull_off",
    "separation_point",
]

_MP = mpmath.mp
_SQRT2PI = math.sqrt(2.0 * math.pi)
_LN10 = math.log(10.0)

#: Quadrature settings of the outer Greenwood-Williamson integrals.
_EPSREL = 1e-11
_LIMIT = 400
#: Truncation of the height integral: z_max = max(d, 0) + _Z_TAIL.
_Z_TAIL = 12.0
#: Log-t range used when scanning the MD curve (t = sqrt(m^2 - 1)).
_Y_SCAN_MAX = math.log(1e25)
_Y_STEP = 0.25


# ---------------------------------------------------------------------------
# Input validation
# ---------------------------------------------------------------------------
def _finite(name, value):
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a real number, got {value!r}") from None
    if not math.isfinite(v):
        raise ValueError(f"{name} must be finite, got {value!r}")
    return v


def _positive(name, value):
    v = _finite(name, value)
    if not v > 0.0:
        raise ValueError(f"{name} must be > 0, got {value!r}")
    return v


class _Params:
    """Validated model parameters and derived constants (Eqs. 2, 3, 15, 17)."""

    __slots__ = (
        "alpha",
        "beta",
        "gamma",
        "nu",
        "h_over_b",
        "tau_f1",
        "tau_f2",
        "a1",
        "a2",
        "hk_slope",
        "hertz_pref",
        "lam",
        "delta_hat",
        "P_hat",
        "A_hat",
        "key",
    )

    def __init__(self, alpha, beta, gamma, nu, h_over_b, tau_f1, tau_f2, a1, a2):
        self.alpha = _positive("alpha", alpha)
        self.beta = _positive("beta", beta)
        self.gamma = _finite("gamma", gamma)
        if self.gamma < 0.0:
            raise ValueError(f"gamma must be >= 0, got {gamma!r}")
        self.nu = _finite("nu", nu)
        if not -1.0 < self.nu < 0.5:
            raise ValueError(f"nu must satisfy -1 < nu < 0.5, got {nu!r}")
        self.h_over_b = _positive("h_over_b", h_over_b)
        self.tau_f1 = _positive("tau_f1", tau_f1)
        self.tau_f2 = _positive("tau_f2", tau_f2)
        self.a1 = _positive("a1", a1)
        self.a2 = _positive("a2", a2)
        if not self.a2 > self.a1:
            raise ValueError(f"a2 must be > a1, got a1={a1!r}, a2={a2!r}")
        # Eq. 3: slope of the straight log-log line of Eq. 2 (any log base).
        self.hk_slope = math.log(self.tau_f2 / self.tau_f1) / math.log(self.a2 / self.a1)
        # Eq. 6 prefactor.
        self.hertz_pref = (4.0 / 3.0) * (2.0 / (1.0 - self.nu)) * self.alpha * self.beta**2
        if self.gamma > 0.0:
            f = conversion_factors(self.alpha, self.beta, self.gamma, nu=self.nu, h_over_b=self.h_over_b)
            self.lam = f["lambda"]
            self.delta_hat = f["delta_hat"]
            self.P_hat = f["P_hat"]
            self.A_hat = f["A_hat"]
        else:
            self.lam = self.delta_hat = self.P_hat = self.A_hat = None
        self.key = (
            self.alpha,
            self.beta,
            self.gamma,
            self.nu,
            self.h_over_b,
            self.tau_f1,
            self.tau_f2,
            self.a1,
            self.a2,
        )


def conversion_factors(alpha, beta, gamma, *, nu=0.3, h_over_b=1.0):
    """Maugis parameter and Maugis <-> model unit conversions (Eqs. 15, 17).

    Derivation (with ``sigma = alpha beta b``, ``R = b beta/alpha`` (Eq. 20),
    ``w = gamma E* b`` (Eq. 16), ``K = 4E*/3``, ``E*/G = 2/(1-nu)``):

    * ``P_bar = P/(G b^2) = P_M pi w R/(G b^2) = P_M (2 pi beta gamma)/((1-nu) alpha)``
      so ``P_hat = (1-nu) alpha/(2 pi beta gamma)``.  (The paper prints
      ``alpha**2``; that is a typo: with it Hertz would not be recovered.)
    * ``u_bar = Delta_M delta_hat`` with
      ``delta_hat = (3 pi gamma/(4 alpha^2 beta))**(2/3)``.
    * ``a_bar = A_M/A_hat`` with ``A_hat = (4/(3 pi gamma) (alpha/beta)^2)**(1/3)``.
    * ``lambda = (b/h) (9 beta gamma^2/(2 pi alpha))**(1/3)`` (Eq. 15).

    As a check, ``delta_hat A_hat^2 = 1/beta^2`` so the Hertz limit
    ``Delta_M = A_M^2`` maps to ``u_bar = a_bar^2/beta^2`` (Eq. 8), and
    ``A_M^3/P_hat`` maps to Eq. 6.

    Parameters
    ----------
    alpha, beta : float
        Roughness and friction-regime parameters (Eq. 7), > 0.
    gamma : float
        Surface energy / compliance coefficient (Eq. 16), > 0.
    nu : float, optional
        Poisson's ratio.
    h_over_b : float, optional
        Maximum adhesion distance over Burgers vector.

    Returns
    -------
    dict
        Keys ``'lambda'``, ``'delta_hat'``, ``'P_hat'``, ``'A_hat'``.
    """
    alpha = _positive("alpha", alpha)
    beta = _positive("beta", beta)
    gamma = _positive("gamma", gamma)
    nu = _finite("nu", nu)
    if not -1.0 < nu < 0.5:
        raise ValueError(f"nu must satisfy -1 < nu < 0.5, got {nu!r}")
    h_over_b = _positive("h_over_b", h_over_b)
    with _MP.workdps(30):
        a, b, g = mpmath.mpf(alpha), mpmath.mpf(beta), mpmath.mpf(gamma)
        lam = mpmath.cbrt(9 * b * g**2 / (2 * mpmath.pi * a)) / mpmath.mpf(h_over_b)
        delta_hat = (3 * mpmath.pi * g / (4 * a**2 * b)) ** (mpmath.mpf(2) / 3)
        P_hat = (1 - mpmath.mpf(nu)) * a / (2 * mpmath.pi * b * g)
        A_hat = mpmath.cbrt(4 / (3 * mpmath.pi * g) * (a / b) ** 2)
        return {"lambda": float(lam), "delta_hat": float(delta_hat), "P_hat": float(P_hat), "A_hat": float(A_hat)}


# ---------------------------------------------------------------------------
# Hurtado-Kim friction stress (Eq. 2)
# ---------------------------------------------------------------------------
def hk_tau(a_bar, *, tau_f1=1 / 43, tau_f2=1 / 43 / 30, a1=28.0, a2=8e4):
    """Hurtado-Kim dimensionless friction stress ``tau_bar(a_bar)`` (Eq. 2).

    ``tau_f1`` for ``a_bar <= a1``, ``tau_f2`` for ``a_bar >= a2`` and the straight
    line in log-log coordinates between ``(a1, tau_f1)`` and ``(a2, tau_f2)``
    (slope ``M`` of Eq. 3) in between.

    Parameters
    ----------
    a_bar : float
        Dimensionless contact radius ``a/b`` (>= 0).
    tau_f1, tau_f2, a1, a2 : float, optional
        Hurtado-Kim constants.

    Returns
    -------
    float
    """
    if a_bar <= a1:
        return float(tau_f1)
    if a_bar >= a2:
        return float(tau_f2)
    slope = math.log(tau_f2 / tau_f1) / math.log(a2 / a1)
    return float(tau_f1 * math.exp(slope * math.log(a_bar / a1)))


def _hk_friction(a, p):
    """Per-asperity friction ``2 pi tau_bar(a) a^2`` (integrand of Eq. 10)."""
    if a <= p.a1:
        tau = p.tau_f1
    elif a >= p.a2:
        tau = p.tau_f2
    else:
        tau = p.tau_f1 * math.exp(p.hk_slope * math.log(a / p.a1))
    return 2.0 * math.pi * tau * a * a


# ---------------------------------------------------------------------------
# Maugis-Dugdale relations (Eqs. 11-13), multiple precision
# ---------------------------------------------------------------------------
def _dps_for(y):
    """Working decimal digits for the MD relations at ``t = exp(y)``."""
    return 34 + int(math.ceil(0.87 * abs(float(y))))


def _md_mp(y, lam):
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


def _md_eval(y, lam):
    """:func:`_md_mp` at adaptive precision; ``y``, ``lam`` floats or mpf."""
    with _MP.workdps(_dps_for(y)):
        return _md_mp(mpmath.mpf(y), mpmath.mpf(lam))


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
    t = _positive("t", t)
    lam = _positive("lam", lam)
    A, P, D = _md_eval(math.log(t), lam)[:3]
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
    with _MP.workdps(40):

        def slope(lam):
            x = _end_x(lam)
            xp = (lam * mpmath.pi / 4 + 2 * lam**2 / (3 * x)) / (
                lam * mpmath.pi * x / 2 + 4 * lam**2 / 3 * (mpmath.pi / 2 - 1)
            )
            return 1 - 4 * lam * xp / 3

        lam_c = mpmath.findroot(slope, (mpmath.mpf("0.9"), mpmath.mpf("0.98")), solver="anderson")
        return float(lam_c)


def _end_x(lam):
    """``x* = lim A_M t`` for ``t -> inf``.

    Root of ``(lam pi/4) x^2 + (4 lam^2/3)(pi/2 - 1) x = 1`` (Eq. 11 as ``A_M -> 0``).
    """
    c2 = lam * mpmath.pi / 4
    c1 = 4 * lam**2 / 3 * (mpmath.pi / 2 - 1)
    return 2 / (c1 + mpmath.sqrt(c1 * c1 + 4 * c2))


def _bisect_mp(f, lo, hi, flo):
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


@functools.cache
def _scan_start(lam):
    """A log-t value deep in the Hertz-like part of the curve (``A_M >= 1e4``)."""
    y = 0.0
    while _md_eval(y, lam)[0] < 1e4:
        y -= 1.0
    return y


@functools.cache
def _branch_end(lam):
    """Branch end of the stable displacement-controlled MD branch (cached per lambda).

    Returns ``(y_end, A_end, D_end, P_end)``; ``y_end`` is ``math.inf`` (and
    ``A_end = 0``) when the branch runs to ``A_M -> 0``.  The mp values are
    returned at >= 34 digits.
    """
    y0 = _scan_start(lam)
    y = y0
    prev = y
    found = False
    while y <= _Y_SCAN_MAX:
        dD = _md_eval(y, lam)[5]
        if dD >= 0:  # dDelta/dt >= 0  <=>  dDelta/dA <= 0  (dA/dt < 0)
            found = True
            break
        prev = y
        y += _Y_STEP
    if found:

        def dDfun(yy):
            with _MP.workdps(_dps_for(yy)):
                return _md_mp(yy, mpmath.mpf(lam))[5]

        with _MP.workdps(_dps_for(y)):
            y_end = _bisect_mp(dDfun, prev, y, -1)
        A, P, D = _md_eval(y_end, lam)[:3]
        return y_end, A, D, P
    # lambda <= lambda_c: the branch runs to A_M -> 0 (t -> inf), closed-form end.
    with _MP.workdps(40):
        lm = mpmath.mpf(lam)
        x = _end_x(lm)
        D_end = -4 * lm * x / 3
        P_end = -mpmath.pi * lm * x * x / 2
        return math.inf, mpmath.mpf(0), D_end, P_end


def md_branch_end(lam):
    """End of the stable displacement-controlled Maugis-Dugdale branch.

    The stable branch is the part of the curve (Eqs. 11-13) with
    ``dDelta_M/dA_M > 0``.  Above ``lambda_c`` (:func:`md_lambda_c`, ~0.938)
    ``Delta_M(A_M)`` has an interior minimum which ends the branch; below it the
    branch runs to ``A_M -> 0`` where (with ``x*`` from :func:`_end_x`)
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
    lam = _positive("lam", lam)
    _, A, D, P = _branch_end(lam)
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
                if hi > _Y_SCAN_MAX:
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
    y_end = _branch_end(lam)[0]
    y0 = _float_guess(lam, float(target), y_end)
    if y0 is not None:
        res = _newton_polish(lam, target, mpmath.mpf(y0), y_end)
        if res is not None:
            return res
    return _robust_solve(lam, target, y_end)


def _newton_polish(lam, target, y, y_end):
    """Newton iterations on ``Delta(e^y) = target`` in mp; None if not converged."""
    for _ in range(8):
        with _MP.workdps(_dps_for(y)):
            A, P, D, dA, dP, dD = _md_mp(y, mpmath.mpf(lam))
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
        with _MP.workdps(_dps_for(yy)):
            return _md_mp(mpmath.mpf(yy), lm)[2] - target

    if math.isfinite(y_end):
        hi = mpmath.mpf(y_end)
    else:
        hi = mpmath.mpf(0)
        while not g(hi) < 0:
            hi += 2
            if hi > 3 * _Y_SCAN_MAX:
                raise ArithmeticError("could not bracket the MD stable branch")
    lo = hi - 1
    while not g(lo) > 0:
        lo -= 2
    with _MP.workdps(_dps_for(max(abs(lo), abs(hi)))):
        y = (lo + hi) / 2
        for _ in range(400):
            with _MP.workdps(_dps_for(y)):
                A, P, D, dA, dP, dD = _md_mp(y, lm)
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
def _branch_point_offset(lam, dd):
    """Stable-branch ``(A_M, P_M)`` floats at ``Delta_M = Delta_end + dd`` (``dd >= 0``)."""
    y_end, A_end, D_end, P_end = _branch_end(lam)
    if dd == 0.0:
        return float(A_end), float(P_end)
    with _MP.workdps(40):
        target = D_end + mpmath.mpf(dd)
    A, P = _solve_branch(lam, target)
    return float(A), float(P)


@functools.lru_cache(maxsize=100_000)
def _md_point_cached(delta, lam):
    y_end, A_end, D_end, P_end = _branch_end(lam)
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
    delta = _finite("delta", delta)
    lam = _positive("lam", lam)
    return _md_point_cached(delta, lam)


@functools.cache
def _md_pull_off_load(lam):
    lm = mpmath.mpf(lam)
    y = _scan_start(lam)
    prev_dP = _md_eval(y, lam)[4]
    best = None
    while y <= _Y_SCAN_MAX:
        ynext = y + _Y_STEP
        dP = _md_eval(ynext, lam)[4]
        # dP/dt < 0 -> > 0 : P has a local minimum in t (in between)
        if prev_dP < 0 <= dP:

            def dPfun(yy):
                with _MP.workdps(_dps_for(yy)):
                    return _md_mp(yy, lm)[4]

            with _MP.workdps(_dps_for(ynext)):
                ym = _bisect_mp(dPfun, y, ynext, -1)
            val = _md_eval(ym, lam)[1]
            best = val if best is None or val < best else best
        prev_dP = dP
        y = ynext
    with _MP.workdps(40):
        x = _end_x(lm)
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
    lam = _positive("lam", lam)
    if control == "load":
        return _md_pull_off_load(lam)
    if control == "displacement":
        return float(_branch_end(lam)[3])
    raise ValueError(f"control must be 'load' or 'displacement', got {control!r}")


# ---------------------------------------------------------------------------
# Breakpoints of the stable branch (cached per lambda)
# ---------------------------------------------------------------------------
@functools.cache
def _branch_D_for_A(lam, A_target):
    """``Delta_M - Delta_end`` (mpf) at the stable-branch point with ``A_M = A_target``.

    Returns None when ``A_target <= A_end`` (no such point on the stable branch).
    """
    y_end, A_end, D_end, _ = _branch_end(lam)
    if not A_target > A_end:
        return None
    lm = mpmath.mpf(lam)
    At = mpmath.mpf(A_target)

    def f(yy):  # A decreasing in t
        with _MP.workdps(_dps_for(yy)):
            return _md_mp(mpmath.mpf(yy), lm)[0] - At

    lo = 0.0
    while not f(lo) > 0:
        lo -= 2.0
    hi = lo + 2.0
    while not f(hi) < 0:
        hi += 2.0
    with _MP.workdps(_dps_for(max(abs(lo), abs(hi)))):
        y = _bisect_mp(f, lo, hi, 1)
    with _MP.workdps(_dps_for(y)):
        return _md_mp(y, lm)[2] - D_end


@functools.cache
def _branch_P_zeros(lam):
    """``Delta_M - Delta_end`` (mpf list) where ``P_M`` changes sign on the stable branch."""
    y_end, A_end, D_end, _ = _branch_end(lam)
    lm = mpmath.mpf(lam)
    y_hi = float(y_end) if math.isfinite(y_end) else _Y_SCAN_MAX
    ys = list(np.arange(_scan_start(lam), y_hi, _Y_STEP)) + [y_hi]
    vals = [_md_eval(y, lam)[1] for y in ys]

    def f(yy):
        with _MP.workdps(_dps_for(yy)):
            return _md_mp(mpmath.mpf(yy), lm)[1]

    out = []
    for i in range(len(ys) - 1):
        if (vals[i] > 0) != (vals[i + 1] > 0):
            with _MP.workdps(_dps_for(max(abs(ys[i]), abs(ys[i + 1])))):
                y = _bisect_mp(f, ys[i], ys[i + 1], 1 if vals[i] > 0 else -1)
            with _MP.workdps(_dps_for(y)):
                out.append(_md_mp(y, lm)[2] - D_end)
    return tuple(out)


# ---------------------------------------------------------------------------
# Greenwood-Williamson integrals
# ---------------------------------------------------------------------------
def gw_moment(d, order):
    """Greenwood-Williamson moment ``int_d^inf (z - d)^order phi(z) dz`` (mpmath).

    Parameters
    ----------
    d : float
        Dimensionless separation.
    order : float
        Order ``k >= 0`` of the moment.

    Returns
    -------
    float
        The moment, computed with :func:`mpmath.quad` at 30 digits.
    """
    d = _finite("d", d)
    order = _finite("order", order)
    if order < 0:
        raise ValueError(f"order must be >= 0, got {order!r}")
    with _MP.workdps(30):
        dm = mpmath.mpf(d)
        k = mpmath.mpf(order)
        c = 1 / mpmath.sqrt(2 * mpmath.pi)

        def f(u):
            return u**k * c * mpmath.exp(-((u + dm) ** 2) / 2)

        scale = 1 / (1 + max(d, 0.0))
        pts = [mpmath.mpf(0), scale / 4, scale, 4 * scale]
        if d < 0:
            pts += [-dm / 2, -dm, -dm + 2]
        pts = sorted(set(pts))
        pts.append(pts[-1] + 8)
        pts.append(mpmath.inf)
        return float(mpmath.quad(f, pts))


class _Local:
    """Per-asperity state as a function of the integration variable ``s``.

    ``u = u_end + s^2``; returns ``(a_bar, P_bar)``.
    """

    def __init__(self, p):
        self.p = p
        if p.gamma == 0.0:
            self.u_end = 0.0
            self.s_breaks = [p.a1 / p.beta, p.a2 / p.beta]
            self.s_Pzero = []
        else:
            lam = p.lam
            self.lam = lam
            _, A_end, D_end, _ = _branch_end(lam)
            self.u_end = float(p.delta_hat * D_end)
            breaks = []
            for ak in (p.a1, p.a2):
                dD = _branch_D_for_A(lam, ak * p.A_hat)
                if dD is not None:
                    breaks.append(math.sqrt(p.delta_hat * float(dD)))
            self.s_breaks = breaks
            self.s_Pzero = [math.sqrt(p.delta_hat * float(v)) for v in _branch_P_zeros(lam)]

    def __call__(self, s):
        p = self.p
        if p.gamma == 0.0:
            return p.beta * s, p.hertz_pref * s**3
        A, P = _branch_point_offset(self.lam, s * s / p.delta_hat)
        return A / p.A_hat, P / p.P_hat


def _quantity(name, loc, a, P):
    if name == "contacts":
        return 1.0
    if name == "P":
        return P
    if name == "area":
        return a * a
    if name == "F":
        return _hk_friction(a, loc.p)
    raise KeyError(name)


def _integrate(d, p, names):
    """Integrals of Eqs. 5, 6/18, 10, 21 at separation ``d`` for the given quantities."""
    loc = _Local(p)
    z0 = d + loc.u_end  # lowest in-contact height
    # truncation z_max = max(d, 0) + 12, i.e. u_max = max(-d, 0) + 12: the s grid
    # does not depend on d for d >= 0, so the per-asperity cache is shared.
    s_max = math.sqrt(max(-d, 0.0) + _Z_TAIL - loc.u_end)
    # extra breakpoints around the bulk of phi when the contact region starts far below it
    s_phi = []
    if z0 < -3.0:
        s_phi = [math.sqrt(zk - z0) for zk in (-6.0, -3.0, 0.0, 3.0, 6.0) if zk - 1.0 > z0]
    pts = sorted({0.0, s_max, *[s for s in loc.s_breaks + loc.s_Pzero + s_phi if 0.0 < s < s_max]})
    if z0 > 0.0:
        # phi(z0 + s^2) = phi(z0) exp(-z0 s^2 - s^4/2): integrate the rest, scale at the end
        scale = math.exp(-0.5 * z0 * z0) / _SQRT2PI

        def weight(s):
            v = s * s
            return 2.0 * s * math.exp(-z0 * v - 0.5 * v * v)
    else:
        scale = 1.0 / _SQRT2PI

        def weight(s):
            z = z0 + s * s
            return 2.0 * s * math.exp(-0.5 * z * z)

    out = {}
    for name in names:

        def f(s, name=name):
            w = weight(s)
            if w == 0.0:
                return 0.0
            a, P = loc(s)
            return w * _quantity(name, loc, a, P)

        total = 0.0
        for lo, hi in zip(pts[:-1], pts[1:], strict=True):
            val, err, info, *msg = integrate.quad(f, lo, hi, epsabs=0.0, epsrel=_EPSREL, limit=_LIMIT, full_output=1)
            if msg and err > 1e-8 * abs(val) and err > 1e-300:
                raise ArithmeticError(f"quadrature of {name!r} at d={d!r} failed: {msg[0]} (err={err:g})")
            total += val
        out[name] = float(total * scale)
    return out


def _params(alpha, beta, gamma, nu, h_over_b, tau_f1, tau_f2, a1, a2):
    return _Params(alpha, beta, gamma, nu, h_over_b, tau_f1, tau_f2, a1, a2)


_NAMES = ("contacts", "P", "F", "area")


def separation_point(
    d, alpha, beta, gamma=0.0, *, nu=0.3, h_over_b=1.0, tau_f1=1 / 43, tau_f2=1 / 43 / 30, a1=28.0, a2=8e4
):
    """Contacts, load, friction and area per asperity at one separation.

    Computes, with ``u = z - d`` and the standard normal height density
    ``phi`` (Eq. 19), integrating over the in-contact asperities
    ``z >= d + u_end`` (``u_end = 0`` for Hertz, ``delta_hat Delta_end`` with
    adhesion):

    * ``contacts = int phi dz`` (Eq. 5, ``n/N``),
    * ``P = int P_bar(u) phi dz`` (Eq. 6 for Hertz, Eq. 18 with the MD load
      ``P_M/P_hat`` of Eqs. 11-13, 17 with adhesion),
    * ``F = int 2 pi tau_bar(a_bar) a_bar^2 phi dz`` (Eq. 10 with Eq. 2),
    * ``area = int a_bar^2 phi dz`` (Eq. 21, ``A/(N pi b^2)``).

    Parameters
    ----------
    d : float
        Dimensionless separation ``d/sigma``.
    alpha, beta : float
        Surface roughness and friction regime parameters (Eq. 7), > 0.
    gamma : float, optional
        Surface energy / compliance coefficient (Eq. 16), >= 0; 0 means no
        adhesion (Hertz).
    nu : float, optional
        Poisson's ratio, ``-1 < nu < 0.5``.
    h_over_b : float, optional
        Maximum adhesion distance over Burgers vector (Eq. 15).
    tau_f1, tau_f2, a1, a2 : float, optional
        Hurtado-Kim constants of Eq. 2 (``a1 < a2``).

    Returns
    -------
    dict
        Float values under ``'contacts'``, ``'P'``, ``'F'``, ``'area'``.
    """
    d = _finite("d", d)
    p = _params(alpha, beta, gamma, nu, h_over_b, tau_f1, tau_f2, a1, a2)
    return _integrate(d, p, _NAMES)


def _P_of_d(d, p):
    return _integrate(d, p, ("P",))["P"]


def load_point(P, alpha, beta, gamma=0.0, *, nu=0.3, h_over_b=1.0, tau_f1=1 / 43, tau_f2=1 / 43 / 30, a1=28.0, a2=8e4):
    """State at the smallest separation where the mean load per asperity equals ``P``.

    ``P_bar(d) -> +inf`` as ``d -> -inf``.  Without adhesion ``P_bar(d)`` is
    strictly decreasing and the root is bracketed by expansion.  With adhesion
    ``P_bar(d)`` need not be monotone: ``d`` is scanned upward in steps of 0.25
    from ``d = -2`` (or lower, until ``P_bar > P``) and the first bracketed
    sign change is refined with :func:`scipy.optimize.brentq` (a crossing
    pair closer together than the scan step could be missed).

    Parameters
    ----------
    P : float
        Target mean load per asperity ``P/(N G b^2)`` (> 0 when ``gamma == 0``).
    alpha, beta, gamma, nu, h_over_b, tau_f1, tau_f2, a1, a2
        As in :func:`separation_point`.

    Returns
    -------
    dict
        ``'d'`` plus the keys of :func:`separation_point`.
    """
    P = _finite("P", P)
    p = _params(alpha, beta, gamma, nu, h_over_b, tau_f1, tau_f2, a1, a2)
    if p.gamma == 0.0 and not P > 0.0:
        raise ValueError(f"P must be > 0 without adhesion, got {P!r}")

    def g(d):
        return _P_of_d(d, p) - P

    lo = 0.0 if p.gamma == 0.0 else -2.0
    glo = g(lo)
    while not glo > 0:
        lo -= 1.0
        if lo < -40:
            raise ValueError(f"P={P!r} not reached for d >= -40")
        glo = g(lo)
    if p.gamma == 0.0:
        step = 1.0
        hi = lo + step
        while g(hi) > 0:
            lo = hi
            step *= 1.5
            hi = lo + step
            if hi > 40:
                raise ValueError(f"P={P!r} too small to be reached (d > 40)")
    else:
        hi = lo + 0.25
        while g(hi) > 0:
            lo = hi
            hi = lo + 0.25
            if hi > 40:
                raise ValueError(f"P={P!r} not reached for d <= 40")
    d = optimize.brentq(g, lo, hi, xtol=1e-13, rtol=1e-15, maxiter=200)
    out = {"d": float(d)}
    out.update(_integrate(d, p, _NAMES))
    return out


def pull_off(
    alpha, beta, gamma, *, d_max=10.0, nu=0.3, h_over_b=1.0, tau_f1=1 / 43, tau_f2=1 / 43 / 30, a1=28.0, a2=8e4
):
    """Pull-off force per asperity: ``max(0, -min_{d <= d_max} P_bar(d))``.

    A grid scan of ``P_bar(d)`` (step 0.25, extended to the left while the
    minimum sits on the left edge) followed by bounded Brent minimisation
    around the best grid point.

    Parameters
    ----------
    alpha, beta, gamma, nu, h_over_b, tau_f1, tau_f2, a1, a2
        As in :func:`separation_point`.
    d_max : float, optional
        Largest separation considered.

    Returns
    -------
    dict
        ``{'pull_off': float, 'd': float}`` with ``'d'`` the separation where
        ``P_bar`` is smallest (``d_max`` if ``P_bar`` decreases up to there).
    """
    d_max = _finite("d_max", d_max)
    p = _params(alpha, beta, gamma, nu, h_over_b, tau_f1, tau_f2, a1, a2)
    step = 0.25
    start = min(-1.0, d_max - 4.0)
    grid = list(np.arange(start, d_max, step)) + [d_max]
    vals = [_P_of_d(x, p) for x in grid]
    while int(np.argmin(vals)) == 0:
        new = grid[0] - step
        grid.insert(0, new)
        vals.insert(0, _P_of_d(new, p))
        if new < -40:
            raise ArithmeticError("pull_off: P_bar has no minimum for d >= -40")
    i = int(np.argmin(vals))
    if i == len(grid) - 1:
        dmin, pmin = grid[i], vals[i]
    else:
        lo, hi = grid[i - 1], grid[i + 1]
        res = optimize.minimize_scalar(
            lambda x: _P_of_d(x, p), bounds=(lo, hi), method="bounded", options={"xatol": 1e-7, "maxiter": 200}
        )
        dmin, pmin = float(res.x), float(res.fun)
        if vals[i] < pmin:
            dmin, pmin = grid[i], vals[i]
    return {"pull_off": float(max(0.0, -pmin)), "d": float(dmin)}
