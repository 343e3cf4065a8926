"""Shared pieces of the paper's studies: curves with labels, checks, CSV rows, plot style.

Nothing here imports matplotlib at module level; :func:`new_figure` imports it when a
figure is drawn.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from functools import lru_cache
from typing import NamedTuple

import numpy as np

from .._atomic import atomic_path
from .._csv import rows_to_csv
from ..curves import COLUMNS, CurveResult, Model

#: Poisson's ratio and Dugdale range used for every study (the paper states h = b only).
NU = 0.3
H_OVER_B = 1.0

#: Figure size (inches) and resolution of the PNGs.
FIGSIZE = (6.0, 4.5)
DPI = 150

#: Axes position in the figure (fractions), room for tick labels and axis labels.
MARGINS = {"left": 0.13, "right": 0.97, "bottom": 0.115, "top": 0.975}

#: Colours of successive curves in one figure (colour-blind safe, prints in grey).
COLOURS = ("#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000")


@lru_cache(maxsize=64)
def model(alpha: float, beta: float, gamma: float = 0.0) -> Model:
    """The :class:`~asperity.Model` for one parameter set, shared by all studies.

    A Model caches its tabulated asperity law, so Figs 4-6 (which share the paper's
    default case) and Figs 7-9 (which share their cases) pay the set-up once.
    """
    return Model(alpha, beta, gamma, nu=NU, h_over_b=H_OVER_B)


@dataclass(frozen=True)
class Series:
    """One plotted curve: its parameters, a legend label and the model's output."""

    key: str  #: plain-text curve id, the ``curve`` column of the CSV
    label: str  #: legend label (matplotlib mathtext)
    alpha: float
    beta: float
    gamma: float
    curve: CurveResult
    adhesion: bool = True  #: False for the gamma = 0 baselines

    def column(self, name: str) -> np.ndarray:
        """A column of the curve, or a derived one: ``P_over_alpha``, ``alpha_mu``, ``abs_P``."""
        if name == "abs_P":
            return np.abs(self.curve.P)
        if name == "P_over_alpha":
            return self.curve.P / self.alpha
        if name == "alpha_mu":
            return self.alpha * self.curve.mu
        return np.asarray(getattr(self.curve, name))


class Check(NamedTuple):
    """A claim of the paper, whether our curves show it, and the numbers behind that."""

    claim: str
    passed: bool
    detail: str


@dataclass(frozen=True)
class FigureData:
    """Everything one figure shows: its curves and how they were chosen."""

    number: int
    title: str
    x: str  #: column plotted on x (see :meth:`Series.column`)
    y: str  #: column plotted on y
    series: tuple[Series, ...]
    caption: str
    parameters: str  #: what we chose and why (the paper does not state it)
    extra: dict = field(default_factory=dict)  #: figure-specific values (e.g. pull-offs)

    def find(self, key: str) -> Series:
        for s in self.series:
            if s.key == key:
                return s
        raise KeyError(key)


def check_data(data, figure: int) -> FigureData:
    """``data`` if it is a :class:`FigureData`; otherwise a TypeError naming ``data`` and the figure."""
    if not isinstance(data, FigureData):
        raise TypeError(f"data must be the FigureData of fig{figure}_data(), got {type(data).__name__}")
    return data


def key_of(alpha: float, beta: float, gamma: float) -> str:
    """Plain-text curve id, e.g. ``alpha=0.01 beta=1000 gamma=0.001``."""
    return f"alpha={alpha:g} beta={beta:g} gamma={gamma:g}"


def number_text(x: float, sci: bool = False) -> str:
    """Plain-text (Unicode) parameter value for legends: 1000 -> 10\u00b3, 0.005 -> 0.005.

    Exact powers of ten with ``|exponent| >= 2`` become ``10`` with a superscript (0.01
    stays 0.01 unless ``sci``); with ``sci`` other values become ``3\u00d710\u207b\u00b3``.
    Legends are plain text because mathtext costs ~25 ms a label per output format.
    """
    if x == 0:
        return "0"
    e = math.floor(math.log10(abs(x)) + 1e-12)
    m = x / 10.0**e
    power = "10" + str(e).translate(_SUPERSCRIPT)
    if math.isclose(m, 1.0, rel_tol=1e-9) and (abs(e) >= 3 or e == 2 or (sci and e != 0)):
        return power
    if sci and e != 0:
        return f"{m:g}\u00d7{power}"
    return f"{x:g}"


def params_text(**values) -> str:
    """Legend text such as ``\u03b1 = 0.01, \u03b2 = 10\u00b3`` (gamma in scientific form)."""
    greek = {"alpha": "\u03b1", "beta": "\u03b2", "gamma": "\u03b3"}
    return ", ".join(f"{greek[k]} = {number_text(v, sci=k == 'gamma')}" for k, v in values.items())


def load_series(alpha, beta, gamma, loads, *, label: str, adhesion: bool | None = None) -> Series:
    """A load curve (Figs 3-6, 9) from the shared :func:`model`."""
    curve = model(alpha, beta, gamma).load_curve(loads)
    return Series(key_of(alpha, beta, gamma), label, float(alpha), float(beta), float(gamma), curve,
                  adhesion=gamma > 0 if adhesion is None else adhesion)


def separation_series(alpha, beta, gamma, d, *, label: str) -> Series:
    """A separation curve (Figs 7-8) from the shared :func:`model`."""
    curve = model(alpha, beta, gamma).separation_curve(d)
    return Series(key_of(alpha, beta, gamma), label, float(alpha), float(beta), float(gamma), curve,
                  adhesion=gamma > 0)


# -- CSV ---------------------------------------------------------------------------------
#: Columns of every figure CSV, in order (long format: one row per plotted point).
CSV_COLUMNS = ("curve", "adhesion", "alpha", "beta", "gamma", "nu", "h_over_b", *COLUMNS,
               "P_over_alpha", "alpha_mu", "x", "y")


def csv_rows(data: FigureData) -> list[dict]:
    """Long-format rows of a figure: curve id, parameters, every column, and x, y plotted."""
    rows = []
    for s in data.series:
        cols = {name: s.column(name) for name in (*COLUMNS, "P_over_alpha", "alpha_mu")}
        x, y = s.column(data.x), s.column(data.y)
        for i in range(len(s.curve)):
            row = {"curve": s.key, "adhesion": s.adhesion, "alpha": s.alpha, "beta": s.beta,
                   "gamma": s.gamma, "nu": NU, "h_over_b": H_OVER_B}
            row.update({name: float(v[i]) for name, v in cols.items()})
            row["x"], row["y"] = float(x[i]), float(y[i])
            rows.append(row)
    return rows


def write_csv(path, rows: Sequence[dict], columns: Sequence[str]) -> None:
    """Write ``rows`` (dicts) with a header, atomically; floats at full precision (repr).

    The text is :func:`asperity._csv.rows_to_csv`'s, the library's one CSV writer.
    """
    rows_to_csv(rows, columns, path)


# -- plotting ----------------------------------------------------------------------------
RC = {
    "font.size": 10,
    "axes.labelsize": 11,
    "legend.fontsize": 8.5,
    "xtick.labelsize": 9.5,
    "ytick.labelsize": 9.5,
    "xtick.direction": "in",
    "ytick.direction": "in",
    "xtick.top": True,
    "ytick.right": True,
    "lines.linewidth": 1.5,
    "legend.frameon": False,
    "svg.fonttype": "path",
    "svg.hashsalt": "asperity",
}


def new_figure():
    """A (Figure, Axes) pair on the Agg canvas, paper size; never touches pyplot."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=FIGSIZE, dpi=DPI)
    FigureCanvasAgg(fig)
    # Fixed margins: every figure has the same kind of labels, and a layout engine would
    # double the time to save each figure.
    fig.subplots_adjust(**MARGINS)
    ax = fig.add_subplot()
    return fig, ax


def drawing(draw: Callable) -> Callable:
    """Decorator: run a drawing function inside the studies' matplotlib rc settings.

    The figure's log axes get plain-text tick labels (see :func:`log_ticks`).
    """

    def wrapper(data: FigureData):
        import matplotlib as mpl

        with mpl.rc_context(RC):
            fig = draw(data)
            for ax in fig.axes:
                log_ticks(ax)
        return fig

    wrapper.__name__ = draw.__name__
    wrapper.__qualname__ = draw.__qualname__
    wrapper.__doc__ = draw.__doc__
    return wrapper


def save_figure(fig, *paths) -> None:
    """Save ``fig`` to each path (format from the suffix) under the studies' rc settings.

    PNGs at :data:`DPI`; no timestamps or software versions in the files, so a rerun with
    the same library gives the same bytes.  Each file is written atomically (a temporary
    file renamed into place).
    """
    import matplotlib as mpl

    with mpl.rc_context(RC):
        for path in paths:
            fmt = str(path).rsplit(".", 1)[-1].lower()
            metadata = {"Date": None} if fmt == "svg" else {"Software": None} if fmt == "png" else None
            with atomic_path(path) as tmp:  # an interrupted save leaves no truncated image
                fig.savefig(tmp, dpi=DPI, metadata=metadata, format=fmt)


_SUPERSCRIPT = str.maketrans("-0123456789", "\u207b\u2070\u00b9\u00b2\u00b3\u2074\u2075\u2076\u2077\u2078\u2079")


def _power_of_ten(x, _pos=None) -> str:
    """Tick label ``10`` with a Unicode superscript exponent (mathtext would cost ~10 ms a label)."""
    if not x > 0:
        return ""
    e = round(math.log10(x))
    if not math.isclose(x, 10.0**e, rel_tol=1e-9):
        return ""
    return "10" + str(e).translate(_SUPERSCRIPT)


def _plain_number(x, _pos=None) -> str:
    """Tick label as a plain decimal (for log axes spanning few decades)."""
    return f"{x:g}" if x > 0 else ""


def log_ticks(ax) -> None:
    """Plain-text tick labels on each log axis of ``ax``.

    Powers of ten when the axis spans three decades or more; otherwise 1, 2 and 5 times
    powers of ten, as decimals, so that a short axis has more than one label.
    """
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

    for axis, lim in ((ax.xaxis, ax.get_xlim()), (ax.yaxis, ax.get_ylim())):
        if axis.get_scale() != "log":
            continue
        if math.log10(max(lim) / min(lim)) < 3.0:
            axis.set_major_locator(LogLocator(subs=(1.0, 2.0, 5.0)))
            axis.set_major_formatter(FuncFormatter(_plain_number))
        else:
            axis.set_major_formatter(FuncFormatter(_power_of_ten))
            if math.log10(max(lim) / min(lim)) > 6.0:
                # 2..9 on every decade would crowd a long axis (and each tick costs ~2 ms).
                axis.set_minor_locator(LogLocator(subs=(2.0, 5.0), numticks=100))
        axis.set_minor_formatter(NullFormatter())


def paired_curves(ax, data: FigureData, x: str, y: str, colour_of: Callable) -> None:
    """Log-log curves in pairs: solid with adhesion, dashed without, one colour per pair."""
    for s in data.series:
        ax.loglog(s.column(x), s.column(y), color=colour_of(s), ls="-" if s.adhesion else "--",
                  label=s.label if s.adhesion else None)


def _pixels(line) -> tuple[np.ndarray, np.ndarray]:
    """A line's points in display coordinates (pixels), finite points only."""
    x, y = (np.asarray(v, dtype=float) for v in line.get_data())
    ok = np.isfinite(x) & np.isfinite(y)
    ok &= (x > 0) if line.axes.get_xscale() == "log" else ok
    ok &= (y > 0) if line.axes.get_yscale() == "log" else ok
    xy = line.axes.transData.transform(np.column_stack([x[ok], y[ok]]))
    order = np.argsort(xy[:, 0])
    return xy[order, 0], xy[order, 1]


def _hides(upper, lower) -> bool:
    """True if the solid line ``upper``, drawn later in another colour, covers ``lower`` wherever it is drawn.

    Covered means: ``lower`` lies within ``upper``'s x range and within half of ``upper``'s
    line width (in pixels) of it at every point.  A dashed line never hides anything (the
    line below shows in its gaps).
    """
    from matplotlib.colors import same_color

    if upper.get_linestyle() not in ("-", "solid") or same_color(upper.get_color(), lower.get_color()):
        return False
    xu, yu = _pixels(upper)
    xl, yl = _pixels(lower)
    if xu.size < 2 or xl.size == 0 or xl.min() < xu.min() - 0.5 or xl.max() > xu.max() + 0.5:
        return False
    half_width = 0.5 * upper.get_linewidth() * upper.figure.dpi / 72.0
    return bool(np.all(np.abs(yl - np.interp(xl, xu, yu)) <= half_width))


def visible_legend_entries(ax) -> tuple[list, list[str]]:
    """The axes' legend handles and labels, without entries for curves nobody can see.

    A labelled curve hidden under a later one (:func:`_hides`: a solid line within half its
    width everywhere) loses its own entry; its label is added to the visible curve's
    (``'alpha = 0.1; also alpha = 0.06'``).  Curves without a point on the axes (e.g. an
    empty tensile part) never appear.  Call it after the axes limits are set.
    """
    lines = [ln for ln in ax.get_lines() if np.size(ln.get_xdata()) > 0]
    labelled = [ln for ln in lines if not ln.get_label().startswith("_")]
    hidden_by = {}
    for i, line in enumerate(lines):
        for later in lines[i + 1:]:
            if _hides(later, line):
                hidden_by[line] = later
                break
    extra: dict = {}
    for line in labelled:
        cover = hidden_by.get(line)
        while cover is not None and cover in hidden_by:
            cover = hidden_by[cover]
        if cover is not None and not cover.get_label().startswith("_"):
            extra.setdefault(cover, []).append(line.get_label())
    handles, labels = [], []
    for line in labelled:
        if line in hidden_by and any(line.get_label() in v for v in extra.values()):
            continue
        also = extra.get(line)
        handles.append(line)
        labels.append(line.get_label() + (f"; also {', '.join(also)}" if also else ""))
    return handles, labels


def adhesion_legend(ax, gamma: float, **kwargs) -> None:
    """The curves' legend plus two style entries: solid = with adhesion, dashed = without."""
    from matplotlib.lines import Line2D

    handles, labels = visible_legend_entries(ax)
    handles += [Line2D([], [], color="0.3", ls="-"), Line2D([], [], color="0.3", ls="--")]
    labels += ["with adhesion, " + params_text(gamma=gamma), "without adhesion, γ = 0"]
    ax.legend(handles, labels, **kwargs)


def log_decades_limits(values, pad: float = 0.15) -> tuple[float, float]:
    """Log-axis limits around the positive finite numbers in ``values`` (a list of arrays),
    padded by ``pad`` decades."""
    v = np.concatenate([np.ravel(np.asarray(x, dtype=float)) for x in values])
    v = v[np.isfinite(v) & (v > 0)]
    lo, hi = np.log10(v.min()), np.log10(v.max())
    return 10 ** (lo - pad), 10 ** (hi + pad)


def ratio_text(values) -> str:
    """Compact text of a sequence of numbers for check details."""
    return ", ".join(f"{v:.3g}" for v in values)
