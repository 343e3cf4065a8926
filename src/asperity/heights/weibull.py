r"""Weibull summit heights parametrised by their skewness (Yu & Polycarpou 2002), standardised.

A Weibull variable :math:`w \ge 0` with shape :math:`c`, density
:math:`c\,w^{c-1}e^{-w^c}`, has moments :math:`E[w^k] = g_k = \Gamma(1 + k/c)` and skewness

.. math::
    Sk(c) = \frac{g_3 - 3g_1g_2 + 2g_1^3}{(g_2 - g_1^2)^{3/2}},

falling from 2 (:math:`c = 1`, the exponential) through 0 (:math:`c \approx 3.602`) to
-1.1395 as :math:`c\to\infty`.  Given the skewness, :math:`c` solves :math:`Sk(c) = Sk`;
heights are standardised, :math:`\bar z = (w - g_1)/\sigma_w` with
:math:`\sigma_w = (g_2 - g_1^2)^{1/2}`:

.. math::
    \phi(\bar z) = \sigma_w\,c\,w^{c-1}e^{-w^c},\quad w = g_1 + \sigma_w\bar z \ge 0,\qquad
    Q(\bar z) = e^{-w^c}.

The support starts at :math:`\bar z = -g_1/\sigma_w` (a kink, a jump at :math:`c = 1`);
the upper tail falls like :math:`e^{-w^c}`, faster than a Gaussian for negative skewness.
Skewness is limited to [-1, 2]: :math:`c \ge 1` keeps the density bounded, and beyond
-1 the shape parameter exceeds 40 and the skewness formula loses digits.  Yu & Polycarpou
fit Weibull distributions to measured summit heights of skewed surfaces.  The GW moments
have no closed form: fixed high-order quadrature
(:func:`~asperity.heights.base.gw_moment_quadrature`).

References
----------
.. [1] N. Yu, A. A. Polycarpou, J. Tribol. 124 (2002) 367-376 (Weibull summit heights).
.. [2] J. I. McCool, Wear 107 (1986) 37-60 (non-Gaussian surfaces in the GW model).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from scipy import optimize, special

from .._validation import check_scalar_range
from ..quadrature import gauss_legendre
from .base import SF_FLOOR, TAIL, HeightDistribution, check_derivative_order

__all__ = ["Weibull", "weibull_skewness", "weibull_shape", "SKEW_RANGE", "SHAPE_RANGE"]

#: Valid skewness of the Weibull family here: c from 40.7 (skewness -1) to 1 (skewness 2).
SKEW_RANGE = (-1.0, 2.0)


def _log_moments(c):
    return [float(special.gammaln(1.0 + k / c)) for k in (1, 2, 3)]


#: Shapes :func:`weibull_skewness` accepts (beyond, its moments overflow or lose every digit).
SHAPE_RANGE = (0.05, 1e4)

def weibull_skewness(c):
    r"""Skewness of a Weibull distribution of shape :math:`c`.

    .. math::
        Sk = \frac{(g_3/g_1^3 - 1) - 3(g_2/g_1^2 - 1)}{(g_2/g_1^2 - 1)^{3/2}},\qquad g_k = \Gamma(1+k/c)

    written with :func:`numpy.expm1` of log-gamma differences for :math:`c \le 4`.  Beyond,
    the numerator is a difference of terms :math:`c^3` times larger than itself, and the
    shape found from a skewness would inherit that (the map from skewness to shape is
    ill-conditioned there: :math:`dc/dSk \approx 125` at :math:`c = 15.6`), so the central
    moments are integrated instead, :math:`\mu_k = \int_0^\infty (t - g_1)^k\,c\,t^{c-1}
    e^{-t^c}dt` (40 panels of 20-point Gauss-Legendre over the mass, exact to ~1e-15).

    Parameters
    ----------
    c : float
        Shape :math:`c` in :data:`SHAPE_RANGE` (0.05 to 1e4: skewness 1.1e10 to -1.139).

    Returns
    -------
    float
        Skewness.

    References
    ----------
    N. L. Johnson, S. Kotz, N. Balakrishnan, Continuous Univariate Distributions vol. 1,
    2nd ed. (1994), Ch. 21, Eq (21.11).
    """
    return _skewness(check_scalar_range(c, "c", *SHAPE_RANGE, what="Weibull shape"))


def _skewness(c: float) -> float:
    """:func:`weibull_skewness` of a checked shape (the root search of :func:`weibull_shape` calls it)."""
    L1, L2, L3 = _log_moments(c)
    if c <= 4.0:
        r2, r3 = math.expm1(L2 - 2 * L1), math.expm1(L3 - 3 * L1)
        return (r3 - 3.0 * r2) / r2**1.5
    g1 = math.exp(L1)
    lo, hi = 1e-40 ** (1.0 / c), (40.0 * math.log(10.0)) ** (1.0 / c)
    x, w = gauss_legendre(20)
    h = (hi - lo) / 40
    t = (lo + h * (np.arange(40)[:, None] + x[None, :])).ravel()
    f = np.tile(h * w, 40) * c * t ** (c - 1.0) * np.exp(-(t**c))
    dt = t - g1
    mu2, mu3 = float(np.sum(f * dt * dt)), float(np.sum(f * dt**3))
    return mu3 / mu2**1.5


def weibull_shape(skew: float) -> float:
    """Shape :math:`c` of the Weibull distribution with skewness ``skew`` in [-1, 2] (Brent's method in log c).

    Parameters
    ----------
    skew : float
        Skewness in :data:`SKEW_RANGE`.

    Returns
    -------
    float
        :math:`c` with :func:`weibull_skewness` (c) = ``skew`` to 1e-14.

    Raises
    ------
    ValueError
        If ``skew`` is not a real number in :data:`SKEW_RANGE`.
    """
    skew = check_scalar_range(skew, "skew", *SKEW_RANGE, what="Weibull skewness")
    if skew == 2.0:
        return 1.0
    lc = optimize.brentq(lambda x: _skewness(math.exp(x)) - skew, 0.0, math.log(60.0), xtol=1e-15,
                         rtol=1e-15, maxiter=200)
    return math.exp(lc)


@dataclass(frozen=True)
class Weibull(HeightDistribution):
    r"""Standardised Weibull heights with skewness ``skew`` (module docstring).

    Parameters
    ----------
    skew : float
        Skewness of the summit heights, in [-1, 2] (0: shape 3.602, nearly Gaussian;
        2: the exponential).

    Attributes
    ----------
    c : float
        Weibull shape :math:`c \ge 1`.
    mean_w, sd_w : float
        :math:`g_1` and :math:`\sigma_w`, the mean and deviation of the unit Weibull variable.

    Examples
    --------
    >>> w = Weibull(skew=0.5)
    >>> w, w.spec, round(w.c, 4), round(w.support[0], 4)
    (Weibull(skew=0.5), 'weibull:skew=0.5', 2.2156, -2.0973)
    """

    skew: float = 0.5
    name: ClassVar[str] = "weibull"
    parameters: ClassVar[tuple[str, ...]] = ("skew",)

    def __post_init__(self):
        skew = check_scalar_range(self.skew, "skew", *SKEW_RANGE, what="Weibull skewness")
        c = weibull_shape(skew)
        L1, L2, _ = _log_moments(c)
        g1 = math.exp(L1)
        sd = g1 * math.sqrt(math.expm1(L2 - 2 * L1))
        lo = -g1 / sd

        def height(w):  # w -> standardised height
            return (w - g1) / sd

        setattr_ = object.__setattr__
        setattr_(self, "skew", skew)
        setattr_(self, "c", c)
        setattr_(self, "mean_w", g1)
        setattr_(self, "sd_w", sd)
        setattr_(self, "support", (lo, math.inf))
        setattr_(self, "edge_power", c - 1.0)
        setattr_(self, "z_top", height((-math.log(TAIL)) ** (1.0 / c)))
        setattr_(self, "z_bottom", max(lo, height((-math.log1p(-TAIL)) ** (1.0 / c))))
        setattr_(self, "z_end", height((-math.log(SF_FLOOR)) ** (1.0 / c)))

    def _w(self, z):
        return self.mean_w + self.sd_w * np.asarray(z, dtype=float)

    def pdf(self, z):
        """Density :math:`\\sigma_w c\\,w^{c-1}e^{-w^c}`, 0 below the support."""
        w = self._w(z)
        inside = w > 0
        wp = np.where(inside, w, 1.0)
        e = np.exp(-(wp**self.c))
        # where e^(-w^c) underflows the density does too (w^(c-1) would make inf * 0)
        return np.where(inside & (e > 0), self.sd_w * self.c * wp ** (self.c - 1.0) * e, 0.0)

    def pdf_derivative(self, z, order: int):
        """First or second derivative of the density (0 below the support)."""
        order = check_derivative_order(order)
        w = self._w(z)
        inside = w > 0
        wp = np.where(inside, w, 1.0)
        c, s = self.c, self.sd_w
        L1 = s * ((c - 1.0) / wp - c * wp ** (c - 1.0))
        f = self.pdf(z)
        live = inside & (f > 0)  # where f underflows, so do its derivatives (w^c ~ 745 there)
        if order == 1:
            return np.where(live, f * L1, 0.0)
        L2 = -(s * s) * ((c - 1.0) / wp**2 + c * (c - 1.0) * wp ** (c - 2.0))
        return np.where(live, f * (L1 * L1 + L2), 0.0)

    def sf(self, z):
        """Survival function :math:`e^{-w^c}` (1 below the support)."""
        z = np.asarray(z, dtype=float)
        w = np.where(z <= self.support[0], 0.0, np.maximum(self._w(z), 0.0))  # exactly 1 from the support's start
        return np.exp(-(w**self.c))

    def stats(self) -> tuple[float, float, float, float]:
        """``(0, 1, skew, kurtosis)`` in closed form (moments :math:`\\Gamma(1+k/c)`)."""
        L = [special.gammaln(1.0 + k / self.c) for k in (1, 2, 3, 4)]
        r = [math.expm1(L[k - 1] - k * L[0]) for k in (2, 3, 4)]  # E[w^k]/g1^k - 1
        mu4 = (r[2] + 1.0) - 4.0 * (r[1] + 1.0) + 6.0 * (r[0] + 1.0) - 3.0  # over g1^4
        return 0.0, 1.0, self.skew, mu4 / r[0] ** 2
