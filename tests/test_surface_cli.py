"""`asperity surface` against the Python API, for every unit spelling the help promises (issue #7).

The command line reads a scan whose file stores no metadata (plain text matrix, .npy) with
``--size`` (lengths with units) and ``--unit`` (the unit of the stored heights).  Its JSON must
equal ``analyse_surface(FILE, physical_sizes=..., unit=...)`` exactly, and both must equal the
summit parameters of the same surface stored in metres.  Only ``asperity.cli.main`` is used,
the entry point before and after the command line became a package.
"""

import json

import numpy as np
import pytest

from asperity._optional import require
from asperity.cli import main
from asperity.topography import analyse_surface

# Import SurfaceTopography once, through the library's lazy import (which silences its
# notice that mpi4py is missing), before the command line imports it.
ST = require("SurfaceTopography", purpose="the surface command tests")

DX = 10e-9  # pixel [m]
HEIGHT_UNITS = {"nm": 1e-9, "um": 1e-6, "µm": 1e-6, "μm": 1e-6, "m": 1.0}


def rough_heights(shape, seed=0):
    """A smooth random surface [m]: white noise low-passed in Fourier space, rms 2 nm."""
    noise = np.random.default_rng(seed).standard_normal(shape)
    k2 = sum(k**2 for k in np.meshgrid(*(np.fft.fftfreq(n) for n in shape), indexing="ij"))
    heights = np.fft.ifftn(np.fft.fftn(noise) * np.exp(-k2 / 0.06**2)).real
    return heights * 2e-9 / heights.std()


@pytest.fixture(scope="module")
def surface_map():
    """64 x 48 map (non-square: swapped axes would show) and its size [m]."""
    return rough_heights((64, 48), seed=1), (64 * DX, 48 * DX)


@pytest.fixture(scope="module")
def profile():
    return rough_heights((512,), seed=2), (512 * DX,)


def write(path, heights):
    """Store heights without metadata: .npy as is, text as a matrix with rows along y (a profile: one column)."""
    if path.suffix == ".npy":
        np.save(path, heights)
    else:
        np.savetxt(path, heights.T)
    return path


def cli_json(capsys, *argv):
    code = main(["surface", *map(str, argv), "--format", "json"])
    out, err = capsys.readouterr()
    assert code == 0 and err == "", err
    return json.loads(out)


def api_json(path, **kwargs):
    return json.loads(json.dumps(analyse_surface(path, **kwargs).to_dict(), allow_nan=False))


def gw(data):
    return [data[m][k] for m in ("spectral", "detected") for k in ("sigma_s", "R", "eta")]


def reference(heights, sizes):
    """The same surface analysed in metres, straight from memory (no file, no units)."""
    topo = ST.Topography(heights, sizes, unit="m") if heights.ndim == 2 else \
        ST.UniformLineScan(heights, sizes[0], unit="m")
    return api_json(topo)


@pytest.mark.parametrize("suffix", ["txt", "npy"])
@pytest.mark.parametrize("unit", list(HEIGHT_UNITS))
def test_map_heights_in_unit_sizes_in_um(capsys, tmp_path, surface_map, suffix, unit):
    heights, sizes = surface_map
    path = write(tmp_path / f"scan.{suffix}", heights / HEIGHT_UNITS[unit])
    size = "0.64um,0.48um"
    got = cli_json(capsys, path, "--size", size, "--unit", unit)
    assert got == api_json(path, physical_sizes=tuple(size.split(",")), unit=unit)
    np.testing.assert_allclose(gw(got), gw(api_json(path, physical_sizes=sizes, unit=unit)), rtol=1e-12, atol=0)
    expected = reference(heights, sizes)
    assert got["physical_sizes"] == pytest.approx(list(sizes), rel=1e-14)
    np.testing.assert_allclose(gw(got), gw(expected), rtol=1e-9, atol=0)
    assert got["detected"]["n_summits"] == expected["detected"]["n_summits"]


@pytest.mark.parametrize("suffix", ["txt", "npy"])
def test_one_size_for_a_square_map(capsys, tmp_path, suffix):
    heights = rough_heights((48, 48), seed=3)
    path = write(tmp_path / f"square.{suffix}", heights * 1e9)
    got = cli_json(capsys, path, "--size", "480nm", "--unit", "nm")
    assert got == api_json(path, physical_sizes="480nm", unit="nm")
    both = cli_json(capsys, path, "--size", "480nm,0.48um", "--unit", "nm")
    assert both["physical_sizes"] == pytest.approx(got["physical_sizes"], rel=1e-15)
    np.testing.assert_allclose(gw(both), gw(got), rtol=1e-13, atol=0)
    np.testing.assert_allclose(gw(got), gw(reference(heights, (48 * DX, 48 * DX))), rtol=1e-9, atol=0)


@pytest.mark.parametrize("suffix", ["txt", "npy"])
@pytest.mark.parametrize("unit", ["nm", "µm"])
def test_line_scan_with_one_size(capsys, tmp_path, profile, suffix, unit):
    heights, sizes = profile
    path = write(tmp_path / f"line.{suffix}", heights / HEIGHT_UNITS[unit])
    got = cli_json(capsys, path, "--size", "5.12um", "--unit", unit)
    assert got["dim"] == 1
    assert got == api_json(path, physical_sizes="5.12um", unit=unit)
    np.testing.assert_allclose(gw(got), gw(reference(heights, sizes)), rtol=1e-9, atol=0)


def test_material_groups_match(capsys, tmp_path, surface_map):
    heights, _ = surface_map
    path = write(tmp_path / "scan.npy", heights * 1e9)
    got = cli_json(capsys, path, "--size", "0.64um,0.48um", "--unit", "nm", "--material", "Au")
    from asperity.materials import material

    assert got == api_json(path, physical_sizes=("0.64um", "0.48um"), unit="nm", material=material("Au"))
    assert got["groups"]["spectral"]["beta"] > 0


def _write_tilted(path):
    x, y = np.meshgrid(np.arange(16.0), np.arange(12.0), indexing="ij")
    np.save(path, 0.3 * x + 0.1 * y + 4.0)
    return path


def _write_empty(path):
    np.save(path, np.zeros((0, 0)))
    return path


def _write_3d(path):
    np.save(path, np.zeros((8, 8, 8)))
    return path


@pytest.mark.parametrize(("make", "args", "needle"), [
    (lambda p: write(p / "s.npy", np.ones((12, 12))), ["--size", "1um,1um", "--unit", "furlong"],
     "not a length unit"),
    (lambda p: write(p / "s.npy", np.ones((12, 12))), ["--size", "1um,1um,1um", "--unit", "nm"],
     "physical_sizes must be 2 positive"),
    (lambda p: write(p / "s.npy", np.ones((12, 12))), ["--size", "1,1", "--unit", "nm"], "needs a unit"),
    (lambda p: write(p / "s.npy", np.ones((12, 12))), ["--size", "1um,1um"], "unit="),
    (lambda p: write(p / "s.npy", np.ones((12, 12))), ["--unit", "nm"], "physical_sizes="),
    (lambda p: _write_tilted(p / "tilted.npy"), ["--size", "1um,1um", "--unit", "nm"], "the surface is flat"),
    (lambda p: write(p / "flat.txt", np.full((12, 12), 5.0)), ["--size", "1um,1um", "--unit", "nm"],
     "the surface is flat"),
    (lambda p: _write_empty(p / "empty.npy"), ["--size", "1um", "--unit", "nm"], "the .npy array is empty"),
    (lambda p: _write_3d(p / "cube.npy"), ["--size", "1um", "--unit", "nm"], "3-d"),
    (lambda p: write(p / "tiny.npy", np.ones((4, 30))), ["--size", "1um", "--unit", "nm"], "too few points"),
    (lambda p: p, ["--size", "1um", "--unit", "nm"], "is a directory"),
    (lambda p: write(p / "huge.npy", np.random.default_rng(1).normal(size=(16, 16)) * 1e300),
     ["--size", "1um,1um", "--unit", "nm"], "cannot be a surface's (at most 1e+50 m: the spectral moments would"),
])
def test_errors_are_one_line(capsys, tmp_path, make, args, needle):
    path = make(tmp_path)
    code = main(["surface", str(path), *args, "--format", "json"])
    out, err = capsys.readouterr()
    assert code == 2 and out == ""
    assert err.startswith("asperity: error: ") and err.count("\n") == 1 and needle in err, err
