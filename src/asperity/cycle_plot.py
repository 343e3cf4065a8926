"""The figure experimentalists draw of an approach-retract cycle.

Force against the displacement of the instrument's base (the separation under displacement
control): approach and retraction with arrows along the path, the whole-surface jumps dashed,
the loop (the energy dissipated) shaded, the pull-off force marked.  Works for a dimensionless
:class:`~asperity.cycle.CycleResult` and for a :class:`~asperity.physical_cycle.PhysicalCycle`
(newtons against nanometres).  matplotlib is imported only here, through
:func:`asperity._optional.require`, and only its object-oriented API is used (no pyplot).
"""

from __future__ import annotations

import math

import numpy as np

from ._optional import require

__all__ = ["plot_cycle"]

_COLORS = {"approach": "tab:blue", "retract": "tab:red"}


def _view(result):
    """(x, P) per branch, jump marks, pull-off point, labels and the energy text."""
    physical = hasattr(result, "energy_J")
    if physical:
        x_scale, P_scale = 1e9, 1e9  # nanometres, nanonewtons
        xlabel, ylabel = "base displacement Z (nm)", "force P (nN), compressive > 0"
        k = result.stiffness_N_m  # N/m = nN/nm
        energy = f"energy dissipated {result.energy_J:.3g} J ({result.energy_J_m2:.3g} J/m$^2$)"
    else:
        x_scale = P_scale = 1.0
        xlabel, ylabel = r"base displacement $Z/\sigma$ (= $d/\sigma$ without a spring)", r"$P/NGb^2$"
        k = result.stiffness
        energy = rf"energy dissipated {result.energy:.4g} $NGb^2\sigma$"
    branches = {}
    for name in ("approach", "retract"):
        b = getattr(result, name)
        branches[name] = (np.asarray(b.d_base) * x_scale, np.asarray(b.P) * P_scale, np.asarray(b.jump, dtype=bool))
    po = result.pull_off
    pull = None
    if po.exists:
        d, P = po.d * x_scale, -po.force * P_scale
        pull = (d - P / k if not math.isinf(k) else d, P)
    return branches, pull, xlabel, ylabel, energy


def _arrow(ax, x, y, color, scale):
    """An arrow along the path, in the middle of the stretch where the force is not negligible."""
    if x.size < 3:
        return
    busy = np.flatnonzero(np.abs(y) > 1e-2 * scale)
    i = int(np.clip(busy[busy.size // 2] if busy.size else x.size // 2, 1, x.size - 2))
    ax.annotate("", xy=(x[i + 1], y[i + 1]), xytext=(x[i - 1], y[i - 1]),
                arrowprops={"arrowstyle": "-|>", "color": color, "lw": 1.5, "mutation_scale": 16})


def plot_cycle(result, ax=None, *, title=None):
    """Draw ``result`` (a cycle) on ``ax`` (default: a new figure); return the axes.

    Parameters
    ----------
    result : CycleResult or PhysicalCycle
        The cycle.
    ax : matplotlib.axes.Axes, optional
        Where to draw; by default a new :class:`matplotlib.figure.Figure` (6.4 x 4.6 in, Agg canvas).
    title : str, optional
        Axes title.

    Returns
    -------
    matplotlib.axes.Axes

    Raises
    ------
    asperity._optional.MissingDependency
        If matplotlib is not installed (``pip install 'asperity[plot]'``).
    """
    from .cycle_result import CycleResult
    from .physical_cycle import PhysicalCycle

    if not isinstance(result, CycleResult | PhysicalCycle):
        raise TypeError(f"result must be a CycleResult or PhysicalCycle (asperity.cycle), got {type(result).__name__}")
    if ax is not None and not callable(getattr(ax, "fill_between", None)):
        raise TypeError(f"ax must be matplotlib Axes, got {type(ax).__name__}")
    if title is not None and not isinstance(title, str):
        raise TypeError(f"title must be a string, got {type(title).__name__}")
    require("matplotlib", purpose="plotting a cycle", extra="plot")
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    if ax is None:
        fig = Figure(figsize=(6.4, 4.6), layout="constrained")
        FigureCanvasAgg(fig)
        ax = fig.subplots()
    branches, pull, xlabel, ylabel, energy = _view(result)
    (xa, Pa, _), (xr, Pr, _) = branches["approach"], branches["retract"]
    scale = max(np.abs(Pa).max(initial=0.0), np.abs(Pr).max(initial=0.0))
    ax.fill(np.concatenate([xa, xr]), np.concatenate([Pa, Pr]), color="0.8", alpha=0.7, lw=0, label=energy)
    for name, (x, P, jump) in branches.items():
        color = _COLORS[name]
        starts = np.concatenate([[0], np.flatnonzero(jump)])
        ends = np.concatenate([np.flatnonzero(jump), [x.size]])
        for n, (a, b) in enumerate(zip(starts, ends, strict=True)):
            seg = slice(a, b)
            ax.plot(x[seg], P[seg], "-", color=color, lw=1.6, label=name if n == 0 else None)
            if n == 0 or b - a > 2:
                _arrow(ax, x[seg], P[seg], color, scale)
        for i in np.flatnonzero(jump):
            ax.plot(x[i - 1:i + 1], P[i - 1:i + 1], "--", color=color, lw=1.2,
                    label=f"jump ({name})" if i == np.flatnonzero(jump)[0] else None)
    if pull is not None:
        ax.plot(*pull, "k^", ms=8, label=f"pull-off {-pull[1]:.4g}")
    ax.axhline(0.0, color="0.5", lw=0.6)
    P_all = np.concatenate([Pa, Pr])
    x_all = np.concatenate([xa, xr])
    active = np.abs(P_all) > 1e-3 * np.abs(P_all).max() if P_all.size else np.zeros(0, dtype=bool)
    if np.any(active):
        lo, hi = x_all.min(), x_all[active].max()
        ax.set_xlim(lo - 0.03 * (hi - lo), hi + 0.1 * (hi - lo))
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    if title:
        ax.set_title(title, fontsize=9)
    ax.legend(fontsize=8, loc="best")
    return ax
