r"""Single-asperity adhesion regimes and the roughness-adhesion competition, in SI units.

Which adhesion law describes one summit depends on how far the surface forces reach
compared with the elastic deformation they cause.  Four numbers say it:

=============================  ==================================================  ====================
function                       definition                                          reference
=============================  ==================================================  ====================
:func:`tabor_parameter`        :math:`\mu_T = (Rw^2/E^{*2}z_0^3)^{1/3}`            Tabor (1977)
:func:`maugis_parameter`       :math:`\lambda = 2\sigma_0(R/\pi wK^2)^{1/3}`       Maugis (1992), Eq 14
:func:`adhesion_regime`        DMT / Maugis-Dugdale / JKR from :math:`\lambda`      Johnson & Greenwood (1997)
:func:`fuller_tabor_parameter` :math:`\theta = E^*\sigma^{3/2}/(R^{1/2}w)`          Fuller & Tabor (1975)
=============================  ==================================================  ====================

with :math:`K = \tfrac43E^*`.  Small :math:`\mu_T` or :math:`\lambda` mean stiff
spheres and long-range forces (DMT), large values compliant spheres and short-range
forces (JKR); the Maugis-Dugdale model (:mod:`asperity.maugis_dugdale`) covers the whole
range.  :math:`\theta` compares the elastic force pushing a summit one roughness
:math:`\sigma` deep with its adhesive force: roughness defeats adhesion when
:math:`\theta` is large.

The physical arguments share one order, ``(R, w, E_star, <range>)``, as does
:func:`asperity.maugis_dugdale.md_lambda`.  Every function takes floats in SI units,
arrays (broadcast like a ufunc) or pint quantities, and returns a float for scalar inputs.

References
----------
.. [1] D. Tabor, J. Colloid Interface Sci. 58 (1977) 2-13.
.. [2] D. Maugis, J. Colloid Interface Sci. 150 (1992) 243-269.
.. [3] K. L. Johnson, J. A. Greenwood, "An adhesion map for the contact of elastic
   spheres", J. Colloid Interface Sci. 192 (1997) 326-333.
.. [4] K. N. G. Fuller, D. Tabor, Proc. R. Soc. A 345 (1975) 327-342.
.. [5] Adams, Müftü, Mohd Azhar, "A nano-scale multi-asperity contact and friction model", Eq (14).
"""

from __future__ import annotations

import numpy as np

from ._validation import check_broadcast, check_finite_result, check_nonnegative, check_positive, check_scalar_positive
from .maugis_dugdale import md_lambda
from .units import to_si

__all__ = ["tabor_parameter", "maugis_parameter", "adhesion_regime", "fuller_tabor_parameter"]


def _out(x):
    """A 0-d result as float, otherwise the array."""
    x = np.asarray(x, dtype=float)
    return float(x) if x.ndim == 0 else x


def tabor_parameter(R, w, E_star, z0):
    r"""Tabor parameter :math:`\mu_T = (R w^2 / E^{*2} z_0^3)^{1/3}`.

    The ratio of the elastic neck height at pull-off to the range of surface forces:
    small values mean DMT-like (stiff, long-range), large values JKR-like contact.

    .. math::

        \mu_T = \Big(\frac{R\,w^2}{E^{*2} z_0^3}\Big)^{1/3}

    Parameters
    ----------
    R : array_like or pint.Quantity
        Sphere (summit) radius (m), > 0.
    w : array_like or pint.Quantity
        Work of adhesion (J/m^2), > 0.
    E_star : array_like or pint.Quantity
        Composite Young's modulus (Pa), > 0.
    z0 : array_like or pint.Quantity
        Equilibrium spacing of the surface-force law (m), > 0 (about 0.2-0.4 nm).

    Returns
    -------
    float or ndarray
        :math:`\mu_T` (dimensionless), broadcast over the inputs.

    Notes
    -----
    For a Lennard-Jones force law the Dugdale model with the same maximum stress and
    work of adhesion gives :math:`\lambda \approx 1.16\,\mu_T` (Johnson & Greenwood 1997).

    References
    ----------
    .. [1] D. Tabor, J. Colloid Interface Sci. 58 (1977) 2-13.
    .. [2] K. L. Johnson, J. A. Greenwood, J. Colloid Interface Sci. 192 (1997) 326-333.
    """
    R = check_positive(to_si(R, "m", "R"), "R")
    w = check_positive(to_si(w, "J/m^2", "w"), "w")
    E_star = check_positive(to_si(E_star, "Pa", "E_star"), "E_star")
    z0 = check_positive(to_si(z0, "m", "z0"), "z0")
    check_broadcast(R=R, w=w, E_star=E_star, z0=z0)
    with np.errstate(all="ignore"):
        mu = np.cbrt(R * w**2 / (E_star**2 * z0**3))
    return _out(check_finite_result(mu, "the Tabor parameter", R=R, w=w, E_star=E_star, z0=z0))


def maugis_parameter(R, w, E_star, sigma0):
    r"""Maugis parameter :math:`\lambda = 2\sigma_0 (R/\pi w K^2)^{1/3}`, :math:`K = \tfrac43E^*` (Eq 14).

    The ratio of the elastic deformation at pull-off to the Dugdale range
    :math:`h = w/\sigma_0`: :math:`\lambda \to 0` is the DMT limit, :math:`\lambda \to \infty`
    the JKR limit (see :func:`adhesion_regime`).

    .. math::

        \lambda = 2\sigma_0\Big(\frac{R}{\pi w K^2}\Big)^{1/3},\qquad K = \tfrac43E^*

    Parameters
    ----------
    R : array_like or pint.Quantity
        Sphere (summit) radius (m), > 0.
    w : array_like or pint.Quantity
        Work of adhesion (J/m^2), > 0.
    E_star : array_like or pint.Quantity
        Composite Young's modulus (Pa), > 0.
    sigma0 : array_like or pint.Quantity
        Dugdale stress (Pa), > 0; :math:`\sigma_0 = w/h` for a Dugdale range ``h``.

    Returns
    -------
    float or ndarray
        :math:`\lambda` (dimensionless), broadcast over the inputs.

    References
    ----------
    .. [1] D. Maugis, J. Colloid Interface Sci. 150 (1992) 243-269.
    .. [2] Adams et al., Eq (14); :func:`asperity.maugis_dugdale.md_lambda`.
    """
    return _out(md_lambda(to_si(R, "m", "R"), to_si(w, "J/m^2", "w"), to_si(E_star, "Pa", "E_star"),
                          to_si(sigma0, "Pa", "sigma0")))


def adhesion_regime(lam, *, dmt_below: float = 0.1, jkr_above: float = 5.0):
    r"""Name the single-asperity adhesion regime of a Maugis parameter.

    ``'DMT'`` for :math:`\lambda <` ``dmt_below``, ``'JKR'`` for :math:`\lambda >`
    ``jkr_above``, ``'Maugis-Dugdale'`` in between (boundaries included):

    .. math::

        \text{regime}(\lambda) = \begin{cases}
        \text{DMT} & \lambda < \lambda_{DMT} \\
        \text{Maugis-Dugdale} & \lambda_{DMT} \le \lambda \le \lambda_{JKR} \\
        \text{JKR} & \lambda > \lambda_{JKR}
        \end{cases}

    Parameters
    ----------
    lam : array_like
        Maugis parameter :math:`\lambda \ge 0` (e.g. :attr:`PhysicalContact.lam` or
        :func:`maugis_parameter`).
    dmt_below, jkr_above : float
        Thresholds, 0 < dmt_below < jkr_above.  Defaults 0.1 and 5 follow the
        Johnson-Greenwood adhesion map, where the DMT and JKR solutions are adequate
        below and above them; the full map also depends on the load, so these are the
        load-independent bounds.

    Returns
    -------
    str or ndarray of str
        A string for a scalar ``lam``, otherwise an array of the same shape.

    References
    ----------
    .. [1] K. L. Johnson, J. A. Greenwood, "An adhesion map for the contact of elastic
       spheres", J. Colloid Interface Sci. 192 (1997) 326-333.
    """
    lam = check_nonnegative(lam, "lam")
    lo = check_scalar_positive(dmt_below, "dmt_below")
    hi = check_scalar_positive(jkr_above, "jkr_above")
    if not lo < hi:
        raise ValueError(f"dmt_below must be < jkr_above, got {lo:g} and {hi:g}")
    names = np.where(lam < lo, "DMT", np.where(lam > hi, "JKR", "Maugis-Dugdale"))
    return str(names) if names.ndim == 0 else names


def fuller_tabor_parameter(sigma, R, w, E_star):
    r"""Fuller-Tabor adhesion parameter :math:`\theta = E^*\sigma^{3/2}/(R^{1/2} w)`.

    The elastic force pushing one summit of radius :math:`R` a depth :math:`\sigma`
    into the flat, :math:`\tfrac43E^*R^{1/2}\sigma^{3/2}`, over its adhesive force scale
    :math:`\pi w R`, is :math:`\tfrac{4}{3\pi}\theta`.  In Fuller & Tabor's GW + JKR
    analysis the pull-off force of the rough contact, relative to a smooth one, falls
    steeply as :math:`\theta` grows: roughness defeats adhesion when the elastic term wins.

    .. math::

        \theta = \frac{E^*\sigma^{3/2}}{R^{1/2}\,w}

    Parameters
    ----------
    sigma : array_like or pint.Quantity
        Standard deviation of summit heights (m), > 0.
    R : array_like or pint.Quantity
        Summit radius (m), > 0.
    w : array_like or pint.Quantity
        Work of adhesion :math:`\Delta\gamma` (J/m^2), > 0.
    E_star : array_like or pint.Quantity
        Composite (plane-strain) modulus :math:`[(1-\nu_1^2)/E_1+(1-\nu_2^2)/E_2]^{-1}` (Pa), > 0.

    Returns
    -------
    float or ndarray
        :math:`\theta` (dimensionless), broadcast over the inputs.

    Notes
    -----
    Convention: :math:`E^*` is the composite modulus of this library (not the JKR
    :math:`K = \tfrac43E^*`) and :math:`w` the work of adhesion.  Later papers write the
    parameter with other moduli or prefactors (e.g. the :math:`\tfrac{4}{3\pi}\theta`
    above); thresholds are only comparable within one convention.

    References
    ----------
    .. [1] K. N. G. Fuller, D. Tabor, "The effect of surface roughness on the adhesion of
       elastic solids", Proc. R. Soc. A 345 (1975) 327-342.
    """
    sigma = check_positive(to_si(sigma, "m", "sigma"), "sigma")
    R = check_positive(to_si(R, "m", "R"), "R")
    w = check_positive(to_si(w, "J/m^2", "w"), "w")
    E_star = check_positive(to_si(E_star, "Pa", "E_star"), "E_star")
    check_broadcast(sigma=sigma, R=R, w=w, E_star=E_star)
    with np.errstate(all="ignore"):
        theta = E_star * sigma**1.5 / (np.sqrt(R) * w)
    return _out(check_finite_result(theta, "the Fuller-Tabor parameter", sigma=sigma, R=R, w=w, E_star=E_star))
