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
