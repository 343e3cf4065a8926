r"""Hertz contact of one elastic asperity on a rigid flat (Eqs 6 and 8, no adhesion).

In the paper's units (penetration over :math:`\sigma`, radius over :math:`b`, force
over :math:`G b^2`):

.. math::
    \bar a = \beta\,\bar u^{1/2}, \qquad
    \frac{P}{G b^2} = \frac43\,\frac{2}{1-\nu}\,\alpha\beta^2\,\bar u^{3/2},

from :math:`a = (Ru)^{1/2}` and :math:`P = \tfrac43 E^* R^{1/2} u^{3/2}` with
:math:`E^*/G = 2/(1-\nu)`.  In Maugis' units (:mod:`asperity.maugis_dugdale`) Hertz is
:math:`P = A^3`, :math:`\Delta = A^2`.

References
----------
.. [1] K. L. Johnson, Contact Mechanics, CUP (1985), ch. 4.
.. [2] Adams et al., Eqs (6) and (8).
"""

from __future__ import annotations

import numpy as np

from ._validation import as_float_array, check_poisson, check_positive

__all__ = ["hertz_radius", "hertz_force", "hertz_load_md", "hertz_penetration_md"]


def _penetration(u_bar):
    u = as_float_array(u_bar, "u_bar", allow_empty=True)
    return np.maximum(u, 0.0)


def hertz_radius(u_bar, beta):
    r"""Hertz contact radius :math:`\bar a = a/b = \beta\,\bar u^{1/2}` (Eq 8).

    Parameters
    ----------
    u_bar : array_like
        Penetration :math:`(z-d)/\sigma`; negative values (no contact) give 0.
    beta : array_like
        Friction regime parameter :math:`\beta = (R\sigma)^{1/2}/b > 0` (Eq 7).

    References
    ----------
    Adams et al., Eq (8).
    """
    return check_positive(beta, "beta") * np.sqrt(_penetration(u_bar))


def hertz_force(u_bar, alpha, beta, nu=0.3):
    r"""Hertz force of one asperity, :math:`P/(Gb^2) = \tfrac43\tfrac{2}{1-\nu}\alpha\beta^2\bar u^{3/2}`.

    This is the integrand of Eq (6).

    Parameters
    ----------
    u_bar : array_like
        Penetration :math:`(z-d)/\sigma`; negative values give 0.
    alpha, beta : array_like
        Roughness and friction-regime parameters (Eq 7), > 0.
    nu : array_like
        Poisson's ratio, -1 < nu < 0.5.

    References
    ----------
    Adams et al., Eq (6).
    """
    alpha = check_positive(alpha, "alpha")
    beta = check_positive(beta, "beta")
    nu = check_poisson(nu)
    return (8.0 / 3.0) / (1.0 - nu) * alpha * beta**2 * _penetration(u_bar) ** 1.5


def hertz_load_md(A):
    """Hertz load in Maugis units, :math:`P/(\\pi w R) = A^3`."""
    return as_float_array(A, "A", allow_empty=True) ** 3


def hertz_penetration_md(A):
    """Hertz penetration in Maugis units, :math:`\\Delta = A^2`."""
    return as_float_array(A, "A", allow_empty=True) ** 2
