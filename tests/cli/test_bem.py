"""``asperity bem`` gives what asperity.validation.validate_surface gives, and refuses bad input in one line."""

import json

import numpy as np
import pytest

pytest.importorskip("ContactMechanics")
pytest.importorskip("pint")

from asperity.validation import validate_surface  # noqa: E402
from asperity.validation.models import model_columns  # noqa: E402
from asperity.validation.surfaces import synthetic_surface  # noqa: E402

from .helpers import one_line_error, rows_of, run, strict_json  # noqa: E402

# Elastic comparisons on gold, which yields at these loads, up to real areas beyond 10 % of the nominal
# area (what the comparison is for): the plasticity and area notes are expected.
pytestmark = [pytest.mark.filterwarnings("ignore::asperity.plasticity.PlasticityWarning"),
              pytest.mark.filterwarnings("ignore::asperity.physical_results.AreaFractionWarning")]



@pytest.fixture(scope="module")
def scan(tmp_path_factory):
    path = tmp_path_factory.mktemp("bem") / "scan.npy"
    topo = synthetic_surface("self-affine", 4e-6, 48, short_cutoff=4e-6 / 8, seed=5)
    np.save(path, np.asarray(topo.heights()) * 1e9)  # heights in nm
    return path


ARGS = ["--size", "4um,4um", "--unit", "nm", "--material", "Au", "--quiet"]


def api(scan, loads, **kwargs):
    return validate_surface(scan, loads, material="Au", physical_sizes=(4e-6, 4e-6), unit="nm", **kwargs)


@pytest.mark.parametrize("load, values", [("1mN:10mN:3", np.geomspace(1e-3, 1e-2, 3)),
                                          ("1mN,5000uN", [1e-3, 5e-3]), ("0.001N", [1e-3])])
def test_csv_equals_api(capsys, scan, load, values):
    code, out, err = run(capsys, "bem", str(scan), *ARGS, "--load", load, "--format", "csv")
    assert code == 0, err
    rows = rows_of(out)
    expected = api(scan, values).columns()
    assert list(rows[0]) == list(model_columns("gw"))
    for name in ("P_N", "area_bem_m2", "area_spectral_m2", "gap_bem_m", "sep_bem_m", "spots_bem"):
        np.testing.assert_allclose([float(r[name]) for r in rows], expected[name], rtol=1e-12)


def test_json_grid_interaction_periodic_and_plot(capsys, scan, tmp_path):
    png, out_file = tmp_path / "b.png", tmp_path / "b.json"
    code, out, err = run(capsys, "bem", str(scan), *ARGS, "--load", "1mN,3mN", "--grid", "24", "--periodic",
                         "--interaction", "cgp2008", "--format", "json", "-o", str(out_file), "--plot", str(png))
    assert code == 0, err
    got = strict_json(out_file.read_text())
    expected = api(scan, [1e-3, 3e-3], grid=24, periodic=True, interaction="cgp2008")
    assert got["parameters"]["nb_grid_pts"] == [24, 24] and got["interaction"] == "cgp2008"
    assert got["contacts"] == strict_json(json.dumps(
        {m: c.to_dict() for m, c in expected.contacts.items()}))
    np.testing.assert_allclose(got["table"]["area_bem_m2"], expected.columns()["area_bem_m2"], rtol=1e-12)
    np.testing.assert_allclose(got["table"]["sep_spectral_m"], expected.columns()["sep_spectral_m"], rtol=1e-12)
    assert got["table"]["sep_bem_m"] == [None, None]
    assert png.read_bytes()[:4] == b"\x89PNG"


@pytest.mark.parametrize("models", ["icha,persson,bgt", "gw,icha", "persson"])
def test_models_csv_and_json_equal_api(capsys, scan, models):
    code, out, err = run(capsys, "bem", str(scan), *ARGS, "--load", "1mN,4mN", "--model", models, "--format", "csv")
    assert code == 0, err
    rows = rows_of(out)
    expected = api(scan, [1e-3, 4e-3], models=models)
    assert list(rows[0]) == list(expected.columns()) == list(model_columns(models))
    for name, values in expected.columns().items():
        got = np.array([float(r[name]) for r in rows])
        np.testing.assert_allclose(got, values, rtol=1e-12, equal_nan=True, err_msg=name)
    code, out, err = run(capsys, "bem", str(scan), *ARGS, "--load", "1mN,4mN", "--model", models, "--format", "json")
    got = strict_json(out)
    assert got["models"] == models.split(",")
    assert set(got["costs"]["ratios"]) == set(expected.cost_ratios)
    assert set(got["max_deviation_up_to_20pc"]) == set(expected.methods)


def test_table_and_progress(capsys, scan):
    code, out, err = run(capsys, "bem", str(scan), *ARGS[:-1], "--load", "1mN", "--format", "table")
    rows = [line for line in out.splitlines() if not line.startswith("#")]
    assert code == 0 and rows[0].split()[0] == "P_N"
    assert "bem" in err  # the progress report goes to standard error
    # each summit method's contact, as the library describes it, above the table
    contacts = api(scan, [1e-3]).contacts
    expected = "".join(f"# summits {m}:\n" + "".join(f"# {line}\n" for line in c.describe().splitlines())
                       for m, c in contacts.items())
    assert out.startswith(expected) and list(contacts) == ["spectral", "detected"]
    code, out, err = run(capsys, "bem", str(scan), *ARGS, "--load", "1mN", "--format", "csv", "--no-comments")
    assert code == 0 and out.startswith("P_N,")


@pytest.mark.parametrize("extra, needle", [
    (["--load", "0mN"], "load"),
    (["--load", "-1mN"], "load"),
    (["--load", "1"], "unit"),
    (["--load", "1mN,,2mN"], "empty item"),
    (["--load", "1mN", "--grid", "8"], "grid"),
    (["--load", "1mN", "--interaction", "bogus"], "interaction"),
    (["--load", "1mN", "--model", "bogus"], "models"),
    (["--load", "1mN", "--model", ","], "models"),
    (["--load", "1mN", "--model", "gw,,icha"], "models: empty name in 'gw,,icha'"),
    (["--load", "1mN", "--model", "gw,"], "models: empty name"),
    (["--load", "1mN", "--model", "icha", "--interaction", "cgp2008"], "include 'gw'"),
    (["--load", "1mN", "--material", "Unobtainium"], "Unobtainium"),
    (["--load", "1mN", "--tolerance", "0"], r"tolerance must lie in (0, 0.1], got 0.0"),
    (["--load", "1mN", "--maxiter", "0"], "maxiter must be a positive integer, got 0"),
])
def test_bad_input_one_line(capsys, scan, extra, needle):
    argv = ["bem", str(scan), "--size", "4um,4um", "--unit", "nm", "--material", "Au", "--quiet", *extra]
    code, out, err = run(capsys, *argv)
    assert one_line_error(code, err, needle), err
    assert out == ""


def test_unreadable_surface(capsys, tmp_path):
    bad = tmp_path / "bad.txt"
    bad.write_text("no heights here\n")
    code, _, err = run(capsys, "bem", str(bad), *ARGS, "--load", "1mN")
    assert one_line_error(code, err, "bad.txt")
    code, _, err = run(capsys, "bem", str(tmp_path / "missing.npy"), *ARGS, "--load", "1mN")
    assert one_line_error(code, err, "no such file")


def test_repeated_model_tolerance_and_maxiter_equal_api(capsys, scan):
    """``--model gw --model icha`` is ``--model gw,icha`` (found by a review: the last one
    won); ``--tolerance`` and ``--maxiter`` reach the solver as in the API."""
    loads = [1e-3, 3e-3]
    code, out, err = run(capsys, "bem", str(scan), *ARGS, "--load", "1mN,3mN", "--model", "gw", "--model", "icha",
                         "--tolerance", "1e-6", "--maxiter", "500", "--format", "json")
    assert code == 0, err
    got = strict_json(out)
    expected = api(scan, loads, models=("gw", "icha"), tolerance=1e-6, maxiter=500)
    assert got["models"] == ["gw", "icha"] and got["parameters"]["tolerance"] == 1e-6
    for name in ("area_bem_m2", "iterations_bem", "area_icha_m2", "area_spectral_m2"):
        np.testing.assert_allclose(got["table"][name], expected.columns()[name], rtol=1e-12)
    code, _, err = run(capsys, "bem", str(scan), *ARGS, "--load", "1mN", "--maxiter", "2")
    assert one_line_error(code, err, "(command line: --maxiter, --tolerance, --grid)"), err


def test_bodies_without_a_common_burgers_vector_use_the_nominal_one(capsys, scan):
    """Found by a review: Au/Si and mica were refused for lack of a Burgers vector the
    comparison does not depend on; now the nominal one is used, with a note, and the areas
    equal the API's with that b."""
    from asperity.materials import material, pair
    from asperity.validation.compare import NOMINAL_B

    argv = ["--size", "4um,4um", "--unit", "nm", "--quiet", "--load", "1mN", "--format", "json"]
    code, out, err = run(capsys, "bem", str(scan), *argv, "--material", "Au/Si")
    assert code == 0, err
    assert "different Burgers vectors: the GW model uses b = 2.5e-10 m" in err
    expected = validate_surface(scan, [1e-3], material=pair(material("Au"), material("Si"), b=NOMINAL_B),
                                physical_sizes=(4e-6, 4e-6), unit="nm")
    np.testing.assert_allclose(strict_json(out)["table"]["area_spectral_m2"],
                               expected.columns()["area_spectral_m2"], rtol=1e-12)
    code, out, err = run(capsys, "bem", str(scan), *argv, "--material", "mica")
    assert code == 0 and "material 'mica' has no Burgers vector b: the GW model uses b = 2.5e-10 m" in err
    code, _, err = run(capsys, "bem", str(scan), *argv, "--material", "Au/Si", "--E2", "-1GPa")
    assert one_line_error(code, err, "E2"), err  # another fault is still named


def test_the_helps_choices_and_default_are_the_librarys():
    from asperity.cli import bem
    from asperity.interaction import interaction_names
    from asperity.validation.bem import DEFAULT_TOLERANCE

    assert bem.INTERACTIONS == tuple(interaction_names()) and bem.DEFAULT_TOLERANCE == DEFAULT_TOLERANCE


def test_solver_options_are_checked_before_the_map_is_read(monkeypatch, tmp_path):
    """A CLI check: --tolerance 0 was refused only after the scan was read and analysed."""
    from asperity import validation
    from asperity.validation import compare

    def fail(*args, **kwargs):
        raise AssertionError("the map was read")

    monkeypatch.setattr(compare, "_topography", fail)
    for kwargs, needle in (({"tolerance": 0.5}, "tolerance must lie in"), ({"maxiter": 0}, "maxiter")):
        with pytest.raises(ValueError, match=needle):
            validation.validate_surface(tmp_path / "none.npy", [1e-3], material="Au", **kwargs)
