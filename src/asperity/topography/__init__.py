r"""Greenwood-Williamson summit parameters of measured surfaces.

Reads an AFM height map or a profilometer line scan with SurfaceTopography and
estimates the three surface inputs of the Greenwood-Williamson (GW) model, named as in
:class:`asperity.surface.Surface` and :data:`asperity.quantities.PHYSICAL_PARAMETERS`,

=================  ===========================================  ==============
symbol             meaning                                      unit
=================  ===========================================  ==============
``sigma_s``        standard deviation of summit heights         m
``R``              mean summit radius of curvature              m
``eta``            summit density :math:`\eta` (per area)       1/m\ :sup:`2`
=================  ===========================================  ==============

in two independent ways:

* :func:`spectral_summits` -- from the spectral moments :math:`m_0, m_2, m_4`
  through the random-process relations of Nayak (1971) as summarised by
  McCool (1986), valid for an isotropic Gaussian surface;
* :func:`detected_summits` -- by finding the summits (local maxima) on the grid
  and measuring their heights and curvatures directly.

:func:`analyse_surface` runs both, compares them and lists what looks unreliable.

====================================  ==============================================================
module                                contents
====================================  ==============================================================
:mod:`~asperity.topography.read`      :func:`read_topography` (sizes in metres, ``unit`` of heights)
:mod:`~asperity.topography.summits`   :class:`SummitParameters`, preparation, spectral moments
:mod:`~asperity.topography.spectral`  Nayak/McCool relations, :func:`spectral_summits`
:mod:`~asperity.topography.detected`  local maxima, curvatures, :func:`detected_summits`
:mod:`~asperity.topography.analysis`  :class:`SurfaceAnalysis`, :func:`analyse_surface`, thresholds
====================================  ==============================================================

References
----------
.. [1] Greenwood, J. A., Williamson, J. B. P. (1966). Contact of nominally flat
   surfaces. Proc. R. Soc. Lond. A 295, 300-319.
.. [2] Nayak, P. R. (1971). Random process model of rough surfaces. J. Lubr. Technol.
   (ASME) 93, 398-407.
.. [3] McCool, J. I. (1986). Comparison of models for the contact of rough surfaces.
   Wear 107, 37-60.
"""

from .analysis import (
    MAX_ANISOTROPY,
    MAX_RMS_SLOPE,
    METHODS,
    MIN_ALPHA_N,
    MIN_RADIUS_PIXELS,
    MIN_SPACING_PIXELS,
    MIN_SUMMITS,
    RATIO_TOLERANCE,
    SIGMA_TOLERANCE,
    SurfaceAnalysis,
    analyse_surface,
)
from .detected import detected_summits
from .read import read_topography
from .spectral import NAYAK_SIGMA_S, RICE_SIGMA_P, spectral_summits
from .summits import FLAT_RTOL, MIN_POINTS, SummitParameters

__all__ = [
    "SummitParameters",
    "SurfaceAnalysis",
    "read_topography",
    "spectral_summits",
    "detected_summits",
    "analyse_surface",
    "NAYAK_SIGMA_S",
    "RICE_SIGMA_P",
    "RATIO_TOLERANCE",
    "SIGMA_TOLERANCE",
    "MIN_ALPHA_N",
    "MIN_SPACING_PIXELS",
    "MIN_RADIUS_PIXELS",
    "MIN_SUMMITS",
    "MAX_ANISOTROPY",
    "MAX_RMS_SLOPE",
    "METHODS",
    "MIN_POINTS",
    "FLAT_RTOL",
]
