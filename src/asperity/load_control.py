r"""Load control: the separation that carries a given load, and the most tensile force.

With adhesion the mean force per asperity :math:`\bar P(\bar d)` is not monotone: it
falls from large compressive values as the surfaces part, may turn tensile, reaches its
most tensile value (the pull-off force, Table 1) and returns to zero as
:math:`\bar d \to \infty`.  Under a given load the surfaces sit at the first separation,
coming from full contact, where :math:`\bar P(\bar d)` equals the load: on the stable
branch, :math:`d\bar P/d\bar d < 0`.

The functions work on a :class:`~asperity.tabulation.Tabulation` (the integrals and their
separation derivatives anywhere in its range): :func:`start_separation` and
:func:`bracket_low` find a separation carrying more than every load, :func:`force_grid`
tabulates the force, :func:`stable_branch` cuts the stable branch at pull-off
(:func:`find_pull_off`, re-exported from :mod:`asperity.pull_off_search` with
:class:`PullOff`), and :func:`invert_branch` (from :func:`branch_guess`) solves
:math:`\bar P(\bar d) = P` on a monotone branch.  :class:`~asperity.curves.Model` caches
the tabulation and pull-off and calls these; a loading/unloading cycle calls them on its
other branches.  Forces are :math:`P/(NGb^2)` per asperity (positive compressive),
separations :math:`d/\sigma`.

References
----------
.. [1] Adams et al., Eqs (6), (18), Table 1 and Figs 3-9.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ._validation import check_1d, check_integer, check_scalar_real
from .asperity_law import U_END_LIMIT, ModelParameters, check_parameters
from .pull_off_search import PullOff, find_pull_off
from .tabulation import D_MAX, D_MIN, Tabulation, check_tabulation

__all__ = ["PullOff", "Branch", "start_separation", "bracket_low", "force_grid", "stable_branch", "branch_guess",
           "invert_branch", "find_pull_off"]


class Branch(NamedTuple):
    """A monotone branch of the force on a grid of separations.

    Attributes
    ----------
    grid : ndarray
        Increasing separations :math:`d/\\sigma`.
    P : ndarray
        Force :math:`P/(NGb^2)` there, monotone along the grid.
    dP : ndarray
        Its derivative in the separation, :math:`dP/d\\bar d`.
    tab : Tabulation
        A tabulation covering the grid (wider than the one passed in if it had to grow).
    pull_off : PullOff or None
        The pull-off the branch ends at, if the force turns tensile on it.
    """

    grid: np.ndarray
    P: np.ndarray
    dP: np.ndarray
    tab: Tabulation
    pull_off: PullOff | None


def start_separation(params: ModelParameters, P_max, d_hi) -> float:
    r"""A separation below which the force is likely to exceed ``P_max``: the Hertz estimate.

    For :math:`\bar d \ll 0` almost every asperity touches and
    :math:`\bar P \approx \tfrac83\alpha\beta^2(-\bar d)^{3/2}/(1-\nu)`, a lower bound by
    Jensen's inequality; adhesion lowers the force a little, hence a margin of 2.

    .. math::
        \bar d_0 = \min\Big(-3,\ \bar d_{hi} - 1,\ -\big(P_{max}(1-\nu)/(\tfrac83\alpha\beta^2)\big)^{2/3} - 2\Big)

    Parameters
    ----------
    params : ModelParameters
        The model's parameters (:math:`\alpha, \beta, \nu`).
    P_max : float
        Largest load :math:`P/(NGb^2)` to be carried, finite (non-positive loads use 0).
    d_hi : float
        Upper end of the search, :math:`d/\sigma`.

    Returns
    -------
    float
        :math:`\bar d_0 \ge` :data:`~asperity.tabulation.D_MIN`.

    Raises
    ------
    ValueError
        If the estimate lies below ``D_MIN`` = -1e4 (the load is too large).

    Examples
    --------
    >>> from asperity.asperity_law import ModelParameters
    >>> start_separation(ModelParameters(0.01, 1000.0), 10.0, 10.0)
    -3.0

    References
    ----------
    Adams et al., Eq (6); Greenwood & Williamson (1966).
    """
    p = check_parameters(params)
    P_max = check_scalar_real(P_max, "P_max")
    d_hi = check_scalar_real(d_hi, "d_hi")
    if not D_MIN <= d_hi <= D_MAX + U_END_LIMIT:
        raise ValueError(f"d_hi (separation d/sigma) must lie in [{D_MIN:g}, {D_MAX + U_END_LIMIT:g}], got {d_hi!r}")
    c = (8.0 / 3.0) / (1.0 - p.nu) * p.alpha * p.beta**2
    d_lo = min(-3.0, d_hi - 1.0, -((max(P_max, 0.0) / c) ** (2.0 / 3.0)) - 2.0)
    _check_floor(d_lo, P_max, p)
    return d_lo


def _check_floor(d_lo, P_max, p):
    if d_lo < D_MIN:
        raise ValueError(f"P_max (the largest load P) = {P_max:g} is too large for alpha = {p.alpha:g}, "
                         f"beta = {p.beta:g}, gamma = {p.gamma:g}: it needs a separation below d/sigma = {D_MIN:g}")


def bracket_low(tab: Tabulation, P_max, d_lo, d_hi) -> tuple[float, Tabulation]:
    r"""A separation where the force exceeds ``P_max``, stepping down from ``d_lo``.

    Steps :math:`\bar d_{lo} \leftarrow \bar d_{lo} - \max(2, |\bar d_{lo}|/2)` until
    :math:`\bar P(\bar d_{lo}) > P_{max}`, widening the tabulation to
    :math:`[\bar d_{lo}, \bar d_{hi}]` on the way (:meth:`~asperity.tabulation.Tabulation.extended`).

    Parameters
    ----------
    tab : Tabulation
        Tabulation of the model (any range; it is widened as needed).
    P_max : float
        Largest load :math:`P/(NGb^2)`, finite.
    d_lo : float
        First separation tried, :math:`\ge -10^4` (e.g. :func:`start_separation`).
    d_hi : float
        Upper end of the range the tabulation must keep serving, > ``d_lo``.

    Returns
    -------
    d_lo : float
        Separation with :math:`\bar P(\bar d_{lo}) > P_{max}`.
    tab : Tabulation
        A tabulation covering :math:`[\bar d_{lo}, \bar d_{hi}]`.

    Raises
    ------
    ValueError
        If no separation above ``D_MIN`` = -1e4 carries ``P_max``, or an input is invalid.

    Examples
    --------
    >>> from asperity.asperity_law import ModelParameters
    >>> p = ModelParameters(0.01, 1000.0)
    >>> d_lo, tab = bracket_low(Tabulation(p, -3.0, 10.0), 100.0, -3.0, 10.0)
    >>> d_lo, bool(tab.sums([d_lo])[0][0, 1] > 100.0)
    (-3.0, True)

    References
    ----------
    Adams et al., Eqs (6), (18).
    """
    d_lo, d_hi = check_tabulation(tab, d_lo, d_hi, covered=False)
    P_max = check_scalar_real(P_max, "P_max")
    while True:
        _check_floor(d_lo, P_max, tab.params)
        tab = tab.extended(d_lo, d_hi)
        if tab.sums(np.array([d_lo]))[0][0, 1] > P_max:
            return d_lo, tab
        d_lo = d_lo - max(2.0, 0.5 * abs(d_lo))


def force_grid(tab: Tabulation, d_lo, d_hi, n=None):
    r"""Separations from ``d_lo`` to ``d_hi`` with the force and its derivative there.

    Parameters
    ----------
    tab : Tabulation
        Tabulation covering :math:`[\bar d_{lo}, \bar d_{hi}]`.
    d_lo, d_hi : float
        Ends of the grid, :math:`d/\sigma`, ``d_lo < d_hi``.
    n : int, optional
        Number of points, >= 2 (default: one per 0.15 sigma, clipped to 40..800; the cubic
        Hermite guesses of :func:`branch_guess` and the pull-off search are good to ~1e-5 there).

    Returns
    -------
    grid, P, dP : ndarray
        Separations :math:`d/\sigma`, force :math:`P/(NGb^2)` and :math:`dP/d\bar d`.

    Raises
    ------
    ValueError
        If the tabulation does not cover the interval, or an input is invalid.

    Examples
    --------
    >>> from asperity.asperity_law import ModelParameters
    >>> grid, P, dP = force_grid(Tabulation(ModelParameters(0.01, 1000.0), 0.0, 2.0), 0.0, 2.0, n=3)
    >>> grid.tolist(), bool(P[0] > P[1] > P[2] > 0), bool(np.all(dP < 0))
    ([0.0, 1.0, 2.0], True, True)

    References
    ----------
    Adams et al., Eqs (6), (18).
    """
    d_lo, d_hi = check_tabulation(tab, d_lo, d_hi)
    n = int(np.clip((d_hi - d_lo) / 0.15, 40, 800)) if n is None else check_integer(n, "n", 2, 10**6)
    grid = np.linspace(d_lo, d_hi, n)
    g0, g1 = tab.sums(grid, order=1)
    return grid, g0[:, 1], g1[:, 1]


def stable_branch(tab: Tabulation, d_lo, d_hi, *, d_top=None, P_min=None, pull_off=None) -> Branch:
    r"""The stable branch of the force from ``d_lo``: where :math:`d\bar P/d\bar d < 0`.

    On a grid from ``d_lo`` to ``d_hi`` the branch runs to the most tensile force, the
    pull-off (:func:`find_pull_off`, refined; its force closes the branch with slope 0).
    Without a tensile force it runs to the smallest force on the grid, and, if loads below
    that are asked for (``P_min``), on to ``d_top`` where the force flattens out.

    Parameters
    ----------
    tab : Tabulation
        Tabulation covering :math:`[\bar d_{lo}, \bar d_{hi}]`; widened to ``d_top`` if needed.
    d_lo, d_hi : float
        Separations :math:`d/\sigma` bounding the search, ``d_lo < d_hi``; the force at
        ``d_lo`` should exceed every load (:func:`bracket_low`).
    d_top : float, optional
        Largest separation the branch may reach when the force is still falling at ``d_hi``
        (default ``d_hi``: no extension).
    P_min : float, optional
        Smallest load to be carried (default: no extension).
    pull_off : PullOff, optional
        A pull-off found before on :math:`[\cdot, \bar d_{hi}]`, to reuse.

    Returns
    -------
    Branch
        ``grid``, ``P``, ``dP`` (force decreasing along the grid), the tabulation used last and
        the pull-off (None without a tensile force).

    Raises
    ------
    ValueError
        If the tabulation does not cover the interval, or an input is invalid.

    Examples
    --------
    >>> from asperity.asperity_law import ModelParameters
    >>> tab = Tabulation(ModelParameters(0.003, 1000.0, 1e-3), -3.0, 10.0)
    >>> br = stable_branch(tab, -3.0, 10.0)
    >>> bool(np.all(np.diff(br.P) < 0)), br.pull_off.exists, bool(br.P[-1] == -br.pull_off.force)
    (True, True, True)

    References
    ----------
    Adams et al., Eq (18), Table 1.
    """
    d_lo, d_hi = check_tabulation(tab, d_lo, d_hi)
    if pull_off is not None and not isinstance(pull_off, PullOff):
        raise TypeError(f"pull_off must be an asperity.PullOff or None, got {type(pull_off).__name__}")
    grid, Pg, dPg = force_grid(tab, d_lo, d_hi)
    i = int(np.argmin(Pg))
    if Pg[i] < 0:  # a pull-off force exists: the branch ends there; this grid locates it
        if pull_off is None:
            pull_off = find_pull_off(tab, d_lo, d_hi, grid, Pg, dPg)
        floor = -pull_off.force
        return Branch(np.append(grid[:i], pull_off.d), np.append(Pg[:i], floor), np.append(dPg[:i], 0.0), tab,
                      pull_off)
    grid, Pg, dPg = grid[:i + 1], Pg[:i + 1], dPg[:i + 1]
    d_top = d_hi if d_top is None else check_scalar_real(d_top, "d_top")
    if not d_hi <= d_top <= D_MAX - tab.law.u_end:
        raise ValueError(f"d_top must lie in [d_hi, {D_MAX - tab.law.u_end:.6g}] = [{d_hi:g}, "
                         f"{D_MAX - tab.law.u_end:.6g}], got {d_top!r}")
    P_min = None if P_min is None else check_scalar_real(P_min, "P_min")
    if P_min is not None and P_min < Pg[-1] and grid[-1] < d_top:  # tiny loads: the flat is far out
        tab = tab.extended(d_lo, d_top)
        more, Pm, dPm = force_grid(tab, grid[-1], d_top, n=200)
        grid, Pg, dPg = (np.append(x, y[1:]) for x, y in ((grid, more), (Pg, Pm), (dPg, dPm)))
    return Branch(grid, Pg, dPg, tab, None)


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
    :func:`branch_guess`, keeping the bracket.  Once a step is below 1e-5 (the error after
    it is ~1e-15) the integrals are carried to the new point by a second-order Taylor step,
    which saves a final pass over the quadrature nodes: one pass usually suffices.  The
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
    for _ in range(80):
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
            # Halley: the root of the quadratic Taylor polynomial, error O(step^3).
            step = np.where(g < 0, -r / (g + 0.5 * h * newton), np.nan)
        step = np.where(np.abs(step - newton) <= np.abs(newton), step, newton)  # far out: plain Newton
        x_new = xa + step
        bad = ~np.isfinite(x_new) | (x_new < a[active]) | (x_new > b[active])
        x_new = np.where(bad, 0.5 * (a[active] + b[active]), x_new)
        done = ~bad & (np.abs(step) <= 1e-5 * np.maximum(1.0, np.abs(xa)))
        done |= (b[active] - a[active]) <= 1e-14 * np.maximum(1.0, np.abs(xa))
        step = np.where(bad, 0.0, step)
        fin = active[done]
        d[fin] = np.where(bad[done], xa[done], x_new[done])
        sd = step[done, None]
        out[fin] = s0[done] + sd * (s1[done] + 0.5 * sd * s2[done])  # error ~ step^3
        x[active] = x_new
        active = active[~done]
    if active.size:  # pragma: no cover - Newton with bisection always converges
        raise RuntimeError("load inversion did not converge")
    return d, out
