"""Reading data files: columns by header name and unit, and every refusal (one ValueError each)."""

import numpy as np
import pytest

from asperity.fit import Dataset, force_separation_data, friction_load_data, pull_off_data, read_data


def write(tmp_path, text, name="data.csv"):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


@pytest.mark.parametrize("text, kind, quantity, physical, x, y", [
    ("P,F\n1,2\n3,4\n", "friction", "F", False, [1, 3], [2, 4]),
    ("P,mu\n1,0.2\n3,0.1\n", "friction", "mu", False, [1, 3], [0.2, 0.1]),
    ("load [mN],friction [nN]\n1,2\n", "friction", "F", True, [1e-3], [2e-9]),
    ("P_N,F_N\n1e-3,2e-9\n", "friction", "F", True, [1e-3], [2e-9]),
    ("normal_force [uN];lateral_force [nN]\n2;3\n", "friction", "F", True, [2e-6], [3e-9]),
    ("load [mN]\tfriction_coefficient\n2\t0.3\n", "friction", "mu", True, [2e-3], [0.3]),
    ("d,P\n-1,5\n2,-0.1\n", "force", "P", False, [-1, 2], [5, -0.1]),
    ("separation [nm],force [nN]\n1,-2\n", "force", "P", True, [1e-9], [-2e-9]),
    ("P_off\n3\n4\n", "pull_off", "pull_off", False, [0, 1], [3, 4]),
    ("# synthetic\n\nP, F \n# a comment\n1, 2\n", "friction", "F", False, [1], [2]),
    ("\ufeffP,F\n1,2\n", "friction", "F", False, [1], [2]),
])
def test_columns_found_by_header(tmp_path, text, kind, quantity, physical, x, y):
    d = read_data(write(tmp_path, text))
    assert (d.kind, d.quantity, d.physical) == (kind, quantity, physical)
    np.testing.assert_allclose(d.x, x, rtol=1e-12)
    np.testing.assert_allclose(d.y, y, rtol=1e-12)


def test_uncertainties_and_their_units(tmp_path):
    d = read_data(write(tmp_path, "load [mN],friction [nN],friction_err,load_err [uN]\n1,2,0.1,5\n2,3,0.2,5\n"))
    np.testing.assert_allclose(d.y_err, [1e-10, 2e-10], rtol=1e-12)  # inherits [nN]
    np.testing.assert_allclose(d.x_err, [5e-6, 5e-6], rtol=1e-12)
    d = read_data(write(tmp_path, "P,F,F_err,P_err\n1,2,0.1,0.01\n"))
    assert d.y_err[0] == 0.1 and d.x_err[0] == 0.01 and not d.physical


def test_units_from_flags(tmp_path):
    path = write(tmp_path, "load,friction\n1,2\n")
    d = read_data(path, units={"load": "mN", "friction": "nN"})
    assert d.physical and d.x[0] == pytest.approx(1e-3) and d.y[0] == pytest.approx(2e-9)
    d = read_data(write(tmp_path, "load [mN],friction [nN]\n1,2\n"), units={"load": "millinewton"})
    assert d.x[0] == pytest.approx(1e-3)  # the same unit twice is fine


def test_pull_off_conditions(tmp_path):
    d = read_data(write(tmp_path, "R [nm],pull_off [nN],pull_off_err\n10,2,0.1\n20,4,0.1\n"))
    np.testing.assert_allclose(d.conditions["R_m"], [1e-8, 2e-8])
    assert d.physical and d.y_err[0] == pytest.approx(1e-10)
    d = read_data(write(tmp_path, "alpha,P_off\n0.002,2100\n0.003,320\n"))
    np.testing.assert_array_equal(d.conditions["alpha"], [0.002, 0.003])


def test_ignored_columns_and_dropped_rows_are_reported(tmp_path):
    d = read_data(write(tmp_path, "time [s],P,F\n0,1,2\n1,,3\n2,3,4\n"), drop_nan=True)
    assert len(d) == 2 and d.n_dropped == 1
    assert any("ignored column(s) 'time [s]'" in n for n in d.notes)
    assert any("dropped 1 row(s)" in n for n in d.notes)


@pytest.mark.parametrize("text, kwargs, match", [
    ("", {}, "no header line"),
    ("# only a comment\n", {}, "no header line"),
    ("P,F\n", {}, "no data rows"),
    ("P,F,F\n1,2,3\n", {}, "appears twice"),
    ("x,y\n1,2\n", {}, "missing columns: found no friction"),
    ("P,time\n1,2\n", {}, "missing columns"),
    ("F\n1\n", {}, "missing column: friction data need a load"),
    ("P,F,mu\n1,2,0.3\n", {}, "ambiguous columns: both a friction force"),
    ("P,load [mN],F\n1,2,3\n", {}, r"ambiguous columns 'P' and 'load \[mN\]'"),
    ("P,F\n1,abc\n", {}, "line 2, column 'F': 'abc' is not a number"),
    ("P,F\n1,inf\n", {}, "'inf' is not finite"),
    ("P,F\n1,\n", {}, "line 2: empty or NaN cell in column 'F'.*--drop-nan"),
    ("P,F\n1,nan\n", {}, "NaN cell"),
    ("P,F\n1,nan\n", {"drop_nan": True}, "every row holds a NaN"),
    ("P,F\n1,-2\n", {}, "data.csv: negative friction: F = -2 at line 2"),
    ("# x\nP,F\n1,2\n\n3,-2\n", {}, "data.csv: negative friction: F = -2 at line 5"),
    ("load (nN),mu\n-1,-0.5\n", {}, "a friction coefficient needs a load > 0, got P = -1e-09 at line 2"),
    ("P,mu\n0,0.1\n", {}, "a friction coefficient needs a load > 0"),
    ("P,F,F_err\n1,2,0\n", {}, r"data.csv, line 2, column 'F_err': an uncertainty must be > 0, got 0"),
    ("P_off\n-1\n", {}, "pull-off forces must be > 0"),
    ("load,friction [nN]\n1,2\n", {}, "column 'load' has no unit.*--load-unit"),
    ("load [furlong],friction [nN]\n1,2\n", {}, "not a quantity with a unit|compatible"),
    ("load [nm],friction [nN]\n1,2\n", {}, "compatible with N"),
    ("load [mN],friction [nN]\n1,2\n", {"units": {"load": "nN"}}, "inconsistent units: column 'load \\[mN\\]'"),
    ("P,friction [nN]\n1,2\n", {}, "inconsistent units: 'P' is dimensionless but 'friction \\[nN\\]'"),
    ("P,F,F_err [nN]\n1,2,0.1\n", {}, "inconsistent units"),
    ("mu [nN],P\n1,2\n", {}, "friction coefficient is dimensionless"),
    ("P,F\n1,2,3\n", {}, "line 2: 3 cells, the header has 2"),
    ("P,F\n1,2\n", {"kind": "force"}, "missing column: force data need a separation"),
    ("P,F\n1,2\n", {"kind": "wear"}, "kind must be one of"),
    ("P,F\n1,2\n", {"units": {"pressure": "Pa"}}, "units: unknown role 'pressure'"),
    ("d,P,F\n1,2,3\n", {}, "ambiguous data: columns of force and friction data"),
])
def test_refused(tmp_path, text, kwargs, match):
    with pytest.raises(ValueError, match=match):
        read_data(write(tmp_path, text), **kwargs)


def test_unreadable_files(tmp_path):
    with pytest.raises(ValueError, match="cannot read data file .*No such file"):
        read_data(tmp_path / "missing.csv")
    with pytest.raises(ValueError, match="cannot read data file .*directory"):
        read_data(tmp_path)
    (tmp_path / "bin.csv").write_bytes(b"\x89PNG\r\n\x1a\n\x00\x00")
    with pytest.raises(ValueError, match="not a text file"):
        read_data(tmp_path / "bin.csv")
    with pytest.raises(ValueError, match="path must be a file name"):
        read_data(42)


def test_dataset_checks_its_arrays():
    with pytest.raises(ValueError, match="^F must have the length of P"):  # the arguments' names
        friction_load_data([1.0, 2.0], [1.0])
    with pytest.raises(ValueError, match="^force_err must have the length of force"):
        pull_off_data([1.0, 2.0], force_err=[0.1])
    with pytest.raises(TypeError, match="^physical must be"):
        friction_load_data([1.0], [1.0], physical=None)
    with pytest.raises(ValueError, match="give the friction force F or the coefficient mu"):
        friction_load_data([1.0], [1.0], mu=[0.1])
    with pytest.raises(ValueError, match="^P must be 1-D"):
        friction_load_data([[1.0]], [[1.0]])
    with pytest.raises(ValueError, match="^P must be finite"):
        force_separation_data([1.0], [np.nan])
    with pytest.raises(ValueError, match="^P must be a real number"):
        friction_load_data([True], [1.0])
    with pytest.raises(ValueError, match=r"conditions\['alpha'\] must have one value per row"):
        pull_off_data([1.0, 2.0], conditions={"alpha": [0.1]})
    with pytest.raises(ValueError, match="kind must be one of"):
        Dataset("wear", [1.0], [1.0], "F")
    d = friction_load_data([1.0, 2.0], mu=[0.1, 0.2], physical=True)
    assert (d.x_name, d.y_name) == ("P_N", "mu")


@pytest.mark.parametrize("header", ["load [nN],friction [nN],friction_err [nN]",
                                    "load (nN),friction (nN),friction_err (nN)",
                                    "load / nN,friction / nN,friction_err / nN",
                                    "Load (nN);Friction [nN];friction_err / nN"])
def test_units_in_brackets_parentheses_or_after_a_slash(tmp_path, header):
    """Found by a review: 'load (nN)' and 'load / nN' (spreadsheet and ISO 80000 styles) were not
    recognised, with a message saying the friction column was missing."""
    sep = ";" if ";" in header else ","
    path = tmp_path / "d.csv"
    path.write_text(header + "\n" + f"1{sep}2{sep}0.1\n3{sep}4{sep}0.1\n")
    d = read_data(str(path))
    assert d.kind == "friction" and d.physical
    np.testing.assert_array_equal(d.x, [1e-9, 3e-9])
    np.testing.assert_array_equal(d.y, [2e-9, 4e-9])
    np.testing.assert_array_equal(d.y_err, [1e-10, 1e-10])


@pytest.mark.parametrize("header, row, read_as", [
    ("P,F,F/P", "1,0.5,0.5", "friction"),                       # a ratio column, not F in units of P
    ("load (nN),friction (nN),friction/load", "1,0.5,0.5", "friction"),
    ("P_N,F_N,mu (-)", "1e-9,5e-10,0.5", "friction"),
    ("load [nN],friction [nN],friction (a.u.)", "1,0.5,7", "friction"),
])
def test_a_name_with_a_slash_or_parentheses_that_is_no_unit_is_ignored_as_before(tmp_path, header, row, read_as):
    """Found by the review of the fix above: 'F/P' became F in units of P (ambiguous with F),
    'friction (a.u.)' a pint error; only a unit of the column's dimension is read as one."""
    path = tmp_path / "d.csv"
    path.write_text(header + "\n" + row + "\n" + row + "\n")
    d = read_data(str(path))
    assert d.kind == read_as and any("ignored column" in n for n in d.notes)


def test_decimal_prefixes_in_files_read_as_on_the_command_line(tmp_path):
    path = tmp_path / "d.csv"
    path.write_text("load / nN,friction [uN]\n3.3,3.3\n4.76,1.6\n")
    d = read_data(str(path))
    assert d.x.tolist() == [3.3e-9, 4.76e-9] and d.y.tolist() == [3.3e-6, 1.6e-6]


@pytest.mark.parametrize("header, match", [
    ("load (nm),friction (nN)", r"column 'load \(nm\)' must have units compatible with N"),
    ("load (nN),friction (uN),friction_err (nm)", r"column 'friction_err \(nm\)' must have units compatible"),
    ("load (nn),friction (nN)", r"missing column: .* \(not recognised: 'load \(nn\)'\)"),
])
def test_a_unit_in_parentheses_of_the_wrong_dimension_or_mistyped_is_named(tmp_path, header, match):
    """The second review: such columns were silently ignored where the bracket form names them."""
    path = tmp_path / "d.csv"
    path.write_text(header + "\n" + ",".join(["1"] * (header.count(",") + 1)) + "\n")
    with pytest.raises(ValueError, match=match):
        read_data(str(path))


def test_symbols_and_conditions_take_units_in_parentheses_too(tmp_path):
    path = tmp_path / "f.csv"
    path.write_text("P (nN),F (nN)\n1,2\n3,4\n")
    d = read_data(str(path))
    assert d.physical and d.x.tolist() == [1e-9, 3e-9]
    path = tmp_path / "po.csv"
    path.write_text("R (nm),pull_off / nN\n10,5\n20,10\n")
    d = read_data(str(path))
    assert d.kind == "pull_off" and d.conditions["R_m"].tolist() == [1e-8, 2e-8]


def test_long_decimal_cells_are_exact_too(tmp_path):
    """The second review: the digits were the float's, so 16-20 digit cells (numpy's %.18e)
    were one ulp off in about 30 % of cases."""
    from decimal import Decimal

    texts = [f"{x:.18e}" for x in np.random.default_rng(0).uniform(0.1, 1e5, 200)]
    path = tmp_path / "d.csv"
    path.write_text("load [nN],friction [nN]\n" + "".join(f"{t},1\n" for t in texts))
    d = read_data(str(path))
    assert d.x.tolist() == [float(Decimal(t).scaleb(-9)) for t in texts]


def test_spreadsheet_exports_read_as_the_plain_file(tmp_path):
    """A user trial with files as spreadsheets and instruments write them: Excel's padding
    (',,' on every line, empty rows), UTF-16 (Windows 'Unicode text'), a semicolon file
    with decimal commas (German/French Excel), '%' comments (MATLAB): each refused before,
    now each read as the plain file, with a note where something was interpreted."""
    rows = [(-8.0, 4.299194), (-6.0, 5.229111), (10.0, 9.5), (50.0, 14.787114)]
    plain = "load (nN),friction (nN)\n" + "".join(f"{p:.6f},{f:.6f}\n" for p, f in rows)
    ref = read_data(write(tmp_path, plain, "plain.csv"))
    padded = plain.replace("\n", ",,\n") + ",,\n,,\n"
    semi = plain.replace(",", ";").replace(".", ",")
    cases = {"padded.csv": (padded.encode(), None),
             "utf16.csv": (plain.replace(",", "\t").replace("\n", "\r\n").encode("utf-16"), None),
             "semi.csv": (semi.encode(), "read decimal commas as decimal points in the ';'-separated file "
                                         "('4,299194' is 4.299194)"),
             "pct.csv": (("% AFM export\n" + plain).encode(), None)}
    for name, (raw, note) in cases.items():
        (tmp_path / name).write_bytes(raw)
        d = read_data(tmp_path / name)
        np.testing.assert_array_equal(d.x, ref.x)
        np.testing.assert_array_equal(d.y, ref.y)
        assert [n.split(": ", 1)[1] for n in d.notes] == ([note] if note else []), (name, d.notes)


@pytest.mark.parametrize("first", ["#N/A", "#VALUE!", "#DIV/0!"])
def test_an_excel_error_cell_is_a_nan_cell_not_a_comment(tmp_path, first):
    """A user trial: a row starting with '#N/A' was skipped as a comment without a word (and
    refused when the error was in the second column).  Excel's errors are NaN cells."""
    path = write(tmp_path, f"P,F\n1,2\n{first},3\n4,5\n")
    with pytest.raises(ValueError, match="line 3: empty or NaN cell in column 'P'"):
        read_data(path)
    d = read_data(path, drop_nan=True)
    assert d.x.tolist() == [1, 4] and d.n_dropped == 1


def test_comment_lines_below_the_header_are_counted(tmp_path):
    """A user trial: a row whose sample ID starts with '#' vanished as a comment, unnoted.  Such
    lines stay comments, as pandas and numpy read them (a review: taking them for data read a
    commented-out row '#B (bad tip),3,400' as a point), and are counted in a note."""
    d = read_data(write(tmp_path, "Sample,R (nm),pull_off (nN)\nA,10,4.9\n#2 (retest),20,9.4\nC,30,14.2\n% end\n"
                                  "# a note, with a comma\n"))
    assert len(d) == 2 and d.conditions["R_m"].tolist() == pytest.approx([1e-8, 3e-8])
    assert any(n.endswith("skipped 3 comment line(s) below the header (line(s) 3, 5, 6: a line starting with '#' "
                          "or '%' is a comment)") for n in d.notes), d.notes
    with pytest.raises(ValueError, match=r"no data rows below the header \(2 line\(s\) below it start with '#'"):
        read_data(write(tmp_path, "P,F\n#1,2\n% two\n"))


@pytest.mark.parametrize("text", ["%RH,load (nN),friction (nN)\n40,1,2\n41,3,4\n",
                                  "% load (nN), friction (nN)\n1,2\n3,4\n",
                                  "#,load (nN),friction (nN)\n1,1,2\n2,3,4\n",
                                  "# sample A, run 3\n% exported\nRH,load (nN),friction (nN)\n40,1,2\n41,3,4\n",
                                  "# Channels: load (nN), friction (nN)\nload (nN),friction (nN)\n1,2\n3,4\n",
                                  "Sample,load (nN),friction (nN)\nA,1,2\n#B (bad tip),3,400\nC,3,4\n"])
def test_a_header_that_starts_like_a_comment(tmp_path, text):
    """A review: '%RH,load (nN),friction (nN)' was taken for a comment and the first data row
    for the header.  When the first line that is no comment holds only numbers, the header is
    the nearest comment above that names a column; otherwise comments stay comments."""
    d = read_data(write(tmp_path, text))
    assert d.x.tolist() == [1e-9, 3e-9] and d.y.tolist() == [2e-9, 4e-9]


def test_a_column_of_the_wrong_dimension_is_ignored_beside_a_right_one(tmp_path):
    """A user trial: a raw 'Lateral force (V)' beside the calibrated friction made the file
    'ambiguous'; now it is ignored with a note, and still refused on its own."""
    d = read_data(write(tmp_path, "Load (nN),Friction (nN),Lateral force (V)\n1,2,0.5\n3,4,0.7\n"))
    assert d.y.tolist() == [2e-9, 4e-9]
    assert any("ignored column(s) 'Lateral force (V)' (not a unit of friction)" in n for n in d.notes)
    with pytest.raises(ValueError, match="compatible with N"):
        read_data(write(tmp_path, "Load (nN),Lateral force (V)\n1,0.5\n"))


@pytest.mark.parametrize("header", ["Radius (nm)", "Tip radius (nm)", "R (nm)"])
def test_a_radius_column_is_the_pull_off_condition(tmp_path, header):
    d = read_data(write(tmp_path, f"{header},Adhesion force (nN)\n10,4.9\n20,9.4\n"))
    np.testing.assert_allclose(d.conditions["R_m"], [1e-8, 2e-8])


def test_a_text_file_in_another_encoding_is_named(tmp_path):
    (tmp_path / "l1.csv").write_bytes("load (µN),friction (µN)\n1,2\n".encode("latin-1"))
    with pytest.raises(ValueError, match=r"l1\.csv: not a text file \(not UTF-8; save it as UTF-8 text\)"):
        read_data(tmp_path / "l1.csv")


def test_conditions_are_checked_by_name_and_unit():
    """A user trial: conditions={'R': ...} (for 'R_m') was ignored without a word, and unit
    strings in physical data were refused as 'dimensionless'."""
    with pytest.raises(ValueError, match="conditions: unknown name 'R'; the names are .*R_m"):
        pull_off_data([1e-7, 2e-7], physical=True, conditions={"R": [1e-6, 2e-6]})
    d = pull_off_data([1e-7, 2e-7], physical=True, conditions={"R_m": ["1um", "2 um"]})
    np.testing.assert_allclose(d.conditions["R_m"], [1e-6, 2e-6])


def test_a_condition_the_model_does_not_use_is_noted():
    """A user trial: a pull-off file's 'E (GPa)' column was read and never used, unnoted."""
    from asperity.fit import fit_pull_off

    R = np.array([1e-8, 2e-8, 5e-8])
    data = pull_off_data(1.5 * np.pi * 0.1 * R, physical=True, conditions={"R_m": R, "E_Pa": [1e9] * 3})
    r = fit_pull_off(data, "jkr", material="Si")
    assert r.values["w_J_m2"] == pytest.approx(0.1, rel=1e-9)
    assert [w for w in r.warnings if "ignored condition" in w] == [
        "pull_off: ignored condition(s) E_Pa: the jkr model has no such parameter"]


def test_a_per_row_parameter_given_again_is_named():
    """A user trial: --R beside a file's R column said "fix: unknown parameter 'R_m'"."""
    from asperity.fit import fit_pull_off

    data = pull_off_data([1e-7, 2e-7], physical=True, conditions={"R_m": [1e-6, 2e-6]})
    with pytest.raises(ValueError, match=r"fix: R_m is given row by row by the data \(its conditions: a column of "
                                         r"the file\), so it is neither fitted nor set here"):
        fit_pull_off(data, "jkr", material="Au", fix={"R_m": 2e-8})


def test_the_delimiter_is_the_one_that_cuts_header_and_data_alike(tmp_path):
    """A user trial: a TSV whose header holds a comma was cut at the comma."""
    d = read_data(write(tmp_path, "Load (nN)\tFriction (nN)\tNote, free text\n1\t2\ta, b\n3\t4\tc\n"))
    assert d.x.tolist() == [1e-9, 3e-9] and d.y.tolist() == [2e-9, 4e-9]
    d = read_data(write(tmp_path, "P;F;comment, if any\n1;2;x\n"))
    assert d.x.tolist() == [1.0]
    d = read_data(write(tmp_path, "load (nN),\tfriction (nN)\n1,\t2\n3,\t4\n"))  # aligned by tabs (a review)
    assert d.x.tolist() == [1e-9, 3e-9] and d.y.tolist() == [2e-9, 4e-9]


@pytest.mark.parametrize("name", ["COF", "µ", "μ", "coefficient of friction"])
def test_friction_coefficient_spellings(tmp_path, name):
    d = read_data(write(tmp_path, f"Load (nN),{name}\n1,0.2\n2,0.3\n"))
    assert d.quantity == "mu" and d.y.tolist() == [0.2, 0.3]


def test_a_column_of_another_kind_is_ignored_once_the_kind_is_given(tmp_path):
    """A user trial: a tribometer's sliding distance beside friction data was refused with --kind friction."""
    path = write(tmp_path, "Load (nN),Friction (nN),Distance (nm)\n1,2,5\n3,4,6\n")
    d = read_data(path, kind="friction")
    assert d.y.tolist() == [2e-9, 4e-9]
    assert any("ignored column(s) 'Distance (nm)' (not used by friction data)" in n for n in d.notes)
    with pytest.raises(ValueError, match="ambiguous data: columns of force and friction data; give the kind"):
        read_data(path)
