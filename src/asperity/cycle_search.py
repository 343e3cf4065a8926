r"""Searches on the branches of a cycle: closest approach under a preload, pull-off on retraction.

* :func:`closest_approach`: the separation :math:`\bar d_{min}` where the approach force reaches
  the preload, the largest compressive load of the cycle: load control on the approach branch
  (:func:`asperity.load_control.start_separation`, :func:`~asperity.load_control.bracket_low`,
  :func:`~asperity.load_control.stable_branch`, :func:`~asperity.load_control.invert_branch`
  on the tabulation of :class:`~asperity.cycle_integrals.ApproachLaw`).
* :func:`retract_pull_off`: the most tensile force on retraction from :math:`\bar d_{min}` to
  :math:`\bar d_{max}`, vectorised over :math:`\bar d_{min}`.  In the transition zone
  (:math:`\bar d - \bar d_{min} <` reach) the force is searched on a Chebyshev grid and the
  minimum refined on :math:`dP/d\bar d = 0` (Illinois, all preloads at once); beyond it the
  retraction force is the paper's curve, searched on one grid shared by all preloads and
  refined by :func:`asperity.load_control.find_pull_off`.  The retraction force is never more
  tensile than the paper's curve, and reaches it once the whole transition zone lies before
  the paper's pull-off point: the pull-off grows with the preload and saturates at the
  paper's (Table 1).
* :func:`first_zero`: where a branch's force first changes sign along the path.

References
----------
.. [1] K. N. G. Fuller, D. Tabor, Proc. R. Soc. A 345 (1975) 327.
.. [2] Adams et al., Eq (18), Table 1.
"""

from __future__ import annotations

import math

import numpy as np

from .cycle_integrals import CycleIntegrals, chebyshev_points
from .load_control import PullOff, bracket_low, find_pull_off, invert_branch, stable_branch, start_separation
from .tabulation import D_MIN

__all__ = ["closest_approach", "retract_pull_off", "first_zero", "bracketed_roots"]

_GRID_STEP = 0.02  # sigma, as the paper's pull-off search


def closest_approach(ci: CycleIntegrals, preload, d_max: float):
    r"""Closest approach :math:`\bar d_{min}` for each preload: :math:`P^{app}(\bar d_{min}) = P_{pre}`.

    The first separation, coming from deep contact, where the approach force equals the
    preload (the stable branch of approach, :math:`dP^{app}/d\bar d < 0`).

    Parameters
    ----------
    ci : CycleIntegrals
        The cycle's integrals.
    preload : ndarray
        Preloads :math:`P/(NGb^2) > 0` (validated by the caller), 1-D.
    d_max : float
        Start of the approach, :math:`d/\sigma`.

    Returns
    -------
    ndarray
        :math:`\bar d_{min}` per preload.

    Raises
    ------
    ValueError
        If a preload needs a separation below ``D_MIN`` = -1e4 (beyond the model's domain), or
        is reached only beyond ``d_max``.
    """
    P_max = float(preload.max())
    p = ci.params
    model = f"alpha = {p.alpha:g}, beta = {p.beta:g}, gamma = {p.gamma:g}"
    d_hi = min(d_max, ci.approach_top)  # beyond it the approach force is 0
    try:
        d_lo = min(start_separation(ci.params, P_max, d_hi), d_hi - 1.0)
        d_lo, tab = bracket_low(ci.approach_tab(d_lo, d_hi), P_max, d_lo, d_hi)
    except ValueError:
        raise ValueError(f"preload = {P_max:g} (in N G b^2) is beyond the domain of the model with {model}: it "
                         f"needs a separation below d/sigma = {D_MIN:g}") from None
    ci.set_approach_tab(tab)
    branch = stable_branch(tab, d_lo, d_hi)
    floor = branch.P[-1]
    if preload.min() < floor:
        raise ValueError(f"preload must be >= {floor:.6g} for the model with {model}: a smaller one is reached "
                         f"only beyond d_max = {d_max:.6g} (the start of the approach); got {preload.min():g}")
    d, _ = invert_branch(branch.tab, preload, branch.grid, branch.P, branch.dP)
    return d


def _zone_minimum(ci: CycleIntegrals, d_min, d_max: float):
    """Most tensile retraction force in the transition zone and where: (P, d), per d_min."""
    n = d_min.size
    span = np.minimum(ci.reach, d_max - d_min)
    m = int(np.clip(np.ceil(span.max() / _GRID_STEP) + 1, 33, 1001))
    x = chebyshev_points(m)
    w = span[:, None] * x[None, :]
    dd = d_min[:, None] + w
    P = ci.zone_sums(dd.ravel(), np.repeat(d_min, m))[0][:, 1].reshape(n, m)
    k = np.argmin(P, axis=1)
    rows = np.arange(n)
    best_P, best_d = P[rows, k], dd[rows, k]
    inner = np.flatnonzero((k > 0) & (k < m - 1))
    if inner.size:
        a, b = dd[inner, k[inner] - 1], dd[inner, k[inner] + 1]
        dmin_in = d_min[inner]

        def slope(x, rows):  # a review: the brackets still searched were a subset of dmin_in
            return ci.zone_sums(x, dmin_in[rows], order=1)[1][:, 1]

        x_star = bracketed_roots(slope, a, b, indexed=True)
        P_star = ci.zone_sums(x_star, dmin_in)[0][:, 1]
        better = P_star < best_P[inner]
        best_P[inner[better]] = P_star[better]
        best_d[inner[better]] = x_star[better]
    return best_P, best_d


def bracketed_roots(f, a, b, fa=None, fb=None, tol=1e-13, iterations=100, indexed=False):
    """Roots of ``f`` (vectorised) in the brackets [a, b], by the Illinois method.

    Parameters
    ----------
    f : callable
        ``f(x)`` for a 1-D array ``x``, evaluated only strictly inside the brackets when
        ``fa`` and ``fb`` are given (useful where ``f`` is one-sided at an end, e.g. a kink).
    a, b : ndarray
        Bracket ends, ``a < b``, 1-D.
    fa, fb : ndarray, optional
        ``f`` at the ends (default: evaluated).
    tol : float
        Relative width of the final bracket.
    indexed : bool
        Call ``f(x, rows)``, ``rows`` the brackets ``x`` belongs to, for an ``f`` that differs
        from bracket to bracket (the brackets still searched are a subset).

    Returns
    -------
    ndarray
        One root per bracket; where ``f(a)`` and ``f(b)`` have the same sign, the end with the
        smaller ``|f|``.
    """
    a = np.array(a, dtype=float, ndmin=1)
    b = np.array(b, dtype=float, ndmin=1)
    every = np.arange(a.size)
    call = (lambda x, rows: f(x, rows)) if indexed else (lambda x, rows: f(x))
    fa = call(a, every) if fa is None else np.array(fa, dtype=float, ndmin=1)
    fb = call(b, every) if fb is None else np.array(fb, dtype=float, ndmin=1)
    sa = np.sign(fa)
    x = np.where(np.abs(fa) <= np.abs(fb), a, b)
    active = np.flatnonzero(sa * np.sign(fb) < 0)
    side = np.zeros(a.size)
    for _ in range(iterations):
        if active.size == 0:
            break
        A, B, FA, FB = a[active], b[active], fa[active], fb[active]
        c = (A * FB - B * FA) / (FB - FA)
        c = np.where((c > A) & (c < B), c, 0.5 * (A + B))
        fc = call(c, active)
        move_a = np.sign(fc) == sa[active]  # the root lies between c and b
        a[active] = np.where(move_a, c, A)
        fa[active] = np.where(move_a, fc, FA)
        b[active] = np.where(move_a, B, c)
        fb[active] = np.where(move_a, FB, fc)
        # Illinois: halve the kept end's value when the same end moved twice in a row.
        s = np.where(move_a, -1.0, 1.0)
        stale = side[active] == s
        fb[active] = np.where(stale & move_a, 0.5 * fb[active], fb[active])
        fa[active] = np.where(stale & ~move_a, 0.5 * fa[active], fa[active])
        side[active] = s
        x[active] = c
        done = (fc == 0) | ((b[active] - a[active]) <= tol * np.maximum(1.0, np.abs(c)))
        active = active[~done]
    return x


def _suffix_argmin(values):
    """``out[j]`` = index of the smallest of ``values[j:]`` (the first such, counting from j)."""
    out = np.empty(values.size, dtype=int)
    best = values.size - 1
    for j in range(values.size - 1, -1, -1):
        if values[j] <= values[best]:
            best = j
        out[j] = best
    return out


def _paper_minimum(ci: CycleIntegrals, d_lo, d_max: float):
    """Most tensile force of the paper's curve on [d_lo_i, d_max] and where: (P, d), per d_lo.

    One grid over [min d_lo, d_max] serves every d_lo: the smallest grid value beyond d_lo (a
    suffix minimum), compared with the force at d_lo itself; an interior minimum is refined
    by :func:`asperity.load_control.find_pull_off`, once per grid bracket.
    """
    n = d_lo.size
    best_P = np.full(n, np.inf)
    best_d = np.full(n, np.nan)
    run = np.flatnonzero(d_lo < d_max)
    if run.size == 0:
        return best_P, best_d
    lo = float(d_lo[run].min())
    tab = ci.paper_tab(lo, d_max)
    m = int(min(4000, np.ceil((d_max - lo) / _GRID_STEP))) + 1
    grid = np.linspace(lo, d_max, m)
    Pg = tab.sums(grid)[0][:, 1]
    P0 = tab.sums(d_lo[run])[0][:, 1]
    first = np.searchsorted(grid, d_lo[run], side="right")  # grid points beyond each d_lo
    g = _suffix_argmin(Pg)[np.minimum(first, m - 1)]
    at_start = (first >= m) | (P0 <= Pg[g])
    best_P[run], best_d[run] = np.where(at_start, P0, Pg[g]), np.where(at_start, d_lo[run], grid[g])
    # a minimum between d_lo and the first grid point beyond it, which the grid cannot see (a
    # review: 1 % low with every summit touched): where the force still falls at d_lo
    slope = tab.sums(d_lo[run], order=1)[1][:, 1]
    for r in np.flatnonzero(at_start & (first < m) & (slope < 0)):
        i = run[r]
        x = np.linspace(float(d_lo[i]), float(grid[first[r]]), 9)
        po = find_pull_off(tab, x[0], x[-1], x, tab.sums(x)[0][:, 1])
        if po.exists and -po.force < best_P[i]:
            best_P[i], best_d[i] = -po.force, po.d
    refined: dict[tuple, PullOff] = {}
    for r in np.flatnonzero(~at_start & (g < m - 1)):  # an interior minimum: refine its bracket
        i, gi = run[r], int(g[r])
        left = (grid[gi - 1], Pg[gi - 1]) if gi - 1 >= first[r] else (d_lo[i], P0[r])
        key = (gi, left[0])
        if key not in refined:
            refined[key] = find_pull_off(tab, left[0], grid[gi + 1], np.array([left[0], grid[gi], grid[gi + 1]]),
                                         np.array([left[1], Pg[gi], Pg[gi + 1]]))
        po = refined[key]
        if po.exists and -po.force < best_P[i]:
            best_P[i], best_d[i] = -po.force, po.d
    return best_P, best_d


def retract_pull_off(ci: CycleIntegrals, d_min, d_max: float) -> list[PullOff]:
    r"""Pull-off force on retraction from each :math:`\bar d_{min}` to :math:`\bar d_{max}`.

    .. math::
        P_{off}(\bar d_{min}) = \max\Big(0,\ -\min_{\bar d_{min} \le \bar d \le \bar d_{max}}
            P^{ret}(\bar d; \bar d_{min})\Big)

    Parameters
    ----------
    ci : CycleIntegrals
        The cycle's integrals.
    d_min : ndarray
        Closest approaches :math:`d/\sigma`, 1-D, each ``< d_max``.
    d_max : float
        End of retraction, :math:`d/\sigma`.

    Returns
    -------
    list of PullOff
        ``force`` :math:`|P|/(NGb^2)`, separation ``d`` and ``exists`` per ``d_min``
        (``PullOff(0.0, nan, False)`` where the retraction force stays compressive).
    """
    d_min = np.asarray(d_min, dtype=float).ravel()
    if not ci.params.adhesive:
        return [PullOff(0.0, float("nan"), False) for _ in d_min]
    P_best = np.full(d_min.size, np.inf)
    d_best = np.full(d_min.size, np.nan)
    if ci.reach > 0:
        P_best, d_best = _zone_minimum(ci, d_min, d_max)
    P_pap, d_pap = _paper_minimum(ci, d_min + ci.reach, d_max)
    take = P_pap < P_best
    P_best = np.where(take, P_pap, P_best)
    d_best = np.where(take, d_pap, d_best)
    return [PullOff(float(-P), float(d), True) if P < 0 else PullOff(0.0, float("nan"), False)
            for P, d in zip(P_best, d_best, strict=True)]


def first_zero(sums, d, P):
    r"""Where the force :math:`P(\bar d)` first changes sign along a path, and the integrals there.

    The first sign change on the path's points brackets the crossing; safeguarded Newton's
    method (the derivative from ``sums``) refines it to 1e-12, and the integrals are carried to
    the final point by a first-order Taylor step, as :func:`asperity.load_control.invert_branch` does.

    Parameters
    ----------
    sums : callable
        ``sums(x)`` -> ``[S_0, S_1]`` at separations ``x`` (1-D): the four integrals (contacts,
        P, F, area) and their derivatives in the separation, shape (x.size, 4) each.
    d, P : ndarray
        The path's separations in path order and the force there.

    Returns
    -------
    x : float
        The separation of the first sign change (NaN if the force keeps its sign).
    row : ndarray or None
        The four integrals there (None if there is no sign change).
    """
    s = np.sign(P)
    change = np.flatnonzero((s[:-1] * s[1:] < 0) | ((s[:-1] != 0) & (s[1:] == 0)))
    if change.size == 0:
        return float("nan"), None
    i = int(change[0])
    (lo, P_lo), (hi, P_hi) = sorted(((d[i], P[i]), (d[i + 1], P[i + 1])))
    x = lo + (hi - lo) * P_lo / (P_lo - P_hi) if P_lo != P_hi else 0.5 * (lo + hi)
    for _ in range(100):
        s0, s1 = sums(np.array([x]))
        f, g = s0[0, 1], s1[0, 1]
        if f == 0.0:
            return float(x), s0[0]
        if np.sign(f) == np.sign(P_lo):
            lo = x
        else:
            hi = x
        step = -f / g if g != 0.0 else math.nan
        if math.isfinite(step) and lo <= x + step <= hi:
            if abs(step) <= 1e-12 * max(1.0, abs(x)):
                return float(x + step), s0[0] + s1[0] * step
            x = x + step
        else:
            x = 0.5 * (lo + hi)
        if hi - lo <= 1e-14 * max(1.0, abs(x)):
            break
    s0 = sums(np.array([x]))[0]
    return float(x), s0[0]
