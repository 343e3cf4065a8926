"""Optional panels: capabilities the explorer shows only where the installed library has them.

A panel is built by a factory in :data:`OPTIONAL_PANELS`, called once per page; the
factory returns None when its capability is missing (so the page has no trace of it),
and otherwise an object with

* ``layout``: a Bokeh layout, placed below the plot grid, with a checkbox ``toggle``;
* ``enabled`` and ``set_enabled(flag)``: whether the user asked for it (extra computations
  cost update time, so panels start switched off); a panel's figure joins the page with
  its first data (a figure without data has no ranges, which breaks the page's other plots);
* ``compute(result)``: the panel's library call for a view's
  :class:`~asperity.explorer.compute.Result`, run in the explorer's worker thread with
  the view's own computation (it touches no Bokeh model; a ValueError of the library
  becomes a message on the page);
* ``show(data)``: puts what ``compute`` returned into its figures, on the page's thread.

The approach/retract panel needs :mod:`asperity.cycle` (loading/unloading cycles); the fit
panel (:mod:`asperity.explorer.fit_panel`) needs :mod:`asperity.fit` and lmfit.  The panels
look their module up when a page opens, never at import.
"""

from __future__ import annotations

import importlib
import importlib.util

import numpy as np

from .compute import asperity_law, friction_law, height_distribution, model_gamma
from .plots import si_tick_formatter
from .state import MODES

__all__ = ["OPTIONAL_PANELS", "optional_panels", "cycle_panel", "CyclePanel"]


def _module(name: str):
    """The module ``asperity.<name>`` if it is installed, else None."""
    full = f"asperity.{name}"
    try:
        return importlib.import_module(full) if importlib.util.find_spec(full) is not None else None
    except ImportError:
        return None


class CyclePanel:
    """Approach and retract curves P(d) of one loading/unloading cycle (:mod:`asperity.cycle`).

    The cycle goes to the view's largest load (``preload``) and back, with the view's
    parameters: ``asperity.cycle.cycle(alpha, beta, gamma, preload=..., n=..., nu=...,
    h_over_b=..., friction=..., heights=..., law=...)`` in dimensionless mode,
    ``PhysicalContact.cycle(preload=..., n=...)`` in physical mode.  The pull-off force on
    retraction is marked.
    """

    def __init__(self, cycle_module):
        from bokeh.layouts import column
        from bokeh.models import Checkbox, ColumnDataSource, HoverTool, Range1d
        from bokeh.plotting import figure

        self.cycle = cycle_module
        self.enabled = False
        self.toggle = Checkbox(label="approach and retract: a loading-unloading cycle up to the largest load "
                                     "(asperity.cycle; each update takes longer)", active=False,
                               css_classes=["asp-toggle-cycle"])
        self.sources = {b: ColumnDataSource({"d": [], "P": []}, name=f"cycle:{b}") for b in ("approach", "retract")}
        self.marker = ColumnDataSource({"d": [], "P": []}, name="cycle:pull_off")
        fig = figure(width=1035, height=270, title="approach and retract (loading-unloading cycle)",
                     tools="pan,wheel_zoom,box_zoom,reset,save", name="plot:cycle", y_range=Range1d(-1.0, 1.0))
        lines = [fig.line("d", "P", source=source, line_width=2, color=colour, legend_label=branch)
                 for (branch, source), colour in zip(self.sources.items(), ("#1f77b4", "#d62728"), strict=True)]
        fig.scatter("d", "P", source=self.marker, size=9, color="#000000", legend_label="pull-off on retraction")
        fig.add_tools(HoverTool(renderers=lines, tooltips=[("d", "@d{%.4g}"), ("P", "@P{%.4g}")],
                                formatters={"@d": "printf", "@P": "printf"}))
        fig.legend.location = "top_right"
        fig.toolbar.autohide = True
        self.figure = fig
        self.layout = column(self.toggle)
        self.set_mode(physical=False)

    def set_enabled(self, flag: bool) -> None:
        """Switch the panel on (its figure appears with the next data) or off (the figure goes)."""
        self.enabled = bool(flag)
        if not self.enabled:
            self.layout.children = [self.toggle]

    def set_mode(self, physical: bool) -> None:
        """Axis labels in the units of a mode."""
        self.figure.xaxis.axis_label = "d (m)" if physical else "d/σ"
        self.figure.yaxis.axis_label = "P (N)" if physical else "P/NGb²"
        for axis in (self.figure.xaxis, self.figure.yaxis):  # '2 n' (nm, nN) as the other plots, not 2e-9
            axis.formatter = si_tick_formatter(physical)

    def compute(self, result):
        """The cycle of a view, from the library."""
        s = result.state
        preload = float(np.max(result.load.P))
        if s.mode == MODES[1]:
            return result.subject.cycle(preload=preload, n=s["n"])
        return self.cycle.cycle(s["alpha"], s["beta"], model_gamma(s), preload=preload, n=s["n"], nu=s["nu"],
                                h_over_b=s["h_over_b"], friction=friction_law(s), heights=height_distribution(s),
                                law=asperity_law(s))

    def show(self, cycle) -> None:
        """Plot both branches and the pull-off on retraction."""
        for name, source in self.sources.items():
            branch = getattr(cycle, name)
            source.data = {"d": np.asarray(branch.d), "P": np.asarray(branch.P)}
        po = cycle.pull_off
        self.marker.data = {"d": [po.d], "P": [-po.force]} if po.exists else {"d": [], "P": []}
        # Around the loop: from twice the pull-off force (tensile) to three times it; else the whole range.
        P = np.concatenate([np.asarray(cycle.approach.P), np.asarray(cycle.retract.P)])
        P = P[np.isfinite(P)]
        lo, hi = (-2.0 * po.force, 3.0 * po.force) if po.exists and po.force > 0 else (P.min(), P.max())
        pad = 0.05 * (hi - lo) if hi > lo else 1.0
        self.figure.y_range.update(start=lo - pad, end=hi + pad)
        if self.enabled and self.figure not in self.layout.children:
            self.layout.children = [self.toggle, self.figure]


def cycle_panel():
    """The approach/retract panel, or None without :mod:`asperity.cycle` (or its ``cycle`` function)."""
    cycle = _module("cycle")
    if cycle is None or not callable(getattr(cycle, "cycle", None)):
        return None
    return CyclePanel(cycle)


def _fit_panel():
    """The fit panel (:mod:`asperity.explorer.fit_panel`), or None without :mod:`asperity.fit` and lmfit."""
    from .fit_panel import fit_panel

    return fit_panel()


#: Factories of the optional panels, in page order.
OPTIONAL_PANELS = (cycle_panel, _fit_panel)


def optional_panels():
    """The factories of :data:`OPTIONAL_PANELS` (each returns a panel or None)."""
    return OPTIONAL_PANELS
