r"""Full elastic boundary-element contact of a rough surface and a rigid flat (ContactMechanics).

The rigid rough surface :math:`h(x, y)` (a SurfaceTopography topography in metres, mean
plane removed) is pressed with a total force :math:`P` onto an elastic half-space of
contact modulus :math:`E^*` (for two elastic bodies, the composite modulus of
:func:`asperity.materials.pair`).  On the grid, with pixel forces :math:`f_i \ge 0`,
surface displacements :math:`u = G * f` and gap :math:`g = u - h - \delta`,

.. math::
    g_i \ge 0,\qquad f_i \ge 0,\qquad f_i\,g_i = 0,\qquad \sum_i f_i = P ,

the hard-wall (non-adhesive, frictionless) contact problem, solved by the constrained
conjugate gradients of Polonsky & Keer (1999) as implemented by ContactMechanics.  The
Green's function :math:`G` is the periodic one of Stanley & Kato (1997) for a periodic
topography (the cell repeats; the mean displacement is a free rigid shift) and the free
one of Johnson (1985, §3.2) with Hockney's doubling of the grid for a non-periodic
topography (an isolated square of roughness on an infinite half-space).

Reported per load: the real contact area (contact pixels times pixel area), the mean gap
:math:`\langle g\rangle` between the flat and the deformed surface, the number of contact
spots (:mod:`~asperity.validation.spots`), the approach :math:`-\delta`, the distance of
the flat from the undeformed mean plane (non-periodic only: in a periodic cell it is a
gauge), and the iterations.  Successive loads start from the previous displacements.

Pixel-counted areas are biased upward: a pixel whose centre touches counts whole, so the
error scales with the spots' perimeter and falls as the grid is refined
(Yastrebov, Anciaux & Molinari 2017); compare two grids.

References
----------
.. [1] I. A. Polonsky, L. M. Keer, Wear 231 (1999) 206-219.
.. [2] H. M. Stanley, T. Kato, J. Tribol. 119 (1997) 481-485.
.. [3] K. L. Johnson, *Contact Mechanics*, Cambridge University Press (1985), §3.2.
.. [4] R. W. Hockney, Methods Comput. Phys. 9 (1970) 135-211.
.. [5] V. A. Yastrebov, G. Anciaux, J.-F. Molinari, Tribol. Int. 114 (2017) 161-171.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np

from .._csv import columns_to_csv, columns_to_dataframe
from .._optional import require
from .._validation import as_float_array, check_bool, check_mean_pressure, check_scalar_positive, check_scalar_real
from .progress import progress_bar
from .spots import count_spots

__all__ = ["BemCurve", "bem_contact", "check_loads", "check_solver_options",
           "subsample", "with_periodicity", "MIN_GRID", "MAX_LOADS",
           "DEFAULT_TOLERANCE", "P_BAR_RANGE"]

#: Fewest grid points along each axis for a boundary-element solve (after ``grid``).
MIN_GRID = 16
#: Most loads in one run (each is a full solve).
MAX_LOADS = 1000
#: Convergence tolerance: largest penetration, in units of the rms height, and largest
#: tensile pixel force, in units of the mean pixel force.
DEFAULT_TOLERANCE = 1e-4


def _contact_mechanics():
    return require("ContactMechanics", purpose="boundary-element contact", extra="bem")


@dataclass(frozen=True)
class BemCurve:
    """Boundary-element results against load, SI units (one value per load).

    Attributes
    ----------
    P : ndarray
        Total normal force [N].
    area : ndarray
        Real contact area, contact pixels times pixel area [m^2].
    mean_gap : ndarray
        Mean gap between the flat and the deformed surface [m].
    separation : ndarray
        Distance of the flat from the undeformed mean plane [m] (NaN for a periodic cell).
    spots : ndarray of int
        Number of contact spots.
    iterations : ndarray of int
        Conjugate-gradient iterations.
    seconds : ndarray
        Wall time of each solve [s].
    nominal_area : float
        Scanned area :math:`A_0` [m^2].
    periodic : bool
        Periodic (True) or free (False) boundaries.
    nb_grid_pts : tuple of int
        Grid of the solve.
    E_star : float
        Contact modulus [Pa].
    """

    P: np.ndarray
    area: np.ndarray
    mean_gap: np.ndarray
    separation: np.ndarray
    spots: np.ndarray
    iterations: np.ndarray
    seconds: np.ndarray
    nominal_area: float
    periodic: bool
    nb_grid_pts: tuple[int, ...]
    E_star: float
    parameters: dict = field(default_factory=dict, compare=False)

    def __len__(self) -> int:
        return int(np.size(self.P))

    @property
    def area_fraction(self) -> np.ndarray:
        """Real over nominal area."""
        return self.area / self.nominal_area

    def columns(self) -> dict[str, np.ndarray]:
        """Column name (SI suffix) -> array."""
        return {"P_N": self.P, "area_m2": self.area, "fraction": self.area_fraction, "gap_m": self.mean_gap,
                "sep_m": self.separation, "spots": self.spots, "iterations": self.iterations,
                "seconds": self.seconds}

    def to_csv(self, path_or_buffer=None) -> str | None:
        """Write the columns as CSV; return the text if no path is given."""
        return columns_to_csv(self.columns(), path_or_buffer)

    def to_dataframe(self):
        """The columns as a pandas DataFrame (needs pandas)."""
        return columns_to_dataframe(self.columns(), self.parameters)


def with_periodicity(topography, periodic):
    """The map with the boundaries asked for: itself if ``periodic`` is None or already its own,
    else the same heights and sizes as a periodic (or free) map.

    The periodicity decides how the map is levelled (its mean removed if periodic, a fitted
    plane if free), how summits are found at its edges and which Green's function is used: a
    user trial found ``asperity bem FILE --periodic`` solving a periodic cell on a map levelled
    as a free one (a fitted plane on a cosine left a step at the seam: the light-load area of
    Westergaard's wave came out 39 % low).

    Parameters
    ----------
    topography : SurfaceTopography.Topography
        A 2-d map.
    periodic : bool or None
        The boundaries wanted (None: as the map says).

    Returns
    -------
    SurfaceTopography.Topography

    Raises
    ------
    ValueError
        If ``periodic`` is not True, False or None.
    """
    if periodic is None:
        return topography
    periodic = check_bool(periodic, "periodic")
    if bool(topography.is_periodic) == periodic or topography.dim != 2 or topography.has_undefined_data:
        return topography  # (undefined data: left for the caller's refusal, not rebuilt without its mask)
    st = require("SurfaceTopography", purpose="boundary-element contact", extra="topography")
    return st.Topography(np.asarray(topography.heights(), dtype=float), tuple(topography.physical_sizes),
                         periodic=periodic, unit=topography.unit)


def subsample(topography, grid):
    """The topography averaged over square blocks so that no axis has more than ``grid`` points.

    Parameters
    ----------
    topography : SurfaceTopography.Topography
        A 2-d map in metres.
    grid : int or None
        Largest number of points along an axis, >= :data:`MIN_GRID`; None keeps the grid.

    Returns
    -------
    SurfaceTopography.Topography
        The same topography if it already fits; otherwise heights averaged over
        :math:`f\\times f` blocks, :math:`f = \\lceil n_{max}/\\mathrm{grid}\\rceil`, the
        rows and columns beyond a whole number of blocks dropped (the physical size
        shrinks with them, and a periodic map stays periodic only if nothing was dropped).

    Raises
    ------
    ValueError
        If ``grid`` is not an integer >= :data:`MIN_GRID`.
    """
    if grid is None:
        return topography
    if isinstance(grid, bool) or not isinstance(grid, int | np.integer) or grid < MIN_GRID:
        raise ValueError(f"grid must be an integer >= {MIN_GRID} (points along the longer axis), got {grid!r}")
    nx, ny = (int(n) for n in topography.nb_grid_pts)
    f = math.ceil(max(nx, ny) / int(grid))
    if f <= 1:
        return topography
    mx, my = nx // f, ny // f
    if min(mx, my) < MIN_GRID:
        raise ValueError(f"grid={grid} leaves {mx} x {my} points after averaging {f} x {f} blocks of the "
                         f"{nx} x {ny} scan; need at least {MIN_GRID} along each axis")
    h = np.asarray(topography.heights(), dtype=float)[:mx * f, :my * f]
    blocks = h.reshape(mx, f, my, f).mean(axis=(1, 3))
    sx, sy = topography.physical_sizes
    periodic = bool(topography.is_periodic and mx * f == nx and my * f == ny)
    st = require("SurfaceTopography", purpose="boundary-element contact", extra="topography")
    return st.Topography(blocks, (sx * mx * f / nx, sy * my * f / ny), periodic=periodic, unit="m")


#: Range of the mean pressure over the contact modulus, :math:`P/(E^*A_0)`, solved: above 1 the
#: strains are of order one (linear elasticity has long failed, and the map is in full contact);
#: below 1e-15 the solver's tolerances, relative to the load, reach the rounding of the heights.
P_BAR_RANGE = (1e-15, 1.0)


def check_loads(P) -> np.ndarray:
    """The loads of a boundary-element run: 1-D, 1 to :data:`MAX_LOADS` of them, each > 0 N (ValueError naming P)."""
    P = as_float_array(P, "P (load)")
    if P.ndim > 1:  # a review: [[1e-6]] was flattened without a word
        raise ValueError(f"P (load) must be one load or a 1-D list of loads, got an array of shape {P.shape}")
    P = P.ravel()
    if P.size == 0 or P.size > MAX_LOADS:
        raise ValueError(f"P (load) must hold 1 to {MAX_LOADS} loads, got {P.size}")
    if np.any(P <= 0):
        raise ValueError(f"P (load) must be > 0 N (hard-wall contact without adhesion), got min {P.min():g}")
    return P


def check_solver_options(tolerance, maxiter) -> float:
    """The solver's ``tolerance`` as a float, 0 < tolerance <= 0.1, and ``maxiter`` a positive
    integer; a ValueError naming the one that is not."""
    tolerance = check_scalar_real(tolerance, "tolerance")
    if not 0.0 < tolerance <= 0.1:
        raise ValueError(f"tolerance must lie in (0, 0.1], got {tolerance!r}")
    if isinstance(maxiter, bool) or not isinstance(maxiter, int | np.integer) or maxiter < 1:
        raise ValueError(f"maxiter must be a positive integer, got {maxiter!r}")
    return tolerance


def bem_contact(topography, P, *, E_star, periodic=None, grid=None, tolerance=DEFAULT_TOLERANCE,
                maxiter=10000, progress=False) -> BemCurve:
    r"""Boundary-element contact of a rigid rough surface on an elastic half-space, versus load.

    .. math::
        g = G * f - h - \delta \ge 0,\quad f \ge 0,\quad fg = 0,\quad \sum f = P

    solved at each load by constrained conjugate gradients (Polonsky & Keer 1999,
    ContactMechanics), warm-started from the previous load's displacements.

    Parameters
    ----------
    topography : SurfaceTopography.Topography
        A 2-d map in metres (``unit`` 'm' or None) without undefined data; its mean plane
        is removed (its mean only, if periodic).
    P : array_like
        Total normal forces [N] on the scanned area, > 0, 1 to :data:`MAX_LOADS` values, with
        mean pressures :math:`P/A_0` between 1e-15 and 1 times :math:`E^*`
        (:data:`P_BAR_RANGE`); solved in increasing order and reported in the order given.
    E_star : float
        Contact modulus :math:`E^*` [Pa], > 0.
    periodic : bool, optional
        Periodic (True) or free (False) boundaries; default: the topography's ``is_periodic``.
    grid : int, optional
        Average the map over blocks to at most ``grid`` points per axis first
        (:func:`subsample`).
    tolerance : float
        Largest penetration over the rms height and largest tensile pixel force over the
        mean pixel force at convergence, in (0, 0.1]; default :data:`DEFAULT_TOLERANCE`.
    maxiter : int
        Most iterations per load, >= 1.
    progress : bool
        Report progress over the loads on standard error (tqdm if installed).

    Returns
    -------
    BemCurve
        One value per load.

    Raises
    ------
    TypeError
        If ``topography`` is not a SurfaceTopography map.
    ValueError
        For bad loads, modulus, grid or tolerance, a line scan, undefined data, fewer than
        :data:`MIN_GRID` points per axis, or a solve that does not converge.
    asperity._optional.MissingDependency
        Without ContactMechanics (``pip install 'asperity[bem]'``).

    References
    ----------
    Polonsky & Keer, Wear 231 (1999) 206; Stanley & Kato, J. Tribol. 119 (1997) 481;
    Johnson (1985), §3.2; Hockney (1970).
    """
    P = check_loads(P)
    E_star = check_scalar_positive(E_star, "E_star", "Pa")
    progress = check_bool(progress, "progress")
    tolerance = check_solver_options(tolerance, maxiter)
    topo = _prepare(topography, grid, periodic)
    periodic = bool(topo.is_periodic) if periodic is None else check_bool(periodic, "periodic")
    cm = _contact_mechanics()
    systems = require("ContactMechanics.Systems", purpose="boundary-element contact", extra="bem")
    nb = tuple(int(n) for n in topo.nb_grid_pts)
    sizes = tuple(float(s) for s in topo.physical_sizes)
    check_mean_pressure(P, E_star, sizes[0] * sizes[1], P_BAR_RANGE)
    half_space = (cm.PeriodicFFTElasticHalfSpace if periodic else cm.FreeFFTElasticHalfSpace)(nb, E_star, sizes)
    system = systems.NonSmoothContactSystem(half_space, topo)
    h = np.asarray(topo.heights(), dtype=float)
    rms = float(np.sqrt(np.mean(h**2)))
    order = np.argsort(P, kind="stable")
    out = {k: np.empty(P.size) for k in ("area", "gap", "sep", "spots", "it", "sec")}
    disp = None
    pixel = sizes[0] * sizes[1] / (nb[0] * nb[1])
    for j, i in zip(order, progress_bar([float(P[k]) for k in order], enabled=progress), strict=True):
        start = time.perf_counter()
        res = system.minimize_proxy(external_force=i, initial_displacements=disp, pentol=tolerance * rms,
                                    forcetol=tolerance * i / h.size, maxiter=int(maxiter))
        out["sec"][j] = time.perf_counter() - start
        if not res.success:
            raise ValueError(f"the boundary-element solve did not converge at P = {i:.6g} N within {maxiter} "
                             f"iterations ({res.message}); raise maxiter or tolerance, or use a coarser grid (command "
                             "line: --maxiter, --tolerance, --grid)")
        disp = res.x
        forces = np.asarray(res.jac)
        contact = forces > 0
        gap = np.asarray(res.x)[:nb[0], :nb[1]] - h - res.offset
        out["area"][j] = contact.sum() * pixel
        out["gap"][j] = float(np.mean(gap))
        out["sep"][j] = math.nan if periodic else -float(res.offset) - float(np.mean(h))
        out["spots"][j] = count_spots(contact, periodic=periodic)
        out["it"][j] = res.nit
    return BemCurve(P=P, area=out["area"], mean_gap=out["gap"], separation=out["sep"],
                    spots=out["spots"].astype(int), iterations=out["it"].astype(int), seconds=out["sec"],
                    nominal_area=sizes[0] * sizes[1], periodic=periodic, nb_grid_pts=nb, E_star=E_star,
                    parameters={"E_star_Pa": E_star, "periodic": periodic, "nb_grid_pts": nb,
                                "physical_sizes_m": sizes, "tolerance": tolerance})


def _prepare(topography, grid, periodic=None):
    """Check the map, put it in metres, subsample it, give it the boundaries asked for
    (after the subsampling, which drops periodicity with edge points), level it."""
    if not all(hasattr(topography, a) for a in ("heights", "dim", "nb_grid_pts", "detrend", "physical_sizes")):
        raise TypeError(f"topography must be a SurfaceTopography map, got {type(topography).__name__}")
    if topography.dim != 2:
        raise ValueError("the boundary-element contact needs a 2-d map, not a line scan")
    if topography.has_undefined_data:
        raise ValueError("the topography has undefined data; fill it (fill_undefined=True) first")
    if topography.unit not in (None, "m"):
        topography = topography.to_unit("m")
    topography = with_periodicity(subsample(topography, grid), periodic)
    nb = tuple(int(n) for n in topography.nb_grid_pts)
    if min(nb) < MIN_GRID:
        raise ValueError(f"grid {nb[0]} x {nb[1]} is too small for a boundary-element solve; need at least "
                         f"{MIN_GRID} points along each axis")
    h = np.asarray(topography.heights(), dtype=float)
    if not np.all(np.isfinite(h)):
        raise ValueError("heights must be finite (no NaN or infinity)")
    return topography.detrend("center" if topography.is_periodic else "height")
