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

Costs are measured: the BEM solves, the summit analysis and the model's curves (wall time,
this process).
"""

from __future__ import annotations

import math
import os
import time
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .._csv import columns_to_csv, columns_to_dataframe
from .._json import dumps
from .._optional import require
from ..materials import as_material
from ..physical import PhysicalContact
from ..quantities import VALIDATION_COLUMNS
from ..topography import analyse_surface, read_topography
from ..topography.summits import plain
from .bem import DEFAULT_TOLERANCE, BemCurve, bem_contact, subsample

__all__ = ["SurfaceValidation", "validate_surface", "METHODS"]

#: The two estimates of the summit parameters compared with the BEM.
METHODS = ("spectral", "detected")


@dataclass(frozen=True)
class SurfaceValidation:
    """The statistical model beside a boundary-element solution; columns in
    :data:`asperity.quantities.VALIDATION_COLUMNS` (one row per load).

    Attributes
    ----------
    table : dict of str -> ndarray
        The columns, SI units.
    bem : BemCurve
        The boundary-element results.
    analysis : SurfaceAnalysis
        Summit parameters of the (subsampled) surface, both methods, with its warnings.
    interaction : str
        Name of the interaction correction of the model (:mod:`asperity.interaction`).
    costs : dict
        Wall times [s]: ``bem`` (all solves), ``analysis`` (summit statistics),
        ``model`` (the statistical curves, both methods), ``model_per_method``.
    parameters : dict
        Material, E*, grid, sizes, periodicity, source file.
    contacts : dict of str -> PhysicalContact
        The model's contact for each summit method (``'spectral'``, ``'detected'``): what
        it computed (:meth:`~asperity.physical.PhysicalContact.describe`).
    """

    table: dict
    bem: BemCurve
    analysis: Any = field(repr=False)
    interaction: str = "none"
    costs: dict = field(default_factory=dict)
    parameters: dict = field(default_factory=dict)
    contacts: dict = field(default_factory=dict, repr=False, compare=False)

    def __len__(self) -> int:
        return len(self.bem)

    def columns(self) -> dict[str, np.ndarray]:
        """Column name (SI suffix) -> array, in the order of :data:`~asperity.quantities.VALIDATION_COLUMNS`."""
        return {name: np.asarray(self.table[name]) for name in VALIDATION_COLUMNS}

    def to_csv(self, path_or_buffer=None) -> str | None:
        """Write the table as CSV (header of column names); return the text if no path is given."""
        return columns_to_csv(self.columns(), path_or_buffer)

    def to_dataframe(self):
        """The table as a pandas DataFrame (needs pandas); units in ``attrs['units']``."""
        units = {name: q.si_unit for name, q in VALIDATION_COLUMNS.items()}
        return columns_to_dataframe(self.columns(), {**self.parameters, "units": units})

    def deviation(self, method: str = "spectral", *, up_to: float = 0.2) -> float:
        """Largest :math:`|A_{GW}/A_{BEM} - 1|` of ``method`` over loads whose BEM area
        fraction is at most ``up_to`` (NaN if there is none)."""
        if method not in METHODS:
            raise ValueError(f"method must be one of {METHODS}, got {method!r}")
        keep = self.table["fraction_bem"] <= up_to
        dev = np.abs(self.table[f"dev_{method}"][keep])
        return float(dev.max()) if dev.size else math.nan

    @property
    def cost_ratio(self) -> float:
        """Statistical-model cost (analysis + curves) over boundary-element cost."""
        return (self.costs["analysis"] + self.costs["model"]) / self.costs["bem"]

    def to_dict(self) -> dict[str, Any]:
        """Plain dictionary for strict JSON (NaN and infinity as None)."""
        return {"parameters": plain(self.parameters), "interaction": self.interaction,
                "costs": plain({**self.costs, "ratio": self.cost_ratio}),
                "max_deviation_up_to_20pc": {m: plain(self.deviation(m)) for m in METHODS},
                "summits": self.analysis.to_dict(),
                "table": {k: [plain(x) for x in v.tolist()] for k, v in self.columns().items()}}

    def to_json(self) -> str:
        """Strict JSON text of :meth:`to_dict`."""
        return dumps(self.to_dict(), indent=1)

    def plot(self, path, fmt: str | None = None) -> None:
        """Draw real area fraction, mean gap and spots against load; save to ``path`` (needs matplotlib).

        ``fmt`` is the image format (default: from the file suffix, else png).
        """
        require("matplotlib", purpose="plotting a validation", extra="plot")
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure

        fmt = fmt or (os.path.splitext(os.fspath(path))[1][1:].lower() or "png")
        t, A0 = self.table, self.bem.nominal_area
        fig = Figure(figsize=(11, 3.6), layout="constrained")
        FigureCanvasAgg(fig)
        ax1, ax2, ax3 = fig.subplots(1, 3)
        P = t["P_N"]
        ax1.loglog(P, t["fraction_bem"], "ko-", label="boundary elements")
        ax2.semilogx(P, t["gap_bem_m"] * 1e9, "ko-", label="boundary elements")
        ax3.loglog(P, t["spots_bem"], "ko-", label="BEM contact spots")
        for method, style in zip(METHODS, ("b^--", "rs:"), strict=True):
            label = f"GW, {method} summits" + ("" if self.interaction == "none" else f" + {self.interaction}")
            ax1.loglog(P, t[f"area_{method}_m2"] / A0, style, label=label)
            ax2.semilogx(P, t[f"gap_{method}_m"] * 1e9, style, label=label)
            ax3.loglog(P, np.maximum(t[f"contacts_{method}"], 1e-300), style, label=f"GW asperities, {method}")
        ax1.set_ylabel("real contact area / nominal area")
        ax2.set_ylabel("mean gap (nm)")
        ax3.set_ylabel("contact spots / asperities in contact")
        for ax in (ax1, ax2, ax3):
            ax.set_xlabel("load P (N)")
        ax1.legend(fontsize=7)
        ax3.legend(fontsize=7)
        src = self.parameters.get("source") or "surface"
        fig.suptitle(f"{os.path.basename(str(src))}: {self.parameters['material']}, grid "
                     f"{self.bem.nb_grid_pts[0]}x{self.bem.nb_grid_pts[1]}, "
                     f"{'periodic' if self.bem.periodic else 'free'} boundaries")
        fig.savefig(path, dpi=150, format=fmt)


def _topography(surface, read_kwargs):
    if isinstance(surface, str | os.PathLike):
        return read_topography(surface, **read_kwargs), os.fsdecode(os.fspath(surface))
    if read_kwargs:
        raise TypeError(f"{sorted(read_kwargs)} only apply when reading a file")
    if not all(hasattr(surface, a) for a in ("heights", "dim", "nb_grid_pts", "detrend")):
        raise TypeError(f"surface must be a file path or a SurfaceTopography map, got {type(surface).__name__}")
    return surface, None


def validate_surface(surface, P, *, material, grid=None, periodic=None, interaction="none",
                     tolerance=DEFAULT_TOLERANCE, maxiter=10000, progress=False, **read_kwargs) -> SurfaceValidation:
    r"""Boundary-element contact beside the statistical model on one surface, versus load.

    Parameters
    ----------
    surface : str, os.PathLike or SurfaceTopography.Topography
        A map file (any format SurfaceTopography reads; see
        :func:`asperity.topography.read_topography`) or a map already read.
    P : array_like
        Total normal forces [N] on the scanned area, > 0.
    material : Material or str
        The elastic body (a name from the table, or :func:`asperity.materials.pair` for
        two bodies): its contact modulus :math:`E^*` drives both solutions; its Burgers
        vector scales the statistical model (Hertz without adhesion: results do not
        depend on it).
    grid : int, optional
        Average the map down to at most ``grid`` points per axis first; both solutions
        then see the same averaged surface.
    periodic : bool, optional
        Boundary-element boundaries; default: the topography's (files read from disk are
        non-periodic unless their reader says otherwise).
    interaction : str
        Interaction correction of the statistical model (:data:`asperity.interaction.INTERACTIONS`);
        default ``'none'`` (plain GW).
    tolerance, maxiter, progress
        Passed to :func:`~asperity.validation.bem.bem_contact`.
    **read_kwargs
        ``physical_sizes``, ``unit``, ``channel_index``, ``fill_undefined`` for a file.

    Returns
    -------
    SurfaceValidation
        The table (:data:`asperity.quantities.VALIDATION_COLUMNS`), both solutions, the
        summit analysis and the costs.

    Raises
    ------
    TypeError, ValueError
        For an unreadable or degenerate surface (the message names the file), bad loads,
        grid, material or interaction.
    asperity._optional.MissingDependency
        Without ContactMechanics (``pip install 'asperity[bem]'``) or SurfaceTopography.
    """
    mat = as_material(material)
    topo, source = _topography(surface, read_kwargs)
    try:
        topo = subsample(topo if topo.unit in (None, "m") else topo.to_unit("m"), grid)
        start = time.perf_counter()
        analysis = analyse_surface(topo)
        t_analysis = time.perf_counter() - start
    except ValueError as err:
        raise ValueError(f"{source}: {err}") if source else err from None
    A0 = float(np.prod(topo.physical_sizes))
    contacts, curves, t_model = {}, {}, {}
    for method in METHODS:
        summits = getattr(analysis, method)
        contacts[method] = PhysicalContact(mat, summits.surface(A0), adhesion=False, interaction=interaction)
    bem = bem_contact(topo, P, E_star=mat.E_star, periodic=periodic, tolerance=tolerance, maxiter=maxiter,
                      progress=progress)
    for method in METHODS:
        start = time.perf_counter()
        curves[method] = contacts[method].load_curve(bem.P)
        t_model[method] = time.perf_counter() - start
    table = _table(bem, analysis, contacts, curves)
    costs = {"bem": float(np.sum(bem.seconds)), "analysis": t_analysis, "model": sum(t_model.values()),
             "model_per_method": t_model}
    params = {"material": mat.name, "E_star_Pa": mat.E_star, "nb_grid_pts": bem.nb_grid_pts,
              "physical_sizes_m": tuple(float(s) for s in topo.physical_sizes), "nominal_area_m2": A0,
              "periodic": bem.periodic, "grid": grid, "source": source, "interaction": contacts[METHODS[0]]
              .interaction.name, "tolerance": tolerance, "warnings": list(analysis.warnings)}
    return SurfaceValidation(table=table, bem=bem, analysis=analysis, interaction=params["interaction"],
                             costs=costs, parameters=params, contacts=contacts)


def _table(bem, analysis, contacts, curves) -> dict[str, np.ndarray]:
    A0 = bem.nominal_area
    t = {"P_N": bem.P, "p_Pa": bem.P / A0, "fraction_bem": bem.area_fraction, "area_bem_m2": bem.area}
    for method in METHODS:
        t[f"area_{method}_m2"] = curves[method].area
    for method in METHODS:
        t[f"dev_{method}"] = curves[method].area / bem.area - 1.0 if np.all(bem.area > 0) else \
            np.where(bem.area > 0, curves[method].area / np.where(bem.area > 0, bem.area, 1.0) - 1.0, np.nan)
    t["gap_bem_m"] = bem.mean_gap
    for method in METHODS:
        summits, c = getattr(analysis, method), contacts[method]
        shift = c.interaction.shift(curves[method].dimensionless.P) * summits.sigma_s
        t[f"gap_{method}_m"] = curves[method].d + shift + summits.mean_summit_height
    t["sep_bem_m"] = bem.separation
    for method in METHODS:
        t[f"sep_{method}_m"] = curves[method].d + getattr(analysis, method).mean_summit_height
    t["spots_bem"] = bem.spots
    for method in METHODS:
        t[f"contacts_{method}"] = curves[method].contacts
    t["iterations_bem"] = bem.iterations
    return {name: np.asarray(t[name]) for name in VALIDATION_COLUMNS}
