r"""Pearson type III (gamma) summit heights with the skewness as the parameter, standardised.

A gamma variable of shape :math:`k = 4/Sk^2` and scale :math:`\theta = |Sk|/2`, shifted to
zero mean (mirrored for negative skewness), has unit variance, skewness :math:`Sk` and
kurtosis :math:`3 + \tfrac32 Sk^2`; :math:`Sk \to 0` is the Gaussian (this is
:class:`scipy.stats.pearson3`).  With :math:`t = Sk\,\bar z/2` the density is, in a form
that stays exact as :math:`k\to\infty`,

.. math::
    \phi(\bar z) = \frac{1}{\sqrt{2\pi}}\exp\!\big(-k\,(t - \ln(1+t)) - \ln(1+t) - \epsilon(k)\big),
    \quad 1 + t > 0,

with :math:`\epsilon(k) = \ln\Gamma(k) - (k-\tfrac12)\ln k + k - \tfrac12\ln 2\pi` (Stirling's
error), and :math:`(\ln\phi)' = -(\bar z + Sk/2)/(1+t)`,
:math:`(\ln\phi)'' = -(1 - Sk^2/4)/(1+t)^2`.  The support ends at :math:`\bar z = -2/Sk`
(below for positive, above for negative skewness).  For :math:`Sk > 0` the GW moments have
the closed form, with :math:`h = \bar d + 2/Sk` the separation measured from the edge,

.. math::
    F_n = \frac{h^{n+k}e^{-h/\theta}\,\Gamma(n+1)\,U(n+1, n+k+1, h/\theta)}{\Gamma(k)\,\theta^k}
    \ (h > 0),\qquad
    F_n = \frac{|h|^{n+k}\,U(k, n+k+1, |h|/\theta)}{\theta^k}\ (h < 0)

(:func:`pearson3_moment`).  Skewness is limited to [-2, 2] (:math:`k \ge 1`, a bounded
density).

References
----------
.. [1] K. Pearson, Phil. Trans. R. Soc. A 186 (1895) 343 (type III curves).
.. [2] N. L. Johnson, S. Kotz, N. Balakrishnan, Continuous Univariate Distributions vol. 1,
   2nd ed. (1994), Ch. 17 (gamma); Abramowitz & Stegun 13.2.5 (Tricomi's U).
.. [3] Reference section 4 of the project (closed forms, verified in tests/test_heights_families.py).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from scipy import special

from .._validation import as_float_array, check_finite_result, check_scalar_range, check_scalar_real, ufunc_result
from .base import (
    SF_FLOOR,
    TAIL,
    HeightDistribution,
    check_derivative_order,
    check_order,
    gw_moment_quadrature_unchecked,
)

__all__ = ["PearsonIII", "pearson3_moment", "stirling_error", "SKEW_RANGE", "SKEW_MIN"]

#: Valid skewness: |Sk| <= 2 keeps the shape k >= 1 (a bounded density).
SKEW_RANGE = (-2.0, 2.0)
#: Smallest non-zero |skewness|: the incomplete gamma function of shape 4/Sk^2 keeps ~1e-12.
SKEW_MIN = 1e-3
_SQRT_2PI = math.sqrt(2.0 * math.pi)


def stirling_error(k: float) -> float:
    r"""Stirling's error :math:`\epsilon(k) = \ln\Gamma(k) - (k-\tfrac12)\ln k + k - \tfrac12\ln 2\pi`.

    Its asymptotic series :math:`1/(12k) - 1/(360k^3) + 1/(1260k^5) - 1/(1680k^7)` for
    :math:`k \ge 10` (error below 1e-16), the definition below.

    Parameters
    ----------
    k : float
        :math:`k > 0`.

    Returns
    -------
    float

    References
    ----------
    Abramowitz & Stegun 6.1.41.
    """
    if k >= 10.0:
        r = 1.0 / (k * k)
        return (1.0 / 12.0 - r * (1.0 / 360.0 - r * (1.0 / 1260.0 - r / 1680.0))) / k
    return float(special.gammaln(k) - (k - 0.5) * math.log(k) + k - 0.5 * math.log(2.0 * math.pi))


def _log1p_minus(t):
    """ln(1+t) - t without cancellation for small t (a series where |t| < 0.1)."""
    t = np.asarray(t, dtype=float)
    flat = t.reshape(-1)
    with np.errstate(divide="ignore", invalid="ignore"):
        out = np.log1p(flat) - flat
    small = np.abs(flat) < 0.1
    if np.any(small):
        ts = flat[small]
        series = np.zeros_like(ts)
        power = ts * ts
        for n in range(2, 20):
            series += (-1.0) ** (n + 1) * power / n
            power = power * ts
        out[small] = series
    return out.reshape(t.shape)


@dataclass(frozen=True)
class PearsonIII(HeightDistribution):
    r"""Standardised Pearson type III (gamma) heights with skewness ``skew`` (module docstring).

    Parameters
    ----------
    skew : float
        Skewness in [-2, 2], 0 or at least 1e-3 in magnitude; 0 is the Gaussian, 2 the
        exponential, negative values have the long tail below the mean (worn, plateau-like
        surfaces).

    Attributes
    ----------
    k : float
        Gamma shape :math:`4/Sk^2` (inf for the Gaussian).

    Examples
    --------
    >>> p = PearsonIII(skew=-0.3)
    >>> p, p.spec, round(p.support[1], 6), [round(x, 12) for x in p.stats()]
    (PearsonIII(skew=-0.3), 'pearson3:skew=-0.3', 6.666667, [0.0, 1.0, -0.3, 3.135])
    """

    skew: float = 0.5
    name: ClassVar[str] = "pearson3"
    parameters: ClassVar[tuple[str, ...]] = ("skew",)

    def __post_init__(self):
        s = check_scalar_range(self.skew, "skew", *SKEW_RANGE, what="Pearson III skewness")
        if 0.0 < abs(s) < SKEW_MIN:
            raise ValueError(f"skew (Pearson III skewness) must be 0 (the Gaussian) or at least {SKEW_MIN:g} in "
                             f"magnitude (below, the gamma shape 4/skew^2 > 4e6 and the survival function loses "
                             f"digits in double precision), got {self.skew!r}")
        setattr_ = object.__setattr__
        setattr_(self, "skew", s)
        if s == 0.0:
            setattr_(self, "k", math.inf)
            setattr_(self, "_eps", 0.0)
            return
        k = 4.0 / (s * s)
        edge = -2.0 / s

        def height(y):  # k(1 + t) = y -> z = 2t/s
            return 2.0 * (y / k - 1.0) / s

        upper, lower = special.gammainccinv, special.gammaincinv  # tails of the gamma variable y
        setattr_(self, "k", k)
        setattr_(self, "_eps", stirling_error(k))
        setattr_(self, "edge_power", k - 1.0)
        if abs(s) < 0.01:  # y/k - 1 would lose the height: the Cornish-Fisher bound, with margin
            a = abs(s)
            lo_, hi_, end = -10.0 - 20.0 * a, 10.0 + 20.0 * a, 36.0 + 250.0 * a
        elif s > 0:
            lo_, hi_, end = height(lower(k, TAIL)), height(upper(k, TAIL)), height(upper(k, SF_FLOOR))
        else:
            lo_, hi_, end = height(upper(k, TAIL)), height(lower(k, TAIL)), edge
        if s > 0:
            setattr_(self, "support", (edge, math.inf))
            setattr_(self, "z_bottom", max(edge, lo_))
            setattr_(self, "z_top", hi_)
            setattr_(self, "z_end", end)
        else:
            setattr_(self, "support", (-math.inf, edge))
            setattr_(self, "z_bottom", lo_)
            setattr_(self, "z_top", min(edge, hi_))
            setattr_(self, "z_end", min(edge, end))

    def _t(self, z):
        t = 0.5 * self.skew * np.asarray(z, dtype=float)
        inside = t > -1.0
        return np.where(inside, t, 0.0), inside

    def pdf(self, z):
        """Density (module docstring), 0 outside the support."""
        z = np.asarray(z, dtype=float)
        if self.k == math.inf:
            return np.exp(-0.5 * z * z) / _SQRT_2PI
        t = 0.5 * self.skew * z
        if self.k <= 16.0:  # k (ln(1+t) - t) loses at most k ulps of t: no series needed
            with np.errstate(divide="ignore", invalid="ignore"):
                lt = np.log1p(t)
                f = np.exp(self.k * (lt - t) - lt - self._eps) / _SQRT_2PI
            return np.where(t > -1.0, f, 0.0)
        t, inside = self._t(z)
        log_f = self.k * _log1p_minus(t) - np.log1p(t) - self._eps
        return np.where(inside, np.exp(log_f) / _SQRT_2PI, 0.0)

    def pdf_derivative(self, z, order: int):
        """:math:`\\phi' = \\phi L_1`, :math:`\\phi'' = \\phi(L_1^2 + L_2)` with the log-derivatives above."""
        order = check_derivative_order(order)
        z = np.asarray(z, dtype=float)
        t, inside = self._t(z)
        L1 = -(z + 0.5 * self.skew) / (1.0 + t)
        f = self.pdf(z)
        if order == 1:
            return np.where(inside, f * L1, 0.0)
        L2 = -(1.0 - 0.25 * self.skew**2) / (1.0 + t) ** 2
        return np.where(inside, f * (L1 * L1 + L2), 0.0)

    def sf(self, z):
        """Survival function: the regularised incomplete gamma function of :math:`k(1+t)`."""
        z = np.asarray(z, dtype=float)
        if self.k == math.inf:
            return special.ndtr(-z)
        x = self.k * np.maximum(1.0 + 0.5 * self.skew * z, 0.0)
        return special.gammaincc(self.k, x) if self.skew > 0 else special.gammainc(self.k, x)

    def stats(self) -> tuple[float, float, float, float]:
        """``(0, 1, skew, 3 + 1.5 skew^2)``."""
        return 0.0, 1.0, self.skew, 3.0 + 1.5 * self.skew**2

    def moment(self, d, order):
        r"""GW moment :math:`F_n(\bar d)`.

        The Tricomi-U closed form (:func:`pearson3_moment`) where SciPy evaluates it exactly
        (positive skewness with an integer shape :math:`k \le 16`: :math:`Sk = 2, 1,
        2/\sqrt3, 0.5, \dots`); elsewhere SciPy's U loses up to 3e-9, so fixed high-order
        quadrature (:func:`~asperity.heights.base.gw_moment_quadrature`, about 1e-14).

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
        if self.skew > 0 and self.k <= 16.0 and abs(self.k - round(self.k)) < 1e-12:
            return self._checked_moment(lambda x: _pearson3_form(x, n, self.skew), d, n)
        return self._checked_moment(lambda x: gw_moment_quadrature_unchecked(self, x, n), d, n)


def pearson3_moment(d, order: float, skew: float):
    r"""GW moment of standardised Pearson III heights of positive skewness, through Tricomi's U.

    .. math::
        F_n = \frac{h^{n+k}e^{-h/\theta}\,\Gamma(n+1)\,U(n+1, n+k+1, h/\theta)}{\Gamma(k)\theta^k}\ (h > 0),
        \quad F_n = \frac{|h|^{n+k}U(k, n+k+1, |h|/\theta)}{\theta^k}\ (h < 0),
        \quad F_n = \frac{\Gamma(n+k)\theta^n}{\Gamma(k)}\ (h = 0)

    with :math:`k = 4/Sk^2`, :math:`\theta = Sk/2`, :math:`h = \bar d + 2/Sk`
    (:func:`scipy.special.hyperu`; exact to about 3e-14 for integer :math:`k \le 16`, but
    off by up to 3e-9 for other k: :meth:`PearsonIII.moment` chooses).

    Parameters
    ----------
    d : array_like
        Separations (any shape), finite.
    order : float
        :math:`-1 < n \le` :data:`~asperity.heights.base.MAX_ORDER`.
    skew : float
        Skewness, :data:`SKEW_MIN` :math:`\le Sk \le 2`.

    Returns
    -------
    ndarray
        :math:`F_n(\bar d)`, shape of ``d``.

    Raises
    ------
    ValueError
        If ``d`` is not real and finite, ``order`` or ``skew`` out of range, or the form
        leaves double precision (:meth:`PearsonIII.moment` then integrates instead).

    References
    ----------
    Abramowitz & Stegun 13.2.5; Johnson, Kotz & Balakrishnan (1994), Ch. 17.
    """
    d = as_float_array(d, "d", allow_empty=True)
    n = check_order(order)
    s = check_scalar_real(skew, "skew")
    if not SKEW_MIN <= s <= 2.0:
        raise ValueError(f"skew must lie in [{SKEW_MIN:g}, 2] (this closed form is for positive skewness), "
                         f"got {skew!r}")
    with np.errstate(all="ignore"):
        out = _pearson3_form(d, n, s)
    return ufunc_result(check_finite_result(out, f"the Pearson III moment of order {n:g}", d=d, skew=s))


def _pearson3_form(d, n, s):
    """The closed form of :func:`pearson3_moment` for checked arrays (any warnings to the caller)."""
    k, th = 4.0 / (s * s), 0.5 * s
    h = d + 2.0 / s
    out = np.full(h.shape, math.exp(special.gammaln(n + k) - special.gammaln(k)) * th**n)
    up, down = h > 0, h < 0
    with np.errstate(divide="ignore", over="ignore", invalid="ignore"):
        hu = np.where(up, h, 1.0)
        log_pre = (n + k) * np.log(hu) - hu / th - special.gammaln(k) - k * math.log(th) + special.gammaln(n + 1)
        out = np.where(up, np.exp(log_pre) * special.hyperu(n + 1.0, n + k + 1.0, hu / th), out)
        hd = np.where(down, -h, 1.0)
        out = np.where(down, np.exp((n + k) * np.log(hd) - k * math.log(th))
                       * special.hyperu(k, n + k + 1.0, hd / th), out)
    return out
