r"""JKR adhesive contact (the :math:`\lambda \to \infty` limit of Maugis-Dugdale), in SI units.

In Maugis' units (:mod:`asperity.maugis_dugdale`):

.. math::
    P = A^3 - \sqrt{6A^3}, \qquad \Delta = A^2 - \sqrt{8A/3}.

Pull-off under load control: :math:`P = -3/2` at :math:`A = (3/2)^{1/3}`; under
displacement control (end of the stable branch, :math:`d\Delta/dA = 0`):
:math:`P = -5/6` at :math:`A = 6^{-1/3}`.  The physical functions are here
(:func:`jkr_contact_radius`, :func:`jkr_normal_force`, :func:`jkr_pull_off_force`); the
solution in Maugis' units (:func:`jkr_load`, :func:`jkr_penetration`, :func:`jkr_pull_off`,
:func:`jkr_solve_load`, :func:`jkr_solve`) is :mod:`asperity.jkr_branch`'s, re-exported.

References
----------
.. [1] K. L. Johnson, K. Kendall, A. D. Roberts, Proc. R. Soc. A 324 (1971) 301.
.. [2] D. Maugis (1992), Eqs for the JKR limit.
"""

from __future__ import annotations

import numpy as np

from ._validation import (
    as_float_array,
    check_broadcast,
    check_finite_result,
    check_nonnegative,
    check_positive,
    check_positive_scaled,
    ufunc_result,
)
from .jkr_branch import DELTA_END, jkr_load, jkr_penetration, jkr_pull_off, jkr_solve, jkr_solve_load
from .maugis_units import check_floor_in_si, penetration_in_maugis_units
from .units import to_si

__all__ = ["jkr_load", "jkr_penetration", "jkr_pull_off", "jkr_solve_load", "jkr_solve", "jkr_contact_radius",
           "jkr_normal_force", "jkr_pull_off_force"]


def _physical(R, w, E_star):
    R = check_positive(to_si(R, "m", "R"), "R")
    w = check_nonnegative(to_si(w, "J/m^2", "w"), "w")
    return R, w, check_positive_scaled(to_si(E_star, "Pa", "E_star"), "E_star", 4.0 / 3.0)


def jkr_contact_radius(P, *, R, w, E_star):
    r"""JKR contact radius of a sphere on a flat at load :math:`P` (load control), in metres.

    .. math::
        a^3 = \frac{R}{K}\Big(P + 3\pi wR + \sqrt{6\pi wRP + (3\pi wR)^2}\Big),\qquad
        K = \tfrac43E^*,\qquad P \ge -\tfrac32\pi wR

    (Johnson, Kendall & Roberts 1971, Eq 2); :math:`w = 0` is Hertz, :math:`a^3 = RP/K`.

    Parameters
    ----------
    P : array_like
        Normal load :math:`P` (N, compressive > 0), at least minus the pull-off force
        :math:`\tfrac32\pi wR` (:func:`jkr_pull_off_force`).
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
        If an input is not real and finite or out of range, or a load is below
        :math:`-\tfrac32\pi wR`.

    Examples
    --------
    >>> import math
    >>> R, w, E_star = 20e-9, 0.1, 100e9
    >>> a = float(jkr_contact_radius(-1.5 * math.pi * w * R, R=R, w=w, E_star=E_star))
    >>> round(a**3 / (1.5 * math.pi * w * R**2 / (4 / 3 * E_star)), 12)  # A^3 = 3/2 at pull-off
    1.0

    References
    ----------
    K. L. Johnson, K. Kendall, A. D. Roberts, Proc. R. Soc. A 324 (1971) 301, Eq (2);
    Maugis (1992).
    """
    P = as_float_array(to_si(P, "N", "P"), "P", allow_empty=True)
    R, w, K = _physical(R, w, E_star)
    check_broadcast(P=P, R=R, w=w, E_star=K)
    with np.errstate(all="ignore"):
        Q = 3.0 * np.pi * w * R
    if np.any(P < -0.5 * Q * (1.0 + 1e-15)):
        raise ValueError("P (load) must be >= -3/2 pi w R (the JKR pull-off load), got min "
                         f"{P.min():g} N")
    with np.errstate(all="ignore"):
        root = np.sqrt(np.maximum(2.0 * Q * P + Q * Q, 0.0))
        a = np.cbrt(R / K * (P + Q + root))
    return check_finite_result(a, "the JKR contact radius", P=P, R=R, w=w, E_star=E_star)


def jkr_normal_force(delta, *, R, w, E_star):
    r"""JKR normal force of a sphere on a flat at penetration :math:`\delta` (displacement control), in newtons.

    .. math::
        P = \pi wR\,(A^3 - \sqrt{6A^3}),\qquad
        \delta\Big(\frac{K^2}{\pi^2w^2R}\Big)^{1/3} = A^2 - \sqrt{8A/3},\qquad A \ge 6^{-1/3}

    on the stable branch (:func:`jkr_solve`); :math:`w = 0` is Hertz,
    :math:`P = KR^{1/2}\delta^{3/2}`.

    Parameters
    ----------
    delta : array_like
        Penetration :math:`\delta` (m) of the undeformed sphere into the flat (negative: apart),
        from the end of the stable branch, :math:`-0.9086\,(\pi^2w^2R/K^2)^{1/3}`, up; >= 0 for
        :math:`w = 0`.
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
        If an input is not real and finite or out of range, the shapes do not broadcast, or
        a penetration lies below the end of the stable branch.

    Examples
    --------
    >>> import math
    >>> R, E_star = 1e-6, 1e9
    >>> float(jkr_normal_force(1e-9, R=R, w=0.0, E_star=E_star)) == 4 / 3 * E_star * math.sqrt(R) * 1e-9**1.5
    True

    References
    ----------
    Johnson, Kendall & Roberts (1971); Maugis (1992).
    """
    delta = as_float_array(to_si(delta, "m", "delta"), "delta", allow_empty=True)
    R, w, K = _physical(R, w, E_star)
    shape = check_broadcast(delta=delta, R=R, w=w, E_star=K)
    hertz = np.broadcast_to(w == 0.0, shape)
    if np.any(hertz & (delta < 0)):
        raise ValueError("delta (penetration) must be >= 0 without adhesion (w = 0, Hertz)")
    with np.errstate(all="ignore"):
        F = np.where(hertz, K * np.sqrt(R) * np.maximum(delta, 0.0)**1.5, 0.0)
    check_finite_result(F, "the Hertz force", delta=delta, R=R, E_star=E_star)
    if np.all(hertz):
        return ufunc_result(F)
    adhesive = ~hertz
    E = as_float_array(to_si(E_star, "Pa", "E_star"), "E_star")
    delta_a, R_a, w_a, E_a = (np.broadcast_to(x, shape)[adhesive] for x in (delta, R, w, E))
    delta_hat, unit = penetration_in_maugis_units(delta_a, R=R_a, w=w_a, E_star=E_a)
    check_floor_in_si(delta_a, delta_hat, DELTA_END, "delta (penetration)", "m", "the end of the stable JKR branch")
    with np.errstate(all="ignore"):
        F[adhesive] = jkr_solve(delta_hat)[1] * unit
    return ufunc_result(check_finite_result(F, "the JKR force", delta=delta, R=R, w=w, E_star=E_star))


def jkr_pull_off_force(*, R, w):
    r"""JKR pull-off force under load control, :math:`\tfrac32\pi wR`, in newtons (the load there is minus it).

    .. math:: F_{po} = \tfrac32\pi wR

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
    >>> float(jkr_pull_off_force(R=1e-6, w=0.1)) == 1.5 * math.pi * 0.1 * 1e-6
    True

    References
    ----------
    Johnson, Kendall & Roberts (1971).
    """
    w, R = check_nonnegative(to_si(w, "J/m^2", "w"), "w"), check_positive(to_si(R, "m", "R"), "R")
    check_broadcast(w=w, R=R)
    with np.errstate(all="ignore"):
        P = 1.5 * np.pi * w * R
    return check_finite_result(P, "the pull-off force", w=w, R=R)
