"""``asperity.cli._output``: formats, strict JSON on every command, atomic -o."""

import json

import numpy as np
import pytest

from asperity.cli._output import format_rows, image_format

from .helpers import AU, MODEL, one_line_error, rows_of, run, strict_json


def test_format_rows():
    rows = [{"name": "a,b", "x": 0.1, "flag": True, "n": 3}, {"name": "c", "x": np.float64(1e-300), "flag": False,
                                                             "n": 4}]
    assert format_rows(rows, "csv") == 'name,x,flag,n\n"a,b",0.1,True,3\nc,1e-300,False,4\n'
    assert strict_json(format_rows(rows, "json")) == [
        {"name": "a,b", "x": 0.1, "flag": True, "n": 3}, {"name": "c", "x": 1e-300, "flag": False, "n": 4}]
    table = format_rows(rows, "table").splitlines()
    assert table[0].split() == ["name", "x", "flag", "n"] and table[2].split() == ["c", "1e-300", "False", "4"]
    assert len({len(line) for line in table}) == 1  # aligned columns


def test_image_format():
    assert [image_format(p) for p in ("a.png", "b.SVG", "dir.v2/c", "d", ".hidden", "e.pdf")] == [
        "png", "svg", "png", "png", "png", "pdf"]


def test_json_has_no_infinity_or_nan(capsys):
    code, out, _ = run(capsys, "load", *MODEL, "--P", "5e-324,0,1", "--format", "json")
    assert code == 0
    rows = json.loads(out)  # strict JSON: Infinity/NaN would not parse back as null
    assert rows[0]["mu"] is None and rows[1]["mu"] is None and rows[2]["mu"] > 0


def _leaves(value):
    if isinstance(value, dict):
        return [x for v in value.values() for x in _leaves(v)]
    if isinstance(value, list):
        return [x for v in value for x in _leaves(v)]
    return [value]


@pytest.mark.parametrize("argv, has_null", [
    (["load", *MODEL, "--P", "0,1,1e3"], True),                          # mu undefined at P = 0
    (["separation", *MODEL, "--d", "-1,0,30"], True),                    # mu undefined for P < 0
    (["pulloff", "--alpha", "0.01", "--beta", "1000", "--gamma", "0"], True),  # no pull-off: d undefined
    (["pulloff", *MODEL], False),
    (["load", *AU, "--load", "0N,1mN"], True),
    (["separation", *AU, "--separation", "0nm,59nm"], True),
    (["pulloff", *AU, "--no-adhesion"], True),
    (["md", "--lam", "1", "--delta", "-0.5,0,1"], False),
    (["md", "--lam", "0.5", "--pulloff"], False),
    (["materials"], True),  # missing table values are null (they were "")
    (["materials", "--sources"], True),
])
def test_every_json_output_is_strict(capsys, argv, has_null):
    code, out, _ = run(capsys, *argv, "--format", "json")
    assert code == 0
    values = _leaves(strict_json(out))  # raises on NaN/Infinity
    assert (None in values) == has_null


def test_non_finite_values_become_null_in_every_table_command(capsys, monkeypatch):
    # materials: a table row with a non-finite number (as a hand-edited table could hold).
    import asperity.materials

    table = asperity.materials.material_table()
    table[0] = {**table[0], "E_Pa": float("nan"), "nu": float("inf")}
    monkeypatch.setattr(asperity.materials, "material_table", lambda: table)
    code, out, _ = run(capsys, "materials", "--format", "json")
    assert code == 0 and strict_json(out)[0]["E_Pa"] is None and strict_json(out)[0]["nu"] is None


def test_output_file_and_plot(capsys, tmp_path):
    out_csv, png = tmp_path / "c.csv", tmp_path / "c.png"
    code, out, _ = run(capsys, "load", *MODEL, "--P", "1:1e3:20", "-o", str(out_csv),
                       "--plot", str(png))
    assert code == 0 and out == ""
    assert len(rows_of(out_csv.read_text())) == 20
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    code, _, _ = run(capsys, "separation", *MODEL, "--d", "0:4:9", "--plot", str(png))
    assert code == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["c.csv", "c.png"]  # no temporary files


def test_output_replaces_an_existing_file_keeping_its_mode(capsys, tmp_path):
    target = tmp_path / "out.csv"
    target.write_text("old content that is longer than nothing\n" * 100)
    target.chmod(0o640)
    code, _, _ = run(capsys, "md", "--lam", "1", "--pulloff", "-o", str(target), "--format", "csv")
    assert code == 0 and [r["control"] for r in rows_of(target.read_text())] == ["load", "displacement"]
    assert target.stat().st_mode & 0o777 == 0o640


def test_output_to_a_device_is_written_in_place(capsys):
    code, _, _ = run(capsys, "md", "--lam", "1", "--pulloff", "-o", "/dev/null")
    assert code == 0


@pytest.mark.parametrize("exc", [OSError(28, "No space left on device"), KeyboardInterrupt()])
def test_failure_mid_write_leaves_no_partial_file(capsys, tmp_path, monkeypatch, exc):
    # The write fails after half the text: the old file is untouched, no temporary file remains.
    import builtins

    target = tmp_path / "out.csv"
    target.write_text("previous result\n")
    real_open = builtins.open

    class HalfWriter:
        def __init__(self, fh):
            self.fh = fh

        def __enter__(self):
            return self

        def __exit__(self, *a):
            self.fh.close()

        def write(self, text):
            self.fh.write(text[: len(text) // 2])
            self.fh.flush()
            raise exc

    def failing_open(file, mode="r", *args, **kwargs):
        fh = real_open(file, mode, *args, **kwargs)
        return HalfWriter(fh) if "w" in mode and str(file).endswith(".tmp") else fh

    monkeypatch.setattr(builtins, "open", failing_open)
    code, out, err = run(capsys, "load", *MODEL, "--P", "1:1e3:50", "-o", str(target), "--format", "csv")
    monkeypatch.undo()
    assert code == (130 if isinstance(exc, KeyboardInterrupt) else 2)
    if code == 2:
        assert one_line_error(code, err, "cannot write output file") and "No space left" in err
    assert target.read_text() == "previous result\n"
    assert [p.name for p in tmp_path.iterdir()] == ["out.csv"]


def test_outputs_may_not_name_each_other_or_an_input(capsys, tmp_path):
    """A review: --summits replaced the scan it read, and -o and --plot (or --summits) naming one
    file kept only the last written, all with status 0."""
    pytest.importorskip("SurfaceTopography")
    scan = tmp_path / "scan.npy"
    np.save(scan, np.random.default_rng(0).normal(size=(32, 32)))
    before = scan.read_bytes()
    surface = ["surface", str(scan), "--size", "1um,1um", "--unit", "nm", "--format", "json"]
    table = tmp_path / "t.txt"
    for argv, needle in [
        ([*surface, "--summits", str(scan)], "is the input file"),
        ([*surface, "--summits", str(table), "-o", str(table)], "-o and --summits name the same file"),
        ([*surface, "--summits", str(tmp_path / "." / "t.txt"), "-o", str(table)], "name the same file"),
        (["load", *MODEL, "--P", "1,10", "-o", str(tmp_path / "x.png"), "--plot", str(tmp_path / "x.png")],
         "-o and --plot name the same file"),
    ]:
        code, out, err = run(capsys, *argv)
        assert code == 2 and out == "" and err.count("\n") == 1 and needle in err, (argv, err)
    assert scan.read_bytes() == before and not table.exists() and not (tmp_path / "x.png").exists()
