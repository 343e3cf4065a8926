r"""Elastic-plastic sphere on a rigid flat: Jackson-Green's area and load fits, and the law built from them.

With :math:`\omega^* = \omega/\omega_c` and :math:`e_y = S_y/E^*` (:mod:`asperity.jackson_green`
for the critical values, :math:`C(\nu)`, :math:`B(e_y)`, :math:`a/R` and :math:`H_G`):

.. math::
    \frac{A}{A_c} = \omega^*\Big(\frac{\omega^*}{1.9}\Big)^B,\qquad
    \frac{P}{P_c} = e^{-\omega^{*5/12}/4}\omega^{*3/2}
        + \frac{4H_G}{CS_y}\Big[1 - e^{-\omega^{*5/9}/25}\Big]\omega^*

(:func:`jg_area_fit`, :func:`jg_load_fit`: JG's published fits, for :math:`\omega^* \ge 1.9`).

**The law in this package** (:func:`jg_area`, :func:`jg_load`) is Hertz,
:math:`A/A_c = \omega^*`, :math:`P/P_c = \omega^{*3/2}`, below the transitions and JG's
fits above.  JG use Hertz up to :math:`\omega^*_t = 1.9`.  Their area fit meets Hertz there
exactly (:math:`(1.9/1.9)^B = 1`), so the area switches at 1.9.  Their load fit does not:
at :math:`\omega^* = 1.9` it differs from Hertz by +7.5 % (:math:`\nu = 0`), +0.5 %
(:math:`\nu = 0.3`, the value JG calibrated with), -2.3 % (:math:`\nu = 0.44`, gold) and
-3.2 % (:math:`\nu = 0.49`), because :math:`C(\nu)` scales its plastic term.  A yielding
sphere can only be softer than the elastic one, so the load is taken as Hertz until the fit
falls below it: the switch is at the crossing :math:`\omega^*_x` of the two curves
(:func:`jg_load_transition`; 4.14 at :math:`\nu = 0`, 2.01 at 0.3, 1.44 at 0.44), where the
load is continuous.  No published number is changed; only the point where one published
curve hands over to the other moves.  The slope of the load and of the area is not
continuous at the switches (JG do not claim it).

All functions broadcast like NumPy ufuncs.

References
----------
.. [1] R. L. Jackson, I. Green, "A finite element study of elasto-plastic hemispherical
   contact against a rigid flat", J. Tribol. 127 (2005) 343-354: the transition
   :math:`\omega^*_t = 1.9`, the area fit and the load fit.
"""

from __future__ import annotations

import numpy as np
from scipy import optimize

from ._validation import as_float_array, check_broadcast, check_finite_result, ufunc_result
from .jackson_green import (
    OMEGA_T,
    jg_area_exponent,
    jg_check_poisson,
    jg_check_yield_strain,
    jg_hardness_ratio,
    jg_radius_ratio,
    jg_yield_coefficient,
)

__all__ = ["jg_area_fit", "jg_area", "jg_load_fit", "jg_load_transition", "jg_load"]


#: Largest interference over the critical one the fits take: far beyond their range (omega* <= ~110
#: in Jackson & Green's finite elements), and the fits stay finite up to it.
OMEGA_STAR_MAX = 1e12


def _omega_star(omega_star):
    w = as_float_array(omega_star, "omega_star", allow_empty=True)
    if np.any((w < 0) | (w > OMEGA_STAR_MAX)):
        raise ValueError(f"omega_star must lie in [0, {OMEGA_STAR_MAX:g}], got {omega_star!r}")
    return w


def jg_area_fit(omega_star, e_y):
    r"""JG's elastic-plastic contact area, :math:`A/A_c = \omega^*(\omega^*/1.9)^B` (for :math:`\omega^* \ge 1.9`).

    .. math::
        \frac{A}{A_c} = \omega^*\Big(\frac{\omega^*}{1.9}\Big)^B,\qquad B = 0.14\,e^{23 e_y}

    The published fit, evaluated wherever asked; :func:`jg_area` is the law (Hertz below 1.9).

    Parameters
    ----------
    omega_star : array_like
        Interference over the critical one, :math:`\omega^* = \omega/\omega_c \ge 0`.
    e_y : array_like
        Yield strain :math:`S_y/E^*`, in (0, 0.05].

    Returns
    -------
    ndarray
        :math:`A/A_c`, the broadcast shape.

    Raises
    ------
    ValueError
        If an input is not real, finite and in its range.

    Examples
    --------
    >>> float(jg_area_fit(1.9, 0.005))  # meets Hertz (A/A_c = omega*) at 1.9
    1.9

    References
    ----------
    Jackson & Green (2005), contact area.
    """
    w = _omega_star(omega_star)
    return w * (w / OMEGA_T) ** jg_area_exponent(e_y)


def jg_area(omega_star, e_y):
    r"""Contact area of the law, :math:`A/A_c`: Hertz up to :math:`\omega^*_t = 1.9`, JG's fit beyond.

    .. math::
        \frac{A}{A_c} = \begin{cases} \omega^*, & \omega^* \le 1.9\\
            \omega^*(\omega^*/1.9)^B, & \omega^* > 1.9 \end{cases}

    Continuous at 1.9 (both sides give 1.9); the slope jumps from 1 to :math:`1 + B`.

    Parameters
    ----------
    omega_star : array_like
        :math:`\omega/\omega_c \ge 0`.
    e_y : array_like
        Yield strain :math:`S_y/E^*`, in (0, 0.05].

    Returns
    -------
    ndarray
        :math:`A/A_c`, the broadcast shape.

    Raises
    ------
    ValueError
        If an input is not real, finite and in its range.

    Examples
    --------
    >>> [round(float(x), 6) for x in jg_area([1.0, 1.9, 10.0], 0.001)]
    [1.0, 1.9, 12.685974]

    References
    ----------
    Jackson & Green (2005), contact area and the transition at 1.9.
    """
    w, e_y = np.broadcast_arrays(_omega_star(omega_star), jg_check_yield_strain(e_y))
    if w.size == 0:  # no interference: nothing to evaluate (e_y broadcast to empty is not "no e_y")
        return np.zeros(w.shape)
    return ufunc_result(np.where(w <= OMEGA_T, w, jg_area_fit(np.maximum(w, OMEGA_T), e_y)))


def jg_load_fit(omega_star, e_y, nu):
    r"""JG's elastic-plastic load, :math:`P/P_c` (their fit for :math:`\omega^* \ge 1.9`).

    .. math::
        \frac{P}{P_c} = \exp\Big(-\tfrac14\omega^{*5/12}\Big)\omega^{*3/2}
            + \frac{4H_G}{C S_y}\Big[1 - \exp\Big(-\tfrac1{25}\omega^{*5/9}\Big)\Big]\omega^*

    with :math:`H_G/S_y` from :func:`jg_hardness_ratio` at the contact radius of the law's
    area (:func:`jg_area`, :func:`jg_radius_ratio`).  The published fit evaluated wherever
    asked; :func:`jg_load` is the law.

    Parameters
    ----------
    omega_star : array_like
        :math:`\omega/\omega_c \ge 0`.
    e_y : array_like
        Yield strain :math:`S_y/E^*`, in (0, 0.05].
    nu : array_like
        Poisson's ratio, :math:`0 \le \nu < 0.5`.

    Returns
    -------
    ndarray
        :math:`P/P_c`, the broadcast shape.

    Raises
    ------
    ValueError
        If an input is not real, finite and in its range.

    Examples
    --------
    >>> round(float(jg_load_fit(1.9, 0.001, 0.3) / 1.9 ** 1.5), 4)  # 0.47 % above Hertz at 1.9
    1.0047

    References
    ----------
    Jackson & Green (2005), load.
    """
    w = _omega_star(omega_star)
    C = jg_yield_coefficient(nu)
    check_broadcast(omega_star=w, e_y=jg_check_yield_strain(e_y), nu=C)
    if w.size == 0:
        return np.zeros(w.shape)
    hardness = jg_hardness_ratio(jg_radius_ratio(jg_area(w, e_y), e_y, nu))
    elastic = np.exp(-0.25 * w ** (5.0 / 12.0)) * w**1.5
    plastic = 4.0 * hardness / C * (1.0 - np.exp(-(w ** (5.0 / 9.0)) / 25.0)) * w
    return elastic + plastic


def _crossing(e_y: float, nu: float) -> float:
    """The omega* > 1 where JG's load fit falls below Hertz, for scalar e_y and nu."""
    def gap(w):
        return float(jg_load_fit(w, e_y, nu)) - w**1.5

    grid = np.linspace(1.0, 8.0, 141)
    values = jg_load_fit(grid, e_y, nu) - grid**1.5
    below = np.flatnonzero(values <= 0.0)
    if values[0] <= 0.0 or below.size == 0:
        raise ValueError(f"the Jackson-Green load fit does not cross Hertz above yield for e_y = {e_y:g}, "
                         f"nu = {nu:g}; these lie outside the fit's range")
    k = int(below[0])
    return float(optimize.brentq(gap, grid[k - 1], grid[k], xtol=1e-15, rtol=4 * np.finfo(float).eps))


def jg_load_transition(e_y, nu):
    r"""Where the law's load leaves Hertz: the crossing :math:`\omega^*_x > 1` of JG's load fit with Hertz.

    .. math::
        \frac{P_{fit}}{P_c}(\omega^*_x) = \omega_x^{*3/2},\qquad
        \frac{P_{fit}}{P_c} > \omega^{*3/2} \text{ on } [1, \omega^*_x)

    JG switch from Hertz to their load fit at 1.9, where the two differ by up to several per
    cent depending on :math:`\nu` (see the module docstring); the law switches at this
    crossing instead, so its load is continuous and never above Hertz once yielding.

    Parameters
    ----------
    e_y : array_like
        Yield strain :math:`S_y/E^*`, in (0, 0.05].
    nu : array_like
        Poisson's ratio, :math:`0 \le \nu < 0.5`.

    Returns
    -------
    ndarray
        :math:`\omega^*_x` (between 1 and about 4.2), the broadcast shape.

    Raises
    ------
    ValueError
        If an input is not real, finite and in its range.

    Examples
    --------
    >>> [round(float(x), 3) for x in jg_load_transition(0.001, [0.0, 0.3, 0.44])]
    [4.136, 2.006, 1.445]

    References
    ----------
    Jackson & Green (2005), load and the transition at 1.9; this package's handling of the
    load's jump there (docs/plasticity.md).
    """
    e_y, nu = jg_check_yield_strain(e_y), jg_check_poisson(nu)
    check_broadcast(e_y=e_y, nu=nu)
    e_y, nu = np.broadcast_arrays(e_y, nu)
    out = np.array([_crossing(float(e), float(n)) for e, n in zip(e_y.ravel(), nu.ravel(), strict=True)])
    return ufunc_result(out.reshape(e_y.shape))


def jg_load(omega_star, e_y, nu):
    r"""Load of the law, :math:`P/P_c`: Hertz up to the crossing :math:`\omega^*_x`, JG's fit beyond.

    .. math::
        \frac{P}{P_c} = \begin{cases} \omega^{*3/2}, & \omega^* \le \omega^*_x\\
            P_{fit}/P_c, & \omega^* > \omega^*_x \end{cases}

    with :math:`\omega^*_x` from :func:`jg_load_transition` and :math:`P_{fit}` from
    :func:`jg_load_fit`.  Continuous everywhere; equal to Hertz below the critical
    interference (:math:`\omega^*_x > 1`).

    Parameters
    ----------
    omega_star : array_like
        :math:`\omega/\omega_c \ge 0`.
    e_y : array_like
        Yield strain :math:`S_y/E^*`, in (0, 0.05].
    nu : array_like
        Poisson's ratio, :math:`0 \le \nu < 0.5`.

    Returns
    -------
    ndarray
        :math:`P/P_c`, the broadcast shape.

    Raises
    ------
    ValueError
        If an input is not real, finite and in its range.

    Examples
    --------
    >>> [round(float(x), 4) for x in jg_load([0.5, 1.0, 10.0], 0.001, 0.3)]
    [0.3536, 1.0, 25.8854]

    References
    ----------
    Jackson & Green (2005), load; docs/plasticity.md (the switch at the crossing).
    """
    w, e_y, nu = _omega_star(omega_star), jg_check_yield_strain(e_y), jg_check_poisson(nu)
    check_broadcast(omega_star=w, e_y=e_y, nu=nu)
    w, e_y, nu = np.broadcast_arrays(w, e_y, nu)
    if w.size == 0:
        return np.zeros(w.shape)
    pairs, index = np.unique(np.stack([e_y.ravel(), nu.ravel()]), axis=1, return_inverse=True)
    cross = np.array([_crossing(float(e), float(n)) for e, n in pairs.T])[index.ravel()].reshape(w.shape)
    with np.errstate(over="ignore", invalid="ignore"):
        fit = jg_load_fit(np.maximum(w, cross), e_y, nu)
        out = np.where(w <= cross, w**1.5, fit)
    return ufunc_result(check_finite_result(out, "P/P_c", omega_star=w))
