"""The paper's figures and Table 1, reproduced from the model.

* :func:`reproduce` writes every figure (PNG, SVG and the plotted data as CSV),
  ``table1.csv`` and a self-contained ``index.html`` into a directory.
* :data:`FIGURES` maps 3..9 to a :class:`~asperity.studies.figures.FigureSpec` with the
  figure's data, drawing function and the paper's claims as machine checks
  (:mod:`~asperity.studies.friction`: Figs 3-6, :mod:`~asperity.studies.separation`:
  Figs 7-8, :mod:`~asperity.studies.pressure`: Fig 9).
* :mod:`~asperity.studies.table1`: the pull-off forces of Table 1.

matplotlib is needed only to draw (``pip install 'asperity[plot]'``); it is imported on
first use, always on the non-interactive Agg canvas.
"""

from ._common import CSV_COLUMNS, Check, FigureData, Series
from .figures import FIGURES, FigureSpec
from .report import reproduce
from .table1 import TABLE1, TABLE1_COLUMNS, table1_rows

__all__ = ["reproduce", "FIGURES", "FigureSpec", "FigureData", "Series", "Check", "CSV_COLUMNS",
           "TABLE1", "TABLE1_COLUMNS", "table1_rows"]
