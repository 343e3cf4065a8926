r"""JKR adhesive contact (the :math:`\lambda \to \infty` limit of Maugis-Dugdale).

In Maugis' units (:mod:`asperity.maugis_dugdale`):

.. math::
    P = A^3 - \sqrt{6A^3}, \qquad \Delta = A^2 - \sqrt{8A/3}.

Pull-off under load control: :math:`P = -3/2` at :math:`A = (3/2)^{1/3}`; under
displacement control (end of the stable branch, :math:`d\Delta/dA = 0`):
:math:`P = -5/6` at :math:`A = 6^{-1/3}`.

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
    check_overflow,
    check_positive,
    check_positive_scaled,
    check_radius,
    ufunc_result,
)
from .maugis_units import penetration_in_maugis_units
from .units import to_si

__all__ = ["jkr_load", "jkr_penetration", "jkr_pull_off", "jkr_solve_load", "jkr_solve", "jkr_contact_radius",
           "jkr_normal_force", "jkr_pull_off_force"]

_FLOAT_MAX = float(np.finfo(float).max)


def jkr_load(A):
    r"""JKR load in Maugis' units, :math:`P/(\pi wR) = A^3 - \sqrt{6A^3}`.

    .. math::
        \frac{P}{\pi wR} = A^3 - \sqrt{6A^3},\qquad A = a\Big(\frac{K}{\pi wR^2}\Big)^{1/3}

    Parameters
    ----------
    A : array_like
        Contact radius in Maugis' units, :math:`0 \le A \le (\mathrm{DBL\_MAX}/6)^{1/3}`
        (about 3.1e102; beyond, :math:`6A^3` overflows).  May be empty.

    Returns
    -------
    ndarray
        :math:`P/(\pi wR)`, the shape of ``A`` (negative: tensile).

    Raises
    ------
    ValueError
        If ``A`` is not real and finite, negative, or the load would overflow.

    Examples
    --------
    >>> round(float(jkr_load(1.5 ** (1 / 3))), 12)  # the load-controlled pull-off
    -1.5

    References
    ----------
    Johnson, Kendall & Roberts (1971); Maugis (1992).
    """
    A = check_radius(A)
    with np.errstate(over="ignore", invalid="ignore"):
        P = A**3 - np.sqrt(6.0 * A**3)
    return check_overflow(P, "A", np.cbrt(_FLOAT_MAX / 6.0), A)


def jkr_penetration(A):
    r"""JKR penetration in Maugis' units, :math:`\Delta = A^2 - \sqrt{8A/3}`.

    .. math::
        \Delta = A^2 - \sqrt{8A/3},\qquad \Delta = u\Big(\frac{K^2}{\pi^2w^2R}\Big)^{1/3}

    Parameters
    ----------
    A : array_like
        Contact radius in Maugis' units, :math:`0 \le A \le \mathrm{DBL\_MAX}^{1/2}`
        (about 1.3e154; beyond, :math:`A^2` overflows).  May be empty.

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
    >>> A = 6 ** (-1 / 3)  # the end of the stable branch: A^2 - sqrt(8A/3)
    >>> round(float(jkr_penetration(A)), 5)
    -0.90856

    References
    ----------
    Johnson, Kendall & Roberts (1971); Maugis (1992).
    """
    A = check_radius(A)
    with np.errstate(over="ignore", invalid="ignore"):  # inf - inf for a huge A: the named error below
        D = A**2 - np.sqrt(8.0 * A / 3.0)
    return check_overflow(D, "A", np.sqrt(_FLOAT_MAX), A)


def jkr_pull_off(control: str = "load"):
    r"""JKR pull-off radius and load ``(A, P)`` in Maugis' units.

    .. math::
        \text{load control: } A = (3/2)^{1/3},\ P = -\tfrac32;\qquad
        \text{displacement control: } A = 6^{-1/3},\ P = -\tfrac56

    Parameters
    ----------
    control : {'load', 'displacement'}
        Which quantity is controlled (default ``'load'``).

    Returns
    -------
    tuple of float
        ``(A, P)``: radius :math:`a(K/\pi wR^2)^{1/3}` and load :math:`P/(\pi wR)`.

    Raises
    ------
    ValueError
        If ``control`` is neither name.

    Examples
    --------
    >>> jkr_pull_off("displacement")[1] == -5 / 6
    True

    References
    ----------
    Johnson, Kendall & Roberts (1971); Maugis (1992).
    """
    if not isinstance(control, str) or control not in ("load", "displacement"):
        raise ValueError(f"control must be 'load' or 'displacement', got {control!r}")
    if control == "load":
        return 1.5 ** (1.0 / 3.0), -1.5
    if control == "displacement":
        return 6.0 ** (-1.0 / 3.0), -5.0 / 6.0
    raise ValueError(f"control must be 'load' or 'displacement', got {control!r}")


# -- load control, displacement control and the physical shell -----------------------------
#: Radius and penetration at the end of the displacement-stable branch, A = 6^(-1/3).
_A_C = 6.0 ** (-1.0 / 3.0)
_DELTA_C = _A_C**2 - np.sqrt(8.0 * _A_C / 3.0)


def jkr_solve_load(P):
    r"""JKR contact radius and penetration at a given load (load control), in Maugis' units.

    The load-stable branch of :math:`P = A^3 - \sqrt{6A^3}` (:math:`A^3 \ge 3/2`) solved for
    :math:`s = A^{3/2}` from :math:`s^2 - \sqrt6\,s - P = 0`:

    .. math::
        A = \Big(\frac{\sqrt6 + \sqrt{6 + 4P}}{2}\Big)^{2/3},\qquad \Delta = A^2 - \sqrt{8A/3},
        \qquad P \ge -\tfrac32

    Parameters
    ----------
    P : array_like
        Load :math:`P/(\pi wR)`, from the load-controlled pull-off -3/2 up, at most 1e300.
        May be empty.

    Returns
    -------
    A, delta : ndarray
        Contact radius :math:`a(K/\pi wR^2)^{1/3}` and penetration
        :math:`\Delta = u(K^2/\pi^2w^2R)^{1/3}`, the shape of ``P``.

    Raises
    ------
    ValueError
        If ``P`` is not real and finite or lies outside :math:`[-3/2, 10^{300}]`.

    Examples
    --------
    >>> A, delta = jkr_solve_load([-1.5, 0.0])
    >>> [round(float(x**3), 12) for x in A]  # pull-off at A^3 = 3/2; A^3 = 6 at zero load
    [1.5, 6.0]

    References
    ----------
    Johnson, Kendall & Roberts (1971); Maugis (1992).
    """
    P = as_float_array(P, "P", allow_empty=True)
    if np.any((P < -1.5) | (P > 1e300)):
        raise ValueError(f"P (load over pi w R) must lie in [-1.5, 1e300] (from the JKR pull-off), got values "
                         f"from {P.min():g} to {P.max():g}")
    s = 0.5 * (np.sqrt(6.0) + np.sqrt(6.0 + 4.0 * P))
    A = np.cbrt(s * s)
    return A, A * A - np.sqrt(8.0 * A / 3.0)


def jkr_solve(delta):
    r"""JKR contact radius and load at a given penetration (displacement control), in Maugis' units.

    Solves :math:`\Delta = A^2 - \sqrt{8A/3}` on the stable branch :math:`A \ge 6^{-1/3}`
    (:math:`d\Delta/dA \ge 0`) for :math:`x = \sqrt A` (Newton's method on the convex, increasing
    :math:`x^4 - \sqrt{8/3}\,x - \Delta`, from the right), then :math:`P = A^3 - \sqrt{6A^3}`.

    .. math::
        \Delta = A^2 - \sqrt{8A/3},\qquad P = A^3 - \sqrt{6A^3},\qquad A \ge 6^{-1/3}

    Parameters
    ----------
    delta : array_like
        Penetration :math:`\Delta = u(K^2/\pi^2w^2R)^{1/3}`, from the end of the stable branch
        :math:`\Delta_c = A_c^2 - \sqrt{8A_c/3} \approx -0.9086` at :math:`A_c = 6^{-1/3}`, up to 1e150.
        May be empty.

    Returns
    -------
    A, P : ndarray
        Contact radius :math:`a(K/\pi wR^2)^{1/3}` and load :math:`P/(\pi wR)`, the shape of
        ``delta``.

    Raises
    ------
    ValueError
        If ``delta`` is not real and finite or lies outside :math:`[\Delta_c, 10^{150}]`.

    Examples
    --------
    >>> A, P = jkr_solve([float(jkr_penetration(2.0))])
    >>> round(float(A[0]), 12), round(float(P[0]), 12) == round(float(jkr_load(2.0)), 12)
    (2.0, True)

    References
    ----------
    Johnson, Kendall & Roberts (1971); Maugis (1992).
    """
    delta = as_float_array(delta, "delta", allow_empty=True)
    if np.any((delta < _DELTA_C) | (delta > 1e150)):
        raise ValueError(f"delta (penetration) must lie in [{_DELTA_C:.17g}, 1e150] (from the end of the "
                         f"stable JKR branch), got values from {delta.min():g} to {delta.max():g}")
    c = np.sqrt(8.0 / 3.0)
    x_c = np.sqrt(_A_C)
    # Start right of the root (f(x) >= 0), then Newton descends monotonically (f convex, increasing).
    x = np.maximum(x_c, np.sqrt(np.sqrt(np.abs(delta)))) + np.cbrt(c) + 1.0
    for _ in range(200):
        f = x**4 - c * x - delta
        df = 4.0 * x**3 - c
        with np.errstate(divide="ignore", invalid="ignore"):
            step = np.where(df > 0, f / df, 0.0)
        x_new = np.maximum(x - step, x_c)
        if np.all(np.abs(x_new - x) <= 1e-15 * x):
            x = x_new
            break
        x = x_new
    A = x * x
    return A, A**3 - np.sqrt(6.0 * A**3)


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
