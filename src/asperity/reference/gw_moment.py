r"""Reference for the Gaussian Greenwood-Williamson moments :math:`F_k(d)` by mpmath.

:math:`F_k(d) = \int_d^\infty (z-d)^k\,\phi(z)\,dz` with :math:`\phi` the standard normal
density (Greenwood & Williamson 1966; the integrals of Eqs 5 and 6 of the paper),
written from the definition only: :func:`mpmath.quad` at 30 digits, the range split where
the integrand changes scale.  The fast path's closed form (parabolic-cylinder functions)
is tested against it.

References
----------
.. [1] J. A. Greenwood, J. B. P. Williamson, "Contact of nominally flat surfaces",
   Proc. R. Soc. A 295 (1966) 300-319.
"""

from __future__ import annotations

from .common import MP, finite, mpmath

__all__ = ["gw_moment"]


def gw_moment(d, order):
    """Greenwood-Williamson moment ``int_d^inf (z - d)^order phi(z) dz`` (mpmath).

    Parameters
    ----------
    d : float
        Dimensionless separation.
    order : float
        Order ``k >= 0`` of the moment.

    Returns
    -------
    float
        The moment, computed with :func:`mpmath.quad` at 30 digits.
    """
    d = finite("d", d)
    order = finite("order", order)
    if order < 0:
        raise ValueError(f"order must be >= 0, got {order!r}")
    with MP.workdps(30):
        dm = mpmath.mpf(d)
        k = mpmath.mpf(order)
        c = 1 / mpmath.sqrt(2 * mpmath.pi)

        def f(u):
            return u**k * c * mpmath.exp(-((u + dm) ** 2) / 2)

        scale = 1 / (1 + max(d, 0.0))
        pts = [mpmath.mpf(0), scale / 4, scale, 4 * scale]
        if d < 0:
            pts += [-dm / 2, -dm, -dm + 2]
        pts = sorted(set(pts))
        pts.append(pts[-1] + 8)
        pts.append(mpmath.inf)
        return float(mpmath.quad(f, pts))
