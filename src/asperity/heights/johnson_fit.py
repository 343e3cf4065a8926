r"""Johnson's translation system fitted by skewness and kurtosis (the moment fit of Johnson 1949).

A Johnson variable is a monotone transform of a standard normal :math:`x`,

.. math::
    x = \gamma + \delta\,g(y),\qquad
    g = \sinh^{-1}y\ (S_U),\quad g = \ln\frac{y}{1-y}\ (S_B),\quad g = \ln y\ (S_L),

with :math:`y = (\bar z - \xi)/\lambda`.  In the (skewness², kurtosis) plane the lognormal
line :math:`S_L` (:math:`\omega = e^{1/\delta^2}`: :math:`Sk^2 = (\omega-1)(\omega+2)^2`,
:math:`Ku = \omega^4 + 2\omega^3 + 3\omega^2 - 3`) separates :math:`S_U` (above: heavy
tails, unbounded) from :math:`S_B` (below, down to the bound :math:`Ku = 1 + Sk^2`:
bounded).  For :math:`S_U`, with :math:`\Omega = \gamma/\delta`,

.. math::
    V = \tfrac12(\omega\cosh2\Omega + 1),\quad
    Sk = -\frac{\sqrt{\omega(\omega-1)}\,[\omega(\omega+2)\sinh3\Omega + 3\sinh\Omega]}{4V^{3/2}},\\
    Ku = \frac{\omega^2(\omega^4+2\omega^3+3\omega^2-3)\cosh4\Omega + 4\omega^2(\omega+2)\cosh2\Omega
         + 3(2\omega+1)}{8V^2}

(Johnson 1949); :math:`S_B` moments are integrals over the normal variable
(Gauss-Legendre panels narrower than the logistic's poles).  A curve of constant
:math:`\delta` runs from the symmetric point (:math:`\gamma = 0`) to the lognormal line
(:math:`|\gamma|\to\infty`) with :math:`|Sk|` increasing in :math:`|\gamma|`, so the fit
solves :math:`Sk(\delta, \gamma) = Sk` for :math:`\gamma` inside a solve of
:math:`Ku(\delta, \gamma(\delta)) = Ku` for :math:`\delta` (Brent's method, both).

References
----------
.. [1] N. L. Johnson, Biometrika 36 (1949) 149-176, Eqs (12)-(17) (S_U moments).
.. [2] I. D. Hill, R. Hill, R. L. Holder, Appl. Statist. 25 (1976) 180 (AS 99, the fit by moments).
.. [3] J. F. Slifker, S. S. Shapiro, Technometrics 22 (1980) 239.
"""

from __future__ import annotations

import functools
import math

import numpy as np
from scipy import optimize

from ..quadrature import gauss_legendre

__all__ = ["su_moments", "sb_moments", "lognormal_line", "fit_johnson", "NEAR_LINE", "NEAR_NORMAL", "SB_DELTA_MIN"]

#: Points closer than this to the lognormal line (in kurtosis) are fitted as S_L.
NEAR_LINE = 1e-7
#: Points closer than this to (0, 3) (in skewness and kurtosis) are the normal distribution.
NEAR_NORMAL = 1e-9
_OMEGA_MAX = 40.0  # |gamma/delta| beyond which S_U is the lognormal to rounding
#: Smallest S_B shape delta: below, the density piles up at both support edges over
#: decades of distance (the integrals lose digits, 5e-10 at delta = 0.19).
SB_DELTA_MIN = 0.25


def su_moments(delta: float, Omega: float) -> tuple[float, float]:
    """Skewness and kurtosis of Johnson S_U with shape ``delta`` and ``Omega = gamma/delta`` (Johnson 1949).

    Parameters
    ----------
    delta : float
        :math:`\\delta > 0`.
    Omega : float
        :math:`\\gamma/\\delta`, real (positive gives negative skewness).

    Returns
    -------
    skew, kurt : float
    """
    wm1 = math.expm1(1.0 / delta**2)
    w = 1.0 + wm1
    V = 0.5 * (w * math.cosh(2 * Omega) + 1.0)
    skew = -0.25 * math.sqrt(w * wm1) * (w * (w + 2) * math.sinh(3 * Omega) + 3 * math.sinh(Omega)) / V**1.5
    kurt = (w * w * (w**4 + 2 * w**3 + 3 * w**2 - 3) * math.cosh(4 * Omega) + 4 * w * w * (w + 2) * math.cosh(2 * Omega)
            + 3 * (2 * w + 1)) / (8 * V * V)
    return skew, kurt


@functools.lru_cache(maxsize=64)
def _sb_grid(delta: float):
    """Normal-variable nodes and weights for S_B moments: 20-point panels of width <= delta on
    [-9.5, 9.5] (the logistic's poles lie pi delta off the axis: error ~ 12^-40)."""
    width = min(1.0, delta)
    m = int(math.ceil(19.0 / width))
    g, gw = gauss_legendre(20)
    h = 19.0 / m
    x = (-9.5 + h * np.arange(m)[:, None] + h * g[None, :]).ravel()
    return x, np.tile(h * gw, m) * np.exp(-0.5 * x * x) / math.sqrt(2 * math.pi)


def sb_moments(delta: float, gamma: float) -> tuple[float, float, float, float]:
    r"""Mean, variance, skewness and kurtosis of ``y = 1/(1 + exp(-(x - gamma)/delta))``, x standard normal.

    Computed for :math:`\tilde y = y\,e^{\gamma/\delta}` (no underflow when :math:`y` crowds
    its lower edge), then scaled back.

    Parameters
    ----------
    delta : float
        :math:`\delta > 0`.
    gamma : float
        :math:`\gamma`, real (positive gives positive skewness here), :math:`|\gamma|/\delta \le 300`.

    Returns
    -------
    mean, var, skew, kurt : float
    """
    x, w = _sb_grid(delta)
    g = abs(gamma)
    yt = np.exp(x / delta - np.logaddexp(0.0, (x - g) / delta))  # y e^(g/delta) for gamma >= 0
    mean = float(np.sum(w * yt))
    c = yt - mean
    m2, m3, m4 = (float(np.sum(w * c**k)) for k in (2, 3, 4))
    scale = math.exp(-g / delta)
    skew = m3 / m2**1.5
    if gamma < 0:  # y -> 1 - y
        return 1.0 - mean * scale, m2 * scale * scale, -skew, m4 / m2**2
    return mean * scale, m2 * scale * scale, skew, m4 / m2**2


def lognormal_line(skew: float) -> tuple[float, float]:
    """``(omega, kurt)`` of the lognormal with skewness ``|skew|``: the S_U/S_B boundary.

    Solves :math:`(\\omega-1)(\\omega+2)^2 = Sk^2` (one real root above 1) and returns
    :math:`\\omega` and :math:`Ku = \\omega^4 + 2\\omega^3 + 3\\omega^2 - 3`.

    Parameters
    ----------
    skew : float
        Skewness (its sign is ignored).

    Returns
    -------
    omega, kurt : float
    """
    b1 = skew * skew
    if b1 == 0.0:
        return 1.0, 3.0
    # omega - 1 = e: e (e + 3)^2 = b1, solved for e > 0 (Brent; the cubic is increasing)
    e = optimize.brentq(lambda e: e * (e + 3.0) ** 2 - b1, 0.0, max(1.0, b1), xtol=1e-300, rtol=1e-15)
    w = 1.0 + e
    return w, w**4 + 2 * w**3 + 3 * w**2 - 3


def _solve_su(skew: float, kurt: float) -> tuple[float, float]:
    """(delta, Omega) of S_U with the given skewness (>= 0 handled by symmetry) and kurtosis."""
    s = abs(skew)
    w_line, _ = lognormal_line(s)
    near = w_line == 1.0  # skewness so small (or 0) that the lognormal line's omega rounds to 1
    delta_line = math.inf if near else 1.0 / math.sqrt(math.log(w_line))

    def omega_for(delta):  # |skew| increases with Omega along a curve of constant delta
        if s == 0.0:
            return 0.0
        f = lambda om: su_moments(delta, -om)[0] - s  # noqa: E731 - Omega < 0 gives positive skewness
        if f(0.0) >= 0.0:  # s below the rounding of the symmetric curve's skewness
            return 0.0
        if f(_OMEGA_MAX) < 0:
            return _OMEGA_MAX
        return optimize.brentq(f, 0.0, _OMEGA_MAX, xtol=1e-15, rtol=1e-15)

    def excess(log_delta):
        delta = math.exp(log_delta)
        return su_moments(delta, -omega_for(delta))[1] - kurt

    hi = math.log(1e4) if near else math.log(delta_line) - 1e-12
    lo = math.log(0.3)
    if excess(lo) < 0:
        raise ValueError(f"kurt = {kurt:g} is too large for skew = {skew:g}: the Johnson S_U fit needs "
                         "delta < 0.3 (tails far beyond any measured surface)")
    if excess(hi) > 0:
        raise ValueError(f"skew = {skew:g}, kurt = {kurt:g} lie too close to the normal point or the "
                         "lognormal line for an S_U fit")
    delta = math.exp(optimize.brentq(excess, lo, hi, xtol=1e-14, rtol=1e-15))
    Omega = -omega_for(delta)
    return delta, (Omega if skew >= 0 else -Omega)


def _solve_sb(skew: float, kurt: float) -> tuple[float, float]:
    """(delta, gamma) of S_B with the given skewness and kurtosis (gamma > 0: positive skewness)."""
    s = abs(skew)
    w_line, _ = lognormal_line(s)
    delta_line = 60.0 if w_line == 1.0 else 1.0 / math.sqrt(math.log(w_line))
    far = ValueError(f"skew = {skew:g}, kurt = {kurt:g}: too close to the lognormal line for an S_B fit")

    def gamma_for(delta):
        if s == 0.0:
            return 0.0
        f = lambda g: sb_moments(delta, g)[2] - s  # noqa: E731
        if f(0.0) >= 0.0:  # s below the rounding of the symmetric curve's skewness (~1e-16)
            return 0.0
        hi = delta
        while f(hi) < 0:
            hi *= 2.0
            if hi > 300.0 * delta:
                raise far
        return optimize.brentq(f, 0.0, hi, xtol=1e-14, rtol=1e-15)

    def excess(log_delta):
        delta = math.exp(log_delta)
        return sb_moments(delta, gamma_for(delta))[3] - kurt

    lo = math.log(SB_DELTA_MIN)
    if excess(lo) > 0:
        raise ValueError(f"kurt = {kurt:g} is too close to its lower bound 1 + skew^2 = {1 + s * s:g} for "
                         f"a Johnson S_B fit (delta < {SB_DELTA_MIN:g}: a U-shaped density piling up at both "
                         "ends of its support); a two-Gaussian mixture may describe it")
    for gap in (1e-2, 1e-3, 1e-4, 1e-5, 1e-6):  # approach the line until the kurtosis is passed
        hi = math.log(delta_line * (1.0 - gap))
        try:
            if excess(hi) > 0:
                break
        except ValueError:
            raise far from None
    else:
        raise far
    delta = math.exp(optimize.brentq(excess, lo, hi, xtol=1e-14, rtol=1e-15))
    gamma = gamma_for(delta)
    return delta, (gamma if skew >= 0 else -gamma)


@functools.lru_cache(maxsize=128)
def fit_johnson(skew: float, kurt: float) -> tuple[str, float, float]:
    """The Johnson curve with skewness ``skew`` and kurtosis ``kurt``: ``(kind, gamma, delta)``.

    ``kind`` is ``'SU'``, ``'SB'``, ``'SL'`` (within :data:`NEAR_LINE` of the lognormal line;
    then ``gamma`` is the orientation, +1 or -1) or ``'N'`` (within :data:`NEAR_NORMAL` of
    the normal point).  Skewness and kurtosis must satisfy :math:`Ku > 1 + Sk^2`.

    Parameters
    ----------
    skew : float
        Skewness.
    kurt : float
        Kurtosis (3 for a Gaussian), > 1 + skew^2.

    Returns
    -------
    kind : str
    gamma, delta : float
        Shape parameters; for S_U and S_B :math:`x = \\gamma + \\delta g(y)`.

    Raises
    ------
    ValueError
        If the pair lies outside the region the fit handles (message says why).
    """
    if abs(skew) < NEAR_NORMAL and abs(kurt - 3.0) < NEAR_NORMAL:
        return "N", 0.0, math.inf
    w, k_line = lognormal_line(skew)
    if abs(kurt - k_line) <= NEAR_LINE * k_line:
        if w - 1.0 < 1e-12:  # skewness ~ 0 on the line: the normal point
            return "N", 0.0, math.inf
        return "SL", (1.0 if skew > 0 else -1.0), 1.0 / math.sqrt(math.log(w))
    if kurt > k_line:
        delta, Omega = _solve_su(skew, kurt)
        return "SU", Omega * delta, delta
    delta, gamma = _solve_sb(skew, kurt)
    return "SB", gamma, delta
