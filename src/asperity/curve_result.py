"""One curve of the model: the arrays of its columns, with its parameters, as tables.

:class:`CurveResult` is what :func:`asperity.separation_curve`, :func:`asperity.load_curve`
and :class:`asperity.Model` return (and, extended, a branch of a cycle): NumPy arrays of
equal length, one per column of :data:`COLUMNS` (the registry
:data:`asperity.quantities.CURVE_COLUMNS`), written as CSV or a pandas DataFrame.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ._csv import columns_to_csv, columns_to_dataframe
from .quantities import CURVE_COLUMNS

__all__ = ["CurveResult", "COLUMNS"]

#: Columns of a curve, in order, with their meaning (derived from :data:`asperity.quantities.CURVE_COLUMNS`).
COLUMNS = {name: q.meaning for name, q in CURVE_COLUMNS.items()}


@dataclass(frozen=True)
class CurveResult:
    """One curve: NumPy arrays of equal length, one per column of :data:`COLUMNS`.

    ``plastic`` (:math:`n_p/N`, the fraction of asperities past the critical interference,
    :data:`asperity.quantities.PLASTIC_COLUMNS`) is None unless the per-asperity law has a
    critical interference (e.g. Jackson-Green); then it is the last column.
    """

    d: np.ndarray
    P: np.ndarray
    F: np.ndarray
    mu: np.ndarray
    area: np.ndarray
    pressure: np.ndarray
    contacts: np.ndarray
    parameters: dict = field(default_factory=dict, compare=False)
    plastic: np.ndarray | None = None
    #: The separations the asperities feel (an interaction shifts them from ``d``); None: ``d``.
    d_local: np.ndarray | None = field(default=None, compare=False, repr=False)

    def __len__(self) -> int:
        return int(np.size(self.d))

    def columns(self) -> dict[str, np.ndarray]:
        """The curve as an ordered dict of column name -> array (``plastic`` last, if present)."""
        cols = {name: np.asarray(getattr(self, name)) for name in COLUMNS}
        if self.plastic is not None:
            cols["plastic"] = np.asarray(self.plastic)
        return cols

    def to_dataframe(self):
        """The curve as a :class:`pandas.DataFrame` (needs pandas: ``asperity[frame]``)."""
        return columns_to_dataframe(self.columns(), self.parameters)

    def to_csv(self, path_or_buffer=None) -> str | None:
        """Write CSV (a header line of column names, then rows); return it if no path."""
        return columns_to_csv(self.columns(), path_or_buffer)
