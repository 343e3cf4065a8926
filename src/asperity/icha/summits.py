r"""The summits of a height map, each with its own height, curvature and position.

The deterministic asperity models (:mod:`asperity.icha`) act on the summits of the
measured map itself, not on a distribution: every regional maximum of the map (8
neighbours; :func:`asperity.topography.detected.local_maxima_2d`: a plateau once, a shoulder
never, wrapping round a periodic map; a point flat both ways dropped) is one
paraboloidal cap of height :math:`z` above the mean plane.  Its two principal curvatures
:math:`\kappa_1, \kappa_2` come from central differences of :math:`h_{xx}, h_{yy}, h_{xy}`;
its radius is

* ``'geometric'`` (default): :math:`R = (\kappa_1\kappa_2)^{-1/2} = (h_{xx}h_{yy} - h_{xy}^2)^{-1/2}`,
  the radius of the sphere equivalent to the elliptical Hertz contact of the cap
  (Johnson 1985, §4.2: the contact area and approach of an elliptical contact follow
  those of a sphere of radius :math:`(R'R'')^{1/2}`, up to correction factors near 1 for
  moderate ellipticity, taken as 1 here); where the grid makes :math:`h_{xx}h_{yy} \le h_{xy}^2`
  (a local maximum of the grid that is not one of the smooth surface) the mean radius is used;
* ``'mean'``: :math:`R = 1/\bar\kappa`, :math:`\bar\kappa = -\tfrac12(h_{xx} + h_{yy})`, the
  estimate of Nayak's and McCool's theory (:func:`asperity.topography.detected.summit_curvatures`)
  and of the GW parameters of :mod:`asperity.topography`.

On a periodic map the neighbours wrap around, so every point can be a summit; on a free
map the border rows and columns are excluded.

References
----------
.. [1] J. A. Greenwood, J. B. P. Williamson, Proc. R. Soc. A 295 (1966) 300-319.
.. [2] P. R. Nayak, J. Lubr. Technol. 93 (1971) 398-407.
.. [3] L. Afferrante, G. Carbone, G. Demelio, Wear 278-279 (2012) 28-33 (summits of the
   numerical surface as the asperities).
.. [4] K. L. Johnson, *Contact Mechanics*, Cambridge University Press (1985), §4.2.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .._validation import as_float_array, check_scalar_positive
from ..topography.detected import local_maxima_2d

__all__ = ["MapSummits", "map_summits", "RADII"]

#: Radius of each summit: of the equivalent sphere (geometric mean of the principal radii) or
#: the reciprocal of the mean curvature.
RADII = ("geometric", "mean")


@dataclass(frozen=True)
class MapSummits:
    """Summits of one height map (arrays of one value per summit, SI units).

    Attributes
    ----------
    x, y : ndarray
        Positions [m], pixel ``(i, j)`` at ``(i dx, j dy)``.
    z : ndarray
        Heights above the mean plane of the map [m].
    R : ndarray
        Radii of curvature [m], > 0 (``radius`` of :func:`map_summits`).
    size : tuple of float
        Sides of the map :math:`L_x, L_y` [m].
    periodic : bool
        Whether the map repeats (neighbours and distances wrap around).
    curvature_ratio : ndarray or None
        Larger over smaller principal curvature of each summit, >= 1 (``inf`` where the
        smaller is not positive: a ridge or saddle-like grid maximum); None if not computed.
    """

    x: np.ndarray
    y: np.ndarray
    z: np.ndarray
    R: np.ndarray
    size: tuple[float, float]
    periodic: bool
    radius: str = "geometric"
    curvature_ratio: np.ndarray | None = None

    def __len__(self) -> int:
        return int(self.z.size)

    @property
    def nominal_area(self) -> float:
        """Area of the map :math:`A_0 = L_xL_y` [m^2]."""
        return self.size[0] * self.size[1]

    @property
    def density(self) -> float:
        """Summits per unit area [1/m^2]."""
        return len(self) / self.nominal_area


def map_summits(heights, pixel_size, *, periodic: bool, radius: str = "geometric") -> MapSummits:
    r"""Every summit of a height map, with its height, radius and position.

    .. math::
        R = (h_{xx}h_{yy} - h_{xy}^2)^{-1/2}\ (\text{geometric}),\qquad
        R = \Big[-\tfrac12(h_{xx} + h_{yy})\Big]^{-1}\ (\text{mean}),\qquad
        z = h - \langle h\rangle

    at the regional maxima of the map (:func:`~asperity.topography.detected.local_maxima_2d`).

    Parameters
    ----------
    heights : array_like
        Heights [m], shape ``(nx, ny)`` with nx, ny >= 3, finite; the mean is removed
        (remove a tilt before, for a free map).
    pixel_size : tuple of float
        Grid spacing :math:`(\Delta x, \Delta y)` [m], > 0.
    periodic : bool
        Wrap the neighbours around the edges (a periodic map); otherwise the border
        rows and columns hold no summit.
    radius : {'geometric', 'mean'}
        Radius of each cap (module docstring): of the sphere equivalent to its elliptical
        Hertz contact, or the reciprocal of its mean curvature.

    Returns
    -------
    MapSummits
        One entry per summit, in the row-major order of the map.

    Raises
    ------
    ValueError
        For a map that is not 2-d, too small, not finite, or without summits.

    Examples
    --------
    >>> h = -np.add.outer(np.arange(-3.0, 4.0) ** 2, np.arange(-3.0, 4.0) ** 2) / 2   # one paraboloid, R = 1
    >>> s = map_summits(h, (1.0, 1.0), periodic=False)
    >>> len(s), float(s.R[0]), float(s.x[0])
    (1, 1.0, 3.0)

    References
    ----------
    Greenwood & Williamson (1966); Nayak (1971); Afferrante, Carbone & Demelio (2012);
    Johnson (1985), §4.2.
    """
    h = as_float_array(heights, "heights")
    if h.ndim != 2 or min(h.shape) < 3:
        raise ValueError(f"heights must be a 2-d map with at least 3 points along each axis, got shape {h.shape}")
    if not isinstance(periodic, bool | np.bool_):
        raise TypeError(f"periodic must be True or False, got {periodic!r}")
    if not isinstance(radius, str):
        raise TypeError(f"radius must be one of {RADII} (a string), got {type(radius).__name__}")
    if radius not in RADII:
        raise ValueError(f"radius must be one of {RADII}, got {radius!r}")
    if isinstance(pixel_size, str | bytes) or not hasattr(pixel_size, "__len__") or len(pixel_size) != 2:
        raise TypeError(f"pixel_size must be a pair of spacings (dx, dy) in m, got {pixel_size!r}")
    dx, dy = (check_scalar_positive(p, "pixel_size", "m") for p in pixel_size)
    h = h - h.mean()
    nx, ny = h.shape
    padded = np.pad(h, 1, mode="wrap")   # for the curvature stencils; a free map's border holds no summit
    peak = local_maxima_2d(h, periodic=True) if periodic else local_maxima_2d(h)
    i, j = np.nonzero(peak)
    if not periodic:
        i, j = i + 1, j + 1
    if i.size == 0:
        raise ValueError("the map has no summit (no local maximum)")
    hxx, hyy, hxy = _second_derivatives(padded, i + 1, j + 1, dx, dy)
    mean = -(hxx + hyy) / 2                       # > 0 at a strict grid maximum
    cap = mean > 0  # a plateau's point can be flat both ways (one wrapping round a periodic map)
    if not np.all(cap):
        i, j, hxx, hyy, hxy, mean = i[cap], j[cap], hxx[cap], hyy[cap], hxy[cap], mean[cap]
        if i.size == 0:
            raise ValueError("the map has no summit with a positive curvature (only flat plateaus)")
    gauss = hxx * hyy - hxy * hxy
    if radius == "mean":
        R = 1.0 / mean
    else:
        R = np.where(gauss > 0, 1.0 / np.sqrt(np.where(gauss > 0, gauss, 1.0)), 1.0 / mean)
    half_gap = np.sqrt(((hxx - hyy) / 2) ** 2 + hxy**2)  # principal curvatures: mean +- half_gap
    low = mean - half_gap
    ratio = np.where(low > 0, (mean + half_gap) / np.where(low > 0, low, 1.0), np.inf)
    return MapSummits(x=i * dx, y=j * dy, z=h[i, j], R=R, size=(nx * dx, ny * dy), periodic=bool(periodic),
                      radius=radius, curvature_ratio=ratio)


def _second_derivatives(padded, i, j, dx, dy):
    """Central differences h_xx, h_yy, h_xy of the padded map at (i, j)."""
    c = padded[i, j]
    hxx = (padded[i + 1, j] - 2 * c + padded[i - 1, j]) / dx**2
    hyy = (padded[i, j + 1] - 2 * c + padded[i, j - 1]) / dy**2
    hxy = (padded[i + 1, j + 1] - padded[i + 1, j - 1] - padded[i - 1, j + 1] + padded[i - 1, j - 1]) / (4 * dx * dy)
    return hxx, hyy, hxy
