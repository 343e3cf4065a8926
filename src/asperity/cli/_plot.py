"""The ``--plot`` figure of ``asperity load`` and ``asperity separation``.

Two panels: mu and the real contact area against the load (load curves, log-log), or
|P| and F against the separation (separation curves, compressive and tensile parts of
P drawn apart).  matplotlib is imported only when a figure is drawn, through
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
    xs = getattr(curve, x)
    if x == "P":
        xlabel = r"$P$ (N)" if physical else r"$\bar P = P/NGb^2$"
        ax1.loglog(xs, curve.mu, "k-")
        ax1.set_xlabel(xlabel)
        ax1.set_ylabel(r"$\mu$")
        ax2.loglog(xs, curve.area, "k-")
        ax2.set_xlabel(xlabel)
        ax2.set_ylabel(r"real contact area $A$ (m$^2$)" if physical else r"$A/N\pi b^2$")
    else:
        pos = curve.P > 0
        ax1.semilogy(xs[pos], curve.P[pos], "k-", label="compressive $P$")
        if np.any(~pos):
            ax1.semilogy(xs[~pos], -curve.P[~pos], "r--", label="tensile $-P$")
        ax1.legend()
        xlabel = r"separation $d$ (m)" if physical else r"$d/\sigma$"
        ax1.set_xlabel(xlabel)
        ax1.set_ylabel(r"$|P|$ (N)" if physical else r"$|P|/NGb^2$")
        ax2.semilogy(xs, curve.F, "k-")
        ax2.set_xlabel(xlabel)
        ax2.set_ylabel(r"$F$ (N)" if physical else r"$F/NGb^2$")
    fig.suptitle(title)
    fig.savefig(path, dpi=150, format=fmt)
