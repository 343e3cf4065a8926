r"""Curves the paper reports: quantities versus separation, versus load, and pull-off.

:class:`Model` holds one parameter set and caches its tabulated per-asperity law, so a
user sweeping thousands of loads pays the set-up once.  The module-level functions
:func:`separation_curve`, :func:`load_curve` and :func:`pull_off` are one-line wrappers.

*Load control.*  With adhesion :math:`\bar P(\bar d)` is not monotone: it falls from
large compressive values, may turn tensile, reaches its most tensile value (the
pull-off force) and returns to zero as :math:`\bar d\to\infty`.  The equilibrium under
a given load is the first separation, coming from full contact, at which
:math:`\bar P(\bar d)` equals the load: the stable branch, :math:`d\bar P/d\bar d < 0`.
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field

import numpy as np

from ._csv import columns_to_csv, columns_to_dataframe
from ._validation import as_float_array
from ._validation import scalar as _scalar
from .asperity_law import AsperityLaw, ModelParameters
from .heights import GAUSSIAN, HeightDistribution
from .multi_asperity import (
    D_MAX,
    D_MIN,
    Tabulation,
    check_separation,
    friction_coefficient,
    mean_pressure,
)
from .quantities import CURVE_COLUMNS

__all__ = ["CurveResult", "PullOff", "Model", "separation_curve", "load_curve", "pull_off"]

#: Columns of a curve, in order, with their meaning (derived from :data:`asperity.quantities.CURVE_COLUMNS`).
COLUMNS = {name: q.meaning for name, q in CURVE_COLUMNS.items()}


@dataclass(frozen=True)
class CurveResult:
    """One curve: NumPy arrays of equal length, one per column of :data:`COLUMNS`."""

    d: np.ndarray
    P: np.ndarray
    F: np.ndarray
    mu: np.ndarray
    area: np.ndarray
    pressure: np.ndarray
    contacts: np.ndarray
    parameters: dict = field(default_factory=dict, compare=False)

    def __len__(self) -> int:
        return int(np.size(self.d))

    def columns(self) -> dict[str, np.ndarray]:
        """The curve as an ordered dict of column name -> array."""
        return {name: np.asarray(getattr(self, name)) for name in COLUMNS}

    def to_dataframe(self):
        """The curve as a :class:`pandas.DataFrame` (needs pandas: ``asperity[frame]``)."""
        return columns_to_dataframe(self.columns(), self.parameters)

    def to_csv(self, path_or_buffer=None) -> str | None:
        """Write CSV (a header line of column names, then rows); return it if no path."""
        return columns_to_csv(self.columns(), path_or_buffer)


@dataclass(frozen=True)
class PullOff:
    """Pull-off force (largest tensile force over separation) and where it occurs.

    ``force`` is :math:`|P|/(NGb^2)` >= 0; ``d`` is the separation of the most tensile
    force (NaN when ``exists`` is False: the force stays compressive for d <= d_max).
    """

    force: float
    d: float
    exists: bool

    def as_dict(self):
        return {"pull_off": self.force, "d": self.d, "exists": self.exists}


class Model:
    """The multi-asperity contact and friction model for one parameter set.

    Parameters
    ----------
    alpha, beta : float
        Roughness and friction-regime parameters (Eq 7), > 0.
    gamma : float
        Adhesion parameter (Eq 16), >= 0; 0 is Hertz without adhesion.
    nu : float
        Poisson's ratio, -1 < nu < 0.5 (default 0.3; the paper does not state it).
    h_over_b : float
        Dugdale range over Burgers vector (Eq 15; paper: 1).
    friction : FrictionLaw, optional
        Single-asperity friction law (default: Hurtado-Kim with the paper's constants).
    heights : HeightDistribution
        Asperity heights (default: Gaussian, Eq 19).

    Examples
    --------
    >>> m = Model(alpha=0.01, beta=1000, gamma=1e-3)
    >>> curve = m.load_curve([1.0, 10.0, 100.0])
    >>> bool(curve.mu[0] > curve.mu[-1])
    True
    """

    def __init__(self, alpha, beta, gamma=0.0, *, nu=0.3, h_over_b=1.0, friction=None,
                 heights: HeightDistribution = GAUSSIAN):
        kwargs = {} if friction is None else {"friction": friction}
        self.params = ModelParameters(alpha, beta, gamma, nu, h_over_b, **kwargs)
        if not isinstance(heights, HeightDistribution):
            raise ValueError("heights must be a HeightDistribution (e.g. asperity.GAUSSIAN)")
        self.heights = heights
        self.law = AsperityLaw(self.params)
        #: Largest valid separation: beyond it every quantity underflows.
        self.d_top = D_MAX - self.law.u_end
        #: Default reach of the pull-off search: 10 sigma past the end of the stable branch.
        self.d_search = 10.0 - self.law.u_end
        self._tab: Tabulation | None = None
        self._pull_off: dict[float, PullOff] = {}

    # -- tabulation -----------------------------------------------------------------
    def tabulation(self, d_min: float, d_max: float) -> Tabulation:
        """A tabulation serving [d_min, d_max], reusing (and widening) the cached one."""
        tab = self._tab
        if tab is not None and tab.covers(d_min, d_max):
            return tab
        if tab is not None:
            d_min, d_max = min(d_min, tab.d_min), max(d_max, tab.d_max)
        self._tab = Tabulation(self.params, d_min, d_max, self.heights, law=self.law)
        return self._tab

    def _parameters(self):
        p = asdict(self.params)
        p["friction"] = repr(self.params.friction)
        return p

    def _result(self, d, sums) -> CurveResult:
        contacts, P, F, area = (sums[:, i] for i in range(4))
        return CurveResult(d=d, P=P, F=F, mu=friction_coefficient(F, P), area=area,
                           pressure=mean_pressure(P, area, self.params.nu), contacts=contacts,
                           parameters=self._parameters())

    # -- curves ---------------------------------------------------------------------
    def separation_curve(self, d) -> CurveResult:
        """All quantities at separations ``d`` (Eqs 5, 6/18, 10, 21, 1)."""
        d = check_separation(d, d_max=self.d_top).ravel()
        tab = self.tabulation(float(d.min()), max(float(d.max()), 10.0))
        return self._result(d, tab.sums(d)[0])

    def pull_off(self, d_max: float | None = None) -> PullOff:
        """Largest tensile force over separations from -3 to ``d_max`` (Table 1, Fig 7).

        ``d_max`` defaults to :attr:`d_search`, 10 sigma beyond the end of the asperities'
        stable branch (10 - u_end; u_end = 0 without adhesion): far enough that the force
        there is a negligible remnant, whatever the adhesion range.
        """
        if d_max is None:
            d_max = self.d_search
        d_max = float(_scalar(d_max, "d_max"))
        if not 0.0 < d_max <= self.d_top:
            raise ValueError(f"d_max must lie in (0, {self.d_top:.6g}], got {d_max!r}")
        if d_max not in self._pull_off:
            self._pull_off[d_max] = self._find_pull_off(d_max)
        return self._pull_off[d_max]

    def _find_pull_off(self, d_max: float, grid=None, P=None) -> PullOff:
        """Most tensile force on [-3, d_max]: a grid (or the caller's, if it covers that range)
        locates the minimum, Newton on dP/dd = 0 refines it."""
        if not self.params.adhesive:
            return PullOff(0.0, math.nan, False)
        if grid is None:
            d_lo = -3.0
            grid = np.linspace(d_lo, d_max, int(min(4000, round((d_max - d_lo) / 0.02))) + 1)
            P = self.tabulation(d_lo, d_max).sums(grid)[0][:, 1]
        tab = self.tabulation(float(grid[0]), d_max)
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

    def load_curve(self, P) -> CurveResult:
        """All quantities at the stable separation for each normal load ``P`` = P/(NGb^2).

        Raises
        ------
        ValueError
            If a load is not positive without adhesion, or more tensile than the
            pull-off force with adhesion (no equilibrium exists).
        """
        P = as_float_array(P, "P").ravel()
        if not self.params.adhesive and np.any(P <= 0):
            raise ValueError("P (load) must be > 0 without adhesion (gamma = 0); "
                             f"got min {P.min():g}")
        d_hi = self.d_search
        d_lo = self._bracket_low(float(P.max()), d_hi)
        tab = self.tabulation(d_lo, d_hi)
        grid, Pg, dPg = self._grid(tab, d_lo, d_hi)
        i = int(np.argmin(Pg))
        if Pg[i] < 0:  # a pull-off force exists: the branch ends there; this grid locates it
            if d_hi not in self._pull_off:
                self._pull_off[d_hi] = self._find_pull_off(d_hi, grid, Pg)
            po = self._pull_off[d_hi]
            floor = -po.force
            grid, Pg, dPg = np.append(grid[:i], po.d), np.append(Pg[:i], floor), np.append(dPg[:i], 0.0)
        else:
            grid, Pg, dPg = grid[:i + 1], Pg[:i + 1], dPg[:i + 1]
            if P.min() < Pg[-1] and grid[-1] < self.d_top:  # tiny loads: the flat is far out
                tab = self.tabulation(d_lo, self.d_top)
                more, Pm, dPm = self._grid(tab, grid[-1], self.d_top, n=200)
                grid, Pg, dPg = (np.append(x, y[1:]) for x, y in ((grid, more), (Pg, Pm), (dPg, dPm)))
            floor = Pg[-1]
        if P.min() < floor:
            what = "minus the pull-off force" if floor < 0 else f"the force at d/sigma = {grid[-1]:.4g}"
            raise ValueError(f"P (load) must be >= {floor:.6g} ({what}): no equilibrium under a smaller "
                             f"load; got min {P.min():g}")
        d, sums = self._invert(tab, P, grid, Pg, dPg)
        sums[:, 1] = P  # solved for to rounding; report the load asked for
        return self._result(d, sums)

    @staticmethod
    def _grid(tab, d_lo, d_hi, n=None):
        """Separations from d_lo to d_hi with the force and its derivative there."""
        n = int(np.clip((d_hi - d_lo) / 0.05, 100, 800)) if n is None else n
        grid = np.linspace(d_lo, d_hi, n)
        g0, g1 = tab.sums(grid, order=1)
        return grid, g0[:, 1], g1[:, 1]

    def _bracket_low(self, P_max, d_hi):
        """A separation where the force exceeds every requested load."""
        p = self.params
        # Hertz estimate for d << 0: P ~ (8/3)/(1-nu) alpha beta^2 (-d)^(3/2), a lower bound
        # by Jensen's inequality; adhesion lowers the force a little, hence the margin.
        c = (8.0 / 3.0) / (1.0 - p.nu) * p.alpha * p.beta**2
        d_lo = min(-3.0, d_hi - 1.0, -((max(P_max, 0.0) / c) ** (2.0 / 3.0)) - 2.0)
        while True:
            if d_lo < D_MIN:
                raise ValueError(f"P (load) = {P_max:g} is too large: it needs a separation "
                                 f"below d/sigma = {D_MIN:g}")
            tab = self.tabulation(d_lo, d_hi)
            if tab.sums(np.array([d_lo]))[0][0, 1] > P_max:
                return d_lo
            d_lo = d_lo - max(2.0, 0.5 * abs(d_lo))

    @staticmethod
    def _initial_guess(P, grid, Pg, dPg):
        """Bracket [a, b] of the first crossing and a cubic-Hermite guess inside it.

        The interpolation runs in y = asinh(P/s), nearly log P, which is smooth over many
        decades of load, so Newton usually needs one step.
        """
        n = grid.size
        below = Pg[None, :] <= P[:, None]
        j = np.clip(np.argmax(below, axis=1), 1, n - 1)
        a, b = grid[j - 1].copy(), grid[j].copy()
        nonzero = np.abs(P[P != 0])
        s = max(1e-3 * (nonzero.min() if nonzero.size else np.abs(Pg).max()), 1e-300)
        y = np.arcsinh(P / s)
        ya, yb = np.arcsinh(Pg[j - 1] / s), np.arcsinh(Pg[j] / s)
        h = b - a
        ma = dPg[j - 1] / np.hypot(s, Pg[j - 1]) * h
        mb = dPg[j] / np.hypot(s, Pg[j]) * h
        with np.errstate(divide="ignore", invalid="ignore"):
            t = np.clip(np.where(ya != yb, (ya - y) / (ya - yb), 0.5), 0.0, 1.0)
            for _ in range(4):  # Newton on the Hermite cubic in t in [0, 1]
                t2, t3 = t * t, t * t * t
                H = ((2 * t3 - 3 * t2 + 1) * ya + (t3 - 2 * t2 + t) * ma
                     + (-2 * t3 + 3 * t2) * yb + (t3 - t2) * mb)
                dH = ((6 * t2 - 6 * t) * ya + (3 * t2 - 4 * t + 1) * ma
                      + (-6 * t2 + 6 * t) * yb + (3 * t2 - 2 * t) * mb)
                t = np.clip(np.where(dH != 0, t - (H - y) / dH, t), 0.0, 1.0)
        t = np.where(np.isfinite(t), t, 0.5)
        return a, b, a + h * t

    @classmethod
    def _invert(cls, tab, P, grid, Pg, dPg):
        """Separations with P(d) = P on the branch, and the four integrals there.

        Safeguarded Newton from the Hermite guess.  Once a step is below 1e-7 the
        integrals are carried to the new point by a first-order Taylor step (error
        ~1e-14 relative), which saves a final pass over the quadrature nodes.
        """
        a, b, x = cls._initial_guess(P, grid, Pg, dPg)
        d = np.empty_like(P)
        out = np.empty((P.size, 4))
        active = np.arange(P.size)
        for _ in range(80):
            if active.size == 0:
                break
            xa = x[active]
            s0, s1 = tab.sums(xa, order=1)
            r = s0[:, 1] - P[active]
            g = s1[:, 1]
            a[active] = np.where(r > 0, xa, a[active])
            b[active] = np.where(r < 0, xa, b[active])
            with np.errstate(divide="ignore", invalid="ignore"):
                step = np.where(g < 0, -r / g, np.nan)
            x_new = xa + step
            bad = ~np.isfinite(x_new) | (x_new < a[active]) | (x_new > b[active])
            x_new = np.where(bad, 0.5 * (a[active] + b[active]), x_new)
            done = ~bad & (np.abs(step) <= 1e-7 * np.maximum(1.0, np.abs(xa)))
            done |= (b[active] - a[active]) <= 1e-14 * np.maximum(1.0, np.abs(xa))
            step = np.where(bad, 0.0, step)
            fin = active[done]
            d[fin] = np.where(bad[done], xa[done], x_new[done])
            out[fin] = s0[done] + s1[done] * step[done, None]
            x[active] = x_new
            active = active[~done]
        if active.size:  # pragma: no cover - Newton with bisection always converges
            raise RuntimeError("load inversion did not converge")
        return d, out



def separation_curve(d, alpha, beta, gamma=0.0, *, nu=0.3, h_over_b=1.0, friction=None,
                     heights=GAUSSIAN) -> CurveResult:
    """Normal and friction force, mu, area, pressure and contacts versus separation.

    Parameters
    ----------
    d : array_like
        Separations :math:`d/\\sigma` (Figs 7-8).
    alpha, beta, gamma, nu, h_over_b, friction, heights :
        See :class:`Model`.

    Returns
    -------
    CurveResult

    References
    ----------
    Adams et al., Eqs (1), (5), (6), (10), (18), (21); Figs 7-8.
    """
    return Model(alpha, beta, gamma, nu=nu, h_over_b=h_over_b, friction=friction,
                 heights=heights).separation_curve(d)


def load_curve(P, alpha, beta, gamma=0.0, *, nu=0.3, h_over_b=1.0, friction=None,
               heights=GAUSSIAN) -> CurveResult:
    """All quantities at the stable separation for each load :math:`P/(NGb^2)` (Figs 3-6, 9).

    See :meth:`Model.load_curve`.
    """
    return Model(alpha, beta, gamma, nu=nu, h_over_b=h_over_b, friction=friction,
                 heights=heights).load_curve(P)


def pull_off(alpha, beta, gamma, *, nu=0.3, h_over_b=1.0, friction=None, heights=GAUSSIAN,
             d_max=None) -> PullOff:
    """Pull-off force :math:`|P|/(NGb^2)`: the largest tensile force for -3 <= d <= d_max (Table 1).

    See :meth:`Model.pull_off`.
    """
    return Model(alpha, beta, gamma, nu=nu, h_over_b=h_over_b, friction=friction,
                 heights=heights).pull_off(d_max)
