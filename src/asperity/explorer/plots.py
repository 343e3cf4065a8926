"""The linked plots of the explorer: Bokeh figures over three data sources.

* ``load`` (one row per load): the library's load curve, plotted against the load on log
  axes as in the paper's Figs 3-6 and 9: friction coefficient, mean pressure, real contact
  area, and the fraction of asperities in contact (with, in physical mode, the real over
  nominal area and the 10 % line above which the model degrades);
* ``separation`` (one row per separation): normal and friction force against separation
  on a log force axis, as Figs 7-8; the tensile part of the normal force is plotted as
  :math:`-P`, dashed;
* ``pull_off``: the most tensile force, marked on the normal-force plot.

The four load plots share their x range, the two separation plots theirs (pan and zoom
one, the others follow); hovering shows the values of every column at that point.
Column names are the library's attribute names (``P``, ``mu``, ``d``, ...), in SI units
in physical mode; axis labels and titles come from :data:`asperity.quantities.CURVE_COLUMNS`.
"""

from __future__ import annotations

from bokeh.layouts import column, row
from bokeh.models import (
    BasicTickFormatter,
    ColumnDataSource,
    CustomJSTickFormatter,
    DataRange1d,
    HoverTool,
    Legend,
    Span,
)
from bokeh.plotting import figure

from ..physical import AREA_FRACTION_CAUTION
from ..quantities import CURVE_COLUMNS
from .labels import axis_label, title

__all__ = ["Plots", "LOAD_COLUMNS", "SEPARATION_COLUMNS", "si_tick_formatter"]

LOAD_COLUMNS = ("d", "P", "F", "mu", "area", "pressure", "contacts", "fraction", "area_fraction")
SEPARATION_COLUMNS = ("d", "P", "F", "mu", "area", "pressure", "contacts", "P_compressive", "P_tensile")
COLOURS = {"line": "#1f77b4", "second": "#d62728", "marker": "#000000", "limit": "#7f7f7f"}
TOOLS = "pan,wheel_zoom,box_zoom,reset,save"
SIZE = {"width": 345, "height": 265}

#: Log-axis ticks: powers of ten as 10ⁿ (1 and 10 plain); others (an axis within one decade)
#: plain from 0.001 to 9999, else as 2×10ⁿ.
_LOG_TICKS = """
const sup = (n) => String(n).replace(/[-0-9]/g, (c) => '⁻⁰¹²³⁴⁵⁶⁷⁸⁹'['-0123456789'.indexOf(c)]);
if (!(tick > 0)) return '';
const e = Math.floor(Math.log10(tick) + 1e-9);
const m = tick / Math.pow(10, e);
if (Math.abs(m - 1) < 1e-6) return e === 0 ? '1' : (e === 1 ? '10' : '10' + sup(e));
const digits = Number(m.toPrecision(2));
return (e >= -3 && e <= 3) ? String(Number(tick.toPrecision(2))) : digits + '×10' + sup(e);
"""


#: Linear ticks of a physical quantity with an SI prefix (``-2 n``, ``500 p``; the unit is in the label).
_SI_TICKS = """
if (tick === 0) return '0';
const prefixes = {'-15': 'f', '-12': 'p', '-9': 'n', '-6': 'µ', '-3': 'm', '0': '', '3': 'k', '6': 'M', '9': 'G'};
const top = Math.max(...ticks.map(Math.abs));
const e = Math.min(9, Math.max(-15, 3 * Math.floor(Math.log10(top) / 3)));
return String(Number((tick / Math.pow(10, e)).toPrecision(4))) + ' ' + prefixes[String(e)];
"""


def si_tick_formatter(physical: bool):
    """Tick formatter of a linear axis: SI prefixes in physical mode (the unit is in the label), plain otherwise."""
    return CustomJSTickFormatter(code=_SI_TICKS) if physical else BasicTickFormatter()


def _log_ticks(axis) -> None:
    axis.formatter = CustomJSTickFormatter(code=_LOG_TICKS)


def _empty(columns) -> dict:
    return {c: [] for c in columns}


def _tooltips(columns, physical: bool):
    rows = [(axis_label(CURVE_COLUMNS[c], physical), f"@{{{c}}}{{%.4g}}") for c in columns]
    return rows, {f"@{{{c}}}": "printf" for c in columns}


class Plots:
    """The sources, figures and their grid (``layout``); :meth:`set_mode` relabels for a mode."""

    def __init__(self):
        self.load = ColumnDataSource(_empty(LOAD_COLUMNS), name="load")
        self.separation = ColumnDataSource(_empty(SEPARATION_COLUMNS), name="separation")
        self.pull_off = ColumnDataSource({"d": [], "force": []}, name="pull_off")
        x_load, x_sep = DataRange1d(), DataRange1d()
        self.hovers = []
        self.figures = {}
        for key, y in (("mu", "mu"), ("pressure", "pressure"), ("area", "area"), ("fraction", "contacts")):
            fig = figure(x_axis_type="log", y_axis_type="log", x_range=x_load, tools=TOOLS, name=f"plot:{key}",
                         **SIZE)
            _log_ticks(fig.xaxis)
            _log_ticks(fig.yaxis)
            col = "fraction" if key == "fraction" else y
            line = fig.line("P", col, source=self.load, line_width=2, color=COLOURS["line"])
            self._hover(fig, line, ("P", "mu", "d", "F", "area", "pressure", "contacts"))
            self.figures[key] = fig
        frac = self.figures["fraction"]
        self.area_fraction = frac.line("P", "area_fraction", source=self.load, line_width=2, color=COLOURS["second"],
                                       line_dash="dotdash")
        self.limit = Span(location=AREA_FRACTION_CAUTION, dimension="width", line_dash="dashed",
                          line_color=COLOURS["limit"])
        frac.add_layout(self.limit)
        self.fraction_legend = Legend(items=[("asperities in contact n/N", [frac.renderers[0]]),
                                             ("real / nominal area A/A0", [self.area_fraction])],
                                      location="bottom_right", background_fill_alpha=0.7)
        frac.add_layout(self.fraction_legend)
        for key, y in (("force", "P_compressive"), ("friction", "F")):
            fig = figure(x_range=x_sep, y_axis_type="log", tools=TOOLS, name=f"plot:{key}", **SIZE)
            _log_ticks(fig.yaxis)
            line = fig.line("d", y, source=self.separation, line_width=2, color=COLOURS["line"])
            self._hover(fig, line, ("d", "P", "F", "mu", "area", "contacts"))
            self.figures[key] = fig
        force = self.figures["force"]
        tensile = force.line("d", "P_tensile", source=self.separation, line_width=2, color=COLOURS["line"],
                             line_dash="dashed")
        self._hover(force, tensile, ("d", "P", "F", "mu", "area", "contacts"))
        marker = force.scatter("d", "force", source=self.pull_off, size=9, color=COLOURS["marker"])
        force.add_layout(Legend(items=[("compressive: P", [force.renderers[0]]), ("tensile: −P", [tensile]),
                                       ("pull-off force", [marker])], location="bottom_left",
                                background_fill_alpha=0.7))
        x_sep.renderers = [force.renderers[0], tensile, self.figures["friction"].renderers[0]]
        f = self.figures
        for fig in f.values():
            fig.toolbar.autohide = True  # each plot's tools show when the pointer is over it
        # Rows in a column rather than a GridPlot: BokehJS (3.9) garbles a GridPlot's plots when
        # another plot joins the page later (the optional panels do).
        self.grid = column(row(f["mu"], f["pressure"], f["area"]), row(f["force"], f["friction"], f["fraction"]),
                           name="plots")
        self.layout = self.grid
        self.set_mode(physical=False)

    def _hover(self, fig, renderer, columns):
        hover = HoverTool(renderers=[renderer], mode="vline")
        fig.add_tools(hover)
        self.hovers.append((hover, columns))

    def set_mode(self, physical: bool) -> None:
        """Axis labels, titles and tooltips in the units of a mode; A/A0 and its limit in physical mode."""
        C = CURVE_COLUMNS
        for key, fig in self.figures.items():
            x = C["d"] if key in ("force", "friction") else C["P"]
            y = {"force": C["P"], "friction": C["F"], "fraction": C["contacts"]}.get(key, C.get(key))
            fig.xaxis.axis_label = axis_label(x, physical)
            fig.yaxis.axis_label = axis_label(y, physical and key != "fraction")
            fig.title.text = title(y, physical and key != "fraction")  # the legend tells compressive from tensile
            fig.title.text_font_size = "12px"  # the registry's longest meanings fit the plot's width
        for key in ("force", "friction"):
            self.figures[key].xaxis.formatter = si_tick_formatter(physical)
        self.figures["fraction"].yaxis.axis_label = "n/N, A/A0" if physical else axis_label(C["contacts"], False)
        self.figures["fraction"].title.text = "contact fraction"
        for item in (self.area_fraction, self.limit, self.fraction_legend):
            item.visible = physical
        for hover, columns in self.hovers:
            hover.tooltips, hover.formatters = _tooltips(columns, physical)

    def update(self, load: dict, separation: dict, pull_off: dict) -> None:
        """Replace the data of the three sources (columns as in :data:`LOAD_COLUMNS` and :data:`SEPARATION_COLUMNS`)."""
        self.load.data = {c: load[c] for c in LOAD_COLUMNS}
        self.separation.data = {c: separation[c] for c in SEPARATION_COLUMNS}
        self.pull_off.data = pull_off
