r"""Elastic-plastic sphere on a rigid flat: Jackson-Green (2005), critical values and hardness.

An elastic-perfectly plastic sphere of radius :math:`R`, composite modulus :math:`E^*`
(JG's :math:`E'`), Poisson's ratio :math:`\nu` and yield strength :math:`S_y`, pressed into
a rigid flat by the interference :math:`\omega`, follows Hertz until yield starts below
the surface at the critical interference :math:`\omega_c`; beyond, JG fit their FEM
results for the contact area and load.  Everything is written in the dimensionless
interference :math:`\omega^* = \omega/\omega_c` and the yield strain
:math:`e_y = S_y/E^*`:

==================  ====================================================  ===================================
quantity            definition                                            function
==================  ====================================================  ===================================
:math:`C`           :math:`1.295\,e^{0.736\nu}` (yield onset)             :func:`jg_yield_coefficient`
:math:`\omega_c`    :math:`(\pi C S_y/2E^*)^2 R`                          :func:`jg_critical_interference`
:math:`P_c`         :math:`\tfrac43(R/E^*)^2(C\pi S_y/2)^3` (Hertz)       :func:`jg_critical_load`
:math:`A_c`         :math:`\pi R\omega_c` (Hertz)                         :func:`jg_critical_area`
:math:`B`           :math:`0.14\,e^{23 e_y}`                              :func:`jg_area_exponent`
:math:`A/A_c`       :math:`\omega^*(\omega^*/1.9)^B` (:math:`\ge 1.9`)     ``jackson_green_fits.jg_area_fit``
:math:`a/R`         :math:`(\pi C e_y/2)(A/A_c)^{1/2}`                    :func:`jg_radius_ratio`
:math:`H_G/S_y`     :math:`2.84[1 - e^{-0.82(a/R)^{-0.7}}]`               ``jackson_green_hardness.jg_hardness_ratio``
:math:`P/P_c`       :math:`e^{-\omega^{*5/12}/4}\omega^{*3/2}
                    + \tfrac{4H_G}{CS_y}[1 - e^{-\omega^{*5/9}/25}]
                    \,\omega^*`                                           ``jackson_green_fits.jg_load_fit``
==================  ====================================================  ===================================

The fits and the law built from them (Hertz below the transitions, the fits above, with the
switch of the load moved to where it is continuous) are in :mod:`asperity.jackson_green_fits`; the hardness in
:mod:`asperity.jackson_green_hardness` (its names are importable from here too).

**Hardness.**  JG's geometric hardness tends to :math:`2.84\,S_y` for small contacts
(:math:`a/R \to 0`, all asperity contacts here), so a hardness :math:`H` (the mean contact
pressure of a fully plastic small contact) gives :math:`S_y = H/2.84`
(:func:`~asperity.jackson_green_hardness.jg_yield_from_hardness`; Tabor's classical :math:`H \approx 2.8\,Y` to 1.4 %).

**Ranges.**  JG's :math:`C(\nu)` is fitted for :math:`0 \le \nu \le 0.5`, so the functions
taking :math:`\nu` accept :math:`0 \le \nu < 0.5`; the yield strain :math:`e_y = S_y/E^*`
must lie in :math:`(0, 0.05]` (JG's FEM materials: about 0.0005-0.01; up to 0.05 the load fit
crosses Hertz above :math:`\omega^* = 1` for every :math:`\nu`, beyond about 0.065 it no longer
does for :math:`\nu \to 0.5`), i.e. hardness :math:`H/E^* \le 0.142`.

All functions broadcast like NumPy ufuncs.

References
----------
.. [1] R. L. Jackson, I. Green, "A finite element study of elasto-plastic hemispherical
   contact against a rigid flat", J. Tribol. 127 (2005) 343-354: the critical
   interference, load and area (with :math:`C(\nu)`), the transition :math:`\omega^*_t =
   1.9`, the area fit with :math:`B(e_y)`, the geometric hardness :math:`H_G` and the load
   fit.
.. [2] I. Green, "Poisson ratio effects and critical values in spherical and cylindrical
   Hertzian contacts", Int. J. Appl. Mech. Eng. 10 (2005) 451-462 (the exact
   :math:`C(\nu)` that JG's exponential fits).
.. [3] D. Tabor, The Hardness of Metals, Oxford (1951): :math:`H \approx 2.8\,Y`.
"""

from __future__ import annotations

import numpy as np

from ._validation import check_broadcast, check_finite_result, check_interval, check_nonnegative, check_positive
from .jackson_green_hardness import HG_LIMIT, HG_POWER, HG_RATE, jg_hardness_ratio, jg_yield_from_hardness

__all__ = [
    "C_PREFACTOR",
    "C_EXPONENT",
    "OMEGA_T",
    "B_PREFACTOR",
    "B_EXPONENT",
    "HG_LIMIT",
    "HG_RATE",
    "HG_POWER",
    "E_Y_MAX",
    "jg_yield_coefficient",
    "jg_yield_from_hardness",
    "jg_critical_interference",
    "jg_critical_load",
    "jg_critical_area",
    "jg_check_poisson",
    "jg_check_yield_strain",
    "jg_area_exponent",
    "jg_radius_ratio",
    "jg_hardness_ratio",
]

#: JG 2005: :math:`C(\nu) = 1.295\,e^{0.736\nu}`, prefactor (fit to Green's exact yield-onset coefficient).
C_PREFACTOR = 1.295
#: JG 2005: exponent of :math:`C(\nu)`.
C_EXPONENT = 0.736
#: JG 2005: :math:`\omega^*_t`, up to which the FEM contact follows Hertz.
OMEGA_T = 1.9
#: JG 2005: :math:`B = 0.14\,e^{23 e_y}`, prefactor of the area exponent.
B_PREFACTOR = 0.14
#: JG 2005: rate of the area exponent in the yield strain :math:`e_y = S_y/E^*`.
B_EXPONENT = 23.0
#: Largest yield strain :math:`S_y/E^*` accepted: up to it the load fit crosses Hertz above yield for
#: every :math:`0 \le \nu < 0.5` (above about 0.065 it no longer does for :math:`\nu \to 0.5`).
E_Y_MAX = 0.05


def jg_check_poisson(nu):
    """Poisson's ratio as a float array, each in JG's fitted range :math:`0 \\le \\nu < 0.5`.

    Raises
    ------
    ValueError
        If ``nu`` is not real and finite or lies outside [0, 0.5).
    """
    return check_interval(nu, "nu (Poisson's ratio)", 0.0, 0.5, hi_open=True,
                          context=" for the Jackson-Green law (C(nu) is fitted there)")


def jg_check_yield_strain(e_y):
    """The yield strain :math:`e_y = S_y/E^*` as a float array, each in :math:`(0, 0.05]`.

    Raises
    ------
    ValueError
        If ``e_y`` is not real and finite or lies outside (0, :data:`E_Y_MAX`].
    """
    return check_interval(e_y, "e_y (yield strain S_y/E*)", 0.0, E_Y_MAX, lo_open=True,
                          context=f" for the Jackson-Green fits (hardness H/E* up to {E_Y_MAX * HG_LIMIT:.3g})")


def jg_yield_coefficient(nu):
    r"""Yield-onset coefficient :math:`C(\nu) = 1.295\,e^{0.736\nu}` of Jackson & Green.

    .. math::
        C = 1.295\,\exp(0.736\,\nu)

    The maximum von Mises stress under a Hertz contact reaches :math:`S_y` when the mean
    pressure is :math:`\tfrac23 C S_y`; JG's exponential fits Green's exact coefficient.

    Parameters
    ----------
    nu : array_like
        Poisson's ratio of the sphere :math:`\nu`, :math:`0 \le \nu < 0.5`.

    Returns
    -------
    ndarray
        :math:`C` (dimensionless), the shape of ``nu``.

    Raises
    ------
    ValueError
        If ``nu`` is not real and finite or lies outside [0, 0.5).

    Examples
    --------
    >>> round(float(jg_yield_coefficient(0.3)), 4)  # 1.295 * exp(0.2208)
    1.615

    References
    ----------
    Jackson & Green (2005), critical interference; Green (2005).
    """
    return C_PREFACTOR * np.exp(C_EXPONENT * jg_check_poisson(nu))


def jg_critical_interference(S_y, E_star, R, nu):
    r"""Critical interference :math:`\omega_c = (\pi C S_y/2E^*)^2 R` at which yield starts.

    .. math::
        \omega_c = \Big(\frac{\pi C S_y}{2E^*}\Big)^2 R,\qquad C = 1.295\,e^{0.736\nu}

    Parameters
    ----------
    S_y : array_like
        Yield strength :math:`S_y > 0` (same unit as ``E_star``).
    E_star : array_like
        Composite modulus :math:`E^* > 0` (JG's :math:`E'`).
    R : array_like
        Sphere radius :math:`R > 0` (any length unit).
    nu : array_like
        Poisson's ratio, :math:`0 \le \nu < 0.5`.

    Returns
    -------
    ndarray
        :math:`\omega_c` in the unit of ``R``, the broadcast shape.

    Raises
    ------
    ValueError
        If an input is not real, finite and in its range.

    Examples
    --------
    >>> C = float(jg_yield_coefficient(0.3))
    >>> w = jg_critical_interference(1.0, 1000.0, 1.0, 0.3)  # S_y/E* = 1e-3, R = 1
    >>> round(float(w / (3.141592653589793 * C * 1e-3 / 2) ** 2), 12)
    1.0

    References
    ----------
    Jackson & Green (2005), critical interference.
    """
    C = jg_yield_coefficient(nu)
    S_y, E_star, R = check_positive(S_y, "S_y"), check_positive(E_star, "E_star"), check_positive(R, "R")
    check_broadcast(S_y=S_y, E_star=E_star, R=R, nu=C)
    with np.errstate(all="ignore"):
        omega_c = (0.5 * np.pi * C * S_y / E_star) ** 2 * R
    return check_finite_result(omega_c, "the critical interference", S_y=S_y, E_star=E_star, R=R)


def jg_critical_load(S_y, E_star, R, nu):
    r"""Critical load :math:`P_c = \tfrac43(R/E^*)^2(C\pi S_y/2)^3`, the Hertz load at :math:`\omega_c`.

    .. math::
        P_c = \frac43\Big(\frac{R}{E^*}\Big)^2\Big(\frac{C\pi S_y}{2}\Big)^3
            = \frac43 E^* R^{1/2}\omega_c^{3/2}

    Parameters
    ----------
    S_y : array_like
        Yield strength :math:`S_y > 0`.
    E_star : array_like
        Composite modulus :math:`E^* > 0`.
    R : array_like
        Sphere radius :math:`R > 0`.
    nu : array_like
        Poisson's ratio, :math:`0 \le \nu < 0.5`.

    Returns
    -------
    ndarray
        :math:`P_c` (force in the units of ``S_y`` times ``R`` squared), the broadcast shape.

    Raises
    ------
    ValueError
        If an input is not real, finite and in its range.

    Examples
    --------
    >>> Pc = jg_critical_load(1.0, 1000.0, 1.0, 0.3)
    >>> wc = jg_critical_interference(1.0, 1000.0, 1.0, 0.3)
    >>> round(float(Pc / (4 / 3 * 1000.0 * wc ** 1.5)), 12)  # Hertz at omega_c
    1.0

    References
    ----------
    Jackson & Green (2005), critical load.
    """
    C = jg_yield_coefficient(nu)
    S_y, E_star, R = check_positive(S_y, "S_y"), check_positive(E_star, "E_star"), check_positive(R, "R")
    check_broadcast(S_y=S_y, E_star=E_star, R=R, nu=C)
    with np.errstate(all="ignore"):
        P_c = (4.0 / 3.0) * (R / E_star) ** 2 * (0.5 * np.pi * C * S_y) ** 3
    return check_finite_result(P_c, "the critical load", S_y=S_y, E_star=E_star, R=R)


def jg_critical_area(S_y, E_star, R, nu):
    r"""Critical contact area :math:`A_c = \pi R\omega_c`, the Hertz area at :math:`\omega_c`.

    .. math::
        A_c = \pi R\,\omega_c = \pi^3\Big(\frac{C S_y R}{2E^*}\Big)^2

    Parameters
    ----------
    S_y : array_like
        Yield strength :math:`S_y > 0`.
    E_star : array_like
        Composite modulus :math:`E^* > 0`.
    R : array_like
        Sphere radius :math:`R > 0`.
    nu : array_like
        Poisson's ratio, :math:`0 \le \nu < 0.5`.

    Returns
    -------
    ndarray
        :math:`A_c` in the unit of ``R`` squared, the broadcast shape.

    Raises
    ------
    ValueError
        If an input is not real, finite and in its range.

    Examples
    --------
    >>> Ac = jg_critical_area(1.0, 1000.0, 2.0, 0.3)
    >>> round(float(Ac / (3.141592653589793 * 2.0 * jg_critical_interference(1.0, 1000.0, 2.0, 0.3))), 12)
    1.0

    References
    ----------
    Jackson & Green (2005), critical area.
    """
    omega_c = jg_critical_interference(S_y, E_star, R, nu)  # checks and broadcasts the inputs
    with np.errstate(over="ignore"):
        A_c = np.pi * check_positive(R, "R") * omega_c
    return check_finite_result(A_c, "the critical area", S_y=S_y, E_star=E_star, R=R)


def jg_area_exponent(e_y):
    r"""Exponent :math:`B = 0.14\,e^{23 e_y}` of JG's area fit.

    .. math::
        B = 0.14\,\exp(23\,e_y),\qquad e_y = S_y/E^*

    Parameters
    ----------
    e_y : array_like
        Yield strain :math:`S_y/E^*`, in (0, 0.05].

    Returns
    -------
    ndarray
        :math:`B` (dimensionless), the shape of ``e_y``.

    Raises
    ------
    ValueError
        If ``e_y`` is not real, finite and in (0, 0.05].

    Examples
    --------
    >>> round(float(jg_area_exponent(0.001)), 6)  # 0.14 * exp(0.023)
    0.143257

    References
    ----------
    Jackson & Green (2005), contact area.
    """
    return B_PREFACTOR * np.exp(B_EXPONENT * jg_check_yield_strain(e_y))


def jg_radius_ratio(area_ratio, e_y, nu):
    r"""Contact radius over sphere radius, :math:`a/R = (\pi C e_y/2)(A/A_c)^{1/2}`.

    .. math::
        \frac aR = \Big(\frac{A}{\pi R^2}\Big)^{1/2}
            = \Big(\frac{\omega_c}{R}\frac{A}{A_c}\Big)^{1/2}
            = \frac{\pi C e_y}{2}\Big(\frac{A}{A_c}\Big)^{1/2}

    Parameters
    ----------
    area_ratio : array_like
        :math:`A/A_c \ge 0`.
    e_y : array_like
        Yield strain :math:`S_y/E^*`, in (0, 0.05].
    nu : array_like
        Poisson's ratio, :math:`0 \le \nu < 0.5`.

    Returns
    -------
    ndarray
        :math:`a/R`, the broadcast shape.

    Raises
    ------
    ValueError
        If an input is not real, finite and in its range.

    Examples
    --------
    >>> C = float(jg_yield_coefficient(0.3))
    >>> r = jg_radius_ratio(4.0, 0.001, 0.3)
    >>> round(float(r / (3.141592653589793 * C * 0.001)), 12)  # (pi C e_y / 2) * sqrt(4)
    1.0

    References
    ----------
    Jackson & Green (2005), contact radius in the geometric hardness.
    """
    ratio = check_nonnegative(area_ratio, "area_ratio")
    C, e_y = jg_yield_coefficient(nu), jg_check_yield_strain(e_y)
    check_broadcast(area_ratio=ratio, e_y=e_y, nu=C)
    return 0.5 * np.pi * C * e_y * np.sqrt(ratio)
