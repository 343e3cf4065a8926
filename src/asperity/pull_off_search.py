r"""The pull-off force: the most tensile mean force per asperity over an interval of separations.

With adhesion the force per asperity :math:`\bar P(\bar d)` turns tensile as the surfaces
part and returns to zero far out; its most tensile value is the pull-off force of the
surface under load control (Table 1, Fig 7):

.. math::
    P_{off} = \max\Big(0,\ -\min_{\bar d_{lo} \le \bar d \le \bar d_{hi}} \bar P(\bar d)\Big).

:func:`find_pull_off` locates it on a :class:`~asperity.tabulation.Tabulation`;
:mod:`asperity.load_control` ends the stable branch there and re-exports both names.

References
----------
.. [1] Adams et al., Eq (18), Table 1, Fig 7.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ._validation import check_1d
from .tabulation import Tabulation, check_tabulation

__all__ = ["PullOff", "find_pull_off"]


@dataclass(frozen=True)
class PullOff:
    """Pull-off force (largest tensile force over separation) and where it occurs.

    Attributes
    ----------
    force : float
        :math:`|P|/(NGb^2) \\ge 0`, the most tensile force per asperity (0 if none).
    d : float
        Separation :math:`d/\\sigma` of the most tensile force (NaN when ``exists`` is False).
    exists : bool
        Whether the force turns tensile on the interval searched.
    """

    force: float
    d: float
    exists: bool

    def to_dict(self) -> dict:
        """``{"pull_off", "d", "exists"}``; NaN becomes None, as strict JSON wants."""
        return {"pull_off": self.force, "d": None if math.isnan(self.d) else self.d, "exists": self.exists}

    as_dict = to_dict  # the former name, kept as an alias


def find_pull_off(tab: Tabulation, d_lo, d_hi, grid=None, P=None) -> PullOff:
    r"""The most tensile force on :math:`[\bar d_{lo}, \bar d_{hi}]` and where it occurs.

    A grid (every 0.02 sigma, at most 4001 points; or the caller's) locates the minimum of
    :math:`\bar P(\bar d)`, and Newton's method on :math:`d\bar P/d\bar d = 0`, kept inside
    the grid's bracket, refines it.  A minimum on an end of the interval is returned as is.

    Parameters
    ----------
    tab : Tabulation
        Tabulation covering the interval.
    d_lo, d_hi : float
        The interval, :math:`d/\sigma`, ``d_lo < d_hi`` (the model searches from -3 to
        10 sigma beyond the end of the asperities' stable branch).
    grid, P : ndarray, optional
        A grid over the interval and the force on it, to reuse (both or neither).

    Returns
    -------
    PullOff
        ``force`` :math:`|P|/(NGb^2)`, separation ``d`` and ``exists``; without adhesion
        (:math:`\gamma = 0`) or without a tensile force: ``PullOff(0.0, nan, False)``.

    Raises
    ------
    ValueError
        If the tabulation does not cover the interval, or an input is invalid.

    Examples
    --------
    >>> from asperity.asperity_law import ModelParameters
    >>> po = find_pull_off(Tabulation(ModelParameters(0.003, 1000.0, 1e-3), -3.0, 10.0), -3.0, 10.0)
    >>> po.exists, round(po.force, 1)  # Table 1 prints 320.1
    (True, 320.1)

    References
    ----------
    Adams et al., Eq (18), Table 1, Fig 7.
    """
    d_lo, d_hi = check_tabulation(tab, d_lo, d_hi)
    if (grid is None) != (P is None):
        raise ValueError(f"give both grid and P, or neither (got {'grid' if P is None else 'P'} alone)")
    if grid is not None:
        grid, P = check_1d(grid, "grid"), check_1d(P, "P")
        if not (grid.size == P.size >= 2 and np.all(np.diff(grid) > 0)):
            raise ValueError("grid must be increasing, with P of its length (at least 2 points)")
    if not tab.params.adhesive:
        return PullOff(0.0, math.nan, False)
    if grid is None:
        grid = np.linspace(d_lo, d_hi, int(min(4000, round((d_hi - d_lo) / 0.02))) + 1)
        P = tab.sums(grid)[0][:, 1]
    i = int(np.argmin(P))
    if P[i] >= 0.0:
        return PullOff(0.0, math.nan, False)
    if i in (0, grid.size - 1):
        return PullOff(float(-P[i]), float(grid[i]), True)
    # Newton on dP/dd = 0 inside the grid bracket.
    a, b, x = grid[i - 1], grid[i + 1], grid[i]
    for _ in range(50):
        _, s1, s2 = tab.sums(np.array([x]), order=2)
        g, h = s1[0, 1], s2[0, 1]
        if g > 0:
            b = x
        else:
            a = x
        x_new = x - g / h if h > 0 else 0.5 * (a + b)
        if not a < x_new < b:
            x_new = 0.5 * (a + b)
        if abs(x_new - x) <= 1e-13 * max(1.0, abs(x)):
            x = x_new
            break
        x = x_new
    P_min = float(tab.sums(np.array([x]))[0][0, 1])
    return PullOff(max(0.0, -P_min), float(x), P_min < 0)
