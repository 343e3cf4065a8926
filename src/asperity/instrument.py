r"""The instrument's spring: measured force-displacement curves with whole-surface jumps.

An AFM cantilever or an SFA spring of stiffness :math:`k` holds one surface; its base is
moved.  At equilibrium the spring carries the contact force, so the base displacement
(measured like the separation, in :math:`\sigma`) is

.. math::
    \bar Z(\bar d) = \bar d - \frac{\bar P(\bar d)}{\bar k},
    \qquad \bar k = \frac{k\,\sigma}{N G b^2},

with :math:`\bar P(\bar d)` the force on the branch being travelled (approach or retraction,
:mod:`asperity.cycle_integrals`).  An equilibrium is stable while
:math:`d\bar Z/d\bar d = 1 - \bar P'(\bar d)/\bar k > 0`: where the contact's stiffness
:math:`\bar P'` (a tensile force growing with the separation) exceeds the spring's, the
whole surface jumps at fixed :math:`\bar Z` to the next stable equilibrium: into contact
on approach, out of it on retraction (the AFM jump-to-contact and jump-off-contact).
Quasi-statically the path visits, in the direction of travel, the separations where
:math:`\bar Z` reaches a new extreme (a new minimum on approach, a new maximum on
retraction); :func:`spring_path` finds them, the folds (:math:`d\bar Z/d\bar d = 0`, or a kink
where the slope changes sign) and the landing points (:math:`\bar Z(\bar d_b) = \bar Z_{fold}`).

A jump releases the energy

.. math::
    \Delta E = \int_{\bar d_a}^{\bar d_b} \big[\bar P(\bar d) - \bar k(\bar d - \bar Z_{fold})\big]\,d\bar d \;\ge 0,

the drop of the spring's and the contact's energy at fixed base; it is dissipated (cantilever
ring-down), and adds to the asperities' own loop losses.  :math:`\bar k = \infty` is
displacement control: :math:`\bar Z = \bar d`, no jumps.

References
----------
.. [1] J. N. Israelachvili, Intermolecular and Surface Forces, 3rd ed., Academic Press (2011),
   ch. 13 (force-measuring springs and their instability where the force gradient exceeds k).
.. [2] H.-J. Butt, B. Cappella, M. Kappl, Surf. Sci. Rep. 59 (2005) 1 (AFM force curves:
   jump-to-contact, jump-off-contact).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ._validation import as_float_array, check_broadcast, check_finite_result, scalar, ufunc_result
from .cycle_search import bracketed_roots
from .quadrature import gauss_legendre

__all__ = ["Jump", "UnstableClosestApproach", "STIFFNESS_MIN", "check_stiffness", "base_displacement", "spring_path",
           "jump_energy", "JUMP_RTOL", "JUMP_LEVELS", "JUMP_PANELS"]


@dataclass(frozen=True)
class Jump:
    """A whole-surface jump at fixed base displacement (model units: sigma, N G b^2).

    Attributes
    ----------
    branch : str
        ``'approach'`` (jump into contact) or ``'retract'`` (jump out of it).
    d_base : float
        Base displacement :math:`\\bar Z` where it happens.
    d_from, d_to : float
        Separation before and after.
    P_from, P_to : float
        Force :math:`P/(NGb^2)` before and after.
    energy : float
        Energy released, :math:`\\Delta E/(NGb^2\\sigma) \\ge 0`.
    """

    branch: str
    d_base: float
    d_from: float
    d_to: float
    P_from: float
    P_to: float
    energy: float

    def to_dict(self) -> dict:
        """The jump as a dict of plain values."""
        return {"branch": self.branch, "d_base": self.d_base, "d_from": self.d_from, "d_to": self.d_to,
                "P_from": self.P_from, "P_to": self.P_to, "energy": self.energy}


#: Softest spring handled, :math:`\bar k = k\sigma/(NGb^2)`: a softer one moves its base more than
#: 1e100 sigma per unit load, and the base positions overflow double precision.
STIFFNESS_MIN = 1e-100


class UnstableClosestApproach(ValueError):
    r"""The closest approach asked for is never a stable state through the spring: the approach
    jumps into contact from ``d_from`` past it.  Attributes in the model's units (``d_from``,
    ``d_min`` in :math:`\sigma`, ``stiffness`` in :math:`NGb^2/\sigma`), so that a caller in
    physical units can say the same in metres and N/m."""

    def __init__(self, d_from: float, d_min: float, stiffness: float, length: str = "", stiffness_unit: str = ""):
        super().__init__(d_from, d_min, stiffness, length, stiffness_unit)  # the args: it pickles and copies
        self.d_from, self.d_min, self.stiffness = float(d_from), float(d_min), float(stiffness)
        self.length, self.stiffness_unit = length, stiffness_unit

    def __str__(self) -> str:
        d = "d" if self.length else "d/sigma"
        return (f"the approach jumps into contact from {d} = {self.d_from:.6g}{self.length} at stiffness "
                f"{self.stiffness:.6g}{self.stiffness_unit}: its end d_min = {self.d_min:.6g}{self.length} is never "
                "a stable state; choose another d_min or give a preload")


def check_stiffness(stiffness) -> float:
    """``stiffness`` as a float in [:data:`STIFFNESS_MIN`, inf]; ValueError naming it otherwise."""
    number = (isinstance(stiffness, float | int | np.floating | np.integer)
              and not isinstance(stiffness, bool | np.bool_))
    if number and math.isinf(stiffness) and stiffness > 0:
        return math.inf
    if number and not stiffness >= STIFFNESS_MIN:  # -inf and NaN too: say what is valid, inf included
        raise ValueError(f"stiffness (instrument spring, k sigma/(N G b^2)) must be >= {STIFFNESS_MIN:g} (inf: "
                         f"displacement control; valid range {STIFFNESS_MIN:g} <= stiffness <= inf), got {stiffness!r}")
    k = float(scalar(as_float_array(stiffness, "stiffness"), "stiffness"))
    if not k >= STIFFNESS_MIN:
        raise ValueError(f"stiffness (instrument spring, k sigma/(N G b^2)) must be >= {STIFFNESS_MIN:g} (inf: "
                         f"displacement control; valid range {STIFFNESS_MIN:g} <= stiffness <= inf), got {stiffness!r}")
    return k


def _stiffness_array(stiffness) -> np.ndarray:
    """``stiffness`` as a float array in [:data:`STIFFNESS_MIN`, inf] (inf allowed element by element)."""
    try:
        raw = None if isinstance(stiffness, str) else np.asarray(stiffness)
    except (TypeError, ValueError):  # ragged lists and the like: as_float_array names them
        raw = None
    if raw is None or raw.dtype.kind not in "fiu" or raw.ndim == 0:
        return np.asarray(check_stiffness(float(raw) if isinstance(stiffness, np.ndarray) and raw.ndim == 0
                                          and raw.dtype.kind in "fiu" else stiffness))
    infinite = np.isposinf(raw)
    k = as_float_array(np.where(infinite, STIFFNESS_MIN, raw), "stiffness")
    if not (k >= STIFFNESS_MIN).all():
        bad = float(k[~(k >= STIFFNESS_MIN)][0])
        raise ValueError(f"stiffness (instrument spring, k sigma/(N G b^2)) must be >= {STIFFNESS_MIN:g} (inf: "
                         f"displacement control; valid range {STIFFNESS_MIN:g} <= stiffness <= inf), got {bad!r}")
    return np.where(infinite, np.inf, k)


def base_displacement(d, P, stiffness):
    r"""Base displacement :math:`\bar Z = \bar d - \bar P/\bar k` of a spring of stiffness :math:`\bar k`.

    .. math:: \bar Z = \bar d - \frac{\bar P}{\bar k}

    Parameters
    ----------
    d : array_like
        Separations :math:`d/\sigma`.
    P : array_like
        Forces :math:`P/(NGb^2)`, compressive > 0, broadcast with ``d``.
    stiffness : array_like
        :math:`\bar k = k\sigma/(NGb^2) \ge` :data:`STIFFNESS_MIN`; ``inf`` gives
        :math:`\bar Z = \bar d`.  Broadcast with ``d`` and ``P``.

    Returns
    -------
    ndarray or numpy.float64
        :math:`\bar Z` in :math:`\sigma`, the broadcast shape (a NumPy scalar for scalars).

    Raises
    ------
    ValueError
        If ``stiffness`` is not real or below :data:`STIFFNESS_MIN` (inf allowed), ``d``,
        ``P`` are not real and finite, or the shapes do not broadcast.

    Examples
    --------
    >>> base_displacement([1.0, 2.0], [10.0, -5.0], 10.0).tolist()
    [0.0, 2.5]

    References
    ----------
    Israelachvili (2011), ch. 13; Butt, Cappella & Kappl (2005).
    """
    k = _stiffness_array(stiffness)
    d = as_float_array(d, "d", allow_empty=True)
    P = as_float_array(P, "P", allow_empty=True)
    check_broadcast(d=d, P=P, stiffness=k)
    with np.errstate(over="ignore"):
        Z = d - np.where(np.isinf(k), 0.0, P) / k
    return ufunc_result(check_finite_result(Z, "the base displacement", d=d, P=P, stiffness=k))


def _folds_inside(gl, gr):
    """Indices i (path order) with a fold strictly between points i and i + 1: the stability
    ``1 - P'/k`` after point i is positive and before point i + 1 is not.  A fold at a kink (a
    path point where the slope changes sign) needs no refinement: the point is on the path."""
    return np.flatnonzero((gr[:-1] > 0) & (gl[1:] <= 0))


def spring_path(d, P, slope_left, slope_right, stiffness, force, *, branch, d_top=math.inf):
    r"""The separations a spring-held surface visits along one branch, with its jumps.

    Parameters
    ----------
    d : ndarray
        Separations of the branch in path order (decreasing on approach, increasing on
        retraction), 1-D, at least 2.
    P : ndarray
        Force :math:`P/(NGb^2)` there.
    slope_left, slope_right : ndarray
        :math:`dP/d\bar d` there, from below and from above (equal except at a kink).
    stiffness : float
        :math:`\bar k > 0`, finite.
    force : callable
        ``force(x, order)`` -> ``(P, dP/dd)`` arrays (``dP`` None for order 0) at separations
        ``x`` on the branch, strictly between path points.
    branch : str
        ``'approach'`` or ``'retract'``.
    d_top : float
        Separation beyond which every force underflows to 0: a jump out that has not landed
        before it lands at :math:`\bar d = \bar Z` (default inf).

    Returns
    -------
    points : ndarray
        Visited separations in path order (the path's points in stable stretches, plus the
        folds and landing points).
    jump : ndarray of bool
        True at a landing point: the step from the previous point is a jump.
    jumps : list of Jump
        The jumps (energy filled in by the caller, who can integrate across kinks).

    Raises
    ------
    ValueError
        If the approach ends inside a jump (its last separation is never a stable state).
    """
    k = float(stiffness)
    direction = -1.0 if branch == "approach" else 1.0
    d = np.asarray(d, dtype=float)
    P = np.asarray(P, dtype=float)
    gl, gr = 1.0 - slope_left / k, 1.0 - slope_right / k
    if direction < 0:  # in path order, "left" (before) of a point is the larger separation
        gl, gr = gr, gl
    inside = _folds_inside(gl, gr)
    # Refine the folds inside intervals: 1 - P'/k = 0.
    extra_d = []
    if inside.size:
        lo = np.minimum(d[inside], d[inside + 1])
        hi = np.maximum(d[inside], d[inside + 1])
        g_lo = np.where(direction > 0, gr[inside], gl[inside + 1])
        g_hi = np.where(direction > 0, gl[inside + 1], gr[inside])
        roots = bracketed_roots(lambda x: 1.0 - force(x, 1)[1] / k, lo, hi, g_lo, g_hi)
        extra_d = list(roots[(roots > lo) & (roots < hi)])
    pts = np.concatenate([d, extra_d])
    Ps = np.concatenate([P, force(np.array(extra_d), 0)[0]]) if extra_d else P.copy()
    order = np.argsort(direction * pts, kind="stable")
    pts, Ps = pts[order], Ps[order]
    Z = pts - Ps / k
    y = direction * Z  # rises along a stable stretch
    best = np.maximum.accumulate(y)
    visited = np.ones(pts.size, dtype=bool)
    visited[1:] = y[1:] > best[:-1]
    out_d, out_jump, jumps = [], [], []
    idx = np.flatnonzero(visited)
    for n, i in enumerate(idx):
        if n > 0 and i > idx[n - 1] + 1:  # a gap: land where Z returns to the fold's value
            a = idx[n - 1]
            Z_fold = Z[a]
            f_prev, f_here = Z[i - 1] - Z_fold, Z[i] - Z_fold
            if pts[i - 1] < pts[i]:
                lo, hi, f_lo, f_hi = pts[i - 1], pts[i], f_prev, f_here
            else:
                lo, hi, f_lo, f_hi = pts[i], pts[i - 1], f_here, f_prev
            x = bracketed_roots(_landing(force, k, Z_fold), np.array([lo]), np.array([hi]), np.array([f_lo]),
                                np.array([f_hi]))[0]
            P_to = float(force(np.array([x]), 0)[0][0])
            jumps.append(Jump(branch, float(Z_fold), float(pts[a]), float(x), float(Ps[a]), P_to, math.nan))
            out_d.append(x)
            out_jump.append(True)
        out_d.append(pts[i])
        out_jump.append(False)
    if not visited[-1] and idx[-1] < pts.size - 1:
        a = idx[-1]
        if direction < 0:
            raise UnstableClosestApproach(pts[a], pts[-1], k)
        x, P_to = _land_beyond(force, k, Z[a], pts[-1], d_top)
        jumps.append(Jump(branch, float(Z[a]), float(pts[a]), x, float(Ps[a]), P_to, math.nan))
        out_d.append(x)
        out_jump.append(True)
    return np.array(out_d), np.array(out_jump, dtype=bool), jumps


def _landing(force, k, Z_fold):
    def f(x):
        return x - force(x, 0)[0] / k - Z_fold
    return f


def _land_beyond(force, k, Z_fold, start, d_top):
    """Landing of a jump out beyond the path's last point: (d, P).  Beyond ``d_top`` every force
    underflows to 0, so a jump that has not landed there lands at d = Z_fold with P = 0."""
    f = _landing(force, k, Z_fold)
    lo, step = start, 1.0
    while lo < d_top:
        hi = min(lo + step, d_top)
        if f(np.array([hi]))[0] >= 0:
            x = bracketed_roots(f, np.array([lo]), np.array([hi]))[0]
            return float(x), float(force(np.array([x]), 0)[0][0])
        lo, step = hi, 2.0 * step
    return float(max(Z_fold, d_top)), 0.0


def jump_energy(jump: Jump, force, stiffness: float, kinks=(), d_top=math.inf) -> float:
    r"""Energy a jump releases, :math:`\int_{d_a}^{d_b}[\bar P - \bar k(\bar d - \bar Z)]\,d\bar d \ge 0`.

    Adaptive composite 16-point Gauss-Legendre: panels between consecutive kinks (4 each to
    start), each halved until its two halves agree with it to :data:`JUMP_RTOL` of the
    integral of :math:`|\bar P|` (a soft spring's jump crosses many sigma while the force
    of a narrow height distribution dies within a fraction of one: fixed panels lost 0.5 %
    there, found by a review); the branch's force from ``force(x, 0)``; beyond ``d_top``,
    where the force is 0, in closed form.
    """
    lo, hi = sorted((jump.d_from, jump.d_to))
    total = 0.0
    if hi > d_top:  # P = 0 there: int_{max(lo, d_top)}^{hi} -k (x - Z) dx
        top = max(lo, d_top)
        total -= 0.5 * stiffness * ((hi - jump.d_base) ** 2 - (top - jump.d_base) ** 2)
        hi = top
    if hi > lo:  # the spring's part is linear: exact on any panel
        total -= 0.5 * stiffness * ((hi - jump.d_base) ** 2 - (lo - jump.d_base) ** 2)
        edges = np.unique(np.concatenate([[lo, hi], [x for x in kinks if lo < x < hi]]))
        a = np.concatenate([np.linspace(p, q, 5)[:-1] for p, q in zip(edges[:-1], edges[1:], strict=True)])
        b = np.append(a[1:], hi)
        total += _adaptive_gauss(lambda x: force(x, 0)[0], a, b)
    return abs(total)


#: Relative tolerance of :func:`jump_energy`'s adaptive quadrature (of the integral of |P|), the
#: most halvings of a panel and the most panels refined at once (a bound on the work and memory).
JUMP_RTOL, JUMP_LEVELS, JUMP_PANELS = 1e-11, 40, 2**14


def _adaptive_gauss(f, a, b) -> float:
    r""":math:`\int f` over the panels ``[a_i, b_i]``, each halved until 16-point Gauss-Legendre
    on it and on its halves agree (vectorised over the panels of each level).  Values that are
    not finite are the result (NaN or infinity) at once: a review found a NaN force doubling
    the panels to 24 GB; past :data:`JUMP_PANELS` panels the rest are kept as they are."""
    x, w = gauss_legendre(16)

    def gl(lo, hi):
        nodes = lo[:, None] + (hi - lo)[:, None] * x[None, :]
        values = np.asarray(f(nodes.ravel()), dtype=float).reshape(nodes.shape)
        return (hi - lo) * (values @ w), (hi - lo) * (np.abs(values) @ w)

    coarse, scale = gl(a, b)
    if not np.all(np.isfinite(coarse)):
        return float(np.sum(coarse))  # NaN or infinity, which no refinement removes
    scale, total = float(np.sum(scale)), 0.0
    for level in range(JUMP_LEVELS):
        m = 0.5 * (a + b)
        left, right = gl(a, m)[0], gl(m, b)[0]
        fine = left + right
        done = np.abs(fine - coarse) <= JUMP_RTOL * max(scale, 1e-300) * (b - a) / max(float(np.sum(b - a)), 1e-300)
        done |= ~np.isfinite(fine)
        if level == JUMP_LEVELS - 1 or 2 * np.count_nonzero(~done) > JUMP_PANELS:
            done[:] = True
        total += float(np.sum(fine[done]))
        if np.all(done):
            break
        a, b = np.concatenate([a[~done], m[~done]]), np.concatenate([m[~done], b[~done]])
        coarse = np.concatenate([left[~done], right[~done]])
    return total
