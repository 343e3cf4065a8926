"""``asperity._csv``: the one CSV writer (curves, physical curves, command line, studies)."""

import csv
import io

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from asperity._csv import columns_to_csv, rows_to_csv, table_to_csv


def test_format_by_hand():
    rows = [{"curve": "alpha=0.01 beta=1000", "adhesion": True, "x": 0.1, "n": 2, "s": None},
            {"curve": 'a,"b"', "adhesion": np.bool_(False), "x": np.float32(0.5), "n": 3, "s": "t"}]
    assert rows_to_csv(rows) == ('curve,adhesion,x,n,s\n'
                                 'alpha=0.01 beta=1000,True,0.1,2,\n'
                                 '"a,""b""",False,0.5,3,t\n')
    assert rows_to_csv(rows, ["x", "curve"]).splitlines()[0] == "x,curve"


def test_columns_are_all_floats():
    text = columns_to_csv({"d": np.array([0, 1]), "P": [1e-300, np.float64(2.5)]})
    assert text == "d,P\n0.0,1e-300\n1.0,2.5\n"
    with pytest.raises(ValueError):
        columns_to_csv({"a": [1.0, 2.0], "b": [1.0]})


def test_write_to_buffer_and_path(tmp_path):
    buf = io.StringIO()
    assert columns_to_csv({"a": [1.0]}, buf) is None and buf.getvalue() == "a\n1.0\n"
    path = tmp_path / "t.csv"
    assert rows_to_csv([{"a": 1.5}], None, path) is None and path.read_text() == "a\n1.5\n"


def test_empty_table():
    assert table_to_csv(["a", "b"], []) == "a,b\n"


@given(st.lists(st.floats(allow_nan=False), min_size=1, max_size=30))
def test_floats_round_trip_exactly(values):
    text = columns_to_csv({"v": np.array(values)})
    back = [float(r[0]) for r in list(csv.reader(io.StringIO(text)))[1:]]
    assert [repr(v) for v in back] == [repr(float(v)) for v in values]


def test_writing_into_a_missing_directory_names_the_path(tmp_path):
    """Found by a review: ``to_csv('nodir/x.csv')`` raised FileNotFoundError naming the
    temporary file; every writer now says which directory is missing, naming the argument."""
    import asperity
    from asperity.heights.samples import write_samples
    from asperity.studies.table1 import write_table1_csv

    target = str(tmp_path / "nodir" / "x.csv")
    for write in (lambda: asperity.load_curve([1.0], 0.01, 1000.0).to_csv(target),
                  lambda: write_table1_csv(target, rows=[]),
                  lambda: write_samples(target, [1.0, 2.0, 3.0])):
        with pytest.raises(ValueError, match=r"x.csv': '.*nodir' does not exist"):
            write()
    assert not (tmp_path / "nodir").exists()
    (tmp_path / "file").write_text("")
    with pytest.raises(ValueError, match=r"'.*file' is a file, not a directory"):
        write_samples(str(tmp_path / "file" / "x.txt"), [1.0, 2.0, 3.0])
