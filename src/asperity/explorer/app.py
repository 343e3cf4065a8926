"""The explorer's page: one :class:`ExplorerSession` per browser tab of the Bokeh server.

A session reads its state from the page's query string, builds the controls from the
fields (:mod:`asperity.explorer.state`, :mod:`asperity.explorer.controls`), and on every
change computes the view with the library (:func:`asperity.explorer.compute.compute`):

* success: the plots, the derived numbers and the URL (``history.replaceState``) show the
  new view, and the messages panel the library's warnings;
* failure (the library rejects a value, or a typed value is not a number): the message
  says why, and the plots, numbers and URL keep the last good view.

The library computes in a worker thread while the page's thread keeps reading the
browser's changes; changes arriving meanwhile are merged into one update (the latest
values win), so dragging a slider never queues stale work.  The CSV buttons send the
library's own CSV (``CurveResult.to_csv`` / ``PhysicalCurve.to_csv``) of the curves shown;
the PNG button asks BokehJS to draw the plot grid into one image.  Nothing here computes:
every number comes from the library.
"""

from __future__ import annotations

import html
from functools import partial

from bokeh.core.properties import Int, String
from bokeh.layouts import column, row
from bokeh.model import DataModel
from bokeh.models import Button, CustomJS, Div, InlineStyleSheet, RadioButtonGroup

from . import compute as _compute
from .controls import make_control
from .panels import optional_panels
from .plots import SIZE, Plots
from .runner import attempt, immediate_runner, threaded_runner
from .state import (
    CUSTOM,
    MATERIAL_KEYS,
    MODES,
    default_state,
    fields,
    material_values,
    state_from_query,
    used,
)

__all__ = ["ExplorerSession", "PageState", "make_document", "attempt", "immediate_runner", "threaded_runner",
           "GROUPS"]

#: Sections of the control column: (heading, field keys); keys of the other mode are hidden.
GROUPS = (
    ("Model parameters", ("alpha", "beta", "gamma", "nu", "h_over_b", "law", "H_over_E", "h_star_over_sigma")),
    ("Physical contact", ("material", "E_Pa", "material_nu", "b_m", "w_J_m2", "H_Pa", "H0_Pa", "h_star_m",
                          "adhesion", "plasticity", "size_effect", "interaction", "sigma_s_m", "R_m", "eta_per_m2",
                          "area_m2")),
    ("Loads and separations", ("P_min", "P_max", "P_min_N", "P_max_N", "d_min", "d_max", "n")),
    ("Hurtado-Kim friction (τ in units of G*, radii in units of b)", ("tau_f1", "tau_f2", "a1", "a2")),
    ("Summit heights", ("heights",)),
)
CONTROL_WIDTH = 330
#: Heights (px) of the messages (at least two lines, growing with them up to about five
#: messages, then scrolling) and of the derived numbers in each mode.
MESSAGES_HEIGHT = 62
MESSAGES_MAX_HEIGHT = 160
DERIVED_HEIGHT = {"dimensionless": 112, "physical": 198}


class PageState(DataModel):
    """What the server tells the page: its query string, the HTML of the messages and numbers, a file to download."""

    query = String(default="", help="the view's query string, without '?'")
    messages_html = String(default="", help="errors, warnings and notes")
    derived_html = String(default="", help="the table of derived numbers")
    download_name = String(default="")
    download_text = String(default="")
    download_count = Int(default=0, help="incremented for each download request")


_URL_JS = "history.replaceState(history.state, '', window.location.pathname + '?' + page.query);"
#: Writes the messages and numbers into their (fixed-size) Divs' boxes directly: a change of a
#: Div's text would make BokehJS lay the whole page out again and repaint every plot.
#: A Div whose height changed (the messages grow with them) is rendered again with its own
#: (empty) text, after this runs: the write is repeated once the browser has laid it out.
_PANELS_JS = """
const write = () => {
  for (const [div, html] of [[messages, page.messages_html], [derived, page.derived_html]]) {
    const view = Bokeh.index.find_one(div);
    const box = view == null ? null : view.shadow_el.querySelector('.asp-box');
    if (box != null && box.innerHTML !== html) box.innerHTML = html;
  }
};
write();
setTimeout(write, 0);
requestAnimationFrame(() => requestAnimationFrame(write));
"""
_DOWNLOAD_JS = """
const blob = new Blob([page.download_text], {type: 'text/csv'});
const a = document.createElement('a');
a.href = URL.createObjectURL(blob);
a.download = page.download_name;
document.body.appendChild(a);
a.click();
a.remove();
setTimeout(() => URL.revokeObjectURL(a.href), 10000);
"""
_PNG_JS = """
const view = Bokeh.index.find_one(grid);
view.export('png').to_blob().then((blob) => {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = 'asperity-explorer.png';
  document.body.appendChild(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 10000);
});
"""


def _html_list(items, cls: str) -> str:
    return "".join(f'<div class="{cls}">{html.escape(text)}</div>' for text in items)


#: Styles of the messages and numbers (each Div renders in its own shadow root, so each gets them).
_STYLE = (".error{background:#fde8e8;border-left:4px solid #c81e1e;padding:4px 8px;margin:2px 0}"
          ".warning{background:#fdf6e3;border-left:4px solid #d39e00;padding:4px 8px;margin:2px 0}"
          ".note{background:#eef2f7;border-left:4px solid #6b7c93;padding:4px 8px;margin:2px 0}"
          ".quiet{color:#888;padding:4px 8px}table.derived td{padding:1px 10px 1px 0}")


class ExplorerSession:
    """The page of one browser tab (see the module docstring).

    Parameters
    ----------
    doc : bokeh.document.Document
        The session's document (the roots are added to it).
    query : str or mapping, optional
        The page's query string (or Tornado's parsed arguments).
    runner : callable, optional
        ``runner(work, done)`` calls ``work()`` (the library's computation of a view,
        :func:`attempt`) and then ``done(outcome)`` on the document's thread.  Default: in a
        worker thread (:func:`threaded_runner`); tests pass :func:`immediate_runner`.
    """

    def __init__(self, doc, query=None, *, runner=None):
        self.doc = doc
        self.runner = runner or threaded_runner(doc)
        self.fields = fields()
        wanted, self.link_messages = state_from_query(query or {})
        if wanted["material"] != CUSTOM:  # a link names a table material: its fields show its values
            wanted = wanted.replace(**material_values(wanted["material"]))
        self.pending = self.good = None
        self.result = None
        self.errors: dict[str, str] = {}
        self.failure: str | None = None
        self.panel_messages: list[str] = []
        self.busy, self.attempted = False, None
        self.controls = {key: make_control(f, wanted[key], self.on_value, self.on_error, width=CONTROL_WIDTH)
                         for key, f in self.fields.items() if key != "mode"}
        self.mode = RadioButtonGroup(labels=list(MODES), active=MODES.index(wanted.mode), name="input:mode",
                                     css_classes=["asp-input-mode"])
        self.mode.on_change("active", lambda attr, old, new: self.on_value("mode", MODES[new]))
        self.plots = Plots()
        # Fixed heights: new text never moves the plots (a moved plot repaints; updates stay quick).
        # Fixed sizes and content written by _PANELS_JS: new text never re-lays the page out.
        box = '<div class="asp-box"></div>'
        wide = 3 * SIZE["width"]  # the plots' row: nothing reaches past it
        self.messages = Div(text=box, width=wide, height=MESSAGES_HEIGHT, name="messages", css_classes=["asp-messages"],
                            stylesheets=[InlineStyleSheet(css=_STYLE)], styles={"overflow-y": "auto"})
        self.derived = Div(text=box, width=wide, height=DERIVED_HEIGHT[MODES[0]], name="derived",
                           css_classes=["asp-derived"], stylesheets=[InlineStyleSheet(css=_STYLE)])
        self.page = PageState(query="", name="page")
        self.page.js_on_change("query", CustomJS(args={"page": self.page}, code=_URL_JS))
        self.page.js_on_change("download_count", CustomJS(args={"page": self.page}, code=_DOWNLOAD_JS))
        write = CustomJS(args={"page": self.page, "messages": self.messages, "derived": self.derived}, code=_PANELS_JS)
        self.page.js_on_change("messages_html", write)
        self.page.js_on_change("derived_html", write)
        self.messages.js_on_change("height", write)
        self.derived.js_on_change("height", write)
        doc.js_on_event("document_ready", CustomJS(args={"page": self.page}, code=_URL_JS))
        doc.js_on_event("document_ready", write)
        self.panels = [panel for make in optional_panels() if (panel := make()) is not None]
        for panel in self.panels:
            panel.toggle.on_change("active", partial(self._toggled, panel))
            if hasattr(panel, "apply_to"):  # a panel that sets parameters (the fit panel's fitted values)
                panel.apply_to = self.set_values
            if hasattr(panel, "runner"):  # a panel with work of its own, run in the view's worker thread
                panel.runner = self.runner
        doc.add_root(self._layout())
        doc.add_root(self.page)
        doc.title = "asperity explore"
        self.pending = wanted
        self._start(wanted)

    # -- layout ---------------------------------------------------------------------------
    def _layout(self):
        csv_load = Button(label="Load curve CSV", width=140, name="button:csv-load",
                          css_classes=["asp-button-csv-load"])
        csv_sep = Button(label="Separation curve CSV", width=170, name="button:csv-separation",
                         css_classes=["asp-button-csv-separation"])
        png = Button(label="Figure PNG", width=110, name="button:png", css_classes=["asp-button-png"])
        csv_load.on_click(lambda: self.download("load"))
        csv_sep.on_click(lambda: self.download("separation"))
        png.js_on_click(CustomJS(args={"grid": self.plots.grid}, code=_PNG_JS))
        head = Div(text="<b style='font-size:1.3em'>asperity explore</b> &nbsp; multi-asperity contact, "
                        "adhesion and friction (Greenwood-Williamson, Hurtado-Kim, Maugis-Dugdale)", width=700)
        sections = [self.mode]
        self.sections = {}
        for heading, keys in GROUPS:
            items = [self.controls[k].layout for k in keys if k in self.controls]
            items += [c.layout for k, c in self.controls.items() if self.fields[k].group and "heights" in keys]
            box = column(Div(text=f"<b>{html.escape(heading)}</b>"), *items, width=CONTROL_WIDTH)
            self.sections[heading] = box
            sections.append(box)
        self.sections["Summit heights"].visible = len(self.fields["heights"].choices) > 1
        right = column(self.messages, self.derived, self.plots.layout,
                       *[p.layout for p in self.panels])
        return column(row(head, csv_load, csv_sep, png), row(column(*sections, width=CONTROL_WIDTH + 10), right))

    def _show_mode(self, state) -> None:
        self.derived.height = DERIVED_HEIGHT[state.mode]
        for key, control in self.controls.items():
            f = self.fields[key]
            visible = f.mode in (None, state.mode) and used(f, state.values)
            control.layout.visible = visible
        self.sections["Model parameters"].visible = state.mode == MODES[0]
        self.sections["Physical contact"].visible = state.mode == MODES[1]
        self.plots.set_mode(state.mode == MODES[1])
        for panel in self.panels:
            panel.set_mode(state.mode == MODES[1])

    # -- changes ----------------------------------------------------------------------------
    def on_value(self, key: str, value) -> None:
        """A control's new value: update the pending state and schedule an update."""
        if self.errors.pop(key, None) is not None:
            self._show_messages()
        changes = {key: value}
        note = None
        if key in MATERIAL_KEYS and self.pending["material"] != CUSTOM:
            table = self.pending["material"]
            changes["material"] = CUSTOM
            self.controls["material"].set(CUSTOM)
            note = self._custom_note(table) or note
        if key == "material" and value == CUSTOM and self.pending["material"] != CUSTOM:  # chosen in the menu
            note = self._custom_note(self.pending["material"]) or note
        if key == "material" and value != CUSTOM:
            changes.update(self._material_values(value))
        self.pending = self.pending.replace(**changes)
        if any(k in ("mode", "heights") or any(f.when and f.when[0] == k for f in self.fields.values())
               for k in changes):
            self._show_mode(self.pending)
        self.link_messages = [note] if note else []
        self.request()

    def _custom_note(self, table: str) -> str | None:
        """The custom copy of a table material keeps the fields' values where the table has none: say so."""
        lacking = [self.fields[k].label or k for k in MATERIAL_KEYS if k not in material_values(table)]
        if not lacking:
            return None
        return (f"custom material from {table}, which has no {', '.join(lacking)} in the table: the values shown "
                "for them are used")

    def set_values(self, values: dict) -> None:
        """Several parameters at once (a fit's values): the controls show them and the view updates."""
        for key, value in values.items():
            self.controls[key].set(value)
            self.errors.pop(key, None)  # a typed text the user had left invalid is replaced
        self.pending = self.pending.replace(**values)
        self.link_messages = []
        self.request()

    def _material_values(self, name: str) -> dict:
        """The table material's E, nu, b, w, H, h* shown in (and carried by) the custom fields."""
        values = material_values(name)
        for k, v in values.items():
            self.controls[k].set(v)
        return values

    def _active_panels(self) -> tuple:
        return tuple(p for p in self.panels if p.enabled)

    def _toggled(self, panel, attr, old, new) -> None:
        """A panel switched on or off: show or hide it, and compute it for the view shown."""
        panel.set_enabled(bool(new))
        if self.pending == self.attempted:
            self.attempted = None  # the same view again, now with (or without) the panel
        self.request()

    def on_error(self, key: str, message: str) -> None:
        """A control's text that is not a value: say so, keep the view."""
        self.errors[key] = message
        self._show_messages()

    def request(self) -> None:
        """Compute the pending state; while a computation runs, changes only update ``pending``
        and the latest is computed when it ends (so a dragged slider never queues stale work)."""
        if self.busy or self.pending == self.attempted:
            return
        self.busy, self.attempted = True, self.pending
        self.runner(partial(attempt, self.pending, self._active_panels()), partial(self._done, self.pending))

    def _done(self, state, outcome) -> None:
        self.busy = False
        self._apply(state, outcome)
        self.request()

    def update(self, state) -> bool:
        """Compute ``state`` now; show it if the library accepts it, else show why and keep the last view."""
        self.attempted = state
        return self._apply(state, attempt(state, self._active_panels()))

    def _apply(self, state, outcome) -> bool:
        if isinstance(outcome, str):
            self.failure = outcome
            self._show_messages()
            return False
        result = outcome
        self.failure = None
        self.good, self.result = state, result
        self.plots.update(_compute.load_columns(result), _compute.separation_columns(result),
                          _compute.pull_off_columns(result))
        self.panel_messages = list(result.extra_warnings)
        for panel, data in result.extras.items():
            if isinstance(data, str):
                self.panel_messages.append(f"{panel.toggle.label.split(':')[0]}: {data}")
            else:
                panel.show(data)
        self.page.derived_html = self._derived_html(result)
        self.page.query = state.to_query(self.fields)
        self._show_messages()
        return True

    def _start(self, wanted) -> None:
        """The first view: the link's, or if the library rejects it, the defaults (saying why)."""
        self._show_mode(wanted)
        if not self.update(wanted):
            notes = [*self.link_messages, f"the link's parameters were rejected ({self.failure}); showing the "
                                          f"default view of its mode ({wanted.mode})"]
            self.pending = default_state().replace(mode=wanted.mode)  # a physical link stays physical
            for key, control in self.controls.items():
                control.set(self.pending[key])
            self.mode.active = MODES.index(self.pending.mode)  # a mode change clears the link's notes
            self.link_messages = notes
            self._show_mode(self.pending)
            self.update(self.pending)

    # -- panels -----------------------------------------------------------------------------
    def _show_messages(self) -> None:
        errors = list(self.errors.values()) + ([self.failure] if self.failure else [])
        kept = ["the plots and numbers show the last valid parameters"] if errors and self.result else []
        cautions = (*self.result.warnings, *self.panel_messages) if self.result is not None and \
            self.good == self.pending else ()
        text = (_html_list(errors, "error") + _html_list(cautions, "warning")
                + _html_list(self.link_messages + kept, "note"))
        # each message: its lines of about 145 characters (18 px) and its padding and margin (12 px)
        need = 4 + sum(12 + 18 * max(1, -(-len(str(m)) // 145))
                       for m in (*errors, *cautions, *self.link_messages, *kept))
        self.messages.height = int(min(MESSAGES_MAX_HEIGHT, max(MESSAGES_HEIGHT, need)))
        self.page.messages_html = text or '<div class="quiet">no warnings from the library for this view</div>'

    @staticmethod
    def _derived_html(result) -> str:
        rows = "".join(f"<tr><td><b>{html.escape(n)}</b></td><td>{html.escape(v)}</td>"
                       f"<td style='color:#666'>{html.escape(m)}</td></tr>" for n, v, m in result.derived)
        return f"<table class='derived'>{rows}</table>"

    def download(self, which: str) -> None:
        """Send the library's CSV of the load or separation curve shown to the browser."""
        if self.result is None:
            return
        curve = self.result.load if which == "load" else self.result.separation
        self.page.download_name = f"asperity-{which}-curve.csv"
        self.page.download_text = curve.to_csv()
        self.page.download_count += 1


def make_document(doc) -> ExplorerSession:
    """The Bokeh application: an :class:`ExplorerSession` for the session's query string."""
    context = doc.session_context
    request = getattr(context, "request", None) if context is not None else None
    return ExplorerSession(doc, getattr(request, "arguments", None) or {})
