"""The figure of a fit: data with the fitted curve, and the weighted residuals below.

One column per data set.  Friction-load data spanning more than a decade of positive loads
are drawn on log-log axes.  matplotlib is imported lazily (``asperity[plot]``), only its
object-oriented API is used (no pyplot), and a path is written atomically.
"""

from __future__ import annotations

import numpy as np

from .._atomic import atomic_path
from .._optional import require
from .._validation import check_image

__all__ = ["plot_fit"]

_LABELS = {"friction": ("load", "friction"), "force": ("separation", "normal force"),
           "pull_off": ("row (condition)", "pull-off force")}


#: SI prefixes of the axes, by power of ten.
_PREFIX = {12: "T", 9: "G", 6: "M", 3: "k", 0: "", -3: "m", -6: "µ", -9: "n", -12: "p", -15: "f"}


def _si_axis(values, unit: str) -> tuple[float, str]:
    """The factor and label of an axis in ``unit`` with the SI prefix of its largest value
    (nanonewtons for AFM forces rather than 1e-8 N and an offset)."""
    finite = np.abs(np.asarray(values, dtype=float))
    finite = finite[np.isfinite(finite) & (finite > 0)]
    if not unit or finite.size == 0:
        return 1.0, f" ({unit})" if unit else ""
    k = int(np.clip(3 * np.floor(np.log10(finite.max()) / 3), -15, 12))
    return 10.0**-k, f" ({_PREFIX[k]}{unit})"


def _curve_xy(curve, data):
    cols = curve.columns()
    if data.kind == "friction":
        x = cols.get("P_N", cols.get("P"))
        y = cols["mu"] if data.quantity == "mu" else cols.get("F_N", cols.get("F"))
    elif data.kind == "force":
        x, y = cols.get("d_m", cols.get("d")), cols.get("P_N", cols.get("P"))
    else:
        x, y = cols["row"], cols.get("pull_off_N", cols.get("pull_off"))
    return np.asarray(x, dtype=float), np.asarray(y, dtype=float)


def plot_fit(result, path=None, *, fmt=None):
    """Draw ``result`` (a :class:`~asperity.fit.result.FitResult`); save to ``path`` if given.

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    asperity._optional.MissingDependency
        Without matplotlib.
    """
    from .result import FitResult

    if not isinstance(result, FitResult):
        raise TypeError(f"result must be an asperity.fit FitResult, got {type(result).__name__}")
    if path is not None:
        path, fmt = check_image(path, fmt)
    require("matplotlib", purpose="plotting a fit", extra="plot")
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    n = len(result.datasets)
    fig = Figure(figsize=(4.6 * n, 5.2), layout="constrained")
    FigureCanvasAgg(fig)
    axes = fig.subplots(2, n, squeeze=False, sharex="col", gridspec_kw={"height_ratios": [3, 1]})
    start = 0
    for k, (data, curve) in enumerate(zip(result.datasets, result.curves, strict=True)):
        top, bottom = axes[0, k], axes[1, k]
        r = result.residuals[start:start + len(data)]
        start += len(data)
        xl, yl = _LABELS[data.kind]
        fx, unit_x = _si_axis(data.x, {"friction": "N", "force": "m"}.get(data.kind, "") if data.physical else "")
        fy, unit_y = _si_axis(data.y, "N" if data.physical and data.quantity != "mu" else "")
        top.errorbar(data.x * fx, data.y * fy, yerr=None if data.y_err is None else data.y_err * fy,
                     xerr=None if data.x_err is None else data.x_err * fx, fmt="o", ms=4, color="k", label="data")
        cx, cy = _curve_xy(curve, data)
        order = np.argsort(cx)
        top.plot(cx[order] * fx, cy[order] * fy, "-", color="C3", label=f"fit: {result.model}")
        log = data.kind == "friction" and np.min(data.x) > 0 and np.max(data.x) / np.min(data.x) > 10
        if log and np.all(data.y > 0):
            top.set_xscale("log")
            top.set_yscale("log")
        top.set_ylabel(("friction coefficient" if data.quantity == "mu" else yl) + unit_y)
        top.set_title(data.name or data.kind)
        top.legend(loc="best", fontsize="small")
        bottom.axhline(0.0, color="0.6", lw=0.8)
        bottom.plot(data.x * fx, r, "o", ms=3, color="C0")
        bottom.set_xlabel(xl + unit_x)
        bottom.set_ylabel(f"residual ({result.weights[k]})")
    fig.suptitle(f"{result.model}: chi-square {result.chisqr:.4g}, AIC {result.aic:.4g}", fontsize="medium")
    if path is not None:
        with atomic_path(path) as tmp:
            fig.savefig(tmp, dpi=150, format=fmt)
    return fig
