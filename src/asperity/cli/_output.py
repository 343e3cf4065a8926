"""Command-line output: tables, CSV and strict JSON, written atomically to -o or standard output.

Formats: ``table`` (aligned columns, 6 significant digits, for reading), ``csv`` (the
library's one CSV writer, :mod:`asperity._csv`: full-precision floats) and ``json``
(strict: NaN and infinity are ``null``, :mod:`asperity._json`).  Without ``--format``
the output is a table on a terminal and CSV (JSON for ``surface``) otherwise.

Order of writing, all or nothing (:func:`write_outputs`):

1. the figure (``--plot``) is drawn and saved to a temporary file beside its target;
2. the table goes to a temporary file beside ``-o`` (or, without ``-o``, to standard
   output, only once the figure has been drawn);
3. the table's file is renamed into place, then the figure's.

So a failing ``--plot`` (matplotlib missing, an unknown image format, an unwritable
directory) writes nothing and prints nothing on standard output, and an error or an
interruption leaves no truncated file: ``-o`` and ``--plot`` targets keep their old
content or stay absent.
"""

from __future__ import annotations

import contextlib
import os
import sys

from .._atomic import atomic_path
from .._csv import rows_to_csv
from .._json import dumps
from .._validation_files import IMAGE_FORMATS
from ._lists import OutputClosed, UsageError

__all__ = ["output_format", "check_targets", "output_targets",
           "format_rows", "format_json", "format_physical", "comment_header", "curve_rows",
           "write_outputs", "image_format", "say"]


def say(text: str) -> None:
    """Write ``text`` to standard output; a full or failing output is a one-line error, a reader
    that left :class:`OutputClosed` (a CLI check: both were tracebacks).  Only these writes are
    so judged: an OSError elsewhere (a file, a cluster) keeps its own message."""
    try:
        sys.stdout.write(text)
        sys.stdout.flush()
    except BrokenPipeError:
        raise OutputClosed from None
    except OSError as err:
        raise UsageError(f"cannot write to standard output: {err.strerror or err}") from None


def output_format(args, piped: str = "csv") -> str:
    """``--format``, or the default: ``table`` on a terminal, ``piped`` otherwise."""
    if args.format:
        return args.format
    return "table" if (args.output in (None, "-") and sys.stdout.isatty()) else piped


def format_json(value, *, indent: int | None = None) -> str:
    """Strict JSON text of ``value`` (NaN/inf as null) and a newline."""
    return dumps(value, indent=indent) + "\n"


def _short(v) -> str:
    import numpy as np

    if v is None:  # undefined (JSON null, an empty CSV cell): no separation without a pull-off
        return "-"
    if isinstance(v, bool | np.bool_):
        return str(bool(v))
    if isinstance(v, float | np.floating):
        return f"{float(v):.6g}"
    return str(v)


def format_rows(rows: list[dict], fmt: str) -> str:
    """Rows (dicts with the same keys) as ``table``, ``csv`` or ``json`` text."""
    if fmt == "json":
        return format_json(rows, indent=1)
    if fmt == "csv":
        return rows_to_csv(rows)
    names = list(rows[0]) if rows else []
    cells = [[_short(r[n]) for n in names] for r in rows]
    widths = [max(len(n), *(len(c[i]) for c in cells)) if cells else len(n) for i, n in enumerate(names)]
    out = ["  ".join(n.rjust(w) for n, w in zip(names, widths, strict=True))]
    out += ["  ".join(c.rjust(w) for c, w in zip(row, widths, strict=True)) for row in cells]
    return "\n".join(out) + "\n"


def format_physical(rows: list[dict], fmt: str, contact, *, comments: bool = True) -> str:
    """Rows of a physical result with the contact computed (:meth:`~asperity.physical.PhysicalContact.describe`).

    ``json``: one object ``{"contact": contact.to_dict(), "rows": rows}``.  ``table`` and
    ``csv``: the description as ``#`` lines, then the rows (``comments=False`` leaves the
    lines out); ``pandas.read_csv(path, comment='#')`` reads such a CSV.
    """
    if fmt == "json":
        return format_json({"contact": contact.to_dict(), "rows": rows}, indent=1)
    return comment_header(contact, comments=comments) + format_rows(rows, fmt)


def comment_header(contact, *, comments: bool = True) -> str:
    """The contact's description (:meth:`~asperity.physical.PhysicalContact.describe`) as
    ``#`` lines ending in a newline; empty for no contact or ``comments=False``."""
    if contact is None or not comments:
        return ""
    return "".join(f"# {line}\n" for line in contact.describe().splitlines())


def curve_rows(curve) -> list[dict]:
    """One dict per point of a curve: dimensionless names, or SI names with units (``P_N``)."""
    cols = curve.columns()
    return [{k: float(v[i]) for k, v in cols.items()} for i in range(len(curve))]


@contextlib.contextmanager
def _target(path: str, what: str):
    """:func:`asperity._atomic.atomic_path` with an OSError turned into a one-line UsageError."""
    try:
        with atomic_path(path) as tmp:
            yield tmp
    except OSError as exc:
        raise UsageError(f"cannot write {what} {path!r}: {exc.strerror or exc}") from None


def output_targets(args) -> tuple[tuple[str, str | None], ...]:
    """The files a command writes: (option, path) for ``-o`` (not '-'), ``--plot`` and ``--summits``."""
    output = getattr(args, "output", None)
    return (("-o", None if output == "-" else output), ("--plot", getattr(args, "plot", None)),
            ("--summits", getattr(args, "summits", None)))


def check_targets(args, targets) -> None:
    """Refuse an output path that names one of the command's input files, or another output
    (either would be replaced: found by a review, ``--summits`` could overwrite the scan read)."""
    named = [(option, path) for option, path in targets if path and path != "-"]
    seen = {}
    for option, path in named:
        key = os.path.realpath(path)
        if key in seen:
            raise UsageError(f"{seen[key]} and {option} name the same file {path!r}: one would replace the "
                             "other; give two names")
        seen[key] = option
    _not_an_input(args, named)


def _not_an_input(args, targets) -> None:
    """Refuse an output path that names one of the command's input files (it would be replaced)."""
    inputs = []
    for name in ("file", "data", "store", "surface", "points"):
        value = getattr(args, name, None)
        inputs += [v for v in (value if isinstance(value, list) else [value]) if isinstance(v, str)]
    heights = getattr(args, "heights", None)  # empirical:FILE and best:FILE read summit heights
    if isinstance(heights, str) and heights.partition(":")[0].strip().lower() in ("empirical", "best"):
        inputs.append(heights.partition(":")[2])
    for option, path in targets:
        if not path or not os.path.exists(path):
            continue
        for source in inputs:
            if os.path.exists(source) and os.path.samefile(path, source):
                raise UsageError(f"{option} {path!r} is the input file {source!r}: it would be replaced; give "
                                 "another name")


def write_outputs(text: str, args, plot=None, also=()) -> None:
    """Write ``text`` to ``args.output`` (or standard output), the figure to ``args.plot`` and any other files.

    Parameters
    ----------
    text : str
        The formatted result.
    args : argparse.Namespace
        With ``output`` and (optionally) ``plot``: target paths or None.
    plot : callable, optional
        ``plot(path, fmt)`` draws the figure and saves it to ``path`` in image format
        ``fmt``; called only when ``args.plot`` is set.
    also : sequence of (path, write, what)
        Further files: ``write(tmp)`` writes one to a temporary path, put in place with the
        others (``asperity surface --summits``: it stayed behind when ``-o`` failed, a review).

    See the module docstring for the order: the figure first, nothing written unless
    everything succeeded.
    """
    plot_path = getattr(args, "plot", None)
    output = None if args.output == "-" else args.output  # '-': standard output, as usual
    check_targets(args, output_targets(args))
    if plot is not None and plot_path == "-":
        raise UsageError("--plot -: an image cannot go to standard output; give a file name")
    if plot is not None and plot_path and image_format(plot_path) not in IMAGE_FORMATS:
        raise UsageError(f"--plot {plot_path!r}: {image_format(plot_path)!r} is not an image format; give a file "
                         f"name ending in .{', .'.join(IMAGE_FORMATS)}")
    with contextlib.ExitStack() as stack:
        for path, write, what in also:
            write(stack.enter_context(_target(path, what)))
        if plot is not None and plot_path:
            tmp = stack.enter_context(_target(plot_path, "plot"))
            plot(tmp, image_format(plot_path))
        if output:
            tmp = stack.enter_context(_target(output, "output file"))
            with open(tmp, "w", encoding="utf-8") as fh:
                fh.write(text)
        else:
            say(text)


def image_format(path: str) -> str:
    """Image format of a figure file from its suffix (``'png'`` when it has none)."""
    return os.path.splitext(path)[1][1:].lower() or "png"
