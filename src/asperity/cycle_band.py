r"""The per-asperity law along a loading cycle: cut off on approach, and the loop band.

:class:`ApproachLaw` is the law an approaching asperity follows (nothing until its
penetration reaches :math:`\bar u_{in}`); :class:`LoopBand` integrates the law over the band
:math:`[\bar u_c, \bar u_{in}]` of asperities still stuck on retraction, on fixed
Gauss-Legendre panels over :math:`[\bar u_{end}, \bar u_{in}]`, with the moving lower limit
(and a support edge of the heights' density) on fresh nodes.  The equations are in
:mod:`asperity.cycle_integrals`, which combines them into the branches of a cycle.

References
----------
.. [1] K. N. G. Fuller, D. Tabor, Proc. R. Soc. A 345 (1975) 327.
.. [2] Adams et al., Eqs (5), (6), (10), (18), (21).
"""

from __future__ import annotations

import math

import numpy as np

from ._validation import as_float_array, scalar
from .asperity_law import ContactLaw
from .quadrature import NODES_PER_PANEL, composite_nodes, gauss_legendre, panel_edges

__all__ = ["ApproachLaw", "LoopBand", "law_columns", "check_u_in"]

#: Families whose density is (z - edge)^p times an analytic function at a support edge.
_ANALYTIC_AT_EDGE = frozenset({"exponential", "weibull", "pearson3"})


def law_columns(law: ContactLaw, u):
    r"""The four integrands of a law at penetrations ``u``: (1, P, F, a^2), shape (u.size, 4).

    The same columns, in the same order, as :data:`asperity.tabulation.COLUMNS`
    (contacts, :math:`\bar P`, :math:`\bar F`, :math:`\bar a^2`); 0 below the law's ``u_end``.
    """
    u = np.asarray(u, dtype=float).ravel()
    a, P = law.evaluate(u)
    F = law.friction(a)
    on = (u >= law.u_end).astype(float)
    return np.stack([on, P, F, a * a], axis=1)


def check_u_in(u_in, u_end: float) -> float:
    """``u_in`` as a float in [u_end, 0]; ValueError naming it otherwise."""
    u_in = float(scalar(as_float_array(u_in, "u_in"), "u_in"))
    if not u_end <= u_in <= 0.0:
        raise ValueError(f"u_in (penetration at which an approaching asperity jumps into contact, in sigma) must "
                         f"lie in [u_end, 0] = [{u_end:.6g}, 0]: from the end of the stable branch to first "
                         f"touch; got {u_in!r}")
    return u_in


def _refined(edges, width: float):
    """``edges`` with every panel wider than ``width`` split into equal panels no wider (the
    density, which varies over its ``resolution``, must be resolved as the tabulation resolves
    it: a narrow mixture component on unit panels made the retraction force wrong by 45 %)."""
    pieces = np.maximum(np.ceil(np.diff(edges) / width - 1e-9), 1).astype(int)
    if np.all(pieces == 1):
        return edges
    parts = [a + (b - a) * np.arange(k) / k for a, b, k in zip(edges[:-1], edges[1:], pieces, strict=True)]
    return np.append(np.concatenate(parts), edges[-1])


class ApproachLaw:
    r"""A contact law seen by an approaching asperity: the law cut off below :math:`\bar u_{in}`.

    An asperity that has not touched yet carries nothing until its penetration reaches
    :math:`\bar u_{in}`; from there on it follows the stable branch of ``law``.  As a
    :class:`~asperity.asperity_law.ContactLaw` with ``u_end = u_in`` it plugs into
    :class:`~asperity.tabulation.Tabulation` and :mod:`asperity.load_control` unchanged.

    Parameters
    ----------
    law : ContactLaw
        The per-asperity law (e.g. :class:`~asperity.asperity_law.AsperityLaw`).
    u_in : float
        Jump-in penetration :math:`\bar u_{in}` in :math:`\sigma`, in ``[law.u_end, 0]``.

    Examples
    --------
    >>> from asperity.asperity_law import AsperityLaw, ModelParameters
    >>> law = AsperityLaw(ModelParameters(0.01, 1000.0, 1e-3))
    >>> app = ApproachLaw(law, 0.0)
    >>> a, P = app.evaluate(np.array([law.u_end / 2, 0.5]))
    >>> float(P[0]), bool(P[1] == law.evaluate(np.array([0.5]))[1][0])
    (0.0, True)
    """

    def __init__(self, law: ContactLaw, u_in: float):
        self.base = law
        self.params = law.params
        self.u_end = check_u_in(u_in, law.u_end)
        self.scale = law.scale
        self.breakpoints = tuple(b for b in law.breakpoints if b > self.u_end)

    def evaluate(self, u_bar):
        """Contact radius and force of ``law`` at ``u_bar``, zero below ``u_in``."""
        u = np.asarray(u_bar, dtype=float)
        a, P = self.base.evaluate(u)
        off = u < self.u_end
        return np.where(off, 0.0, a), np.where(off, 0.0, P)

    def friction(self, a_bar):
        """Friction force of one asperity of radius ``a_bar`` (the law's)."""
        return self.base.friction(a_bar)


class LoopBand:
    r"""The per-asperity law on fixed quadrature panels over :math:`[\bar u_{end}, \bar u_{in}]`.

    Gives :math:`\int_{\bar u_c}^{\bar u_{in}} q(\bar u)\,\phi^{(j)}(\bar d + \bar u)\,d\bar u` for
    pairs :math:`(\bar d, \bar u_c)` (:meth:`sums`) and the loop integrals (:meth:`loop`).
    Panels are those of the tabulation (:func:`~asperity.quadrature.panel_edges`: a first panel
    in :math:`s`, :math:`\bar u = \bar u_{end} + s^4`, graded panels, the law's breakpoints as
    edges, unit panels), cut at :math:`\bar u_{in}` and split to at most twice the heights'
    ``resolution`` (as the tabulation's); the panel holding :math:`\bar u_c` is
    integrated from :math:`\bar u_c` on 16 fresh Gauss-Legendre nodes (in :math:`s` on the
    first panel), the panels above on the fixed nodes.

    Parameters
    ----------
    law : ContactLaw
        The per-asperity law.
    u_in : float
        Jump-in penetration, in ``[law.u_end, 0]``.
    heights : HeightDistribution
        The height distribution (its ``pdf``, ``pdf_derivative``, ``sf``, ``weighted_sums``).
    """

    def __init__(self, law: ContactLaw, u_in: float, heights):
        self.law = law
        self.heights = heights
        self.u_end = float(law.u_end)
        self.u_in = check_u_in(u_in, self.u_end)
        self.width = self.u_in - self.u_end
        if self.width <= 1e-12:  # no tensile range, or one narrower than the edges' own tolerance below
            self.edges = np.array([self.u_in])
            self.u = np.zeros(0)
            self.weights = np.zeros((0, 4))
            return
        first = min(law.scale, 0.2, *((bp - self.u_end) / 3.0 for bp in law.breakpoints if bp > self.u_end))
        edges = panel_edges(self.u_end, self.u_in + 2.0, first, law.breakpoints)  # run past u_in, then cut
        keep = edges < self.u_in - 1e-12 * max(1.0, self.width)
        self.edges = _refined(np.append(edges[keep], self.u_in), min(1.0, 2.0 * float(heights.resolution)))
        u, w = composite_nodes(self.edges)
        self.u = u
        self.weights = w[:, None] * law_columns(law, u)

    @property
    def panels(self) -> int:
        """Number of panels."""
        return self.edges.size - 1

    def _partial(self, u_c, edge=False):
        """Nodes and weighted integrands on [u_c, next edge] for each u_c: (m, 16), (m, 16, 4); with
        ``edge``, also the integrands at u_c itself, (m, 4) (one call of the law for both)."""
        x, w = gauss_legendre(NODES_PER_PANEL)
        j = np.clip(np.searchsorted(self.edges, u_c, side="right") - 1, 0, self.panels - 1)
        right = self.edges[j + 1]
        nodes = u_c[:, None] + (right - u_c)[:, None] * x[None, :]
        weights = (right - u_c)[:, None] * w[None, :]
        first = j == 0  # in s, u = u_end + s^4: analytic at the branch end
        if np.any(first):
            s_a = np.maximum(u_c[first] - self.u_end, 0.0) ** 0.25
            s_b = (right[first] - self.u_end) ** 0.25
            s = s_a[:, None] + (s_b - s_a)[:, None] * x[None, :]
            nodes[first] = self.u_end + s**4
            weights[first] = 4.0 * s**3 * (s_b - s_a)[:, None] * w[None, :]
        q = law_columns(self.law, np.concatenate([nodes.ravel(), u_c if edge else []]))
        wq = weights[:, :, None] * q[:nodes.size].reshape(*nodes.shape, 4)
        return (j, nodes, wq, q[nodes.size:]) if edge else (j, nodes, wq)

    def sums(self, d, u_c, order: int = 0, edge: bool = False):
        r"""``[B_0, .., B_order]``: :math:`B_0 = \int_{u_c}^{u_{in}} q\,\phi(d + u)\,du` and its
        derivative in :math:`d` at fixed :math:`u_c`, shape (n, 4); ``order`` 0 or 1.

        ``d`` and ``u_c`` are 1-D of equal length, ``u_c`` in ``[u_end, u_in]``.  Where the
        heights' support ends inside :math:`[d + u_c, d + u_{in}]` (a lowest summit: exponential,
        Weibull, Pearson III heights; a highest: Pearson III of negative skew, Johnson
        :math:`S_B`), the integral runs between the edges (:meth:`_cut_row`), and :math:`B_1`
        includes their motion with :math:`d`.  With ``edge``, the integrands at the lower
        limits (shape (n, 4)) are appended to the list.
        """
        if order not in (0, 1):
            raise ValueError(f"order must be 0 or 1, got {order!r}")
        d = np.asarray(d, dtype=float).ravel()
        u_c = np.asarray(u_c, dtype=float).ravel()
        out = [np.zeros((d.size, 4)) for _ in range(order + 1)]
        if self.width <= 0.0 or d.size == 0:
            return out + ([np.zeros((d.size, 4))] if edge else [])
        h = self.heights
        # Gauss-Legendre across a support's edge (a jump or a power-law start of the density) errs
        # by percents (found by two reviews: 5 % at the exponential's lowest summit, 56 % at the
        # highest of a Pearson III of negative skew): such rows are integrated between the edges.
        z_lo, z_hi = (float(z) for z in h.support)
        cut = np.zeros(d.size, dtype=bool)
        # also where an edge lies just outside the band: the density's power-law start (p < 2) is
        # then nearly singular at its end (a review: slopes 8 % off 1e-4 sigma above the edge)
        p = float(h.edge_power)
        analytic = p.is_integer() and h.name in _ANALYTIC_AT_EDGE  # then an edge outside does not matter
        near = self.width if p < 2.0 and not analytic else 0.0
        tol = 1e-12 * np.maximum(1.0, np.abs(u_c))  # an edge on the band's end is on it (its motion counts)
        if math.isfinite(z_lo):
            cut |= z_lo - d > u_c - np.maximum(near, tol)
        if math.isfinite(z_hi):
            cut |= z_hi - d < self.u_in + np.maximum(near, tol)
        q_lo = np.zeros((d.size, 4))
        rows = np.flatnonzero(cut)
        if rows.size:
            parts, q_lo[rows] = self._cut_rows(d[rows], u_c[rows], order)
            for k in range(order + 1):
                out[k][rows] = parts[k]
        rest = np.flatnonzero(~cut)
        if rest.size:
            parts = self._sums_inside(d[rest], u_c[rest], order)
            for k in range(order + 1):
                out[k][rest] = parts[k]
            q_lo[rest] = parts[-1]
        return out + ([q_lo] if edge else [])

    def _sums_inside(self, d, u_c, order):
        """:meth:`sums` where the band lies inside the support: the cut panel on fresh nodes, the
        panels above on the fixed ones; the integrands at u_c last."""
        h = self.heights
        out = [np.zeros((d.size, 4)) for _ in range(order + 1)]
        uniq, inv = np.unique(u_c, return_inverse=True)
        j, nodes, wq, q_c = self._partial(uniq, edge=True)
        if uniq.size * 8 < d.size:  # few distinct cuts (a shared grid): one product per cut
            for c in range(uniq.size):
                rows = np.flatnonzero(inv == c)
                x = d[rows, None] + nodes[c]
                out[0][rows] += h.pdf(x) @ wq[c]
                for k in range(1, order + 1):
                    out[k][rows] += h.pdf_derivative(x, k) @ wq[c]
        else:
            x = d[:, None] + nodes[inv]  # (n, 16)
            dens = [h.pdf(x)] + [h.pdf_derivative(x, k) for k in range(1, order + 1)]
            for k in range(order + 1):
                out[k] += np.einsum("nj,njc->nc", dens[k], wq[inv])
        # Whole panels above the cut, on the fixed nodes, grouped by the cut panel.
        z_top = h.z_top
        rows_j = j[inv]
        for jj in np.unique(rows_j):
            rows = np.flatnonzero(rows_j == jj)
            start = (jj + 1) * NODES_PER_PANEL
            if start >= self.u.size:
                continue
            lo, hi = -d[rows].max() - z_top, -d[rows].min() + z_top  # where the density reaches
            a = start + np.searchsorted(self.u[start:], lo)
            b = start + np.searchsorted(self.u[start:], hi, side="right")
            if b > a:
                parts = h.weighted_sums(d[rows], self.u[a:b], self.weights[a:b], order)
                for k in range(order + 1):
                    out[k][rows] += parts[k]
        return out + [q_c[inv]]

    def _cut_nodes(self, d: float, u_c: float):
        r"""Quadrature of one row whose band meets or nears a support edge, over :math:`[a, b]`,
        :math:`a = \max(u_c, z_{lo} - d)`, :math:`b = \min(u_{in}, z_{hi} - d)`.

        The pieces are the panels' edges inside, refined geometrically towards an edge of the
        density where it is not analytic there (each piece then as far from it as it is wide);
        the piece at an edge is integrated in s, :math:`u = a + (u - a)s^k`, :math:`k = 4/(p + 1)`
        (p the density's edge power), mirrored at an upper edge; the first panel in s,
        :math:`u = u_{end} + s^4`, at the branch end.  Returns ``(u, weights, a, b, lo_edge,
        hi_edge)`` (``u`` empty if :math:`b \le a`); an edge within 1e-12 of the band's end
        counts as on it.
        """
        h = self.heights
        z_lo, z_hi = (float(z) for z in h.support)
        tol = 1e-12 * max(1.0, abs(u_c), abs(self.u_in))
        lo_edge, hi_edge = z_lo - d > u_c - tol, z_hi - d < self.u_in + tol
        a = max(u_c, z_lo - d)
        b = min(self.u_in, z_hi - d)
        if not b > a:
            return np.zeros(0), np.zeros(0), a, b, lo_edge, hi_edge
        p = float(h.edge_power)
        k = 4.0 / (p + 1.0) if math.isfinite(p) else 1.0
        inner = self.edges[(self.edges > a) & (self.edges < b)]
        points = [a, b, *inner]
        grow = 2.0 ** np.arange(1, 60)
        # a density like (z - edge)^p is not analytic at its edge unless p is an integer (and the
        # family's other factor analytic: exponential, Weibull, Pearson III; not Johnson S_B):
        # pieces refined geometrically away from the edge's piece
        refine = not (float(p).is_integer() and h.name in _ANALYTIC_AT_EDGE)
        if refine and lo_edge:
            w0 = (inner[0] if inner.size else b) - a
            points += list(a + w0 * grow)
        elif refine and math.isfinite(z_lo):  # an edge just below a, at distance delta
            points += list(a + (a - (z_lo - d)) * (grow - 1.0))
        if hi_edge:  # the upper edge's piece stays clear of the branch end (q's root at u_end)
            below = inner[-1] if inner.size else a
            below = 0.5 * (a + b) if below < self.edges[1] else below
            points.append(below)
            if refine:
                points += list(b - (b - below) * grow)
        elif refine and math.isfinite(z_hi):
            points += list(b - ((z_hi - d) - b) * (grow - 1.0))
        points = np.unique(np.clip(np.array(points), a, b))
        x, w = gauss_legendre(NODES_PER_PANEL)
        nodes, weights = [], []
        for left, right in zip(points[:-1], points[1:], strict=True):
            width = right - left
            if lo_edge and left == a:
                u, wt = left + width * x**k, k * x ** (k - 1.0) * width * w
            elif hi_edge and right == b:
                u, wt = right - width * x**k, k * x ** (k - 1.0) * width * w
            elif left < self.edges[1]:  # the first panel: in s, u = u_end + s^4 (the branch end)
                s_a, s_b = max(left - self.u_end, 0.0) ** 0.25, (right - self.u_end) ** 0.25
                sv = s_a + (s_b - s_a) * x
                u, wt = self.u_end + sv**4, 4.0 * sv**3 * (s_b - s_a) * w
            else:
                u, wt = left + width * x, width * w
            nodes.append(u)
            weights.append(wt)
        return np.concatenate(nodes), np.concatenate(weights), a, b, lo_edge, hi_edge

    def _cut_rows(self, d, u_c, order: int):
        r"""The rows of :meth:`sums` whose band meets or nears a support edge (:meth:`_cut_nodes`),
        the law evaluated once for all of them.  :math:`B_1 = \int q\phi' + q(a)\phi(z_{lo}^+)
        - q(b)\phi(z_{hi}^-)` (a limit at an edge moves with :math:`d`), or, where :math:`\phi'`
        is singular (0 < p < 1), by parts: :math:`q(b)\phi(d + b)[b = u_{in}] - q(a)\phi(d + a)[a = u_c]
        - \int q_u\phi`, :math:`q_u` by central differences.  Returns ``([B_0, (B_1)], q(a))``."""
        h = self.heights
        z_lo, z_hi = (float(z) for z in h.support)
        rows = [self._cut_nodes(float(di), float(ci)) for di, ci in zip(d, u_c, strict=True)]
        sizes = np.array([r[0].size for r in rows])
        u = np.concatenate([r[0] for r in rows])
        wt = np.concatenate([r[1] for r in rows])
        a = np.array([r[2] for r in rows])
        b = np.array([r[3] for r in rows])
        lo_edge = np.array([r[4] for r in rows])
        hi_edge = np.array([r[5] for r in rows])
        z = np.repeat(d, sizes) + u
        q = law_columns(self.law, u)
        q_a, q_b = law_columns(self.law, a), law_columns(self.law, b)
        starts = np.concatenate([[0], np.cumsum(sizes)[:-1]])
        full = sizes > 0

        def row_sums(values):  # per-row sums of (n_nodes, 4) values; 0 for empty rows
            out = np.zeros((d.size, 4))
            if u.size:
                out[full] = np.add.reduceat(values, starts[full], axis=0)
            return out

        dens = wt * h.pdf(z)
        out = [row_sums(dens[:, None] * q)]
        if order == 1:
            p = float(h.edge_power)
            with np.errstate(all="ignore"):
                phi_a, phi_b = h.pdf(d + a), h.pdf(d + b)
            if 0.0 < p < 1.0:
                step = np.maximum(np.minimum(1e-6 * np.maximum(1.0, np.abs(u)), 0.5 * (u - self.u_end)),
                                  1e-12 * np.maximum(1.0, np.abs(u)))
                lo = np.maximum(u - step, self.u_end)  # one-sided at the branch end
                q_u = (law_columns(self.law, u + step) - law_columns(self.law, lo)) / (u + step - lo)[:, None]
                b1 = -row_sums(dens[:, None] * q_u)
                b1 += np.where(hi_edge[:, None], 0.0, q_b * phi_b[:, None])
                b1 -= np.where(lo_edge[:, None], 0.0, q_a * phi_a[:, None])
            else:
                b1 = row_sums((wt * h.pdf_derivative(z, 1))[:, None] * q)
                if math.isfinite(z_lo):
                    b1 += np.where(lo_edge[:, None], q_a * float(h.pdf(np.array([np.nextafter(z_lo, math.inf)]))[0]),
                                   0.0)
                if math.isfinite(z_hi):
                    b1 -= np.where(hi_edge[:, None],
                                   q_b * float(h.pdf(np.array([np.nextafter(z_hi, -math.inf)]))[0]), 0.0)
            out.append(np.where(full[:, None], b1, 0.0))
        return out, q_a

    def loop(self, d_min, d_max: float):
        r"""Loop integrals :math:`L(\bar d_{min}, \bar d_{max})` (module docstring), shape (n, 4).

        ``d_min`` 1-D, each ``<= d_max``.  Columns as in :func:`law_columns`; ``-L[:, 1]`` is the
        energy dissipated per cycle and per asperity, in :math:`Gb^2\sigma`.
        """
        d_min = np.asarray(d_min, dtype=float).ravel()
        out = np.zeros((d_min.size, 4))
        if self.width <= 0.0:
            return out
        sf = self.heights.sf
        u_c = np.maximum(self.u_end, self.u_in - (d_max - d_min))
        for value in np.unique(u_c):
            rows = np.flatnonzero(u_c == value)
            j, nodes, wq = self._partial(np.array([value]))
            start = (int(j[0]) + 1) * NODES_PER_PANEL
            u = np.concatenate([nodes[0], self.u[start:]])
            W = np.concatenate([wq[0], self.weights[start:]])
            count = sf(d_min[rows, None] + self.u_in) - sf(d_max + u[None, :])  # (rows, nodes)
            out[rows] = count @ W
        return out

    def loop_energy(self) -> float:
        r""":math:`e = -\int_{\bar u_{end}}^{\bar u_{in}} \bar P(\bar u)\,d\bar u` (:math:`Gb^2\sigma`):
        the energy one asperity dissipates going once through the whole loop (0 without one)."""
        return float(-self.weights[:, 1].sum()) if self.u.size else 0.0
