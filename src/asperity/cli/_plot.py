"""The ``--plot`` figure of ``asperity load`` and ``asperity separation``.

Two panels: mu and the real contact area against the load (load curves, log-log; mu
only where the load is compressive), or |P| and F against the separation (separation
curves, compressive and tensile parts of P drawn apart; the legend appears only when a
tensile part is drawn, and names only what is drawn).  Physical separations are shown in
nm, µm or mm, whichever fits their size.  matplotlib is imported only when a figure is drawn, through
:func:`asperity._optional.require`, and only its object-oriented API is used (no pyplot,
no global backend), on the Agg canvas.
"""

from __future__ import annotations

__all__ = ["plot_curve"]


def plot_curve(curve, path: str, fmt: str, *, x: str, title: str, physical: bool = False) -> None:
    """Draw ``curve`` against ``x`` (``'P'`` or ``'d'``) and save it to ``path`` as ``fmt``.

    Raises
    ------
    asperity._optional.MissingDependency
        If matplotlib is not installed.
    ValueError
        For an image format matplotlib cannot write.
    """
    from .._optional import require

    require("matplotlib", purpose="--plot", extra="plot")
    import numpy as np
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(9, 3.6), layout="constrained")
    FigureCanvasAgg(fig)
    ax1, ax2 = fig.subplots(1, 2)
    xs = np.asarray(getattr(curve, x), dtype=float)
    dots = {"marker": "o", "markersize": 3} if xs.size < 20 else {}  # a point alone is drawn too
    if x == "P":
        xlabel = r"$P$ (N)" if physical else r"$\bar P = P/NGb^2$"
        pos = xs > 0  # mu is defined (and a log axis exists) only under a compressive load
        ax1.loglog(xs[pos], curve.mu[pos], "k-", **dots)
        ax1.set_xlabel(xlabel)
        ax1.set_ylabel(r"$\mu$")
        ax2.plot(xs, curve.area, "k-", **dots)
        ax2.set_yscale(_scale(curve.area))
        ax2.set_xscale("log" if np.all(pos) else "linear")  # tensile loads: a linear load axis
        ax2.set_xlabel(xlabel)
        ax2.set_ylabel(r"real contact area $A$ (m$^2$)" if physical else r"$A/N\pi b^2$")
    else:
        scale, unit = _length_unit(xs) if physical else (1.0, "")
        xs = xs / scale
        xlabel = f"separation $d$ ({unit})" if physical else r"$d/\sigma$"
        pos = curve.P > 0
        drawn = []
        if np.any(pos):
            drawn += ax1.semilogy(xs[pos], curve.P[pos], "k-", label="compressive $P$", **dots)
        if np.any(~pos & (curve.P < 0)):
            drawn += ax1.semilogy(xs[curve.P < 0], -curve.P[curve.P < 0], "r--", label="tensile $-P$", **dots)
        if any(line.get_label().startswith("tensile") for line in drawn):  # |P| needs saying which is which
            ax1.legend()
        ax1.set_xlabel(xlabel)
        ax1.set_ylabel(r"$|P|$ (N)" if physical else r"$|P|/NGb^2$")
        ax2.semilogy(xs, curve.F, "k-", **dots)
        ax2.set_xlabel(xlabel)
        ax2.set_ylabel(r"$F$ (N)" if physical else r"$F/NGb^2$")
    fig.suptitle(title)
    fig.savefig(path, dpi=150, format=fmt)


def _scale(values) -> str:
    """``'log'`` for positive values spanning more than a decade, else ``'linear'``."""
    import numpy as np

    v = np.asarray(values, dtype=float)
    v = v[np.isfinite(v)]
    return "log" if v.size and v.min() > 0 and v.max() > 10 * v.min() else "linear"


def _length_unit(d_m) -> tuple[float, str]:
    """A unit for separations in metres: the SI prefix of their largest magnitude (nm, um, mm, m)."""
    import numpy as np

    largest = float(np.max(np.abs(d_m))) if np.size(d_m) else 0.0
    for scale, unit in ((1e-9, "nm"), (1e-6, "µm"), (1e-3, "mm")):
        if largest < 1000 * scale:
            return scale, unit
    return 1.0, "m"
