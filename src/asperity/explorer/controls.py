"""Bokeh widgets for the fields of a view, built from the quantity registry.

A number with a typical range in the registry gets a :class:`NumberControl`: a text entry
(titled with its plain-text symbol and unit, with the registry's help as tooltip) beside
a slider over the typical range, on log10 of the value where the registry says the
quantity spans decades.  Other numbers (load and separation ranges, points) get the
entry only; choices a menu; flags a checkbox.

Every control reports a new value through ``on_value(key, value)`` and a value it cannot
read through ``on_error(key, message)``; :meth:`set` changes what it shows without
reporting.  The slider stops at its ends; a typed value beyond them widens the slider.
"""

from __future__ import annotations

import math

from bokeh.layouts import row
from bokeh.models import Checkbox, Select, Slider, TextInput

from .labels import plain, unit_text
from .state import Field, number_text, parse_value

__all__ = ["NumberControl", "ChoiceControl", "FlagControl", "make_control", "slider_steps"]

#: Slider positions across a typical range.
SLIDER_STEPS = 300


def slider_steps(lo: float, hi: float, log: bool) -> tuple[float, float, float]:
    """Slider ``(start, end, step)`` over ``[lo, hi]`` (in log10 if ``log``)."""
    if log:
        lo, hi = math.log10(lo), math.log10(hi)
    return lo, hi, (hi - lo) / SLIDER_STEPS


def _title(f: Field) -> str:
    if f.label:
        text = f.label
    elif f.quantity is not None:
        text = plain(f.quantity.symbol)
    else:
        text = f.key
    return f"{text} ({unit_text(f.unit)})" if f.unit and f.unit != "1" else text


class NumberControl:
    """A text entry, with a slider when the registry gives a typical range (see the module docstring)."""

    def __init__(self, f: Field, value, on_value, on_error, *, width: int = 300):
        self.field, self.on_value, self.on_error = f, on_value, on_error
        self._quiet = False
        q = f.quantity
        self.log = bool(q is not None and q.log)
        has_slider = q is not None and q.typical is not None
        self.text = TextInput(value=number_text(value), title=_title(f), description=f.help or None,
                              width=100 if has_slider else width - 10, name=f"input:{f.key}",
                              css_classes=[f"asp-input-{f.key}"])
        self.text.on_change("value", self._typed)
        self.slider = None
        if has_slider:
            start, end, step = slider_steps(*q.typical, self.log)
            self.slider = Slider(start=start, end=end, step=step, value=start, show_value=False, title="",
                                 width=width - 120, align="end", name=f"slider:{f.key}",
                                 css_classes=[f"asp-slider-{f.key}"])
            self._place(value)
            self.slider.on_change("value", self._slid)
        self.layout = row(self.text, self.slider) if self.slider is not None else self.text

    # -- slider position <-> value ------------------------------------------------------
    def _position(self, value: float) -> float | None:
        if self.log:
            return math.log10(value) if value > 0 and math.isfinite(value) else None
        return value if math.isfinite(value) else None

    def value_at(self, position: float) -> float:
        """The value of a slider position, to 3 significant digits."""
        raw = 10.0**position if self.log else position
        return float(f"{raw:.3g}")

    def _place(self, value: float) -> None:
        """Move the slider to ``value``, widening its range if needed (not for values it cannot show)."""
        pos = self._position(float(value))
        if pos is None:
            pos = self.slider.start
        if pos < self.slider.start:
            self.slider.start = pos
        if pos > self.slider.end:
            self.slider.end = pos
        self.slider.value = pos

    # -- callbacks ------------------------------------------------------------------------
    def _slid(self, attr, old, new):
        if self._quiet:
            return
        value = self.value_at(new)
        self._quietly(lambda: setattr(self.text, "value", number_text(value)))
        self.on_value(self.field.key, value)

    def _typed(self, attr, old, new):
        if self._quiet:
            return
        try:
            value = parse_value(self.field, new)
        except ValueError as err:
            self.on_error(self.field.key, str(err))
            return
        if self.slider is not None:
            self._quietly(lambda: self._place(value))
        self.on_value(self.field.key, value)

    def _quietly(self, change) -> None:
        self._quiet = True
        try:
            change()
        finally:
            self._quiet = False

    def set(self, value) -> None:
        """Show ``value`` without reporting it."""
        def change():
            self.text.value = number_text(value)
            if self.slider is not None:
                self._place(value)
        self._quietly(change)


class ChoiceControl:
    """A menu of a choice field."""

    def __init__(self, f: Field, value, on_value, on_error, *, width: int = 300):
        self.field, self.on_value = f, on_value
        self._quiet = False
        self.widget = Select(title=_title(f), options=list(f.choices), value=value, description=f.help or None,
                             width=width - 10, name=f"input:{f.key}", css_classes=[f"asp-input-{f.key}"])
        self.widget.on_change("value", lambda attr, old, new: None if self._quiet else on_value(f.key, new))
        self.layout = self.widget

    def set(self, value) -> None:
        self._quiet = True
        try:
            self.widget.value = value
        finally:
            self._quiet = False


class FlagControl:
    """A checkbox of a flag field."""

    def __init__(self, f: Field, value, on_value, on_error, *, width: int = 300):
        self.field = f
        self._quiet = False
        self.widget = Checkbox(label=f"{f.label or f.key}: {f.help}", active=bool(value), width=width - 10,
                               name=f"input:{f.key}", css_classes=[f"asp-input-{f.key}"])
        self.widget.on_change("active", lambda attr, old, new: None if self._quiet else on_value(f.key, bool(new)))
        self.layout = self.widget

    def set(self, value) -> None:
        self._quiet = True
        try:
            self.widget.active = bool(value)
        finally:
            self._quiet = False


def make_control(f: Field, value, on_value, on_error, *, width: int = 300):
    """The control of a field: a menu, a checkbox or a number entry (with slider)."""
    cls = {"choice": ChoiceControl, "flag": FlagControl}.get(f.kind, NumberControl)
    return cls(f, value, on_value, on_error, width=width)
