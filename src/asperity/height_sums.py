r"""Multi-asperity integrals for any height distribution: tabulated in the separation, interpolated.

Every integral of the model is :math:`S(\bar d) = \int q(\bar u)\,\phi(\bar d + \bar u)\,d\bar u`
(:mod:`asperity.tabulation`).  The Gaussian factorises :math:`\phi(\bar d + \bar u)` and
sums quadrature nodes afresh for every separation; other densities do not factorise, and
finite supports put a kink or a jump of :math:`\phi` at :math:`\bar u = z_{edge} - \bar d`,
which moves with :math:`\bar d` across fixed nodes.  :class:`HeightSums` therefore

1. integrates accurately at a few separations: composite 16-point Gauss-Legendre panels
   in penetration (no wider than twice the distribution's ``resolution``; the law's
   endpoint and breakpoints are panel edges, as in :class:`~asperity.tabulation.Tabulation`),
   except on the panels that hold a support edge or lie closer to it than 0.3 of their
   width, which are integrated again with tanh-sinh from the edge (the per-asperity law
   interpolated on each panel from its own 16 nodes: degree-15 Lagrange, in the panel's
   own variable);
2. tabulates the ratio :math:`R(\bar d) = S(\bar d)/Q(\bar d + \bar u_{end})` to the
   survival function (the contact fraction, so :math:`R` stays smooth and the relative
   accuracy holds far in the tail) at 20 Chebyshev points on panels of the separation
   ``panel_resolutions`` (2, 1.5 for a mixture) ``resolution`` wide, split and graded
   (factor 2, down to 1e-12) at the
   separations where :math:`S` is not smooth: where a support edge meets the law's
   endpoint or a breakpoint, :math:`\bar d = z_{edge} - \bar u_s`;
3. interpolates :math:`S = QR` and its derivatives
   :math:`S' = Q'R + QR'`, :math:`S'' = Q''R + 2Q'R' + QR''` (:math:`Q' = -\phi`,
   :math:`Q'' = -\phi'`) from the Chebyshev coefficients.

Panels are evaluated lazily, when a separation in them is first asked for.  A curve of
1000 loads asks for about 200 accurate sums instead of 1300 (docs/heights.md gives the
accuracy and speed).  Beyond :math:`\bar d = z_{end} - \bar u_{end}` (survival function
below :data:`~asperity.heights.base.SF_FLOOR`, or past a bounded support) every integral
is zero.

References
----------
.. [1] L. N. Trefethen, Approximation Theory and Approximation Practice (SIAM 2013), Chs 3, 4, 8
   (Chebyshev interpolation, its convergence, and differentiation).
.. [2] H. Takahasi, M. Mori, Publ. RIMS Kyoto Univ. 9 (1974) 721 (tanh-sinh quadrature).
.. [3] Adams et al., Eqs (5), (6), (10), (18), (21).
"""

from __future__ import annotations

import math

import numpy as np

from .asperity_law import ContactLaw
from .heights import EDGE_BAND, HeightDistribution
from .heights.base import decay_length, tanh_sinh
from .heights.mixture import KernelGaussian
from .quadrature import (
    NODES_PER_PANEL,
    chebyshev_basis,
    composite_nodes,
    gauss_legendre,
    legendre_to_chebyshev,
    panel_edges,
)

__all__ = ["HeightSums", "CHEBYSHEV_POINTS", "GRADED_POINTS", "D_MARGIN"]

#: Chebyshev points per separation panel (panels of twice the resolution: ~5e-14 relative;
#: 16 points give ~5e-12, and 1e-9 on the second derivative).
CHEBYSHEV_POINTS = 20
#: Chebyshev points on the graded panels next to a singular separation.
GRADED_POINTS = 12
#: The quadrature nodes serve separations this far (in sigma) beyond the separation panels.
D_MARGIN = 0.5
_GRADE_MIN = 1e-12  # smallest graded panel next to a singular separation (relative)
_BATCH_SPAN = 4.0  # separations evaluated together span at most this (in sigma)


def _chebyshev_values(s, n: int):
    """T_0..T_{n-1} at s (any shape, in [-1, 1]): shape s.shape + (n,)."""
    T = np.empty((n,) + s.shape)  # the recurrence on contiguous slices, then T_k last
    T[0] = 1.0
    T[1] = s
    two_s = 2.0 * s
    for k in range(2, n):
        np.multiply(two_s, T[k - 1], out=T[k])
        T[k] -= T[k - 2]
    return np.moveaxis(T, 0, -1)


class HeightSums:
    r"""The integrals of a per-asperity law against a height distribution, interpolated in the separation.

    What :class:`~asperity.tabulation.Tabulation` delegates to for a distribution with
    ``fast_sums`` False (module docstring).

    Parameters
    ----------
    law : ContactLaw
        Per-asperity law (its ``params``, ``u_end``, ``scale``, ``breakpoints``,
        ``evaluate``, ``friction``).
    heights : HeightDistribution
        Height distribution.
    d_min, d_max : float
        Separations to serve, ``d_min <= d_max`` (``D_MARGIN`` beyond them too).

    Attributes
    ----------
    edges, u, a_bar, weights : ndarray
        Quadrature panels, nodes, contact radius there and weighted integrands (nodes x 4:
        contacts, P, F, area), as in Tabulation.
    d_edges : ndarray
        Edges of the separation panels.
    """

    def __init__(self, law: ContactLaw, heights: HeightDistribution, d_min: float, d_max: float):
        self.law, self.heights = law, heights
        self.d_min, self.d_max = float(d_min), float(d_max)
        h = heights
        self.width = min(1.0, 2.0 * h.resolution)
        # Width of the separation panels: 2 resolutions for a single-humped density or a
        # kernel estimate (~5e-14); the ratio R of a two-width mixture, whose narrow component
        # hands its tail to the wide one, needs 1.5 (1e-12, against 1.5e-10 at 2).
        self._W = h.panel_resolutions * h.resolution
        # Separation panels lie on a global grid (multiples of W, split at the singular
        # separations), so a wider tabulation inherits the panels already computed; the
        # quadrature nodes serve every panel that touches [d_min, d_max].
        lo_d = math.floor((self.d_min - 0.5) / self._W) * self._W
        hi_d = math.ceil((self.d_max + 0.5) / self._W) * self._W
        translates = h.translates()
        self._kernel = None
        if translates is not None:  # sums of a kernel's translates: tabulate the kernel once
            weights, centres, width = translates
            self._translates = (np.asarray(weights, dtype=float), np.asarray(centres, dtype=float))
            kernel = KernelGaussian(width)
            self._kernel = HeightSums(law, kernel, lo_d - max(centres), hi_d - min(centres))
            self.edges, self.u, self.a_bar, self.weights = (getattr(self._kernel, k)
                                                            for k in ("edges", "u", "a_bar", "weights"))
            self._edges_of_support = []
        else:
            self._nodes(lo_d - D_MARGIN, hi_d + D_MARGIN)
            self._edges_of_support = [e for e in h.support
                                      if math.isfinite(e) and h.z_bottom - EDGE_BAND <= e <= h.z_top + EDGE_BAND]
        self._layout(lo_d, hi_d)
        panels = self.d_edges.size - 1
        self._state = np.zeros(panels, dtype=np.int8)  # 0: not yet computed, 1: coefficients, 2: zero
        self._C = [np.zeros((panels, CHEBYSHEV_POINTS, 4)) for _ in range(3)]  # R, R', R'' coefficients

    def inherit(self, other: HeightSums) -> None:
        """Take the separation panels ``other`` (same law and heights, any range) has computed."""
        if not (other.law is self.law and other.heights == self.heights):
            return
        E, F = self.d_edges, other.d_edges
        i = np.searchsorted(E, F[:-1])
        i = np.minimum(i, E.size - 2)
        same = (E[i] == F[:-1]) & (E[i + 1] == F[1:]) & (other._state > 0)
        self._state[i[same]] = other._state[same]
        for mine, theirs in zip(self._C, other._C, strict=True):
            mine[i[same]] = theirs[same]

    def _nodes(self, lo_d, hi_d):
        """Quadrature panels and the law on their nodes, serving separations in [lo_d, hi_d]."""
        law, h = self.law, self.heights
        u_top = max(h.z_top - lo_d, law.u_end + (h.z_top - h.z_bottom))
        u_bottom = h.z_bottom - hi_d
        first = law.scale
        for bp in law.breakpoints:
            if bp > law.u_end:
                first = min(first, (bp - law.u_end) / 3.0)
        # far in a light tail the integrand falls within the decay length sf/pdf of the lower limit
        first = min(first, 0.2, self.width, 3.0 * decay_length(h, min(hi_d + law.u_end, h.z_end)))
        edges = panel_edges(law.u_end, u_top, first, law.breakpoints, lo_clip=u_bottom)
        edges = self._refine(edges)
        u, w = composite_nodes(edges)
        a, P = law.evaluate(u)
        F = law.friction(a)
        self.edges, self.u, self.a_bar = edges, u, a
        self.q = np.stack([np.ones_like(u), P, F, a * a], axis=1).reshape(edges.size - 1, NODES_PER_PANEL, 4)
        self.weights = w[:, None] * self.q.reshape(-1, 4)
        # the law on each panel as a polynomial in its own variable (for the edge panels)
        self._q_coef = np.einsum("kj,pjc->pkc", legendre_to_chebyshev(NODES_PER_PANEL), self.q)
        self._group()

    # -- quadrature in penetration ------------------------------------------------------
    def _refine(self, edges):
        """Split every panel wider than ``width`` into equal parts (unit panels all alike)."""
        widths = np.diff(edges)
        parts = np.maximum(1, np.ceil(widths / self.width - 1e-9).astype(int))
        if np.all(parts == 1):
            return edges
        start = np.repeat(edges[:-1], parts)
        step = np.repeat(widths / parts, parts)
        k = np.arange(parts.sum()) - np.repeat(np.cumsum(parts) - parts, parts)
        return np.append(start + step * k, edges[-1])

    def _group(self):
        """Equal panels of the unit width (their nodes share offsets) go to panel_sums, the rest direct."""
        n = NODES_PER_PANEL
        widths = np.diff(self.edges)
        unit = 1.0 / max(1, int(math.ceil(1.0 / self.width - 1e-9)))
        uniform = np.isclose(widths, unit, rtol=0, atol=1e-12 * unit)
        uniform[0] = False  # the first panel carries the s^4 substitution
        mask = np.repeat(uniform, n)
        self._direct_u, self._direct_w = self.u[~mask], self.weights[~mask]
        left = self.edges[:-1][uniform]
        x, _ = gauss_legendre(n)
        self._centers = left + 0.5 * unit
        self._offsets = (x - 0.5) * unit
        self._panel_w = self.weights[mask].reshape(left.size, n, 4)
        self._unit = unit

    def direct(self, d, edges: bool = True):
        """The four integrals at separations ``d`` (1-D, a narrow range), accurately: shape (n, 4).

        ``edges=False`` leaves out the correction at the edges of the heights' support (which
        :meth:`_prepare` then adds for all its batches at once: per separation, the same).
        """
        if self._kernel is not None:  # sum of the kernel's integrals, shifted
            w, c = self._translates
            G = self._kernel.sums((d[:, None] - c[None, :]).ravel())[0].reshape(d.size, c.size, 4)
            return np.einsum("k,nkc->nc", w, G)
        h = self.heights
        lo, hi = h.z_bottom - d.max(), max(self.law.u_end, -d.min()) + h.z_top
        a, b = np.searchsorted(self._direct_u, [lo, hi])
        S = h.weighted_sums(d, self._direct_u[a:b], self._direct_w[a:b], 0)[0]
        a, b = np.searchsorted(self._centers, [lo - self._unit, hi + self._unit])
        if b > a:
            S = S + h.panel_sums(d, self._centers[a:b], self._offsets, self._panel_w[a:b], 0)[0]
        if edges and self._edges_of_support:
            S = S + self._edge_correction(d)
        return S

    def _edge_correction(self, d):
        """Replace the panels at a support edge by tanh-sinh over their part inside the support
        (the law interpolated on each panel from its own nodes)."""
        h, E = self.heights, self.edges
        last = E.size - 2
        lo_e, hi_e = h.support
        uc_lo = (lo_e - d) if lo_e in self._edges_of_support else np.full(d.size, -np.inf)
        uc_hi = (hi_e - d) if hi_e in self._edges_of_support else np.full(d.size, np.inf)

        def panel(u):
            return np.clip(np.searchsorted(E, u, side="right") - 1, 0, last)

        # Panels that hold an edge or lie closer to it than 0.3 of their width (farther, the
        # edge's singularity leaves 16-point Gauss-Legendre exact to ~1e-16): at most 3 each.
        K = 3
        k = np.arange(K)
        f0 = panel(uc_lo)[:, None] + k
        f1 = panel(uc_hi)[:, None] - k
        idx = np.clip(np.concatenate([f0, f1], axis=1), 0, last)
        a, b = E[idx], E[idx + 1]
        gap = np.concatenate([a[:, :K] - uc_lo[:, None], uc_hi[:, None] - b[:, K:]], axis=1)
        ok = (gap < 0.3 * (b - a)) & (np.concatenate([f0, f1], axis=1) == idx)
        ok[:, K:] &= ~((idx[:, K:, None] == idx[:, None, :K]) & ok[:, None, :K]).any(axis=2)  # counted once
        idx = np.clip(idx, 0, last)
        rows = np.broadcast_to(np.arange(d.size)[:, None], idx.shape)
        a, b = E[idx], E[idx + 1]
        lo_u, hi_u = np.maximum(a, uc_lo[:, None]), np.minimum(b, uc_hi[:, None])
        ok &= hi_u > lo_u
        if not ok.any():
            return 0.0
        # Only the (separation, panel) pairs that need it, flattened.
        row, p, a, b, lo_u, hi_u = (v[ok] for v in (rows, idx, a, b, lo_u, hi_u))
        dd = d[row]
        first = p == 0
        hq = (b - a) ** 0.25  # panel 0: u = a + (hq x)^4; others: u = a + (b - a) x

        def to_x(u):
            return np.where(first, np.maximum(u - a, 0.0) ** 0.25 / hq, (u - a) / (b - a))

        x_lo, x_hi = np.clip(to_x(lo_u), 0.0, 1.0), np.clip(to_x(hi_u), 0.0, 1.0)
        span = x_hi - x_lo
        t, _, tw = tanh_sinh(0.125)
        x = x_lo[:, None] + span[:, None] * t
        u = np.where(first[:, None], a[:, None] + (hq[:, None] * x) ** 4, a[:, None] + (b - a)[:, None] * x)
        du = np.where(first[:, None], 4.0 * hq[:, None] ** 4 * x**3, (b - a)[:, None])
        q_hat = _chebyshev_values(2.0 * x - 1.0, NODES_PER_PANEL) @ self._q_coef[p]  # (pairs, M, 4)
        f = h.pdf(dd[:, None] + u)
        exact = ((span[:, None] * tw * du * f)[:, None, :] @ q_hat)[:, 0]
        nodes = self.u.reshape(-1, NODES_PER_PANEL)[p]  # (pairs, J)
        naive = (h.pdf(dd[:, None] + nodes)[:, None, :] @ self.weights.reshape(-1, NODES_PER_PANEL, 4)[p])[:, 0]
        diff = exact - naive  # summed per separation (bincount: in order, as np.add.at, faster)
        return np.stack([np.bincount(row, weights=diff[:, j], minlength=d.size) for j in range(4)], axis=1)

    # -- interpolation in the separation ------------------------------------------------
    def _layout(self, lo, hi):
        """Separation panels over [lo, hi] (multiples of W): split at the separations where S is
        not smooth, and graded towards them by halving (down to a depth set by the edge's power)."""
        law, h = self.law, self.heights
        self.d_zero = h.z_end - law.u_end
        graded = []  # (separation, smallest panel next to it)
        for e in self._edges_of_support:
            for us in (law.u_end, *law.breakpoints):
                if us < law.u_end:
                    continue
                # S - smooth ~ |d - d*|^beta at least: the law may jump at its endpoint (a
                # Maugis-Dugdale branch end), it only kinks at a breakpoint (Hurtado-Kim radii)
                beta = h.edge_power + (1.0 if us == law.u_end else 2.0)
                depth = 10.0 ** (-13.0 / beta) if beta < 13.0 else math.inf
                if e == h.support[1] and us == law.u_end:
                    depth = 0.0  # S/Q ~ |d - d*|^(1/2) where the support ends above
                graded.append((e - us, depth))
        graded.append((self.d_zero, math.inf))
        W = self._W
        points = list(W * np.arange(round(lo / W), round(hi / W) + 1))
        for s_, depth in graded:
            if not lo < s_ < hi:
                continue
            points.append(s_)
            step = W / 2.0
            floor = max(depth, _GRADE_MIN * max(1.0, abs(s_)))
            while step > floor:
                points += [s_ - step, s_ + step]
                step /= 2.0
        self.d_edges = np.unique(np.clip(points, lo, hi))

    def _prepare(self, panels):
        """Chebyshev coefficients of R on the given separation panels (evaluated in batches).

        Panels narrower than W/4 lie next to a singular separation, at a distance of their
        own width (the grading): 12 points reach 5.8^-12 ~ 1e-9 of the singular part, which
        is itself below 1e-10 of R there; the others take CHEBYSHEV_POINTS.
        """
        E, state = self.d_edges, self._state
        todo = [k for k in panels if state[k] == 0]
        for k in todo:
            if E[k] >= self.d_zero:
                state[k] = 2  # zero: beyond the last summit (or the survival function's underflow)
        todo = np.array([k for k in todo if state[k] == 0], dtype=int)
        if todo.size == 0:
            return
        narrow = (E[todo + 1] - E[todo]) < 0.25 * self._W
        jobs = []  # (batch, points, separations, integrals without the support-edge correction)
        for group, n in ((todo[~narrow], CHEBYSHEV_POINTS), (todo[narrow], GRADED_POINTS)):
            xc = chebyshev_basis(n)[0]
            i = 0
            while i < group.size:
                j = i + 1
                while j < group.size and E[group[j] + 1] - E[group[i]] <= _BATCH_SPAN and j - i < 20:
                    j += 1
                batch = group[i:j]
                a, b = E[batch], E[batch + 1]
                dn = (0.5 * (a + b)[:, None] + 0.5 * (b - a)[:, None] * xc).ravel()
                jobs.append((batch, n, dn, self.direct(dn, edges=False)))
                i = j
        if self._edges_of_support and self._kernel is None and jobs:  # one call for every batch
            fix = self._edge_correction(np.concatenate([job[2] for job in jobs]))
            if not np.isscalar(fix):
                ends = np.cumsum([job[2].size for job in jobs])[:-1]
                jobs = [(bt, n, dn, S + part) for (bt, n, dn, S), part in zip(jobs, np.split(fix, ends), strict=True)]
        for batch, n, dn, S in jobs:
            _, T, D = chebyshev_basis(n)
            a, b = E[batch], E[batch + 1]
            Q = self.heights.sf(dn + self.law.u_end)
            R = (S / np.where(Q > 0, Q, 1.0)[:, None]).reshape(batch.size, n, 4)
            c0 = T @ R  # (batch, n, 4)
            scale = (2.0 / (b - a))[:, None, None]
            c1 = scale * (D @ c0)
            for C, c in zip(self._C, (c0, c1, scale * (D @ c1)), strict=True):
                C[batch, :n] = c  # coefficients beyond n stay zero
            state[batch] = 1

    def sums(self, d, order: int = 0):
        """``[S_0, .., S_order]``: the four integrals (columns) and their d-derivatives, as Tabulation.sums."""
        d = np.asarray(d, dtype=float).ravel()
        out = [np.zeros((d.size, 4)) for _ in range(order + 1)]
        if d.size == 0:
            return out
        E = self.d_edges
        if d.min() < E[0] or d.max() > E[-1]:
            raise ValueError(f"separations from {d.min():g} to {d.max():g} lie outside the range these integrals "
                             f"were built for, [{E[0]:g}, {E[-1]:g}]: extend the tabulation first")
        k = np.clip(np.searchsorted(E, d, side="right") - 1, 0, E.size - 2)
        present = np.zeros(E.size - 1, dtype=bool)
        present[k] = True
        self._prepare(np.flatnonzero(present).tolist())
        rows = self._state[k] == 1
        if not rows.any():
            return out
        kk = k[rows]
        a, b = E[kk], E[kk + 1]
        x = np.clip((2.0 * d[rows] - a - b) / (b - a), -1.0, 1.0)
        n = CHEBYSHEV_POINTS
        Tx = np.empty((n, x.size))  # the recurrence on contiguous rows, then one transpose
        Tx[0] = 1.0
        Tx[1] = x
        for j in range(2, n):
            Tx[j] = 2.0 * x * Tx[j - 1] - Tx[j - 2]
        Tx = np.ascontiguousarray(Tx.T)[:, None, :]
        R = [(Tx @ self._C[j][kk])[:, 0] for j in range(order + 1)]
        z = d[rows] + self.law.u_end
        h = self.heights
        Q = h.sf(z)[:, None]
        out[0][rows] = Q * R[0]
        if order >= 1:
            Q1 = -h.pdf(z)[:, None]
            out[1][rows] = Q1 * R[0] + Q * R[1]
        if order >= 2:
            Q2 = -h.pdf_derivative(z, 1)[:, None]
            out[2][rows] = Q2 * R[0] + 2.0 * Q1 * R[1] + Q * R[2]
        return out
