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


def find_pull_off(tab: Tabulation, d_lo, d_hi, grid=None, P=None, dP=None) -> PullOff:
    r"""The most tensile force on :math:`[\bar d_{lo}, \bar d_{hi}]` and where it occurs.

    A grid (every 0.05 sigma, at most 4001 points, with :math:`d\bar P/d\bar d`; or the
    caller's) locates the minimum of :math:`\bar P(\bar d)`; the cubic Hermite interpolant
    of the grid starts Newton's method on :math:`d\bar P/d\bar d = 0`, kept inside the grid's
    bracket, which stops once a step is below 1e-7 (the next would be ~1e-14): the force is
    carried there by a second-order Taylor step.  A minimum on an end of the interval is
    returned as is.

    Parameters
    ----------
    tab : Tabulation
        Tabulation covering the interval.
    d_lo, d_hi : float
        The interval, :math:`d/\sigma`, ``d_lo < d_hi`` (the model searches from -3 to
        10 sigma beyond the end of the asperities' stable branch).
    grid, P : ndarray, optional
        A grid over the interval and the force on it, to reuse (both or neither).
    dP : ndarray, optional
        :math:`d\bar P/d\bar d` on ``grid``, to start Newton's method closer (with ``grid``).

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
    if dP is not None and grid is None:
        raise ValueError("dP needs grid and P: give grid and P (and optionally dP), or none of them")
    if grid is not None:
        grid, P = check_1d(grid, "grid"), check_1d(P, "P")
        if not (grid.size == P.size >= 2 and np.all(np.diff(grid) > 0)):
            raise ValueError("grid must be increasing, with P of its length (at least 2 points)")
        if dP is not None:
            dP = check_1d(dP, "dP")
            if dP.size != grid.size:
                raise ValueError(f"dP must have the length of grid ({grid.size}), got {dP.size}")
    if not tab.params.adhesive:
        return PullOff(0.0, math.nan, False)
    if grid is None:
        grid = np.linspace(d_lo, d_hi, int(min(4000, round((d_hi - d_lo) / 0.05))) + 1)
        P, dP = (s[:, 1] for s in tab.sums(grid, order=1))
    i = int(np.argmin(P))
    if P[i] >= 0.0:
        return PullOff(0.0, math.nan, False)
    if i in (0, grid.size - 1):
        return PullOff(float(-P[i]), float(grid[i]), True)
    # Newton on dP/dd = 0 inside the grid bracket, from the Hermite minimum if dP is known.
    a, b = grid[i - 1], grid[i + 1]
    x = grid[i] if dP is None else _hermite_minimum(grid[i - 1:i + 2], P[i - 1:i + 2], dP[i - 1:i + 2])
    for _ in range(50):
        s0, s1, s2 = (s[0, 1] for s in tab.sums(np.array([x]), order=2))
        if s1 > 0:
            b = x
        else:
            a = x
        step = -s1 / s2 if s2 > 0 else math.nan
        if abs(step) <= 1e-7 * max(1.0, abs(x)) and a <= x + step <= b:
            P_min = float(s0 + step * (s1 + 0.5 * step * s2))  # error ~ step^3
            x = x + step
            break
        x = x + step if a < x + step < b else 0.5 * (a + b)
    else:  # pragma: no cover - bisection converges well within 50 steps
        P_min = float(tab.sums(np.array([x]))[0][0, 1])
    return PullOff(max(0.0, -P_min), float(x), bool(P_min < 0))


def _hermite_minimum(x, P, dP):
    """Minimum of the cubic Hermite interpolant of (x, P, dP) on the two intervals of three
    points whose middle one is the smallest: a root of the quadratic dH/dx, else x[1]."""
    j = 0 if dP[1] > 0 else 1  # the interval where dP changes sign
    x0, h = x[j], x[j + 1] - x[j]
    p0, p1, m0, m1 = P[j], P[j + 1], dP[j] * h, dP[j + 1] * h
    # H(s) = c3 s^3 + c2 s^2 + m0 s + p0 on s in [0, 1]; H'(s) = 3 c3 s^2 + 2 c2 s + m0.
    c3 = 2.0 * (p0 - p1) + m0 + m1
    c2 = 3.0 * (p1 - p0) - 2.0 * m0 - m1
    qa, qb, qc = 3.0 * c3, 2.0 * c2, m0
    disc = qb * qb - 4.0 * qa * qc
    if disc < 0:
        return float(x[1])
    # The root where H'' > 0, written without cancellation.
    q = -0.5 * (qb + math.copysign(math.sqrt(disc), qb))
    roots = [r for r in ((q / qa) if qa != 0 else math.nan, (qc / q) if q != 0 else math.nan)
             if 0.0 <= r <= 1.0 and 6.0 * c3 * r + 2.0 * c2 > 0]
    return float(x0 + h * roots[0]) if roots else float(x[1])
