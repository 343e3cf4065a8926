"""Table output shared by the result objects (dimensionless and physical curves)."""

from __future__ import annotations

import csv
import io

import numpy as np


def columns_to_csv(columns: dict[str, np.ndarray], path_or_buffer=None) -> str | None:
    """Write named equal-length columns as CSV (header, then rows; floats round-trip exactly).

    Returns the text when ``path_or_buffer`` is None, else writes to the path or buffer.
    """
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(list(columns))
    for row in zip(*columns.values(), strict=True):
        writer.writerow([repr(float(v)) for v in row])
    text = buffer.getvalue()
    if path_or_buffer is None:
        return text
    if hasattr(path_or_buffer, "write"):
        path_or_buffer.write(text)
    else:
        with open(path_or_buffer, "w", encoding="utf-8") as fh:
            fh.write(text)
    return None


def columns_to_dataframe(columns: dict[str, np.ndarray], attrs: dict):
    """Named columns as a :class:`pandas.DataFrame` with ``attrs`` (needs ``asperity[frame]``)."""
    try:
        import pandas as pd
    except ImportError:  # pragma: no cover - depends on the environment
        raise ImportError("to_dataframe needs pandas: pip install 'asperity[frame]'") from None
    frame = pd.DataFrame(columns)
    frame.attrs.update(attrs)
    return frame
