r"""The models put beside the boundary elements, by name, and the columns each one fills.

=============  ===================================================================================
name           model
=============  ===================================================================================
``gw``         Greenwood-Williamson with the summit parameters of the map, both estimates
               (spectral Nayak/McCool and detected summits; :class:`asperity.physical.PhysicalContact`,
               optionally with an ``interaction`` correction)
``icha``       interacting and coalescing Hertzian asperities on the map's own summits
               (:func:`asperity.icha.icha_contact`; Afferrante, Carbone & Demelio 2012)
``persson``    Persson's area :math:`\mathrm{erf}(\sqrt2\,p/E^*h')` from the rms slope of the map
               (:func:`asperity.persson.persson_area_fraction`)
``bgt``        the light-load asymptote of Bush, Gibson & Thomas, :math:`\sqrt{2\pi}\,p/E^*h'`
               (:func:`asperity.persson.bgt_area_fraction`)
=============  ===================================================================================

Each model's cost is measured with its own input analysis (summit statistics for GW, summit
detection and field tabulation for ICHA, the rms slope for Persson and BGT).
"""

from __future__ import annotations

import time

import numpy as np

from ..icha import icha_contact
from ..persson import bgt_area_fraction, persson_area_fraction, rms_slope
from ..quantities import VALIDATION_COLUMNS

__all__ = ["MODELS", "AREA_METHODS", "model_columns", "check_models", "run_icha", "run_slope_law"]

#: The models that can be put beside the boundary elements.
MODELS = ("gw", "icha", "persson", "bgt")
#: Area estimates (the ``method`` of :meth:`SurfaceValidation.deviation`) of each model.
AREA_METHODS = {"gw": ("spectral", "detected"), "icha": ("icha",), "persson": ("persson",), "bgt": ("bgt",)}
_BEM_COLUMNS = ("P_N", "p_Pa", "fraction_bem", "area_bem_m2", "gap_bem_m", "sep_bem_m", "spots_bem",
                "iterations_bem")


def check_models(models) -> tuple[str, ...]:
    """The models as a tuple of known names, in the order of :data:`MODELS` (a string: comma-separated)."""
    if isinstance(models, str):
        items = [m.strip() for m in models.split(",")]
        if any(not m for m in items):  # 'gw,,icha': an empty item is an error, never dropped (a review)
            raise ValueError(f"models: empty name in {models!r}; give names from {', '.join(MODELS)} separated "
                             "by commas")
        models = items
    try:
        names = list(models)
    except TypeError:
        raise TypeError(f"models must be names from {MODELS}, got {models!r}") from None
    bad = [m for m in names if not isinstance(m, str) or m not in MODELS]
    if bad or not names:
        raise ValueError(f"models must be one or more of {', '.join(MODELS)}, got {models!r}")
    return tuple(m for m in MODELS if m in names)


def model_columns(models) -> tuple[str, ...]:
    """The columns of a comparison with these models, in the order of the registry."""
    models = check_models(models)
    methods = [m for model in models for m in AREA_METHODS[model]]
    keep = set(_BEM_COLUMNS)
    for method in methods:
        keep |= {f"area_{method}_m2", f"dev_{method}"}
    if "gw" in models:
        keep |= {f"{c}_{m}_m" for c in ("gap", "sep") for m in ("spectral", "detected")}
        keep |= {"contacts_spectral", "contacts_detected"}
    if "icha" in models:
        keep |= {"gap_icha_m", "sep_icha_m", "spots_icha"}
    return tuple(name for name in VALIDATION_COLUMNS if name in keep)


def _deviation(area, bem_area):
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(bem_area > 0, area / np.where(bem_area > 0, bem_area, 1.0) - 1.0, np.nan)


def run_icha(topography, P, E_star, periodic, bem_area, **options):
    """ICHA on the map at the loads: (columns, seconds, curve)."""
    curve = icha_contact(topography, P, E_star=E_star, periodic=periodic, **options)
    cols = {"area_icha_m2": curve.area, "dev_icha": _deviation(curve.area, bem_area),
            "gap_icha_m": curve.mean_gap, "sep_icha_m": curve.separation, "spots_icha": curve.spots}
    return cols, curve.setup_seconds + float(np.sum(curve.seconds)), curve


def run_slope_law(name, topography, P, E_star, nominal_area, bem_area):
    """Persson's or BGT's area at the loads: (columns, seconds, rms slope)."""
    start = time.perf_counter()
    slope = rms_slope(topography)
    law = persson_area_fraction if name == "persson" else bgt_area_fraction
    area = law(np.asarray(P) / nominal_area, E_star, slope) * nominal_area
    seconds = time.perf_counter() - start
    return {f"area_{name}_m2": area, f"dev_{name}": _deviation(area, bem_area)}, seconds, slope
