"""Optional panels: capabilities the explorer shows only where the installed library has them.

A panel is built by a factory in :data:`OPTIONAL_PANELS`, called once per page; the
factory returns None when its capability is missing, and otherwise an object with a
``layout`` (a Bokeh layout, placed below the plot grid) and ``update(result)`` (called
with each new :class:`~asperity.explorer.compute.Result`; it may raise the library's
ValueError, which the page shows as a message).

The approach/retract panel needs :mod:`asperity.cycle` (loading/unloading cycles); a fit
panel would follow the same pattern.  Both capabilities are being written alongside the
explorer, so their panels look the module up at run time, never at import.
"""

from __future__ import annotations

import importlib
import importlib.util

__all__ = ["OPTIONAL_PANELS", "optional_panels", "cycle_panel", "CyclePanel"]


def _module(name: str):
    """The module ``asperity.<name>`` if it is installed, else None."""
    full = f"asperity.{name}"
    try:
        return importlib.import_module(full) if importlib.util.find_spec(full) is not None else None
    except ImportError:
        return None


class CyclePanel:
    """Approach and retract curves P(d) of a loading/unloading cycle (:mod:`asperity.cycle`).

    Calls ``asperity.cycle.cycle_curve(subject, P_max)`` with the view's model (or physical
    contact) and its largest load, and plots each branch of the result (its ``branch``,
    ``d`` and ``P`` columns) against separation.
    """

    def __init__(self, cycle):
        from bokeh.models import ColumnDataSource
        from bokeh.plotting import figure

        self.cycle = cycle
        self.sources = {b: ColumnDataSource({"d": [], "P": []}, name=f"cycle:{b}") for b in ("approach", "retract")}
        fig = figure(width=700, height=270, title="approach and retract (loading/unloading cycle)",
                     tools="pan,wheel_zoom,box_zoom,reset,save,hover", name="plot:cycle")
        for (branch, source), colour in zip(self.sources.items(), ("#1f77b4", "#d62728"), strict=True):
            fig.line("d", "P", source=source, line_width=2, color=colour, legend_label=branch)
        fig.xaxis.axis_label, fig.yaxis.axis_label = "separation", "normal force"
        self.layout = fig

    def update(self, result) -> None:
        import numpy as np

        P_max = float(np.max(result.load.P))
        curve = self.cycle.cycle_curve(result.subject, P_max)
        columns = curve.columns()
        branch = np.asarray(columns["branch"]).astype(str)
        d_key = "d_m" if "d_m" in columns else "d"
        P_key = "P_N" if "P_N" in columns else "P"
        for name, source in self.sources.items():
            keep = branch == name
            source.data = {"d": np.asarray(columns[d_key])[keep], "P": np.asarray(columns[P_key])[keep]}


def cycle_panel():
    """The approach/retract panel, or None without :mod:`asperity.cycle` (or its ``cycle_curve``)."""
    cycle = _module("cycle")
    if cycle is None or not callable(getattr(cycle, "cycle_curve", None)):
        return None
    return CyclePanel(cycle)


#: Factories of the optional panels, in page order.
OPTIONAL_PANELS = (cycle_panel,)


def optional_panels():
    """The factories of :data:`OPTIONAL_PANELS` (each returns a panel or None)."""
    return OPTIONAL_PANELS
