"""Which lines of a measured data file are its header, its data and its comments.

Used by :mod:`asperity.fit.read`.  A line that starts with ``#`` or ``%`` is a comment, as
pandas' ``comment='#'`` and ``numpy.loadtxt`` read it; below the header such lines are
counted in a note (a user trial: a row '#2 (retest),...' vanished without a word), and
Excel's error values (``#N/A``, ``#VALUE!``, ...) are cells, read as NaN, not comments.  One
exception (a review): when the first line that is not a comment holds only numbers, the
header is the nearest comment above it that names a column the reader knows, without its
marker (``%RH,load (nN),friction (nN)``, ``% load (nN), friction (nN)``: a header a program
marked as a comment).

The delimiter is the one of comma, tab and semicolon that cuts the header and the first
data lines into as many cells, the most cells if several do, a comma before a tab before
a semicolon on a tie (``Note, free text`` in a tab-separated header; ``load (nN),<TAB>...``
aligned by tabs after the commas).
"""

from __future__ import annotations

import csv

from .._numbers import is_number
from .headers import classify_header, condition_names

#: Excel's error values: data cells (NaN, dropped with drop_nan), never comments.
EXCEL_ERRORS = ("#n/a", "#value!", "#div/0!", "#ref!", "#name?", "#num!", "#null!", "#spill!", "#calc!",
                "#getting_data")
_DELIMITERS = (",", "\t", ";")


def marked(line: str) -> bool:
    """A line that starts as a comment does (``#``, ``%``) and not with an Excel error value."""
    text = line.lstrip().lower()
    return text.startswith(("#", "%")) and not text.startswith(EXCEL_ERRORS)


def cells(line: str, delimiter: str) -> list[str]:
    return next(csv.reader([line], delimiter=delimiter))


def delimiter(header: str, data: list[str]) -> str:
    """The delimiter (see the module docstring); with no data line, the first of comma, tab,
    semicolon in the header."""
    found = []
    for rank, d in enumerate(_DELIMITERS):
        n = len(cells(header, d))
        if n > 1 and data and all(len(cells(line, d)) == n for line in data):
            found.append((n, -rank, d))
    if found:
        return max(found)[2]
    return next((d for d in _DELIMITERS if d in header), ",")


def _names_a_column(cell: str) -> bool:
    role, is_err, _, _, _, base = classify_header(cell.strip())
    return role is not None or (base in condition_names() and not is_err)


def _numbers_only(line: str) -> bool:
    """Every cell a number (a decimal comma allowed in a ';' or tab line) or empty."""
    d = next((d for d in (";", "\t", ",") if d in line), None)
    parts = [c.strip() for c in (cells(line, d) if d else [line])]
    return all(is_number(c if d == "," else c.replace(",", ".")) for c in parts if c)


def split(text: str):
    """``(delimiter, lines, skipped)``: the header's and the data's ``(line number, text)``,
    the header first (without a comment marker it had), and the line numbers of comments
    below the header; None if the text holds no header (empty, only comments).  Empty lines
    and a spreadsheet's empty rows (``,,``) are dropped."""
    candidates = [(i + 1, line) for i, line in enumerate(text.splitlines()) if line.strip(" \t,;")]
    first = next((k for k, (_, line) in enumerate(candidates) if not marked(line)), None)
    if first is None:
        return None
    start, header = first, candidates[first][1]
    if _numbers_only(header):  # data with its header behind a comment marker
        for k in range(first - 1, -1, -1):
            line = candidates[k][1].lstrip()[1:]
            if any(_names_a_column(c) for c in cells(line, delimiter(line, [header]))):
                start, header = k, line
                break
    body = candidates[start + 1:]
    d = delimiter(header, [line for _, line in body if not marked(line)][:5])
    lines = [(candidates[start][0], header)] + [(no, line) for no, line in body if not marked(line)]
    skipped = [no for no, line in body if marked(line)]
    return d, lines, skipped
