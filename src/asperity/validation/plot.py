"""Figure of a side-by-side check: real area, mean gap and contact spots against load (matplotlib)."""

from __future__ import annotations

import os

import numpy as np

from .._atomic import atomic_path
from .._optional import require
from .._validation import check_image

__all__ = ["plot_validation"]

#: Line style and label of each area estimate.
_STYLES = {"spectral": ("b^--", "GW, spectral summits"), "detected": ("rs:", "GW, detected summits"),
           "icha": ("gD-", "ICHA (detected summits)"), "persson": ("mv-", "Persson"),
           "bgt": ("c<--", "BGT light-load asymptote")}  # every one with markers: a single load is seen too


def plot_validation(result, path, fmt: str | None = None) -> None:
    """Draw a :class:`~asperity.validation.SurfaceValidation` and save it to ``path``.

    Parameters
    ----------
    result : SurfaceValidation
        The comparison.
    path : str or os.PathLike
        Image file.
    fmt : str, optional
        Image format (default: from the file suffix, else png).

    Raises
    ------
    asperity._optional.MissingDependency
        Without matplotlib (``pip install 'asperity[plot]'``).
    """
    from .compare import SurfaceValidation

    if not isinstance(result, SurfaceValidation):
        raise TypeError(f"result must be a SurfaceValidation (asperity.validation.validate_surface), got "
                        f"{type(result).__name__}")
    path, fmt = check_image(path, fmt)
    require("matplotlib", purpose="plotting a validation", extra="plot")
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    t, A0 = result.columns(), result.bem.nominal_area
    fig = Figure(figsize=(11, 3.6), layout="constrained")
    FigureCanvasAgg(fig)
    ax1, ax2, ax3 = fig.subplots(1, 3)
    P = t["P_N"]
    ax1.loglog(P, t["fraction_bem"], "ko-", label="boundary elements")
    ax2.semilogx(P, t["gap_bem_m"] * 1e9, "ko-", label="boundary elements")
    ax3.loglog(P, t["spots_bem"], "ko-", label="BEM contact spots")
    suffix = "" if result.interaction == "none" else f" + {result.interaction}"
    for method in result.methods:
        style, label = _STYLES[method]
        label += suffix if method in ("spectral", "detected") else ""
        ax1.loglog(P, t[f"area_{method}_m2"] / A0, style, label=label)
        if f"gap_{method}_m" in t:
            ax2.semilogx(P, t[f"gap_{method}_m"] * 1e9, style, label=label)
    for name, (style, label) in (("contacts_spectral", _STYLES["spectral"]), ("contacts_detected",
                                                                             _STYLES["detected"]),
                                 ("spots_icha", _STYLES["icha"])):
        if name in t:
            ax3.loglog(P, np.maximum(t[name], 1e-300), style, label=label)
    ax1.set_ylabel("real contact area / nominal area")
    ax2.set_ylabel("mean gap (nm)")
    ax3.set_ylabel("contact spots / asperities in contact")
    for ax in (ax1, ax2, ax3):
        ax.set_xlabel("load P (N)")
    ax1.legend(fontsize=7)
    ax3.legend(fontsize=7)
    src = result.parameters.get("source") or "surface"
    fig.suptitle(f"{os.path.basename(str(src))}: {result.parameters['material']}, grid "
                 f"{result.bem.nb_grid_pts[0]}x{result.bem.nb_grid_pts[1]}, "
                 f"{'periodic' if result.bem.periodic else 'free'} boundaries")
    with atomic_path(path) as tmp:  # nothing is left behind if drawing fails
        fig.savefig(tmp, dpi=150, format=fmt)
