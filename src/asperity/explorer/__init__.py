"""``asperity explore``: a live view of the model in the browser, served by a local Bokeh server.

The page has log sliders with typed entry for the model's parameters (dimensionless
groups, or a physical contact: material, surface and loads in SI units), plots linked to
them (friction coefficient, mean pressure, real contact area and contact fraction against
load; normal force with the pull-off marked and friction force against separation), the
derived numbers (Maugis lambda, adhesion regime, pull-off force, Tabor and Fuller-Tabor
parameters), every warning or error of the library, and buttons to download the curves
(the library's CSV) and the figure (PNG).  The view lives in the URL's query string.

Modules, each importing only downward:

* :mod:`~asperity.explorer.state`: the fields of a view and its query string (no Bokeh);
* :mod:`~asperity.explorer.compute`: a view's curves and numbers from the library (no Bokeh);
* :mod:`~asperity.explorer.labels`: plain-text labels from the quantity registry;
* :mod:`~asperity.explorer.controls`, :mod:`~asperity.explorer.plots`,
  :mod:`~asperity.explorer.panels`: the Bokeh widgets, figures and optional panels;
* :mod:`~asperity.explorer.app`: the page of one browser tab;
* :mod:`~asperity.explorer.server`: the Bokeh server in this process (:func:`serve`).

Only :mod:`state` and :mod:`compute` load without Bokeh (``pip install 'asperity[explore]'``).
"""

from __future__ import annotations

__all__ = ["serve", "start_server", "State", "state_from_query", "default_state"]


def __getattr__(name: str):
    """Lazy access: the state and compute functions need no Bokeh; the server does."""
    import importlib

    where = {"serve": "server", "start_server": "server", "State": "state", "state_from_query": "state",
             "default_state": "state"}
    if name in where:
        return getattr(importlib.import_module(f"{__name__}.{where[name]}"), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
