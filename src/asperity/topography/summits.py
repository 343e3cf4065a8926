r"""Summit parameters of a measured surface, and the preparation both estimators share.

A :class:`SummitParameters` holds the three Greenwood-Williamson inputs estimated from one
surface by one method, under the names of :class:`asperity.surface.Surface` and of
:data:`asperity.quantities.PHYSICAL_PARAMETERS`:

=================  ===========================================  ==============
field              meaning                                      unit
=================  ===========================================  ==============
``sigma_s``        standard deviation of summit heights         m
``R``              mean summit radius of curvature              m
``eta``            summit density (per nominal area)            1/m\ :sup:`2`
=================  ===========================================  ==============

:func:`prepare` checks a SurfaceTopography object, converts it to metres, removes its
mean plane (line) and refuses degenerate surfaces; :func:`moments` gives its profile
spectral moments :math:`m_0, m_2, m_4` (see :mod:`asperity.topography.spectral`).

**Degenerate surfaces.**  A flat or tilted plane has, after its mean plane is removed, a
residual made only of the rounding of the stored numbers: about :math:`10^{-16}` of the
largest absolute height for float64 data and up to about :math:`3\times10^{-8}` for
float32 data.  Summit statistics of such a residual are noise.  :func:`prepare` therefore
refuses a surface whose detrended rms height is at most :data:`FLAT_RTOL` (:math:`10^{-7}`)
times its largest absolute height before detrending.  The threshold sits a factor 3 above
float32 rounding and below what any instrument resolves (a 24-bit converter spans
:math:`6\times10^{-8}` of its range per step), so real roughness is not refused.
Surfaces with fewer than :data:`MIN_POINTS` points along an axis are refused too.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import asdict, dataclass
from typing import Any

import numpy as np

from ..quantities import PHYSICAL_PARAMETERS
from ..surface import Surface

__all__ = ["SummitParameters", "prepare", "moments", "plain", "MIN_POINTS", "FLAT_RTOL", "GW_PARAMETERS"]

#: Fewest grid points along each axis for summit statistics (a 3-point stencil needs
#: interior points, the detrending a few more).
MIN_POINTS = 8
#: Largest ratio of the detrended rms height to the largest absolute height that counts as
#: a flat (or tilted) plane made of rounding noise; see the module docstring.
FLAT_RTOL = 1e-7
#: Largest absolute height accepted [m]: far above any surface, far below the moments' overflow (h^2/dx^4).
MAX_HEIGHT = 1e50
#: The three GW summit parameters, named as in :data:`asperity.quantities.PHYSICAL_PARAMETERS`.
GW_PARAMETERS = {name: PHYSICAL_PARAMETERS[name] for name in ("sigma_s", "R", "eta")}


@dataclass(frozen=True)
class SummitParameters:
    """GW summit parameters of one surface, estimated by one method.

    Attributes
    ----------
    sigma_s : float
        Standard deviation of summit heights :math:`\\sigma_s` [m].
    R : float
        Mean summit radius :math:`R` [m], the reciprocal of the mean summit curvature.
    eta : float
        Summit density :math:`\\eta` [1/m^2].
    method : str
        ``'spectral'`` or ``'detected'``.
    sigma : float
        Rms height :math:`\\sqrt{m_0}` of the detrended surface [m].
    mean_summit_height : float
        Mean summit height above the mean plane [m].
    m0, m2, m4 : float or None
        Profile spectral moments [m^2], [-], [1/m^2] (None where not used).
    alpha_n : float or None
        Bandwidth parameter :math:`\\alpha_N = m_0 m_4/m_2^2` [-].
    n_summits : int or None
        Number of summits (or profile peaks) found; None for the spectral method.
    anisotropy : float or None
        Ratio of the larger to the smaller mean square slope along x and y (maps only).
    source : str
        ``'map'`` or ``'line scan'``.

    Notes
    -----
    ``radius`` and ``density`` are deprecated read-only aliases of ``R`` and ``eta``
    (they warn with :class:`DeprecationWarning`).
    """

    sigma_s: float
    R: float
    eta: float
    method: str
    sigma: float
    mean_summit_height: float
    m0: float | None = None
    m2: float | None = None
    m4: float | None = None
    alpha_n: float | None = None
    n_summits: int | None = None
    anisotropy: float | None = None
    source: str = "map"

    @property
    def radius(self) -> float:
        """Deprecated alias of :attr:`R` [m]."""
        warnings.warn("SummitParameters.radius is deprecated; use .R", DeprecationWarning, stacklevel=2)
        return self.R

    @property
    def density(self) -> float:
        """Deprecated alias of :attr:`eta` [1/m^2]."""
        warnings.warn("SummitParameters.density is deprecated; use .eta", DeprecationWarning, stacklevel=2)
        return self.eta

    @property
    def spacing(self) -> float:
        """Mean distance between summits, :math:`\\eta^{-1/2}` [m]."""
        return 1.0 / math.sqrt(self.eta)

    def surface(self, area, *, source: str | None = None) -> Surface:
        """The GW :class:`~asperity.surface.Surface` of these summits over a nominal ``area`` (m^2).

        ``source`` (default: the method, e.g. ``'spectral summits (Nayak/McCool)'``) labels
        where the numbers come from.
        """
        label = f"{self.method} summits{' (Nayak/McCool)' if self.method == 'spectral' else ''}"
        return Surface(**{name: getattr(self, name) for name in GW_PARAMETERS}, area=area,
                       source=label if source is None else source)

    def to_dict(self) -> dict[str, Any]:
        """Plain ``float``/``int``/``str``/None dictionary, ready for strict JSON.

        Keys are the field names (``'sigma_s'``, ``'R'``, ``'eta'``, ...).
        """
        return {k: plain(v) for k, v in asdict(self).items()}


def plain(value):
    """``value`` as plain JSON data: NumPy scalars to int/float, tuples to lists, NaN/inf to None."""
    if isinstance(value, dict):
        return {k: plain(v) for k, v in value.items()}
    if isinstance(value, (tuple, list)):
        return [plain(v) for v in value]
    if isinstance(value, bool | np.bool_):
        return bool(value)
    if isinstance(value, int | np.integer):
        return int(value)
    if isinstance(value, float | np.floating):
        return float(value) if math.isfinite(value) else None
    return value


def prepare(topography):
    """Check a SurfaceTopography object; return it in metres with the mean plane removed.

    Parameters
    ----------
    topography : SurfaceTopography.Topography or SurfaceTopography.UniformLineScan
        Uniform grid with physical sizes and no undefined data; heights and sizes in
        ``topography.unit`` (taken as metres if None).

    Returns
    -------
    Topography or UniformLineScan
        In metres, mean plane (line) removed; a periodic surface only has its mean removed
        (removing a tilt would break its periodicity).

    Raises
    ------
    TypeError
        If ``topography`` is not a SurfaceTopography topography or line scan.
    ValueError
        For a nonuniform line scan, missing physical sizes, undefined data, fewer than
        :data:`MIN_POINTS` points along an axis, or a flat (or tilted-plane) surface
        whose detrended rms height is at most :data:`FLAT_RTOL` of its largest
        absolute height, or heights above :data:`MAX_HEIGHT` metres (a wrong unit).
    """
    if not all(hasattr(topography, attr) for attr in ("heights", "dim", "nb_grid_pts", "detrend")):
        raise TypeError(f"topography must be a SurfaceTopography topography or line scan, "
                        f"got {type(topography).__name__}")
    if not topography.is_uniform:
        raise ValueError("nonuniform line scan: resample it with topography.to_uniform(...) first")
    if topography.physical_sizes is None:
        raise ValueError("the topography has no physical size; read it with physical_sizes=...")
    if topography.has_undefined_data:
        raise ValueError("the topography has undefined data; fill it (interpolate_undefined_data) first")
    grid = tuple(int(n) for n in topography.nb_grid_pts)
    if min(grid) < MIN_POINTS:
        raise ValueError(f"too few points for summit statistics: grid {grid}; need at least {MIN_POINTS} "
                         f"along every axis")
    if topography.unit not in (None, "m"):
        topography = topography.to_unit("m")
    detrended = topography.detrend("center" if topography.is_periodic else "height")
    _check_not_flat(_heights(topography), _heights(detrended))
    return detrended


def _heights(topography) -> np.ndarray:
    return np.asarray(np.ma.getdata(topography.heights()), dtype=float)


def _check_not_flat(raw, detrended):
    """Refuse a surface whose detrended residual is rounding noise (see the module docstring)."""
    if not (np.all(np.isfinite(raw)) and np.all(np.isfinite(detrended))):
        raise ValueError("heights must be finite (no NaN or infinity)")
    scale = float(np.max(np.abs(raw)))
    if scale > MAX_HEIGHT:
        raise ValueError(f"heights up to {scale:.3g} m cannot be a surface's (at most {MAX_HEIGHT:g} m: the spectral "
                         f"moments would overflow); check the height unit")
    rms = scale * float(np.sqrt(np.mean((detrended / scale) ** 2))) if scale > 0 else 0.0
    if rms <= FLAT_RTOL * scale:
        raise ValueError(f"the surface is flat: after removing its mean plane the rms height is {rms:.3g} m, "
                         f"at most {FLAT_RTOL:g} of the largest absolute height {scale:.3g} m (rounding noise); "
                         f"a flat, tilted or constant surface has no summits")


def moments(topography):
    """Profile spectral moments :math:`(m_0, m_2, m_4)` and the x/y slope anisotropy.

    Parameters
    ----------
    topography : Topography or UniformLineScan
        Prepared by :func:`prepare` (metres, mean plane removed).

    Returns
    -------
    m0 : float
        :math:`\\langle h^2\\rangle` [m^2].
    m2 : float
        Mean square profile slope [-]: :math:`R_{\\Delta q}^2` for a line scan,
        :math:`\\langle|\\nabla h|^2\\rangle/2` for a map.
    m4 : float
        Mean square profile curvature [1/m^2]: :math:`R_{\\Delta\\Delta q}^2` for a line
        scan, :math:`\\tfrac38\\langle(\\nabla^2 h)^2\\rangle` for a map.
    anisotropy : float or None
        Larger over smaller mean square slope along x and y (None for a line scan or if a
        direction is flat).

    References
    ----------
    Nayak (1971), J. Lubr. Technol. 93, 398-407; Longuet-Higgins (1957), Phil. Trans.
    R. Soc. A 249, 321-387 (see :mod:`asperity.topography.spectral`).
    """
    if not all(hasattr(topography, attr) for attr in ("heights", "dim", "nb_grid_pts", "detrend")):
        raise TypeError(f"topography must be a SurfaceTopography topography or line scan (from prepare()), "
                        f"got {type(topography).__name__}")
    if topography.dim == 1:
        return (float(topography.Rq()) ** 2, float(topography.Rdq()) ** 2, float(topography.Rddq()) ** 2,
                None)
    m0 = float(topography.Sq()) ** 2
    m2 = float(topography.rms_gradient()) ** 2 / 2
    m4 = 1.5 * float(topography.rms_curvature_from_area()) ** 2
    return m0, m2, m4, _anisotropy(topography)


def _anisotropy(topography):
    """Larger over smaller mean square slope along x and y (upwind differences); None if flat."""
    h = _heights(topography)
    dx, dy = topography.pixel_size
    m2x = np.mean(np.diff(h, axis=0) ** 2) / dx**2
    m2y = np.mean(np.diff(h, axis=1) ** 2) / dy**2
    return float(max(m2x, m2y) / min(m2x, m2y)) if min(m2x, m2y) > 0 else None
