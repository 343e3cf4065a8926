"""Which lines of a measured data file are its header, its data and its comments.

Used by :mod:`asperity.fit.read`.  A line that starts with ``#`` or ``%`` is a comment, with
two exceptions found by user trials and a review (each was lost before):

* above the data, one that names a column the reader knows (``%RH,load (nN),friction (nN)``,
  ``#,load (nN),friction (nN)``) is the header;
* below the header, one that has as many cells as the header is a data row (a sample ID
  ``#2 (retest)``; Excel's error values such as ``#N/A`` are always cells, read as NaN).

The delimiter is the one of comma, tab and semicolon that cuts the header and the first
data lines into as many cells, the most cells if several do, a comma before a tab before
a semicolon on a tie (``Note, free text`` in a tab-separated header; ``load (nN),<TAB>...``
aligned by tabs after the commas).
"""

from __future__ import annotations

import csv

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


def split(text: str):
    """``(delimiter, lines, skipped)``: the header's and the data's ``(line number, text)``,
    the header first, and the line numbers of comments below the header; None if the text
    holds no header (empty, only comments).  Empty lines and a spreadsheet's empty rows
    (``,,``) are dropped."""
    candidates = [(i + 1, line) for i, line in enumerate(text.splitlines()) if line.strip(" \t,;")]
    start = None
    for k, (_, line) in enumerate(candidates):
        if not marked(line):
            start = k
            break
        following = [other for _, other in candidates[k + 1:] if not marked(other)][:1]
        if any(_names_a_column(c) for c in cells(line, delimiter(line, following))):
            start = k
            break
    if start is None:
        return None
    header = candidates[start][1]
    body = candidates[start + 1:]
    d = delimiter(header, [line for _, line in body if not marked(line)][:5])
    n = len(cells(header, d))
    lines, skipped = [candidates[start]], []
    for no, line in body:
        if marked(line) and len(cells(line, d)) != n:
            skipped.append(no)
        else:
            lines.append((no, line))
    return d, lines, skipped
