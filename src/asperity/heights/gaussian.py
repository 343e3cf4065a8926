r"""The paper's Gaussian summit heights (Eq 19) and the GW moment of a Gaussian.

.. math::
    \phi(\bar z) = \frac{e^{-\bar z^2/2}}{\sqrt{2\pi}},\qquad
    F_n(\bar d) = \int_{\bar d}^\infty(\bar z-\bar d)^n\phi\,d\bar z
        = \frac{\Gamma(n+1)}{\sqrt{2\pi}}\,e^{-\bar d^2/4}\,D_{-n-1}(\bar d)

with :math:`D_\nu` the parabolic-cylinder function (Greenwood & Williamson 1966).  The
Gaussian factorises its quadrature sums (:meth:`Gaussian.panel_sums`), which makes every
separation cost a row of exponentials; the two-Gaussian mixture and the kernel estimate
of :mod:`asperity.heights.mixture` reuse it component by component.

References
----------
.. [1] J. A. Greenwood, J. B. P. Williamson, Proc. R. Soc. A 295 (1966) 300.
.. [2] Adams et al., Eq (19).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from scipy import special

from .._validation import as_float_array, check_finite_result, ufunc_result
from .base import HeightDistribution, check_derivative_order, check_order, gw_moment_quadrature_unchecked

__all__ = ["Gaussian", "GAUSSIAN", "gaussian_moment"]

_SQRT_2PI = math.sqrt(2.0 * math.pi)


@dataclass(frozen=True)
class Gaussian(HeightDistribution):
    r"""Standard normal heights (Eq 19): :math:`\phi(\bar z) = e^{-\bar z^2/2}/\sqrt{2\pi}`.

    Examples
    --------
    >>> g = Gaussian()
    >>> g, g == GAUSSIAN, g.spec, float(g.sf(0.0))
    (Gaussian(), True, 'gaussian', 0.5)
    """

    z_top = 10.0
    z_bottom = -10.0
    z_end = 35.0
    fast_sums = True
    name: ClassVar[str] = "gaussian"

    def pdf(self, z):
        """Density :math:`\\phi(z)`, shape of ``z``."""
        z = np.asarray(z, dtype=float)
        return np.exp(-0.5 * z * z) / _SQRT_2PI

    def pdf_derivative(self, z, order: int):
        """:math:`\\phi' = -z\\phi` (order 1) or :math:`\\phi'' = (z^2-1)\\phi` (order 2)."""
        z = np.asarray(z, dtype=float)
        if check_derivative_order(order) == 1:
            return -z * self.pdf(z)
        return (z * z - 1.0) * self.pdf(z)

    def sf(self, z):
        """Survival function :math:`Q(z) = \\Phi(-z)`."""
        return special.ndtr(-np.asarray(z, dtype=float))

    def stats(self) -> tuple[float, float, float, float]:
        """``(0, 1, 0, 3)``: mean, variance, skewness, kurtosis."""
        return 0.0, 1.0, 0.0, 3.0

    def weighted_sums(self, d, u, weights, order: int = 0):
        # phi' = -x phi and phi'' = (x^2 - 1) phi with x = d + u: one exponential matrix
        # serves every order, the u-powers going into the weights (BLAS does the rest).
        E = self.pdf(d[:, None] + u[None, :])
        return self._combine(d, [E @ (u[:, None] ** k * weights) for k in range(order + 1)])

    def panel_sums(self, d, centers, offsets, weights, order: int = 0):
        r""":meth:`weighted_sums` for nodes ``centers[p] + offsets[j]`` of equal panels.

        The Gaussian factorises: with :math:`x = d + c_p`,
        :math:`\phi(x + \xi_j) = \phi(x)\,e^{-(d-d_0)\xi_j}\,e^{-(c_p+d_0)\xi_j - \xi_j^2/2}`, so
        a block of P panels of J nodes costs P + J exponentials per separation instead
        of P J.  ``weights`` has shape (P, J, columns).
        """
        # Shift by a reference d0 so e^(-(d - d0) xi) stays finite; where e^(-(c + d0) xi)
        # would overflow the density factor phi(d + c) is already exactly zero.
        d0 = 0.5 * float(d.min() + d.max()) if d.size else 0.0  # mid-range: smallest |d - d0|
        far = np.abs(d - d0) * np.abs(offsets).max() > 100.0
        if np.any(far):
            out = [np.empty((d.size, weights.shape[-1])) for _ in range(order + 1)]
            for rows, method in ((far, super().panel_sums), (~far, self.panel_sums)):
                if np.any(rows):
                    parts = method(d[rows], centers, offsets, weights, order)
                    for o, part in zip(out, parts, strict=True):
                        o[rows] = part
            return out
        A = self.pdf(d[:, None] + centers[None, :])  # (n, P)
        B = np.exp(-(d - d0)[:, None] * offsets[None, :])  # (n, J)
        C = np.exp(np.minimum(-np.outer(centers + d0, offsets) - 0.5 * offsets**2, 300.0))
        u = centers[:, None] + offsets[None, :]
        sums = []
        for k in range(order + 1):
            Wk = (C * u**k)[:, :, None] * weights  # (P, J, c)
            npan, nj, nc = Wk.shape
            # M[n, p, c] = sum_j B[n, j] Wk[p, j, c]
            M = (B @ Wk.transpose(1, 0, 2).reshape(nj, npan * nc)).reshape(-1, npan, nc)
            sums.append((A[:, None, :] @ M)[:, 0, :])  # sum_p A[n, p] M[n, p, c]
        return self._combine(d, sums)

    @staticmethod
    def _combine(d, sums):
        """Derivatives in d from S_k = sum w u^k phi(d + u): phi' = -x phi, phi'' = (x^2-1) phi."""
        dd = d[:, None]
        out = [sums[0]]
        if len(sums) > 1:
            out.append(-(dd * sums[0] + sums[1]))
        if len(sums) > 2:
            out.append(dd * dd * sums[0] + 2.0 * dd * sums[1] + sums[2] - sums[0])
        return out

    def moment(self, d, order):
        r"""GW moment :math:`\int_d^\infty (z-d)^n\phi(z)\,dz = \Gamma(n+1)e^{-d^2/4}D_{-n-1}(d)/\sqrt{2\pi}`.

        :func:`gaussian_moment`: the parabolic-cylinder closed form for integer orders
        (:func:`scipy.special.pbdv`), fixed high-order quadrature otherwise.

        Parameters
        ----------
        d : array_like
            Separation :math:`\bar d`, finite (any shape).
        order : float
            :math:`n > -1` (0: contact fraction, 1: area, 3/2: Hertz load).

        Returns
        -------
        ndarray
            :math:`F_n(\bar d)`, shape of ``d``.
        """
        d = as_float_array(d, "d", allow_empty=True)
        n = check_order(order)
        return self._checked_moment(lambda x: gaussian_moment(x, n), d, n)


#: The paper's distribution (Eq 19).
GAUSSIAN = Gaussian()


def gaussian_moment(x, order: float):
    r"""GW moment of the standard normal density, :math:`G_n(x) = \int_x^\infty (z-x)^n\phi(z)\,dz`.

    .. math::
        G_n(x) = \frac{\Gamma(n+1)}{\sqrt{2\pi}}\,e^{-x^2/4}\,D_{-n-1}(x)

    The parabolic-cylinder form (:func:`scipy.special.pbdv`) is exact to about 1e-14 for
    integer :math:`n` and :math:`x \ge -35`; for other orders SciPy's :math:`D_\nu` loses
    up to 1e-9 (e.g. :math:`n = 3/2` near :math:`x = 6`), so those, and :math:`x < -35`
    where the form overflows, use :func:`~asperity.heights.base.gw_moment_quadrature`
    (about 1e-14).

    Parameters
    ----------
    x : array_like
        Separations (any shape), finite.
    order : float
        :math:`-1 < n \le` :data:`~asperity.heights.base.MAX_ORDER`.

    Returns
    -------
    ndarray
        :math:`G_n(x)`, shape of ``x``.

    Raises
    ------
    ValueError
        If ``x`` is not real and finite, ``order`` out of range, or :math:`G_n` leaves
        double precision (far below the mean, for high orders).

    References
    ----------
    Greenwood & Williamson (1966); Abramowitz & Stegun 19.5.3 (integral of :math:`D_\nu`).
    """
    x = as_float_array(x, "x", allow_empty=True)
    k = check_order(order)
    # above x = 40, G_n < Gamma(n + 1) phi(x) / x^(n+1) is below the smallest double for every
    # order served (SciPy's D_nu gives NaN far out)
    zero = x > 40.0
    closed = (x >= -35.0) & ~zero & (k == round(k))
    out = np.zeros(x.shape)
    with np.errstate(all="ignore"):
        if np.any(closed):
            D, _ = special.pbdv(-k - 1.0, x[closed])
            out[closed] = special.gamma(k + 1.0) * np.exp(-0.25 * x[closed] ** 2) * D / _SQRT_2PI
        rest = ~closed & ~zero
        if np.any(rest):
            out[rest] = gw_moment_quadrature_unchecked(GAUSSIAN, x[rest], k)
    return ufunc_result(check_finite_result(out, f"the Gaussian moment of order {k:g}", x=x))
