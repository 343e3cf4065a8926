r"""GW summit parameters from the spectral moments of a surface (Nayak 1971; McCool 1986).

**Spectral moments.**  McCool's moments are *profile* moments of an isotropic
surface :math:`h(x, y)`:

.. math::

    m_0 = \langle h^2 \rangle, \qquad
    m_2 = \langle (\partial h/\partial x)^2 \rangle, \qquad
    m_4 = \langle (\partial^2 h/\partial x^2)^2 \rangle ,

the same in every direction.  For a map they are computed from area averages that
do not single out a direction (Nayak 1971; Longuet-Higgins 1957: :math:`m_{20} = m_{02} = m_2`,
:math:`m_{40} = m_{04} = 3 m_{22} = m_4` for an isotropic surface):

.. math::

    m_0 = S_q^2, \qquad
    \langle |\nabla h|^2 \rangle = m_{20} + m_{02} = 2 m_2, \qquad
    \langle (\nabla^2 h)^2 \rangle = m_{40} + 2 m_{22} + m_{04} = \tfrac{8}{3} m_4 .

SurfaceTopography's ``rms_gradient`` is :math:`\langle |\nabla h|^2\rangle^{1/2}` and
its ``rms_curvature_from_area`` is half the rms Laplacian,
:math:`\langle (\nabla^2 h/2)^2\rangle^{1/2}`, hence

.. math::

    m_2 = \tfrac12\,\mathrm{rms\_gradient}^2, \qquad
    m_4 = \tfrac38 \langle (\nabla^2 h)^2\rangle = \tfrac32\,\mathrm{rms\_curvature\_from\_area}^2 .

For a line scan, :math:`m_0 = R_q^2`, :math:`m_2 = R_{\Delta q}^2`,
:math:`m_4 = R_{\Delta\Delta q}^2` (``Rq``, ``Rdq``, ``Rddq``).  All derivatives are
SurfaceTopography's finite differences on the measured grid (upwind for slopes,
central for curvatures), i.e. the moments include everything the instrument
resolved, down to the pixel (:func:`asperity.topography.summits.moments`).

**Summit statistics** (Nayak 1971, as collected by McCool 1986), with the bandwidth
parameter :math:`\alpha_N = m_0 m_4 / m_2^2 \ge 1` (:func:`bandwidth_alpha`):

.. math::

    \eta = \frac{m_4}{6\pi\sqrt3\, m_2}, \qquad
    R = \frac{3}{8}\sqrt{\frac{\pi}{m_4}}, \qquad
    \sigma_s = \Bigl(1 - \frac{0.8968}{\alpha_N}\Bigr)^{1/2} \sqrt{m_0}, \qquad
    \bar z_s = \frac{4}{\sqrt{\pi \alpha_N}} \sqrt{m_0}

(:func:`summit_density`, :func:`summit_radius`, :func:`summit_sigma`,
:func:`mean_summit_height`).  :math:`R` is the reciprocal of the mean summit curvature
:math:`\bar\kappa_s = \tfrac83\sqrt{m_4/\pi}`, the curvature of a summit being the
mean of its two principal curvatures, :math:`\kappa = -(h_{xx}+h_{yy})/2`.  Averaged
over *all* summits this value does not depend on :math:`\alpha_N` (the Hessian of a
stationary Gaussian field is independent of its gradient); it is the large-:math:`\alpha_N`
limit only for the curvature of the high summits.  :math:`\bar z_s` is the mean summit
height above the mean plane, which the GW separation is measured from.

References
----------
.. [1] Greenwood, J. A., Williamson, J. B. P. (1966). Contact of nominally flat
   surfaces. Proc. R. Soc. Lond. A 295, 300-319.
.. [2] Nayak, P. R. (1971). Random process model of rough surfaces. J. Lubr. Technol.
   (ASME) 93, 398-407.
.. [3] McCool, J. I. (1986). Comparison of models for the contact of rough surfaces.
   Wear 107, 37-60.
.. [4] Longuet-Higgins, M. S. (1957). The statistical analysis of a random, moving
   surface. Phil. Trans. R. Soc. Lond. A 249, 321-387.
.. [5] Rice, S. O. (1944). Mathematical analysis of random noise. Bell Syst. Tech. J.
   23, 282-332.
"""

from __future__ import annotations

import math

import numpy as np

from .._validation import check_broadcast, check_finite_result, check_positive, check_range
from ..surface import NAYAK_SIGMA_S
from .summits import SummitParameters, moments, prepare

__all__ = [
    "NAYAK_SIGMA_S",
    "RICE_SIGMA_P",
    "bandwidth_alpha",
    "summit_density",
    "summit_radius",
    "summit_sigma",
    "mean_summit_height",
    "spectral_summits",
]

#: Same constant for the heights of profile peaks, :math:`\pi/2 - 1` (Rice 1944).
RICE_SIGMA_P = math.pi / 2 - 1


def _out(x):
    x = np.asarray(x, dtype=float)
    return float(x) if x.ndim == 0 else x


def bandwidth_alpha(m0, m2, m4):
    r"""Nayak's bandwidth :math:`\alpha_N = m_0 m_4 / m_2^2` (>= 1 for a profile, >= 1.5 for an isotropic map).

    .. math:: \alpha_N = \frac{m_0\,m_4}{m_2^2}

    Parameters
    ----------
    m0 : array_like
        Mean square height :math:`m_0` [m^2], > 0.
    m2 : array_like
        Mean square profile slope :math:`m_2` [-], > 0.
    m4 : array_like
        Mean square profile curvature :math:`m_4` [1/m^2], > 0.

    Returns
    -------
    float or ndarray
        :math:`\alpha_N` [-], broadcast over the inputs.

    References
    ----------
    Nayak (1971); McCool (1986).
    """
    m0, m2, m4 = check_positive(m0, "m0"), check_positive(m2, "m2"), check_positive(m4, "m4")
    check_broadcast(m0=m0, m2=m2, m4=m4)
    with np.errstate(all="ignore"):
        alpha_n = m0 * m4 / m2**2
    return _out(check_finite_result(alpha_n, "alpha_N", m0=m0, m2=m2, m4=m4))


def summit_density(m2, m4):
    r"""Summit density of an isotropic Gaussian surface, :math:`\eta = m_4/(6\pi\sqrt3\,m_2)`.

    .. math:: \eta = \frac{m_4}{6\pi\sqrt3\,m_2}

    Parameters
    ----------
    m2 : array_like
        Mean square profile slope :math:`m_2` [-], > 0.
    m4 : array_like
        Mean square profile curvature :math:`m_4` [1/m^2], > 0.

    Returns
    -------
    float or ndarray
        :math:`\eta` [1/m^2], broadcast over the inputs.

    References
    ----------
    Nayak (1971); McCool (1986).
    """
    m2, m4 = check_positive(m2, "m2"), check_positive(m4, "m4")
    check_broadcast(m2=m2, m4=m4)
    with np.errstate(all="ignore"):
        eta = m4 / (6 * math.pi * math.sqrt(3) * m2)
    return _out(check_finite_result(eta, "eta", m2=m2, m4=m4))


def summit_radius(m4):
    r"""Mean summit radius, the reciprocal of the mean summit curvature, :math:`R = \tfrac38\sqrt{\pi/m_4}`.

    .. math:: R = \frac{1}{\bar\kappa_s} = \frac38\sqrt{\frac{\pi}{m_4}}

    Parameters
    ----------
    m4 : array_like
        Mean square profile curvature :math:`m_4` [1/m^2], > 0.

    Returns
    -------
    float or ndarray
        :math:`R` [m].

    References
    ----------
    Nayak (1971) (mean curvature of all summits); McCool (1986).
    """
    m4 = check_positive(m4, "m4")
    with np.errstate(all="ignore"):
        R = 0.375 * np.sqrt(math.pi / m4)
    return _out(check_finite_result(R, "R", m4=m4))


def summit_sigma(m0, alpha_n, constant=NAYAK_SIGMA_S):
    r"""Standard deviation of summit (or peak) heights, :math:`\sigma_s = (1 - c/\alpha_N)^{1/2}\sqrt{m_0}`.

    .. math:: \sigma_s = \Bigl(1 - \frac{c}{\alpha_N}\Bigr)^{1/2}\sqrt{m_0}

    with :math:`c =` :data:`NAYAK_SIGMA_S` (0.8968) for the summits of a surface and
    :math:`c =` :data:`RICE_SIGMA_P` (:math:`\pi/2-1`) for the peaks of a profile.  The
    factor is clipped at 0 for :math:`\alpha_N < c`, outside the relation's range.

    Parameters
    ----------
    m0 : array_like
        Mean square height :math:`m_0` [m^2], >= 0.
    alpha_n : array_like
        Bandwidth parameter :math:`\alpha_N` [-], > 0.
    constant : float
        :math:`c`, 0 <= c <= 1.

    Returns
    -------
    float or ndarray
        :math:`\sigma_s` [m].

    References
    ----------
    Nayak (1971); McCool (1986); Rice (1944) for profile peaks.
    """
    m0 = check_range(m0, "m0", 0.0, math.inf)
    alpha_n = check_positive(alpha_n, "alpha_n")
    c = check_range(constant, "constant", 0.0, 1.0)
    check_broadcast(m0=m0, alpha_n=alpha_n, constant=c)
    with np.errstate(all="ignore"):
        sigma_s = np.sqrt(np.maximum(1.0 - c / alpha_n, 0.0) * m0)
    return _out(check_finite_result(sigma_s, "sigma_s", m0=m0, alpha_n=alpha_n))


def mean_summit_height(m0, alpha_n):
    r"""Mean summit height above the mean plane, :math:`\bar z_s = 4\sqrt{m_0/(\pi\alpha_N)}`.

    .. math:: \bar z_s = \frac{4}{\sqrt{\pi\alpha_N}}\sqrt{m_0}

    Parameters
    ----------
    m0 : array_like
        Mean square height :math:`m_0` [m^2], >= 0.
    alpha_n : array_like
        Bandwidth parameter :math:`\alpha_N` [-], > 0.

    Returns
    -------
    float or ndarray
        :math:`\bar z_s` [m].

    References
    ----------
    Nayak (1971); McCool (1986).
    """
    m0 = check_range(m0, "m0", 0.0, math.inf)
    alpha_n = check_positive(alpha_n, "alpha_n")
    check_broadcast(m0=m0, alpha_n=alpha_n)
    with np.errstate(all="ignore"):
        z = 4 * np.sqrt(m0 / (math.pi * alpha_n))
    return _out(check_finite_result(z, "the mean summit height", m0=m0, alpha_n=alpha_n))


def spectral_summits(topography) -> SummitParameters:
    r"""GW summit parameters from spectral moments (Nayak 1971; McCool 1986).

    The mean plane (line) is removed first.  For a map,
    :math:`m_0 = S_q^2`, :math:`m_2 = \mathrm{rms\_gradient}^2/2`,
    :math:`m_4 = \tfrac32\,\mathrm{rms\_curvature\_from\_area}^2`
    (:math:`= \tfrac38\langle(\nabla^2 h)^2\rangle`); for a line scan
    :math:`m_0 = R_q^2`, :math:`m_2 = R_{\Delta q}^2`, :math:`m_4 = R_{\Delta\Delta q}^2`.
    Then, with :math:`\alpha_N = m_0 m_4/m_2^2`,

    .. math::

        \eta = \frac{m_4}{6\pi\sqrt3\,m_2},\quad
        R = 0.375\sqrt{\pi/m_4},\quad
        \sigma_s = \sqrt{1 - 0.8968/\alpha_N}\,\sqrt{m_0},\quad
        \bar z_s = 4\sqrt{m_0/(\pi\alpha_N)} .

    Parameters
    ----------
    topography : SurfaceTopography.Topography or SurfaceTopography.UniformLineScan
        Uniform grid, heights and sizes in ``topography.unit`` (taken as metres if None).

    Returns
    -------
    SummitParameters
        ``method='spectral'``, ``n_summits=None``; SI units.

    Raises
    ------
    TypeError
        If ``topography`` is not a SurfaceTopography object.
    ValueError
        For a surface :func:`~asperity.topography.summits.prepare` refuses (too few points,
        flat or tilted plane, undefined data), or with zero slope or curvature.

    Notes
    -----
    Valid for an isotropic Gaussian surface.  A line scan is taken to be one profile
    of such a surface.  The relations for :math:`\sigma_s` and :math:`\bar z_s` lose
    accuracy for small :math:`\alpha_N` (below about 5).

    References
    ----------
    Nayak (1971), J. Lubr. Technol. 93, 398-407.
    McCool (1986), Wear 107, 37-60.
    Greenwood & Williamson (1966), Proc. R. Soc. A 295, 300-319.
    """
    topo = prepare(topography)
    m0, m2, m4, anisotropy = moments(topo)
    if m2 <= 0 or m4 <= 0:
        raise ValueError("the surface is flat (zero slope or curvature): no summits")
    alpha_n = bandwidth_alpha(m0, m2, m4)
    return SummitParameters(
        sigma_s=summit_sigma(m0, alpha_n), R=summit_radius(m4), eta=summit_density(m2, m4),
        method="spectral", sigma=math.sqrt(m0), mean_summit_height=mean_summit_height(m0, alpha_n),
        m0=m0, m2=m2, m4=m4, alpha_n=alpha_n, anisotropy=anisotropy,
        source="map" if topo.dim == 2 else "line scan")
