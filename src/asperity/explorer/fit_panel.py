"""The fit panel: measured friction against load, fitted by the rough-surface model from the view.

An optional panel (:mod:`asperity.explorer.panels`) that exists where :mod:`asperity.fit`
does (the ``[fit]`` extra, lmfit).  Switched on, it offers a file field for a friction-load
table (the CSV of ``asperity fit``: a load column and a friction or friction-coefficient
column, optional uncertainties; see docs/fitting.md) and a button that fits
:math:`\\alpha, \\beta, \\gamma` of the Greenwood-Williamson model to it, starting from the
view's values and keeping the view's other parameters (:math:`\\nu`, :math:`h/b`, the
Hurtado-Kim constants, the summit heights):

``asperity.fit.fit_friction_load(data, GWFit(heights=...), start={alpha, beta, gamma},
fix={nu, h_over_b, tau_f1, tau_f2, a1, a2}, vary=('alpha', 'beta', 'gamma'))``.

With the view's Jackson-Green law (no adhesion) it fits :math:`\\alpha, \\beta, H/E^*` of
``GWFit(heights=..., law=JacksonGreen(...))`` instead, :math:`h^*/\\sigma` held.

The data, the fitted curve and the view's own curve are drawn together (log axes), the
fitted values with their standard errors and 95 % intervals listed, the fit's warnings
shown; a second button copies the fitted values into the view's controls.  Fitting is
dimensionless: in physical mode the panel says so (``asperity fit --material ...`` fits a
physical contact).  A fit runs in the explorer's worker thread (after, never beside, a
view's computation) and takes about a second; the page shows it when it ends.
"""

from __future__ import annotations

import base64
import html
import os
import re
import tempfile
from functools import partial

import numpy as np

from .compute import asperity_law, height_distribution
from .state import ELASTIC, MODES
from .wording import page_wording

__all__ = ["FitPanel", "fit_panel", "FIT_VARY", "PLASTIC_VARY", "fitted_names", "MAX_UPLOAD_BYTES"]

#: The parameters the panel fits (the others stay at the view's values).
FIT_VARY = ("alpha", "beta", "gamma")
#: The same with the Jackson-Green law of the view (no adhesion, no gamma: its hardness instead).
PLASTIC_VARY = ("alpha", "beta", "H_over_E")
#: Largest file the panel reads (a friction-load table is a few kB).
MAX_UPLOAD_BYTES = 5_000_000
_FIXED = ("nu", "h_over_b", "tau_f1", "tau_f2", "a1", "a2")


class FitPanel:
    """Fit alpha, beta, gamma to a friction-load file, from the view's parameters (:mod:`asperity.fit`).

    Parameters
    ----------
    fit_module : module
        :mod:`asperity.fit` (its ``fit_friction_load`` and ``read_data``).
    """

    #: The run button's label (the panel's messages name it).
    FIT_LABEL = "Fit from the view's values"

    def __init__(self, fit_module):
        from bokeh.layouts import column, row
        from bokeh.models import Button, Checkbox, ColumnDataSource, Div, FileInput, HoverTool
        from bokeh.plotting import figure

        self.fit = fit_module
        self.enabled = False
        self.state = None        # the view the panel last saw (the fit's start)
        self.data = None         # the Dataset read from the file
        self.result = None       # the last FitResult
        self.model = None        # the view's Model (dimensionless mode)
        self.apply_to = None     # set by the app: a function taking {name: value} for the controls
        self.runner = None       # set by the app: its runner (the worker thread); None: at once
        self.toggle = Checkbox(label="fit: alpha, beta, gamma (or H/E*) to measured friction against load "
                                     "(asperity.fit; about a second a fit)", active=False,
                               css_classes=["asp-toggle-fit"])
        self.upload = FileInput(accept=".csv,.txt,.dat", name="fit:file", css_classes=["asp-fit-file"])
        self.run_button = Button(label=self.FIT_LABEL, name="fit:run", width=220,
                                 css_classes=["asp-fit-run"], disabled=True)
        self.use_button = Button(label="Use the fitted values", name="fit:use", width=180,
                                 css_classes=["asp-fit-use"], disabled=True)
        self.info = Div(text="Choose a friction-load file (CSV: load and friction columns, as for "
                             "<code>asperity fit</code>).", width=1035, name="fit:info", css_classes=["asp-fit-info"])
        self.points = ColumnDataSource({"P": [], "F": [], "F_err": []}, name="fit:data")
        self.curve = ColumnDataSource({"P": [], "F": []}, name="fit:curve")
        self.view_curve = ColumnDataSource({"P": [], "F": []}, name="fit:view")
        fig = figure(width=1035, height=300, title="friction against load: data, fit and the view",
                     x_axis_type="log", y_axis_type="log", tools="pan,wheel_zoom,box_zoom,reset,save",
                     name="plot:fit", x_axis_label="P/NGb²", y_axis_label="F/NGb²")
        dots = fig.scatter("P", "F", source=self.points, size=6, color="#000000", legend_label="data")
        fitted = fig.line("P", "F", source=self.curve, line_width=2, color="#d62728", legend_label="fit")
        fig.line("P", "F", source=self.view_curve, line_width=1.5, color="#1f77b4", line_dash="dashed",
                 legend_label="the view")
        fig.add_tools(HoverTool(renderers=[dots, fitted], tooltips=[("P", "@P{%.4g}"), ("F", "@F{%.4g}")],
                                formatters={"@P": "printf", "@F": "printf"}))
        fig.legend.location = "top_left"
        fig.toolbar.autohide = True
        self.figure = fig
        self.controls = column(row(self.upload, self.run_button, self.use_button), self.info)
        self.layout = column(self.toggle)
        self.upload.on_change("value", self._uploaded)
        self.upload.on_change("filename", self._uploaded)
        self.run_button.on_click(self.run_fit)
        self.use_button.on_click(self.use_fitted)

    # -- the panel protocol ---------------------------------------------------------------------
    def set_enabled(self, flag: bool) -> None:
        """Show the file field, buttons and figure (on) or only the checkbox (off)."""
        self.enabled = bool(flag)
        self.layout.children = [self.toggle, self.controls, self.figure] if self.enabled else [self.toggle]

    def set_mode(self, physical: bool) -> None:
        """Fitting is dimensionless: in physical mode the run button is off and the panel says why."""
        self.physical = physical
        self._buttons()
        if physical:
            self.info.text = ("The fit panel fits the dimensionless model: switch to the dimensionless mode "
                              "(or fit a physical contact with <code>asperity fit --material ...</code>).")

    def compute(self, result):
        """The view's state and model, and its friction curve at the data's loads (cheap: no fit here)."""
        dimensionless = result.state.mode == MODES[0]
        data = self.data  # once: an upload on the page's thread may replace it meanwhile
        curve = result.subject.load_curve(np.asarray(data.x, dtype=float)) if data is not None and dimensionless \
            else None
        return result.state, result.subject if dimensionless else None, curve

    def show(self, data) -> None:
        """Remember the view (the next fit's start) and draw its curve beside the data."""
        self.state, self.model, curve = data
        self._show_view(curve)

    def _show_view(self, curve) -> None:
        self.view_curve.data = ({"P": [], "F": []} if curve is None else
                                {"P": np.asarray(curve.P), "F": np.asarray(curve.F)})

    # -- the file, the fit ----------------------------------------------------------------------
    def _uploaded(self, attr, old, new) -> None:
        """The browser sends a file's content and its name as two changes, in either order: read
        it once both have arrived."""
        try:
            content, filename = self.upload.value, self.upload.filename
        except ValueError:  # Bokeh's UnsetValueError: the other half has not arrived yet
            return
        self.read_upload(content, filename or "data.csv")

    def read_upload(self, content_b64: str, filename: str) -> None:
        """Read an uploaded file (base64, as Bokeh's FileInput gives it) as friction-load data."""
        self.data, self.result = None, None
        self.curve.data = {"P": [], "F": []}
        try:
            raw = base64.b64decode(content_b64 or "", validate=True)
        except ValueError:
            return self._say(f"{filename}: not a file the browser could send")
        if len(raw) > MAX_UPLOAD_BYTES:
            return self._say(f"{filename}: {len(raw)} bytes, more than {MAX_UPLOAD_BYTES} (a friction-load table)")
        # the copy's name keeps the file's extension (read_data reads by it); messages give the user's name
        name = re.sub(r"[^A-Za-z0-9._-]", "_", re.split(r"[\\/]", filename)[-1]).lstrip(".") or "data.csv"
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, name)  # the user's file name, so that messages name it
            with open(path, "wb") as fh:
                fh.write(raw)
            try:
                data = self.fit.read_data(path, kind="friction")
            except ValueError as err:
                return self._say(page_wording(str(err).replace(path, filename).replace(tmp, "")))
        if data.physical:
            return self._say(f"{filename}: loads with units (physical data); the panel fits the dimensionless "
                             "model: give P and F (or mu) in units of N G b^2, or use asperity fit --material")
        if data.x.size <= len(FIT_VARY):
            return self._say(f"{filename}: {data.x.size} points; a fit of {len(FIT_VARY)} parameters needs at least "
                             f"{len(FIT_VARY) + 1}")
        self.data = data
        F, F_err = self._friction(data)
        self.points.data = {"P": np.asarray(data.x), "F": F, "F_err": F_err}
        model = getattr(self, "model", None)
        try:
            self._show_view(None if model is None else model.load_curve(self._loads()))
        except ValueError:  # loads beyond the view's domain (more tensile than its pull-off)
            self._show_view(None)
        points = f"{data.x.size} point{'s' if data.x.size != 1 else ''}"
        self._say(f"{html.escape(filename)}: {points} read; press <b>{html.escape(self.FIT_LABEL)}</b>.",
                  escape=False)

    def run_fit(self):
        """Fit alpha, beta, gamma from the view's values; show the fitted curve and values.

        The fit runs through the explorer's runner (its one worker thread, so it never overlaps
        a view's computation: both record warnings, which is process-wide state) and is shown
        when it ends; with an immediate runner (tests, scripts) it is done on return, and the
        :class:`~asperity.fit.FitResult` is returned.
        """
        if self.data is None or self.state is None or self.state.mode != MODES[0]:
            return None
        work = partial(self._fit, self.data, self.state)
        self.run_button.disabled = True
        self.info.text = "fitting ..."
        (self.runner or _immediate)(work, self._fitted)
        return self.result

    def _fit(self, data, state):
        """The fit itself (in the worker thread): a FitResult, or the library's message."""
        from ..fit.gw import GWFit

        vary = fitted_names(state)
        fixed = _FIXED if vary == FIT_VARY else (*_FIXED, "h_star_over_sigma")
        try:
            # the view's summit heights and asperity law
            model = GWFit(heights=height_distribution(state), law=asperity_law(state))
            # Wald intervals: profile likelihoods of nearly degenerate parameters (alpha and beta
            # often correlate at |r| ~ 0.999 in friction-load data) can take minutes, and the page
            # would wait; the correlation warning is shown with the intervals.
            return self.fit.fit_friction_load(data, model, start={k: state[k] for k in vary},
                                              fix={k: state[k] for k in fixed}, vary=vary, ci="wald")
        except ValueError as err:
            return f"the fit failed: {page_wording(str(err))}"

    def _fitted(self, outcome) -> None:
        """Show a fit's outcome (on the page's thread)."""
        if isinstance(outcome, str):
            self.result = None
            self._say(outcome)
            return
        self.result = outcome
        c = outcome.curve
        self.curve.data = {"P": np.asarray(c.P), "F": np.asarray(c.F)}
        self.info.text = self._report(outcome)
        self._buttons()

    def use_fitted(self) -> None:
        """Copy the fitted values (alpha, beta and gamma or H/E*) into the view's controls (the view then updates)."""
        if self.result is not None and self.apply_to is not None:
            self.apply_to({k: float(self.result.values[k]) for k in _varied(self.result)})

    # -- helpers --------------------------------------------------------------------------------
    def _loads(self) -> np.ndarray:
        return np.asarray(self.data.x, dtype=float)

    @staticmethod
    def _friction(data):
        """Friction F and its uncertainty from a data set of F or mu against P."""
        x, y = np.asarray(data.x), np.asarray(data.y)
        err = np.full(x.size, np.nan) if data.y_err is None else np.asarray(data.y_err)
        return (y, err) if data.quantity == "F" else (y * x, err * x)

    def _buttons(self) -> None:
        physical = getattr(self, "physical", False)
        self.run_button.disabled = self.data is None or physical
        self.use_button.disabled = self.result is None or physical

    def _say(self, text: str, escape: bool = True) -> None:
        self.info.text = html.escape(text) if escape else text
        self._buttons()

    @staticmethod
    def _report(r) -> str:
        rows = []
        for name in _varied(r):
            p = r.parameters[name]
            err = "—" if p.stderr is None or not np.isfinite(p.stderr) else f"{p.stderr:.3g}"
            lo, hi = (np.nan if x is None else float(x) for x in (p.ci95 or (None, None)))
            ci = f"[{lo:.4g}, {hi:.4g}]" if np.isfinite(lo) and np.isfinite(hi) else "—"
            rows.append(f"<tr><td>{name}</td><td>{p.value:.6g}</td><td>± {err}</td><td>{ci}</td></tr>")
        notes = "".join(f"<li>{html.escape(page_wording(w))}</li>" for w in r.warnings)
        return ("<table class='asp-fit-table'><tr><th>parameter</th><th>value</th><th>standard error</th>"
                f"<th>95 % interval</th></tr>{''.join(rows)}</table>"
                f"<div>χ² = {r.chisqr:.4g} over {r.n_points} points, AIC = {r.aic:.4g}</div>"
                + (f"<ul>{notes}</ul>" if notes else ""))


def _varied(result) -> list[str]:
    """The names a fit varied, in the model's order."""
    return [name for name, p in result.parameters.items() if p.vary]


def fitted_names(state) -> tuple[str, ...]:
    """The parameters the panel fits for a view: :data:`FIT_VARY` with the elastic law,
    :data:`PLASTIC_VARY` with the Jackson-Green law."""
    return FIT_VARY if state["law"] == ELASTIC else PLASTIC_VARY


def _immediate(work, done) -> None:
    done(work())


def fit_panel():
    """The fit panel, or None without :mod:`asperity.fit` (or lmfit, which it needs)."""
    import importlib
    import importlib.util

    try:
        if importlib.util.find_spec("lmfit") is None or importlib.util.find_spec("asperity.fit") is None:
            return None
        fit = importlib.import_module("asperity.fit")
    except ImportError:
        return None
    if not (callable(getattr(fit, "fit_friction_load", None)) and callable(getattr(fit, "read_data", None))):
        return None
    return FitPanel(fit)
