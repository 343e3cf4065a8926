"""The table of real materials, ``asperity/data/materials.csv``, as rows of SI numbers.

Handbook values with a source for every number; missing values are empty in the file and
None here, never guessed.  :func:`asperity.materials.material` makes a
:class:`~asperity.materials.Material` of a row; this module only reads the file (once,
cached).
"""

from __future__ import annotations

import csv
import functools
from importlib import resources

from ._validation import check_text

__all__ = ["TABLE_UNITS", "material_names", "material_table", "table_row"]

#: Numeric columns of the table and their SI units.
TABLE_UNITS = {
    "E_Pa": "Pa",
    "nu": "1",
    "G_Pa": "Pa",
    "lattice_constant_m": "m",
    "b_m": "m",
    "surface_energy_J_m2": "J/m^2",
    "work_of_adhesion_J_m2": "J/m^2",
    "hardness_Pa": "Pa",
    "ise_H0_Pa": "Pa",
    "ise_h_star_m": "m",
}


def _cell(row: dict, column: str) -> float | None:
    text = (row.get(column) or "").strip()
    return float(text) if text else None


@functools.cache
def _rows() -> tuple[dict, ...]:
    text = resources.files("asperity").joinpath("data/materials.csv").read_text(encoding="utf-8")
    lines = [line for line in text.splitlines() if line.strip() and not line.startswith("#")]
    rows = []
    for raw in csv.DictReader(lines):
        row = {k: (v or "").strip() for k, v in raw.items()}
        row.update({column: _cell(raw, column) for column in TABLE_UNITS})
        rows.append(row)
    return tuple(rows)


def material_table() -> list[dict]:
    """Every row of ``data/materials.csv`` as a dict (numbers as float in SI units, missing as None).

    Keys: ``name``, ``kind``, ``components``, the numeric columns of :data:`TABLE_UNITS`,
    ``slip_system`` and ``sources``.
    """
    return [dict(row) for row in _rows()]


def material_names() -> list[str]:
    """Names of the materials in the table (elements, compounds, then pairs such as ``'Au/Au'``)."""
    return [row["name"] for row in _rows()]


def table_row(name: str) -> dict | None:
    """The row of ``name`` (case-insensitive, surrounding blanks ignored) as a dict, or None.

    Parameters
    ----------
    name : str
        A material name such as ``'Au'`` or ``'Au/mica'`` (pairs have rows of their own).

    Returns
    -------
    dict or None
        A copy of the row as :func:`material_table` gives it, None for a name not in the table.
    """
    key = check_text(name, "name").strip().lower()
    for row in _rows():
        if row["name"].lower() == key:
            return dict(row)
    return None
