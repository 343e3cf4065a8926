r"""Reading AFM maps and profilometer line scans into metres, with SurfaceTopography.

:func:`read_topography` opens any format SurfaceTopography reads (text matrices with or
without a header, ``.npy``, x3p, NetCDF, Gwyddion, DI, Bruker, ...) and returns the
surface in metres.  SurfaceTopography is imported lazily through
:func:`asperity._optional.require` (``pip install 'asperity[topography]'``).

**Units.**  SurfaceTopography keeps *one* unit for a topography's lateral sizes and its
heights.  asperity separates the two, so that a size can never be scaled by the height
unit by mistake:

* ``physical_sizes`` are lengths in **metres**: floats, pint quantities or strings with a
  unit such as ``'5um'`` (converted with :func:`asperity.units.to_si`);
* ``unit`` is the unit of the **stored heights**, for files that store none
  (plain-text matrices, ``.npy``): ``'m'``, ``'mm'``, ``'um'`` (or ``'µm'``, ``'μm'``),
  ``'nm'``, ``'Å'``, ``'pm'``.

The sizes are converted to the height unit before SurfaceTopography sees them, and the
result is converted to metres, so the scan of heights in nm with ``physical_sizes=('5um',
'5um')`` and the same scan written in metres give the same surface (to rounding).  A file
that stores its sizes but no unit has both in ``unit`` (SurfaceTopography's rule).

**Refused files.**  A missing path, a directory, an empty file, a file no reader
recognises, a ``.npy`` array that is empty, 0-d, more than 2-d or not real numbers,
fewer than :data:`~asperity.topography.summits.MIN_POINTS` points along an axis,
undefined (NaN) heights unless ``fill_undefined=True``, and a file matched only by its size
as a NASA SRTM ``.hgt`` elevation tile (which has no header) unless it is named ``*.hgt``.
"""

from __future__ import annotations

import contextlib
import logging
import os
import warnings

import numpy as np

from .._optional import require
from .._validation import as_float_array
from .._warnings import AsperityWarning
from ..units import to_si
from ._textfile import open_bytes, ragged_note
from .summits import MIN_POINTS

__all__ = ["read_topography", "HEIGHT_UNITS"]

#: Height units accepted for files that store none, and SurfaceTopography's name for each.
HEIGHT_UNITS = {"m": "m", "mm": "mm", "um": "um", "µm": "µm", "μm": "µm", "nm": "nm", "Å": "Å", "pm": "pm"}

_NPY_MAGIC = b"\x93NUMPY"


def _surface_topography():
    return require("SurfaceTopography", purpose="reading measured surfaces", extra="topography")


def read_topography(path, *, physical_sizes=None, unit=None, channel_index=None, fill_undefined=False):
    """Read an AFM map or profilometer line scan into a SurfaceTopography object in metres.

    Parameters
    ----------
    path : str or os.PathLike
        A file in any format SurfaceTopography reads (text matrix with or without a
        header, x3p, NetCDF, npy, Gwyddion, DI, Bruker, ...).
    physical_sizes : float, str, pint.Quantity or sequence of them, optional
        Scan size in **metres** along x and y (a map) or along the line (a line scan),
        only for files that do not store it: ``(5e-6, 5e-6)``, ``('5um', '5um')``,
        ``5 * ureg.um``.  One value for a map means a square scan.
    unit : str, optional
        Unit of the **stored heights**, only for files that do not store one: ``'m'``,
        ``'mm'``, ``'um'`` (``'µm'``, ``'μm'``), ``'nm'``, ``'Å'`` or ``'pm'``.
    channel_index : int, optional
        Data channel to read (default: the file's default channel).
    fill_undefined : bool, optional
        Undefined (NaN/masked) heights raise :class:`ValueError` unless True, in which
        case they are filled by harmonic interpolation, with an
        :class:`~asperity.AsperityWarning` saying how many.  Default False.

    Returns
    -------
    SurfaceTopography.Topography or SurfaceTopography.UniformLineScan
        Heights and sizes in metres (``unit == 'm'``).

    Raises
    ------
    TypeError
        If ``path`` is not a str or os.PathLike, or ``unit`` is not a string.
    ValueError
        If the file is missing, a directory, empty, unreadable, a degenerate ``.npy``
        (empty, 0-d, 3-d or more, not real numbers), has too few points, has no physical
        size or unit (the message says which keyword to pass), stores one that is also
        passed, or has undefined data.  Every message starts with the file name.
    ImportError
        If SurfaceTopography is not installed.

    Notes
    -----
    Warnings raised by SurfaceTopography while reading are re-issued with the file
    name, never dropped (only its notice that mpi4py is missing is ignored).

    Examples
    --------
    A text matrix of heights in nm from a 5 um x 5 um scan:

    >>> topo = read_topography("scan.txt", physical_sizes=("5um", "5um"), unit="nm")  # doctest: +SKIP
    >>> topo.physical_sizes  # doctest: +SKIP
    (5e-06, 5e-06)
    """
    name = _file_name(path)
    if not isinstance(fill_undefined, bool | np.bool_):
        raise TypeError(f"fill_undefined must be True or False, got {type(fill_undefined).__name__} "
                        f"{fill_undefined!r}")
    st = _surface_topography()
    unit = _height_unit(name, unit)
    fmt = _check_npy(name) if _is_npy(name) else None
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        topo = _read(st, name, fmt, physical_sizes, unit, channel_index)
    for w in caught:
        warnings.warn(f"{name}: {w.message}", w.category, stacklevel=2)
    if fmt == "npy" and topo.dim == 2:
        _note_pixel_shape(topo, name)
    elif topo.dim == 2 and topo.is_uniform:
        _note_index_lines(topo, name)
    return _finish(topo, name, fill_undefined)


def _note_index_lines(topo, name: str) -> None:
    """A note when a map's first or last line or column counts 0, 1, 2, ... or 1, 2, 3, ..., or
    runs in even steps where the line next to it does not (from its first or second value): a
    header of indices or coordinates read as heights (user trials: a line '0 1 ... 255' on top
    gave R 133 times too small, coordinates in um eta 5 times too large, flagged only by the
    methods' disagreement)."""
    h = np.ma.getdata(topo.heights())
    for axis, what in ((1, "line"), (0, "column")):  # a text matrix's lines are along the second axis
        for index, inner, where in ((0, 1, "first"), (-1, -2, "last")):
            line, next_line = np.take(h, index, axis=axis), np.take(h, inner, axis=axis)
            for skip in (0, 1):  # the whole line, or after a corner cell (a header and an index)
                values = line[skip:]
                if values.size < 8:
                    continue
                if any(np.array_equal(values, np.arange(start, start + values.size)) for start in (0, 1)):
                    first = ", ".join(f"{v:g}" for v in values[:3])
                    found = f"counts {first}, ... {values[-1]:g}: a header of indices"
                elif _even_steps(values) and not _even_steps(next_line[skip:]):
                    found = f"runs from {values[0]:g} to {values[-1]:g} in even steps: a header of coordinates"
                else:
                    continue
                warnings.warn(f"{name}: its {where} {what} {found} read as heights?  Remove it from the file",
                              AsperityWarning, stacklevel=3)
                return


def _even_steps(values) -> bool:
    """Monotone in steps equal to 1 % (coordinates printed to a few digits)."""
    step = np.diff(values)
    mean = step.mean()
    return bool(mean != 0 and np.all(step * mean > 0) and np.ptp(step) <= 0.01 * abs(mean))


def _note_pixel_shape(topo, name: str) -> None:
    """A note when a ``.npy`` map's pixels are more than twice as long one way as the other:
    its first axis is x (SurfaceTopography's convention), unlike a text matrix's rows."""
    dx, dy = (float(s) / n for s, n in zip(topo.physical_sizes, topo.nb_grid_pts, strict=True))
    if max(dx, dy) > 2.0 * min(dx, dy):
        unit = f" {topo.unit}" if topo.unit else ""
        warnings.warn(f"{name}: the pixels are {dx:.4g} x {dy:.4g}{unit} (x by y): a .npy array's first axis is x "
                      f"({topo.nb_grid_pts[0]} points), unlike a text matrix's rows; if the array is an image (rows "
                      "are scan lines), save its transpose or swap the sizes", AsperityWarning, stacklevel=3)


def _file_name(path) -> str:
    """The file name of ``path``; TypeError for a non-path, ValueError for a missing/empty/non-file."""
    if not isinstance(path, str | os.PathLike):
        raise TypeError(f"path must be a str or os.PathLike naming a file, got {type(path).__name__} {path!r}")
    name = os.fsdecode(os.fspath(path))
    if name == "":
        raise ValueError("path must not be empty")
    if os.path.isdir(name):
        raise ValueError(f"{name}: is a directory, not a topography file")
    if not os.path.exists(name):
        raise ValueError(f"{name}: no such file")
    if not os.path.isfile(name):
        raise ValueError(f"{name}: not a regular file")
    if os.path.getsize(name) == 0:
        raise ValueError(f"{name}: file is empty")
    return name


def _height_unit(name: str, unit):
    """SurfaceTopography's name of the height unit ``unit`` (None stays None)."""
    if unit is None:
        return None
    if not isinstance(unit, str):
        raise TypeError(f"unit must be a string naming a length unit such as 'nm', got {type(unit).__name__} {unit!r}")
    key = unit.strip()
    if key not in HEIGHT_UNITS:
        raise ValueError(f"{name}: unit {unit!r} is not a length unit; use one of {', '.join(HEIGHT_UNITS)} "
                         f"(the unit of the stored heights)")
    return HEIGHT_UNITS[key]


def _is_npy(name: str) -> bool:
    with open(name, "rb") as fobj:
        return fobj.read(len(_NPY_MAGIC)) == _NPY_MAGIC


def _check_npy(name: str) -> str:
    """Refuse an empty, 0-d, >2-d or non-real ``.npy`` array before any reader guesses at it."""
    try:
        with open(name, "rb") as fobj:
            version = np.lib.format.read_magic(fobj)
            if version == (1, 0):
                shape, _, dtype = np.lib.format.read_array_header_1_0(fobj)
            elif version == (2, 0):
                shape, _, dtype = np.lib.format.read_array_header_2_0(fobj)
            else:  # (3, 0): np.load's own mapping checks the size
                array = np.load(name, mmap_mode="r", allow_pickle=False)
                shape, dtype = array.shape, array.dtype
            data_start = fobj.tell() if version in ((1, 0), (2, 0)) else None
    except Exception as err:
        raise ValueError(f"{name}: not a valid .npy file ({type(err).__name__}: {err})") from None
    need = int(np.prod(shape, dtype=np.int64)) * np.dtype(dtype).itemsize
    have = need if data_start is None else os.path.getsize(name) - data_start
    if have < need:  # a reader would fill the rest from memory (a review: garbage heights)
        raise ValueError(f"{name}: not a valid .npy file: it is truncated ({have} of the {need} bytes its header "
                         f"announces for shape {shape})")
    if not (np.issubdtype(dtype, np.integer) or np.issubdtype(dtype, np.floating)):
        raise ValueError(f"{name}: the .npy array holds {dtype}, not real numbers (heights)")
    if len(shape) not in (1, 2):
        raise ValueError(f"{name}: the .npy array is {len(shape)}-d (shape {shape}); a surface is a 2-d map "
                         f"or a 1-d line scan")
    if 0 in shape:
        raise ValueError(f"{name}: the .npy array is empty (shape {shape}): no height data")
    return "npy"


@contextlib.contextmanager
def _quiet_readers():
    """Without a logging configuration of the user's, the log records of the format readers tried
    (igor2's 'could not reshape data from ...', 3 kB of binary text for a file it is not) would go
    to standard error through logging's last resort: a second line after the one-line error
    (found by a review).  A NullHandler on the root logger, while reading only, keeps them quiet;
    a user who configured logging still gets them."""
    root = logging.getLogger()
    if root.handlers:
        yield
        return
    quiet = logging.NullHandler()
    root.addHandler(quiet)
    try:
        yield
    finally:
        root.removeHandler(quiet)


def _read(st, name, fmt, physical_sizes, unit, channel_index):
    """Open ``name`` with SurfaceTopography; every failure becomes a ValueError naming the file."""
    try:
        with _quiet_readers(), open_bytes(name) as fobj, st.open_topography(fobj, format=fmt) as reader:
            if type(reader).__name__ == "HGTReader" and not name.lower().endswith(".hgt"):
                raise ValueError(f"{name}: not a readable topography file (only its size matches a headerless "
                                 f"NASA SRTM .hgt tile; name it *.hgt if it is one)")
            channel = _channel(name, reader, channel_index)
            _check_metadata(name, channel, physical_sizes, unit)
            kwargs = {"channel_index": channel.index}
            if channel.unit is None:
                kwargs["unit"] = unit
            if channel.physical_sizes is None:
                kwargs["physical_sizes"] = _sizes_in_unit(name, physical_sizes, channel.dim, channel.unit or unit)
            return reader.topography(**kwargs)
    except ValueError as err:
        if str(err).startswith(name):
            raise
        raise ValueError(f"{name}: cannot read topography ({_reason(err)})") from None
    except Exception as err:  # SurfaceTopography raises many exception types
        raise ValueError(f"{name}: not a readable topography file ({_reason(err)}{ragged_note(name)})") from None


def _channel(name, reader, channel_index):
    """The requested data channel of an open reader."""
    if channel_index is None:
        return reader.default_channel
    if isinstance(channel_index, bool) or not isinstance(channel_index, int | np.integer):
        raise ValueError(f"{name}: channel_index must be an integer, got {channel_index!r}")
    if not 0 <= channel_index < len(reader.channels):
        raise ValueError(f"{name}: no channel {channel_index} (channel_index); the file has {len(reader.channels)} "
                         "channel(s): "
                         + ", ".join(repr(c.name) for c in reader.channels))
    return reader.channels[channel_index]


def _reason(err) -> str:
    """One line describing a SurfaceTopography read error."""
    if type(err).__name__ == "CannotDetectFileFormat":
        return ("no SurfaceTopography reader recognises the format (a matrix of numbers is read as text "
                "separated by blanks, commas or semicolons, one line per scan line, or .npy)")
    lines = [line.strip() for line in str(err).splitlines() if line.strip()]
    return f"{type(err).__name__}: {lines[0]}" if lines else type(err).__name__


def _check_metadata(name, channel, physical_sizes, unit):
    """Reject empty or tiny channels, missing or doubled sizes/units, before reading heights."""
    grid = channel.nb_grid_pts
    if grid is None or len(grid) == 0 or min(grid) == 0:
        raise ValueError(f"{name}: contains no height data (grid {grid})")
    if min(grid) < MIN_POINTS:
        hint = "; a line scan is one column of heights, not one line" if len(grid) == 2 and grid[1] == 1 else ""
        raise ValueError(f"{name}: too few points for summit statistics: grid {tuple(grid)}; need at least "
                         f"{MIN_POINTS} along every axis{hint}")
    if channel.physical_sizes is None and physical_sizes is None:
        raise ValueError(f"{name}: the file does not store the scan size; pass physical_sizes=(Lx, Ly) for a map "
                         f"or (L,) for a line scan, in metres or with units (e.g. ('5um', '5um')) "
                         f"(command line: --size)")
    if channel.unit is None and unit is None:
        raise ValueError(f"{name}: the file does not store the unit of its heights; pass unit='m', 'um' or 'nm' "
                         "(command line: --unit)")
    if channel.physical_sizes is not None and physical_sizes is not None:
        stored = ", ".join(f"{float(size):g}" for size in channel.physical_sizes)
        in_unit = f" {channel.unit}" if channel.unit else " (in the unit of its heights)"
        raise ValueError(f"{name}: the file already stores the scan size ({stored}){in_unit}; "
                         f"do not pass physical_sizes (command line: leave out --size)")
    if channel.unit is not None and unit is not None:
        raise ValueError(f"{name}: the file already stores the unit {channel.unit!r}; do not pass unit "
                         "(command line: leave out --unit)")


def _sizes_in_unit(name, physical_sizes, dim, unit) -> tuple[float, ...]:
    """``physical_sizes`` (metres, quantities or strings) as ``dim`` floats in the height ``unit``."""
    kind = "map (Lx, Ly; one value means a square scan)" if dim == 2 else "line scan (L)"
    problem = f"physical_sizes must be {dim} positive number(s) of metres for this {kind}, got {physical_sizes!r}"
    try:
        sizes = np.atleast_1d(as_float_array(to_si(physical_sizes, "m", "physical_sizes"), "physical_sizes"))
    except ValueError as err:
        raise ValueError(f"{name}: {problem} ({err})") from None
    if sizes.ndim != 1 or sizes.size not in (1, dim) or np.any(sizes <= 0):
        raise ValueError(f"{name}: {problem}")
    if sizes.size != dim:
        sizes = np.repeat(sizes, dim)
    try:
        conversion = require("SurfaceTopography.Support.UnitConversion", purpose="reading measured surfaces",
                             extra="topography")
        metres_to_unit = conversion.get_unit_conversion_factor("m", unit)
    except ValueError:
        raise ValueError(f"{name}: the heights are stored in {unit!r}, not a length unit; physical_sizes "
                         f"cannot be converted to it") from None
    with np.errstate(all="ignore"):
        converted = sizes * metres_to_unit
    if not np.all(np.isfinite(converted)):
        raise ValueError(f"{name}: {problem}: beyond double precision in {unit!r}")
    return tuple(float(s) for s in converted)


def _finish(topo, name, fill_undefined):
    """Check the heights, fill undefined data if asked, convert to metres."""
    if not topo.is_uniform:
        raise ValueError(f"{name}: nonuniformly sampled line scan; resample it with "
                         f"topography.to_uniform(...) and pass the topography instead of the file")
    if topo.has_undefined_data:
        n_bad = int(np.ma.count_masked(topo.heights()))
        if n_bad == topo.heights().size:
            raise ValueError(f"{name}: every height is undefined (NaN or infinite): no height data")
        if not fill_undefined:
            raise ValueError(f"{name}: {n_bad} of {topo.heights().size} heights are undefined (NaN or infinite); "
                             f"pass fill_undefined=True to fill them by harmonic interpolation (command line: "
                             f"--fill-undefined)")
        topo = topo.interpolate_undefined_data()
        warnings.warn(f"{name}: {n_bad} of {topo.heights().size} heights ({100 * n_bad / topo.heights().size:.3g} %) "
                      "were undefined and are filled by harmonic interpolation", AsperityWarning, stacklevel=3)
    heights = np.ma.getdata(topo.heights())
    if not np.all(np.isfinite(heights)):
        raise ValueError(f"{name}: heights contain infinite or NaN values")
    try:
        metres = topo.to_unit("m")
        metres.heights()  # the conversion is lazy: force it so a bad unit fails here
    except Exception:
        raise ValueError(f"{name}: unit {topo.unit!r} is not a length unit (m, mm, um, nm, ...)") from None
    return metres
