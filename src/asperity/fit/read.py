r"""Reading measured data from CSV files: columns found by their header names and units.

:func:`read_data` reads a CSV file.  Columns are found by their header:

* dimensionless: ``P``, ``F`` or ``mu``, ``d``, ``P_off``, with ``F_err``, ``mu_err``,
  ``P_err``, ``d_err``, ``P_off_err``;
* physical, the unit in brackets: ``load [mN]``, ``friction [nN]``, ``separation [nm]``,
  ``pull_off [nN]``, ``friction_err [nN]`` (or in parentheses, ``load (mN)``, or after a
  slash between blanks, ``load / mN``, where the text is a unit symbol), or in SI names:
  ``P_N``, ``F_N``, ``d_m``.
  Other spellings: ``normal_force``/``force`` (load), ``friction_force``/``lateral_force``,
  ``friction_coefficient``, ``distance``/``gap`` (separation), ``pull_off_force``/
  ``adhesion_force``.  A physical column without a unit takes one from ``units``
  (``{"load": "mN", "friction": "nN", "separation": "nm"}``; ``load`` also serves normal
  and pull-off forces); an uncertainty column without a unit has its value column's unit.

Comment lines start with ``#`` or ``%`` (those below the header are counted in a note;
Excel's error values such as ``#N/A`` are cells, read as NaN; a header a program marked as
a comment is found: :mod:`asperity.fit._lines`); the delimiter is a comma, a tab or a
semicolon (the one that cuts header and data alike); in a semicolon-separated file a
decimal comma (``4,25``) is read as a decimal point, with a note.  Columns with no name
and no values (a spreadsheet's padding) are dropped; a column whose unit has the wrong
dimension (``lateral force (V)``) is ignored beside one of the right dimension, else
refused.  The text is UTF-8, or UTF-16 with its byte-order mark.  Refused, with a
:class:`ValueError` naming the line and column: a missing, unreadable or empty file, a
missing or ambiguous column (``F`` and ``mu``; ``P`` and ``load [mN]``), a non-numeric
or infinite cell, a NaN (empty) cell unless ``drop_nan=True`` (then the row is dropped
and counted), negative friction or coefficient, a coefficient at a load <= 0, a zero or
negative uncertainty or pull-off force, an unknown unit or one of the wrong dimension,
dimensionless and physical columns mixed, a column unit that contradicts ``units``.  Columns that are none of these are
ignored and named in :attr:`Dataset.notes`.
"""

from __future__ import annotations

import codecs
import csv
import math
import os
import re

import numpy as np

from ..units import parse_quantity, strict_float
from ._lines import EXCEL_ERRORS
from ._lines import split as split_lines
from .data import KINDS, MAX_ROWS, Dataset
from .headers import ROLES, SI_UNITS, UNIT_FLAGS, classify_header, condition_names, to_si_exact, unit_factor

__all__ = ["ROLES", "read_data", "as_dataset"]

_NAN_TEXT = {"", "nan", "na", "n/a", "none", "null"}


def read_data(path, *, kind=None, units=None, drop_nan=False) -> Dataset:
    """Read a CSV file of friction-load, force-separation or pull-off data (see the module docstring).

    Parameters
    ----------
    path : str or os.PathLike
        The CSV file: a header line of column names, then one line per point.
    kind : {'friction', 'force', 'pull_off'}, optional
        What the file must hold; default: found from its columns.
    units : dict, optional
        Units of physical columns whose header has none, by role: ``{"load": "mN",
        "friction": "nN", "separation": "nm"}`` (pint syntax; ``load`` also serves normal
        and pull-off forces).  A header unit that contradicts it is an error.
    drop_nan : bool
        Drop rows with an empty or NaN cell in a column used, and count them
        (:attr:`Dataset.n_dropped`); default: such a row is an error.

    Returns
    -------
    Dataset

    Raises
    ------
    ValueError
        For every problem listed in the module docstring, naming the row and column.
    """
    if units is not None and not isinstance(units, dict):
        raise TypeError(f"units must be a dict of role -> unit (e.g. {{'load': 'nN'}}), got {type(units).__name__}")
    units = dict(units or {})
    for key in units:
        if key not in ("load", "friction", "separation"):
            raise ValueError(f"units: unknown role {key!r}; give load, friction or separation")
    text, name = _read_text(path)
    found = split_lines(text)
    if found is None:
        raise ValueError(f"{name}: no header line (the file is empty or holds only comments)")
    delimiter, lines, skipped = found
    rows = _drop_padding(list(csv.reader([line for _, line in lines], delimiter=delimiter)))
    headers = [h.strip() for h in rows[0]]
    if len(headers) == 1 and len(rows) > 1 and rows[1] and len(rows[1][0].split()) > 1:  # space-separated
        raise ValueError(f"{name}: the header {headers[0]!r} is one column: separate the columns with ',', ';' "
                         "or a tab (spaces cannot, since a name may hold them: 'load [nN]')")
    if len(set(headers)) != len(headers):
        dup = next(h for h in headers if headers.count(h) > 1)
        raise ValueError(f"{name}: column {dup!r} appears twice in the header")
    data_rows = rows[1:]
    if not data_rows:
        why = f" ({len(skipped)} line(s) below it start with '#' or '%', which marks a comment)" if skipped else ""
        raise ValueError(f"{name}: no data rows below the header{why}")
    if len(data_rows) > MAX_ROWS:
        raise ValueError(f"{name}: {len(data_rows)} rows, more than MAX_ROWS = {MAX_ROWS}")
    columns, conditions, ignored = _columns(headers, units, name)
    try:
        kind = _kind(columns, kind, name)
        used, unused = _used(columns, kind, name)
    except ValueError as err:  # say which columns were not recognised ('load (nn)': a typo)
        if ignored and "missing column" in str(err):
            raise ValueError(f"{err} (not recognised: {_shown(ignored)})") from None
        raise
    physical = _physical(columns, used, name)
    values = {key: [] for key in (*used, *conditions)}
    index = {**{k: columns[k][0] for k in used}, **{k: v[0] for k, v in conditions.items()}}
    factor = {**{k: columns[k][1] for k in used}, **{k: v[1] for k, v in conditions.items()}}
    dropped, commas, kept = 0, [], []
    for r, row in enumerate(data_rows):
        line_no = lines[r + 1][0]
        if len(row) != len(headers):
            raise ValueError(f"{name}, line {line_no}: {len(row)} cells, the header has {len(headers)}")
        texts = {k: _decimal_point(row[i], delimiter, commas) for k, i in index.items()}
        cells = {k: _number(texts[k], name, line_no, headers[index[k]]) for k in index}
        if any(np.isnan(v) for v in cells.values()):
            if not drop_nan:
                bad = next(headers[index[k]] for k, v in cells.items() if np.isnan(v))
                raise ValueError(f"{name}, line {line_no}: empty or NaN cell in column {bad!r} (drop such rows with "
                                 "drop_nan=True, --drop-nan on the command line)")
            dropped += 1
            continue
        kept.append(line_no)
        for k, v in cells.items():
            values[k].append(to_si_exact(v, factor[k], texts[k]))
    if not values[used[0]]:
        raise ValueError(f"{name}: every row holds a NaN; nothing left to fit")
    notes = []
    if ignored:
        notes.append(f"{name}: ignored column(s) {_shown(ignored)}")
    if unused:  # the kind given: a sliding distance beside friction data (a user trial: refused before)
        notes.append(f"{name}: ignored column(s) {_shown(unused)} (not used by {kind} data)")
    if dropped:
        notes.append(f"{name}: dropped {dropped} row(s) holding NaN")
    if skipped:  # a user trial: a row '#N/A,...' or '#2 (retest),...' vanished without a word
        shown = ", ".join(map(str, skipped[:5])) + (", ..." if len(skipped) > 5 else "")
        notes.append(f"{name}: skipped {len(skipped)} comment line(s) below the header (line(s) {shown}: a line "
                     "starting with '#' or '%' is a comment)")
    if commas:
        notes.append(f"{name}: read decimal commas as decimal points in the ';'-separated file ({commas[0]!r} is "
                     f"{commas[0].replace(',', '.')})")
    for k in (k for k in used if k.endswith("_err")):
        bad = [i for i, v in enumerate(values[k]) if not v > 0]
        if bad:
            raise ValueError(f"{name}, line {kept[bad[0]]}, column {headers[index[k]]!r}: an uncertainty must be "
                             f"> 0, got {values[k][bad[0]]:g}")
    try:
        return _dataset(kind, values, used, conditions, physical, name, dropped, notes)
    except ValueError as err:  # the data's checks count rows: say the file and its line (a user trial)
        text = re.sub(r"\b(at|in) row (\d+)", lambda m: f"{m.group(1)} line {kept[int(m.group(2)) - 1]}", str(err))
        raise ValueError(f"{name}: {text}") from None


_DECIMAL_COMMA = re.compile(r"\s*[+-]?\d+,\d+(?:[eE][+-]?\d+)?\s*")


def _decimal_point(cell: str, delimiter: str, commas: list) -> str:
    """A cell with a decimal comma ('4,299194') as a number with a point, in a ';'-separated
    file only (a spreadsheet's in a language that writes decimal commas); the first counted."""
    if delimiter == ";" and "," in cell and _DECIMAL_COMMA.fullmatch(cell):
        if not commas:
            commas.append(cell.strip())
        return cell.replace(",", ".")
    return cell


def _drop_padding(rows):
    """The rows without columns that have no name and no values (a spreadsheet's padding,
    'load (nN),friction (nN),,': a user trial got "column '' appears twice")."""
    drop = {j for j, h in enumerate(rows[0]) if not h.strip()
            and not any(len(r) > j and r[j].strip() for r in rows[1:])}
    return [[c for j, c in enumerate(r) if j not in drop] for r in rows] if drop else rows


def _shown(ignored) -> str:
    """The ignored headers, quoted, each with its reason if it has one."""
    return ", ".join(f"{h!r}" if isinstance(h, str) else f"{h[0]!r} ({h[1]})" for h in ignored)


def _read_text(path):
    name = os.fspath(path) if isinstance(path, str | os.PathLike) else None
    if name is None:
        raise ValueError(f"path must be a file name, got {path!r}")
    shown = os.path.basename(name) or name
    try:
        with open(name, "rb") as fh:
            raw = fh.read(64 * 1024 * 1024 + 1)
    except OSError as err:
        raise ValueError(f"path: cannot read data file {name!r}: {err.strerror or err}") from None
    if len(raw) > 64 * 1024 * 1024:
        raise ValueError(f"{shown}: larger than 64 MB; not a data file of at most {MAX_ROWS} rows")
    encoding = "utf-16" if raw.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)) else "utf-8-sig"
    try:
        text = raw.decode(encoding)
    except UnicodeDecodeError:
        raise ValueError(f"{shown}: not a text file (not {encoding.removesuffix('-sig').upper()}; save it as "
                         "UTF-8 text)") from None
    if "\x00" in text:
        raise ValueError(f"{shown}: not a text file (holds NUL bytes)")
    if encoding == "utf-16" and not any(c.isascii() and c.isalnum() for c in text):
        raise ValueError(f"{shown}: not a text file (no letter or digit after its UTF-16 byte-order mark)")
    return text, shown


def _columns(headers, units, name):
    """Role key ('load', 'friction_err', ...) -> (column index, factor to SI, physical, header).

    ``physical`` is None for a friction coefficient (dimensionless either way).
    """
    columns, conditions, ignored, pending, misfits = {}, {}, [], [], []
    cond_names = condition_names()
    for i, header in enumerate(headers):
        role, is_err, unit, suffix_unit, symbol, base = classify_header(header)
        if role is None:
            if base in cond_names and not is_err:
                conditions[cond_names[base][0]] = (i, _condition_factor(cond_names[base], unit, header, name))
            else:
                ignored.append(header)
            continue
        key = f"{role}_err" if is_err else role
        if unit is not None and suffix_unit is not None:
            raise ValueError(f"{name}: column {header!r} has two units")
        unit = unit if unit is not None else suffix_unit
        if unit is not None and role != "mu":
            try:
                unit_factor(unit, role, header)
            except ValueError as err:  # 'Lateral force (V)' beside 'Friction (nN)': a raw signal
                misfits.append((key, header, err))
                continue
        if key in columns or key in pending:
            first = columns[key][3] if key in columns else next(h for k, h, _ in pending if k == key)
            raise ValueError(f"{name}: ambiguous columns {first!r} and {header!r} (both the "
                             f"{key.replace('_', ' ')}); keep one")
        if role == "mu":
            columns[key] = (i, unit_factor(unit or "", "mu", header), None, header)
            continue
        flag = units.get(UNIT_FLAGS[role])
        if flag is not None:
            if unit is None:
                unit = flag
            elif not math.isclose(unit_factor(unit, role, header), unit_factor(flag, role, header), rel_tol=1e-12):
                raise ValueError(f"{name}: inconsistent units: column {header!r} says [{unit}] but the "
                                 f"{UNIT_FLAGS[role]} unit given is {flag!r}")
        if unit is not None:
            columns[key] = (i, unit_factor(unit, role, header), True, header)
        elif is_err:
            pending.append((key, header, i))  # takes its value column's unit
        elif symbol:
            columns[key] = (i, 1.0, False, header)  # the paper's dimensionless symbol
        else:
            example = f"{header} [{'nN' if SI_UNITS[role] == 'N' else 'nm'}]"
            raise ValueError(f"{name}: column {header!r} has no unit: write it in brackets ({example!r}) or give "
                             f"the {UNIT_FLAGS[role]} unit (units={{'{UNIT_FLAGS[role]}': ...}}, "
                             f"--{UNIT_FLAGS[role]}-unit)")
    for key, header, err in misfits:  # ignored beside a column of the right dimension, else the error
        if key not in columns and all(k != key for k, _, _ in pending):
            raise ValueError(f"{name}: {err}") from None
        ignored.append((header, f"not a unit of {key.replace('_', ' ')}"))
    for key, header, i in pending:
        value = columns.get(key.removesuffix("_err"))
        factor, physical = (value[1], value[2]) if value is not None else (1.0, False)
        columns[key] = (i, factor, physical, header)
    return columns, conditions, ignored


def _condition_factor(entry, unit, header, name):
    fit_name, si = entry
    if not si:
        if unit not in (None, "", "1", "-"):
            raise ValueError(f"{name}: column {header!r}: {fit_name} is dimensionless, got the unit {unit!r}")
        return 1.0
    return parse_quantity(f"1 {unit or si}", si, f"column {header!r}")


def _kind(columns, kind, name):
    found = [k for k, role in (("force", "separation"), ("pull_off", "pull_off")) if role in columns]
    if "friction" in columns or "mu" in columns:
        found.append("friction")
    if "friction" in columns and "mu" in columns:
        raise ValueError(f"{name}: ambiguous columns: both a friction force ({columns['friction'][3]!r}) and a "
                         f"coefficient ({columns['mu'][3]!r}); keep one")
    if kind is not None:
        if not isinstance(kind, str) or kind not in KINDS:
            raise ValueError(f"kind must be one of {', '.join(KINDS)}, got {kind!r}")
        if kind not in found:
            need = {"friction": "a load and a friction (F, mu, friction [nN])", "force":
                    "a separation (d, separation [nm]) and a normal force (P, force [nN])",
                    "pull_off": "a pull-off force (P_off, pull_off [nN])"}[kind]
            raise ValueError(f"{name}: missing column: {kind} data need {need}")
        return kind
    if len(found) != 1:
        raise ValueError(f"{name}: " + ("missing columns: found no friction (F, mu, friction [nN]), separation "
                                        "(d, separation [nm]) or pull-off (P_off, pull_off [nN]) column"
                                        if not found else f"ambiguous data: columns of {' and '.join(found)} data; "
                                        "give the kind"))
    return found[0]


def _used(columns, kind, name):
    x, y = {"friction": ("load", "mu" if "mu" in columns else "friction"), "force": ("separation", "load"),
            "pull_off": (None, "pull_off")}[kind]
    for role in (x, y):
        if role is not None and role not in columns:
            what = {"load": "a load (P, load [mN]) or normal force (force [nN])",
                    "separation": "a separation", "friction": "a friction"}[role]
            raise ValueError(f"{name}: missing column: {kind} data need {what}")
    used = [k for k in (y, x, f"{y}_err", f"{x}_err") if k in columns]
    return used, [columns[k][3] for k in columns if k not in used]


def _physical(columns, used, name):
    """True if the columns used are physical (SI), False if dimensionless; mixed is an error."""
    flags = [(columns[k][3], columns[k][2]) for k in used if columns[k][2] is not None]
    dimless = [h for h, physical in flags if not physical]
    physical = [h for h, p in flags if p]
    if dimless and physical:
        raise ValueError(f"{name}: inconsistent units: {dimless[0]!r} is dimensionless but {physical[0]!r} has a unit")
    return bool(physical)


def _number(cell: str, name, line_no, header) -> float:
    text = cell.strip()
    if text.lower() in _NAN_TEXT or text.lower() in EXCEL_ERRORS:
        return float("nan")
    try:
        value = strict_float(text)
    except ValueError as err:
        why = str(err) if "smallest double" in str(err) else f"{text!r} is not a number"
        raise ValueError(f"{name}, line {line_no}, column {header!r}: {why}") from None
    if np.isinf(value):
        raise ValueError(f"{name}, line {line_no}, column {header!r}: {text!r} is not finite")
    return value


def _dataset(kind, values, used, conditions, physical, name, dropped, notes) -> Dataset:
    arr = {k: np.asarray(v, dtype=float) for k, v in values.items()}
    cond = {k: arr[k] for k in conditions}
    if kind == "pull_off":
        return Dataset("pull_off", np.arange(arr["pull_off"].size, dtype=float), arr["pull_off"], "pull_off",
                       physical, y_err=arr.get("pull_off_err"), conditions=cond, name=name, n_dropped=dropped,
                       notes=tuple(notes))
    if cond:
        notes = [*notes, f"{name}: ignored condition column(s) {', '.join(cond)} (only pull-off data use them)"]
    if kind == "force":
        return Dataset("force", arr["separation"], arr["load"], "P", physical, y_err=arr.get("load_err"),
                       x_err=arr.get("separation_err"), name=name, n_dropped=dropped, notes=tuple(notes))
    y = "mu" if "mu" in arr else "friction"
    return Dataset("friction", arr["load"], arr[y], "mu" if y == "mu" else "F", physical, y_err=arr.get(f"{y}_err"),
                   x_err=arr.get("load_err"), name=name, n_dropped=dropped, notes=tuple(notes))


_KIND_NAMES = {"friction": "friction-load", "force": "force-separation", "pull_off": "pull-off"}


def as_dataset(data, kind=None, units=None, drop_nan=False) -> Dataset:
    """``data`` as a :class:`Dataset`: a Dataset (checked to be of ``kind``) or a CSV path read with :func:`read_data`.

    Raises
    ------
    ValueError
        For data of another kind, anything but a Dataset or a path, or a file :func:`read_data` refuses.
    """
    if kind is not None and (not isinstance(kind, str) or kind not in KINDS):
        raise ValueError(f"kind must be one of {', '.join(KINDS)}, got {kind!r:.60}")
    if units is not None and not isinstance(units, dict):
        raise TypeError(f"units must be a dict of role -> unit (e.g. {{'load': 'nN'}}), got {type(units).__name__}")
    if isinstance(data, Dataset):
        if kind is not None and data.kind != kind:
            raise ValueError(f"expected {_KIND_NAMES[kind]} data, got {_KIND_NAMES[data.kind]} data ({data.name})")
        return data
    if isinstance(data, str | os.PathLike):
        try:
            return read_data(data, kind=kind, units=units, drop_nan=drop_nan)
        except ValueError as err:
            raise ValueError(f"data: {err}") from None
    raise ValueError(f"data must be a Dataset or the path of a CSV file, got {type(data).__name__}")
