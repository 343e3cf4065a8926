r"""GW summit parameters from the summits found on the measured grid.

Instead of relying on a random-process model (:mod:`asperity.topography.spectral`), this
module finds the summits (local maxima) of the detrended height map and measures them:
their number per area gives :math:`\eta`, the mean of their curvatures gives
:math:`R = 1/\bar\kappa`, the spread of their heights :math:`\sigma_s`.  The detected
summit heights are the natural input of empirical height distributions.

===============================  ============================================================
function                         what it finds
===============================  ============================================================
:func:`local_maxima_2d`          interior regional maxima of a map (8 neighbours; a plateau once)
:func:`local_maxima_1d`          interior regional maxima of a profile (a plateau once)
:func:`summit_curvatures`        mean curvature :math:`-(h_{xx}+h_{yy})/2` at the maxima of a map
:func:`detected_summits`         the GW parameters from the maxima (maps and line scans)
:func:`detected_summit_heights`  the heights of those maxima (for height distributions)
===============================  ============================================================

A line scan's peaks are converted to the summits of the isotropic Gaussian surface it is
taken from (Nayak 1971; McCool 1986; Rice 1944): see :func:`detected_summits`.

References
----------
.. [1] Greenwood, J. A., Williamson, J. B. P. (1966). Proc. R. Soc. Lond. A 295, 300-319.
.. [2] Nayak, P. R. (1971). J. Lubr. Technol. (ASME) 93, 398-407.
.. [3] McCool, J. I. (1986). Wear 107, 37-60.
.. [4] Rice, S. O. (1944). Bell Syst. Tech. J. 23, 282-332.
"""

from __future__ import annotations

import math

import numpy as np

from .._validation import as_float_array, check_finite_result, check_scalar_positive
from .spectral import NAYAK_SIGMA_S, RICE_SIGMA_P, bandwidth_alpha, summit_sigma
from .summits import SummitParameters, moments, prepare

__all__ = ["local_maxima_2d", "local_maxima_1d", "summit_curvatures", "detected_summits", "detected_summit_heights",
           "PEAK_TO_SUMMIT_MEAN"]


def _grid(h, ndim: int, name: str = "h") -> np.ndarray:
    h = as_float_array(h, name)
    if h.ndim != ndim or min(h.shape) < 3:
        raise ValueError(f"{name} must be a {ndim}-d array with at least 3 points along each axis, "
                         f"got shape {h.shape}")
    return h


def local_maxima_2d(h, periodic: bool = False) -> np.ndarray:
    r"""Regional maxima of a height map (8 neighbours), a plateau counted once.

    A point is a summit if no neighbour is higher and none is equal (a strict maximum),
    or, for a plateau (a connected set of equal heights, 8-connected), once at its first
    point in row order if no point next to it is higher (and, on a free map, it does not
    reach the border; a constant periodic map has none).  A shoulder (a plateau next to a
    higher point) is no summit.  On a free map the border rows and columns are never
    summits; a periodic map wraps round.

    .. math::

        h_{i,j} > h_{i+k,\,j+l}\ \text{for all}\ (k,l)\ne(0,0),\ |k|,|l|\le1,
        \quad\text{or a plateau } P \text{ with } h_P > h \text{ on every point next to } P

    Parameters
    ----------
    h : array_like
        Heights, shape ``(nx, ny)`` with nx, ny >= 3, finite.
    periodic : bool
        Whether the map repeats (neighbours and plateaus wrap round its edges).

    Returns
    -------
    ndarray of bool
        Shape ``(nx-2, ny-2)``: True at the interior summits; periodic: ``(nx, ny)``.

    Notes
    -----
    Quantized scans (heights in steps of the instrument's resolution) hold many plateaus:
    a rule that compared each point with its neighbours alone counted an L-shaped plateau
    twice and every shoulder (found by a review: 2517 summits where a Gaussian map rounded to
    1 nm steps has 586 regional maxima).
    """
    h = _grid(h, 2)
    if not isinstance(periodic, bool | np.bool_):
        raise TypeError(f"periodic must be True or False, got {periodic!r}")
    return _regional_maxima(h, [(1, -1), (1, 0), (1, 1), (0, 1)], bool(periodic))


def local_maxima_1d(h) -> np.ndarray:
    r"""Interior regional maxima of a profile, a plateau counted once (at its first point).

    .. math:: h_{i-1} < h_i > h_{i+1},\quad\text{or a run of equal heights higher than both
        points next to it}

    Parameters
    ----------
    h : array_like
        Heights, shape ``(n,)`` with n >= 3, finite.

    Returns
    -------
    ndarray of bool
        Shape ``(n-2,)``: True at the interior peaks.
    """
    h = _grid(h, 1)
    return _regional_maxima(h, [(1,)], False)


def _regional_maxima(h, forward, periodic: bool) -> np.ndarray:
    """The regional maxima of ``h`` (1-D or 2-D; ``forward``: half the neighbour offsets, the
    others their negatives): in its interior, or everywhere on a periodic map.  Candidates have
    no higher neighbour; two adjacent candidates are equal, so the candidates with an equal
    neighbour group into plateaus by connectivity alone (joined across the edges of a periodic
    map); a plateau that has an equal neighbour outside the candidates (a point next to a
    higher one, or the border of a free map) is dropped.  Only the comparisons for "higher"
    touch the whole map; the rest works on the candidates' indices."""
    from scipy import ndimage, sparse
    from scipy.sparse import csgraph

    offsets = [o for f in forward for o in (f, tuple(-k for k in f))]
    hp = np.pad(h, 1, mode="wrap") if periodic else h
    inner = tuple(slice(1, n - 1) for n in hp.shape)
    c = hp[inner]
    higher = np.zeros(c.shape, dtype=bool)
    for o in offsets:
        higher |= hp[tuple(slice(1 + k, n - 1 + k) for k, n in zip(o, hp.shape, strict=True))] > c
    candidate = ~higher
    if periodic and not np.any(h != h.flat[0]):
        return np.zeros(c.shape, dtype=bool)  # a constant periodic map: one plateau, no lower point
    points = np.flatnonzero(candidate)
    at = np.unravel_index(points, c.shape)
    values = c.ravel()[points]

    def neighbours(o):
        """Flat indices in ``c`` of the candidates' neighbours at offset ``o`` (-1: off a free map)."""
        moved = [a + k for a, k in zip(at, o, strict=True)]
        if periodic:
            return np.ravel_multi_index(moved, c.shape, mode="wrap")
        inside = np.all([(m >= 0) & (m < n) for m, n in zip(moved, c.shape, strict=True)], axis=0)
        flat = np.ravel_multi_index([np.clip(m, 0, n - 1) for m, n in zip(moved, c.shape, strict=True)], c.shape)
        return np.where(inside, flat, -1)

    def neighbour_values(o):
        return hp[tuple(a + 1 + k for a, k in zip(at, o, strict=True))]

    equal = np.zeros(points.size, dtype=bool)
    spoiled = np.zeros(points.size, dtype=bool)
    flat_candidate = candidate.ravel()
    nbrs = {}
    for o in offsets:
        same = neighbour_values(o) == values
        nbrs[o] = neighbours(o)
        equal |= same
        spoiled |= same & ((nbrs[o] < 0) | ~flat_candidate[np.maximum(nbrs[o], 0)])
    if not equal.any():
        return candidate
    plateau = np.zeros(c.size, dtype=bool)
    plateau[points[equal]] = True
    labels, count = ndimage.label(plateau.reshape(c.shape), structure=np.ones((3,) * h.ndim, dtype=bool))
    labels = labels.ravel()
    component = np.arange(count + 1)
    if periodic:  # plateaus that meet across an edge are one
        a = np.concatenate([labels[points[equal]] for _ in offsets])
        b = np.concatenate([labels[nbrs[o][equal]] for o in offsets])
        join = (b > 0) & (a != b)
        graph = sparse.coo_matrix((np.ones(join.sum()), (a[join], b[join])), shape=(count + 1, count + 1))
        component = csgraph.connected_components(graph, directed=False)[1]
    bad = np.zeros(component.max() + 1, dtype=bool)
    bad[component[labels[points[equal & spoiled]]]] = True
    members = points[equal]  # in increasing flat order: each component's first is its first in row order
    ids, first = np.unique(component[labels[members]], return_index=True)
    out = candidate.ravel().copy()
    out[members] = False
    out[members[first[~bad[ids]]]] = True
    return out.reshape(c.shape)


def summit_curvatures(h, peak, dx, dy) -> np.ndarray:
    r"""Mean curvature of a map at its summits, by central differences.

    .. math::

        \kappa = -\tfrac12\,(h_{xx} + h_{yy}),\qquad
        h_{xx} \approx \frac{h_{i+1,j} - 2h_{i,j} + h_{i-1,j}}{\Delta x^2},\quad
        h_{yy} \approx \frac{h_{i,j+1} - 2h_{i,j} + h_{i,j-1}}{\Delta y^2}

    Parameters
    ----------
    h : array_like
        Heights [m], shape ``(nx, ny)``.
    peak : array_like of bool
        Summit mask of shape ``(nx-2, ny-2)``, as from :func:`local_maxima_2d`.
    dx, dy : float
        Grid spacing along x and y [m], > 0.

    Returns
    -------
    ndarray
        Curvatures [1/m] of the summits, in the order of ``h[1:-1, 1:-1][peak]``
        (positive for a cap).
    """
    h = _grid(h, 2)
    if not (isinstance(peak, np.ndarray) and peak.dtype == bool):
        raise TypeError(f"peak must be a boolean array (local_maxima_2d(h)), got {type(peak).__name__}")
    if peak.shape != (h.shape[0] - 2, h.shape[1] - 2):
        raise ValueError(f"peak must have shape {(h.shape[0] - 2, h.shape[1] - 2)}, got {peak.shape}")
    dx, dy = np.float64(check_scalar_positive(dx, "dx")), np.float64(check_scalar_positive(dy, "dy"))
    c = h[1:-1, 1:-1]
    with np.errstate(all="ignore"):
        hxx = (h[2:, 1:-1] - 2 * c + h[:-2, 1:-1]) / dx**2
        hyy = (h[1:-1, 2:] - 2 * c + h[1:-1, :-2]) / dy**2
        curvature = -(hxx + hyy)[peak] / 2
    return check_finite_result(curvature, "the summit curvature", dx=dx, dy=dy)


def detected_summits(topography) -> SummitParameters:
    r"""GW summit parameters from the summits found on the grid.

    After removing the mean plane (line):

    * **map** -- summits are the interior regional maxima (:func:`local_maxima_2d`: 8
      neighbours, a plateau once, a shoulder never; border rows and columns excluded).  The
      summit curvature is the mean of the two principal curvatures, :math:`\kappa = -(h_{xx}+h_{yy})/2`, from central
      differences; :math:`R = 1/\bar\kappa`, :math:`\sigma_s` is the standard deviation
      of the summit heights and :math:`\eta` the number of summits divided by the
      interior area :math:`(n_x-2)(n_y-2)\Delta x\Delta y`.
    * **line scan** -- profile peaks are the interior regional maxima (:func:`local_maxima_1d`),
      with peak density
      :math:`D_p` (per length), mean peak curvature :math:`\bar\kappa_p = -\overline{h''}`
      and peak-height deviation :math:`\sigma_p`.  They are converted to summit values
      of the isotropic Gaussian surface the profile is taken from, using its profile
      moments (Nayak 1971; McCool 1986; Rice 1944):
      :math:`D_p = \sqrt{m_4/m_2}/2\pi` and :math:`\eta = m_4/(6\pi\sqrt3 m_2)` give
      :math:`\eta = \tfrac{2\pi}{3\sqrt3} D_p^2`;
      :math:`\bar\kappa_p = \sqrt{\pi m_4/2}` and :math:`\bar\kappa_s = \tfrac83\sqrt{m_4/\pi}`
      give :math:`R = 3\pi/(8\sqrt2\,\bar\kappa_p)`;
      :math:`\sigma_p^2 = m_0(1 - (\pi/2-1)/\alpha_N)` and
      :math:`\sigma_s^2 = m_0(1 - 0.8968/\alpha_N)` give
      :math:`\sigma_s = \sigma_p\,[(1-0.8968/\alpha_N)/(1-(\pi/2-1)/\alpha_N)]^{1/2}`,
      with :math:`\alpha_N` from the profile's moments; the mean peak height times
      :data:`PEAK_TO_SUMMIT_MEAN` (Nayak's :math:`4\sigma/\sqrt{\pi\alpha_N}` over Rice's
      :math:`\sigma\sqrt{\pi/2\alpha_N}`) gives the mean summit height.

    .. math::

        \text{map:}\quad \eta = \frac{n_s}{(n_x-2)(n_y-2)\Delta x\Delta y},\quad
        R = \frac{1}{\bar\kappa},\quad \sigma_s = \mathrm{std}(z_s);\qquad
        \text{profile:}\quad \eta = \frac{2\pi}{3\sqrt3}D_p^2,\quad
        R = \frac{3\pi}{8\sqrt2\,\bar\kappa_p}

    :math:`R` is the reciprocal of the *mean curvature*, not the mean of the radii:
    this is the quantity of Nayak's and McCool's theory (so both methods estimate the
    same thing), and it is robust, whereas nearly flat summits give arbitrarily large
    radii that dominate a mean of radii.

    Parameters
    ----------
    topography : SurfaceTopography.Topography or SurfaceTopography.UniformLineScan
        Uniform grid, heights and sizes in ``topography.unit`` (taken as metres if None).

    Returns
    -------
    SummitParameters
        ``method='detected'``; ``n_summits`` counts summits (map) or profile peaks.

    Raises
    ------
    TypeError
        If ``topography`` is not a SurfaceTopography object.
    ValueError
        For a surface :func:`~asperity.topography.summits.prepare` refuses (too few points,
        flat or tilted plane, undefined data), or if no summit with positive mean
        curvature is found.

    References
    ----------
    Greenwood & Williamson (1966), Proc. R. Soc. A 295, 300-319.
    Nayak (1971), J. Lubr. Technol. 93, 398-407.
    McCool (1986), Wear 107, 37-60.
    Rice, S. O. (1944), Mathematical analysis of random noise, Bell Syst. Tech. J. 23, 282-332.
    """
    topo = prepare(topography)
    h = np.asarray(np.ma.getdata(topo.heights()), dtype=float)
    if topo.dim == 2:
        return _detected_map(h, topo.pixel_size)
    return _detected_profile(topo, h)


def detected_summit_heights(topography) -> np.ndarray:
    r"""Heights of the summits (map) or peaks (line scan) that :func:`detected_summits` measures.

    After removing the mean plane (line), the interior local maxima of
    :func:`local_maxima_2d` (maps) or :func:`local_maxima_1d` (line scans); their spread is
    the detected :math:`\sigma_s` of a map, their shape the input of
    :func:`asperity.heights.fit_heights` and :class:`asperity.heights.Empirical`.  The heights
    of a line scan's peaks are not those of the surface's summits (they are lower and less
    skewed): use a map where possible.

    .. math:: z_s = h_{i,j}\ \text{at the local maxima of the detrended heights}

    Parameters
    ----------
    topography : SurfaceTopography.Topography or SurfaceTopography.UniformLineScan
        Uniform grid, heights in ``topography.unit`` (taken as metres if None).

    Returns
    -------
    ndarray
        1-D, heights above the mean plane in the topography's unit.

    Raises
    ------
    TypeError
        If ``topography`` is not a SurfaceTopography object.
    ValueError
        For a surface :func:`~asperity.topography.summits.prepare` refuses.

    References
    ----------
    Greenwood & Williamson (1966); Nayak (1971) (peak and summit height distributions).
    """
    topo = prepare(topography)
    h = np.asarray(np.ma.getdata(topo.heights()), dtype=float)
    if topo.dim == 2:
        return h[1:-1, 1:-1][local_maxima_2d(h)]
    return h[1:-1][local_maxima_1d(h)]


#: Mean summit height over mean peak height of a Gaussian surface, :math:`4\sqrt2/\pi`: Nayak's
#: (1971) :math:`4\sigma/\sqrt{\pi\alpha}` over Rice's :math:`\sigma\sqrt{\pi/2\alpha}` (a line scan's
#: peaks stand lower than the surface's summits; a review found the peaks' mean reported as the
#: summits' beside summit values of sigma_s, R and eta).
PEAK_TO_SUMMIT_MEAN = 4.0 * math.sqrt(2.0) / math.pi


def _mean_curvature(kappa) -> float:
    if kappa.size == 0:
        raise ValueError("no summits found on the surface")
    mean = float(np.mean(kappa))
    if not mean > 0:
        raise ValueError("the detected summits have no positive mean curvature")
    return mean


def _detected_map(h, pixel_size) -> SummitParameters:
    dx, dy = (float(p) for p in pixel_size)
    peak = local_maxima_2d(h)
    mean_kappa = _mean_curvature(summit_curvatures(h, peak, dx, dy))
    z = h[1:-1, 1:-1][peak]
    area = (h.shape[0] - 2) * (h.shape[1] - 2) * dx * dy
    return SummitParameters(
        sigma_s=float(np.std(z)), R=1.0 / mean_kappa, eta=z.size / area,
        method="detected", sigma=float(np.std(h)), mean_summit_height=float(np.mean(z)),
        n_summits=int(z.size), source="map")


def _detected_profile(topo, h) -> SummitParameters:
    dx = float(topo.pixel_size[0])
    peak = local_maxima_1d(h)
    mean_kappa = _mean_curvature(-(h[2:] - 2 * h[1:-1] + h[:-2])[peak] / dx**2)
    z = h[1:-1][peak]
    peak_density = z.size / ((h.size - 2) * dx)
    m0, m2, m4, _ = moments(topo)
    alpha_n = bandwidth_alpha(m0, m2, m4)
    ratio = summit_sigma(1.0, alpha_n, NAYAK_SIGMA_S) / summit_sigma(1.0, alpha_n, RICE_SIGMA_P)
    return SummitParameters(
        sigma_s=float(np.std(z)) * ratio, R=3 * math.pi / (8 * math.sqrt(2) * mean_kappa),
        eta=2 * math.pi / (3 * math.sqrt(3)) * peak_density**2,
        method="detected", sigma=float(np.std(h)), mean_summit_height=float(np.mean(z)) * PEAK_TO_SUMMIT_MEAN,
        m0=m0, m2=m2, m4=m4, alpha_n=alpha_n, n_summits=int(z.size), source="line scan")
