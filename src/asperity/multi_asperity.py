r"""Greenwood-Williamson multi-asperity integrals at a separation (Eqs 5, 6, 9, 10, 18, 21).

All quantities are per asperity (divided by :math:`N`):

===============  ==========================================================  =========
quantity         integral over in-contact asperities                         equation
===============  ==========================================================  =========
contacts         :math:`n/N = \int\phi\,d\bar z`                              Eq 5
P                :math:`P/(NGb^2) = \int\bar P(\bar u)\phi\,d\bar z`          Eqs 6, 18
F                :math:`F/(NGb^2) = \int 2\pi\bar\tau_f\bar a^2\phi\,d\bar z`  Eqs 9, 10
area             :math:`A/(N\pi b^2) = \int\bar a^2\phi\,d\bar z`             Eq 21
===============  ==========================================================  =========

with :math:`\bar u = \bar z - \bar d`, from the end of the asperity's stable branch
(:math:`\bar u = 0` for Hertz) to infinity.

**How it is fast.**  Written in the penetration :math:`\bar u`, each integral is
:math:`\int q(\bar u)\,\phi(\bar d + \bar u)\,d\bar u`: the per-asperity law
:math:`q` does not depend on :math:`\bar d`.  A :class:`Tabulation` evaluates it once,
on fixed Gauss-Legendre panels split at the law's breakpoints (branch end, Hurtado-Kim
radii), and each separation then costs one row of exponentials and a matrix product.
Derivatives with respect to :math:`\bar d` (for Newton's method) come from the same
nodes.
"""

from __future__ import annotations

import numpy as np

from ._validation import as_float_array, check_poisson
from .asperity_law import AsperityLaw, ModelParameters
from .heights import GAUSSIAN, HeightDistribution
from .quadrature import NODES_PER_PANEL, composite_nodes, gauss_legendre, panel_edges

__all__ = [
    "D_MIN",
    "D_MAX",
    "Tabulation",
    "contact_fraction",
    "normal_force",
    "friction_force",
    "real_contact_area",
    "mean_pressure",
    "friction_coefficient",
]

#: Valid separations d/sigma: D_MAX beyond the end of the asperities' stable branch
#: (30 for Hertz) every quantity underflows double precision.
D_MIN, D_MAX = -1.0e4, 30.0

# Column order of the tabulated integrands.
_COLUMNS = ("contacts", "P", "F", "area")
_BLOCK_SPAN = 24.0  # separations (in sigma) summed together
_BLOCK_ROWS = 2000  # and at most this many at once, to bound memory


def check_separation(d, name="d", d_max=D_MAX):
    """Separations as a float array within [D_MIN, d_max] (d_max: where everything underflows)."""
    d = as_float_array(d, name)
    if np.any((d < D_MIN) | (d > d_max)):
        raise ValueError(f"{name} (separation d/sigma) must lie in [{D_MIN:g}, {d_max:.6g}], "
                         f"got values from {d.min():g} to {d.max():g}")
    return d


class Tabulation:
    """The per-asperity integrands on fixed quadrature nodes, for separations in a range.

    Parameters
    ----------
    params : ModelParameters
        Model parameters.
    d_min, d_max : float
        Range of separations the nodes must serve.
    heights : HeightDistribution
        Asperity height distribution (default Gaussian, Eq 19).
    """

    def __init__(self, params: ModelParameters, d_min: float, d_max: float,
                 heights: HeightDistribution = GAUSSIAN, law: AsperityLaw | None = None):
        self.params = params
        self.heights = heights
        self.law = law if law is not None else AsperityLaw(params)
        self.d_min, self.d_max = float(d_min), float(d_max)
        law = self.law
        z_top = heights.z_top
        # For a separation d the integrand peaks at u* = max(u_end, -d) and is negligible
        # (< phi(z_top) relative) beyond u* + z_top and below -d - z_top.
        u_top = max(z_top - self.d_min, law.u_end + z_top)
        u_bottom = -z_top - self.d_max
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
        return self.d_min <= d_min and d_max <= self.d_max

    def sums(self, d, order=0):
        """``[S_0, .., S_order]``: the four integrals (columns) and their d-derivatives.

        Separations are sorted into blocks spanning at most a few sigma; each block sums
        only the nodes its height densities reach, so wide load ranges stay cheap.
        """
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
            lo, hi = -block[-1] - z_top, max(self.law.u_end, -block[0]) + z_top
            for k, part in enumerate(self._block_sums(block, lo, hi, order)):
                out[k][order_idx[i:j]] = part
            i = j
        return out

    def _block_sums(self, block, lo, hi, order):
        h = self.heights
        a, b = np.searchsorted(self.direct_u, [lo, hi])
        parts = [h.weighted_sums(block, self.direct_u[a:b], self.direct_w[a:b], order)]
        a, b = np.searchsorted(self.centers, [lo - 1.0, hi + 1.0])
        if b > a:
            parts.append(h.panel_sums(block, self.centers[a:b], self.offsets, self.panel_w[a:b], order))
        return [sum(p[k] for p in parts) for k in range(order + 1)]

    def evaluate(self, d):
        """Dict of contacts, P, F, area at separations ``d`` (any shape)."""
        d = np.asarray(d, dtype=float)
        s = self.sums(d)[0]
        return {name: s[:, i].reshape(d.shape) for i, name in enumerate(_COLUMNS)}


def _integrals(d, alpha, beta, gamma, nu, h_over_b, friction, heights):
    kwargs = {} if friction is None else {"friction": friction}
    params = ModelParameters(alpha, beta, gamma, nu, h_over_b, **kwargs)
    if not isinstance(heights, HeightDistribution):
        raise ValueError("heights must be a HeightDistribution (e.g. asperity.GAUSSIAN)")
    law = AsperityLaw(params)
    d = check_separation(d, d_max=D_MAX - law.u_end)
    tab = Tabulation(params, float(d.min()), float(d.max()), heights, law=law)
    return tab.evaluate(d), params


def contact_fraction(d, alpha, beta, gamma=0.0, *, nu=0.3, h_over_b=1.0, friction=None,
                     heights=GAUSSIAN):
    r"""Fraction of asperities in contact, :math:`n/N = \int\phi(\bar z)\,d\bar z` (Eq 5).

    With adhesion the lower limit is the end of the stable branch (negative penetration),
    so adhesive contacts outnumber Hertzian ones at the same separation.

    Parameters
    ----------
    d : array_like
        Separation :math:`\bar d = d/\sigma` of the mean summit plane from the flat.
    alpha, beta, gamma, nu, h_over_b, friction :
        Model parameters, see :class:`~asperity.asperity_law.ModelParameters`.
    heights : HeightDistribution
        Height statistics (default: Gaussian, Eq 19).

    Returns
    -------
    ndarray
        :math:`n/N`, same shape as ``d``.

    References
    ----------
    Adams et al., Eq (5); Greenwood & Williamson (1966).
    """
    return _integrals(d, alpha, beta, gamma, nu, h_over_b, friction, heights)[0]["contacts"]


def normal_force(d, alpha, beta, gamma=0.0, *, nu=0.3, h_over_b=1.0, friction=None,
                 heights=GAUSSIAN):
    r"""Normal force per asperity :math:`\bar P = P/(NGb^2)` (Eq 6 for gamma = 0, Eq 18 otherwise).

    .. math::
        \gamma = 0:\ \bar P = \frac43\frac{2}{1-\nu}\alpha\beta^2
            \int_{\bar d}^\infty(\bar z-\bar d)^{3/2}\phi\,d\bar z,\qquad
        \gamma > 0:\ \bar P = \frac1{\hat P}\int_{\bar d+\bar u_{end}}^\infty
            P_M\big((\bar z-\bar d)/\hat\delta\big)\phi\,d\bar z

    Positive is compressive.  See :func:`contact_fraction` for the parameters.

    References
    ----------
    Adams et al., Eqs (6), (17) (with the corrected :math:`\hat P`) and (18).
    """
    return _integrals(d, alpha, beta, gamma, nu, h_over_b, friction, heights)[0]["P"]


def friction_force(d, alpha, beta, gamma=0.0, *, nu=0.3, h_over_b=1.0, friction=None,
                   heights=GAUSSIAN):
    r"""Friction force per asperity :math:`\bar F = F/(NGb^2)` (Eqs 9-10).

    .. math::
        \bar F = 2\pi\int\bar\tau_f(\bar a)\,\bar a^2\,\phi(\bar z)\,d\bar z

    with the Hurtado-Kim stress evaluated at the (adhesive, if gamma > 0) contact radius;
    the integral is split at the radii :math:`\bar a_1`, :math:`\bar a_2`.  See
    :func:`contact_fraction` for the parameters.

    References
    ----------
    Adams et al., Eqs (9), (10).
    """
    return _integrals(d, alpha, beta, gamma, nu, h_over_b, friction, heights)[0]["F"]


def real_contact_area(d, alpha, beta, gamma=0.0, *, nu=0.3, h_over_b=1.0, friction=None,
                      heights=GAUSSIAN):
    r"""Real contact area per asperity :math:`A/(N\pi b^2) = \int\bar a^2\phi\,d\bar z` (Eq 21).

    Without adhesion this equals :math:`\beta^2\int(\bar z-\bar d)\phi\,d\bar z`.  See
    :func:`contact_fraction` for the parameters.

    References
    ----------
    Adams et al., Eq (21).
    """
    return _integrals(d, alpha, beta, gamma, nu, h_over_b, friction, heights)[0]["area"]


def mean_pressure(P, area, nu=0.3):
    r"""Mean contact pressure :math:`P/(E^*A) = \bar P(1-\nu)/(2\pi\bar A)` (Fig 9).

    Parameters
    ----------
    P : array_like
        :math:`P/(NGb^2)`.
    area : array_like
        :math:`A/(N\pi b^2)`; where it is 0 (no contact) the result is NaN.
    nu : float
        Poisson's ratio (:math:`E^*/G = 2/(1-\nu)`).
    """
    P = np.asarray(P, dtype=float)
    area = np.asarray(area, dtype=float)
    nu = check_poisson(nu)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(area > 0, P * (1.0 - nu) / (2.0 * np.pi * np.where(area > 0, area, 1.0)),
                        np.nan)


def friction_coefficient(F, P):
    r"""Friction coefficient :math:`\mu = F/P` (Eq 1); NaN where :math:`P \le 0` (undefined).

    Under zero or tensile load an adhesive contact still has a finite friction force, so
    :math:`\mu` is infinite or meaningless there; NaN marks it.
    """
    F = np.asarray(F, dtype=float)
    P = np.asarray(P, dtype=float)
    with np.errstate(over="ignore"):  # a finite friction over a vanishing load: mu = inf
        return np.where(P > 0, F / np.where(P > 0, P, 1.0), np.nan)
