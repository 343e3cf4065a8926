r"""The stable Maugis-Dugdale branch at a given penetration: the per-asperity law of the integrals.

:func:`md_solve` inverts Eq (13) of the parametric curve of :mod:`asperity.maugis_dugdale`,
:math:`\Delta(t) = A^2 - \tfrac43\lambda At`, on the stable branch (from its end,
:func:`~asperity.maugis_dugdale_branch.md_branch_end`, to :data:`DELTA_MAX`), and evaluates
Eqs (11)-(12) there.  A table of a variable nearly linear in :math:`\log t` (cached per
:math:`\lambda` and range) gives the start, safeguarded Newton finishes, vectorized over the
penetrations; :math:`\lambda` is broadcast by solving once per distinct value
(:func:`~asperity.maugis_dugdale_branch.for_each_lambda`).  Re-exported by
:mod:`asperity.maugis_dugdale`; the curve is imported from there on first use, since that
module imports this one.

References
----------
.. [1] D. Maugis, "Adhesion of spheres: the JKR-DMT transition using a Dugdale
   model", J. Colloid Interface Sci. 150 (1992) 243-269.
.. [2] Adams et al., Eqs (11)-(13).
"""

from __future__ import annotations

import functools

import numpy as np

from ._validation import as_float_array, check_broadcast, ufunc_result
from .maugis_dugdale_branch import DELTA_MAX, check_lambda, for_each_lambda, md_branch_end

__all__ = ["md_solve"]


def _the_curve():
    """The parametric curve, :func:`asperity.maugis_dugdale.md_curve` (that module imports this one)."""
    from . import maugis_dugdale

    return maugis_dugdale.md_curve


def md_solve(delta, lam):
    r"""Stable-branch contact radius and load of one asperity at penetration :math:`\Delta`.

    Inverts Eq (13), :math:`\Delta(t) = A^2 - \tfrac43\lambda At`, for :math:`t` on the
    stable branch (where :math:`\Delta(t)` is strictly decreasing, i.e.
    :math:`d\Delta/dA > 0`) by safeguarded Newton iteration in :math:`\log t`, then
    evaluates Eqs (11)-(12).  At the end of a branch that runs to :math:`A \to 0`
    (:math:`\lambda < \lambda_c`) it returns the limit values, with :math:`t = \infty`.
    Broadcasts like a ufunc over ``delta`` and ``lam``.

    Parameters
    ----------
    delta : array_like
        Penetration :math:`\Delta = u(K^2/\pi^2w^2R)^{1/3}`, from the end of the stable
        branch :math:`\Delta_{end}` (:func:`~asperity.maugis_dugdale_branch.md_branch_end`,
        negative) to :data:`~asperity.maugis_dugdale_branch.DELTA_MAX` (1e150).  May be empty.
    lam : array_like
        Maugis parameter :math:`\lambda` in ``[1e-12, 1e12]`` (:data:`~asperity.maugis_dugdale_branch.LAMBDA_RANGE`),
        broadcast with ``delta`` (one inversion per distinct value).

    Returns
    -------
    A, P, t : ndarray or numpy.float64
        Contact radius :math:`a(K/\pi wR^2)^{1/3}`, load :math:`P/(\pi wR)` and parameter
        :math:`t = \sqrt{m^2-1}` at each ``delta`` (the broadcast shape).

    Raises
    ------
    ValueError
        If ``lam`` is not real or out of range, ``delta`` is not real and finite or lies
        outside :math:`[\Delta_{end}(\lambda), 10^{150}]`, or the shapes do not broadcast.

    Examples
    --------
    >>> A, P, t = md_solve([1.0, 4.0], 1e-8)  # near DMT: Delta = A^2, P = A^3 - 2
    >>> [round(float(x), 2) for x in A], [round(float(x), 2) for x in P]
    ([1.0, 2.0], [-1.0, 6.0])

    References
    ----------
    Maugis (1992); Adams et al., Eqs (11)-(13).
    """
    lam = check_lambda(lam)
    delta = as_float_array(delta, "delta", allow_empty=True)
    check_broadcast(delta=delta, lam=lam)
    return ufunc_result(for_each_lambda(_solve_one, lam, delta, outputs=3))


def _solve_one(lam: float, delta):
    """(A, P, t) at penetrations ``delta`` for one lambda."""
    end = md_branch_end(lam)
    if ((delta < end.delta) | (delta > DELTA_MAX)).any():
        raise ValueError(f"delta (penetration) must lie in [{end.delta:.17g}, {DELTA_MAX:g}] for lam={lam:g}: "
                         f"from the end of the stable branch to DELTA_MAX; got "
                         f"values from {delta.min():g} to {delta.max():g}")
    t, A, P = _invert_penetration(delta, lam, end)
    return A, P, t


def _inverse_variable(D, end):
    """y(Delta), falling with s = log10 t and nearly linear in s away from lambda ~ 1 (Delta >> 1
    or near the branch end), and dy/dDelta: log(Delta - Delta_end) where the branch runs to
    t = inf, asinh(sqrt(Delta - Delta_end)) where it ends at a minimum of Delta."""
    x = np.maximum(D - end.delta, 1e-300)
    if np.isinf(end.t):
        return np.log(x), 1.0 / x
    r = np.sqrt(x)
    return np.arcsinh(r), 0.5 / (r * np.sqrt(1.0 + x))


@functools.lru_cache(maxsize=256)
def _penetration_table(lam: float, s_lo: float, s_hi: float):
    """y (:func:`_inverse_variable`) and dy/ds on 257 points of s = log10 t in [s_lo, s_hi].

    s(y) is nearly linear, so a cubic-Hermite inverse of this table is good to about 1e-9.
    """
    md_curve = _the_curve()
    grid = np.linspace(s_lo, s_hi, 257)
    t = 10.0**grid
    D, dD = md_curve(t, lam, True)[2::3]
    y, dy = _inverse_variable(D, md_branch_end(lam))
    return grid, y, dD * t * np.log(10.0) * dy


def _table_range(lam, end, lo, hi):
    """Ends (s_lo, s_hi) of s = log10 t for the table, with Delta(s_lo) >= hi and (branch to
    t = inf) Delta(s_hi) <= lo, stepping by 2 from s_hi = 2 and s_lo = min(s_hi - 1, 0): one point
    of the curve at a time (its fast path for single floats)."""
    md_curve = _the_curve()
    s_hi = float(np.log10(end.t)) if np.isfinite(end.t) else 2.0
    while np.isinf(end.t) and md_curve(10.0**s_hi, lam)[2] > lo and s_hi < 300:
        s_hi += 2.0
    s_lo = min(s_hi - 1.0, 0.0)
    while md_curve(10.0**s_lo, lam)[2] < hi:
        s_lo -= 2.0
    return s_lo, s_hi


def _invert_penetration(delta, lam, end):
    """(t, A, P) on the stable branch with Delta(t) = delta (delta >= end.delta), vectorized.

    A cubic-Hermite inverse of a table of y(Delta) (:func:`_inverse_variable`, cached per
    lambda and range) gives each start; safeguarded Newton on y in log10 t finishes, usually
    in one or two steps, also next to the branch end where Delta(t) is flat but y is not.
    """
    md_curve = _the_curve()
    flat = delta.ravel()
    t_out, A_out, P_out = (np.full_like(flat, x) for x in (end.t, end.A, end.P))
    todo = np.flatnonzero(flat > end.delta)
    if todo.size == 0:
        return (x.reshape(delta.shape) for x in (t_out, A_out, P_out))
    target = flat[todo]
    s_lo, s_hi = _table_range(lam, end, float(target.min()), float(target.max()))
    grid, ygrid, slope = _penetration_table(lam, float(s_lo), float(s_hi))
    # Table look-up for a bracket [a, b] and a cubic-Hermite start for s(y).
    y = _inverse_variable(target, end)[0]
    j = np.clip(np.searchsorted(-ygrid, -y), 1, grid.size - 1)
    a, b = grid[j - 1], grid[j]
    D0, D1 = ygrid[j - 1], ygrid[j]
    x = (y - D0) / (D1 - D0)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        H = ((2 * x - 3) * x * x + 1) * a + (3 - 2 * x) * x * x * b \
            + (D1 - D0) * x * (1 - x) * ((1 - x) / slope[j - 1] - x / slope[j])
    s = np.where(np.isfinite(H) & (H >= a) & (H <= b), H, a + (b - a) * x)
    active = np.arange(target.size)
    for _ in range(100):
        if active.size == 0:
            break
        sa = s[active]
        t = 10.0**sa
        A, P, D, dA, dP, dD = md_curve(t, lam, True)
        resid = D - target[active]
        # Keep the bracket: Delta decreases with s.
        a[active] = np.where(resid > 0, sa, a[active])
        b[active] = np.where(resid < 0, sa, b[active])
        yD, dy = _inverse_variable(D, end)
        slope = dD * t * np.log(10.0) * dy  # dy/ds
        with np.errstate(divide="ignore", invalid="ignore"):
            step = np.where(slope < 0, -(yD - y[active]) / slope, np.nan)
        s_new = sa + step
        bad = ~np.isfinite(s_new) | (s_new < a[active]) | (s_new > b[active])
        s_new = np.where(bad, 0.5 * (a[active] + b[active]), s_new)
        tol = 1e-14 * np.maximum(1.0, np.abs(sa))
        # Stop at a residual at rounding level (near the branch end Delta(t) is flat and the
        # step cannot shrink below rounding), a tiny step or a collapsed bracket.
        done = ((np.abs(resid) <= 1e-15 * np.maximum(np.abs(D), np.abs(target[active])))
                | (~bad & (np.abs(step) <= tol)) | (b[active] - a[active] <= tol))
        # A finished step is tiny: carry A and P along it to first order.
        dt = np.where(bad, 0.0, 10.0**s_new - t)[done]
        fin = todo[active[done]]
        t_out[fin], A_out[fin], P_out[fin] = t[done] + dt, A[done] + dA[done] * dt, P[done] + dP[done] * dt
        s[active] = s_new
        active = active[~done]
    return (x.reshape(delta.shape) for x in (t_out, A_out, P_out))
