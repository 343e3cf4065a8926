"""asperity.topography.read: files to SurfaceTopography objects in metres."""

import re
import sys
import warnings

import numpy as np
import pint
import pytest

import asperity
from asperity.topography import analyse_surface, read_topography

from .synthetic import DX, ST, synthetic_map

UREG = pint.UnitRegistry()


@pytest.fixture()
def small_map():
    heights = np.random.default_rng(4).standard_normal((12, 10))  # nm
    return heights, ST.Topography(heights, (1.2, 1.0), unit="µm")


def _check_map(topo, heights, height_scale=1e-9, sizes=(1.2e-6, 1.0e-6)):
    assert topo.unit == "m"
    assert topo.nb_grid_pts == heights.shape
    assert tuple(topo.physical_sizes) == pytest.approx(sizes, rel=1e-12)
    np.testing.assert_allclose(topo.heights(), heights * height_scale, rtol=1e-12)


def test_read_handwritten_text_matrix(tmp_path):
    # rows along y, columns along x (not 0, 1, 2, ... along a line: that is noted as a header of indices)
    heights = (0.5 * np.arange(72.0) - 3.0).reshape(8, 9)
    path = tmp_path / "afm.txt"
    path.write_text("# Channel: Height\n# Width: 9 µm\n# Height: 8 µm\n# Value units: nm\n"
                    + "\n".join(" ".join(f"{v:g}" for v in row) for row in heights) + "\n", encoding="utf-8")
    _check_map(read_topography(path), heights.T, sizes=(9e-6, 8e-6))


@pytest.mark.parametrize(("writer", "suffix"), [("to_matrix", "txt"), ("to_x3p", "x3p"), ("to_netcdf", "nc")])
def test_read_written_formats(tmp_path, small_map, writer, suffix):
    heights, topo = small_map
    path = tmp_path / f"map.{suffix}"
    getattr(topo.scale(1e-3), writer)(str(path))  # heights in µm, as the unit says
    _check_map(read_topography(path), heights)


def test_read_npy_needs_sizes_and_unit(tmp_path, small_map):
    heights, _ = small_map
    path = tmp_path / "map.npy"
    np.save(path, heights)
    with pytest.raises(ValueError, match=re.escape(str(path)) + ".*physical_sizes="):
        read_topography(path)
    with pytest.raises(ValueError, match="unit="):
        read_topography(path, physical_sizes=(1.2, 1.0))
    # physical_sizes are metres (or lengths with units); unit is the unit of the stored heights
    _check_map(read_topography(path, physical_sizes=(1.2e-6, 1.0e-6), unit="nm"), heights)
    _check_map(read_topography(path, physical_sizes=("1.2um", "1000 nm"), unit="nm"), heights)
    _check_map(read_topography(path, physical_sizes=np.array([1.2, 1.0]) * UREG.um, unit="nm"), heights)


@pytest.mark.parametrize(("kwargs", "message"), [
    ({"physical_sizes": (1, 1), "unit": "V"}, "not a length unit"),
    ({"physical_sizes": (1, 1), "unit": "furlong"}, "not a length unit"),
    ({"physical_sizes": (1, 1, 1), "unit": "nm"}, "2 positive number"),
    ({"physical_sizes": (1, -1), "unit": "nm"}, "2 positive number"),
    ({"physical_sizes": (1, "a"), "unit": "nm"}, "2 positive number"),
    ({"physical_sizes": (1, 1), "unit": "nm", "channel_index": 3}, "no channel 3"),
])
def test_bad_read_arguments(tmp_path, small_map, kwargs, message):
    path = tmp_path / "map.npy"
    np.save(path, small_map[0])
    with pytest.raises(ValueError, match=re.escape(str(path)) + ".*" + message):
        read_topography(path, **kwargs)


def test_file_metadata_cannot_be_overridden(tmp_path, small_map):
    _, topo = small_map
    path = tmp_path / "map.txt"
    topo.to_matrix(str(path))
    with pytest.raises(ValueError, match="already stores the unit"):
        read_topography(path, unit="nm")
    with pytest.raises(ValueError, match="already stores the scan size"):
        read_topography(path, physical_sizes=(1, 1))


def test_read_line_scan(tmp_path):
    heights = np.sin(np.linspace(0, 20, 200))  # nm
    path = tmp_path / "profile.txt"
    ST.UniformLineScan(heights, 50.0, unit="µm").scale(1e-3).to_matrix(str(path))
    line = read_topography(path)
    assert line.dim == 1 and line.unit == "m"
    assert tuple(line.physical_sizes) == pytest.approx((50e-6,))
    np.testing.assert_allclose(line.heights(), heights * 1e-9, rtol=1e-12)
    result = analyse_surface(path)
    assert result.dim == 1 and result.source == str(path)
    assert any("line scan" in w for w in result.warnings)


def test_undefined_data(tmp_path, small_map):
    heights, _ = small_map
    holes = heights.copy()
    holes[4, 5] = np.nan
    path = tmp_path / "holes.txt"
    np.savetxt(path, holes.T, header="Width: 1.2 um\nHeight: 1.0 um\nValue units: nm")
    with pytest.raises(ValueError, match=re.escape(str(path)) + ".*1 of 120 heights are undefined"):
        read_topography(path)
    with pytest.warns(asperity.AsperityWarning, match=re.escape(str(path)) + r": 1 of 120 heights \(0.833 %\) were "
                      "undefined and are filled by harmonic interpolation"):
        filled = read_topography(path, fill_undefined=True)
    assert not filled.has_undefined_data
    with pytest.raises(TypeError, match="fill_undefined must be True or False"):
        read_topography(path, fill_undefined="no")
    every = tmp_path / "none.txt"
    np.savetxt(every, np.full_like(holes.T, np.nan), header="Width: 1.2 um\nHeight: 1.0 um\nValue units: nm")
    with pytest.raises(ValueError, match="every height is undefined"):
        read_topography(every, fill_undefined=True)
    # harmonic fill of one hole on a square grid: the mean of its 4 neighbours
    neighbours = heights[3, 5] + heights[5, 5] + heights[4, 4] + heights[4, 6]
    assert filled.heights()[4, 5] == pytest.approx(neighbours / 4 * 1e-9, rel=1e-6)


@pytest.mark.parametrize("content", [None, b"", np.random.default_rng(5).bytes(3001),
                                     b"this is not\na topography\n"])
def test_bad_files_raise_value_error_naming_file(tmp_path, content):
    path = tmp_path / "bad.dat"
    if content is not None:
        path.write_bytes(content)
    with pytest.raises(ValueError, match=re.escape(str(path))) as info:
        read_topography(path)
    assert info.value.__cause__ is None and (info.value.__context__ is None or info.value.__suppress_context__)
    with pytest.raises(ValueError, match=re.escape(str(path))):
        analyse_surface(path)


def test_reader_warnings_are_reissued_with_file_name(tmp_path, small_map, monkeypatch):
    _, topo = small_map
    path = tmp_path / "map.txt"
    topo.to_matrix(str(path))
    original = ST.open_topography

    def noisy(fobj, *args, **kwargs):
        warnings.warn("odd header", UserWarning, stacklevel=2)
        return original(fobj, *args, **kwargs)

    monkeypatch.setattr(ST, "open_topography", noisy)
    with pytest.warns(UserWarning, match=re.escape(f"{path}: odd header")):
        read_topography(path)


def test_missing_surface_topography(monkeypatch, tmp_path):
    path = tmp_path / "map.npy"
    np.save(path, np.zeros((8, 8)))
    monkeypatch.setitem(sys.modules, "SurfaceTopography", None)
    with pytest.raises(ImportError, match="reading measured surfaces needs SurfaceTopography: "
                                          + re.escape("pip install 'asperity[topography]'")):
        read_topography(path)


# -- units: sizes in metres, `unit` = unit of the stored heights (issue #7) -------------------

HEIGHT_UNITS = {"m": 1.0, "mm": 1e-3, "um": 1e-6, "µm": 1e-6, "μm": 1e-6, "nm": 1e-9, "Å": 1e-10, "pm": 1e-12}


@pytest.fixture(scope="module")
def scan():
    """A 64 x 48 rough map [m] (non-square, so swapped axes would show) and its sizes [m]."""
    heights = synthetic_map(64, roll_px=32, min_px=4, seed=3)[0][:, :48]
    return heights, (64 * DX, 48 * DX)


def _write(path, heights):
    """Heights as stored by a plain text matrix (rows along y) or a .npy file, no metadata."""
    if path.suffix == ".npy":
        np.save(path, heights)
    else:
        np.savetxt(path, heights.T)
    return path


def _gw(result):
    return [(p.sigma_s, p.R, p.eta) for p in (result.spectral, result.detected)]


@pytest.mark.parametrize("suffix", ["txt", "npy"])
@pytest.mark.parametrize("unit", list(HEIGHT_UNITS))
def test_heights_in_any_unit_equal_the_surface_in_metres(tmp_path, scan, suffix, unit):
    """The same scan stored in `unit`, sizes in um: sigma_s, R, eta as for the scan in metres."""
    heights, sizes = scan
    reference = analyse_surface(ST.Topography(heights, sizes, unit="m"))
    in_metres = analyse_surface(_write(tmp_path / f"m.{suffix}", heights), physical_sizes=sizes, unit="m")
    scaled = _write(tmp_path / f"scaled.{suffix}", heights / HEIGHT_UNITS[unit])
    um = ("0.64um", "0.48 um")
    for result in (in_metres, analyse_surface(scaled, physical_sizes=um, unit=unit),
                   analyse_surface(scaled, physical_sizes=(0.64 * UREG.um, 480 * UREG.nm), unit=f" {unit} ")):
        assert result.physical_sizes == pytest.approx(sizes, rel=1e-14)
        assert result.pixel_size == pytest.approx((DX, DX), rel=1e-14)
        np.testing.assert_allclose(_gw(result), _gw(reference), rtol=1e-9)
    topo = read_topography(scaled, physical_sizes=um, unit=unit)
    assert topo.unit == "m" and topo.nb_grid_pts == (64, 48)
    np.testing.assert_allclose(topo.heights(), heights, rtol=1e-12)


def test_sizes_are_converted_to_a_unit_the_file_stores(tmp_path, scan):
    """A text file with 'Value units: nm' but no sizes: physical_sizes (metres) go into nm."""
    heights, sizes = scan
    path = tmp_path / "nm.txt"
    np.savetxt(path, heights.T * 1e9, header="Value units: nm")
    topo = read_topography(path, physical_sizes=sizes)
    assert tuple(topo.physical_sizes) == pytest.approx(sizes, rel=1e-14)
    np.testing.assert_allclose(topo.heights(), heights, rtol=1e-12)
    with pytest.raises(ValueError, match="already stores the unit 'nm'"):
        read_topography(path, physical_sizes=sizes, unit="nm")


def test_one_size_means_a_square_map(tmp_path):
    path = _write(tmp_path / "square.npy", np.random.default_rng(8).standard_normal((16, 16)))
    for sizes in ("2um", ("2um",), 2e-6, [2e-6]):
        assert tuple(read_topography(path, physical_sizes=sizes, unit="nm").physical_sizes) == \
            pytest.approx((2e-6, 2e-6), rel=1e-14)


def test_line_scan_sizes(tmp_path):
    path = _write(tmp_path / "line.npy", np.sin(np.linspace(0, 30, 300)))
    for sizes in ("30um", ("30um",), 3e-5):
        line = read_topography(path, physical_sizes=sizes, unit="nm")
        assert line.dim == 1 and tuple(line.physical_sizes) == pytest.approx((3e-5,), rel=1e-14)
    with pytest.raises(ValueError, match=r"physical_sizes must be 1 positive number\(s\) of metres for this line"):
        read_topography(path, physical_sizes=("30um", "30um"), unit="nm")


@pytest.mark.parametrize(("kwargs", "error", "message"), [
    ({"physical_sizes": ("1um", "1 GPa"), "unit": "nm"}, ValueError, "physical_sizes must have units compatible"),
    ({"physical_sizes": ("1um", "1"), "unit": "nm"}, ValueError, "needs a unit"),
    ({"physical_sizes": (True, 1e-6), "unit": "nm"}, ValueError, "boolean"),
    ({"physical_sizes": (1e-6, float("nan")), "unit": "nm"}, ValueError, "finite"),
    ({"physical_sizes": None, "unit": "nm"}, ValueError, "does not store the scan size"),
    ({"physical_sizes": (1e-6, 1e-6), "unit": 1e-9}, TypeError, "unit must be a string"),
    ({"physical_sizes": (1e-6, 1e-6), "unit": "cm"}, ValueError, "'cm' is not a length unit; use one of m, mm"),
    ({"physical_sizes": (1e-6, 1e-6), "unit": "nm", "channel_index": True}, ValueError, "channel_index"),
])
def test_bad_sizes_and_units(tmp_path, kwargs, error, message):
    path = _write(tmp_path / "map.npy", np.random.default_rng(9).standard_normal((10, 10)))
    with pytest.raises(error, match=message):
        read_topography(path, **kwargs)


# -- refused files ---------------------------------------------------------------------------

@pytest.mark.parametrize(("array", "message"), [
    (np.zeros((0,)), r"the .npy array is empty \(shape \(0,\)\)"),
    (np.zeros((0, 0)), "the .npy array is empty"),
    (np.zeros((16, 0)), "the .npy array is empty"),
    (np.array(3.0), r"the .npy array is 0-d \(shape \(\)\)"),
    (np.zeros((4, 4, 4)), r"the .npy array is 3-d \(shape \(4, 4, 4\)\)"),
    (np.ones((10, 10)) * 1j, "the .npy array holds complex128, not real numbers"),
    (np.array([[1, "a"]] * 9, dtype=object), "the .npy array holds object, not real numbers"),
    (np.ones((10, 10), dtype=bool), "the .npy array holds bool, not real numbers"),
    (np.ones((2, 10)), r"too few points for summit statistics: grid \(2, 10\); need at least 8"),
    (np.ones(7), r"too few points .* grid \(7,\)"),
])
def test_degenerate_npy_files(tmp_path, array, message):
    path = tmp_path / "bad.npy"
    np.save(path, array, allow_pickle=True)
    with pytest.raises(ValueError, match=re.escape(str(path)) + ": " + message):
        read_topography(path, physical_sizes=1e-6, unit="nm")
    with pytest.raises(ValueError, match=re.escape(str(path)) + ": " + message):
        analyse_surface(path, physical_sizes=1e-6, unit="nm")


def test_corrupt_npy_header(tmp_path):
    path = tmp_path / "bad.npy"
    path.write_bytes(b"\x93NUMPY\x01\x00garbage that is not a header")
    with pytest.raises(ValueError, match=re.escape(str(path)) + ": not a valid .npy file"):
        read_topography(path, physical_sizes=1e-6, unit="nm")


@pytest.mark.parametrize("version", [(1, 0), (2, 0)])
def test_truncated_npy_is_refused_not_read_from_memory(tmp_path, version):
    """A review: a .npy file a few bytes short was read with garbage heights (1e-320, 1e307, ...)
    and then called flat or undefined, advising --fill-undefined."""
    path = tmp_path / "short.npy"
    with open(path, "wb") as fobj:
        np.lib.format.write_array(fobj, np.random.default_rng(0).normal(size=(16, 16)), version=version)
    path.write_bytes(path.read_bytes()[:-8])
    with pytest.raises(ValueError, match=re.escape(str(path)) + r": not a valid .npy file: it is truncated "
                                         r"\(2040 of the 2048 bytes"):
        read_topography(path, physical_sizes=1e-6, unit="nm")


def test_file_matched_only_by_its_size_is_refused(tmp_path):
    """SRTM .hgt tiles have no header: any file of 2 n^2 bytes matches; only *.hgt is taken as one."""
    path = tmp_path / "scan.bin"
    path.write_bytes(np.random.default_rng(6).bytes(2 * 16 * 16))
    with pytest.raises(ValueError, match=re.escape(str(path)) + ": not a readable topography file .*hgt"):
        read_topography(path)


def test_directory_and_non_path(tmp_path):
    with pytest.raises(ValueError, match=re.escape(str(tmp_path)) + ": is a directory"):
        read_topography(tmp_path)
    with pytest.raises(ValueError, match="is a directory"):
        analyse_surface(str(tmp_path))
    for bad in (3, None, b"scan.npy", ["scan.npy"], np.zeros((8, 8))):
        with pytest.raises(TypeError, match="path must be a str or os.PathLike"):
            read_topography(bad)


def test_npy_first_axis_is_x_text_rows_are_y_and_long_pixels_are_noted(tmp_path):
    """The convention docs/physical.md states (SurfaceTopography's): the same array saved with
    np.save and np.savetxt is read transposed; a .npy map with pixels more than twice as long
    one way gets a note naming the convention (found by a review), a square-pixel one none."""
    h = np.random.default_rng(3).standard_normal((24, 40))
    np.save(tmp_path / "a.npy", h)
    np.savetxt(tmp_path / "a.txt", h)
    with pytest.warns(asperity.AsperityWarning, match=r"a.npy: the pixels are 208.3 x 75 nm \(x by y\): a .npy "
                                                       r"array's first axis is x \(24 points\)"):
        npy = read_topography(tmp_path / "a.npy", physical_sizes=("5um", "3um"), unit="nm")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        txt = read_topography(tmp_path / "a.txt", physical_sizes=("5um", "3um"), unit="nm")
        square = read_topography(tmp_path / "a.npy", physical_sizes=("2.4um", "4um"), unit="nm")
    assert npy.nb_grid_pts == (24, 40) and txt.nb_grid_pts == (40, 24) and square.nb_grid_pts == (24, 40)
    np.testing.assert_array_equal(npy.heights(), square.heights())
    np.testing.assert_allclose(np.asarray(txt.heights()).T, npy.heights(), rtol=1e-15)


def test_the_readers_notes_are_in_the_analysis_and_the_surface_json(tmp_path, capsys):
    """Found by a review: a .npy map's pixel-shape note went to standard error only, so
    ``asperity surface --format json`` did not hold it.  Now it is one of the analysis's
    warnings (issued once, not also as a Python warning); a square-pixel map has none."""
    import json

    from asperity.cli import main

    h = np.random.default_rng(3).standard_normal((48, 80))
    np.save(tmp_path / "a.npy", h)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        result = analyse_surface(tmp_path / "a.npy", physical_sizes=("5um", "3um"), unit="nm")
        square = analyse_surface(tmp_path / "a.npy", physical_sizes=("4.8um", "8um"), unit="nm")
    pixel_notes = [w for w in result.warnings if "the pixels are" in w]
    assert len(pixel_notes) == 1 and pixel_notes[0].startswith(f"{tmp_path / 'a.npy'}: the pixels are 104.2 x 37.5")
    assert not any("the pixels are" in w for w in square.warnings)
    code = main(["surface", str(tmp_path / "a.npy"), "--size", "5um,3um", "--unit", "nm", "--format", "json"])
    assert code in (0, None)
    out, err = capsys.readouterr()
    assert json.loads(out)["warnings"] == result.to_dict()["warnings"] and "the pixels are" not in err


@pytest.mark.parametrize("layout, where", [("header", "first line"), ("index", "first column"), ("both", "first line"),
                                           ("plain", None)])
def test_a_line_of_indices_read_as_heights_is_noted(tmp_path, layout, where):
    """Found by a user trial: a text matrix with a header line '0 1 ... 31' (or a first column
    of row numbers) is read as heights, and only the summit methods' disagreement hinted at it.
    Now a note names the line (a note, not a repair: the file is read as it is)."""
    h = np.random.default_rng(4).standard_normal((32, 40))
    if layout == "header":
        h = np.vstack([np.arange(40.0), h])
    elif layout == "index":
        h = np.hstack([np.arange(1.0, 33.0)[:, None], h])
    elif layout == "both":  # a spreadsheet's: a corner cell 0, a header 0 ... 39, an index column 0 ... 31
        h = np.vstack([np.r_[0.0, np.arange(39.0)], np.hstack([np.arange(32.0)[:, None], h[:, 1:]])])
        assert h[0, :3].tolist() == [0.0, 0.0, 1.0] and h[:3, 0].tolist() == [0.0, 0.0, 1.0]
    np.savetxt(tmp_path / "m.txt", h)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        topo = read_topography(tmp_path / "m.txt", physical_sizes=("4um", "4um"), unit="nm")
    notes = [str(w.message) for w in caught if "a header of indices" in str(w.message)]
    assert topo.nb_grid_pts == h.shape[::-1]  # read as it is
    if where is None:
        assert notes == []
    else:
        start, end = {"header": ("0, 1, 2", 39), "index": ("1, 2, 3", 32), "both": ("0, 1, 2", 38)}[layout]
        assert notes == [f"{tmp_path / 'm.txt'}: its {where} counts {start}, ... {end}: a header of indices read as "
                         "heights?  Remove it from the file"]


@pytest.mark.parametrize("encoding", ["utf-8-sig", "utf-16", "utf-16-le-bom", "utf-16-be-bom"])
def test_a_text_matrix_with_a_byte_order_mark_keeps_its_first_line(tmp_path, encoding):
    """A user trial: a text matrix saved with a UTF-8 byte-order mark lost its first scan line
    (SurfaceTopography took it for a header; 256 x 255 read, no note), and UTF-16, a Windows
    export, was refused.  Now both read as the plain file does."""
    h = np.random.default_rng(5).standard_normal((16, 20))
    np.savetxt(tmp_path / "plain.txt", h)
    text = (tmp_path / "plain.txt").read_text()
    raw = {"utf-8-sig": text.encode("utf-8-sig"), "utf-16": text.replace("\n", "\r\n").encode("utf-16"),
           "utf-16-le-bom": b"\xff\xfe" + text.encode("utf-16-le"),
           "utf-16-be-bom": b"\xfe\xff" + text.encode("utf-16-be")}[encoding]
    (tmp_path / "m.txt").write_bytes(raw)
    kw = {"physical_sizes": ("4um", "3um"), "unit": "nm"}
    plain, marked = (read_topography(tmp_path / f, **kw) for f in ("plain.txt", "m.txt"))
    assert marked.nb_grid_pts == plain.nb_grid_pts == (20, 16)
    np.testing.assert_array_equal(marked.heights(), plain.heights())


def test_a_utf16_mark_on_what_is_not_utf16_is_one_error(tmp_path):
    (tmp_path / "m.txt").write_bytes(b"\xff\xfe" + b"\x00\xd8" * 3)  # a lone surrogate
    with pytest.raises(ValueError, match=r"m\.txt: not a readable topography file \(it starts with a utf-16"):
        read_topography(tmp_path / "m.txt", physical_sizes=("4um", "3um"), unit="nm")


@pytest.mark.parametrize("layout, where", [("row", "first line"), ("both", "first line"), ("column", "first column"),
                                           ("last", "last column"), ("plane", None), ("plain", None)])
def test_a_line_of_coordinates_read_as_heights_is_noted(tmp_path, layout, where):
    """A user trial: a text matrix with coordinates in um on top (and left), printed to six
    decimals, read as heights gave eta 5 times too large, flagged only by the methods'
    disagreement.  Now a line in even steps where its neighbour is not is noted; a tilted
    plane (every line in even steps) is not."""
    rng = np.random.default_rng(6)
    h = rng.standard_normal((32, 40))
    x, y = np.round(np.arange(40) * 4 / 40, 6), np.round(np.arange(32) * 3 / 32, 6)
    if layout == "row":
        h = np.vstack([x, h])
    elif layout == "both":
        h = np.vstack([np.r_[0.0, x[:-1]], np.hstack([y[:, None], h[:, 1:]])])
    elif layout == "column":
        h = np.hstack([y[:, None] + 1.0, h])
    elif layout == "last":
        h = np.hstack([h, -2.0 * y[:, None]])
    elif layout == "plane":
        h = 0.3 * np.arange(40)[None, :] + 0.2 * np.arange(32)[:, None] + 1e-3 * h
    np.savetxt(tmp_path / "m.txt", h, fmt="%.6f")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        read_topography(tmp_path / "m.txt", physical_sizes=("4um", "4um"), unit="nm")
    notes = [str(w.message) for w in caught if "a header of" in str(w.message)]
    if where is None:
        assert notes == []
    else:
        assert len(notes) == 1 and re.fullmatch(rf".*m\.txt: its {where} runs from \S+ to \S+ in even steps: a "
                                                 r"header of coordinates read as heights\?  Remove it from the file",
                                                 notes[0]), notes


def test_a_line_scan_written_as_one_line_says_how_to_write_it(tmp_path):
    np.savetxt(tmp_path / "row.txt", np.random.default_rng(1).standard_normal((1, 64)))
    with pytest.raises(ValueError, match=r"grid \(64, 1\); need at least 8 along every axis; a line scan is one "
                                         r"column of heights, not one line$"):
        read_topography(tmp_path / "row.txt", physical_sizes="5um", unit="nm")


@pytest.mark.parametrize("delimiter", [",", ";", ", "])
def test_a_comma_or_semicolon_separated_matrix_reads_as_the_blank_separated_one(tmp_path, delimiter):
    """A user trial: np.savetxt(..., delimiter=',') (a spreadsheet's export) was refused."""
    h = np.random.default_rng(7).standard_normal((12, 14))
    np.savetxt(tmp_path / "plain.txt", h)
    np.savetxt(tmp_path / "m.csv", h, delimiter=delimiter, header="exported", comments="# ")
    kw = {"physical_sizes": ("4um", "3um"), "unit": "nm"}
    plain, delimited = (read_topography(tmp_path / f, **kw) for f in ("plain.txt", "m.csv"))
    assert delimited.nb_grid_pts == plain.nb_grid_pts == (14, 12)
    np.testing.assert_array_equal(delimited.heights(), plain.heights())


def test_decimal_commas_between_blanks_are_not_taken_for_delimiters(tmp_path):
    """'1,5<TAB>2,3' must not become four numbers: such a file stays refused."""
    h = np.random.default_rng(8).standard_normal((10, 9))
    (tmp_path / "m.txt").write_text("\n".join("\t".join(f"{v:.4f}".replace(".", ",") for v in r) for r in h))
    with pytest.raises(ValueError, match=r"m\.txt: not a readable topography file \(no SurfaceTopography .*decimal "
                                         r"commas \(.1,5.\) are not read: write decimal points\)$"):
        read_topography(tmp_path / "m.txt", physical_sizes=("4um", "3um"), unit="nm")


def test_a_comma_separated_profile_is_the_blank_separated_one(tmp_path):
    x = np.arange(64) * 20.0
    z = np.sin(x / 50.0)
    np.savetxt(tmp_path / "p.txt", np.c_[x, z])
    np.savetxt(tmp_path / "p.csv", np.c_[x, z], delimiter=",")
    plain, delimited = (read_topography(tmp_path / f, unit="nm") for f in ("p.txt", "p.csv"))
    assert delimited.dim == plain.dim == 1
    np.testing.assert_array_equal(delimited.heights(), plain.heights())


def test_a_ragged_text_matrix_names_its_odd_line(tmp_path):
    """A user trial: one short line was reported as an unknown format, blaming commas."""
    h = np.random.default_rng(9).standard_normal((12, 10))
    lines = [" ".join(f"{v:.5f}" for v in row) for row in h]
    lines[6] = " ".join(lines[6].split()[:-1])
    (tmp_path / "m.txt").write_text("\n".join(lines) + "\n")
    with pytest.raises(ValueError, match=r"; line 7 holds 9 values, the others 10\)$"):
        read_topography(tmp_path / "m.txt", physical_sizes=("4um", "3um"), unit="nm")


def test_a_trailing_delimiter_and_a_long_marked_file(tmp_path, monkeypatch):
    """A review: a comma ending every line (a spreadsheet's) left the matrix refused without a
    hint, and a file with a byte-order mark longer than the text limit was cut short unnoted."""
    from asperity.topography import _textfile

    h = np.random.default_rng(10).standard_normal((12, 10))
    np.savetxt(tmp_path / "plain.txt", h)
    (tmp_path / "t.csv").write_text("\n".join(",".join(f"{v:.18e}" for v in r) + "," for r in h) + "\n")
    kw = {"physical_sizes": ("4um", "3um"), "unit": "nm"}
    plain = read_topography(tmp_path / "plain.txt", **kw)
    np.testing.assert_array_equal(read_topography(tmp_path / "t.csv", **kw).heights(), plain.heights())
    size = len((tmp_path / "plain.txt").read_bytes())
    monkeypatch.setattr(_textfile, "MAX_TEXT", size // 2)
    (tmp_path / "b.txt").write_bytes(b"\xef\xbb\xbf" + (tmp_path / "plain.txt").read_bytes())
    np.testing.assert_array_equal(read_topography(tmp_path / "b.txt", **kw).heights(), plain.heights())
    monkeypatch.setattr(_textfile, "MAX_TEXT", size // 8)  # beyond four times the limit: refused, not cut
    with pytest.raises(ValueError, match=r"b\.txt: a text map of more than \d+ MB; save it in a binary format"):
        read_topography(tmp_path / "b.txt", **kw)
