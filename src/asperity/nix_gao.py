r"""Indentation size effect: the Nix-Gao hardness, mapped onto an asperity's interference.

Geometrically necessary dislocations make small indents harder.  Nix and Gao's model
gives the hardness at indentation depth :math:`h`

.. math::
    H = H_0\sqrt{1 + h^*/h},

with :math:`H_0` the hardness of large indents and :math:`h^*` a material length
(micrometres for annealed metals).

**Mapping onto an asperity.**  An asperity pressed by the flat to the interference
:math:`\omega` is taken as an indent of depth :math:`h = \omega`, so its hardness and yield
strength (:math:`S_y = H/2.84`, :mod:`asperity.jackson_green`) rise by
:math:`\sqrt{1 + h^*/\omega}`.  Every critical value of an elastic-plastic sphere scales as
:math:`\omega_c \propto S_y^2 \propto H^2`, so at interference :math:`\omega` the local
critical interference is :math:`\omega_c(\omega) = \omega_{c0}(1 + h^*/\omega)`, with
:math:`\omega_{c0}` the one of hardness :math:`H_0`, and the local dimensionless
interference is

.. math::
    \omega^* = \frac{\omega}{\omega_c(\omega)} = \frac{\omega^2}{\omega_{c0}(\omega + h^*)}.

Yield starts where :math:`\omega^* = 1`, the self-consistent critical interference

.. math::
    \omega_c = \omega_{c0}\,\frac{1 + \sqrt{1 + 4h^*/\omega_{c0}}}{2}
    \;\approx\; \sqrt{\omega_{c0}h^*}\quad (h^* \gg \omega_{c0}).

This is the quasi-static ("local") use of the size effect: at each interference the
asperity responds as an elastic-perfectly plastic sphere with the hardness of that depth.
Limits: the Nix-Gao count of geometrically necessary dislocations applied to a spherical
profile gives a density :math:`\propto 1/(bR)`, independent of depth (Swadener, George &
Pharr 2002 measured the radius dependence this predicts), so mapping :math:`h = \omega`
overstates the effect at the smallest interferences; and Nix-Gao itself overestimates the
hardness of very shallow indents (tens of nanometres and below), where the storage volume
of the geometrically necessary dislocations saturates.
docs/plasticity.md discusses both.

All functions broadcast like NumPy ufuncs; lengths in any one unit.

References
----------
.. [1] W. D. Nix, H. Gao, "Indentation size effects in crystalline materials: a law for
   strain gradient plasticity", J. Mech. Phys. Solids 46 (1998) 411-425.
.. [2] J. G. Swadener, E. P. George, G. M. Pharr, "The correlation of the indentation size
   effect measured with indenters of various shapes", J. Mech. Phys. Solids 50 (2002)
   681-694.
"""

from __future__ import annotations

import numpy as np

from ._validation import check_broadcast, check_finite_result, check_nonnegative, check_positive, ufunc_result

__all__ = ["ng_hardness", "ng_scaled_interference", "ng_interference", "ng_critical_interference"]


def ng_hardness(h, H0, h_star):
    r"""Nix-Gao hardness at indentation depth :math:`h`, :math:`H = H_0\sqrt{1 + h^*/h}`.

    .. math::
        H = H_0\sqrt{1 + \frac{h^*}{h}}

    Parameters
    ----------
    h : array_like
        Indentation depth (here: an asperity's interference) :math:`h > 0`.
    H0 : array_like
        Hardness of large indents :math:`H_0 > 0` (any pressure unit).
    h_star : array_like
        Material length :math:`h^* \ge 0` (the unit of ``h``); 0: no size effect.

    Returns
    -------
    ndarray
        :math:`H` in the unit of ``H0``, the broadcast shape.

    Raises
    ------
    ValueError
        If an input is not real, finite and in its range.

    Examples
    --------
    >>> float(ng_hardness(1.0, 2.0, 3.0))  # 2 sqrt(1 + 3)
    4.0

    References
    ----------
    Nix & Gao (1998), the depth dependence of hardness.
    """
    h = check_positive(h, "h")
    H0_, hs = check_positive(H0, "H0"), check_nonnegative(h_star, "h_star")
    check_broadcast(h=h, H0=H0_, h_star=hs)
    with np.errstate(all="ignore"):
        out = H0_ * np.sqrt(1.0 + hs / h)
    return ufunc_result(check_finite_result(out, "the hardness", h=h, H0=H0_, h_star=hs))


def ng_scaled_interference(omega, omega_c0, h_star):
    r"""Local dimensionless interference :math:`\omega^* = \omega^2/(\omega_{c0}(\omega + h^*))`.

    .. math::
        \omega^* = \frac{\omega}{\omega_{c0}(1 + h^*/\omega)} = \frac{\omega^2}{\omega_{c0}(\omega + h^*)}

    The interference over the critical interference of the hardness at depth
    :math:`\omega` (:func:`ng_hardness`, :math:`\omega_c \propto H^2`); :math:`\omega/\omega_{c0}`
    for :math:`h^* = 0`.  Increasing in :math:`\omega`.

    Parameters
    ----------
    omega : array_like
        Interference :math:`\omega \ge 0`.
    omega_c0 : array_like
        Critical interference at the large-indent hardness :math:`H_0`, :math:`> 0`.
    h_star : array_like
        Nix-Gao length :math:`h^* \ge 0`.

    Returns
    -------
    ndarray
        :math:`\omega^*`, the broadcast shape.

    Raises
    ------
    ValueError
        If an input is not real, finite and in its range.

    Examples
    --------
    >>> float(ng_scaled_interference(2.0, 1.0, 0.0)), float(ng_scaled_interference(2.0, 1.0, 2.0))
    (2.0, 1.0)

    References
    ----------
    Nix & Gao (1998); the mapping :math:`h = \omega` (module docstring).
    """
    w = check_nonnegative(omega, "omega")
    w0 = check_positive(omega_c0, "omega_c0")
    hs = check_nonnegative(h_star, "h_star")
    check_broadcast(omega=w, omega_c0=w0, h_star=hs)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        out = np.where(w > 0, w / (w0 * (1.0 + hs / np.where(w > 0, w, 1.0))), 0.0)  # w^2/(w0 (w + h*))
    return ufunc_result(check_finite_result(out, "omega*", omega=w, omega_c0=w0, h_star=hs))


def ng_interference(omega_star, omega_c0, h_star):
    r"""Interference at which :math:`\omega^*` is reached, the inverse of :func:`ng_scaled_interference`.

    .. math::
        \omega = \frac{\omega^*\omega_{c0} + \sqrt{(\omega^*\omega_{c0})^2 + 4\omega^*\omega_{c0}h^*}}{2}

    Parameters
    ----------
    omega_star : array_like
        Local dimensionless interference :math:`\omega^* \ge 0`.
    omega_c0 : array_like
        Critical interference at hardness :math:`H_0`, :math:`> 0`.
    h_star : array_like
        Nix-Gao length :math:`h^* \ge 0`.

    Returns
    -------
    ndarray
        :math:`\omega` in the unit of ``omega_c0``, the broadcast shape.

    Raises
    ------
    ValueError
        If an input is not real, finite and in its range.

    Examples
    --------
    >>> float(ng_interference(1.0, 1.0, 2.0))  # omega^2 = omega + 2
    2.0

    References
    ----------
    Nix & Gao (1998); the mapping :math:`h = \omega` (module docstring).
    """
    ws, w0, hs = (check_nonnegative(omega_star, "omega_star"), check_positive(omega_c0, "omega_c0"),
                  check_nonnegative(h_star, "h_star"))
    check_broadcast(omega_star=ws, omega_c0=w0, h_star=hs)
    with np.errstate(all="ignore"):
        x = ws * w0
        out = 0.5 * (x + np.sqrt(x * x + 4.0 * x * hs))
        # where x^2 overflows, the same root factorised (exact for h* = 0 only in the form above)
        out = np.where(np.isfinite(out), out, 0.5 * (x + np.sqrt(x) * np.sqrt(x + 4.0 * hs)))
    return ufunc_result(check_finite_result(out, "the interference", omega_star=ws, omega_c0=w0, h_star=hs))


def ng_critical_interference(omega_c0, h_star):
    r"""Self-consistent critical interference with the size effect, :math:`\omega_c = \omega_{c0}(1 + h^*/\omega_c)`.

    .. math::
        \omega_c = \omega_{c0}\,\frac{1 + \sqrt{1 + 4h^*/\omega_{c0}}}{2}

    Yield starts where the interference reaches the critical interference of the hardness
    at that depth.  :math:`\omega_{c0}` for :math:`h^* = 0`; about
    :math:`\sqrt{\omega_{c0}h^*}` for :math:`h^* \gg \omega_{c0}`.

    Parameters
    ----------
    omega_c0 : array_like
        Critical interference at the large-indent hardness :math:`H_0`, :math:`> 0`.
    h_star : array_like
        Nix-Gao length :math:`h^* \ge 0`.

    Returns
    -------
    ndarray
        :math:`\omega_c` in the unit of ``omega_c0``, the broadcast shape.

    Raises
    ------
    ValueError
        If an input is not real, finite and in its range.

    Examples
    --------
    >>> float(ng_critical_interference(1.0, 0.0)), float(ng_critical_interference(1.0, 2.0))
    (1.0, 2.0)

    References
    ----------
    Nix & Gao (1998); the mapping :math:`h = \omega` (module docstring).
    """
    return ng_interference(1.0, omega_c0, h_star)
