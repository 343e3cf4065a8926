r"""Approach and retract: loading-unloading hysteresis, energy dissipated, pull-off against preload.

The paper's force (Eq 18) counts every asperity down to the end of its stable branch: the
surface pulled away after full contact.  An experiment (AFM colloidal probe, SFA, MEMS
stiction test) is a cycle :math:`\bar d_{max} \to \bar d_{min} \to \bar d_{max}`.  On approach an
asperity carries nothing until it touches (penetration :math:`\bar u_{in}`, default 0); on
retraction it stays stuck, tensile, until its branch ends at :math:`\bar u_{end} < 0`.  The
two curves differ (Fuller & Tabor 1975, here with Maugis-Dugdale asperities), the loop between
them is energy dissipated, and the pull-off force on retraction grows with the preload until
it reaches the paper's (Table 1).  The integrals are in :mod:`asperity.cycle_integrals`, the
searches in :mod:`asperity.cycle_search`, the instrument's spring in :mod:`asperity.instrument`.

* :func:`cycle`: one cycle (from a closest approach ``d_min`` or a ``preload``), with the
  approach and retract curves, the pull-off on retraction, the energy dissipated, the friction
  hysteresis and, with a finite ``stiffness``, the measured curve with its jumps.
* :func:`preload_curve`: pull-off force and energy dissipated against preload, in one call.

The module itself is callable: ``asperity.cycle(alpha, beta, gamma, d_min=...)`` is
:func:`cycle` (``from asperity.cycle import cycle`` works as well).

Everything is per asperity and dimensionless as in :mod:`asperity.curves`: forces in
:math:`NGb^2`, separations in :math:`\sigma`, energies in :math:`NGb^2\sigma`.

References
----------
.. [1] K. N. G. Fuller, D. Tabor, Proc. R. Soc. A 345 (1975) 327.
.. [2] D. Maugis, J. Colloid Interface Sci. 150 (1992) 243; D. Maugis, Contact, Adhesion and
   Rupture of Elastic Solids, Springer (2000).
.. [3] K. L. Johnson, J. A. Greenwood, J. Colloid Interface Sci. 192 (1997) 326.
.. [4] J. A. Greenwood, Tribol. Lett. 65 (2017) 159.
.. [5] Adams et al., Eqs (6), (10), (18), (21), Table 1.
"""

from __future__ import annotations

import dataclasses
import math
import sys
import types

import numpy as np

from ._validation import as_float_array, scalar
from .asperity_law import ContactLaw
from .curves import Model
from .cycle_integrals import CycleIntegrals, chebyshev_points
from .cycle_result import BranchCurve, CycleResult, PreloadCurve
from .cycle_search import closest_approach, first_zero, retract_pull_off
from .heights import GAUSSIAN
from .instrument import Jump, base_displacement, check_stiffness, jump_energy, spring_path
from .load_control import PullOff
from .multi_asperity import friction_coefficient, mean_pressure
from .tabulation import D_MIN

__all__ = ["BranchCurve", "CycleResult", "PreloadCurve", "cycle", "preload_curve", "compute_cycle",
           "compute_preload_curve", "MAX_POINTS"]

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
    return BranchCurve(d=d, P=P, F=F, mu=friction_coefficient(F, P), area=area,
                       pressure=mean_pressure(P, area, ci.params.nu), contacts=contacts, parameters=parameters,
                       d_base=base_displacement(d, P, stiffness), jump=jump, branch=name,
                       spring=not math.isinf(stiffness))


def compute_cycle(ci: CycleIntegrals, *, d_min=None, preload=None, d_max=None, d=None, n=200,
                  stiffness=math.inf) -> CycleResult:
    """One cycle on the integrals ``ci`` (see :func:`cycle` for the parameters and the result)."""
    d_max = _check_d_max(ci, d_max)
    k = check_stiffness(stiffness)
    n = _check_points(n)
    d_min = _turning_point(ci, d_min, preload, d_max)
    parameters = _parameters(ci)
    if d is not None:
        if not math.isinf(k):
            raise ValueError("d (separations) evaluates the displacement-controlled branches; with a finite "
                             "stiffness the measured path is computed: give n instead of d")
        d = as_float_array(d, "d").ravel()
        if d.size > MAX_POINTS or np.any((d < d_min) | (d > d_max)):
            raise ValueError(f"d (separations) must lie in [d_min, d_max] = [{d_min:.6g}, {d_max:.6g}] (at most "
                             f"{MAX_POINTS} values), got values from {d.min():g} to {d.max():g}")
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


def cycle(alpha, beta, gamma=0.0, *, d_min=None, preload=None, d_max=None, d=None, n=200, stiffness=math.inf,
          u_in=0.0, nu=0.3, h_over_b=1.0, friction=None, heights=GAUSSIAN,
          law: ContactLaw | None = None) -> CycleResult:
    r"""One approach-retract cycle :math:`\bar d_{max} \to \bar d_{min} \to \bar d_{max}`: curves, pull-off, energy.

    With :math:`\bar u = \bar z - \bar d` (:mod:`asperity.cycle_integrals`): on approach the
    asperities with :math:`\bar u \ge \bar u_{in}` touch; on retraction those that touched
    (:math:`\bar z \ge \bar d_{min} + \bar u_{in}`) and have :math:`\bar u \ge \bar u_{end}`.

    .. math::
        \bar P^{app}(\bar d) = \int_{\bar u_{in}}^\infty\bar P(\bar u)\phi\,d\bar u,\quad
        \bar P^{ret}(\bar d) = \int_{\max(\bar u_{end},\,\bar u_{in}+\bar d_{min}-\bar d)}^\infty
            \bar P(\bar u)\phi\,d\bar u,\quad
        E = \int_{\bar d_{min}}^{\bar d_{max}}(\bar P^{app} - \bar P^{ret})\,d\bar d

    (and the same for F, area, contacts).  With a spring of stiffness :math:`\bar k` the measured
    curve is the force against the base displacement :math:`\bar Z = \bar d - \bar P/\bar k`, with
    whole-surface jumps where :math:`d\bar P/d\bar d > \bar k` (:mod:`asperity.instrument`).

    Parameters
    ----------
    alpha, beta : float
        Roughness :math:`\alpha = (\sigma/R)^{1/2} > 0` and friction regime parameter
        :math:`\beta = (R\sigma)^{1/2}/b > 0` (Eq 7).
    gamma : float
        Adhesion parameter :math:`\gamma = w/(E^*b) \ge 0` (Eq 16); 0 (Hertz): no hysteresis.
    d_min : float, optional
        Closest approach :math:`d/\sigma`, in :math:`[-10^4, \bar d_{max})`.
    preload : float, optional
        Largest compressive load :math:`P/(NGb^2) > 0`, reached at the closest approach (on the
        approach branch).  Give exactly one of ``d_min`` and ``preload``.
    d_max : float, optional
        Start and end of the cycle, :math:`d/\sigma` (default: 10 beyond the end of the stable
        branch, :math:`10 - \bar u_{end}`, where every asperity's loop is closed), at most
        :math:`30 - \bar u_{end}`.
    d : array_like, optional
        Separations in :math:`[\bar d_{min}, \bar d_{max}]` at which to evaluate both branches
        instead of the path (displacement control only).
    n : int
        Points per branch on the path (default 200, at least a quarter of them in the transition
        zone :math:`[\bar d_{min}, \bar d_{min} + \bar u_{in} - \bar u_{end}]`).
    stiffness : float
        Instrument spring :math:`\bar k = k\sigma/(NGb^2) > 0`; ``inf`` (default): displacement control.
    u_in : float
        Penetration :math:`\bar u_{in}` in :math:`[\bar u_{end}, 0]` at which an approaching asperity
        jumps into contact (default 0: first touch; :math:`\bar u_{end}` gives the paper's
        hysteresis-free reading).
    nu : float
        Poisson's ratio, -1 < nu < 0.5 (default 0.3; the paper does not state it).
    h_over_b : float
        Dugdale range over Burgers vector :math:`h/b > 0` (Eq 15; default 1).
    friction : FrictionLaw, optional
        Single-asperity friction law (default: Hurtado-Kim with the paper's constants).
    heights : HeightDistribution
        Asperity heights (default: ``Gaussian()``, Eq 19).
    law : ContactLaw, optional
        Per-asperity law built for these parameters (default: ``AsperityLaw``).

    Returns
    -------
    CycleResult
        ``approach`` and ``retract`` curves (all the columns of a curve, ``d_base``, ``jump``),
        ``pull_off`` on retraction, ``energy`` (:math:`NGb^2\sigma`), ``loop_energy``,
        ``loop_fraction``, ``jump_energy``, ``friction_hysteresis``, ``friction_zero_load``, ``jumps``.

    Raises
    ------
    ValueError
        If a parameter is out of its range: ``d_min`` not below ``d_max``, a non-positive or
        non-numeric ``stiffness``, a ``preload`` that is not compressive or needs a separation
        beyond the model's domain, ``u_in`` outside :math:`[\bar u_{end}, 0]`, both or neither
        of ``d_min`` and ``preload``, ``d`` outside :math:`[\bar d_{min}, \bar d_{max}]` or with a
        finite stiffness, or a ``d_min`` inside a jump of the spring.

    Examples
    --------
    >>> c = cycle(0.01, 1000.0, 1e-3, d_min=0.0, n=50)
    >>> bool(c.energy > 0), bool(c.retract.P[-1] <= c.approach.P[0] + 1e-12), c.pull_off.exists
    (True, True, True)

    References
    ----------
    Fuller & Tabor (1975); Maugis (1992); Johnson & Greenwood (1997); Greenwood (2017);
    Adams et al., Eqs (6), (10), (18), (21).
    """
    model = Model(alpha, beta, gamma, nu=nu, h_over_b=h_over_b, friction=friction, heights=heights, law=law)
    return compute_cycle(CycleIntegrals(model, u_in), d_min=d_min, preload=preload, d_max=d_max, d=d, n=n,
                         stiffness=stiffness)


def compute_preload_curve(ci: CycleIntegrals, preload, *, d_max=None) -> PreloadCurve:
    """Pull-off and energy against preload on the integrals ``ci`` (see :func:`preload_curve`)."""
    d_max = _check_d_max(ci, d_max)
    P = as_float_array(preload, "preload").ravel()
    if P.size > MAX_POINTS or np.any(P <= 0):
        raise ValueError(f"preload (largest compressive loads, P/(N G b^2)) must be > 0 (compressive), at most "
                         f"{MAX_POINTS} values; got min {P.min():g}")
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


def preload_curve(preload, alpha, beta, gamma=0.0, *, d_max=None, u_in=0.0, nu=0.3, h_over_b=1.0, friction=None,
                  heights=GAUSSIAN, law: ContactLaw | None = None) -> PreloadCurve:
    r"""Pull-off force and energy dissipated against preload (displacement control), vectorised.

    For each preload :math:`P_{pre}` the closest approach :math:`\bar d_{min}` solves
    :math:`\bar P^{app}(\bar d_{min}) = P_{pre}`; then

    .. math::
        P_{off} = \max\Big(0, -\min_{\bar d_{min}\le\bar d\le\bar d_{max}}\bar P^{ret}(\bar d)\Big),\qquad
        E = -\int_{\bar u_c}^{\bar u_{in}}\bar P(\bar u)\big[\bar\Phi(\bar d_{min}+\bar u_{in})
            - \bar\Phi(\bar d_{max}+\bar u)\big]d\bar u,

    :math:`\bar u_c = \max(\bar u_{end}, \bar u_{in} - \bar d_{max} + \bar d_{min})`.  The pull-off
    rises from 0 and saturates at the paper's (:func:`asperity.pull_off`) once the preload pushes
    the whole transition zone below the paper's pull-off separation.

    Parameters
    ----------
    preload : array_like
        Preloads :math:`P/(NGb^2) > 0`, at most 10^6.
    alpha, beta, gamma : float
        Model parameters (Eqs 7, 16).
    d_max : float, optional
        Start and end of each cycle, :math:`d/\sigma` (default :math:`10 - \bar u_{end}`).
    u_in : float
        Jump-in penetration in :math:`[\bar u_{end}, 0]` (default 0).
    nu : float
        Poisson's ratio, -1 < nu < 0.5 (default 0.3; the paper does not state it).
    h_over_b : float
        Dugdale range over Burgers vector :math:`h/b > 0` (Eq 15; default 1).
    friction : FrictionLaw, optional
        Single-asperity friction law (default: Hurtado-Kim with the paper's constants).
    heights : HeightDistribution
        Asperity heights (default: ``Gaussian()``, Eq 19).
    law : ContactLaw, optional
        Per-asperity law built for these parameters (default: ``AsperityLaw``).

    Returns
    -------
    PreloadCurve
        ``preload``, ``d_min``, ``pull_off``, ``d_pull_off``, ``energy``, ``loop_fraction``,
        ``friction_hysteresis``, one per preload.

    Raises
    ------
    ValueError
        If a preload is not positive, is reached only beyond ``d_max``, or needs a separation
        below :math:`-10^4`; or a parameter is out of its range.

    Examples
    --------
    >>> pc = preload_curve([1.0, 1e3, 1e6], 0.003, 1000.0, 1e-3)
    >>> bool(pc.pull_off[0] <= pc.pull_off[1] <= pc.pull_off[2]), round(float(pc.pull_off[-1]), 1)
    (True, 320.1)

    References
    ----------
    Fuller & Tabor (1975); Greenwood (2017); Adams et al., Eq (18), Table 1.
    """
    model = Model(alpha, beta, gamma, nu=nu, h_over_b=h_over_b, friction=friction, heights=heights, law=law)
    return compute_preload_curve(CycleIntegrals(model, u_in), preload, d_max=d_max)


class _CallableModule(types.ModuleType):
    """This module, callable: ``asperity.cycle(...)`` is :func:`cycle` (the issue's spelling)."""

    def __call__(self, *args, **kwargs) -> CycleResult:
        return cycle(*args, **kwargs)


sys.modules[__name__].__class__ = _CallableModule
