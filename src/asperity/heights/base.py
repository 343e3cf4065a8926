r"""The interface every summit-height distribution implements, and its generic GW moment.

Heights :math:`\bar z` are in units of the summit-height standard deviation
:math:`\sigma_s`, measured from the mean summit height: every distribution here is
*standardised*, zero mean and unit variance, like the paper's Gaussian (Eq 19).  The model
only ever needs the density :math:`\phi` (and its first two derivatives, for Newton's
method in the separation), its survival function and where its tails become negligible;
the multi-asperity integrals call

.. math::
    S_j(\bar d) = \sum_k w_k\, q_k\, \phi^{(j)}(\bar d + \bar u_k)

through :meth:`HeightDistribution.weighted_sums` and :meth:`HeightDistribution.panel_sums`
(quadrature nodes :math:`\bar u_k` in penetration, per-asperity law :math:`q_k`).

Attributes the integrals read (see :class:`HeightDistribution`):

==================  ==================================================================
``z_bottom``        heights below carry a negligible share (cdf < :data:`TAIL`)
``z_top``           heights above carry a negligible share (sf < :data:`TAIL`); also the
                    reach of the density above the integrand's lower limit
``support``         ``(lo, hi)``, where the density is non-zero (edges are kinks)
``z_end``           above it the survival function is below :data:`SF_FLOOR` (or 0)
``resolution``      smallest width (in sigma) over which the density changes
``fast_sums``       True if ``weighted_sums``/``panel_sums`` are cheap per separation
==================  ==================================================================

The Greenwood-Williamson moment

.. math::
    F_n(\bar d) = \int_{\bar d}^\infty (\bar z - \bar d)^n\,\phi(\bar z)\,d\bar z

gives the Hertz-law integrals in closed form (:math:`n/N = F_0`, :math:`A \propto F_1`,
:math:`P \propto F_{3/2}`); :func:`gw_moment_quadrature` computes it for any distribution
with fixed high-order quadrature, and families with a closed form override
:meth:`HeightDistribution.moment`.

References
----------
.. [1] J. A. Greenwood, J. B. P. Williamson, Proc. R. Soc. A 295 (1966) 300, Eqs (2)-(5).
.. [2] Adams et al., Eqs (5), (6), (19), (21).
"""

from __future__ import annotations

import abc
import functools
import math
from typing import ClassVar

import numpy as np

from .._validation import as_float_array, ufunc_result
from .._validation_files import short_repr
from ..quadrature import gauss_legendre
from .checks import MAX_ORDER, check_derivative_order, check_order, checked_density

__all__ = ["HeightDistribution", "TAIL", "SF_FLOOR", "EDGE_BAND", "MAX_ORDER", "check_heights", "check_order",
           "check_derivative_order", "tanh_sinh",
           "gw_moment_quadrature", "decay_length"]

#: Tail share taken as negligible: z_top and z_bottom are where sf and cdf fall below it
#: (the Gaussian's z_top = 10 has sf = 7.6e-24).
TAIL = 1e-23
#: Below this survival function the integrals are taken as zero (``z_end``).
SF_FLOOR = 1e-280
#: Within this distance (in sigma) of a finite support edge a density may vary on any scale
#: (a power law, a jump, Johnson S_B's logarithmic pile-up): ``resolution`` ignores the band,
#: and the integrals integrate it with tanh-sinh instead of the fixed panels.
EDGE_BAND = 2.0


class HeightDistribution(abc.ABC):
    r"""Interface of a standardised distribution of summit heights (in units of sigma_s).

    A subclass implements :meth:`pdf`, :meth:`pdf_derivative` and :meth:`sf`, vectorised
    over arrays of any shape, and sets the attributes below (class or instance
    attributes).  The multi-asperity integrals call :meth:`weighted_sums` and
    :meth:`panel_sums`; the defaults form density matrices.  When ``fast_sums`` is False
    (the default) the integrals are tabulated in the separation and interpolated
    (:mod:`asperity.height_sums`), which also handles the edges of a finite support; the
    Gaussian and the mixtures factorise their sums and set it True.

    Attributes
    ----------
    z_top, z_bottom : float
        Heights above ``z_top`` and below ``z_bottom`` carry a negligible share of every
        integral (Gaussian: 10 and -10).  A subclass that sets only ``z_top`` gets
        ``z_bottom = -z_top``.
    support : tuple of float
        ``(lo, hi)``: the density vanishes outside (``-inf``, ``inf`` if unbounded).
    z_end : float
        Above it the survival function is below :data:`SF_FLOOR`, or zero.
    resolution : float
        Smallest width, in sigma, over which the density changes (> 0, at most 1), away
        from a finite support edge (:data:`EDGE_BAND`): quadrature and interpolation panels
        are no wider than twice it.
    panel_resolutions : float
        Width of the separation panels the integrals interpolate on, in resolutions (2; a
        two-width mixture needs 1.5).
    edge_power : float
        The density behaves like (distance to a finite support edge)^edge_power next to it
        (0: a jump, the default; ``inf``: flatter than any power); sets how finely the
        integrals resolve the separations where an edge meets the law's endpoint.
    fast_sums : bool
        Whether :meth:`weighted_sums`/:meth:`panel_sums` are cheap enough to be called for
        every separation (True for the Gaussian and the mixtures).
    name : str
        Registry name (:data:`asperity.heights.DISTRIBUTIONS`).
    parameters : tuple of str
        Names of the parameters of the command-line spelling (``weibull:skew=0.5``).
    """

    z_top: float = 10.0
    z_bottom: float = -10.0
    support: tuple[float, float] = (-math.inf, math.inf)
    z_end: float = 35.0
    resolution: float = 1.0
    panel_resolutions: float = 2.0
    edge_power: float = 0.0
    fast_sums: bool = False
    name: ClassVar[str] = ""
    parameters: ClassVar[tuple[str, ...]] = ()

    def __init_subclass__(cls, **kwargs):
        super().__init_subclass__(**kwargs)
        if "z_top" in cls.__dict__ and "z_bottom" not in cls.__dict__:
            cls.z_bottom = -cls.z_top  # the symmetric cut-off of the original interface
        for name in ("pdf", "sf", "pdf_derivative"):  # every family's, checked the same way
            method = cls.__dict__.get(name)
            if method is not None and not getattr(method, "_checked", False):
                setattr(cls, name, checked_density(method, name))

    def __repr__(self) -> str:
        """``Name()``, so signatures and help() show the distribution, not an object address
        (a distribution with parameters shows them, as a dataclass does).

        >>> from asperity.heights import GAUSSIAN
        >>> GAUSSIAN
        Gaussian()
        """
        return f"{type(self).__name__}()"

    @property
    def spec(self) -> str:
        """The command-line spelling, e.g. ``'weibull:skew=0.5'`` (:func:`asperity.heights.parse_heights`)."""
        values = ",".join(f"{p}={getattr(self, p)!r}" for p in self.parameters)
        return f"{self.name}:{values}" if values else self.name

    def translates(self):
        """``(weights, centres, width)`` if the density is a sum of one Gaussian kernel's translates, else None.

        The integrals of such a density are those of the kernel, shifted and summed
        (:mod:`asperity.height_sums`); :class:`~asperity.heights.Empirical` is one.
        """
        return None

    @abc.abstractmethod
    def pdf(self, z):
        """Probability density phi(z)."""

    @abc.abstractmethod
    def pdf_derivative(self, z, order: int):
        """d^order phi / dz^order at z (order 1 or 2)."""

    @abc.abstractmethod
    def sf(self, z):
        """Survival function: the fraction of asperities higher than z."""

    def stats(self) -> tuple[float, float, float, float]:
        """``(mean, variance, skewness, kurtosis)`` (kurtosis 3 for a Gaussian), by quadrature.

        Families override this with closed forms; for a standardised distribution the first
        two are 0 and 1.
        """
        m = [float(_full_moment(self, k)) for k in range(1, 5)]
        var = m[1] - m[0] ** 2
        mu3 = m[2] - 3 * m[0] * m[1] + 2 * m[0] ** 3
        mu4 = m[3] - 4 * m[0] * m[2] + 6 * m[0] ** 2 * m[1] - 3 * m[0] ** 4
        return m[0], var, mu3 / var**1.5, mu4 / var**2

    def weighted_sums(self, d, u, weights, order: int = 0):
        r"""Return ``[S_0, ..., S_order]``, :math:`S_j[i, c] = \sum_k W[k, c]\phi^{(j)}(d_i + u_k)`.

        ``weights`` is a (nodes, columns) matrix.  The default forms the density matrices;
        subclasses may do better.
        """
        x = d[:, None] + u[None, :]
        out = [self.pdf(x) @ weights]
        for j in range(1, order + 1):
            out.append(self.pdf_derivative(x, j) @ weights)
        return out

    def panel_sums(self, d, centers, offsets, weights, order: int = 0):
        """:meth:`weighted_sums` for nodes ``centers[p] + offsets[j]`` (weights (P, J, c))."""
        u = (centers[:, None] + offsets[None, :]).ravel()
        return self.weighted_sums(d, u, weights.reshape(u.size, -1), order)

    def moment(self, d, order):
        r"""Greenwood-Williamson moment :math:`F_n(\bar d) = \int_{\bar d}^\infty(\bar z-\bar d)^n\phi\,d\bar z`.

        The default is fixed high-order quadrature (:func:`gw_moment_quadrature`); families
        with a closed form override it.

        Parameters
        ----------
        d : array_like
            Separation :math:`\bar d` (any shape, finite).
        order : float
            :math:`-1 < n \le` :data:`MAX_ORDER` (0: contact fraction, 1: area, 3/2: Hertz load).

        Returns
        -------
        ndarray
            :math:`F_n(\bar d)`, shape of ``d``.

        Raises
        ------
        ValueError
            If ``d`` is not real and finite, ``order`` out of range, or the moment leaves
            double precision.
        """
        d = as_float_array(d, "d", allow_empty=True)
        n = check_order(order)
        return self._checked_moment(lambda x: gw_moment_quadrature_unchecked(self, x, n), d, n)

    def _checked_moment(self, raw, d, n):
        """``raw(d)`` (a family's form of F_n) without warnings; entries where an intermediate
        overflowed (a closed form far in a tail) are redone by :func:`gw_moment_quadrature`,
        whose terms stay finite; a moment that itself leaves double precision is a ValueError."""
        with np.errstate(all="ignore"):
            try:
                out = np.array(raw(d), dtype=float)
            except ValueError:  # a closed form that checks its own result (Gaussian, mixtures) overflowed
                out = np.full(d.shape, np.nan)
            bad = ~np.isfinite(out)
            if bad.any():
                out[bad] = gw_moment_quadrature_unchecked(self, d[bad], n)
        bad = ~np.isfinite(out)
        if bad.any():
            raise ValueError(f"the GW moment of order {n:g} overflows double precision at d = {short_repr(d[bad])}: "
                             "give separations of physical size (within a few hundred sigma)")
        return ufunc_result(out)


def check_heights(heights) -> HeightDistribution:
    """``heights`` if it is a :class:`HeightDistribution`; a spec string (``'weibull:skew=0.5'``,
    ``'empirical:FILE'``, as the command line's ``--heights``) read by
    :func:`asperity.heights.parse_heights`; else a ValueError saying how to get one."""
    if isinstance(heights, str):
        from .registry import parse_heights

        return parse_heights(heights)
    if not isinstance(heights, HeightDistribution):
        raise ValueError("heights must be a HeightDistribution (e.g. asperity.GAUSSIAN, or "
                         f"asperity.heights.parse_heights('weibull:skew=0.5')) or such a spec string, got {heights!r}")
    return heights


@functools.lru_cache(maxsize=4)
def tanh_sinh(step: float = 0.1, t_max: float = 3.3):
    r"""Tanh-sinh (double-exponential) rule on [0, 1]: nodes, their distance to 1, weights.

    .. math::
        x = \tfrac12\big(1 + \tanh(\tfrac\pi2\sinh t)\big),\qquad
        w = \tfrac\pi4\,h\cosh t/\cosh^2(\tfrac\pi2\sinh t),\qquad t = kh,\ |t|\le t_{max}

    Integrable endpoint singularities (a density's support edge, :math:`(z-d)^n`) and
    singularities just outside an endpoint cost nothing: with the default 67 nodes
    :math:`\int_0^1 (x+\delta)^a e^{-x}dx` is exact to 2e-15 for :math:`a \ge 10^{-4}`,
    :math:`0 \le \delta`.

    Returns
    -------
    x, one_minus_x, w : ndarray
        Nodes, ``1 - x`` without cancellation, and weights.

    References
    ----------
    H. Takahasi, M. Mori, Publ. RIMS Kyoto Univ. 9 (1974) 721.
    """
    t = np.arange(-t_max, t_max + step / 2, step)
    s = 0.5 * np.pi * np.sinh(t)
    x = 1.0 / (1.0 + np.exp(-2.0 * s))
    one_minus_x = 1.0 / (1.0 + np.exp(2.0 * s))
    w = step * 0.25 * np.pi * np.cosh(t) / np.cosh(s) ** 2
    keep = (w > 0) & (x > 0) & (one_minus_x > 0)
    return x[keep], one_minus_x[keep], w[keep]


def _pieces(dist: HeightDistribution, span: float, first: float | None = None):
    """Distances t from the lower end and weights on [0, span]: tanh-sinh on the end pieces
    (a support edge, :math:`(z-d)^n`), 20-point Gauss-Legendre between, the panels growing
    geometrically from ``first`` (the tail's decay length) to the resolution."""
    width = min(1.0, 2.0 * dist.resolution)
    first = width if first is None or not first > 0 else min(width, max(first, 1e-12 * width))
    x, xm, w = tanh_sinh()
    if span <= 2.0 * first:
        return span * x, span * w
    nodes, weights = [first * x, span - first * xm[::-1]], [first * w, first * w[::-1]]
    edges, t = [first], first
    step = first
    while t < span - first:
        step = min(2.0 * step, width)
        t = min(t + step, span - first)
        edges.append(t)
    edges = np.array(edges)
    g, gw = gauss_legendre(20)
    h = np.diff(edges)
    nodes.append((edges[:-1, None] + h[:, None] * g[None, :]).ravel())
    weights.append((h[:, None] * gw[None, :]).ravel())
    return np.concatenate(nodes), np.concatenate(weights)


def decay_length(dist: HeightDistribution, z: float) -> float:
    """``sf(z)/pdf(z)``, the length over which the upper tail falls by e at height z (inf where pdf = 0)."""
    f = float(dist.pdf(z))
    return float(dist.sf(z)) / f if f > 0 else math.inf


def gw_moment_quadrature(dist: HeightDistribution, d, order: float):
    r"""GW moment :math:`F_n(\bar d) = \int_{\bar d}^\infty(\bar z-\bar d)^n\phi(\bar z)\,d\bar z` by quadrature.

    .. math::
        F_n(\bar d) \approx \int_{a}^{b}(\bar z-\bar d)^n\phi(\bar z)\,d\bar z,\quad
        a = \max(\bar d, z_{lo}, z_{bottom}),\quad b = \min(z_{hi}, a + z_{top} - z_{bottom})

    on fixed panels no wider than twice the distribution's resolution: tanh-sinh on the
    first and last (the :math:`(\bar z-\bar d)^n` endpoint and a support edge), 20-point
    Gauss-Legendre between; far in a light tail the first panels shrink to half the decay
    length :math:`Q(a)/\phi(a)` and grow geometrically.  The truncation drops a share below :data:`TAIL` (the upper end
    reaches as far above :math:`a` as the distribution's whole range, so the relative
    accuracy holds far in the upper tail).

    Parameters
    ----------
    dist : HeightDistribution
        The distribution.
    d : ndarray
        Separations :math:`\bar d` (any shape, finite).
    order : float
        :math:`n > -1`.

    Returns
    -------
    ndarray
        :math:`F_n(\bar d)`, shape of ``d``.

    Raises
    ------
    TypeError
        If ``dist`` is not a :class:`HeightDistribution`.
    ValueError
        If ``d`` is not real and finite, ``order`` is outside (-1, 20], or the moment
        leaves double precision.

    References
    ----------
    Greenwood & Williamson (1966), Eqs (2)-(5).
    """
    if not isinstance(dist, HeightDistribution):  # a user trial: None gave an AttributeError, NaN a 0
        raise TypeError(f"dist must be an asperity.heights.HeightDistribution, got {type(dist).__name__}")
    d, n = as_float_array(d, "d", allow_empty=True), check_order(order)
    with np.errstate(all="ignore"):
        out = gw_moment_quadrature_unchecked(dist, d, n)
    if not np.isfinite(out).all():
        raise ValueError(f"the GW moment of order {n:g} overflows double precision at d = "
                         f"{short_repr(d[~np.isfinite(out)])}: give separations of physical size")
    return ufunc_result(out)


def gw_moment_quadrature_unchecked(dist, d, order):
    """:func:`gw_moment_quadrature` without its checks, for the distributions' own calls on
    arguments they checked: ``d`` a float array, ``order`` in (-1, 20]; where a term
    overflows the result is inf (the callers redo or refuse it)."""
    d = np.asarray(d, dtype=float)
    lo_s, hi_s = dist.support
    out = np.zeros(d.shape)
    flat = out.reshape(-1)
    for i, di in enumerate(d.reshape(-1)):
        a = max(di, lo_s, dist.z_bottom)
        b = min(hi_s, a + dist.z_top - dist.z_bottom)
        if not a < b:
            continue
        t, w = _pieces(dist, b - a, 0.5 * decay_length(dist, a))
        flat[i] = np.sum(w * ((a - di) + t) ** order * dist.pdf(a + t))
    return out


def _full_moment(dist: HeightDistribution, k: int) -> float:
    """:math:`E[z^k]` by the same quadrature over the whole (truncated) support."""
    lo = max(dist.support[0], dist.z_bottom)
    hi = min(dist.support[1], dist.z_top)
    t, w = _pieces(dist, hi - lo)
    return float(np.sum(w * (lo + t) ** k * dist.pdf(lo + t)))
