r"""The interacting and coalescing Hertzian asperity model on a measured or generated map.

:func:`icha_contact` finds the summits of the map (:func:`~asperity.icha.summits.map_summits`)
and loads them with a rigid flat, load by load in increasing order, each load starting
from the previous one's contacts (:class:`~asperity.icha.solver.IchaState`); :func:`icha_curve`
does the same on summits already found.  Results: :class:`IchaCurve`.
"""

from __future__ import annotations

import dataclasses
import math
import time
from dataclasses import dataclass, field

import numpy as np

from .._csv import columns_to_csv, columns_to_dataframe
from .._validation import as_float_array, check_mean_pressure, check_scalar_positive
from .field import FreeKernel, PeriodicKernel
from .rectangle import boussinesq_rectangle_mean
from .solver import IchaState
from .summits import MapSummits, map_summits

__all__ = ["IchaCurve", "icha_contact", "icha_curve", "MAX_SUMMITS", "MAX_LOADS", "P_BAR_RANGE", "ELONGATED_RATIO"]

#: Most summits on one map: the model keeps two summits x summits matrices (distances and
#: point-force fields, 8 N^2 bytes each: 256 MB at the limit).
MAX_SUMMITS = 4000
#: A summit whose principal curvatures differ more than this many times is elongated (a ridge):
#: the Hertz cap of the equivalent sphere overstates its contact area (Johnson 1985, section 4.2:
#: the elliptic correction factors, taken as 1, are no longer near 1).
ELONGATED_RATIO = 10.0
#: Most loads in one run.
MAX_LOADS = 1000
#: Range of the mean pressure over the contact modulus, :math:`P/(E^*A_0)`: above 1 the strains are
#: of order one (linear elasticity has long failed); below 1e-20 the first contact's penetration
#: is lost in the rounding of the summit heights and the solver no longer converges.
P_BAR_RANGE = (1e-20, 1.0)


@dataclass(frozen=True)
class IchaCurve:
    """Results of the interacting and coalescing Hertzian asperity model, SI units, one value per load.

    Attributes
    ----------
    P : ndarray
        Total normal force [N].
    area : ndarray
        Real contact area, the sum of the spots' :math:`\\pi a^2` [m^2].
    spots : ndarray of int
        Contact spots (asperities in contact, a coalesced group counting once).
    mean_gap : ndarray
        Mean gap between the flat and the deformed surface [m].
    separation : ndarray
        Distance of the flat from the undeformed mean plane [m] (free maps; NaN for a
        periodic one, where it is a gauge).
    merges : ndarray of int
        Coalescences up to this load.
    force_sum : ndarray
        Sum of the contact forces [N] (equals ``P`` at convergence).
    seconds : ndarray
        Wall time of each load step [s].
    n_summits : int
        Summits of the map.
    nominal_area : float
        Area of the map [m^2].
    periodic : bool
        Whether the map repeats.
    E_star : float
        Contact modulus [Pa].
    interaction, coalescence : bool
        Whether the contacts interact elastically and coalesce.
    setup_seconds : float
        Wall time of finding the summits and tabulating the periodic field [s].
    elongated : float
        Share of the summits whose principal curvatures differ more than
        :data:`ELONGATED_RATIO`-fold (ridges: their equivalent-sphere caps overstate the
        contact area); NaN if the summits' curvatures are not known.
    """

    P: np.ndarray
    area: np.ndarray
    spots: np.ndarray
    mean_gap: np.ndarray
    separation: np.ndarray
    merges: np.ndarray
    force_sum: np.ndarray
    seconds: np.ndarray
    n_summits: int
    nominal_area: float
    periodic: bool
    E_star: float
    interaction: bool = True
    coalescence: bool = True
    setup_seconds: float = 0.0
    elongated: float = math.nan
    parameters: dict = field(default_factory=dict, compare=False)

    def __len__(self) -> int:
        return int(np.size(self.P))

    @property
    def area_fraction(self) -> np.ndarray:
        """Real over nominal area."""
        return self.area / self.nominal_area

    def columns(self) -> dict[str, np.ndarray]:
        """Column name (SI suffix) -> array."""
        return {"P_N": self.P, "area_m2": self.area, "fraction": self.area_fraction, "spots": self.spots,
                "gap_m": self.mean_gap, "sep_m": self.separation, "merges": self.merges,
                "seconds": self.seconds}

    def to_csv(self, path_or_buffer=None) -> str | None:
        """Write the columns as CSV; return the text if no path is given."""
        return columns_to_csv(self.columns(), path_or_buffer)

    def to_dataframe(self):
        """The columns as a pandas DataFrame (needs pandas)."""
        return columns_to_dataframe(self.columns(), self.parameters)


def _check_loads(P) -> np.ndarray:
    P = as_float_array(P, "P (load)").ravel()
    if P.size > MAX_LOADS:
        raise ValueError(f"P (load) must hold 1 to {MAX_LOADS} loads, got {P.size}")
    if np.any(P <= 0):
        raise ValueError(f"P (load) must be > 0 N (contact without adhesion), got min {P.min():g}")
    return P


def icha_curve(summits, P, *, E_star, interaction=True, coalescence=True) -> IchaCurve:
    r"""Interacting and coalescing Hertzian asperities (Afferrante, Carbone & Demelio 2012), versus load.

    Each summit :math:`i` of the map is a Hertzian cap (height :math:`z_i`, radius
    :math:`R_i`, position :math:`\mathbf r_i`) pressed by a rigid flat at :math:`d`:

    .. math::
        \delta_i = z_i - d - \sum_{j\ne i}u_j(\mathbf r_i),\qquad
        F_i = \tfrac43E^*R_i^{1/2}\delta_i^{3/2},\qquad a_i^2 = R_i\delta_i,\qquad \sum_iF_i = P,

    :math:`u_j` the Hertzian displacement field of contact :math:`j` (Johnson Eq 3.42; with
    all periodic images on a periodic map); overlapping contact circles coalesce into one
    equivalent Hertzian spot that conserves their area and force.  Loads are solved in
    increasing order, each from the previous state (coalescence is irreversible).

    Parameters
    ----------
    summits : MapSummits
        The asperities (:func:`~asperity.icha.summits.map_summits`), at most :data:`MAX_SUMMITS`.
    P : array_like
        Total normal forces [N] on the map, > 0, 1 to :data:`MAX_LOADS` values, with mean
        pressures :math:`P/A_0` between 1e-20 and 1 times :math:`E^*` (:data:`P_BAR_RANGE`);
        reported in the order given.
    E_star : float
        Contact modulus :math:`E^*` [Pa], > 0.
    interaction : bool
        Let the contacts feel each other's displacement field (False: independent Hertz caps).
    coalescence : bool
        Merge overlapping contact spots (False: they overlap freely).

    Returns
    -------
    IchaCurve
        One value per load.

    Raises
    ------
    TypeError
        If ``summits`` is not a :class:`MapSummits` or a flag is not a bool.
    ValueError
        For bad loads or modulus, too many summits, or a load step that does not converge.

    Examples
    --------
    >>> s = map_summits(-np.add.outer(np.arange(-3.0, 4.0) ** 2, np.arange(-3.0, 4.0) ** 2) / 2, (1.0, 1.0),
    ...                 periodic=False)
    >>> c = icha_curve(s, [1.0], E_star=3.0)             # one cap, R = 1: Hertz, a^3 = 3PR/4E*
    >>> round(float(c.area[0] / math.pi) ** 1.5, 12)
    0.25

    References
    ----------
    L. Afferrante, G. Carbone, G. Demelio, Wear 278-279 (2012) 28-33;
    K. L. Johnson, Contact Mechanics (1985), Eqs (3.42), (4.22)-(4.23).
    """
    if not isinstance(summits, MapSummits):
        raise TypeError(f"summits must be a MapSummits (asperity.icha.map_summits), got {type(summits).__name__}")
    for flag, name in ((interaction, "interaction"), (coalescence, "coalescence")):
        if not isinstance(flag, bool | np.bool_):
            raise TypeError(f"{name} must be True or False, got {flag!r}")
    if len(summits) > MAX_SUMMITS:
        raise ValueError(f"the map has {len(summits)} summits, more than {MAX_SUMMITS}; average it down "
                         "(grid=..., --grid on the command line) first")
    P = _check_loads(P)
    E_star = check_scalar_positive(E_star, "E_star", "Pa")
    check_mean_pressure(P, E_star, summits.nominal_area, P_BAR_RANGE)
    start = time.perf_counter()
    kernel = PeriodicKernel(*summits.size) if summits.periodic else FreeKernel()
    state = IchaState.start(summits, E_star, kernel, interaction=bool(interaction), coalescence=bool(coalescence))
    setup = time.perf_counter() - start
    out = {k: np.empty(P.size) for k in ("area", "spots", "gap", "sep", "merges", "force", "sec")}
    A0 = summits.nominal_area
    for j in np.argsort(P, kind="stable"):
        start = time.perf_counter()
        state.solve(float(P[j]))
        on = state.F > 0
        a = state.radii()
        out["area"][j] = math.pi * float(np.sum(a[on] ** 2))
        out["spots"][j] = int(on.sum())
        out["merges"][j] = state.merges
        out["force"][j] = float(state.F.sum())
        if summits.periodic or not interaction:   # periodic: the field has zero mean (module field)
            mean_u = 0.0
        else:
            mean_u = float(np.sum(state.F[on] * boussinesq_rectangle_mean(
                np.clip(state.x[on], 0, summits.size[0]), np.clip(state.y[on], 0, summits.size[1]),
                *summits.size))) / (math.pi * E_star)
        out["gap"][j] = state.d + mean_u
        out["sep"][j] = math.nan if summits.periodic else state.d
        out["sec"][j] = time.perf_counter() - start
    return IchaCurve(P=P, area=out["area"], spots=out["spots"].astype(int), mean_gap=out["gap"],
                     separation=out["sep"], merges=out["merges"].astype(int), force_sum=out["force"],
                     seconds=out["sec"], n_summits=len(summits), nominal_area=A0, periodic=summits.periodic,
                     E_star=E_star, interaction=bool(interaction), coalescence=bool(coalescence),
                     setup_seconds=setup, elongated=_elongated(summits),
                     parameters={"E_star_Pa": E_star, "periodic": summits.periodic, "n_summits": len(summits),
                                 "interaction": bool(interaction), "coalescence": bool(coalescence),
                                 "radius": summits.radius, "nominal_area_m2": A0})


def icha_contact(topography, P, *, E_star, periodic=None, radius="geometric", interaction=True,
                 coalescence=True) -> IchaCurve:
    r"""Interacting and coalescing Hertzian asperities on the summits of a map, versus load.

    Finds the summits of the map (:func:`~asperity.icha.summits.map_summits`) and solves
    :func:`icha_curve` on them:

    .. math::
        \delta_i = z_i - d - \sum_{j\ne i}u_j(\mathbf r_i),\qquad
        F_i = \tfrac43E^*R_i^{1/2}\delta_i^{3/2},\qquad \sum_iF_i = P .

    Parameters
    ----------
    topography : SurfaceTopography.Topography
        A 2-d map (``unit`` 'm', another length unit, or None for metres) without
        undefined data; its mean plane is removed (only its mean, if periodic).
    P : array_like
        Total normal forces [N] on the map, > 0, with mean pressures :math:`P/A_0` between
        1e-20 and 1 times :math:`E^*` (:data:`P_BAR_RANGE`).
    E_star : float
        Contact modulus :math:`E^*` [Pa], > 0.
    periodic : bool, optional
        Treat the map as periodic (images, wrapped neighbours); default: the topography's.
    radius : {'geometric', 'mean'}
        Radius of each cap (:func:`~asperity.icha.summits.map_summits`).
    interaction, coalescence : bool
        Switch the elastic interaction and the coalescence of spots on or off.

    Returns
    -------
    IchaCurve
        One value per load; ``setup_seconds`` includes finding the summits.

    Raises
    ------
    TypeError
        If ``topography`` is not a SurfaceTopography map.
    ValueError
        For a line scan, undefined data, bad loads, modulus or radius, or no summits.

    Examples
    --------
    >>> from SurfaceTopography import Topography                      # doctest: +SKIP
    >>> c = icha_contact(Topography(h, (4e-6, 4e-6), periodic=True, unit="m"), [1e-3], E_star=1e11)  # doctest: +SKIP

    References
    ----------
    L. Afferrante, G. Carbone, G. Demelio, Wear 278-279 (2012) 28-33; K. L. Johnson,
    Contact Mechanics (1985), §3.4, §4.2.
    """
    start = time.perf_counter()
    if not all(hasattr(topography, a) for a in ("heights", "dim", "nb_grid_pts", "detrend", "pixel_size")):
        raise TypeError(f"topography must be a SurfaceTopography map, got {type(topography).__name__}")
    if topography.dim != 2:
        raise ValueError("the asperity model needs a 2-d map, not a line scan")
    if topography.has_undefined_data:
        raise ValueError("the topography has undefined data; fill it (fill_undefined=True) first")
    if topography.unit not in (None, "m"):
        topography = topography.to_unit("m")
    periodic = bool(topography.is_periodic) if periodic is None else periodic
    if not isinstance(periodic, bool | np.bool_):
        raise TypeError(f"periodic must be True, False or None, got {periodic!r}")
    topo = topography.detrend("center" if topography.is_periodic else "height")
    summits = map_summits(np.asarray(topo.heights(), dtype=float), topo.pixel_size, periodic=bool(periodic),
                          radius=radius)
    found = time.perf_counter() - start
    curve = icha_curve(summits, P, E_star=E_star, interaction=interaction, coalescence=coalescence)
    return dataclasses.replace(curve, setup_seconds=curve.setup_seconds + found)


def _elongated(summits: MapSummits) -> float:
    """Share of the summits past :data:`ELONGATED_RATIO` (NaN without their curvature ratios)."""
    ratio = summits.curvature_ratio
    if ratio is None or ratio.size == 0:
        return math.nan
    return float(np.mean(ratio > ELONGATED_RATIO))
