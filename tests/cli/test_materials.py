"""``asperity materials``: the table, in every format."""

import csv
import io

from asperity.materials import material_table

from .helpers import rows_of, run


def test_materials_listing(capsys):
    code, out, _ = run(capsys, "materials", "--format", "csv", "--sources")
    rows = rows_of(out)
    assert code == 0 and {"Au", "Si", "diamond", "Au/mica"} <= {r["name"] for r in rows}
    assert all(r["sources"] for r in rows if r["E_Pa"])


def test_materials_csv_quotes_text_with_commas(capsys):
    # Sources contain commas: each row must still have exactly the header's fields.
    code, out, _ = run(capsys, "materials", "--format", "csv", "--sources")
    records = list(csv.reader(io.StringIO(out)))
    assert code == 0 and all(len(r) == len(records[0]) for r in records)
    table = {row["name"]: row for row in material_table()}
    for name, *_, sources in records[1:]:
        assert sources == (table[name]["sources"] or "")


def test_materials_values_round_trip(capsys):
    code, out, _ = run(capsys, "materials", "--format", "csv")
    table = {row["name"]: row for row in material_table()}
    assert code == 0
    for r in rows_of(out):
        for key in ("E_Pa", "nu", "b_m", "work_of_adhesion_J_m2", "hardness_Pa", "ise_H0_Pa", "ise_h_star_m"):
            want = table[r["name"]][key]
            assert (r[key] == "") if want is None else float(r[key]) == want


def test_materials_json_has_null_for_missing_values(capsys):
    """A CLI check: missing values were "" among the numbers (strict JSON has null, as the README says)."""
    import json

    from asperity.materials import material_table

    code, out, _ = run(capsys, "materials", "--format", "json")
    rows = json.loads(out)
    table = {r["name"]: r for r in material_table()}
    assert code in (0, None) and rows and all(v != "" for r in rows for v in r.values())
    assert all(r[k] == table[r["name"]][k] for r in rows for k in r)
    assert any(v is None for r in rows for v in r.values())
