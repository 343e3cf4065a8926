r"""Load steps of the interacting and coalescing Hertzian asperity model.

At a load :math:`P` the rigid flat stands at :math:`d` above the mean plane of the map and
every asperity :math:`i` (height :math:`z_i`, radius :math:`R_i`) is compressed by

.. math::
    \delta_i = z_i - d - \sum_{j\ne i} u_j(\mathbf r_i) - u_i^{images},\qquad
    F_i = \tfrac43 E^* R_i^{1/2}\delta_i^{3/2},\quad a_i = (R_i\delta_i)^{1/2}\quad(\delta_i>0),

with :math:`u_j` the Hertzian field of contact :math:`j` (:mod:`asperity.icha.field`), and
:math:`\sum_i F_i = P`.  The contacts are found by an active-set Newton method on
:math:`(\delta_i, d)` with the exact Jacobian (the field's dependence on the contact radii
included), a ratio test where a contact opens and backtracking where a full step does not
reduce the residual; the previous load's state is the starting point.  Without
coalescence, an asperity inside another's spot can be pushed in and out of contact for
ever by the overlapping Hertz fields: after :data:`MAX_ENTRIES` entries in one solve it
stays out.

**Coalescence.**  When the contact circles of two spots overlap,
:math:`|\mathbf r_i - \mathbf r_j| < a_i + a_j`, they become one equivalent Hertzian spot
(:func:`merge_spots`) with the sum of their contact areas and forces, at their
area-weighted centroid, whose radius of curvature and height follow from Hertz's laws;
it replaces the two asperities from then on, and the load step is solved again until no
spots overlap.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import optimize

from .._validation import check_positive, check_scalar_positive

__all__ = ["merge_spots", "IchaState", "MAX_ITERATIONS"]

#: Most Newton iterations per solve of one load step (between merges).
MAX_ITERATIONS = 1000
#: Most times an asperity may come into contact during one solve (see :meth:`IchaState._equilibrium`).
MAX_ENTRIES = 5
#: Most rounds of merging at one load.
MAX_MERGE_ROUNDS = 10000


def merge_spots(F1, a1, F2, a2, E_star):
    r"""The equivalent Hertzian spot of two coalescing contacts: force and area conserved.

    .. math::
        F = F_1 + F_2,\qquad a^2 = a_1^2 + a_2^2,\qquad
        R = \frac{4E^*a^3}{3F},\qquad \delta = \frac{a^2}{R} = \frac{3F}{4E^*a}

    (Afferrante, Carbone & Demelio 2012: an equivalent contact spot conserving the
    contact area and the load; the equivalent asperity is a Hertzian cap of radius
    :math:`R` carrying :math:`F` over the area :math:`\pi a^2`).

    Parameters
    ----------
    F1, F2 : array_like
        Forces of the two contacts [N], > 0.
    a1, a2 : array_like
        Their contact radii [m], > 0.
    E_star : float
        Contact modulus [Pa], > 0.

    Returns
    -------
    F, a, R, delta : ndarray
        Force [N], contact radius [m], radius of curvature [m] and interference [m] of
        the equivalent spot.

    Raises
    ------
    ValueError
        For non-finite or non-positive forces, radii or modulus.

    Examples
    --------
    >>> F, a, R, delta = merge_spots(1.0, 1e-8, 1.0, 1e-8, 1e11)   # two equal spots: R grows by sqrt(2)
    >>> round(float(R / (4e11 * 1e-24 / 3)), 12), round(float(a / 1e-8) ** 2, 12)
    (1.414213562373, 2.0)

    References
    ----------
    L. Afferrante, G. Carbone, G. Demelio, Wear 278-279 (2012) 28-33; Johnson (1985), §4.2.
    """
    F1, a1, F2, a2 = (check_positive(v, n) for v, n in ((F1, "F1"), (a1, "a1"), (F2, "F2"), (a2, "a2")))
    E_star = check_scalar_positive(E_star, "E_star", "Pa")
    F = F1 + F2
    a = np.sqrt(a1 * a1 + a2 * a2)
    R = 4 * E_star * a**3 / (3 * F)
    return F, a, R, a * a / R


@dataclass
class IchaState:
    """Working state of the model on one map (mutable, advanced from load to load).

    Attributes
    ----------
    x, y, z, R : ndarray
        Position [m], height [m] and radius [m] of each asperity (merged ones replace their parts).
    members : ndarray of int
        Number of original summits in each asperity.
    F : ndarray
        Contact forces [N] (0 off contact).
    d : float
        Position of the flat above the mean plane [m].
    merges : int
        Coalescences so far.
    """

    x: np.ndarray
    y: np.ndarray
    z: np.ndarray
    R: np.ndarray
    members: np.ndarray
    F: np.ndarray
    d: float
    E_star: float
    kernel: object = None  # FreeKernel or PeriodicKernel
    interaction: bool = True
    coalescence: bool = True
    merges: int = 0
    iterations: int = 0
    distance: np.ndarray = None   # nearest-image distances between asperities [m]
    point: np.ndarray = None      # pi E* x point-force field between asperities [1/m], images on the diagonal

    def __post_init__(self):
        self.refresh()

    def refresh(self):
        """Compute the distances (infinite on the diagonal) and point-force fields between the asperities."""
        self.distance, self.point = self.kernel.point_matrix(self.x, self.y)
        np.fill_diagonal(self.distance, np.inf)

    def _refresh_row(self, i):
        """Update the distances and fields of asperity ``i`` after it moved."""
        others = np.arange(self.z.size) != i
        r, g = self.kernel.point_row(self.x[i], self.y[i], self.x[others], self.y[others])
        self.distance[i, others] = self.distance[others, i] = r
        self.point[i, others] = self.point[others, i] = g

    @classmethod
    def start(cls, summits, E_star, kernel, *, interaction=True, coalescence=True):
        """A state with no contact, the flat above the highest summit."""
        n = len(summits)
        return cls(x=summits.x.astype(float), y=summits.y.astype(float), z=summits.z.astype(float),
                   R=summits.R.astype(float), members=np.ones(n, dtype=int), F=np.zeros(n),
                   d=float(np.max(summits.z)), E_star=float(E_star), kernel=kernel,
                   interaction=bool(interaction), coalescence=bool(coalescence))

    # -- geometry ---------------------------------------------------------------------------
    def separations(self, rows, cols):
        """Nearest-image separations (dx, dy, r) between asperities ``rows`` and ``cols``."""
        dx = self.x[rows][:, None] - self.x[cols][None, :]
        dy = self.y[rows][:, None] - self.y[cols][None, :]
        return self.kernel.nearest(dx, dy)

    def radii(self, F=None) -> np.ndarray:
        """Contact radii :math:`a = (3FR/4E^*)^{1/3}` [m]."""
        F = self.F if F is None else F
        return np.cbrt(3 * F * self.R / (4 * self.E_star))

    def compliance(self, rows, cols, a_cols):
        r"""Influence matrix [m/N]: displacement at ``rows`` per unit force at ``cols``.

        The Hertzian field of each contact (radius ``a_cols``), with the periodic images
        when the map is periodic; on the diagonal (an asperity on itself) only the images,
        its own compression being the Hertz interference.
        """
        if not self.interaction:
            return np.zeros((rows.size, cols.size))
        ix = np.ix_(rows, cols)
        out = self.point[ix] + self.kernel.spot_excess(self.distance[ix], a_cols[None, :])
        return out / (math.pi * self.E_star)

    # -- one load ---------------------------------------------------------------------------
    def first_guess(self, P):
        """Independent Hertz asperities carrying ``P``: the flat position and the forces."""
        k = 4 / 3 * self.E_star * np.sqrt(self.R)

        def excess(d):
            return float(np.sum(k * np.clip(self.z - d, 0, None) ** 1.5)) - P

        top = float(self.z.max())
        span = float(np.ptp(self.z)) or abs(top) or 1.0
        lo = float(self.z.min()) - span
        while excess(lo) < 0:
            lo -= 2 * span
            span *= 2
        self.d = optimize.brentq(excess, lo, float(self.z.max()), xtol=1e-300, rtol=1e-15)
        self.F = k * np.clip(self.z - self.d, 0, None) ** 1.5

    def solve(self, P, *, tol=1e-12):
        """Contact forces and flat position carrying the total force ``P`` [N], with coalescence."""
        if not np.any(self.F > 0):
            self.first_guess(P)
        for _ in range(MAX_MERGE_ROUNDS):
            settled = self._equilibrium(P, tol)
            merged = self.coalescence and self._merge_overlapping()
            if settled and not merged:
                return
        raise ValueError(f"the asperity model did not settle its coalescences at P = {P:.6g} N")

    def _equilibrium(self, P, tol) -> bool:
        """Solve the load step for the current asperities.

        Returns True at equilibrium; False if it stopped early because asperities coming
        into contact overlap a contact spot (they are left in contact, provisionally, for
        :meth:`_merge_overlapping`), with coalescence on.
        """
        k = 4 / 3 * self.E_star * np.sqrt(self.R)
        n = self.z.size
        index = np.arange(n)
        scale = float(np.ptp(self.z)) or float(np.max(np.abs(self.z))) or 1.0
        delta = np.where(self.F > 0, np.cbrt((self.F / k) ** 2), 0.0)
        d = self.d
        it = 0
        entries = np.zeros(n, dtype=int)                              # times each asperity entered contact
        while it < MAX_ITERATIONS:
            act = index[delta > 0]
            if act.size == 0:                                         # all released: restart from Hertz
                self.F = np.zeros(n)
                self.first_guess(P)
                delta = np.where(self.F > 0, np.cbrt((self.F / k) ** 2), 0.0)
                d = self.d
                continue
            while it < MAX_ITERATIONS:                                # Newton on the contacts
                it += 1
                a, C, F, res = self._residual(act, k, delta, d, P)
                norm = self._norm(res, scale, P)
                if np.max(np.abs(res[:-1])) <= tol * scale and abs(res[-1]) <= tol * P:
                    break
                m = act.size
                dF = 1.5 * k[act] * np.sqrt(delta[act])
                J = np.empty((m + 1, m + 1))
                J[:m, :m] = C * dF[None, :]
                if self.interaction:                                  # the field's dependence on a_j
                    ix = np.ix_(act, act)
                    dC = self.kernel.spot_excess_da(self.distance[ix], a[None, :]) / (math.pi * self.E_star)
                    J[:m, :m] += dC * (F * a / (2 * delta[act]))[None, :]
                J[np.arange(m), np.arange(m)] += 1.0
                J[:m, m] = 1.0
                J[m, :m] = dF
                J[m, m] = 0.0
                step = np.linalg.solve(J, -res)
                down = step[:m] < 0                                   # ratio test: stop where a contact opens
                ratio = np.min(-delta[act][down] / step[:m][down]) if down.any() else np.inf
                if ratio < 1.0:
                    opening = act[down][np.argmin(-delta[act][down] / step[:m][down])]
                    delta[act] += ratio * step[:m]
                    d += ratio * step[m]
                    delta[opening] = 0.0                              # it leaves the set; the rest go on
                    delta[act] = np.where(delta[act] > 0, delta[act], 0.0)
                    break
                alpha = 1.0                                           # backtrack until the residual falls
                for _ in range(30):
                    trial = delta.copy()
                    trial[act] += alpha * step[:m]
                    if self._norm(self._residual(act, k, trial, d + alpha * step[m], P)[3], scale, P) \
                            <= (1 - 1e-4 * alpha) * norm:
                        break
                    alpha /= 2
                delta[act] += alpha * step[:m]
                d += alpha * step[m]
            else:
                break
            if np.any(delta[act] <= 0):
                continue
            rest = index[delta <= 0]                                  # does any other asperity touch?
            gap = self.z[rest] - d - self.compliance(rest, act, a) @ F
            # Without coalescence an asperity inside another's spot can be pushed in and out
            # for ever (overlapping Hertz fields): after MAX_ENTRIES entries it stays out.
            grow = (gap > tol * scale) & (entries[rest] < MAX_ENTRIES)
            if not grow.any() or (self.coalescence and self._touching(rest[grow], gap[grow], act, a)):
                self.F = np.zeros(n)
                self.F[act] = F
                if grow.any():                                        # provisional: they merge next
                    self.F[rest[grow]] = k[rest[grow]] * gap[grow] ** 1.5
                self.d, self.iterations = d, self.iterations + it
                return not grow.any()
            delta[rest[grow]] = gap[grow]                             # new contacts start at their gap
            entries[rest[grow]] += 1
        raise ValueError(f"the asperity model did not converge at P = {P:.6g} N within {MAX_ITERATIONS} "
                         "iterations")

    def _residual(self, act, k, delta, d, P):
        """Contact radii, influence matrix, forces and residuals of the contacts ``act``."""
        a = np.sqrt(self.R[act] * delta[act])
        C = self.compliance(act, act, a)
        F = k[act] * delta[act] ** 1.5
        return a, C, F, np.append(delta[act] - (self.z[act] - d - C @ F), F.sum() - P)

    @staticmethod
    def _norm(res, scale, P) -> float:
        """Size of the residuals: interferences over the height range, force over the load."""
        return math.hypot(float(np.linalg.norm(res[:-1])) / scale, float(res[-1]) / P)

    def _touching(self, new, gap, act, a) -> bool:
        """Whether an asperity coming into contact (interference ``gap``) overlaps a contact spot."""
        a_new = np.sqrt(self.R[new] * gap)
        return bool(np.any(self.distance[np.ix_(new, act)] < a_new[:, None] + a[None, :]))

    def _merge_overlapping(self) -> bool:
        """Merge every disjoint pair of overlapping contact circles; True if any merged."""
        act = np.flatnonzero(self.F > 0)
        if act.size < 2:
            return False
        a = self.radii()[act]
        _, _, r = self.separations(act, act)
        overlap = (a[:, None] + a[None, :]) - r
        iu, ju = np.triu_indices(act.size, 1)
        hit = overlap[iu, ju] > 0
        if not hit.any():
            return False
        iu, ju = iu[hit], ju[hit]
        order = np.argsort(-overlap[iu, ju] / (a[iu] + a[ju]), kind="stable")
        used = np.zeros(act.size, bool)
        pairs = []
        for p in order:
            i, j = iu[p], ju[p]
            if not (used[i] or used[j]):
                used[i] = used[j] = True
                pairs.append((act[i], act[j]))
        before = (self.x.copy(), self.y.copy(), self.F.copy(), self.radii())
        for i, j in pairs:                 # every merge from the state before this round: order-free
            self._merge(i, j, *before)
        keep = np.ones(self.z.size, bool)
        keep[[j for _, j in pairs]] = False
        for i, _ in pairs:
            self._refresh_row(i)
        for name in ("x", "y", "z", "R", "members", "F"):
            setattr(self, name, getattr(self, name)[keep])
        self.distance, self.point = self.distance[np.ix_(keep, keep)], self.point[np.ix_(keep, keep)]
        self.merges += len(pairs)
        return True

    def _merge(self, i, j, x0, y0, F0, a0):
        """Replace asperity i by the equivalent spot of i and j (j is dropped by the caller).

        ``x0, y0, F0, a0`` are the positions, forces and radii before this round of merges:
        the equivalent spot's height is set so that it carries its force in the field of the
        other contacts as they were.
        """
        F, _, R, delta = merge_spots(F0[i], a0[i], F0[j], a0[j], self.E_star)
        w = a0[j] ** 2 / (a0[i] ** 2 + a0[j] ** 2)
        dx, dy, _ = self.kernel.nearest(x0[j] - x0[i], y0[j] - y0[i])
        x, y = x0[i] + w * dx, y0[i] + w * dy
        if self.kernel.size is not None:
            x, y = x % self.kernel.size[0], y % self.kernel.size[1]
        self.x[i], self.y[i], self.R[i], self.F[i], self.F[j] = x, y, R, F, 0.0
        self.members[i] += self.members[j]
        u = 0.0
        if self.interaction:
            others = np.flatnonzero(F0 > 0)
            others = others[(others != i) & (others != j)]
            field = self.kernel.unit_field(x - x0[others], y - y0[others], a0[others])
            u = (F * self.kernel.self_images + float(field @ F0[others])) / (math.pi * self.E_star)
        self.z[i] = self.d + delta + u
