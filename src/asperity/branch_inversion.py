r"""Inversion of a monotone force branch: the separation where :math:`\bar P(\bar d) = P`.

Used by load control (:mod:`asperity.load_control`, which re-exports both functions) on
the stable branch, and by loading/unloading cycles on their other branches.
:func:`branch_guess` brackets each load's first crossing on a tabulated grid and guesses
it by a cubic Hermite interpolation in :math:`\sinh^{-1}(P/s)`; :func:`invert_branch`
refines it by safeguarded Halley steps on the integrals of a
:class:`~asperity.tabulation.Tabulation`.  Forces are :math:`P/(NGb^2)` per asperity
(positive compressive), separations :math:`d/\sigma`.

References
----------
.. [1] Adams et al., Eqs (6), (18).
"""

from __future__ import annotations

import numpy as np

from ._validation import check_1d
from .tabulation import Tabulation, check_tabulation

__all__ = ["branch_guess", "invert_branch"]


def branch_guess(P, grid, Pg, dPg):
    r"""Bracket :math:`[a, b]` of the first crossing of :math:`\bar P = P` on a decreasing grid,
    and a cubic-Hermite guess inside it.

    The interpolation runs in :math:`y = \sinh^{-1}(P/s)`, nearly :math:`\log P`, which is
    smooth over many decades of load, so Newton's method usually needs one step from it.

    Parameters
    ----------
    P : ndarray
        Loads :math:`P/(NGb^2)` within :math:`[\min P_g, \max P_g]`, 1-D.
    grid, Pg, dPg : ndarray
        Increasing separations, the force there (decreasing) and its derivative.

    Returns
    -------
    a, b, x : ndarray
        Bracket ends and the guess, one per load.

    Raises
    ------
    ValueError
        If an input is not real and finite, or the grid is not increasing with ``Pg``, ``dPg``
        of its length.

    Examples
    --------
    >>> a, b, x = branch_guess(np.array([1.5]), np.array([0.0, 1.0]), np.array([2.0, 1.0]),
    ...                        np.array([-1.0, -1.0]))
    >>> float(a[0]), float(b[0]), bool(0.0 < x[0] < 1.0)
    (0.0, 1.0, True)

    References
    ----------
    Fritsch & Carlson, SIAM J. Numer. Anal. 17 (1980) 238 (cubic Hermite interpolation).
    """
    P = check_1d(P, "P")
    grid, Pg, dPg = _check_grid(grid, Pg, dPg)
    return _branch_guess(P, grid, Pg, dPg)


def _check_grid(grid, Pg, dPg):
    grid, Pg, dPg = (check_1d(x, n) for x, n in ((grid, "grid"), (Pg, "Pg"), (dPg, "dPg")))
    if not (grid.size >= 2 and grid.size == Pg.size == dPg.size and np.all(np.diff(grid) > 0)):
        raise ValueError("grid must be increasing, with Pg and dPg of its length (at least 2 points)")
    return grid, Pg, dPg


def _branch_guess(P, grid, Pg, dPg):
    n = grid.size
    if (np.diff(Pg) < 0).all():  # strictly falling: the first point at or below P, by bisection
        j = np.clip(np.searchsorted(-Pg, -P, side="left"), 1, n - 1)
    else:
        j = np.clip(np.argmax(Pg[None, :] <= P[:, None], axis=1), 1, n - 1)
    a, b = grid[j - 1].copy(), grid[j].copy()
    nonzero = np.abs(P[P != 0])
    big = max(float(np.abs(P).max(initial=0.0)), float(np.abs(Pg).max()))
    s = max(1e-3 * (nonzero.min() if nonzero.size else np.abs(Pg).max()), 1e-300, 1e-300 * big)  # P/s <= 1e300
    y = np.arcsinh(P / s)
    ya, yb = np.arcsinh(Pg[j - 1] / s), np.arcsinh(Pg[j] / s)
    h = b - a
    ma = dPg[j - 1] / np.hypot(s, Pg[j - 1]) * h
    mb = dPg[j] / np.hypot(s, Pg[j]) * h
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.clip(np.where(ya != yb, (ya - y) / (ya - yb), 0.5), 0.0, 1.0)
        # The Hermite cubic as c3 t^3 + c2 t^2 + c1 t + c0 (minus y), t in [0, 1].
        c0, c1 = ya - y, ma
        c2 = 3.0 * (yb - ya) - 2.0 * ma - mb
        c3 = 2.0 * (ya - yb) + ma + mb
        for _ in range(4):  # Newton on it; stops early once every step is at rounding level
            H = ((c3 * t + c2) * t + c1) * t + c0
            dH = (3.0 * c3 * t + 2.0 * c2) * t + c1
            t_new = np.clip(np.where(dH != 0, t - H / dH, t), 0.0, 1.0)
            if not (np.abs(t_new - t) > 1e-13).any():
                t = t_new
                break
            t = t_new
    t = np.where(np.isfinite(t), t, 0.5)
    return a, b, a + h * t


def invert_branch(tab: Tabulation, P, grid, Pg, dPg):
    r"""Separations where :math:`\bar P(\bar d) = P` on a monotone branch, and the integrals there.

    Safeguarded Halley steps (the root of the quadratic Taylor polynomial of
    :math:`\bar P`, from the integrals' first two separation derivatives) from
    :func:`branch_guess`, keeping the bracket.  Once a step is below 1e-5 and the
    polynomial's linear term outweighs its quadratic one (the error after it is then
    ~1e-15; next to the end of a branch, where :math:`d\bar P/d\bar d \to 0`, a small step
    alone proves nothing) the integrals are carried to the new point by a second-order
    Taylor step, which saves a final pass over the quadrature nodes: one pass usually
    suffices.  The
    branch may fall (loading, :func:`stable_branch`) or rise (e.g. beyond pull-off) from
    ``grid[0]`` to ``grid[-1]``; each load's separation is the first crossing coming from
    ``grid[0]``, the only one where the force is monotone.

    Parameters
    ----------
    tab : Tabulation
        Tabulation covering the grid.
    P : array_like
        Loads :math:`P/(NGb^2)`, finite, between the forces at the ends of the branch.
    grid : array_like
        Increasing separations :math:`d/\sigma` of the branch, at least 2.
    Pg, dPg : array_like
        The force and its separation derivative on ``grid`` (:func:`force_grid`).

    Returns
    -------
    d : ndarray
        Separation :math:`d/\sigma` for each load.
    sums : ndarray
        Shape (loads, 4): contacts :math:`n/N`, force :math:`P/(NGb^2)`, friction
        :math:`F/(NGb^2)` and area :math:`A/(N\pi b^2)` there.

    Raises
    ------
    ValueError
        If the grid is not increasing, a load lies outside the forces at its ends, or the
        tabulation does not cover the grid.

    Examples
    --------
    >>> from asperity.asperity_law import ModelParameters
    >>> from asperity.load_control import force_grid
    >>> tab = Tabulation(ModelParameters(0.01, 1000.0), -3.0, 10.0)
    >>> grid, Pg, dPg = force_grid(tab, -3.0, 5.0)
    >>> d, sums = invert_branch(tab, [10.0], grid, Pg, dPg)
    >>> round(float(sums[0, 1]), 9)
    10.0

    References
    ----------
    Adams et al., Eqs (6), (18).
    """
    P = check_1d(P, "P")
    grid, Pg, dPg = _check_grid(grid, Pg, dPg)
    check_tabulation(tab, grid[0], grid[-1], names=("grid", "grid"))
    sign = 1.0 if Pg[0] >= Pg[-1] else -1.0  # work on a falling branch: -P on a rising one
    lo, hi = min(Pg[0], Pg[-1]), max(Pg[0], Pg[-1])
    if np.any((P < lo) | (P > hi)):
        raise ValueError(f"P (load) must lie between the forces at the ends of the branch, [{lo:.6g}, {hi:.6g}], "
                         f"got values from {P.min():g} to {P.max():g}")
    return _invert(tab, P, grid, Pg, dPg, sign)


def _invert(tab, P, grid, Pg, dPg, sign=1.0):
    a, b, x = _branch_guess(sign * P, grid, sign * Pg, sign * dPg)
    d = np.empty_like(P)
    out = np.empty((P.size, 4))
    active = np.arange(P.size)
    target = sign * P
    moved = np.full(P.size, np.inf)  # each load's last move
    for _ in range(200):
        if active.size == 0:
            break
        xa = x[active]
        s0, s1, s2 = tab.sums(xa, order=2)
        r = sign * s0[:, 1] - target[active]
        g = sign * s1[:, 1]
        h = sign * s2[:, 1]
        a[active] = np.where(r > 0, xa, a[active])
        b[active] = np.where(r < 0, xa, b[active])
        with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
            newton = np.where(g < 0, -r / g, np.nan)
            # Halley's variant: the root nearest 0 of the quadratic Taylor polynomial
            # r + g s + h s^2 / 2 (error O(step^3)), in the form free of cancellation; where
            # the quadratic has no real root (next to the pull-off), Newton's step.
            root = np.sqrt(g * g - 2.0 * h * r)
            quad = -2.0 * r / (g - root)
        halley = np.isfinite(quad) & (g - root < 0)
        step = np.where(halley, quad, newton)
        x_new = xa + step
        # Bisection where the step leaves the bracket or does not halve the last move (next to
        # the end of a branch, where dP/dd -> 0, the steps can creep or cycle: a review).
        bad = ~np.isfinite(x_new) | (x_new < a[active]) | (x_new > b[active]) | \
            (np.abs(step) > 0.5 * moved[active])
        x_new = np.where(bad, 0.5 * (a[active] + b[active]), x_new)
        # Converged once a Halley step is small and the polynomial's linear term dominates
        # (then the error after it is ~step^3: next to the end of a branch a small step alone
        # proves nothing), or the bracket has closed, or the load is met exactly.
        done = ~bad & halley & (np.abs(step) <= 1e-5 * np.maximum(1.0, np.abs(xa))) & (np.abs(h * step) <= np.abs(g))
        done |= (b[active] - a[active]) <= 1e-14 * np.maximum(1.0, np.abs(xa))
        done |= r == 0.0
        bad |= r == 0.0
        step = np.where(bad, 0.0, step)
        fin = active[done]
        d[fin] = np.where(bad[done], xa[done], x_new[done])
        sd = step[done, None]
        out[fin] = s0[done] + sd * (s1[done] + 0.5 * sd * s2[done])  # error ~ step^3
        moved[active] = np.abs(x_new - xa)
        x[active] = x_new
        active = active[~done]
    if active.size:  # pragma: no cover - bisection closes any bracket to 1e-14 within 60 steps
        raise RuntimeError("load inversion did not converge")
    return d, out
