"""``asperity plot``: a heat map of a finished sweep (NetCDF or Zarr).

``asperity plot map.nc --x alpha --y gamma --z pull_off`` draws the variable ``--z`` over
two dimensions of the sweep; any other dimension is fixed with ``--at NAME=VALUE`` (the
nearest value).  Axes are logarithmic for the quantities :mod:`asperity.quantities` marks
``log``, and so is the colour scale when every value is positive; the colour bar carries
the variable's meaning and units from the file's attributes.
"""

from __future__ import annotations

import argparse
import math
import os
import warnings

from .._numbers import strict_float
from .._warnings import AsperityWarning
from ._args import UsageError, output_file

NAME = "plot"
HELP = "heat map of a finished sweep"
DESCRIPTION = "Draw one variable of a sweep (asperity sweep) over two of its dimensions as a heat map."
EPILOG = """Example:
  asperity plot map.nc --x alpha --y gamma --z pull_off -o pull_off.png
  asperity plot map.nc --x alpha --y gamma --z mu --at P=10"""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("store", metavar="MAP", help="the sweep: a NetCDF file or a .zarr directory")
    parser.add_argument("--x", required=True, help="dimension on the horizontal axis (e.g. alpha)")
    parser.add_argument("--y", required=True, help="dimension on the vertical axis (e.g. gamma)")
    parser.add_argument("--z", required=True, help="variable drawn in colour (e.g. pull_off, mu)")
    parser.add_argument("--at", metavar="NAME=VALUE", action="append", default=[],
                        help="fix another dimension at the value nearest VALUE (in decades on a log axis; "
                             "repeatable), e.g. P=10, or a material by name, e.g. material=Au; a dimension of "
                             "materials can also be --x or --y (one column per material)")
    parser.add_argument("-o", "--output", metavar="FILE.png", type=output_file, default=None,
                        help="image file (default: Z.png); the format follows the extension")


def _at(items) -> dict[str, float | str]:
    """--at NAME=VALUE: a number, or a text (a material's name) for a dimension of names."""
    out = {}
    for item in items:
        name, sep, value = item.partition("=")
        name = name.strip()
        try:
            number = strict_float(value)  # as every number of the command line ('1_0' is refused)
        except ValueError:
            number = value.strip()  # a name, for a dimension of names (checked against the sweep's)
            if not number or any(c.isdigit() for c in number[:1]) or number.lower() in ("nan", "inf", "-inf"):
                sep = ""
        if not sep or not name:
            raise UsageError(f"--at: expected NAME=VALUE with a number (or a material's name), got {item!r}")
        if isinstance(number, float) and not math.isfinite(number):
            raise UsageError(f"--at: {name} must be a finite number (a value of the sweep's grid), got {value!r}")
        if name in out:
            both = (f" ({out[name]:g} and {number:g})" if isinstance(number, float) and isinstance(out[name], float)
                    else "")
            raise UsageError(f"--at: {name} given twice{both}; a map fixes each dimension once")
        out[name] = number
    return out


def _select(var, at: dict, quantity):
    """``var`` at the grid values nearest those of ``at`` (in decades on a log axis), a name exactly."""
    import numpy as np

    for name, wanted in at.items():
        values = var[name].values
        if values.dtype.kind in "OUS":  # a dimension of names (materials)
            names = [str(v) for v in values]
            if wanted not in names:
                raise UsageError(f"--at: {name}={wanted}: the sweep's {name} values are {', '.join(names)}")
            var = var.isel({name: names.index(wanted)})
            continue
        if isinstance(wanted, str):
            raise UsageError(f"--at: {name} takes a number (a value of the sweep's grid), got {wanted!r}")
        v = values.astype(float)
        log = _is_log(name, quantity) and np.all(v > 0) and wanted > 0
        i = int(np.argmin(np.abs(np.log(v) - math.log(wanted)) if log else np.abs(v - wanted)))
        var = var.isel({name: i})
        got = float(v[i])
        if not math.isclose(got, wanted, rel_tol=1e-9, abs_tol=1e-300):  # say so when it is not the one asked for
            warnings.warn(f"--at {name}={wanted!r}: the sweep has no {name} = {wanted!r}; its nearest grid value"
                          f"{' (in decades)' if log else ''}, {got!r}, is drawn", AsperityWarning, stacklevel=3)
    return var


def heat_map(ds, x: str, y: str, z: str, at: dict, path: str, fmt: str) -> None:
    """Draw ``ds[z]`` over dimensions ``x`` (horizontal) and ``y`` and save it to ``path`` as ``fmt``.

    Raises
    ------
    UsageError
        For an unknown variable or dimension, or a dimension left unfixed.
    """
    import matplotlib
    import numpy as np
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.colors import LogNorm
    from matplotlib.figure import Figure

    from ..quantities import quantity

    if z not in ds.data_vars or z in ("message", "chunk_done"):
        raise UsageError(f"--z: {z!r} is not a variable of the sweep; it has "
                         f"{', '.join(v for v in ds.data_vars if v not in ('message', 'chunk_done'))}")
    # stores written before sweeps sorted their grids may hold a dimension out of order:
    # nearest selection and the cell edges need increasing coordinates
    ds = ds.sortby([d for d in ds[z].dims if d in ds.coords and ds[d].dtype != object])
    var = ds[z]
    for option, name in (("--x", x), ("--y", y)):
        if name not in var.dims:
            raise UsageError(f"{option}: {name!r} is not a dimension of {z}; its dimensions are {', '.join(var.dims)}")
    if x == y:
        raise UsageError("--x and --y must be different dimensions")
    for name in at:
        if name not in var.dims or name in (x, y):
            raise UsageError(f"--at: {name!r} is not another dimension of {z} ({', '.join(var.dims)})")
    var = _select(var, at, quantity)
    left = [d for d in var.dims if d not in (x, y)]
    if left:
        raise UsageError(f"{z} also varies along {', '.join(left)}: fix it with --at "
                         + " ".join(f"{d}=VALUE" for d in left))
    values = var.transpose(y, x).values.astype(float)
    fig = Figure(figsize=(6.4, 4.8), layout="constrained")
    FigureCanvasAgg(fig)
    ax = fig.subplots()
    finite = values[np.isfinite(values)]
    failed = not np.all(np.isfinite(values))  # NaN: a set outside the model's domain (its message says why)
    log_z = bool(np.any(finite > 0)) and _is_log(z, quantity)
    not_positive = log_z and bool(np.any(finite <= 0))
    if log_z:  # decades: a log colour scale; zeros (no pull-off, say) and NaN drawn grey
        values = np.where(values > 0, values, np.nan)
    cmap = matplotlib.colormaps["viridis"].with_extremes(bad="0.85")
    names = {name: ds[name].values.dtype.kind in "OUS" for name in (x, y)}  # materials: one cell per name
    logs = {name: bool(not names[name] and _is_log(name, quantity) and np.all(ds[name].values > 0)
                       and ds[name].size > 1) for name in (x, y)}
    # cell edges halfway between the grid values: geometric midpoints on a log axis
    edges = {name: np.arange(ds[name].size + 1) - 0.5 if names[name] else _edges(ds[name].values, logs[name])
             for name in (x, y)}
    mesh = ax.pcolormesh(edges[x], edges[y], np.ma.masked_invalid(values), shading="flat",
                         norm=LogNorm() if log_z else None, cmap=cmap)
    for name, axis, set_scale, set_label in ((x, ax.xaxis, ax.set_xscale, ax.set_xlabel),
                                             (y, ax.yaxis, ax.set_yscale, ax.set_ylabel)):
        if logs[name]:
            set_scale("log")
        if names[name]:
            axis.set_ticks(np.arange(ds[name].size), [str(v) for v in ds[name].values])
        set_label(_label(ds[name], name))
    bar = fig.colorbar(mesh, ax=ax)
    bar.set_label(_label(ds[z], z))
    notes = [f"{k} = {var[k].item()}" if isinstance(at[k], str) else f"{k} = {float(var[k]):.4g}" for k in at]
    grey = (["<= 0"] if not_positive else []) + (["not computed (see message)"] if failed else [])
    if grey:
        notes.append("grey: " + " or ".join(grey))
    if notes:
        ax.set_title(", ".join(notes), fontsize=10)
    fig.savefig(path, dpi=150, format=fmt)


def _is_log(name, quantity) -> bool:
    base = {"pull_off": "P", "pull_off_N": "P", "P_N": "P", "F_N": "F", "area_m2": "area",
            "pressure_Pa": "pressure", "d_m": "d", "pull_off_d": "d", "pull_off_d_m": "d"}.get(name, name)
    try:
        return quantity(base).log
    except ValueError:
        return False


def _label(da, name) -> str:
    """``'$\\alpha$'``, ``'pull_off [N G b^2]'``: the symbol (or name) and the unit from the attributes."""
    from ..quantities import quantity

    try:
        text = f"${quantity(name).symbol}$" if name in da.dims else name
    except ValueError:
        text = name
    unit = da.attrs.get("units")
    return f"{text} [{unit}]" if unit and unit != "1" else text


def _edges(values, log: bool):
    """Cell edges around the grid values (sorted or not): midpoints, geometric on a log axis;
    the outer edges as far outside as the nearest midpoint is inside."""
    import numpy as np

    v = np.asarray(values, dtype=float)
    if v.size == 1:
        return np.array([v[0] / 2, v[0] * 2]) if log and v[0] > 0 else np.array([v[0] - 0.5, v[0] + 0.5])
    t = np.log(v) if log else v
    mid = 0.5 * (t[1:] + t[:-1])
    edges = np.concatenate([[2 * t[0] - mid[0]], mid, [2 * t[-1] - mid[-1]]])
    return np.exp(edges) if log else edges


def run(args) -> None:
    from .._atomic import atomic_path
    from .._optional import require
    from ._output import image_format, say

    xr = require("xarray", purpose="asperity plot", extra="sweep")
    require("matplotlib", purpose="asperity plot", extra="plot")
    if not os.path.exists(args.store):
        raise UsageError(f"no such sweep: {args.store!r}")
    at = _at(args.at)
    zarr = args.store.rstrip("/").endswith(".zarr")
    try:
        ds = xr.open_zarr(args.store, consolidated=False) if zarr else xr.open_dataset(args.store)
    except (OSError, ValueError) as err:
        raise UsageError(f"cannot read the sweep {args.store!r}: {err}") from None
    with ds:
        if args.z not in ds.data_vars or args.z in ("message", "chunk_done"):  # before the default output file
            raise UsageError(f"--z: {args.z!r} is not a variable of the sweep; it has "
                             f"{', '.join(v for v in ds.data_vars if v not in ('message', 'chunk_done'))}")
        if args.output == "-":
            raise UsageError("-o -: an image cannot go to standard output; give a file name")
        path = args.output or f"{args.z}.png"
        if os.path.exists(path) and os.path.samefile(path, args.store):
            raise UsageError(f"-o {path!r} is the sweep being read: give another name")
        fmt = image_format(path)
        with atomic_path(path) as tmp:
            heat_map(ds, args.x, args.y, args.z, at, tmp, fmt)
    say(f"wrote {path}\n")
