r"""Real contact area from the power spectrum: Persson's theory and the light-load asymptote.

Two statistical comparators of the asperity models that need only the rms slope
:math:`h' = \langle|\nabla h|^2\rangle^{1/2}` of the surface, i.e. the second moment of its
power spectrum :math:`C(q)`, :math:`h'^2 = 2\pi\int q^3C(q)\,\mathrm dq` (isotropic,
:math:`\langle h^2\rangle = 2\pi\int qC(q)\,\mathrm dq`):

* **Persson (2001)**: the probability of finding a point of the interface under a pressure
  :math:`\sigma` diffuses as the roughness is added scale by scale, from :math:`\delta(\sigma - p)`
  with an absorbing boundary at :math:`\sigma = 0`; the surviving fraction is the real area

  .. math::
      \frac{A}{A_0} = \mathrm{erf}\Big(\frac{p}{2\sqrt G}\Big),\qquad
      G = \frac\pi4E^{*2}\int q^3C(q)\,\mathrm dq = \frac{E^{*2}h'^2}{8}
      \quad\Rightarrow\quad \frac{A}{A_0} = \mathrm{erf}\Big(\frac{\sqrt2\,p}{E^*h'}\Big),

  whose light-load slope is :math:`A/A_0 \simeq \kappa\,p/E^*h'` with
  :math:`\kappa = \sqrt{8/\pi} \approx 1.596` (:data:`KAPPA_PERSSON`);
* **Bush, Gibson & Thomas (1975)**: the asymptote of the asperity theory of an isotropic
  Gaussian surface of infinite bandwidth at vanishing load, :math:`A/A_0 = \kappa p/E^*h'`
  with :math:`\kappa = \sqrt{2\pi} \approx 2.507` (:data:`KAPPA_BGT`; in the profile
  moment :math:`m_2 = h'^2/2`, :math:`A/A_0 = \sqrt{\pi/m_2}\,p/E^*`).  Linear: meaningful
  only at small area fractions.

Boundary-element solutions of self-affine surfaces give :math:`\kappa` near 2, between the two
(Hyun, Pei, Molinari & Robbins 2004; Campañá & Müser 2007; Yastrebov, Anciaux & Molinari 2017;
docs/validation.md for the values measured here).

References
----------
.. [1] B. N. J. Persson, Theory of rubber friction and contact mechanics, J. Chem. Phys. 115
   (2001) 3840-3861 (the contact-area distribution P(sigma, zeta) and its erf solution).
.. [2] A. W. Bush, R. D. Gibson, T. R. Thomas, The elastic contact of a rough surface,
   Wear 35 (1975) 87-111.
.. [3] S. Hyun, L. Pei, J.-F. Molinari, M. O. Robbins, Phys. Rev. E 70 (2004) 026117.
.. [4] C. Campañá, M. H. Müser, Europhys. Lett. 77 (2007) 38005.
.. [5] V. A. Yastrebov, G. Anciaux, J.-F. Molinari, J. Mech. Phys. Solids 107 (2017) 469-493.
"""

from __future__ import annotations

import math

import numpy as np
from scipy import special

from ._validation import (
    as_float_array,
    check_broadcast,
    check_finite_result,
    check_positive,
    ufunc_result,
)
from .units import to_si

__all__ = ["KAPPA_PERSSON", "KAPPA_BGT", "persson_area_fraction", "bgt_area_fraction", "rms_slope"]

#: Light-load slope of Persson's area, :math:`\sqrt{8/\pi}`.
KAPPA_PERSSON = math.sqrt(8.0 / math.pi)
#: Light-load slope of Bush, Gibson & Thomas, :math:`\sqrt{2\pi}`.
KAPPA_BGT = math.sqrt(2.0 * math.pi)


def _pressure(p):
    p = as_float_array(to_si(p, "Pa", "p"), "p", allow_empty=True)
    if np.any(p < 0):
        raise ValueError(f"p (nominal pressure) must be >= 0 Pa, got min {p.min():g}")
    return p


def _inputs(p, E_star, rms_slope):
    """Pressure (>= 0), modulus and slope (> 0) as arrays that broadcast together."""
    p = _pressure(p)
    E_star = check_positive(to_si(E_star, "Pa", "E_star"), "E_star")
    slope = check_positive(to_si(rms_slope, "", "rms_slope"), "rms_slope")
    check_broadcast(p=p, E_star=E_star, rms_slope=slope)
    return p, E_star, slope


def persson_area_fraction(p, E_star, rms_slope):
    r"""Real contact area fraction of Persson's theory (full contact is reached only as p -> infinity).

    .. math::
        \frac{A}{A_0} = \mathrm{erf}\Big(\frac{\sqrt2\,p}{E^*h'}\Big)
        \;\simeq\; \sqrt{\frac8\pi}\,\frac{p}{E^*h'}\quad(p\to0)

    Parameters
    ----------
    p : array_like
        Nominal pressure :math:`p = P/A_0` [Pa], >= 0.
    E_star : array_like
        Contact modulus :math:`E^*` [Pa], > 0.
    rms_slope : array_like
        Rms gradient of the surface :math:`h' = \langle|\nabla h|^2\rangle^{1/2}` [-], > 0
        (:func:`rms_slope`).

    Returns
    -------
    ndarray
        :math:`A/A_0` in [0, 1), the broadcast shape of the inputs.

    Raises
    ------
    ValueError
        For negative or non-finite pressures, a non-positive modulus or slope, or shapes
        that do not broadcast.

    Examples
    --------
    >>> round(float(persson_area_fraction(1e8, 1e11, 0.1)), 6), round(KAPPA_PERSSON * 0.01, 6)  # light: slope
    (0.015957, 0.015958)

    References
    ----------
    B. N. J. Persson, J. Chem. Phys. 115 (2001) 3840 (erf solution of the stress diffusion).
    """
    p, E_star, slope = _inputs(p, E_star, rms_slope)
    with np.errstate(all="ignore"):
        x = check_finite_result(math.sqrt(2.0) * p / (E_star * slope), "p/(E_star rms_slope)", p=p, E_star=E_star,
                                rms_slope=slope)
    return ufunc_result(special.erf(x))


def bgt_area_fraction(p, E_star, rms_slope):
    r"""Light-load real contact area fraction of Bush, Gibson & Thomas (1975).

    .. math::
        \frac{A}{A_0} = \sqrt{2\pi}\,\frac{p}{E^*h'} = \sqrt{\frac{\pi}{m_2}}\,\frac{p}{E^*}

    The asymptote of the isotropic Gaussian asperity theory at vanishing load; linear, so
    above a few per cent of contact it is an extrapolation (it exceeds 1 at
    :math:`p > E^*h'/\sqrt{2\pi}`).

    Parameters
    ----------
    p : array_like
        Nominal pressure [Pa], >= 0.
    E_star : array_like
        Contact modulus [Pa], > 0.
    rms_slope : array_like
        Rms gradient :math:`h'` [-], > 0.

    Returns
    -------
    ndarray
        :math:`A/A_0`, the broadcast shape of the inputs (not capped at 1).

    Raises
    ------
    ValueError
        For negative or non-finite pressures, a non-positive modulus or slope, or shapes
        that do not broadcast.

    Examples
    --------
    >>> round(float(bgt_area_fraction(1e8, 1e11, 0.1)), 6)
    0.025066

    References
    ----------
    A. W. Bush, R. D. Gibson, T. R. Thomas, Wear 35 (1975) 87-111.
    """
    p, E_star, slope = _inputs(p, E_star, rms_slope)
    with np.errstate(all="ignore"):
        out = KAPPA_BGT * p / (E_star * slope)
    return ufunc_result(check_finite_result(out, "the BGT area fraction", p=p, E_star=E_star, rms_slope=slope))


def rms_slope(topography):
    r"""Rms gradient :math:`h' = \langle|\nabla h|^2\rangle^{1/2}` of a map, from its power spectrum.

    .. math::
        h'^2 = \frac{1}{N^2}\sum_{\mathbf q}q^2\,\frac{|\tilde h(\mathbf q)|^2}{N^2}
        = 2\pi\int q^3C(q)\,\mathrm dq

    For a periodic map, the sum over its discrete Fourier coefficients (exact for a
    band-limited surface); for a free map, SurfaceTopography's finite-difference
    ``rms_gradient`` (a window-free estimate; the periodogram of a non-periodic map leaks).

    Parameters
    ----------
    topography : SurfaceTopography.Topography
        A 2-d map in metres (or ``unit`` None), no undefined data.

    Returns
    -------
    float
        :math:`h'` [-].

    Raises
    ------
    TypeError
        If ``topography`` is not a SurfaceTopography map.
    ValueError
        For a line scan or undefined data.

    Examples
    --------
    >>> from SurfaceTopography import Topography                      # doctest: +SKIP
    >>> x = np.arange(64) / 64                                        # doctest: +SKIP
    >>> rms_slope(Topography(np.sin(2 * np.pi * x)[:, None] * np.ones(64), (1.0, 1.0), periodic=True))  # doctest: +SKIP
    4.442882938158366

    References
    ----------
    Persson (2001); T. D. B. Jacobs, T. Junge, L. Pastewka, Surf. Topogr.: Metrol. Prop. 5 (2017) 013001.
    """
    if not all(hasattr(topography, a) for a in ("heights", "dim", "pixel_size", "is_periodic")):
        raise TypeError(f"topography must be a SurfaceTopography map, got {type(topography).__name__}")
    if topography.dim != 2:
        raise ValueError("rms_slope needs a 2-d map, not a line scan")
    if topography.has_undefined_data:
        raise ValueError("the topography has undefined data; fill it first")
    if topography.unit not in (None, "m"):
        topography = topography.to_unit("m")
    if not topography.is_periodic:
        return float(topography.rms_gradient())
    h = np.asarray(topography.heights(), dtype=float)
    nx, ny = h.shape
    dx, dy = (float(p) for p in topography.pixel_size)
    qx = 2 * math.pi * np.fft.fftfreq(nx, d=dx)
    qy = 2 * math.pi * np.fft.fftfreq(ny, d=dy)
    power = np.abs(np.fft.fft2(h)) ** 2
    return math.sqrt(float(np.sum((qx[:, None] ** 2 + qy[None, :] ** 2) * power))) / (nx * ny)
