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

from ._validation import (
    as_float_array,
    check_broadcast,
    check_finite_result,
    check_overflow,
    check_poisson,
    check_positive,
    check_positive_scaled,
    check_radius,
)
from .units import to_si

__all__ = ["hertz_radius", "hertz_force", "hertz_load_md", "hertz_penetration_md", "hertz_contact_radius",
           "hertz_normal_force"]

_FLOAT_MAX = float(np.finfo(float).max)


def _penetration(u_bar):
    u = as_float_array(u_bar, "u_bar", allow_empty=True)
    return np.maximum(u, 0.0)


def hertz_radius(u_bar, beta):
    r"""Hertz contact radius :math:`\bar a = a/b = \beta\,\bar u^{1/2}` (Eq 8).

    .. math::
        \bar a = \beta\,\bar u^{1/2}\quad(\bar u > 0),\qquad \bar a = 0\quad(\bar u \le 0)

    Parameters
    ----------
    u_bar : array_like
        Penetration :math:`\bar u = (z-d)/\sigma`, finite; negative values (no contact) give 0.
        At most :math:`(\mathrm{DBL\_MAX}/\beta)^2` (DBL_MAX = 1.8e308), beyond which the
        radius overflows.
    beta : array_like
        Friction regime parameter :math:`\beta = (R\sigma)^{1/2}/b > 0` (Eq 7).

    Returns
    -------
    ndarray
        :math:`a/b`, the broadcast shape of ``u_bar`` and ``beta``.

    Raises
    ------
    ValueError
        If an input is not real and finite, ``beta <= 0``, or the radius would overflow.

    Examples
    --------
    >>> float(hertz_radius(4.0, 10.0))
    20.0

    References
    ----------
    Adams et al., Eq (8).
    """
    beta = check_positive(beta, "beta")
    u = _penetration(u_bar)
    check_broadcast(u_bar=u, beta=beta)
    with np.errstate(over="ignore"):
        a = beta * np.sqrt(u)
    return check_overflow(a, "u_bar", lambda: (_FLOAT_MAX / beta) ** 2, u)


def hertz_force(u_bar, alpha, beta, nu=0.3):
    r"""Hertz force of one asperity, :math:`P/(Gb^2) = \tfrac43\tfrac{2}{1-\nu}\alpha\beta^2\bar u^{3/2}`.

    .. math::
        \frac{P}{Gb^2} = \frac43\,\frac{2}{1-\nu}\,\alpha\beta^2\,\bar u^{3/2}

    from :math:`P = \tfrac43E^*R^{1/2}u^{3/2}` and :math:`E^*/G = 2/(1-\nu)`: the integrand
    of Eq (6).

    Parameters
    ----------
    u_bar : array_like
        Penetration :math:`\bar u = (z-d)/\sigma`, finite; negative values give 0.  At most
        :math:`(\mathrm{DBL\_MAX}/\max(c, 1))^{2/3}` with :math:`c = \tfrac83\alpha\beta^2/(1-\nu)`
        and DBL_MAX = 1.8e308, beyond which the force overflows.
    alpha : array_like
        Roughness parameter :math:`\alpha = (\sigma/R)^{1/2} > 0` (Eq 7).
    beta : array_like
        Friction regime parameter :math:`\beta = (R\sigma)^{1/2}/b > 0` (Eq 7), with
        :math:`\beta^2` and :math:`c` finite.
    nu : array_like
        Poisson's ratio :math:`\nu`, -1 < nu < 0.5 (default 0.3).

    Returns
    -------
    ndarray
        :math:`P/(Gb^2)`, the broadcast shape of the inputs.

    Raises
    ------
    ValueError
        If an input is not real and finite or out of its range, or the force would overflow.

    Examples
    --------
    >>> round(float(hertz_force(1.0, 0.01, 1000.0, nu=0.3)), 6)  # (8/3)/0.7 * 0.01 * 1e6
    38095.238095

    References
    ----------
    Adams et al., Eq (6); Johnson (1985), Eq (4.23).
    """
    alpha = check_positive(alpha, "alpha")
    beta = check_positive(beta, "beta")
    nu = check_poisson(nu)
    u = _penetration(u_bar)
    check_broadcast(u_bar=u, alpha=alpha, beta=beta, nu=nu)
    with np.errstate(over="ignore", invalid="ignore"):
        scale = (8.0 / 3.0) / (1.0 - nu) * alpha * beta**2
        P = scale * u**1.5
    # beta**2 and the scale must stay finite; then u**1.5 and the product.
    check_overflow(scale, "beta", lambda: np.sqrt(_FLOAT_MAX / np.maximum((8.0 / 3.0) / (1.0 - nu) * alpha, 1.0)),
                   beta, given={"alpha": alpha, "nu": nu})
    return check_overflow(P, "u_bar", lambda: (_FLOAT_MAX / np.maximum(scale, 1.0)) ** (2.0 / 3.0), u)


def hertz_load_md(A):
    r"""Hertz load in Maugis' units, :math:`P/(\pi wR) = A^3` (the :math:`w \to 0` limit).

    .. math::
        \frac{P}{\pi wR} = A^3,\qquad A = a\Big(\frac{K}{\pi wR^2}\Big)^{1/3}

    Parameters
    ----------
    A : array_like
        Contact radius in Maugis' units, :math:`0 \le A \le \mathrm{DBL\_MAX}^{1/3}`
        (about 5.6e102; beyond, the load overflows).  May be empty.

    Returns
    -------
    ndarray
        :math:`P/(\pi wR)`, the shape of ``A``.

    Raises
    ------
    ValueError
        If ``A`` is not real and finite, negative, or its load would overflow.

    Examples
    --------
    >>> float(hertz_load_md(2.0))
    8.0

    References
    ----------
    Maugis (1992); Johnson (1985), ch. 4.
    """
    A = check_radius(A)
    with np.errstate(over="ignore"):
        P = A**3
    return check_overflow(P, "A", np.cbrt(_FLOAT_MAX), A)


def hertz_penetration_md(A):
    r"""Hertz penetration in Maugis' units, :math:`\Delta = A^2`.

    .. math::
        \Delta = A^2,\qquad \Delta = u\Big(\frac{K^2}{\pi^2w^2R}\Big)^{1/3}

    Parameters
    ----------
    A : array_like
        Contact radius in Maugis' units, :math:`0 \le A \le \mathrm{DBL\_MAX}^{1/2}`
        (about 1.3e154; beyond, the penetration overflows).  May be empty.

    Returns
    -------
    ndarray
        :math:`\Delta`, the shape of ``A``.

    Raises
    ------
    ValueError
        If ``A`` is not real and finite, negative, or its penetration would overflow.

    Examples
    --------
    >>> float(hertz_penetration_md(3.0))
    9.0

    References
    ----------
    Maugis (1992); Johnson (1985), ch. 4.
    """
    A = check_radius(A)
    with np.errstate(over="ignore"):
        D = A**2
    return check_overflow(D, "A", np.sqrt(_FLOAT_MAX), A)


# -- the physical shell ----------------------------------------------------------------------
def hertz_contact_radius(P, *, R, E_star):
    r"""Hertz contact radius of a sphere on a flat at load :math:`P`, in metres.

    .. math::
        a = \Big(\frac{PR}{K}\Big)^{1/3},\qquad K = \tfrac43E^*,\qquad P \ge 0

    Parameters
    ----------
    P : array_like
        Normal load :math:`P` (N), >= 0.
    R : array_like
        Sphere (tip) radius :math:`R` (m), > 0.
    E_star : array_like
        Composite Young's modulus :math:`E^*` (Pa), > 0.

    Returns
    -------
    ndarray
        Contact radius :math:`a` (m), the broadcast shape of the inputs.

    Raises
    ------
    ValueError
        If an input is not real and finite or out of range (a negative load: no adhesion,
        no tensile contact).

    Examples
    --------
    >>> round(float(hertz_contact_radius(1e-6, R=1e-6, E_star=0.75e9)) * 1e9, 9)  # (1e-21 m^3)^(1/3) in nm
    100.0

    References
    ----------
    H. Hertz (1882); Johnson (1985), Eq (4.22).
    """
    P = as_float_array(to_si(P, "N", "P"), "P", allow_empty=True)
    R = check_positive(to_si(R, "m", "R"), "R")
    K = check_positive_scaled(to_si(E_star, "Pa", "E_star"), "E_star", 4.0 / 3.0)
    check_broadcast(P=P, R=R, E_star=K)
    if np.any(P < 0):
        raise ValueError(f"P (load) must be >= 0 without adhesion (Hertz), got min {P.min():g} N")
    with np.errstate(all="ignore"):
        a = np.cbrt(P * R / K)
    return check_finite_result(a, "the Hertz contact radius", P=P, R=R, E_star=E_star)


def hertz_normal_force(delta, *, R, E_star):
    r"""Hertz normal force of a sphere on a flat at penetration :math:`\delta`, in newtons.

    .. math::
        P = KR^{1/2}\delta^{3/2},\qquad K = \tfrac43E^*,\qquad \delta \ge 0

    Parameters
    ----------
    delta : array_like
        Penetration :math:`\delta` (m), >= 0.
    R : array_like
        Sphere radius :math:`R` (m), > 0.
    E_star : array_like
        Composite Young's modulus :math:`E^*` (Pa), > 0.

    Returns
    -------
    ndarray
        Normal force :math:`P` (N), the broadcast shape of the inputs.

    Raises
    ------
    ValueError
        If an input is not real and finite or out of range (a negative penetration).

    Examples
    --------
    >>> float(hertz_normal_force(1e-9, R=1e-6, E_star=0.75e9)) == 1e9 * 1e-3 * 1e-9**1.5
    True

    References
    ----------
    H. Hertz (1882); Johnson (1985), Eq (4.23).
    """
    delta = as_float_array(to_si(delta, "m", "delta"), "delta", allow_empty=True)
    R = check_positive(to_si(R, "m", "R"), "R")
    K = check_positive_scaled(to_si(E_star, "Pa", "E_star"), "E_star", 4.0 / 3.0)
    check_broadcast(delta=delta, R=R, E_star=K)
    if np.any(delta < 0):
        raise ValueError("delta (penetration) must be >= 0 without adhesion (Hertz)")
    with np.errstate(all="ignore"):
        F = K * np.sqrt(R) * delta**1.5
    return check_finite_result(F, "the Hertz force", delta=delta, R=R, E_star=E_star)
