"""``asperity surface``: summit parameters of a measured surface against the library."""

import json

import numpy as np
import pytest

from .helpers import one_line_error, run, strict_json


@pytest.fixture
def scan(tmp_path):
    pytest.importorskip("SurfaceTopography")
    from SurfaceTopography import Topography

    x = np.arange(128) * 10e-9
    h = 2e-9 * (np.sin(2 * np.pi * x / 160e-9)[:, None] * np.sin(2 * np.pi * x / 160e-9)[None, :])
    path = tmp_path / "scan.x3p"
    Topography(h, (1.28e-6, 1.28e-6), unit="m").to_x3p(str(path))
    return path


def test_surface_command(capsys, tmp_path, scan):
    from asperity.materials import material
    from asperity.topography import analyse_surface

    path = scan
    code, out, _ = run(capsys, "surface", str(path), "--material", "Au", "--format", "json")
    assert code == 0
    got = json.loads(out)
    ref = analyse_surface(path, material=material("Au")).to_dict()
    for method in ("spectral", "detected"):
        for key in ("sigma_s", "R", "eta"):
            assert got[method][key] == pytest.approx(ref[method][key], rel=1e-15)
    assert got["groups"]["spectral"]["beta"] == pytest.approx(ref["groups"]["spectral"]["beta"], rel=1e-15)
    code, out, _ = run(capsys, "surface", str(path), "--b", "0.3nm", "--format", "table")
    assert code == 0 and "spectral" in out and "detected" in out
    bad = tmp_path / "bad.x3p"
    bad.write_bytes(b"\x00\x01garbage")
    for argv in (["surface", str(bad)], ["surface", str(tmp_path / "missing.txt")],
                 ["surface", str(path), "--material", "Au", "--b", "1nm"]):
        code, _, err = run(capsys, *argv)
        assert code == 2 and err.count("\n") == 1 and "Traceback" not in err


def test_surface_json_is_strict(capsys, tmp_path, scan, monkeypatch):
    # A non-finite number in the result (e.g. a parameter no summit defines) must be null.
    import asperity.topography

    class Result:
        def to_dict(self):
            return {"spectral": {"sigma_s": float("nan"), "radius": np.float64(np.inf)}, "n": [1.0, -np.inf]}

    monkeypatch.setattr(asperity.topography, "analyse_surface", lambda *a, **k: Result())
    code, out, _ = run(capsys, "surface", str(scan), "--format", "json")
    assert code == 0
    assert strict_json(out) == {"spectral": {"sigma_s": None, "radius": None}, "n": [1.0, None]}


@pytest.mark.parametrize("size", ["1um,,1um", "1um,", ",1um"])
def test_surface_size_list_must_be_well_formed(capsys, scan, size):
    code, _, err = run(capsys, "surface", str(scan), "--size", size)
    assert one_line_error(code, err, "--size")


def test_a_binary_file_is_one_line_of_error(tmp_path):
    """Found by a review: a format reader tried on a binary file logged 'could not reshape data
    from ...' (3 kB of binary text) to standard error through logging's last resort, a second
    line after the error."""
    import os
    import subprocess
    import sys
    from pathlib import Path

    import asperity

    path = tmp_path / "bin.dat"
    path.write_bytes(bytes(range(256)) * 4)
    # in a process of its own: pytest's log capture would stand in for logging's last resort
    done = subprocess.run([sys.executable, "-m", "asperity.cli", "surface", str(path), "--size", "4um,4um",
                           "--unit", "nm"], capture_output=True, text=True, timeout=120,
                          env={**os.environ, "PYTHONPATH": str(Path(asperity.__file__).parents[1])})
    assert one_line_error(done.returncode, done.stderr, "bin.dat: not a readable topography file"), done.stderr


def test_summits_and_output_are_written_together_or_not_at_all(capsys, tmp_path):
    """Found by a review: with -o in a directory that cannot be written, the summits file was
    written anyway (exit status 2)."""
    pytest.importorskip("SurfaceTopography")
    scan = tmp_path / "scan.npy"
    np.save(scan, np.random.default_rng(0).normal(size=(128, 128)))
    summits, size = tmp_path / "summits.txt", ["--size", "4um,4um", "--unit", "nm"]
    code, _, err = run(capsys, "surface", str(scan), *size, "--summits", str(summits), "-o", "/proc/x.json")
    assert code == 2 and not summits.exists(), err
    code, _, err = run(capsys, "surface", str(scan), *size, "--summits", str(summits), "-o", str(tmp_path / "s.json"))
    assert code == 0 and summits.read_text().startswith("z_m\n") and (tmp_path / "s.json").exists(), err
