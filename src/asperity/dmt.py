r"""DMT adhesive contact (the :math:`\lambda \to 0` limit of Maugis-Dugdale).

In Maugis' units the contact keeps its Hertz radius and penetration while the
adhesive ring outside it pulls with :math:`2\pi w R`:

.. math::
    P = A^3 - 2, \qquad \Delta = A^2,

so the pull-off load is :math:`-2` (:math:`-2\pi w R`) under either control.

References
----------
.. [1] B. V. Derjaguin, V. M. Muller, Yu. P. Toporov, J. Colloid Interface Sci. 53
   (1975) 314.
"""

from __future__ import annotations

import numpy as np

from ._validation import (
    as_float_array,
    check_broadcast,
    check_finite_result,
    check_nonnegative,
    check_overflow,
    check_positive,
    check_positive_scaled,
    check_radius,
)
from .units import to_si

__all__ = ["dmt_load", "dmt_penetration", "DMT_PULL_OFF", "dmt_solve_load", "dmt_solve", "dmt_contact_radius",
           "dmt_normal_force", "dmt_pull_off_force"]

#: DMT pull-off load P/(pi w R).
DMT_PULL_OFF = -2.0

_FLOAT_MAX = float(np.finfo(float).max)


def dmt_load(A):
    r"""DMT load in Maugis' units, :math:`P/(\pi wR) = A^3 - 2`.

    .. math::
        \frac{P}{\pi wR} = A^3 - 2,\qquad A = a\Big(\frac{K}{\pi wR^2}\Big)^{1/3}

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
        If ``A`` is not real and finite, negative, or the load would overflow.

    Examples
    --------
    >>> float(dmt_load(0.0)) == DMT_PULL_OFF
    True

    References
    ----------
    Derjaguin, Muller & Toporov (1975); Maugis (1992).
    """
    A = check_radius(A)
    with np.errstate(over="ignore"):
        P = A**3 - 2.0
    return check_overflow(P, "A", np.cbrt(_FLOAT_MAX), A)


def dmt_penetration(A):
    r"""DMT penetration in Maugis' units, :math:`\Delta = A^2` (Hertzian).

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
        If ``A`` is not real and finite, negative, or the penetration would overflow.

    Examples
    --------
    >>> float(dmt_penetration(3.0))
    9.0

    References
    ----------
    Derjaguin, Muller & Toporov (1975); Maugis (1992).
    """
    A = check_radius(A)
    with np.errstate(over="ignore"):
        D = A**2
    return check_overflow(D, "A", np.sqrt(_FLOAT_MAX), A)


# -- load control, displacement control and the physical shell -----------------------------
def dmt_solve_load(P):
    r"""DMT contact radius and penetration at a given load, in Maugis' units.

    .. math::
        A = (P + 2)^{1/3},\qquad \Delta = A^2,\qquad P \ge -2

    Parameters
    ----------
    P : array_like
        Load :math:`P/(\pi wR)`, from the pull-off -2 up to 1e300.  May be empty.

    Returns
    -------
    A, delta : ndarray
        Contact radius :math:`a(K/\pi wR^2)^{1/3}` and penetration
        :math:`\Delta = u(K^2/\pi^2w^2R)^{1/3}`, the shape of ``P``.

    Raises
    ------
    ValueError
        If ``P`` is not real and finite or lies outside :math:`[-2, 10^{300}]`.

    Examples
    --------
    >>> A, delta = dmt_solve_load([-2.0, 6.0])
    >>> [float(x) for x in A], [float(x) for x in delta]
    ([0.0, 2.0], [0.0, 4.0])

    References
    ----------
    Derjaguin, Muller & Toporov (1975); Maugis (1992).
    """
    P = as_float_array(P, "P", allow_empty=True)
    if np.any((P < DMT_PULL_OFF) | (P > 1e300)):
        raise ValueError(f"P (load over pi w R) must lie in [-2, 1e300] (from the DMT pull-off), got values "
                         f"from {P.min():g} to {P.max():g}")
    A = np.cbrt(P - DMT_PULL_OFF)
    return A, A * A


def dmt_solve(delta):
    r"""DMT contact radius and load at a given penetration, in Maugis' units.

    .. math::
        A = \Delta^{1/2},\qquad P = \Delta^{3/2} - 2,\qquad \Delta \ge 0

    Parameters
    ----------
    delta : array_like
        Penetration :math:`\Delta = u(K^2/\pi^2w^2R)^{1/3}`, from 0 (the contact edge; DMT has
        no contact at negative penetration) up to 1e200.  May be empty.

    Returns
    -------
    A, P : ndarray
        Contact radius :math:`a(K/\pi wR^2)^{1/3}` and load :math:`P/(\pi wR)`, the shape of
        ``delta``.

    Raises
    ------
    ValueError
        If ``delta`` is not real and finite or lies outside :math:`[0, 10^{200}]`.

    Examples
    --------
    >>> A, P = dmt_solve([0.0, 4.0])
    >>> [float(x) for x in A], [float(x) for x in P]
    ([0.0, 2.0], [-2.0, 6.0])

    References
    ----------
    Derjaguin, Muller & Toporov (1975); Maugis (1992).
    """
    delta = as_float_array(delta, "delta", allow_empty=True)
    if np.any((delta < 0) | (delta > 1e200)):
        raise ValueError("delta (penetration) must lie in [0, 1e200]: DMT has no contact at negative "
                         f"penetration; got values from {delta.min():g} to {delta.max():g}")
    A = np.sqrt(delta)
    return A, A**3 + DMT_PULL_OFF


def dmt_contact_radius(P, *, R, w, E_star):
    r"""DMT contact radius of a sphere on a flat at load :math:`P`, in metres.

    .. math::
        a^3 = \frac{R}{K}\,(P + 2\pi wR),\qquad K = \tfrac43E^*,\qquad P \ge -2\pi wR

    Hertz's radius under the load plus the adhesive pull :math:`2\pi wR` of the ring outside
    the contact; :math:`w = 0` is Hertz.

    Parameters
    ----------
    P : array_like
        Normal load :math:`P` (N, compressive > 0), at least minus the pull-off force
        :math:`2\pi wR` (:func:`dmt_pull_off_force`).
    R : array_like
        Sphere (tip) radius :math:`R` (m), > 0.
    w : array_like
        Work of adhesion :math:`w` (J/m^2), >= 0.
    E_star : array_like
        Composite Young's modulus :math:`E^*` (Pa), > 0.

    Returns
    -------
    ndarray
        Contact radius :math:`a` (m), the broadcast shape of the inputs.

    Raises
    ------
    ValueError
        If an input is not real and finite or out of range, or a load is below :math:`-2\pi wR`.

    Examples
    --------
    >>> import math
    >>> R, w, E_star = 20e-9, 0.1, 100e9
    >>> float(dmt_contact_radius(-2 * math.pi * w * R, R=R, w=w, E_star=E_star))
    0.0

    References
    ----------
    B. V. Derjaguin, V. M. Muller, Yu. P. Toporov, J. Colloid Interface Sci. 53 (1975) 314;
    Maugis (1992).
    """
    P = as_float_array(to_si(P, "N", "P"), "P", allow_empty=True)
    R = check_positive(to_si(R, "m", "R"), "R")
    w = check_nonnegative(to_si(w, "J/m^2", "w"), "w")
    K = check_positive_scaled(to_si(E_star, "Pa", "E_star"), "E_star", 4.0 / 3.0)
    check_broadcast(P=P, R=R, w=w, E_star=K)
    with np.errstate(all="ignore"):
        Q = 2.0 * np.pi * w * R
    if np.any(P < -Q * (1.0 + 1e-15)):
        raise ValueError(f"P (load) must be >= -2 pi w R (the DMT pull-off load), got min {P.min():g} N")
    with np.errstate(all="ignore"):
        a = np.cbrt(R / K * np.maximum(P + Q, 0.0))
    return check_finite_result(a, "the DMT contact radius", P=P, R=R, w=w, E_star=E_star)


def dmt_normal_force(delta, *, R, w, E_star):
    r"""DMT normal force of a sphere on a flat at penetration :math:`\delta`, in newtons.

    .. math::
        P = KR^{1/2}\delta^{3/2} - 2\pi wR,\qquad K = \tfrac43E^*,\qquad \delta \ge 0

    Parameters
    ----------
    delta : array_like
        Penetration :math:`\delta` (m), >= 0 (DMT has no contact at negative penetration).
    R : array_like
        Sphere radius :math:`R` (m), > 0.
    w : array_like
        Work of adhesion :math:`w` (J/m^2), >= 0.
    E_star : array_like
        Composite Young's modulus :math:`E^*` (Pa), > 0.

    Returns
    -------
    ndarray
        Normal force :math:`P` (N, compressive > 0), the broadcast shape of the inputs.

    Raises
    ------
    ValueError
        If an input is not real and finite or out of range, or a penetration is negative.

    Examples
    --------
    >>> import math
    >>> float(dmt_normal_force(0.0, R=1e-6, w=0.1, E_star=1e9)) == -2 * math.pi * 0.1 * 1e-6
    True

    References
    ----------
    Derjaguin, Muller & Toporov (1975); Maugis (1992).
    """
    delta = as_float_array(to_si(delta, "m", "delta"), "delta", allow_empty=True)
    R = check_positive(to_si(R, "m", "R"), "R")
    w = check_nonnegative(to_si(w, "J/m^2", "w"), "w")
    K = check_positive_scaled(to_si(E_star, "Pa", "E_star"), "E_star", 4.0 / 3.0)
    check_broadcast(delta=delta, R=R, w=w, E_star=K)
    if np.any(delta < 0):
        raise ValueError("delta (penetration) must be >= 0: DMT has no contact at negative penetration")
    with np.errstate(all="ignore"):
        F = K * np.sqrt(R) * delta**1.5 - 2.0 * np.pi * w * R
    return check_finite_result(F, "the DMT force", delta=delta, R=R, w=w, E_star=E_star)


def dmt_pull_off_force(*, R, w):
    r"""DMT pull-off force :math:`2\pi wR`, in newtons (the load there is minus it).

    .. math:: F_{po} = 2\pi wR

    Parameters
    ----------
    R : array_like
        Sphere radius :math:`R` (m), > 0.
    w : array_like
        Work of adhesion :math:`w` (J/m^2), >= 0.

    Returns
    -------
    ndarray
        The pull-off force (N), broadcast over the inputs.

    Raises
    ------
    ValueError
        If an input is not real and finite or out of range.

    Examples
    --------
    >>> import math
    >>> float(dmt_pull_off_force(R=1e-6, w=0.1)) == 2 * math.pi * 0.1 * 1e-6
    True

    References
    ----------
    Derjaguin, Muller & Toporov (1975).
    """
    w, R = check_nonnegative(to_si(w, "J/m^2", "w"), "w"), check_positive(to_si(R, "m", "R"), "R")
    check_broadcast(w=w, R=R)
    with np.errstate(all="ignore"):
        P = 2.0 * np.pi * w * R
    return check_finite_result(P, "the pull-off force", w=w, R=R)
