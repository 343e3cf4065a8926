r"""Exponential summit heights (Greenwood & Williamson 1966), standardised.

GW (1966) noted that with exponential heights the real contact area is exactly
proportional to the load; the upper tail of many real summit distributions is close to
exponential.  Standardised to zero mean and unit variance:

.. math::
    \phi(\bar z) = e^{-(\bar z + 1)}\quad(\bar z \ge -1),\qquad
    F_n(\bar d) = \int_{\bar d}^\infty(\bar z-\bar d)^n\phi\,d\bar z =
    \begin{cases}
      \Gamma(n+1)\,e^{-(\bar d+1)} & \bar d \ge -1\\
      e^{D}\,\Gamma(n+1, D) = D^{n+1}\,U(1, n+2, D) & D = -1-\bar d > 0
    \end{cases}

(skewness 2, kurtosis 9; :math:`\Gamma(a, x)` the upper incomplete gamma function, U
Tricomi's confluent hypergeometric function).  The density jumps at the support edge
:math:`\bar z = -1`: the model's integrals treat the edge explicitly
(:mod:`asperity.height_sums`).

References
----------
.. [1] J. A. Greenwood, J. B. P. Williamson, Proc. R. Soc. A 295 (1966) 300, section 3.
.. [2] Abramowitz & Stegun 6.5.3, 13.2.5.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from scipy import special

from .._validation import as_float_array, check_finite_result, ufunc_result
from .base import TAIL, HeightDistribution, check_derivative_order, check_order

__all__ = ["Exponential", "exponential_moment"]


@dataclass(frozen=True)
class Exponential(HeightDistribution):
    r"""Standardised exponential heights, :math:`\phi(\bar z) = e^{-(\bar z+1)}` for :math:`\bar z \ge -1`.

    Examples
    --------
    >>> e = Exponential()
    >>> e, e.spec, e.support, [round(x, 12) for x in e.stats()]
    (Exponential(), 'exponential', (-1.0, inf), [0.0, 1.0, 2.0, 9.0])
    """

    z_bottom = -1.0
    z_top = -1.0 - math.log(TAIL)  # sf(z_top) = TAIL: 51.96
    support = (-1.0, math.inf)
    z_end = 643.0  # sf = 1e-280
    name: ClassVar[str] = "exponential"

    def pdf(self, z):
        """Density :math:`e^{-(z+1)}` for :math:`z \\ge -1`, else 0."""
        z = np.asarray(z, dtype=float)
        return np.where(z >= -1.0, np.exp(-(np.maximum(z, -1.0) + 1.0)), 0.0)

    def pdf_derivative(self, z, order: int):
        """:math:`\\phi' = -\\phi`, :math:`\\phi'' = \\phi` inside the support (0 outside)."""
        return (-1.0) ** check_derivative_order(order) * self.pdf(z)

    def sf(self, z):
        """Survival function :math:`e^{-(z+1)}` above -1, 1 below."""
        z = np.asarray(z, dtype=float)
        return np.exp(-(np.maximum(z, -1.0) + 1.0))

    def stats(self) -> tuple[float, float, float, float]:
        """``(0, 1, 2, 9)``: mean, variance, skewness, kurtosis."""
        return 0.0, 1.0, 2.0, 9.0

    def weighted_sums(self, d, u, weights, order: int = 0):
        r"""The sums factorise: :math:`\phi(\bar d + \bar u_k) = e^{-(\bar u_k - u_c)}` above the cut
        :math:`u_c = -1 - \bar d`, so each separation is a suffix sum of the node weights (order 0;
        the derivatives use the default)."""
        if order > 0 or d.size == 0:
            return super().weighted_sums(d, u, weights, order)
        ref = -1.0 - float(d.max())  # the lowest cut: every exponent below is <= 0
        keep = u >= ref
        us = u[keep]
        srt = np.argsort(us, kind="stable")
        us = us[srt]
        g = np.exp(-(us - ref))[:, None] * weights[keep][srt]
        suffix = np.concatenate([np.cumsum(g[::-1], axis=0)[::-1], np.zeros((1, weights.shape[1]))])
        first = np.searchsorted(us, -1.0 - d, side="left")
        return [np.exp(-(d - float(d.max())))[:, None] * suffix[first]]

    def moment(self, d, order):
        r"""GW moment :math:`F_n(\bar d)` in closed form (:func:`exponential_moment`).

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
        return self._checked_moment(lambda x: _exponential_form(x, n), d, n)


def exponential_moment(d, order: float):
    r"""GW moment of the standardised exponential density.

    .. math::
        F_n(\bar d) = \Gamma(n+1)\,e^{-(\bar d+1)}\ (\bar d \ge -1),\qquad
        F_n(\bar d) = e^{D}\,\Gamma(n+1)\,Q(n+1, D) = D^{n+1}U(1, n+2, D),\ D = -1-\bar d > 0

    with :math:`Q` the regularised upper incomplete gamma function
    (:func:`scipy.special.gammaincc`, used for :math:`D \le 500`, where it is exact to
    about 5e-14) and U Tricomi's function (:func:`scipy.special.hyperu`, for larger D;
    SciPy's U loses up to 4e-10 near :math:`D \approx 10` for non-integer n, so it is not
    used there).

    Parameters
    ----------
    d : array_like
        Separations (any shape), finite.
    order : float
        :math:`-1 < n \le` :data:`~asperity.heights.base.MAX_ORDER`.

    Returns
    -------
    ndarray
        :math:`F_n(\bar d)`, shape of ``d``.

    Raises
    ------
    ValueError
        If ``d`` is not real and finite, ``order`` out of range, or :math:`F_n` leaves
        double precision (far below the support, for high orders).

    References
    ----------
    Greenwood & Williamson (1966); Abramowitz & Stegun 6.5.3, 13.2.5.
    """
    d = as_float_array(d, "d", allow_empty=True)
    n = check_order(order)
    with np.errstate(all="ignore"):
        out = _exponential_form(d, n)
    return ufunc_result(check_finite_result(out, f"the exponential moment of order {n:g}", d=d))


def _exponential_form(d, n):
    """The closed form of :func:`exponential_moment` for checked arrays (any warnings to the caller)."""
    D = -1.0 - d
    out = special.gamma(n + 1.0) * np.exp(-np.maximum(-D, 0.0))
    mid = (D > 0) & (D <= 500.0)
    out = np.where(mid, np.exp(np.where(mid, D, 0.0)) * special.gamma(n + 1.0)
                   * special.gammaincc(n + 1.0, np.where(mid, D, 1.0)), out)
    far = D > 500.0
    if np.any(far):
        out[far] = D[far] ** (n + 1.0) * special.hyperu(1.0, n + 2.0, D[far])
    return out
