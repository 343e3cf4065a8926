r"""Gaussian mixtures: two-process (plateau-honed) surfaces, and the sums every mixture shares.

A plateau-honed (two-process) surface is a fine plateau texture cut into a coarser valley
structure; its height distribution is a superposition of two Gaussians, bimodal only for
some ratios of the plateau and valley roughness.  Standardised,

.. math::
    \phi(\bar z) = \sum_i \frac{w_i}{s_i}\,\varphi\!\Big(\frac{\bar z - m_i}{s_i}\Big),\qquad
    \sum_i w_i m_i = 0,\quad \sum_i w_i(s_i^2 + m_i^2) = 1,

and every integral of the model is a weighted sum of Gaussian ones:

.. math::
    F_n(\bar d) = \sum_i w_i\,s_i^n\,G_n\!\Big(\frac{\bar d - m_i}{s_i}\Big),\qquad
    S_j(\bar d) = \sum_i \frac{w_i}{s_i^{1+j}}\,S^{G}_j\!\Big(\frac{\bar d - m_i}{s_i};
        \frac{\bar u}{s_i}\Big)

with :math:`G_n` the Gaussian GW moment (the parabolic-cylinder form,
:func:`~asperity.heights.gaussian.gaussian_moment`) and :math:`S^G_j` the Gaussian's
factorised quadrature sums on nodes scaled by :math:`1/s_i`.  Two identical components
are the Gaussian, exactly.  The kernel estimate of :mod:`asperity.heights.empirical` is a
mixture too.

References
----------
.. [1] ISO 13565-3:1998 (plateau and valley components of stratified surfaces).
.. [2] Materials 13 (2020) 4037; Materials 15 (2022) 268 (two-process surfaces, bimodality).
.. [3] Greenwood & Williamson (1966) for the GW moments.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from scipy import special

from .._validation import as_float_array, check_finite_result, check_scalar_range, ufunc_result
from .base import HeightDistribution, check_derivative_order, check_order
from .gaussian import GAUSSIAN, gaussian_moment

__all__ = ["Mixture", "GaussianSum", "KernelGaussian", "mixture_pdf", "mixture_pdf_derivative", "mixture_sf",
           "mixture_moment", "mixture_weighted_sums", "mixture_panel_sums", "mixture_stats", "FAST_WIDTH"]

_SQRT_2PI = math.sqrt(2.0 * math.pi)
#: Narrowest component the unit quadrature panels of the fast (factorised) path resolve:
#: 16-point Gauss-Legendre on a unit panel integrates a Gaussian of this width to ~1e-15.
FAST_WIDTH = 0.4


def _standard(z, means, sds):
    """(z - m_i)/s_i with the components along a new last axis."""
    z = np.asarray(z, dtype=float)
    return (z[..., None] - np.asarray(means)) / np.asarray(sds)


def mixture_pdf(z, weights, means, sds):
    r"""Density :math:`\sum_i (w_i/s_i)\varphi((z - m_i)/s_i)`, shape of ``z``."""
    x = _standard(z, means, sds)
    return np.exp(-0.5 * x * x) @ (np.asarray(weights) / np.asarray(sds)) / _SQRT_2PI


def mixture_pdf_derivative(z, order, weights, means, sds):
    r"""First or second derivative of the mixture density, shape of ``z``."""
    order = check_derivative_order(order)
    x = _standard(z, means, sds)
    poly = -x if order == 1 else x * x - 1.0
    return (poly * np.exp(-0.5 * x * x)) @ (np.asarray(weights) / np.asarray(sds) ** (1 + order)) / _SQRT_2PI


def mixture_sf(z, weights, means, sds):
    r"""Survival function :math:`\sum_i w_i Q((z - m_i)/s_i)`, shape of ``z``."""
    return special.ndtr(-_standard(z, means, sds)) @ np.asarray(weights)


def mixture_moment(d, order, weights, means, sds):
    r"""GW moment :math:`\sum_i w_i s_i^n G_n((\bar d - m_i)/s_i)` (module docstring), shape of ``d``."""
    d = as_float_array(d, "d", allow_empty=True)
    order = check_order(order)
    with np.errstate(all="ignore"):
        out = sum(w * s**order * gaussian_moment((d - m) / s, order)
                  for w, m, s in zip(weights, means, sds, strict=True))
    return ufunc_result(check_finite_result(out, f"the mixture's moment of order {order:g}", d=d))


def mixture_stats(weights, means, sds) -> tuple[float, float, float, float]:
    """Mean, variance, skewness and kurtosis of a Gaussian mixture (closed form)."""
    w, m, s = (np.asarray(x, dtype=float) for x in (weights, means, sds))
    mean = float(np.sum(w * m))
    c = m - mean
    var = float(np.sum(w * (s * s + c * c)))
    mu3 = float(np.sum(w * (c**3 + 3 * c * s * s)))
    mu4 = float(np.sum(w * (c**4 + 6 * c * c * s * s + 3 * s**4)))
    v = np.float64(var)  # NumPy arithmetic: an overflow is inf under the caller's errstate, not OverflowError
    return mean, var, float(mu3 / v**1.5), float(mu4 / v**2)


def mixture_weighted_sums(d, u, W, order, weights, means, sds):
    """The quadrature sums of a mixture, each component through the Gaussian's (module docstring)."""
    out = None
    for w, m, s in zip(weights, means, sds, strict=True):
        parts = GAUSSIAN.weighted_sums((d - m) / s, u / s, W, order)
        out = _accumulate(out, parts, w, s)
    return out


def mixture_panel_sums(d, centers, offsets, W, order, weights, means, sds):
    """The panel sums of a mixture, each component through the Gaussian's factorised ones."""
    out = None
    for w, m, s in zip(weights, means, sds, strict=True):
        parts = GAUSSIAN.panel_sums((d - m) / s, centers / s, offsets / s, W, order)
        out = _accumulate(out, parts, w, s)
    return out


def _accumulate(out, parts, w, s):
    scaled = [p * (w / s ** (1 + j)) for j, p in enumerate(parts)]
    return scaled if out is None else [o + p for o, p in zip(out, scaled, strict=True)]


class GaussianSum(HeightDistribution):
    """A density that is a weighted sum of Gaussians (:class:`Mixture`, the kernel estimate
    :class:`~asperity.heights.Empirical`): everything from ``self._components``, the tuple
    ``(weights, means, deviations)`` a subclass sets, through the closed forms above."""

    _components: tuple

    def pdf(self, z):
        """Density :math:`\\sum_i (w_i/s_i)\\varphi((z-m_i)/s_i)`."""
        return mixture_pdf(z, *self._components)

    def pdf_derivative(self, z, order: int):
        """First or second derivative of the density."""
        order = check_derivative_order(order)
        return mixture_pdf_derivative(z, order, *self._components)

    def sf(self, z):
        """Survival function :math:`\\sum_i w_i Q((z - m_i)/s_i)`."""
        return mixture_sf(z, *self._components)

    def stats(self) -> tuple[float, float, float, float]:
        """Mean (0), variance (1), skewness and kurtosis in closed form."""
        return mixture_stats(*self._components)

    def weighted_sums(self, d, u, weights, order: int = 0):
        return mixture_weighted_sums(d, u, weights, order, *self._components)

    def panel_sums(self, d, centers, offsets, weights, order: int = 0):
        return mixture_panel_sums(d, centers, offsets, weights, order, *self._components)


@dataclass(frozen=True)
class Mixture(GaussianSum):
    r"""Two Gaussian components, standardised to zero mean and unit variance (module docstring).

    The parameters may be given in any unit (e.g. the plateau and valley roughness of
    ISO 13565-3 in micrometres); the mixture is shifted and scaled to zero mean and unit
    variance, and the attributes hold the standardised values.

    Parameters
    ----------
    w : float
        Weight of the first component, in (0, 1].
    m1, s1 : float
        Mean and standard deviation (> 0) of the first component.
    m2, s2 : float
        Mean and standard deviation (> 0) of the second component.

    Examples
    --------
    >>> Mixture(0.5, 0.0, 2.0, 0.0, 2.0)  # two identical components: the Gaussian
    Mixture(w=0.5, m1=0.0, s1=1.0, m2=0.0, s2=1.0)
    >>> plateau = Mixture(w=0.8, m1=0.5, s1=0.5, m2=-2.0, s2=1.2)
    >>> [round(x, 3) for x in plateau.stats()]
    [0.0, 1.0, -1.613, 5.355]
    """

    w: float = 0.8
    m1: float = 0.3
    s1: float = 0.6
    m2: float = -1.2
    s2: float = 1.2
    panel_resolutions = 1.5  # the narrow component hands its tail to the wide one
    name: ClassVar[str] = "mixture"
    parameters: ClassVar[tuple[str, ...]] = ("w", "m1", "s1", "m2", "s2")

    def __post_init__(self):
        w = check_scalar_range(self.w, "w", 0.0, 1.0, what="weight of the first component")
        if w == 0.0:
            raise ValueError("w (weight of the first component) must be > 0 (give the other component "
                             "as the first)")
        m1, m2 = (check_scalar_range(getattr(self, k), k, -1e6, 1e6, what="component mean") for k in ("m1", "m2"))
        s1, s2 = (_deviation(getattr(self, k), k) for k in ("s1", "s2"))
        mean, var, _, _ = mixture_stats((w, 1 - w), (m1, m2), (s1, s2))
        if abs(mean) > 1e-15 or abs(var - 1.0) > 4e-16:  # standardised already: keep the values (spec round trip)
            sd = math.sqrt(var)
            m1, m2, s1, s2 = (m1 - mean) / sd, (m2 - mean) / sd, s1 / sd, s2 / sd
        if min(s1, s2) < 0.02:
            raise ValueError(f"a component is narrower than 0.02 of the mixture's deviation (s1 = {s1:.3g}, "
                             f"s2 = {s2:.3g} after standardising the mixture w = {self.w!r}, m1 = {self.m1!r}, "
                             f"s1 = {self.s1!r}, m2 = {self.m2!r}, s2 = {self.s2!r}: the means lie too far apart "
                             "for the deviations): use a single Gaussian or a wider component")
        setattr_ = object.__setattr__
        for key, value in (("w", w), ("m1", m1), ("s1", s1), ("m2", m2), ("s2", s2)):
            setattr_(self, key, value)
        live = [(wi, mi, si) for wi, mi, si in ((w, m1, s1), (1.0 - w, m2, s2)) if wi > 0]
        weights, means, sds = (tuple(c) for c in zip(*live, strict=True))
        setattr_(self, "_components", (weights, means, sds))
        setattr_(self, "z_top", max(m + 10.0 * s for m, s in zip(means, sds, strict=True)))
        setattr_(self, "z_bottom", min(m - 10.0 * s for m, s in zip(means, sds, strict=True)))
        setattr_(self, "z_end", max(m + 35.0 * s for m, s in zip(means, sds, strict=True)))
        narrow = min(sds)
        setattr_(self, "resolution", min(1.0, narrow))
        setattr_(self, "fast_sums", narrow >= FAST_WIDTH)

    def moment(self, d, order):
        r"""GW moment :math:`F_n(\bar d) = \sum_i w_i s_i^n G_n((\bar d - m_i)/s_i)` (Gaussian closed forms).

        Parameters
        ----------
        d : array_like
            Separation :math:`\bar d`, finite (any shape).
        order : float
            :math:`n > -1`.

        Returns
        -------
        ndarray
            :math:`F_n(\bar d)`, shape of ``d``.
        """
        d = as_float_array(d, "d", allow_empty=True)
        n = check_order(order)
        return self._checked_moment(lambda x: mixture_moment(x, n, *self._components), d, n)


@dataclass(frozen=True)
class KernelGaussian(HeightDistribution):
    """A Gaussian of standard deviation ``sd`` (not standardised): the kernel of a kernel estimate.

    :class:`asperity.height_sums.HeightSums` uses it to tabulate the integrals of one kernel
    once, for a kernel estimate (:class:`~asperity.heights.Empirical`).

    Parameters
    ----------
    sd : float
        Kernel width, in sigma, > 0.
    """

    sd: float = 0.3
    fast_sums = True

    def __post_init__(self):
        sd = check_scalar_range(self.sd, "sd", 0.0, 1e6, what="kernel width")
        if not sd > 0:
            raise ValueError(f"sd (kernel width) must be > 0, got {self.sd!r}")
        setattr_ = object.__setattr__
        setattr_(self, "sd", sd)
        for key, value in (("z_top", 10.0 * sd), ("z_bottom", -10.0 * sd), ("z_end", 35.0 * sd),
                           ("resolution", min(1.0, sd)), ("_parts", ((1.0,), (0.0,), (sd,)))):
            setattr_(self, key, value)

    def pdf(self, z):
        """Density of N(0, sd^2)."""
        return mixture_pdf(z, *self._parts)

    def pdf_derivative(self, z, order: int):
        """Its first or second derivative."""
        return mixture_pdf_derivative(z, order, *self._parts)

    def sf(self, z):
        """Its survival function."""
        return mixture_sf(z, *self._parts)

    def weighted_sums(self, d, u, weights, order: int = 0):
        return mixture_weighted_sums(d, u, weights, order, *self._parts)

    def panel_sums(self, d, centers, offsets, weights, order: int = 0):
        return mixture_panel_sums(d, centers, offsets, weights, order, *self._parts)


def _deviation(value, name: str) -> float:
    """A component's standard deviation, in (0, 1e6]."""
    try:
        s = check_scalar_range(value, name, 0.0, 1e6, what="component deviation")
    except ValueError:
        s = None
    if s is None or s == 0.0:
        raise ValueError(f"{name} (component deviation) must lie in (0, 1e+06], got {value!r}")
    return s
