r"""Statistics of asperity (summit) heights: the :math:`\phi(\bar z)` of Eqs (5)-(10).

Heights are in units of their standard deviation :math:`\sigma`.  A distribution
supplies its density and the derivatives of the density (for the separation that
matches a load, found by Newton's method), plus where its upper tail becomes
negligible.  The multi-asperity integrals only ever need

.. math::
    S_j(\bar d) = \sum_k w_k\, q_k\, \phi^{(j)}(\bar d + \bar u_k),

sums over quadrature nodes :math:`\bar u_k` in penetration, so a distribution may
override :meth:`HeightDistribution.weighted_sums` with something faster (the Gaussian
does).  Exponential, Weibull or empirical heights implement the same interface.

References
----------
.. [1] J. A. Greenwood, J. B. P. Williamson, Proc. R. Soc. A 295 (1966) 300.
.. [2] Adams et al., Eq (19).
"""

from __future__ import annotations

import abc
import math

import numpy as np
from scipy import special

from ._validation import as_float_array

__all__ = ["HeightDistribution", "Gaussian", "GAUSSIAN"]

_SQRT_2PI = math.sqrt(2.0 * math.pi)


class HeightDistribution(abc.ABC):
    """Interface of a distribution of asperity heights (in units of sigma).

    The quadrature nodes are placed for a smooth density on [-z_top, z_top]: a density
    with a kink or a finite support edge (exponential, Weibull) should also override
    :meth:`weighted_sums` or add its own breakpoints; the Gaussian needs neither.
    """

    #: Heights above this carry a negligible share of any integral (pdf < ~1e-22).
    z_top: float = 10.0

    def __repr__(self) -> str:
        """``Name()``, so signatures and help() show the distribution, not an object address
        (a distribution with parameters shows them, as a dataclass does).

        >>> GAUSSIAN
        Gaussian()
        """
        return f"{type(self).__name__}()"

    @abc.abstractmethod
    def pdf(self, z):
        """Probability density phi(z)."""

    @abc.abstractmethod
    def pdf_derivative(self, z, order: int):
        """d^order phi / dz^order at z (order 1 or 2)."""

    @abc.abstractmethod
    def sf(self, z):
        """Survival function: the fraction of asperities higher than z."""

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


class Gaussian(HeightDistribution):
    r"""Standard normal heights (Eq 19): :math:`\phi(\bar z) = e^{-\bar z^2/2}/\sqrt{2\pi}`."""

    z_top = 10.0

    def pdf(self, z):
        z = np.asarray(z, dtype=float)
        return np.exp(-0.5 * z * z) / _SQRT_2PI

    def pdf_derivative(self, z, order: int):
        z = np.asarray(z, dtype=float)
        if order == 1:
            return -z * self.pdf(z)
        if order == 2:
            return (z * z - 1.0) * self.pdf(z)
        raise ValueError(f"order must be 1 or 2, got {order}")

    def sf(self, z):
        return special.ndtr(-np.asarray(z, dtype=float))

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
        r"""Closed form :math:`\int_d^\infty (z-d)^k\phi(z)\,dz = \Gamma(k+1)e^{-d^2/4}D_{-k-1}(d)/\sqrt{2\pi}`.

        Uses :func:`scipy.special.pbdv`, good to about 1e-10 relative for non-integer
        orders; the tests use mpmath for tighter checks.

        Parameters
        ----------
        d : array_like
            Separation :math:`\bar d`.
        order : float
            :math:`k > -1` (0: contact fraction, 1: area, 3/2: Hertz load).
        """
        d = as_float_array(d, "d", allow_empty=True)
        if np.any(d < -35.0):
            raise ValueError("d must be >= -35 for the parabolic-cylinder form (it overflows below)")
        k = float(order)
        if not k > -1:
            raise ValueError(f"order must be > -1, got {order!r}")
        D, _ = special.pbdv(-k - 1.0, d)
        return special.gamma(k + 1.0) * np.exp(-0.25 * d * d) * D / _SQRT_2PI


#: The paper's distribution (Eq 19).
GAUSSIAN = Gaussian()
