"""The command line: outputs against the library, formats, and error paths."""

import csv
import io
import json
import subprocess
import sys

import numpy as np
import pytest

import asperity
from asperity.cli import main, parse_list

MODEL = ["--alpha", "0.01", "--beta", "1000", "--gamma", "1e-3"]


def run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def rows_of(text):
    return list(csv.DictReader(io.StringIO(text)))


def test_parse_list():
    np.testing.assert_allclose(parse_list("0,0.5,1", log=False, name="x"), [0, 0.5, 1])
    np.testing.assert_allclose(parse_list("1:100:3", log=True, name="x"), [1, 10, 100])
    np.testing.assert_allclose(parse_list("0:1:3", log=False, name="x"), [0, 0.5, 1])


def test_load_csv_matches_library(capsys):
    code, out, _ = run(capsys, "load", *MODEL, "--P", "1:1e4:5", "--format", "csv")
    assert code == 0
    rows = rows_of(out)
    assert list(rows[0]) == ["d", "P", "F", "mu", "area", "pressure", "contacts"]
    ref = asperity.load_curve(np.geomspace(1, 1e4, 5), 0.01, 1000, 1e-3)
    for key in ("d", "P", "F", "mu", "area", "pressure", "contacts"):
        np.testing.assert_allclose([float(r[key]) for r in rows], getattr(ref, key), rtol=1e-15)


def test_separation_json_matches_library(capsys):
    code, out, _ = run(capsys, "separation", *MODEL, "--d", "-1,0,2.5", "--format", "json")
    assert code == 0
    rows = json.loads(out)
    ref = asperity.separation_curve([-1, 0, 2.5], 0.01, 1000, 1e-3)
    assert [r["d"] for r in rows] == [-1, 0, 2.5]
    np.testing.assert_allclose([r["F"] for r in rows], ref.F, rtol=1e-15)
    assert set(rows[0]) == {"d", "P", "F", "mu", "area", "pressure", "contacts"}


def test_pulloff_and_table(capsys):
    code, out, _ = run(capsys, "pulloff", "--alpha", "0.003", "--beta", "1000", "--gamma", "1e-3",
                       "--format", "json")
    assert code == 0
    got = json.loads(out)
    ref = asperity.pull_off(0.003, 1000, 1e-3)
    assert got["pull_off"] == pytest.approx(ref.force, rel=1e-15) and set(got) == {"pull_off", "d"}
    code, out, _ = run(capsys, "pulloff", "--alpha", "0.003", "--beta", "1000", "--gamma", "1e-3",
                       "--format", "table")
    assert "pull_off" in out.splitlines()[0]


def test_md_commands(capsys):
    code, out, _ = run(capsys, "md", "--lam", "1", "--delta", "-0.5,0,1", "--format", "csv")
    assert code == 0
    rows = rows_of(out)
    A, P, t = asperity.md_solve(np.array([-0.5, 0, 1]), 1.0)
    np.testing.assert_allclose([float(r["A"]) for r in rows], A, rtol=1e-15)
    np.testing.assert_allclose([float(r["m"]) for r in rows], np.sqrt(1 + t**2), rtol=1e-15)
    code, out, _ = run(capsys, "md", "--lam", "1e4", "--pulloff", "--format", "csv")
    rows = {r["control"]: float(r["P"]) for r in rows_of(out)}
    assert rows["load"] == pytest.approx(-1.5, rel=1e-3)
    assert rows["displacement"] == pytest.approx(-5 / 6, rel=1e-3)


def test_output_file_and_plot(capsys, tmp_path):
    out_csv, png = tmp_path / "c.csv", tmp_path / "c.png"
    code, out, _ = run(capsys, "load", *MODEL, "--P", "1:1e3:20", "-o", str(out_csv),
                       "--plot", str(png))
    assert code == 0 and out == ""
    assert len(rows_of(out_csv.read_text())) == 20
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    code, _, _ = run(capsys, "separation", *MODEL, "--d", "0:4:9", "--plot", str(png))
    assert code == 0


@pytest.mark.parametrize("argv, needle", [
    (["load", "--alpha", "-1", "--beta", "10", "--P", "1"], "alpha"),
    (["load", "--alpha", "0.01", "--beta", "10", "--P", "0,1"], "P"),
    (["load", "--alpha", "0.01", "--beta", "10", "--P", "a,b"], "--P"),
    (["load", "--alpha", "0.01", "--beta", "10", "--P", "0:1:5"], "--P"),
    (["separation", "--alpha", "0.01", "--beta", "10", "--d", "0,nan"], "--d"),
    (["separation", "--alpha", "0.01", "--beta", "10", "--nu", "0.7", "--d", "0"], "nu"),
    (["separation", "--alpha", "0.01", "--beta", "10", "--d", "0", "--bogus"], "bogus"),
    (["pulloff", "--alpha", "0.01", "--beta", "10"], "gamma"),
    (["md", "--lam", "-1", "--pulloff"], "lam"),
    (["md", "--lam", "1", "--delta", "-5"], "delta"),
    (["separation", "--alpha", "x", "--beta", "10", "--d", "0"], "alpha"),
    (["separation", "--alpha", "0.01", "--beta", "10", "--d", "0", "-o", "/nonexistent/dir/f"],
     "cannot write"),
    (["nosuchcommand"], "nosuchcommand"),
])
def test_errors_one_line_status_2(capsys, argv, needle):
    code, out, err = run(capsys, *argv)
    assert code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("asperity: error:") and needle in lines[0]
    assert "Traceback" not in err


def test_help_explains_every_parameter(capsys):
    for cmd in ("separation", "load", "pulloff", "md", "reproduce"):
        with pytest.raises(SystemExit) as exc:
            main([cmd, "--help"])
        assert exc.value.code == 0
        out = " ".join(capsys.readouterr().out.split())
        for word in {"separation": ["--alpha", "--beta", "--gamma", "--nu", "--h-over-b",
                                    "linearly", "N G b^2"],
                     "load": ["logarithmically", "--plot", "contacts"],
                     "pulloff": ["--d-max"], "md": ["--lam", "--delta", "--pulloff"],
                     "reproduce": ["--out"]}[cmd]:
            assert word in out, (cmd, word)


def test_subprocess_entry_point(tmp_path):
    version = subprocess.run([sys.executable, "-m", "asperity.cli", "--version"],
                             capture_output=True, text=True, check=True)
    assert version.stdout.strip() == f"asperity {asperity.__version__}"
    res = subprocess.run([sys.executable, "-m", "asperity.cli", "load", *MODEL, "--P", "10"],
                         capture_output=True, text=True, check=True)
    row = rows_of(res.stdout)[0]  # not a terminal: CSV by default
    assert float(row["P"]) == 10.0
    bad = subprocess.run([sys.executable, "-m", "asperity.cli", "load", "--alpha", "0",
                          "--beta", "1", "--P", "1"], capture_output=True, text=True)
    assert bad.returncode == 2 and bad.stderr.count("\n") == 1 and "Traceback" not in bad.stderr


def test_reproduce_command(tmp_path):
    # The README's main job, through the installed entry point's module.
    out = tmp_path / "paper"
    res = subprocess.run([sys.executable, "-m", "asperity.cli", "reproduce", "--out", str(out)],
                         capture_output=True, text=True, check=True)
    lines = res.stdout.splitlines()
    assert sum(line.startswith("Fig ") for line in lines) == 7 and "index.html" in lines[-1]
    assert (out / "index.html").exists() and (out / "table1.csv").exists()


def test_reproduce_unwritable(capsys, tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    code, _, err = run(capsys, "reproduce", "--out", str(blocker / "sub"))
    assert code == 2 and err.count("\n") == 1 and "cannot write" in err


AU = ["--material", "Au", "--sigma", "2nm", "--radius", "1um", "--density", "1e12/m^2", "--area", "1mm^2"]


def test_physical_load_matches_library(capsys):
    from asperity.physical import PhysicalContact, Surface

    code, out, _ = run(capsys, "load", *AU, "--load", "1mN:1N:4", "--format", "csv")
    assert code == 0
    rows = rows_of(out)
    assert list(rows[0]) == ["d_m", "P_N", "F_N", "mu", "area_m2", "pressure_Pa", "contacts"]
    ref = PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6)).load_curve(np.geomspace(1e-3, 1, 4))
    np.testing.assert_allclose([float(r["P_N"]) for r in rows], ref.P, rtol=1e-14)
    np.testing.assert_allclose([float(r["F_N"]) for r in rows], ref.F, rtol=1e-14)
    np.testing.assert_allclose([float(r["d_m"]) for r in rows], ref.d, rtol=1e-14)


def test_physical_separation_and_pulloff(capsys):
    from asperity.physical import PhysicalContact, Surface

    contact = PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6), adhesion=False)
    code, out, _ = run(capsys, "separation", *AU, "--no-adhesion", "--separation", "-2nm,0nm,3nm",
                       "--format", "json")
    assert code == 0
    got = json.loads(out)
    np.testing.assert_allclose([r["P_N"] for r in got], contact.separation_curve([-2e-9, 0, 3e-9]).P,
                               rtol=1e-14)
    code, out, _ = run(capsys, "pulloff", *AU, "--format", "json")
    got = json.loads(out)
    ref = PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6)).pull_off()
    assert set(got) == {"pull_off_N", "d_m"} and got["pull_off_N"] == pytest.approx(ref.force, rel=1e-14)


def test_materials_listing(capsys):
    code, out, _ = run(capsys, "materials", "--format", "csv", "--sources")
    rows = rows_of(out)
    assert code == 0 and {"Au", "Si", "diamond", "Au/mica"} <= {r["name"] for r in rows}
    assert all(r["sources"] for r in rows if r["E_Pa"])


@pytest.mark.parametrize("argv, needle", [
    (["load", *AU, "--load", "1"], "--load"),                  # missing unit
    (["load", *AU, "--load", "1m"], "--load"),                 # wrong dimension
    (["load", *AU[:2], "--load", "1mN"], "--sigma"),           # incomplete surface
    (["load", *AU, "--P", "1"], "--load"),                     # dimensionless list with material
    (["load", *AU, "--alpha", "0.1", "--load", "1mN"], "not both"),
    (["load", "--material", "Unobtainium", *AU[2:], "--load", "1mN"], "Unobtainium"),
    (["separation", *AU[:2], "--sigma", "-2nm", *AU[4:], "--separation", "0nm"], "sigma"),
    (["load", "--beta", "10", "--P", "1"], "--alpha"),
    (["pulloff", "--alpha", "0.01", "--beta", "10"], "--gamma"),
])
def test_physical_errors(capsys, argv, needle):
    code, _, err = run(capsys, *argv)
    assert code == 2 and err.count("\n") == 1 and needle in err, err


def test_surface_command(capsys, tmp_path):
    pytest.importorskip("SurfaceTopography")
    from SurfaceTopography import Topography

    from asperity.topography import analyse_surface

    x = np.arange(128) * 10e-9
    h = 2e-9 * (np.sin(2 * np.pi * x / 160e-9)[:, None] * np.sin(2 * np.pi * x / 160e-9)[None, :])
    path = tmp_path / "scan.x3p"
    Topography(h, (1.28e-6, 1.28e-6), unit="m").to_x3p(str(path))
    code, out, _ = run(capsys, "surface", str(path), "--material", "Au", "--format", "json")
    assert code == 0
    got = json.loads(out)
    from asperity.materials import material

    ref = analyse_surface(path, material=material("Au")).to_dict()
    for method in ("spectral", "detected"):
        for key in ("sigma_s", "radius", "density"):
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


def test_json_has_no_infinity_or_nan(capsys):
    code, out, _ = run(capsys, "load", *MODEL, "--P", "5e-324,0,1", "--format", "json")
    assert code == 0
    rows = json.loads(out)  # strict JSON: Infinity/NaN would not parse back as null
    assert rows[0]["mu"] is None and rows[1]["mu"] is None and rows[2]["mu"] > 0


def test_negative_quantity_is_a_value_not_an_option(capsys):
    argv = ["separation", *AU[:2], "--sigma", "-2nm", *AU[4:], "--separation", "0nm"]
    code, _, err = run(capsys, *argv)
    assert code == 2 and "sigma_s must be > 0" in err


def test_note_when_real_area_approaches_nominal(capsys):
    argv = ["load", "--material", "Au", "--sigma", "5nm", "--radius", "0.8um", "--density", "2e13/m^2",
            "--area", "1mm^2", "--load", "1N,1e5N", "--format", "csv"]
    code, out, err = run(capsys, *argv)
    rows = rows_of(out)
    assert code == 0 and float(rows[1]["area_m2"]) > 0.1e-6
    assert "note:" in err and "nominal" in err
