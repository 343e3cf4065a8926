r"""Johnson S_U / S_B / S_L summit heights fitted to a skewness and a kurtosis, standardised.

Johnson's translation system maps a standard normal variable :math:`x` onto the heights,
:math:`x = \gamma + \delta\,g(y)`, :math:`y = (\bar z - \xi)/\lambda`, with
:math:`g = \sinh^{-1}` (S_U, unbounded, above the lognormal line), :math:`g = \ln(y/(1-y))`
(S_B, bounded, below it) or :math:`g = \ln y` (S_L, the lognormal, on it); any
(skewness, kurtosis) with :math:`Ku > 1 + Sk^2` has exactly one member
(:func:`~asperity.heights.johnson_fit.fit_johnson`).  Standardised (:math:`\xi`,
:math:`\lambda` from the mean and variance of :math:`y`), the density and its
log-derivatives are

.. math::
    \phi(\bar z) = \frac{\delta\,g'(y)}{\lambda}\,\varphi(x),\quad
    (\ln\phi)' = \frac{A(y) - \delta g'(y)\,x}{\lambda},\quad
    (\ln\phi)'' = \frac{A'(y) - \delta g''(y)\,x - \delta^2 g'(y)^2}{\lambda^2},

:math:`A = g''/g'`, and the survival function is :math:`\Phi(-x)`.  The GW moments are
integrals over the normal variable, :math:`F_n(\bar d) = \int_{x(\bar d)}^\infty(\bar z(x) -
\bar d)^n\varphi(x)\,dx`, by fixed high-order quadrature (the heavy S_U tails stay short
in :math:`x`).  Chen & Huang (NCKU 1998) characterise measured height distributions by the
Johnson system fitted to four moments.

References
----------
.. [1] N. L. Johnson, Biometrika 36 (1949) 149-176.
.. [2] I. D. Hill, R. Hill, R. L. Holder, Appl. Statist. 25 (1976) 180 (AS 99).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from scipy import special

from .._validation import as_float_array, check_scalar_range
from ..quadrature import gauss_legendre
from .base import EDGE_BAND, SF_FLOOR, TAIL, HeightDistribution, check_derivative_order, check_order, tanh_sinh
from .johnson_fit import fit_johnson, sb_moments, su_moments

__all__ = ["Johnson", "KURT_MAX"]

#: Largest kurtosis accepted (S_U tails beyond it reach thousands of sigma).
KURT_MAX = 30.0
_SQRT_2PI = math.sqrt(2.0 * math.pi)
_X_TAIL = float(-special.ndtri(TAIL))  # normal quantile of the negligible tail, 9.86
_X_END = float(-special.ndtri(SF_FLOOR))


@dataclass(frozen=True)
class Johnson(HeightDistribution):
    r"""Standardised Johnson heights with skewness ``skew`` and kurtosis ``kurt`` (module docstring).

    Parameters
    ----------
    skew : float
        Skewness, in [-3, 3].
    kurt : float
        Kurtosis (3 for a Gaussian), with :math:`1 + Sk^2 < Ku \le 30`.

    Attributes
    ----------
    kind : str
        ``'SU'``, ``'SB'``, ``'SL'`` or ``'N'`` (the normal point (0, 3)).
    gamma, delta, xi, lam : float
        :math:`\gamma, \delta` (shape) and :math:`\xi, \lambda` (standardisation); for S_L
        ``gamma`` is the orientation (+1: long upper tail).

    Examples
    --------
    >>> j = Johnson(skew=0.5, kurt=4.0)
    >>> j, j.kind, j.spec
    (Johnson(skew=0.5, kurt=4.0), 'SU', 'johnson:skew=0.5,kurt=4.0')
    """

    skew: float = 0.0
    kurt: float = 3.0
    name: ClassVar[str] = "johnson"
    parameters: ClassVar[tuple[str, ...]] = ("skew", "kurt")

    def __post_init__(self):
        s = check_scalar_range(self.skew, "skew", -3.0, 3.0, what="Johnson skewness")
        k = check_scalar_range(self.kurt, "kurt", 1.0, KURT_MAX, what="Johnson kurtosis, > 1 + skew^2")
        if not k > 1.0 + s * s:
            raise ValueError(f"kurt (Johnson kurtosis) must exceed 1 + skew^2 = {1 + s * s:g} (no distribution "
                             f"has less), got {self.kurt!r}")
        kind, gamma, delta = fit_johnson(s, k)
        if kind == "SU":
            w = math.exp(1.0 / delta**2)
            Omega = gamma / delta
            mean = -math.sqrt(w) * math.sinh(Omega)
            var = 0.5 * math.expm1(1.0 / delta**2) * (w * math.cosh(2 * Omega) + 1.0)
        elif kind == "SB":
            mean, var, _, _ = sb_moments(delta, gamma)
        elif kind == "SL":
            w = math.exp(1.0 / delta**2)
            mean, var = math.sqrt(w), w * math.expm1(1.0 / delta**2)
        else:
            mean, var = 0.0, 1.0
        lam = 1.0 / math.sqrt(var)
        rising = not (kind == "SL" and gamma < 0)  # heights increase with the normal variable
        setattr_ = object.__setattr__
        for key, value in (("skew", s), ("kurt", k), ("kind", kind), ("gamma", gamma), ("delta", delta),
                           ("lam", lam), ("xi", -mean * lam if rising else mean * lam), ("_rising", rising)):
            setattr_(self, key, value)
        lo, hi = self._height(-math.inf), self._height(math.inf)
        setattr_(self, "support", (lo, hi))
        setattr_(self, "edge_power", 0.0)  # S_B can pile up at an edge (delta < 1): resolve it fully
        setattr_(self, "z_bottom", max(lo, self._height(-_X_TAIL)))
        setattr_(self, "z_top", min(hi, self._height(_X_TAIL)))
        setattr_(self, "z_end", min(hi, self._height(_X_END)))
        # Resolution: the largest log-curvature where the density matters (>= 1e-4 of its peak),
        # away from a finite support edge (within EDGE_BAND of one the integrals use tanh-sinh).
        band = min(EDGE_BAND, 0.25 * (hi - lo))  # a narrow S_B keeps its middle half
        z = np.linspace(max(self._height(-6.0), lo + band), min(self._height(6.0), hi - band), 4001)
        f = self.pdf(z)
        curvature = np.max(np.abs(self._log_derivatives(z)[1])[f >= 1e-4 * f.max()])
        setattr_(self, "resolution", float(min(1.0, 1.0 / math.sqrt(curvature))))

    # -- the transform -----------------------------------------------------------------
    def _height(self, v: float) -> float:
        """Height at the normal quantile v of the heights (v = x, or -x for a falling S_L); inf allowed."""
        with np.errstate(over="ignore"):
            return float(self._heights(np.float64(v)))

    def _normal(self, z):
        """(x, g'(y), A(y), A'(y), g''(y), inside) at heights z."""
        z = np.asarray(z, dtype=float)
        if self.kind == "N":
            one = np.ones_like(z)
            return z, one, 0 * z, 0 * z, 0 * z, one.astype(bool)
        y = (z - self.xi) / self.lam
        if self.kind == "SU":
            r = 1.0 + y * y
            g1 = 1.0 / np.sqrt(r)
            A, dA = -y / r, -(1.0 - y * y) / r**2
            x = self.gamma + self.delta * np.arcsinh(y)
            return x, g1, A, dA, A * g1, np.ones(z.shape, dtype=bool)
        if self.kind == "SB":
            inside = (y > 0) & (y < 1)
            y = np.where(inside, y, 0.5)
            g1 = 1.0 / (y * (1.0 - y))
            A, dA = -1.0 / y + 1.0 / (1.0 - y), 1.0 / y**2 + 1.0 / (1.0 - y) ** 2
            x = self.gamma + self.delta * (np.log(y) - np.log1p(-y))
            return x, g1, A, dA, A * g1, inside
        sign = 1.0 if self.gamma > 0 else -1.0  # S_L: y = sign (z - xi)/lam > 0
        y = sign * y
        inside = y > 0
        y = np.where(inside, y, 1.0)
        x = self.delta * np.log(y)
        g1, A = 1.0 / y, -1.0 / y
        return x, g1, A, 1.0 / y**2, A * g1, inside

    def _log_derivatives(self, z):
        x, g1, A, dA, g2, _ = self._normal(z)
        J = 1.0 / self.lam if self.kind != "SL" or self.gamma > 0 else -1.0 / self.lam
        if self.kind == "N":
            return -x, -np.ones_like(x)
        L1 = (A - self.delta * g1 * x) * J
        L2 = (dA - self.delta * g2 * x - self.delta**2 * g1 * g1) * J * J
        return L1, L2

    # -- the interface ----------------------------------------------------------------
    def pdf(self, z):
        """Density :math:`\\delta g'(y)\\varphi(x)/\\lambda` (0 outside the support)."""
        z = np.asarray(z, dtype=float)
        if self.kind == "N":
            return np.exp(-0.5 * z * z) / _SQRT_2PI
        y = (z - self.xi) / self.lam
        c = self.delta / (self.lam * _SQRT_2PI)
        if self.kind == "SU":  # the common case, without the derivative terms of _normal
            x = self.gamma + self.delta * np.arcsinh(y)
            return c * np.exp(-0.5 * x * x) / np.sqrt(1.0 + y * y)
        if self.kind == "SB":
            inside = (y > 0) & (y < 1)
            y = np.where(inside, y, 0.5)
            x = self.gamma + self.delta * (np.log(y) - np.log1p(-y))
            return np.where(inside, c * np.exp(-0.5 * x * x) / (y * (1.0 - y)), 0.0)
        x, g1, _, _, _, inside = self._normal(z)
        return np.where(inside, c * g1 * np.exp(-0.5 * x * x), 0.0)

    def pdf_derivative(self, z, order: int):
        """:math:`\\phi L_1` (order 1) or :math:`\\phi(L_1^2 + L_2)` (order 2), 0 outside the support."""
        order = check_derivative_order(order)
        f = self.pdf(z)
        L1, L2 = self._log_derivatives(z)
        out = f * L1 if order == 1 else f * (L1 * L1 + L2)
        return np.where(f > 0, out, 0.0)

    def sf(self, z):
        r"""Survival function :math:`\Phi(-v)`, v the normal quantile of the height (1 below, 0 above the support)."""
        z = np.asarray(z, dtype=float)
        x, _, _, _, _, inside = self._normal(z)
        q = special.ndtr(-x) if self._rising else special.ndtr(x)
        return np.where(inside, q, np.where(z <= self.support[0], 1.0, 0.0))

    def stats(self) -> tuple[float, float, float, float]:
        """``(0, 1, skew, kurt)``: the fit reproduces them (S_U in closed form, S_B to ~1e-13)."""
        if self.kind == "SU":
            sk, ku = su_moments(self.delta, self.gamma / self.delta)
            return 0.0, 1.0, sk, ku
        if self.kind == "SB":
            _, _, sk, ku = sb_moments(self.delta, self.gamma)
            return 0.0, 1.0, sk, ku
        return 0.0, 1.0, self.skew, self.kurt

    def moment(self, d, order):
        r"""GW moment :math:`F_n(\bar d) = \int_{x(\bar d)}^\infty (\bar z(x) - \bar d)^n\varphi(x)\,dx`.

        Tanh-sinh on the first unit of the normal variable :math:`x` (the
        :math:`(\bar z-\bar d)^n` endpoint), then 42 20-point Gauss-Legendre panels (width
        at most 1/2) up to :math:`\max(x, 0) + 9.9` (the normal tail below 1e-23).

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
        return self._checked_moment(lambda x: self._moment_form(x, n), d, n)

    def _moment_form(self, d, n):
        """The quadrature of :meth:`moment` in the normal variable, for checked arrays."""
        v_d = self._v_of(d)
        a = np.where(np.isposinf(v_d), 0.0, np.maximum(v_d, -_X_TAIL))[..., None]  # above the support: F = 0
        ts, _, tw = tanh_sinh()
        g, gw = gauss_legendre(20)
        # GL panels (42, width <= 1/2) from a + 1 to max(a, 0) + x_tail + 1
        h = (np.maximum(a, 0.0) + _X_TAIL - a) / 42.0
        grid = (np.arange(42)[:, None] + g[None, :]).ravel()
        v = np.concatenate([a + ts, a + 1.0 + h * grid], axis=-1)
        w = np.concatenate([np.broadcast_to(tw, v[..., :ts.size].shape), h * np.tile(gw, 42)], axis=-1)
        dz = np.maximum(self._heights(v) - d[..., None], 0.0)
        out = np.sum(w * dz**n * np.exp(-0.5 * v * v), axis=-1) / _SQRT_2PI
        return np.where(np.isposinf(v_d), 0.0, out)

    def _v_of(self, d):
        """Normal quantile v of the heights d, increasing with d (-inf below, +inf above the support)."""
        d = np.asarray(d, dtype=float)
        x, _, _, _, _, inside = self._normal(d)
        v = x if self._rising else -x
        return np.where(inside, v, np.where(d <= self.support[0], -np.inf, np.inf))

    def _heights(self, v):
        """Heights of normal quantiles v (increasing in v; array)."""
        v = np.asarray(v, dtype=float)
        if self.kind == "N":
            return v
        if self.kind == "SU":
            y = np.sinh((v - self.gamma) / self.delta)
        elif self.kind == "SB":
            y = special.expit((v - self.gamma) / self.delta)
        else:  # S_L: z = xi + lam sign exp(x/delta) with x = sign v
            sign = 1.0 if self._rising else -1.0
            y = sign * np.exp(sign * v / self.delta)
        return self.xi + self.lam * y
