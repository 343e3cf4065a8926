r"""Maugis-Dugdale adhesive contact of one sphere on a flat (Eqs 11-14).

The Dugdale cohesive zone (constant tensile stress :math:`\sigma_0` over a gap
:math:`h`) spans the whole range from DMT (:math:`\lambda \to 0`) to JKR
(:math:`\lambda \to \infty`).  In Maugis' units

.. math::
    A = a\Big(\frac{K}{\pi w R^2}\Big)^{1/3},\quad
    P = \frac{P}{\pi w R},\quad
    \Delta = u\Big(\frac{K^2}{\pi^2 w^2 R}\Big)^{1/3},\quad
    \lambda = 2\sigma_0\Big(\frac{R}{\pi w K^2}\Big)^{1/3},\quad K=\tfrac43 E^*,

the solution is parametric in :math:`m = c/a > 1`.  We use
:math:`t = \sqrt{m^2-1} \in (0, \infty)` instead: near :math:`m = 1` the first
bracket of Eq (11) is a difference of :math:`O(t)` terms worth
:math:`\tfrac43 t^3`, which we evaluate by its series.  Along the curve :math:`t`
runs from :math:`A = \infty` (:math:`t \to 0`) to :math:`A \to 0` (:math:`t \to \infty`).

Stability under displacement control requires :math:`d\Delta/dA > 0`.  Above
:math:`\lambda_c \approx 0.938` the curve :math:`\Delta(A)` has an interior minimum,
which ends the stable branch; below it the branch runs to :math:`A \to 0` with a
finite tensile load.

All functions broadcast over ``t`` and ``lam`` like ufuncs, except where noted.

References
----------
.. [1] D. Maugis, "Adhesion of spheres: the JKR-DMT transition using a Dugdale
   model", J. Colloid Interface Sci. 150 (1992) 243-269.
.. [2] K. L. Johnson, J. A. Greenwood, "An adhesion map for the contact of elastic
   spheres", J. Colloid Interface Sci. 192 (1997) 326-333.
.. [3] Adams, Müftü, Mohd Azhar, Eqs (11)-(14).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np
from scipy import optimize

from ._validation import as_float_array, check_positive, scalar

__all__ = [
    "LAMBDA_C",
    "BranchPoint",
    "md_radius",
    "md_load",
    "md_penetration",
    "md_curve",
    "md_branch_end",
    "md_solve",
    "md_pull_off",
    "md_lambda",
    "LAMBDA_RANGE",
    "check_lambda",
]

# Coefficients of the series t + (t^2 - 1) atan t = sum_k (-1)^(k+1) 4k t^(2k+1)/((2k-1)(2k+1)).
_SERIES_T = 0.5
_K = np.arange(1, 31)
_F1_COEF = (-1.0) ** (_K + 1) * 4.0 * _K / ((2 * _K - 1) * (2 * _K + 1))


def _f1(t):
    """First bracket of Eq (11): t + (t^2 - 1) atan t, without cancellation near t = 0."""
    t = np.asarray(t, dtype=float)
    scalar = t.ndim == 0
    t = np.atleast_1d(t)
    out = t + (t * t - 1.0) * np.arctan(t)
    small = t < _SERIES_T
    if np.any(small):
        ts = t[small]
        t2 = ts * ts
        series = np.zeros_like(ts)
        for c in _F1_COEF[::-1]:  # Horner in t^2
            series = series * t2 + c
        out[small] = series * ts**3
    return out[0] if scalar else out


def _brackets(t):
    """The three brackets of Eqs (11)-(12) and their t-derivatives."""
    t = np.asarray(t, dtype=float)
    at = np.arctan(t)
    m = np.sqrt(1.0 + t * t)
    f1 = _f1(t)
    f2 = t * at - t * t / (1.0 + m)  # t atan t - m + 1, with m - 1 = t^2/(1 + m)
    g = t + m * m * at  # bracket of Eq (12)
    df1 = 2.0 * t * (at + t / (m * m))
    df2 = at + t / (m * m) - t / m
    dg = 2.0 + 2.0 * t * at
    return f1, f2, g, df1, df2, dg


def _radius_from_brackets(lam, f1, f2):
    # Eq (11) is a2 A^2 + a1 A - 1 = 0 with a1, a2 >= 0; the positive root without
    # cancellation is 2 / (a1 + sqrt(a1^2 + 4 a2)).
    a2 = 0.5 * lam * f1
    a1 = (4.0 / 3.0) * lam * lam * f2
    return 2.0 / (a1 + np.sqrt(a1 * a1 + 4.0 * a2)), a1, a2


#: Range of the Maugis parameter handled (DMT and JKR are within 1e-6 of their limits far inside).
LAMBDA_RANGE = (1e-12, 1e12)
#: Range of t = sqrt(m^2 - 1) handled without overflow.
T_RANGE = (1e-100, 1e100)


def check_lambda(lam):
    """The Maugis parameter as a float array within :data:`LAMBDA_RANGE`."""
    lam = check_positive(lam, "lam")
    lo, hi = LAMBDA_RANGE
    if np.any((lam < lo) | (lam > hi)):
        raise ValueError(f"lam (Maugis parameter) must lie in [{lo:g}, {hi:g}] (use asperity.dmt below and "
                         f"asperity.jkr above), got {lam!r}")
    return lam


def _check_t_lam(t, lam):
    t = as_float_array(t, "t", allow_empty=True)
    lo, hi = T_RANGE
    if np.any((t < lo) | (t > hi)):
        raise ValueError(f"t = sqrt(m^2 - 1) must lie in [{lo:g}, {hi:g}]")
    return t, check_lambda(lam)


def md_radius(t, lam):
    r"""Contact radius :math:`A` from Eq (11) at :math:`t = \sqrt{m^2-1}`.

    .. math::
        \frac{\lambda A^2}{2}\big[t + (m^2-2)\tan^{-1}t\big]
        + \frac{4\lambda^2 A}{3}\big[t\tan^{-1}t - m + 1\big] = 1

    solved as a quadratic for its only positive root, without cancellation.

    Parameters
    ----------
    t : array_like
        :math:`\sqrt{m^2-1} > 0`, with :math:`m = c/a`.
    lam : array_like
        Maugis parameter :math:`\lambda > 0`.

    Returns
    -------
    ndarray
        :math:`A = a (K/\pi w R^2)^{1/3}`.

    References
    ----------
    Maugis (1992); Adams et al., Eq (11).
    """
    t, lam = _check_t_lam(t, lam)
    f1, f2, *_ = _brackets(t)
    return _radius_from_brackets(lam, f1, f2)[0]


def md_load(t, lam):
    r"""Load :math:`P = P/(\pi w R)` from Eq (12): :math:`A^3 - \lambda A^2[t + m^2\tan^{-1}t]`.

    Parameters and units as in :func:`md_radius`.

    References
    ----------
    Maugis (1992); Adams et al., Eq (12).
    """
    return md_curve(t, lam)[1]


def md_penetration(t, lam):
    r"""Penetration :math:`\Delta` from Eq (13): :math:`A^2 - \tfrac43\lambda A t`.

    Parameters and units as in :func:`md_radius`.

    References
    ----------
    Maugis (1992); Adams et al., Eq (13).
    """
    return md_curve(t, lam)[2]


def md_curve(t, lam):
    """Radius, load and penetration ``(A, P, Delta)`` at ``t`` (Eqs 11-13 at once)."""
    t, lam = _check_t_lam(t, lam)
    return _curve(t, lam)[:3]


def _curve(t, lam, derivatives=False):
    f1, f2, g, df1, df2, dg = _brackets(t)
    A, a1, a2 = _radius_from_brackets(lam, f1, f2)
    P = A**3 - lam * A * A * g
    D = A * A - (4.0 / 3.0) * lam * A * t
    if not derivatives:
        return A, P, D
    da2 = 0.5 * lam * df1
    da1 = (4.0 / 3.0) * lam * lam * df2
    dA = -(da2 * A * A + da1 * A) / (2.0 * a2 * A + a1)
    dD = 2.0 * A * dA - (4.0 / 3.0) * lam * (dA * t + A)
    dP = 3.0 * A * A * dA - lam * (2.0 * A * dA * g + A * A * dg)
    return A, P, D, dA, dP, dD


def _x0(lam):
    """Limit of A t as A -> 0: root of (pi lam/4) x^2 + (4 lam^2/3)(pi/2 - 1) x - 1 = 0."""
    q2 = 0.25 * np.pi * lam
    q1 = (4.0 / 3.0) * lam * lam * (0.5 * np.pi - 1.0)
    return 2.0 / (q1 + np.sqrt(q1 * q1 + 4.0 * q2))


def _small_a_curvature(lam):
    """c in Delta - Delta(A=0) = c A^2 + O(A^3) near A = 0; the branch reaches A = 0 iff c > 0."""
    x0 = _x0(lam)
    dF = 0.5 * np.pi * lam * x0 + (4.0 / 3.0) * lam * lam * (0.5 * np.pi - 1.0)
    c2 = (0.25 * np.pi * lam + 2.0 * lam * lam / (3.0 * x0)) / dF
    return 1.0 - (4.0 / 3.0) * lam * c2


#: Critical Maugis parameter: below it the stable branch runs to A -> 0.
LAMBDA_C = float(optimize.brentq(_small_a_curvature, 0.5, 1.5, xtol=1e-15, rtol=1e-15))


@dataclass(frozen=True)
class BranchPoint:
    """A point of the Maugis-Dugdale curve: parameter t, radius A, load P, penetration delta."""

    t: float
    A: float
    P: float
    delta: float


def _first_sign_change(func, lam, hi=16.0, n=400):
    """log10 t of the first change of func(t) from < 0 to >= 0, or None."""
    lo = min(-12.0, np.log10(1e-3 / lam))  # JKR-like curves turn at t ~ 1/lam
    s = np.linspace(lo, hi, n)
    vals = func(10.0**s)
    idx = np.flatnonzero(vals >= 0)
    if idx.size == 0 or idx[0] == 0:
        return None
    i = idx[0]
    root = optimize.brentq(lambda x: float(func(10.0**x)), s[i - 1], s[i], xtol=1e-14,
                           rtol=1e-15)
    return root


@functools.lru_cache(maxsize=4096)
def _branch_end(lam: float) -> BranchPoint:
    if lam < LAMBDA_C:
        x0 = float(_x0(lam))
        return BranchPoint(t=np.inf, A=0.0, P=-0.5 * np.pi * lam * x0 * x0,
                           delta=-(4.0 / 3.0) * lam * x0)
    s = _first_sign_change(lambda t: _curve(t, lam, True)[5], lam)
    if s is None:  # lam within rounding of LAMBDA_C: the minimum sits at A -> 0
        return _branch_end(np.nextafter(LAMBDA_C, 0.0))
    t = 10.0**s
    A, P, D = _curve(np.float64(t), lam)
    return BranchPoint(t=t, A=float(A), P=float(P), delta=float(D))


def md_branch_end(lam) -> BranchPoint:
    r"""End of the stable, displacement-controlled branch of one asperity.

    Above :math:`\lambda_c` (:data:`LAMBDA_C`) it is the minimum of :math:`\Delta(A)`
    (:math:`d\Delta/dA = 0`); below, the limit :math:`A \to 0`, where
    :math:`At \to x_0` with :math:`\tfrac{\pi\lambda}{4}x_0^2 + \tfrac{4\lambda^2}{3}
    (\tfrac{\pi}{2}-1)x_0 = 1`, so :math:`\Delta = -\tfrac43\lambda x_0` and
    :math:`P = -\tfrac{\pi}{2}\lambda x_0^2`.  The load there is the pull-off force under
    displacement control.

    Parameters
    ----------
    lam : float
        Maugis parameter :math:`\lambda > 0` (scalar).

    Returns
    -------
    BranchPoint
        ``t`` (``inf`` below :math:`\lambda_c`), ``A``, ``P`` and ``delta`` there.

    References
    ----------
    Maugis (1992); Johnson & Greenwood (1997).
    """
    lam = float(check_lambda(scalar(lam, "lam")))
    return _branch_end(lam)


def md_solve(delta, lam):
    r"""Stable-branch contact radius and load of one asperity at penetration :math:`\Delta`.

    Inverts Eq (13) for :math:`t` on the stable branch (where :math:`\Delta(t)` is strictly
    decreasing) by safeguarded Newton iteration in :math:`\log t`, then evaluates
    Eqs (11)-(12).  Vectorized over ``delta``.

    Parameters
    ----------
    delta : array_like
        Penetration :math:`\Delta \ge \Delta_{end}` (see :func:`md_branch_end`).
    lam : float
        Maugis parameter :math:`\lambda > 0` (scalar).

    Returns
    -------
    A, P, t : ndarray
        Contact radius, load and parameter :math:`t` at each ``delta``.

    References
    ----------
    Maugis (1992); Adams et al., Eqs (11)-(13).
    """
    lam = float(check_lambda(scalar(lam, "lam")))
    delta = as_float_array(delta, "delta", allow_empty=True)
    end = _branch_end(lam)
    if np.any(delta < end.delta):
        raise ValueError(f"delta must be >= the end of the stable branch, {end.delta:.17g}, "
                         f"for lam={lam:g}")
    t = _invert_penetration(delta, lam, end)
    # At the end of a branch that runs to A -> 0 (t = inf) take the limit values.
    finite = np.isfinite(t)
    A, P, _ = _curve(np.where(finite, t, 1.0), lam)
    A = np.where(finite, A, end.A)
    P = np.where(finite, P, end.P)
    return A, P, t


def _invert_penetration(delta, lam, end):
    """t on the stable branch with Delta(t) = delta (delta >= end.delta), vectorized."""
    flat = delta.ravel()
    if flat.size == 0:
        return delta.copy()
    out = np.empty_like(flat)
    at_end = flat <= end.delta
    out[at_end] = end.t
    todo = ~at_end
    if not np.any(todo):
        return out.reshape(delta.shape)
    target = flat[todo]
    # Bracket in s = log10 t: Delta(s) is decreasing on the stable branch.
    s_hi = np.log10(end.t) if np.isfinite(end.t) else 2.0
    while np.isinf(end.t) and _curve(10.0**s_hi, lam)[2] > target.min() and s_hi < 300:
        s_hi += 2.0
    s_lo = min(s_hi - 1.0, 0.0)
    while _curve(10.0**s_lo, lam)[2] < target.max():
        s_lo -= 2.0
    grid = np.linspace(s_lo, s_hi, 257)
    dgrid = _curve(10.0**grid, lam)[2]
    # Table look-up for a bracket and a starting point (dgrid is decreasing).
    j = np.clip(np.searchsorted(-dgrid, -target), 1, grid.size - 1)
    a, b = grid[j - 1], grid[j]
    s = a + (b - a) * (dgrid[j - 1] - target) / (dgrid[j - 1] - dgrid[j])
    active = np.arange(target.size)
    for _ in range(100):
        if active.size == 0:
            break
        sa = s[active]
        t = 10.0**sa
        _, _, D, _, _, dD = _curve(t, lam, True)
        resid = D - target[active]
        # Keep the bracket: Delta decreases with s.
        a[active] = np.where(resid > 0, sa, a[active])
        b[active] = np.where(resid < 0, sa, b[active])
        slope = dD * t * np.log(10.0)
        with np.errstate(divide="ignore", invalid="ignore"):
            step = np.where(slope < 0, -resid / slope, np.nan)
        s_new = sa + step
        bad = ~np.isfinite(s_new) | (s_new < a[active]) | (s_new > b[active])
        s_new = np.where(bad, 0.5 * (a[active] + b[active]), s_new)
        tol = 1e-14 * np.maximum(1.0, np.abs(sa))
        # Stop at a tiny step, a collapsed bracket, or a residual at rounding level (near
        # the branch end Delta(t) is flat and the step cannot shrink below rounding).
        done = ((np.abs(resid) <= 1e-15 * np.maximum(np.abs(D), np.abs(target[active])))
                | (~bad & (np.abs(step) <= tol)) | (b[active] - a[active] <= tol))
        s[active] = np.where(done & bad, sa, s_new)
        active = active[~done]
    out[todo] = 10.0**s
    return out.reshape(delta.shape)


def _t_of_radius(A, lam):
    """t with md_radius(t, lam) = A, vectorized: Eq (11) at fixed A is increasing in t."""
    A = np.asarray(A, dtype=float)
    c2, c1 = 0.5 * lam * A * A, (4.0 / 3.0) * lam * lam * A
    a = np.full_like(A, np.log10(T_RANGE[0]))
    b = np.full_like(A, np.log10(T_RANGE[1]))
    # Start from the asymptotes: t << 1 (f1 ~ 4t^3/3, f2 ~ t^2/2), t >> 1 (f1 ~ pi t^2/2,
    # f2 ~ (pi/2 - 1) t); the smaller root is the better one.
    small = np.minimum(np.cbrt(0.75 / c2), np.sqrt(2.0 / c1))
    q2, q1 = 0.5 * np.pi * c2, (0.5 * np.pi - 1.0) * c1
    large = 2.0 / (q1 + np.sqrt(q1 * q1 + 4.0 * q2))
    s = np.log10(np.where(small < 1.0, small, large))
    for _ in range(200):
        t = 10.0**s
        f1, f2, _, df1, df2, _ = _brackets(t)
        g = c2 * f1 + c1 * f2 - 1.0
        a, b = np.where(g < 0, s, a), np.where(g > 0, s, b)
        with np.errstate(divide="ignore", invalid="ignore"):
            s_new = s - g / ((c2 * df1 + c1 * df2) * t * np.log(10.0))
        bad = ~np.isfinite(s_new) | (s_new < a) | (s_new > b)
        s_new = np.where(bad, 0.5 * (a + b), s_new)
        if np.all(np.abs(s_new - s) <= 1e-13 * np.maximum(1.0, np.abs(s))):
            return 10.0**s_new
        s = s_new
    return 10.0**s  # pragma: no cover - bisection converges well within 200 steps


def md_pull_off(lam, control: str = "load") -> BranchPoint:
    r"""Pull-off point of one Maugis-Dugdale asperity.

    Parameters
    ----------
    lam : float
        Maugis parameter :math:`\lambda > 0`.
    control : {'load', 'displacement'}
        ``'load'``: the minimum of :math:`P` over the whole curve (JKR: :math:`-3/2`,
        DMT: :math:`-2`).  ``'displacement'``: the load at the end of the stable branch
        (JKR: :math:`-5/6` at :math:`A = 6^{-1/3}`).

    Returns
    -------
    BranchPoint
        Where pull-off happens; ``P`` is the (negative) pull-off load :math:`P/(\pi w R)`.

    References
    ----------
    Maugis (1992), Johnson & Greenwood (1997).
    """
    lam = float(check_lambda(scalar(lam, "lam")))
    if control == "displacement":
        return _branch_end(lam)
    if control != "load":
        raise ValueError(f"control must be 'load' or 'displacement', got {control!r}")
    return _load_pull_off(lam)


@functools.lru_cache(maxsize=1024)
def _load_pull_off(lam: float) -> BranchPoint:
    x0 = float(_x0(lam))
    limit = BranchPoint(t=np.inf, A=0.0, P=-0.5 * np.pi * lam * x0 * x0,
                        delta=-(4.0 / 3.0) * lam * x0)
    s = _first_sign_change(lambda t: _curve(t, lam, True)[4], lam)
    if s is None:
        return limit
    t = 10.0**s
    A, P, D = _curve(np.float64(t), lam)
    if P > limit.P:
        return limit
    return BranchPoint(t=t, A=float(A), P=float(P), delta=float(D))


def md_lambda(R, w, E_star, sigma0):
    r"""Maugis parameter :math:`\lambda = 2\sigma_0 (R/\pi w K^2)^{1/3}`, :math:`K = \tfrac43E^*` (Eq 14).

    The arguments come in the order of the regime family
    (:func:`asperity.regimes.tabor_parameter` ``(R, w, E_star, z0)``,
    :func:`asperity.regimes.maugis_parameter` ``(R, w, E_star, sigma0)``).

    .. math::

        \lambda = 2\sigma_0\Big(\frac{R}{\pi w K^2}\Big)^{1/3},\qquad K = \tfrac43 E^*

    Parameters
    ----------
    R : array_like
        Sphere radius :math:`R` (m), > 0.
    w : array_like
        Work of adhesion :math:`w` (J/m^2), > 0.
    E_star : array_like
        Composite Young's modulus :math:`E^*` (Pa), > 0.
    sigma0 : array_like
        Dugdale adhesive stress :math:`\sigma_0 = w/h` (Pa), > 0.

    Returns
    -------
    ndarray
        :math:`\lambda` (dimensionless), broadcast over the inputs (0-d for scalars).

    References
    ----------
    Maugis (1992); Adams et al., Eq (14).
    """
    R = check_positive(R, "R")
    w = check_positive(w, "w")
    K = (4.0 / 3.0) * check_positive(E_star, "E_star")
    sigma0 = check_positive(sigma0, "sigma0")
    return 2.0 * sigma0 * np.cbrt(R / (np.pi * w * K * K))
