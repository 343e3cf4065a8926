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
:class:`PullOff`), and :func:`invert_branch` (from :func:`branch_guess`; both in
:mod:`asperity.branch_inversion` and re-exported here) solves :math:`\bar P(\bar d) = P`
on a monotone branch.  :class:`~asperity.curves.Model` caches
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

from ._numbers import apart
from ._validation import check_integer, check_scalar_real
from .asperity_law import U_END_LIMIT, ModelParameters, check_parameters
from .branch_inversion import branch_guess, invert_branch
from .pull_off_search import PullOff, find_pull_off
from .tabulation import D_MAX, D_MIN, Tabulation, check_tabulation

__all__ = ["LoadOutOfRange", "PullOff", "Branch", "start_separation", "bracket_low", "force_grid", "stable_branch",
           "branch_guess", "invert_branch", "find_pull_off"]


class LoadOutOfRange(ValueError):
    """A load with no equilibrium: below the least load the model carries.

    A :class:`ValueError` whose message is in the model's units; its attributes let a caller
    in physical units say the same in newtons.

    Attributes
    ----------
    floor : float
        The least load :math:`P/(NGb^2)`: 0 (exclusive) without adhesion, else minus the
        pull-off force or the force at the end of the branch (inclusive).
    got : float
        The smallest load given.
    what : str
        What the floor is, in words.
    exclusive : bool
        True if the floor itself has no equilibrium (no adhesion: loads must be > 0).
    units : str
        Appended to the numbers in the message (``" N"``; empty in the model's units).
    d_end : float or None
        The separation whose force is the floor when that is the end of the branch, not a
        pull-off (the caller's units).

    The fields are the exception's ``args``, so it pickles and copies (a process pool sends it
    between processes).
    """

    def __init__(self, floor: float, got: float, what: str, exclusive: bool = False, units: str = "",
                 d_end: float | None = None):
        super().__init__(floor, got, what, exclusive, units, d_end)
        self.floor, self.got, self.what, self.exclusive = float(floor), float(got), what, bool(exclusive)
        self.units, self.d_end = units, d_end

    def __str__(self) -> str:
        k = apart(self.floor, self.got)
        floor, got = (f"{x:.{k}g}{self.units}" for x in (self.floor, self.got))
        bound = f"> {floor}" if self.exclusive else f">= {floor}"
        return f"P (load) must be {bound} ({self.what}): no equilibrium under a smaller load; got min {got}"


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
        tab = tab.extended(d_lo, d_hi)
        if tab.sums(np.array([d_lo]))[0][0, 1] > P_max:
            return d_lo, tab
        if d_lo == D_MIN:  # the steps stop at the floor, not beyond it (a hunt: 'd_lo must lie in ...')
            _check_floor(-np.inf, P_max, tab.params)
        d_lo = max(d_lo - max(2.0, 0.5 * abs(d_lo)), D_MIN)


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
        # the grid points before the refined pull-off (which may lie either side of grid[i - 1],
        # and, reused from another grid, anywhere near grid[i]), above its force: the branch
        # stays ordered in d and decreasing in P up to it
        k = int(np.searchsorted(grid[:i + 1], pull_off.d, side="left"))
        above = np.flatnonzero(Pg[:k] <= floor)
        k = int(above[0]) if above.size else k
        return Branch(np.append(grid[:k], pull_off.d), np.append(Pg[:k], floor), np.append(dPg[:k], 0.0), tab,
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
