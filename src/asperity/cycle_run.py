r"""The algorithms behind :func:`asperity.cycle.cycle` and :func:`asperity.cycle.preload_curve`.

:func:`compute_cycle` and :func:`compute_preload_curve` work on a
:class:`~asperity.cycle_integrals.CycleIntegrals` (one parameter set's cached tables), so a
physical contact or a sweep reuses them: validation of the cycle's inputs, the path, both
branches, the loop integrals, the pull-off on retraction and, with a spring, the measured path
(:mod:`asperity.instrument`).  Units are the model's, per asperity (:mod:`asperity.cycle`).

References
----------
.. [1] K. N. G. Fuller, D. Tabor, Proc. R. Soc. A 345 (1975) 327.
.. [2] Adams et al., Eqs (6), (10), (18), (21), Table 1.
"""

from __future__ import annotations

import dataclasses
import math
import warnings

import numpy as np

from ._validation import as_float_array, check_1d, scalar
from ._warnings import AsperityWarning, frames_to_user
from .cycle_integrals import CycleIntegrals, chebyshev_points
from .cycle_result import BranchCurve, CycleResult, PreloadCurve
from .cycle_search import closest_approach, first_zero, retract_pull_off
from .instrument import Jump, base_displacement, check_stiffness, jump_energy, spring_path
from .load_control import PullOff
from .multi_asperity import friction_coefficient, mean_pressure
from .tabulation import D_MIN

__all__ = ["compute_cycle", "compute_preload_curve", "MAX_POINTS"]

#: Largest number of points per branch (``n``) or of preloads.
MAX_POINTS = 10**6
_CHUNK = 2000  # preloads searched together


# -- validation ----------------------------------------------------------------------------
def _parameters(ci: CycleIntegrals) -> dict:
    """The model's inputs and the jump-in penetration, as a flat dict."""
    p = dataclasses.asdict(ci.params)
    p["friction"] = repr(ci.params.friction)
    p["u_in"] = ci.u_in
    return p


def _scalar(value, name):
    return float(scalar(as_float_array(value, name), name))


def _check_points(n):
    if isinstance(n, bool) or not isinstance(n, int | np.integer) or not 2 <= n <= MAX_POINTS:
        raise ValueError(f"n (points per branch) must be an integer in [2, {MAX_POINTS}], got {n!r}")
    return int(n)


def _check_d_max(ci: CycleIntegrals, d_max) -> float:
    m = ci.model
    if d_max is None:
        return m.d_search
    d_max = _scalar(d_max, "d_max")
    if not D_MIN < d_max <= m.d_top:
        raise ValueError(f"d_max (start and end of the cycle, d/sigma) must lie in ({D_MIN:g}, {m.d_top:.6g}], "
                         f"got {d_max!r}")
    return d_max


def _turning_point(ci: CycleIntegrals, d_min, preload, d_max: float) -> float:
    if (d_min is None) == (preload is None):
        raise ValueError("give exactly one of d_min (closest approach, d/sigma) and preload (largest "
                         "compressive load, P/(N G b^2))")
    if d_min is not None:
        d_min = _scalar(d_min, "d_min")
        if not D_MIN <= d_min < d_max:
            raise ValueError(f"d_min (closest approach) must lie in [{D_MIN:g}, d_max) = [{D_MIN:g}, {d_max:.6g}): "
                             f"below the start of the cycle; got {d_min!r}")
        return d_min
    P = _scalar(preload, "preload")
    if not P > 0:
        raise ValueError(f"preload (largest compressive load, P/(N G b^2)) must be > 0 (compressive), got {preload!r}")
    return float(closest_approach(ci, np.array([P]), d_max)[0])


def _path_grid(d_min: float, d_max: float, reach: float, n: int):
    """``n`` separations from d_min to d_max, a quarter (at least) in the transition zone."""
    d_j = d_min + reach
    if reach <= 0 or d_j >= d_max or n < 3:
        return np.linspace(d_min, d_max, n)
    m = int(np.clip(round(n * reach / (d_max - d_min)), max(2, n // 4), n - 1))
    zone = d_min + reach * chebyshev_points(m)
    return np.concatenate([zone, np.linspace(d_j, d_max, n - m + 1)[1:]])


# -- the cycle -----------------------------------------------------------------------------
def _branch(ci: CycleIntegrals, name, d, sums, stiffness, jump, parameters) -> BranchCurve:
    contacts, P, F, area = (sums[:, i] for i in range(4))
    plastic = ci.law.plastic_fraction(d, ci.heights) if hasattr(ci.law, "plastic_fraction") else None
    return BranchCurve(d=d, P=P, F=F, mu=friction_coefficient(F, P), area=area, plastic=plastic,
                       pressure=mean_pressure(P, area, ci.params.nu), contacts=contacts, parameters=parameters,
                       d_base=base_displacement(d, P, stiffness), jump=jump, branch=name,
                       spring=not math.isinf(stiffness))


def compute_cycle(ci: CycleIntegrals, *, d_min=None, preload=None, d_max=None, d=None, n=200,
                  stiffness=math.inf) -> CycleResult:
    r"""One approach-retract cycle on cached integrals: the algorithm behind :func:`cycle`.

    Builds the path (``n`` separations from :math:`\bar d_{min}` to :math:`\bar d_{max}`, at least
    a quarter of them in the transition zone) or takes ``d``, evaluates both branches
    (:meth:`~asperity.cycle_integrals.CycleIntegrals.approach_sums`, ``retract_sums``), the loop
    integrals (energy, friction hysteresis), the pull-off on retraction
    (:func:`~asperity.cycle_search.retract_pull_off`) and, with a finite ``stiffness``, the measured
    path and its jumps (:func:`~asperity.instrument.spring_path`).

    .. math::
        E = -\int_{\bar u_c}^{\bar u_{in}}\bar P(\bar u)\big[\bar\Phi(\bar d_{min}+\bar u_{in})
            - \bar\Phi(\bar d_{max}+\bar u)\big]d\bar u + \sum_{jumps}\Delta E

    Parameters
    ----------
    ci : CycleIntegrals
        The parameter set's integrals (a :class:`~asperity.curves.Model` and :math:`\bar u_{in}`).
    d_min : float, optional
        Closest approach :math:`d/\sigma`, in :math:`[-10^4, \bar d_{max})`.
    preload : float, optional
        Largest compressive load :math:`P/(NGb^2) > 0`; exactly one of ``d_min`` and ``preload``.
    d_max : float, optional
        Start and end of the cycle (default :math:`10 - \bar u_{end}`), at most :math:`30 - \bar u_{end}`.
    d : array_like, optional
        Separations in :math:`[\bar d_{min}, \bar d_{max}]` instead of the path (displacement control).
    n : int
        Points per branch on the path, in [2, 10^6] (default 200).
    stiffness : float
        Spring :math:`\bar k = k\sigma/(NGb^2)` in (0, inf] (default inf: displacement control).

    Returns
    -------
    CycleResult
        As :func:`cycle`.

    Raises
    ------
    ValueError
        As :func:`cycle`.

    Examples
    --------
    >>> from asperity.curves import Model
    >>> ci = CycleIntegrals(Model(0.01, 1000.0, 1e-3))
    >>> a, b = compute_cycle(ci, d_min=0.0, n=20), compute_cycle(ci, d_min=1.0, n=20)  # one cache, two cycles
    >>> bool(a.energy > b.energy > 0)
    True

    References
    ----------
    Fuller & Tabor (1975); Adams et al., Eqs (6), (10), (18), (21).
    """
    d_max = _check_d_max(ci, d_max)
    k = check_stiffness(stiffness)
    n = _check_points(n)
    d_min = _turning_point(ci, d_min, preload, d_max)
    parameters = _parameters(ci)
    if d is not None:
        if not math.isinf(k):
            raise ValueError("d (separations) evaluates the displacement-controlled branches; with a finite "
                             "stiffness the measured path is computed: give n instead of d")
        d = check_1d(d, "d")
        if d.size > MAX_POINTS:
            raise ValueError(f"d (separations) must hold at most {MAX_POINTS} values, got {d.size}")
        if np.any((d < d_min) | (d > d_max)):
            raise ValueError(f"d (separations) must lie in [d_min, d_max] = [{d_min:.6g}, {d_max:.6g}], got values "
                             f"from {d.min():g} to {d.max():g}")
        grid = d
    else:
        grid = _path_grid(d_min, d_max, ci.reach, n)
    spring = not math.isinf(k)
    app = ci.approach_sums(grid, int(spring))
    ret = ci.retract_sums(grid, d_min, int(spring))
    zeros = (_zero_load(lambda x: ci.approach_sums(x, 1), grid[::-1], app[0][::-1]),
             _zero_load(lambda x: ci.retract_sums(x, d_min, 1), grid, ret[0]))
    loop = ci.loop([d_min], d_max)[0]
    jumps: list[Jump] = []
    if not spring:
        no_jump = np.zeros(grid.size, dtype=bool)
        order = slice(None, None, -1) if d is None else slice(None)
        approach = _branch(ci, "approach", grid[order], app[0][order], k, no_jump, parameters)
        retract = _branch(ci, "retract", grid, ret[0], k, no_jump, parameters)
        po = retract_pull_off(ci, np.array([d_min]), d_max)[0]
    else:
        approach, retract, jumps = _measured(ci, grid, app, ret, d_min, k, parameters)
        po = _measured_pull_off(ci, retract, jumps, d_min, d_max)
    lost = sum(j.energy for j in jumps)
    if hasattr(ci.law, "plastic_fraction") and np.any(approach.plastic > 0):
        name = getattr(ci.law, "name", type(ci.law).__name__)
        warnings.warn(f"the {name} law has no unloading: the retraction retraces the approach as if the "
                      f"asperities had not yielded (up to {100 * np.max(approach.plastic):.3g} % of all the asperities "
                      f"past the critical interference), so the loop dissipates no plastic work; the energy and "
                      f"pull-off are those of a reversible contact", AsperityWarning, stacklevel=1 + frames_to_user())
    return CycleResult(
        approach=approach, retract=retract, pull_off=po, energy=float(-loop[1] + lost),
        loop_energy=ci.loop_energy(), loop_fraction=float(ci.loop_fraction(d_min, d_max)), jump_energy=float(lost),
        friction_hysteresis=float(loop[2]), friction_zero_load=zeros, d_min=d_min, d_max=d_max,
        preload=float(ci.approach_sums([d_min])[0][0, 1]), stiffness=k, u_in=ci.u_in, u_end=ci.u_end,
        jumps=tuple(jumps), parameters=parameters)


def _zero_load(sums_at, d, sums) -> float:
    """Friction where the force first changes sign along a path (NaN if it does not)."""
    _, row = first_zero(sums_at, d, sums[:, 1])
    return math.nan if row is None else float(row[2])


def _rows(points, grid, sums, fn):
    """The four integrals at ``points``: from ``sums`` (on ``grid``) where a point is a grid point,
    from ``fn(x)`` elsewhere."""
    i = np.clip(np.searchsorted(grid, points), 0, grid.size - 1)
    known = grid[i] == points
    out = np.empty((points.size, 4))
    out[known] = sums[i[known]]
    if not np.all(known):
        out[~known] = fn(points[~known])
    return out


def _measured(ci: CycleIntegrals, grid, app, ret, d_min: float, k: float, parameters):
    """The branches as a spring of stiffness k measures them: visited points and jumps.

    ``app`` and ``ret`` are ``[S_0, S_1]`` on the (increasing) ``grid``.
    """
    d_top = ci.model.d_top

    def f_app(x, order):
        s = ci.approach_sums(x, order)
        return s[0][:, 1], (s[1][:, 1] if order else None)

    def f_ret(x, order):
        s = ci.retract_sums(x, d_min, order)
        return s[0][:, 1], (s[1][:, 1] if order else None)

    def beyond_top(x):  # a jump out lands beyond d_top, where every integral is 0
        out = np.zeros((x.size, 4))
        inside = x <= d_top
        out[inside] = ci.retract_sums(x[inside], d_min)[0]
        return out

    d_j = d_min + ci.reach
    down = slice(None, None, -1)
    pts_a, jump_a, jumps = spring_path(grid[down], app[0][down, 1], app[1][down, 1], app[1][down, 1], k, f_app,
                                       branch="approach")
    left = ret[1][:, 1].copy()
    kink = np.flatnonzero(grid == d_j) if ci.reach > 0 else np.array([], dtype=int)
    if kink.size:
        left[kink] = ci.zone_sums(grid[kink], d_min, order=1)[1][:, 1]
    pts_r, jump_r, more = spring_path(grid, ret[0][:, 1], left, ret[1][:, 1], k, f_ret, branch="retract",
                                      d_top=d_top)
    jumps = [dataclasses.replace(j, energy=jump_energy(j, f_app, k)) for j in jumps]
    jumps += [dataclasses.replace(j, energy=jump_energy(j, f_ret, k, kinks=(d_j,), d_top=d_top)) for j in more]
    approach = _branch(ci, "approach", pts_a, _rows(pts_a, grid, app[0], lambda x: ci.approach_sums(x)[0]), k, jump_a,
                       parameters)
    retract = _branch(ci, "retract", pts_r, _rows(pts_r, grid, ret[0], beyond_top), k, jump_r, parameters)
    return approach, retract, jumps


def _measured_pull_off(ci, retract: BranchCurve, jumps, d_min: float, d_max: float) -> PullOff:
    """The most tensile force on the measured retraction: the displacement-controlled pull-off if
    the path visits it, else the most tensile visited point (e.g. right before a jump out)."""
    po = retract_pull_off(ci, np.array([d_min]), d_max)[0]
    gaps = [sorted((j.d_from, j.d_to)) for j in jumps if j.branch == "retract"]
    if po.exists and not any(lo < po.d < hi for lo, hi in gaps):
        return po
    i = int(np.argmin(retract.P))
    P = float(retract.P[i])
    return PullOff(-P, float(retract.d[i]), True) if P < 0 else PullOff(0.0, math.nan, False)


def compute_preload_curve(ci: CycleIntegrals, preload, *, d_max=None) -> PreloadCurve:
    r"""Pull-off force and energy dissipated against preload on cached integrals: the algorithm
    behind :func:`preload_curve`.

    The closest approach of every preload by one load inversion on the approach branch
    (:func:`~asperity.cycle_search.closest_approach`), then the retraction pull-off
    (:func:`~asperity.cycle_search.retract_pull_off`) and the loop integrals for all of them, in
    blocks of 2000 preloads.

    .. math::
        P^{app}(\bar d_{min}) = P_{pre},\qquad
        P_{off} = \max\Big(0, -\min_{\bar d\ge\bar d_{min}}\bar P^{ret}(\bar d;\bar d_{min})\Big)

    Parameters
    ----------
    ci : CycleIntegrals
        The parameter set's integrals.
    preload : array_like
        Preloads :math:`P/(NGb^2)`, finite and > 0; at most 10^6 of them.
    d_max : float, optional
        Start and end of each cycle (default :math:`10 - \bar u_{end}`).

    Returns
    -------
    PreloadCurve
        As :func:`preload_curve`.

    Raises
    ------
    ValueError
        As :func:`preload_curve`.

    Examples
    --------
    >>> from asperity.curves import Model
    >>> pc = compute_preload_curve(CycleIntegrals(Model(0.003, 1000.0, 1e-3)), [1.0, 1e6])
    >>> bool(pc.pull_off[0] < pc.pull_off[1])
    True

    References
    ----------
    Fuller & Tabor (1975); Adams et al., Eq (18), Table 1.
    """
    d_max = _check_d_max(ci, d_max)
    P = check_1d(preload, "preload")
    if P.size > MAX_POINTS:
        raise ValueError(f"preload must hold at most {MAX_POINTS} values, got {P.size}")
    if np.any(P <= 0):
        raise ValueError(f"preload (largest compressive loads, P/(N G b^2)) must be > 0 (compressive); got min "
                         f"{P.min():g}")
    d_min = closest_approach(ci, P, d_max)
    pos, loop = [], np.empty((P.size, 4))
    for start in range(0, P.size, _CHUNK):  # bounded memory for long preload lists
        part = slice(start, start + _CHUNK)
        pos += retract_pull_off(ci, d_min[part], d_max)
        loop[part] = ci.loop(d_min[part], d_max)
    return PreloadCurve(preload=P, d_min=d_min, pull_off=np.array([p.force for p in pos]),
                        d_pull_off=np.array([p.d for p in pos]), energy=-loop[:, 1],
                        loop_fraction=np.asarray(ci.loop_fraction(d_min, d_max), dtype=float),
                        friction_hysteresis=loop[:, 2], d_max=d_max, u_in=ci.u_in, parameters=_parameters(ci))
