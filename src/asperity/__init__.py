"""asperity: nano- to macro-scale multi-asperity contact, adhesion and friction.

Greenwood-Williamson statistics of asperity heights, the Hurtado-Kim scale-dependent
friction stress and Maugis-Dugdale adhesion, after G. G. Adams, S. Müftü, N. Mohd Azhar,
"A Scale-Dependent Model for Multi-Asperity Contact and Friction", J. Tribol. 125(4),
700-708 (2003), doi:10.1115/1.1572515 (preprint: "A nano-scale multi-asperity contact and
friction model", whose equation numbers the docstrings use).

Layers, each importing only downward:

* single-asperity laws: :mod:`~asperity.friction_stress`, :mod:`~asperity.hertz`,
  :mod:`~asperity.jkr`, :mod:`~asperity.dmt`, :mod:`~asperity.maugis_dugdale`
  (:mod:`~asperity.maugis_dugdale_load` under load control), :mod:`~asperity.cos`,
  :mod:`~asperity.amontons`, :mod:`~asperity.jackson_green` and
  :mod:`~asperity.jackson_green_fits`,
  :mod:`~asperity.jackson_green_hardness` (elastic-plastic), :mod:`~asperity.nix_gao` (size effect)
* dimensionless groups and height statistics: :mod:`~asperity.groups`,
  :mod:`~asperity.heights` (Gaussian, exponential, Weibull, Pearson III, Johnson, mixture,
  empirical summit heights)
* multi-asperity integrals: :mod:`~asperity.asperity_law`,
  :mod:`~asperity.multi_asperity` (:mod:`~asperity.height_sums` for non-Gaussian heights);
  the laws by name: :mod:`~asperity.elastic_plastic`
* curves: :mod:`~asperity.curves` (:mod:`~asperity.curve_result`); loading-unloading cycles: :mod:`~asperity.cycle`
  (``asperity.cycle(...)``, :func:`~asperity.cycle.preload_curve`); fitting measured data:
  :mod:`~asperity.fit`; the paper's figures: :mod:`~asperity.studies`;
  the command line: :mod:`~asperity.cli`; the browser explorer: :mod:`~asperity.explorer`

Everything is imported lazily (PEP 562): ``import asperity`` loads only the version, and
the first use of a name below (``asperity.load_curve``) or of a submodule
(``asperity.jkr``, ``asperity.physical``) imports the module that defines it.  So the
command line answers ``--help`` without loading NumPy or SciPy, and ``from asperity
import load_curve`` works as before.
"""

from __future__ import annotations

import importlib

from ._version import __version__

#: Public name -> submodule defining it; imported on first access (module ``__getattr__``).
_EXPORTS = {
    "CurveResult": "curve_result",
    "Model": "curves",
    "PullOff": "curves",
    "load_curve": "curves",
    "pull_off": "curves",
    "separation_curve": "curves",
    "AreaFractionWarning": "physical_results",
    "CycleResult": "cycle",
    "PreloadCurve": "cycle",
    "preload_curve": "cycle",
    "ConstantShear": "friction_stress",
    "Elastic": "elastic_plastic",
    "JacksonGreen": "elastic_plastic",
    "LAWS": "elastic_plastic",
    "PlasticityWarning": "plasticity",
    "AsperityWarning": "_warnings",
    "HurtadoKim": "friction_stress",
    "GAUSSIAN": "heights",
    "Gaussian": "heights",
    "HeightDistribution": "heights",
    "Exponential": "heights",
    "Weibull": "heights",
    "PearsonIII": "heights",
    "Johnson": "heights",
    "Mixture": "heights",
    "Empirical": "heights",
    "parse_heights": "heights",
    "fit_heights": "heights",
    "LAMBDA_C": "maugis_dugdale",
    "md_branch_end": "maugis_dugdale",
    "md_pull_off": "maugis_dugdale",
    "md_solve": "maugis_dugdale",
    "contact_fraction": "multi_asperity",
    "friction_force": "multi_asperity",
    "mean_pressure": "multi_asperity",
    "normal_force": "multi_asperity",
    "real_contact_area": "multi_asperity",
    "sweep": "sweeps",
}

#: Public submodules reachable as attributes (``asperity.jkr``), imported on first access.
#: Any other public submodule (one added later) is found the same way.
_SUBMODULES = (
    "amontons",
    "asperity_law",
    "bodies",
    "cli",
    "cos",
    "curve_result",
    "curves",
    "cycle",
    "cycle_band",
    "dmt",
    "elastic_plastic",
    "explorer",
    "fit",
    "friction_stress",
    "groups",
    "height_sums",
    "heights",
    "hertz",
    "icha",
    "interaction",
    "jackson_green",
    "jackson_green_fits",
    "jackson_green_hardness",
    "jkr",
    "jkr_branch",
    "material_table",
    "materials",
    "maugis_dugdale",
    "maugis_dugdale_load",
    "maugis_dugdale_solve",
    "maugis_units",
    "multi_asperity",
    "instrument",
    "nix_gao",
    "persson",
    "physical",
    "physical_cycle",
    "physical_cycle_inputs",
    "physical_groups",
    "physical_results",
    "plasticity",
    "quadrature",
    "quantities",
    "reference",
    "regimes",
    "studies",
    "surface",
    "sweeps",
    "topography",
    "units",
    "validation",
)

__all__ = [
    "__version__",
    "CurveResult",
    "Model",
    "PullOff",
    "load_curve",
    "pull_off",
    "separation_curve",
    "AreaFractionWarning",
    "CycleResult",
    "PreloadCurve",
    "preload_curve",
    "ConstantShear",
    "Elastic",
    "JacksonGreen",
    "LAWS",
    "PlasticityWarning",
    "AsperityWarning",
    "HurtadoKim",
    "GAUSSIAN",
    "Gaussian",
    "HeightDistribution",
    "Exponential",
    "Weibull",
    "PearsonIII",
    "Johnson",
    "Mixture",
    "Empirical",
    "parse_heights",
    "fit_heights",
    "LAMBDA_C",
    "md_branch_end",
    "md_pull_off",
    "md_solve",
    "contact_fraction",
    "friction_force",
    "mean_pressure",
    "normal_force",
    "real_contact_area",
    "sweep",
]


def __getattr__(name: str):
    """Import a public name or submodule on first access (PEP 562)."""
    if name in _EXPORTS:
        value = getattr(importlib.import_module(f"{__name__}.{_EXPORTS[name]}"), name)
        globals()[name] = value  # later accesses skip this function
        return value
    if not name.startswith("_"):
        try:
            return importlib.import_module(f"{__name__}.{name}")  # also sets the attribute
        except ModuleNotFoundError as err:
            if err.name != f"{__name__}.{name}":  # the submodule exists but an import inside failed
                raise
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    """The public names, the public submodules and what is already loaded."""
    return sorted({*globals(), *__all__, *_SUBMODULES})
