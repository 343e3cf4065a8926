"""The one CSV writer: curves, physical curves, the command line and the paper's studies.

Every CSV asperity writes comes from :func:`table_to_csv`: a header line, then one line
per row, ``\\n`` line ends, fields quoted only where CSV needs it (a comma, a quote or a
line break in a text field).  Floats (Python or NumPy) are written with :func:`repr`, the
shortest text that reads back as the same number, so a CSV round-trips exactly; booleans
are ``True``/``False``, ``None`` is an empty field, anything else its ``str``.

:func:`columns_to_csv` writes named columns (a result's ``columns()``),
:func:`rows_to_csv` a list of dicts; both return the text or write it, atomically, to a
path (:func:`asperity._atomic.atomic_write`).
"""

from __future__ import annotations

import csv
import io
from collections.abc import Iterable, Sequence

import numpy as np

from ._atomic import atomic_write
from ._optional import require
from ._validation import check_output_path

__all__ = ["table_to_csv", "rows_to_csv", "columns_to_csv", "columns_to_dataframe"]


def _cell(value):
    """A float as its shortest round-tripping text; anything else as the csv module writes it."""
    if isinstance(value, float | np.floating) and not isinstance(value, bool):
        return repr(float(value))
    return value


def _deliver(text: str, path_or_buffer) -> str | None:
    if path_or_buffer is None:
        return text
    if hasattr(path_or_buffer, "write"):
        path_or_buffer.write(text)
    else:
        atomic_write(check_output_path(path_or_buffer, "path_or_buffer"), text)
    return None


def table_to_csv(header: Sequence[str], rows: Iterable[Sequence]) -> str:
    """CSV text of a header and rows of cells (see the module docstring for the format).

    Parameters
    ----------
    header : sequence of str
        Column names.
    rows : iterable of sequences
        One sequence of cells per row, in the order of ``header``.

    Returns
    -------
    str
        The CSV text, ending with a newline.
    """
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(list(header))
    for row in rows:
        writer.writerow([_cell(v) for v in row])
    return buffer.getvalue()


def rows_to_csv(rows: Sequence[dict], columns: Sequence[str] | None = None, path_or_buffer=None) -> str | None:
    """Write a list of dicts as CSV, columns ``columns`` (default: the first row's keys).

    Returns the text when ``path_or_buffer`` is None, else writes it to the buffer or,
    atomically, to the path and returns None.
    """
    columns = list(rows[0]) if columns is None and rows else list(columns or ())
    text = table_to_csv(columns, ([row[c] for c in columns] for row in rows))
    return _deliver(text, path_or_buffer)


def columns_to_csv(columns: dict[str, np.ndarray], path_or_buffer=None) -> str | None:
    """Write named equal-length columns as CSV (header, then rows).

    Numeric columns are written as floats; text and boolean columns (a cycle's ``branch`` and
    ``jump``) as they are.  Returns the text when ``path_or_buffer`` is None, else writes it to
    the buffer or, atomically, to the path and returns None.
    """
    arrays = [np.asarray(v) for v in columns.values()]
    arrays = [a if a.dtype.kind in "USOb" else a.astype(float) for a in arrays]
    text = table_to_csv(list(columns), zip(*arrays, strict=True))
    return _deliver(text, path_or_buffer)


def columns_to_dataframe(columns: dict[str, np.ndarray], attrs: dict):
    """Named columns as a :class:`pandas.DataFrame` with ``attrs`` (needs ``asperity[frame]``)."""
    pd = require("pandas", purpose="to_dataframe", extra="frame")
    frame = pd.DataFrame(columns)
    frame.attrs.update(attrs)
    return frame
