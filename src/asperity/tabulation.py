r"""Fast multi-asperity integrals: the per-asperity law tabulated on fixed quadrature nodes.

Written in the penetration :math:`\bar u = \bar z - \bar d`, each integral of
:mod:`asperity.multi_asperity` is :math:`\int q(\bar u)\,\phi(\bar d + \bar u)\,d\bar u`:
the per-asperity law :math:`q` (a :class:`~asperity.asperity_law.ContactLaw`) does not
depend on :math:`\bar d`.  A :class:`Tabulation` evaluates it once, on fixed Gauss-Legendre
panels split at the law's breakpoints (branch end, Hurtado-Kim radii), and each separation
then costs one row of exponentials and a matrix product.  Derivatives with respect to
:math:`\bar d` (for Newton's method, :mod:`asperity.load_control`) come from the same nodes.

References
----------
.. [1] Adams et al., Eqs (5), (6), (10), (18), (21).
.. [2] J. A. Greenwood, J. B. P. Williamson, Proc. R. Soc. A 295 (1966) 300.
"""

from __future__ import annotations

import numpy as np

from ._validation import as_float_array, check_bool, check_scalar_real, check_text
from .asperity_law import U_END_LIMIT, ContactLaw, ModelParameters, check_law, check_parameters
from .height_sums import HeightSums
from .heights import GAUSSIAN, HeightDistribution, check_heights
from .quadrature import NODES_PER_PANEL, composite_nodes, gauss_legendre, panel_edges

__all__ = ["D_MIN", "D_MAX", "COLUMNS", "Tabulation", "check_separation", "check_tabulation"]

#: Valid separations d/sigma: D_MAX beyond the end of the asperities' stable branch
#: (30 for Hertz) every quantity underflows double precision.
D_MIN, D_MAX = -1.0e4, 30.0

#: Column order of the tabulated integrals (the columns of :meth:`Tabulation.sums`).
COLUMNS = ("contacts", "P", "F", "area")
_BLOCK_SPAN = 24.0  # separations (in sigma) summed together
_BLOCK_ROWS = 2000  # and at most this many at once, to bound memory


def check_separation(d, name="d", d_max=D_MAX):
    """Separations as a float array within [D_MIN, d_max] (d_max: where everything underflows).

    Raises
    ------
    ValueError
        If ``d`` is not real and finite or lies outside the range, naming ``name``.
    """
    name = check_text(name, "name")
    d_max = check_scalar_real(d_max, "d_max")
    if not D_MIN < d_max <= D_MAX + U_END_LIMIT:
        raise ValueError(f"d_max must lie in ({D_MIN:g}, {D_MAX + U_END_LIMIT:g}], got {d_max!r}")
    d = as_float_array(d, name)
    if ((d < D_MIN) | (d > d_max)).any():
        raise ValueError(f"{name} (separation d/sigma) must lie in [{D_MIN:g}, d_max = {d_max:.6g}], "
                         f"got values from {d.min():g} to {d.max():g}")
    return d


class Tabulation:
    r"""The per-asperity integrands on fixed quadrature nodes, for separations in a range.

    Built once per parameter set and range, it gives the four integrals (contacts, P, F,
    area) and their derivatives in the separation at any separations in the range, at the
    cost of one row of density values per separation (:meth:`sums`).

    Parameters
    ----------
    params : ModelParameters
        Model parameters.
    d_min, d_max : float
        Range of separations :math:`d/\sigma` the nodes must serve, ``d_min <= d_max``.
    heights : HeightDistribution or str
        Asperity height distribution (default Gaussian, Eq 19).  One whose sums do not
        factorise (``fast_sums`` False) is tabulated in the separation and interpolated by
        :class:`asperity.height_sums.HeightSums`, to which :meth:`sums` then delegates.
    law : ContactLaw, optional
        Per-asperity law built for ``params`` (default: ``AsperityLaw(params)``, Hertz or
        Maugis-Dugdale with the friction law of ``params``).

    Raises
    ------
    ValueError
        If ``law`` is not a :class:`~asperity.asperity_law.ContactLaw` for ``params``, or
        ``heights`` is not a :class:`~asperity.heights.HeightDistribution`.

    Examples
    --------
    >>> from asperity.asperity_law import ModelParameters
    >>> tab = Tabulation(ModelParameters(0.01, 1000.0), -3.0, 10.0)
    >>> S0, S1 = tab.sums([0.0], order=1)  # columns: contacts, P, F, area
    >>> round(float(S0[0, 0]), 12), bool(S1[0, 1] < 0)  # half the asperities touch; P falls with d
    (0.5, True)
    """

    def __init__(self, params: ModelParameters, d_min: float, d_max: float,
                 heights: HeightDistribution = GAUSSIAN, law: ContactLaw | None = None):
        heights = check_heights(heights)
        self.params = check_parameters(params)
        self.heights = heights
        self.law = check_law(law, params)
        self.d_min, self.d_max = (check_scalar_real(x, n) for x, n in ((d_min, "d_min"), (d_max, "d_max")))
        top = D_MAX - self.law.u_end
        for x, n in ((self.d_min, "d_min"), (self.d_max, "d_max")):
            if not D_MIN <= x <= top:
                raise ValueError(f"{n} (separation d/sigma) must lie in [{D_MIN:g}, {top:.6g}], got {x!r}")
        if not self.d_min <= self.d_max:
            raise ValueError(f"d_min must be <= d_max, got {self.d_min!r} and {self.d_max!r}")
        # Heights whose sums do not factorise (all but the Gaussian and the wide mixtures) are
        # tabulated in the separation and interpolated: asperity.height_sums.
        self.height_sums = None
        if not heights.fast_sums:
            self.height_sums = hs = HeightSums(self.law, heights, self.d_min, self.d_max)
            self.edges, self.u, self.a_bar, self.weights = hs.edges, hs.u, hs.a_bar, hs.weights
            return
        law = self.law
        z_top = heights.z_top
        # For a separation d the integrand peaks at u* = max(u_end, -d) and is negligible
        # (< phi(z_top) relative) beyond u* + z_top and below z_bottom - d.
        u_top = max(z_top - self.d_min, law.u_end + z_top)
        u_bottom = heights.z_bottom - self.d_max
        first = law.scale
        for bp in law.breakpoints:
            if bp > law.u_end:
                first = min(first, (bp - law.u_end) / 3.0)
        first = min(first, 0.2)  # the s^4 panel: keep the density smooth in s across it
        edges = panel_edges(law.u_end, u_top, first, law.breakpoints, lo_clip=u_bottom)
        u, w = composite_nodes(edges)
        a, P = law.evaluate(u)
        F = law.friction(a)
        self.edges = edges
        self.u = u
        self.a_bar = a
        self.weights = w[:, None] * np.stack([np.ones_like(u), P, F, a * a], axis=1)
        self._split_panels()

    def _split_panels(self):
        """Group equal-width panels (their nodes share offsets) for the factorised sums."""
        n = NODES_PER_PANEL
        widths = np.diff(self.edges)
        uniform = np.zeros(widths.size, dtype=bool)
        uniform[1:] = widths[1:] == 1.0  # panel 0 carries the s^2 substitution
        if uniform.sum() < 4:
            uniform[:] = False
        node_mask = np.repeat(uniform, n)
        self.direct_u = self.u[~node_mask]
        self.direct_w = self.weights[~node_mask]
        left = self.edges[:-1][uniform]
        x, _ = gauss_legendre(n)
        self.centers = left + 0.5
        self.offsets = x - 0.5
        self.panel_w = self.weights[node_mask].reshape(left.size, n, self.weights.shape[1])

    def covers(self, d_min, d_max) -> bool:
        """Whether the nodes serve every separation in [d_min, d_max]."""
        return self.d_min <= d_min and d_max <= self.d_max

    def extended(self, d_min, d_max) -> Tabulation:
        """This tabulation if it covers [d_min, d_max], else a new one (same law and heights)
        over the union of both ranges."""
        if self.covers(d_min, d_max):
            return self
        wider = Tabulation(self.params, min(d_min, self.d_min), max(d_max, self.d_max), self.heights, law=self.law)
        if self.height_sums is not None:  # keep the separation panels already computed
            wider.height_sums.inherit(self.height_sums)
        return wider

    def sums(self, d, order=0):
        """``[S_0, .., S_order]``: the four integrals (columns) and their d-derivatives.

        Separations are sorted into blocks spanning at most a few sigma; each block sums
        only the nodes its height densities reach, so wide load ranges stay cheap.

        Raises
        ------
        ValueError
            If ``d`` is not real and finite or lies outside ``[d_min, d_max]`` (the nodes
            serve no other separation: :meth:`extended` first; heights tabulated in the
            separation, :class:`~asperity.height_sums.HeightSums`, serve their own, wider
            range), or ``order`` is not 0, 1 or 2.
        """
        if not (type(d) is np.ndarray and d.dtype == np.float64):  # the Newton steps pass float arrays
            d = as_float_array(d, "d", allow_empty=True)
        if d.size and not (d.min() >= self.d_min and d.max() <= self.d_max):  # NaN fails too
            d = as_float_array(d, "d")  # names a NaN or an infinity
        if self.height_sums is None and d.size and (d.min() < self.d_min or d.max() > self.d_max):
            raise ValueError(f"d (separation d/sigma) must lie in [{self.d_min:g}, {self.d_max:g}], the separations "
                             f"this tabulation serves (extend it first: tab.extended(d_min, d_max)); got values "
                             f"from {d.min():g} to {d.max():g}")
        if isinstance(order, bool) or order not in (0, 1, 2):
            raise ValueError(f"order must be 0, 1 or 2, got {order!r}")
        out = self._sums(d, order)
        # n/N = integral of phi <= 1: the quadrature's round-off can pass 1 by a few ulps
        out[0] = out[0].copy()
        np.minimum(out[0][:, 0], 1.0, out=out[0][:, 0])
        return out

    def _sums(self, d, order):
        if self.height_sums is not None:
            return list(self.height_sums.sums(d, order))
        d = np.asarray(d, dtype=float).ravel()
        out = [np.zeros((d.size, 4)) for _ in range(order + 1)]
        order_idx = np.argsort(d, kind="stable")
        ds = d[order_idx]
        z_top = self.heights.z_top
        i = 0
        while i < ds.size:
            j = int(np.searchsorted(ds, ds[i] + _BLOCK_SPAN, side="right"))
            j = min(j, i + _BLOCK_ROWS)
            block = ds[i:j]
            lo, hi = self.heights.z_bottom - float(block[-1]), max(self.law.u_end, -float(block[0])) + z_top
            for k, part in enumerate(self._block_sums(block, lo, hi, order)):
                out[k][order_idx[i:j]] = part
            i = j
        return out

    def _block_sums(self, block, lo, hi, order):
        h = self.heights
        if block.size <= 2:  # a Newton step's separation: one density row over the nodes in reach
            a, b = self.u.searchsorted(lo), self.u.searchsorted(hi)
            return h.weighted_sums(block, self.u[a:b], self.weights[a:b], order)
        a, b = self.direct_u.searchsorted(lo), self.direct_u.searchsorted(hi)
        parts = [h.weighted_sums(block, self.direct_u[a:b], self.direct_w[a:b], order)]
        a, b = self.centers.searchsorted(lo - 1.0), self.centers.searchsorted(hi + 1.0)
        if b > a:
            parts.append(h.panel_sums(block, self.centers[a:b], self.offsets, self.panel_w[a:b], order))
        if len(parts) == 1:
            return parts[0]
        return [p + q for p, q in zip(*parts, strict=True)]

    def evaluate(self, d):
        """Dict of contacts, P, F, area at separations ``d`` (any shape) in ``[d_min, d_max]``;
        a ValueError otherwise, as :meth:`sums`."""
        d = as_float_array(d, "d", allow_empty=True)
        s = self.sums(d)[0]
        return {name: s[:, i].reshape(d.shape) for i, name in enumerate(COLUMNS)}


def check_tabulation(tab, d_lo, d_hi, *, names=("d_lo", "d_hi"), covered=True) -> tuple[float, float]:
    """Check that ``tab`` is a :class:`Tabulation` serving the interval [d_lo, d_hi].

    Returns ``(d_lo, d_hi)`` as floats.  With ``covered=False`` the interval need not lie in
    the tabulation's range (for callers that widen it).

    Raises
    ------
    ValueError
        If ``tab`` is not a Tabulation, an end is not a real finite scalar, ``d_lo >= d_hi``,
        or (``covered``) the tabulation does not serve the interval.
    """
    if not isinstance(tab, Tabulation):
        raise ValueError(f"tab must be an asperity.tabulation.Tabulation, got {type(tab).__name__}")
    if not (isinstance(names, tuple | list) and len(names) == 2 and all(isinstance(n, str) for n in names)):
        raise TypeError(f"names must be two parameter names (str), got {names!r}")
    covered = check_bool(covered, "covered")
    d_lo, d_hi = (check_scalar_real(x, n) for x, n in zip((d_lo, d_hi), names, strict=True))
    top = D_MAX - tab.law.u_end
    for x, n in zip((d_lo, d_hi), names, strict=True):
        if not D_MIN <= x <= top:
            raise ValueError(f"{n} (separation d/sigma) must lie in [{D_MIN:g}, {top:.6g}], got {x!r}")
    if not d_lo < d_hi:
        raise ValueError(f"{names[0]} must be < {names[1]}, got {d_lo!r} and {d_hi!r}")
    if covered and not tab.covers(d_lo, d_hi):
        raise ValueError(f"{names[0]}, {names[1]} = {d_lo:g}, {d_hi:g} lie outside the separations the tabulation "
                         f"serves, [{tab.d_min:g}, {tab.d_max:g}]: use tab.extended({d_lo:g}, {d_hi:g})")
    return d_lo, d_hi

