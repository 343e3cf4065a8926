r"""The statistical model beside a boundary-element solution of the same surface.

:func:`validate_surface` reads (or takes) a measured or generated map, optionally
averages it down to ``grid`` points per axis, and on that one surface

* solves the full elastic contact at each load (:func:`~asperity.validation.bem.bem_contact`);
* estimates the Greenwood-Williamson summit parameters :math:`\sigma_s, R, \eta` two ways
  (:func:`asperity.topography.analyse_surface`: spectral Nayak/McCool and detected
  summits) and runs the statistical model without adhesion
  (:class:`asperity.physical.PhysicalContact`, nominal area = scanned area, optionally
  with an ``interaction`` correction, :mod:`asperity.interaction`) at the same loads.

Compared quantities, SI units (columns :data:`asperity.quantities.VALIDATION_COLUMNS`):

* real contact area, and its deviation :math:`A_{GW}/A_{BEM} - 1`;
* mean gap between the flat and the deformed surface: the BEM's :math:`\langle g\rangle`;
  the model's local separation from the mean summit plane plus the mean summit height
  above the mean plane, :math:`d_{loc} + \bar z_s` (the GW deformation is local);
* the approach, the distance of the flat from the undeformed mean plane (non-periodic BEM
  only), and the model's :math:`d + \bar z_s` (with an interaction: :math:`d_{loc} - \Delta`);
* the number of contact spots (BEM) beside the number of asperities in contact (model).

Other models can be put beside them (``models``, :mod:`~asperity.validation.models`): the
interacting and coalescing Hertzian asperities on the map's own summits (``'icha'``),
Persson's area from the rms slope (``'persson'``) and the light-load asymptote of Bush,
Gibson & Thomas (``'bgt'``).

Costs are measured: the BEM solves, the summit analysis and the model's curves, and each
other model with its own input analysis (wall time, this process).
"""

from __future__ import annotations

import dataclasses
import math
import os
import time
import warnings
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .._csv import columns_to_csv, columns_to_dataframe
from .._json import dumps
from .._validation import check_bool, check_scalar_positive
from ..materials import as_material
from ..persson import rms_slope
from ..physical import PhysicalContact
from ..quantities import VALIDATION_COLUMNS
from ..topography import analyse_surface, read_topography
from ..topography.summits import plain
from .bem import (
    DEFAULT_TOLERANCE,
    BemCurve,
    bem_contact,
    check_loads,
    check_solver_options,
    subsample,
    with_periodicity,
)
from .models import AREA_METHODS, check_models, model_columns, run_icha, run_slope_law
from .notes import comparison_notes, model_warning_notes
from .plot import plot_validation
from .progress import stage

__all__ = ["SurfaceValidation", "validate_surface", "METHODS", "NOMINAL_B"]

#: The two estimates of the summit parameters compared with the BEM.
METHODS = ("spectral", "detected")
#: Burgers vector [m] the GW model uses for a material without one (it only scales the
#: dimensionless groups of a contact without adhesion and friction: no result depends on it).
NOMINAL_B = 2.5e-10


@dataclass(frozen=True)
class SurfaceValidation:
    """The models beside a boundary-element solution; columns from
    :data:`asperity.quantities.VALIDATION_COLUMNS` (one row per load), those of the models compared.

    Attributes
    ----------
    table : dict of str -> ndarray
        The columns, SI units.
    bem : BemCurve
        The boundary-element results.
    analysis : SurfaceAnalysis or None
        Summit parameters of the (subsampled) surface, both methods, with its warnings
        (None without the GW model).
    interaction : str
        Name of the interaction correction of the GW model (:mod:`asperity.interaction`).
    costs : dict
        Wall times [s]: ``bem`` (all solves); for GW ``analysis`` (summit statistics),
        ``model`` (the statistical curves, both methods), ``model_per_method``; ``icha``
        (summits, field and loads), ``persson``, ``bgt`` (rms slope and law).
    parameters : dict
        Material, E*, grid, sizes, periodicity, source file, models; ``warnings``: notes
        (the summit analysis's doubts, the GW curves' warnings naming the summit method, and
        :func:`~asperity.validation.notes.comparison_notes`), not issued as Python warnings.
    models : tuple of str
        The models compared (:data:`asperity.validation.models.MODELS`).
    icha : IchaCurve or None
        The ICHA results, if compared.
    contacts : dict of str -> PhysicalContact
        The GW model's contact for each summit method (``'spectral'``, ``'detected'``): what
        it computed (:meth:`~asperity.physical.PhysicalContact.describe`); empty without GW.
    """

    table: dict
    bem: BemCurve
    analysis: Any = field(repr=False)
    interaction: str = "none"
    costs: dict = field(default_factory=dict)
    parameters: dict = field(default_factory=dict)
    models: tuple = ("gw",)
    icha: Any = field(default=None, repr=False)
    contacts: dict = field(default_factory=dict, repr=False, compare=False)

    def __len__(self) -> int:
        return len(self.bem)

    @property
    def methods(self) -> tuple[str, ...]:
        """The area estimates compared: ``spectral``, ``detected`` (GW), ``icha``, ``persson``, ``bgt``."""
        return tuple(m for model in self.models for m in AREA_METHODS[model])

    def columns(self) -> dict[str, np.ndarray]:
        """Column name (SI suffix) -> array, in the order of :data:`~asperity.quantities.VALIDATION_COLUMNS`."""
        return {name: np.asarray(self.table[name]) for name in model_columns(self.models)}

    def to_csv(self, path_or_buffer=None) -> str | None:
        """Write the table as CSV (header of column names); return the text if no path is given."""
        return columns_to_csv(self.columns(), path_or_buffer)

    def to_dataframe(self):
        """The table as a pandas DataFrame (needs pandas); units in ``attrs['units']``."""
        units = {name: VALIDATION_COLUMNS[name].si_unit for name in self.columns()}
        return columns_to_dataframe(self.columns(), {**self.parameters, "units": units})

    def deviation(self, method: str = "spectral", *, up_to: float = 0.2) -> float:
        """Largest :math:`|A/A_{BEM} - 1|` of ``method`` (:attr:`methods`) over loads whose BEM
        area fraction is at most ``up_to``.

        Raises
        ------
        ValueError
            For a method not compared (GW's are ``'spectral'`` and ``'detected'``), an
            ``up_to`` outside (0, 1], or when no load has a boundary-element area fraction up
            to ``up_to``.
        """
        if method not in self.methods:
            gw = " (GW's methods are 'spectral' and 'detected')" if method == "gw" else ""
            raise ValueError(f"method must be one of {self.methods}{gw}, got {method!r}")
        up_to = check_scalar_positive(up_to, "up_to")
        if up_to > 1.0:
            raise ValueError(f"up_to (a real-area fraction) must lie in (0, 1], got {up_to!r}")
        dev = self._deviation(method, up_to)
        if math.isnan(dev):
            raise ValueError(f"no load has a boundary-element area fraction up to {up_to:g} (the smallest is "
                             f"{float(np.min(self.table['fraction_bem'])):.3g}): give a larger up_to or lighter loads")
        return dev

    def _deviation(self, method: str, up_to: float) -> float:
        keep = self.table["fraction_bem"] <= up_to
        dev = np.abs(self.table[f"dev_{method}"][keep])
        return float(dev.max()) if dev.size else math.nan

    @property
    def cost_ratio(self) -> float:
        """GW cost (summit analysis + curves) over boundary-element cost (NaN without GW)."""
        if "gw" not in self.models:
            return math.nan
        return (self.costs["analysis"] + self.costs["model"]) / self.costs["bem"]

    @property
    def cost_ratios(self) -> dict[str, float]:
        """Each model's cost (with its input analysis) over the boundary-element cost."""
        out = {"gw": self.cost_ratio} if "gw" in self.models else {}
        out.update({m: self.costs[m] / self.costs["bem"] for m in self.models if m != "gw"})
        return out

    def to_dict(self) -> dict[str, Any]:
        """Plain dictionary for strict JSON (NaN and infinity as None)."""
        return {"parameters": plain(self.parameters), "interaction": self.interaction, "models": list(self.models),
                "costs": plain({**self.costs, "ratio": self.cost_ratio, "ratios": self.cost_ratios}),
                "max_deviation_up_to_20pc": {m: plain(self._deviation(m, 0.2)) for m in self.methods},
                "summits": None if self.analysis is None else self.analysis.to_dict(),
                "table": {k: [plain(x) for x in v.tolist()] for k, v in self.columns().items()}}

    def to_json(self) -> str:
        """Strict JSON text of :meth:`to_dict`."""
        return dumps(self.to_dict(), indent=1)

    def plot(self, path, fmt: str | None = None) -> None:
        """Draw real area fraction, mean gap and spots against load; save to ``path`` (needs matplotlib).

        ``fmt`` is the image format (default: from the file suffix, else png).
        """
        plot_validation(self, path, fmt)


def _topography(surface, read_kwargs):
    if isinstance(surface, str | os.PathLike):
        try:
            return read_topography(surface, **read_kwargs), os.fsdecode(os.fspath(surface))
        except ValueError as err:
            raise ValueError(f"surface: {err}") from None
    if read_kwargs:
        raise TypeError(f"{sorted(read_kwargs)} only apply when reading a file")
    if not all(hasattr(surface, a) for a in ("heights", "dim", "nb_grid_pts", "detrend")):
        raise TypeError(f"surface must be a file path or a SurfaceTopography map, got {type(surface).__name__}")
    return surface, None


def validate_surface(surface, P, *, material, grid=None, periodic=None, interaction="none", models=("gw",),
                     tolerance=DEFAULT_TOLERANCE, maxiter=10000, progress=False, **read_kwargs) -> SurfaceValidation:
    r"""Boundary-element contact beside the statistical and asperity models on one surface, versus load.

    Parameters
    ----------
    surface : str, os.PathLike or SurfaceTopography.Topography
        A map file (any format SurfaceTopography reads; see
        :func:`asperity.topography.read_topography`) or a map already read.
    P : array_like
        Total normal forces [N] on the scanned area, > 0.
    material : Material or str
        The elastic body (a name from the table, or :func:`asperity.materials.pair` for
        two bodies): its contact modulus :math:`E^*` drives all solutions; its Burgers
        vector scales the statistical model (Hertz without adhesion: results do not
        depend on it; a material without one gets :data:`NOMINAL_B`, with a note).
    grid : int, optional
        Average the map down to at most ``grid`` points per axis first; all solutions
        then see the same averaged surface.
    periodic : bool, optional
        Boundary-element (and ICHA) boundaries; default: the topography's (files read from
        disk are non-periodic unless their reader says otherwise).
    interaction : str
        Interaction correction of the GW model (:data:`asperity.interaction.INTERACTIONS`);
        default ``'none'`` (plain GW).
    models : sequence of str or str
        Models put beside the boundary elements (:data:`asperity.validation.models.MODELS`:
        ``'gw'``, ``'icha'``, ``'persson'``, ``'bgt'``; a string is split at commas); default GW only.
    tolerance, maxiter, progress
        Passed to :func:`~asperity.validation.bem.bem_contact`.
    **read_kwargs
        ``physical_sizes``, ``unit``, ``channel_index``, ``fill_undefined`` for a file.

    Returns
    -------
    SurfaceValidation
        The table (:data:`asperity.quantities.VALIDATION_COLUMNS`, the models' columns),
        the solutions, the summit analysis and the costs.

    Raises
    ------
    TypeError, ValueError
        For an unreadable or degenerate surface (the message names the file), bad loads,
        grid, material, interaction (or an interaction without the GW model) or models.
    asperity._optional.MissingDependency
        Without ContactMechanics (``pip install 'asperity[bem]'``) or SurfaceTopography.
    """
    mat = as_material(material)
    models = check_models(models)
    progress = check_bool(progress, "progress")
    P = check_loads(P)
    check_solver_options(tolerance, maxiter)  # before the map is read and analysed (a CLI check)
    if "gw" not in models and interaction != "none":
        raise ValueError(f"interaction={interaction!r} corrects the GW model: include 'gw' in models")
    topo, source = _topography(surface, read_kwargs)
    analysis, t_analysis = None, 0.0
    try:
        topo = with_periodicity(topo, periodic)  # levelling, summits at the edges, ICHA: as the solve's
        full = topo if topo.unit in (None, "m") else topo.to_unit("m")
        topo = with_periodicity(subsample(full, grid), periodic)  # as the solve's, points dropped or not
        shape = tuple(int(n) for n in topo.nb_grid_pts)
        if "gw" in models:
            stage(f"summit statistics of the {' x '.join(map(str, shape))} map", enabled=progress,
                  points=int(np.prod(shape)))
            start = time.perf_counter()
            try:
                analysis = analyse_surface(topo)
            except ValueError as err:  # (a user trial: a wave has no summits, and no hint was given)
                raise ValueError(f"{err}: the GW model needs summit statistics; compare without it (models=...; "
                                 "command line: --model persson,bgt, or icha where the map has summits)") from None
            t_analysis = time.perf_counter() - start
    except ValueError as err:
        raise ValueError(f"{source}: {err}") if source else err from None
    A0 = float(np.prod(topo.physical_sizes))
    contacts, notes = {}, _cropped(full, topo, grid)
    if "gw" in models and mat.b is None:  # it scales the groups only: no adhesion, no friction here
        mat = dataclasses.replace(mat, b=NOMINAL_B)
        notes.append(f"material {mat.name!r} has no Burgers vector b: the GW model uses b = {NOMINAL_B:g} m, on which "
                     "this comparison (no adhesion, no friction) does not depend")
    if "gw" in models:
        for method in METHODS:
            summits = getattr(analysis, method)
            try:
                contacts[method] = PhysicalContact(mat, summits.surface(A0), adhesion=False, interaction=interaction)
            except ValueError as err:
                if "interaction" in str(err):
                    raise
                raise ValueError(f"{source or 'surface'}: its {method} summit parameters give no GW surface ({err}): "
                                 "too few summits or too little roughness; compare without GW "
                                 "(models=...; command line: --model icha,persson)") from None
    stage(f"boundary elements on {' x '.join(map(str, shape))} points, {np.size(P)} loads", enabled=progress,
          points=int(np.prod(shape)))
    bem = bem_contact(topo, P, E_star=mat.E_star, periodic=periodic, tolerance=tolerance, maxiter=maxiter,
                      progress=progress)
    table = {"P_N": bem.P, "p_Pa": bem.P / A0, "fraction_bem": bem.area_fraction, "area_bem_m2": bem.area,
             "gap_bem_m": bem.mean_gap, "sep_bem_m": bem.separation, "spots_bem": bem.spots,
             "iterations_bem": bem.iterations}
    costs = {"bem": float(np.sum(bem.seconds))}
    icha = None
    notes = (list(analysis.warnings) if analysis else []) + notes
    if "gw" in models:
        curves, t_model = {}, {}
        for method in METHODS:
            with warnings.catch_warnings(record=True) as caught:  # -> notes naming the method
                warnings.simplefilter("always")
                start = time.perf_counter()
                try:
                    curves[method] = contacts[method].load_curve(bem.P)
                except ValueError as err:  # (a user trial: metre heights read as nm gave only this)
                    raise ValueError(f"{source or 'surface'}: the GW model on its {method} summits cannot carry "
                                     f"these loads ({err}); the map's rms height is {analysis.spectral.sigma:.3g} m: "
                                     "check the height unit (unit=, --unit) and the loads") from None
                t_model[method] = time.perf_counter() - start
            notes += model_warning_notes(method, caught)
        table.update(_gw_table(bem, analysis, contacts, curves))
        costs.update({"analysis": t_analysis, "model": sum(t_model.values()), "model_per_method": t_model})
    if "icha" in models:
        cols, costs["icha"], icha = run_icha(topo, bem.P, mat.E_star, bem.periodic, bem.area)
        table.update(cols)
    slopes = {}
    for name in ("persson", "bgt"):
        if name in models:
            cols, costs[name], slopes[name] = run_slope_law(name, topo, bem.P, mat.E_star, A0, bem.area)
            table.update(cols)
    methods = tuple(m for model in models for m in AREA_METHODS[model])
    notes += comparison_notes(table, methods, A0, elongated=None if icha is None else icha.elongated,
                              rms_slope=next(iter(slopes.values())) if slopes else _slope(topo))
    params = {"material": mat.name, "E_star_Pa": mat.E_star, "nb_grid_pts": bem.nb_grid_pts,
              "physical_sizes_m": tuple(float(s) for s in topo.physical_sizes), "nominal_area_m2": A0,
              "periodic": bem.periodic, "grid": grid, "source": source, "models": list(models),
              "interaction": contacts[METHODS[0]].interaction.name if contacts else "none",
              "tolerance": tolerance, "warnings": notes}
    if slopes:
        params["rms_slope"] = next(iter(slopes.values()))
    if icha is not None:
        params["icha_summits"] = icha.n_summits
    return SurfaceValidation(table={k: np.asarray(v) for k, v in table.items()}, bem=bem, analysis=analysis,
                             interaction=params["interaction"], costs=costs, parameters=params, models=models,
                             icha=icha, contacts=contacts)


def _gw_table(bem, analysis, contacts, curves) -> dict[str, np.ndarray]:
    t = {}
    for method in METHODS:
        t[f"area_{method}_m2"] = curves[method].area
        t[f"dev_{method}"] = np.where(bem.area > 0, curves[method].area / np.where(bem.area > 0, bem.area, 1.0)
                                      - 1.0, np.nan)
        summits, c = getattr(analysis, method), contacts[method]
        shift = c.interaction.shift(curves[method].dimensionless.P) * summits.sigma_s
        t[f"gap_{method}_m"] = curves[method].d + shift + summits.mean_summit_height
        t[f"sep_{method}_m"] = curves[method].d + summits.mean_summit_height
        t[f"contacts_{method}"] = curves[method].contacts
    return t


def _slope(topo):
    """The map's rms slope for the notes (None if it cannot be had: the notes then say nothing of it)."""
    try:
        return rms_slope(topo)
    except ValueError:
        return None


def _cropped(full, averaged, grid) -> list[str]:
    """A note when ``grid`` averaging dropped the rows or columns beyond whole blocks."""
    if grid is None or tuple(full.nb_grid_pts) == tuple(averaged.nb_grid_pts):
        return []
    f = math.ceil(max(full.nb_grid_pts) / grid)
    if all(n * f == m for n, m in zip(averaged.nb_grid_pts, full.nb_grid_pts, strict=True)):
        return []
    kept = " x ".join(f"{n * f}" for n in averaged.nb_grid_pts)
    sizes = " x ".join(f"{float(x):.4g}" for x in averaged.physical_sizes)
    lost = " and periodicity" if full.is_periodic and not averaged.is_periodic else ""
    return [f"grid={grid}: the {full.nb_grid_pts[0]} x {full.nb_grid_pts[1]} scan is averaged over {f} x {f} blocks; "
            f"the points beyond whole blocks are dropped{lost}: {kept} points, {sizes} m, are compared"]
