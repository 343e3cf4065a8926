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
    edges, unit panels), cut at :math:`\bar u_{in}`; the panel holding :math:`\bar u_c` is
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
        self.edges = np.append(edges[keep], self.u_in)
        u, w = composite_nodes(self.edges)
        self.u = u
        self.weights = w[:, None] * law_columns(law, u)

    @property
    def panels(self) -> int:
        """Number of panels."""
        return self.edges.size - 1

    def _partial(self, u_c, edge=False, anchored=None):
        """Nodes and weighted integrands on [u_c, next edge] for each u_c: (m, 16), (m, 16, 4); with
        ``edge``, also the integrands at u_c itself, (m, 4) (one call of the law for both).
        Where ``anchored`` (m booleans) is True, u_c is a support edge of the heights' density,
        which starts there like (u - u_c)^p (p: :attr:`~asperity.heights.HeightDistribution.edge_power`);
        the panel is integrated in s, u = u_c + (right - u_c) s^k with k = 4/(p + 1), which makes
        the integrand start like s^3."""
        x, w = gauss_legendre(NODES_PER_PANEL)
        j = np.clip(np.searchsorted(self.edges, u_c, side="right") - 1, 0, self.panels - 1)
        anchored = np.zeros(u_c.size, dtype=bool) if anchored is None else anchored
        # an edge just below a panel's end would leave the next (fixed) panel next to the density's
        # power-law start: that panel joins the substituted one
        near = anchored & (j + 2 <= self.panels)
        near[near] = (self.edges[j[near] + 1] - u_c[near]) < 0.5 * (self.edges[j[near] + 2] - self.edges[j[near] + 1])
        j = j + near
        right = self.edges[j + 1]
        nodes = u_c[:, None] + (right - u_c)[:, None] * x[None, :]
        weights = (right - u_c)[:, None] * w[None, :]
        first = (j == 0) & ~anchored  # in s, u = u_end + s^4: analytic at the branch end
        if np.any(anchored):
            p = float(self.heights.edge_power)
            k = 4.0 / (p + 1.0) if math.isfinite(p) else 1.0  # flatter than any power: no substitution
            width = (right - u_c)[anchored, None]
            nodes[anchored] = u_c[anchored, None] + width * x[None, :] ** k
            weights[anchored] = k * x[None, :] ** (k - 1.0) * width * w[None, :]
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
        heights' support starts above :math:`d + u_c` (a lowest summit: exponential, Weibull,
        Pearson III heights) the integral starts at the edge :math:`u_e = z_{lo} - d`, and
        :math:`B_1` gains :math:`q(u_e)\phi(z_{lo}^+)` (that lower limit moves with :math:`d`).
        With ``edge``, the integrands at the lower limits (shape (n, 4)) are appended to the list.
        """
        if order not in (0, 1):
            raise ValueError(f"order must be 0 or 1, got {order!r}")
        d = np.asarray(d, dtype=float).ravel()
        u_c = np.asarray(u_c, dtype=float).ravel()
        out = [np.zeros((d.size, 4)) for _ in range(order + 1)]
        if self.width <= 0.0 or d.size == 0:
            return out + ([np.zeros((d.size, 4))] if edge else [])
        h = self.heights
        # Below the support's lower edge the density is 0: the integral starts at the edge
        # (found by a review: Gauss-Legendre across the exponential's jump erred by 5 %).
        z_lo = float(h.support[0])
        at_edge = (z_lo - d > u_c) if math.isfinite(z_lo) else np.zeros(d.size, dtype=bool)
        u_lo = np.where(at_edge, np.minimum(z_lo - d, self.u_in), u_c)
        uniq, inv = np.unique(u_lo, return_inverse=True)
        anchored = np.zeros(uniq.size, dtype=bool)
        anchored[inv[at_edge]] = True
        j, nodes, wq, q_c = self._partial(uniq, edge=True, anchored=anchored)
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
        moving = at_edge & (z_lo - d < self.u_in)
        if order == 1 and np.any(moving):
            p = float(h.edge_power)
            if 0.0 < p < 1.0:  # phi' ~ (z - z_lo)^(p - 1): integrated by parts on the edge's panel
                rows = np.flatnonzero(moving)
                c = inv[rows]
                x = d[rows, None] + nodes[c]
                out[1][rows] += self._by_parts(j[c], nodes[c], wq[c], x) - np.einsum(
                    "nj,njc->nc", h.pdf_derivative(x, 1), wq[c])
            else:  # the density's jump at the edge (0 for p >= 1)
                out[1][moving] += q_c[inv[moving]] * float(h.pdf(np.array([z_lo]))[0])
        return out + ([q_c[inv]] if edge else [])

    def _by_parts(self, j, nodes, wq, x):
        r""":math:`\int_{u_e}^{R} q\,\phi'(d + u)\,du + q(u_e)\phi(z_{lo}^+)
        = q(R)\phi(d + R) - \int_{u_e}^{R} q_u\,\phi(d + u)\,du` on the edge's panel (nodes,
        weighted integrands ``wq`` and ``x = d + u`` per row), :math:`q_u` by central differences."""
        h = self.heights
        right = self.edges[j + 1]
        step = 1e-6 * np.maximum(1.0, np.abs(nodes))
        q_u = (law_columns(self.law, (nodes + step).ravel()) - law_columns(self.law, (nodes - step).ravel())) \
            / (2.0 * step.ravel())[:, None]
        weights = wq[:, :, 0]  # the quadrature weights: the contacts column is 1 above u_end
        integral = np.einsum("nj,njc->nc", h.pdf(x) * weights, q_u.reshape(*nodes.shape, 4))
        end = law_columns(self.law, right) * h.pdf(x[:, 0] - nodes[:, 0] + right)[:, None]
        return end - integral

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
