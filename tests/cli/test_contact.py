"""The physical-contact options (cli/_args.py): every route equals the Python API.

Bodies (--material, --E, --nu, --material2, --E2, --nu2, --b, --w, --h, --sigma0), surfaces
(--sigma-s, --rms with --bandwidth, --R, --eta, --area, --surface FILE), friction (--tau,
--tau-f1 --tau-f2 --a1 --a2), the contact stated at the top of every physical result, and the
area-fraction note.
"""

import io
import json

import numpy as np
import pytest

from asperity.bodies import contact_material
from asperity.friction_stress import HurtadoKim
from asperity.physical import PhysicalContact
from asperity.surface import Surface

from .helpers import AU, AU_NEW, comment_lines, one_line_error, rows_of, run, strict_json

#: Gold asperities of these surfaces yield (plasticity index psi ~ 23): the elastic model
#: warns (asperity.PlasticityWarning), tested in tests/test_plasticity.py, not here.
pytestmark = pytest.mark.filterwarnings("ignore::asperity.plasticity.PlasticityWarning")

pytest.importorskip("pint")

SURF = Surface(2e-9, 1e-6, 1e12, 1e-6)
S_ARGS = ["--sigma-s", "2nm", "--R", "1um", "--eta", "1e12/m^2", "--area", "1mm^2"]


def expected(contact, curve):
    """The command's JSON for a physical curve, from the API alone."""
    cols = curve.columns()
    rows = [{k: float(v[i]) for k, v in cols.items()} for i in range(len(curve))]
    return json.loads(json.dumps({"contact": contact.to_dict(), "rows": rows}).replace("NaN", "null"))


def separation_json(capsys, *argv, separation="0nm,2nm"):
    code, out, err = run(capsys, "separation", *argv, "--separation", separation, "--format", "json")
    assert code == 0, err
    return strict_json(out)


D = [0.0, 2e-9]


@pytest.mark.parametrize("argv, body, kwargs", [
    (["--material", "Au"], "Au", {}),
    (["--material", "Au/Au"], "Au/Au", {}),
    (["--material", "Au", "--material2", "Au"], contact_material("Au", material2="Au"), {}),
    (["--material", "Au", "--w", "0.1J/m^2"], contact_material("Au", w=0.1), {}),
    (["--material", "Au", "--w", "50mJ/m^2", "--h", "0.5nm"], contact_material("Au", w=0.05, h=5e-10), {}),
    (["--material", "Au", "--w", "0.1J/m^2", "--sigma0", "1GPa"], contact_material("Au", w=0.1, sigma0=1e9), {}),
    (["--material", "Au", "--E", "70GPa", "--nu", "0.4"], contact_material("Au", E=70e9, nu=0.4), {}),
    (["--E", "70GPa", "--nu", "0.2", "--b", "0.25nm", "--w", "0.05J/m^2"],
     contact_material(E=70e9, nu=0.2, b=2.5e-10, w=0.05), {}),
    (["--material", "Au", "--material2", "Si", "--b", "0.3nm", "--w", "0.5J/m^2"],
     contact_material("Au", material2="Si", b=3e-10, w=0.5), {}),
    (["--material", "Au/Si", "--b", "0.3nm", "--w", "0.5J/m^2"], contact_material("Au/Si", b=3e-10, w=0.5), {}),
    (["--material", "Au", "--E2", "160GPa", "--nu2", "0.22", "--w", "0.5J/m^2"],
     contact_material("Au", E2=160e9, nu2=0.22, w=0.5), {}),
    (["--material", "Au", "--b", "0.3nm"], contact_material("Au", b=3e-10), {}),
    (["--material", "Au", "--no-adhesion"], "Au", {"adhesion": False}),
    (["--material", "Au", "--tau", "50MPa"], "Au", {"friction": 5e7}),
    (["--material", "Au", "--tau-f1", "0.01", "--a2", "1e5"], "Au", {"friction": HurtadoKim(tau_f1=0.01, a2=1e5)}),
])
def test_bodies_and_friction_equal_the_api(capsys, argv, body, kwargs):
    contact = PhysicalContact(body, SURF, **kwargs)
    assert separation_json(capsys, *argv, *S_ARGS) == expected(contact, contact.separation_curve(D))


def test_gold_on_gold_is_not_gold_on_a_flat(capsys):
    one = separation_json(capsys, "--material", "Au", *S_ARGS)
    two = separation_json(capsys, "--material", "Au/Au", *S_ARGS)
    assert two["contact"]["E_star_Pa"] == pytest.approx(one["contact"]["E_star_Pa"] / 2, rel=1e-14)
    assert one["contact"]["body2"]["rigid"] and not two["contact"]["body2"]["rigid"]
    assert one["rows"] != two["rows"]


def test_the_library_names_and_the_old_spellings_agree(capsys):
    new = run(capsys, "load", *AU_NEW, "--load", "1mN,1N", "--format", "csv")
    old = run(capsys, "load", *AU, "--load", "1mN,1N", "--format", "csv")
    assert new == old and new[0] == 0


def test_rms_with_bandwidth_equals_the_api(capsys):
    contact = PhysicalContact("Au", Surface.from_rms(5e-9, 1e-6, 1e12, 1e-6, alpha_n=10.0))
    got = separation_json(capsys, "--material", "Au", "--rms", "5nm", "--bandwidth", "10", "--R", "1um",
                          "--eta", "1e12/m^2", "--area", "1mm^2")
    assert got == expected(contact, contact.separation_curve(D))
    assert got["contact"]["sigma_s_m"] == pytest.approx(5e-9 * (1 - 0.8968 / 10) ** 0.5, rel=1e-15)
    alias = separation_json(capsys, "--material", "Au", "--rms", "5nm", "--alpha-n", "10", "--R", "1um",
                            "--eta", "1e12/m^2", "--area", "1mm^2")
    assert alias == got


@pytest.mark.parametrize("argv, needle", [
    (["--material", "Au", "--rms", "5nm", "--R", "1um", "--eta", "1/um^2", "--area", "1mm^2"],
     "--rms needs --bandwidth"),
    (["--material", "Au", "--sigma-s", "2nm", "--rms", "5nm", "--bandwidth", "10", "--R", "1um", "--eta",
      "1/um^2", "--area", "1mm^2"], "not both"),
    ([*S_ARGS[:-2], "--material", "Au"], "needs --area"),
    (["--material", "Au", "--R", "1um", "--eta", "1/um^2", "--area", "1mm^2"], "--sigma-s (or --rms)"),
    (["--material", "Au", *S_ARGS, "--bandwidth", "10"], "--bandwidth only applies with --rms"),
    (["--material", "Au", *S_ARGS, "--size", "5um"], "--size applies only with --surface"),
    (["--material", "Au", *S_ARGS, "--surface", "x.npy"], "--surface gives sigma_s, R and eta"),
    (["--material", "Au", *S_ARGS, "--tau", "50MPa", "--a1", "30"], "--tau (a constant shear strength)"),
    (["--material", "Au", *S_ARGS, "--alpha", "0.1"], "not both"),
    (["--material", "Au", *S_ARGS, "--h-over-b", "2"], "not both"),
    ([*S_ARGS], "give a material"),
    (["--E", "70GPa", *S_ARGS], "nu is needed"),
    (["--material", "Au", "--E2", "70GPa", *S_ARGS], "nu2 is needed"),
    (["--material", "Au/Au", "--material2", "Si", *S_ARGS], "already a pair"),
    (["--material", "Au", "--w", "-1J/m^2", *S_ARGS], "w must be >= 0"),
    (["--material", "Au", "--w", "1GPa", *S_ARGS], "--w must have units compatible with J/m^2"),
    (["--material", "Au", "--nu", "0.7", *S_ARGS], "nu (Poisson's ratio) must lie in (-1, 0.5)"),
    (["--material", "Au", "--tau", "-5MPa", *S_ARGS], "must be > 0 Pa"),
    (["--material", "Au", "--tau-f1", "0", *S_ARGS], "tau_f1"),
    (["--material", "Au/Si", *S_ARGS], "different Burgers vectors"),
    (["--material", "mica", *S_ARGS], "has no Burgers vector b"),
])
def test_bad_contacts_are_one_line_errors(capsys, argv, needle):
    code, out, err = run(capsys, "separation", *argv, "--separation", "0nm")
    assert one_line_error(code, err, needle), err
    assert out == ""


def test_tau_needs_a_physical_contact(capsys):
    code, _, err = run(capsys, "load", "--alpha", "0.01", "--beta", "1000", "--tau", "5MPa", "--P", "1")
    assert one_line_error(code, err, "--tau is a stress")


def test_friction_constants_serve_the_dimensionless_model_too(capsys):
    import asperity

    code, out, _ = run(capsys, "load", "--alpha", "0.01", "--beta", "1000", "--tau-f2", "1e-4", "--P", "1,10",
                       "--format", "csv")
    assert code == 0
    assert out == asperity.load_curve([1, 10], 0.01, 1000, friction=HurtadoKim(tau_f2=1e-4)).to_csv()


# -- the contact stated at the top of every physical result -------------------------------------

@pytest.mark.parametrize("command, points", [("load", ["--load", "1mN,1N"]),
                                             ("separation", ["--separation", "0nm,2nm"]),
                                             ("pulloff", [])])
@pytest.mark.parametrize("fmt", ["table", "csv"])
def test_every_physical_result_starts_with_the_contact(capsys, command, points, fmt):
    contact = PhysicalContact("Au/Au", SURF)
    code, out, _ = run(capsys, command, "--material", "Au/Au", *S_ARGS, *points, "--format", fmt)
    assert code == 0
    assert comment_lines(out) == contact.describe().splitlines()
    assert out.startswith("# contact: Au (E 78 GPa, nu 0.44) on Au (E 78 GPa, nu 0.44)\n")
    code, bare, _ = run(capsys, command, "--material", "Au/Au", *S_ARGS, *points, "--format", fmt,
                        "--no-comments")
    assert code == 0 and not comment_lines(bare) and out.endswith(bare)


def test_pandas_reads_the_commented_csv(capsys):
    pd = pytest.importorskip("pandas")
    code, out, _ = run(capsys, "load", *AU_NEW, "--load", "1mN:1N:4", "--format", "csv")
    frame = pd.read_csv(io.StringIO(out), comment="#")
    ref = PhysicalContact("Au", SURF).load_curve(np.geomspace(1e-3, 1, 4))
    assert list(frame.columns) == ["d_m", "P_N", "F_N", "mu", "area_m2", "pressure_Pa", "contacts"]
    np.testing.assert_allclose(frame["F_N"], ref.F, rtol=1e-15)


def test_json_is_one_object_with_the_contact_and_rows(capsys):
    code, out, _ = run(capsys, "load", *AU_NEW, "--load", "1mN,1N", "--format", "json")
    got = strict_json(out)
    contact = PhysicalContact("Au", SURF)
    assert got == expected(contact, contact.load_curve([1e-3, 1.0]))
    for key in ("alpha", "beta", "gamma", "lambda", "N", "E_star_Pa", "G_star_Pa", "regime", "body1", "body2"):
        assert key in got["contact"]


def test_dimensionless_results_have_no_contact_lines(capsys):
    code, out, _ = run(capsys, "load", "--alpha", "0.01", "--beta", "1000", "--P", "1", "--format", "csv")
    assert code == 0 and not out.startswith("#")


# -- the area-fraction note ----------------------------------------------------------------------

#: Gold yields on this surface: --plastic-threshold 1 turns its yield note off, leaving the area's.
DENSE = ["--material", "Au", "--sigma-s", "5nm", "--R", "0.8um", "--eta", "2e13/m^2", "--area", "1mm^2",
         "--plastic-threshold", "1"]


@pytest.mark.parametrize("command, points", [("load", ["--load", "1N,1e5N"]),
                                             ("separation", ["--separation", "-20nm,0nm"])])
def test_one_note_when_the_real_area_passes_the_nominal(capsys, command, points):
    code, out, err = run(capsys, command, *DENSE, *points, "--format", "csv")
    assert code == 0 and rows_of(out)
    lines = err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("asperity: note: the real contact area reaches")
    assert "not physical" in lines[0]


def test_no_note_below_ten_percent(capsys):
    code, _, err = run(capsys, "load", *DENSE, "--load", "1mN", "--format", "csv")
    assert code == 0 and err == ""


def test_no_note_after_an_error(capsys):
    code, _, err = run(capsys, "load", *DENSE, "--load", "1e5N,-1e9N", "--format", "csv")
    assert one_line_error(code, err, "P (load)")


# -- from a scan to forces in one command --------------------------------------------------------

@pytest.fixture(scope="module")
def scan_nm(tmp_path_factory):
    """A 128 x 128 self-affine scan with heights in nm, stored without sizes or units (.npy)."""
    pytest.importorskip("SurfaceTopography")
    from SurfaceTopography.Generation import fourier_synthesis

    topo = fourier_synthesis((128, 128), (2.5e-6, 2.5e-6), 0.8, rms_height=6e-9, short_cutoff=0.1e-6,
                             long_cutoff=1e-6, rng=np.random.default_rng(7))
    path = tmp_path_factory.mktemp("scan") / "gold_nm.npy"
    np.save(path, topo.heights() * 1e9)
    return path


@pytest.mark.parametrize("method", ["spectral", "detected"])
def test_scan_to_forces_equals_the_api(capsys, scan_nm, method):
    from asperity.topography import analyse_surface

    analysis = analyse_surface(scan_nm, physical_sizes=("2.5um", "2.5um"), unit="nm")
    summits = getattr(analysis, method)
    contact = PhysicalContact("Au", Surface(summits.sigma_s, summits.R, summits.eta, 1e-6))
    ref = contact.load_curve([1e-3, 0.1])
    code, out, err = run(capsys, "load", "--surface", str(scan_nm), "--size", "2.5um,2.5um", "--unit", "nm",
                         "--method", method, "--material", "Au", "--area", "1mm^2", "--load", "1mN,0.1N",
                         "--format", "json")
    assert code == 0, err
    got = strict_json(out)
    assert got["rows"] == expected(contact, ref)["rows"]
    for name in ("sigma_s", "R", "eta"):
        assert got["contact"][{"sigma_s": "sigma_s_m", "R": "R_m", "eta": "eta_per_m2"}[name]] == \
            getattr(summits, name)
    assert got["contact"]["surface_source"].startswith(f"{scan_nm}, {method} summits")


def test_scan_route_in_pulloff_and_separation(capsys, scan_nm):
    from asperity.topography import analyse_surface

    surface = analyse_surface(scan_nm, physical_sizes=("2.5um", "2.5um"), unit="nm").surface(1e-6)
    contact = PhysicalContact("Au", surface)
    scan = ["--surface", str(scan_nm), "--size", "2.5um,2.5um", "--unit", "nm", "--material", "Au",
            "--area", "1mm^2"]
    code, out, _ = run(capsys, "pulloff", *scan, "--format", "json")
    assert code == 0 and strict_json(out)["rows"] == [contact.pull_off().to_dict()]
    got = separation_json(capsys, *scan, separation="5nm,10nm")
    assert got == expected(contact, contact.separation_curve([5e-9, 10e-9]))


def test_scan_doubts_are_notes(capsys, tmp_path):
    pytest.importorskip("SurfaceTopography")
    path = tmp_path / "noise.npy"
    np.save(path, np.random.default_rng(3).standard_normal((64, 64)))
    code, out, err = run(capsys, "pulloff", "--surface", str(path), "--size", "1um", "--unit", "nm",
                         "--material", "Au", "--area", "1mm^2", "--format", "csv")
    assert code == 0 and comment_lines(out)
    assert err and all(line.startswith(f"asperity: note: surface {path}: ") for line in err.strip().splitlines())


def test_a_bad_scan_is_one_line(capsys, tmp_path):
    pytest.importorskip("SurfaceTopography")
    code, _, err = run(capsys, "load", "--surface", str(tmp_path), "--material", "Au", "--area", "1mm^2",
                       "--load", "1mN")
    assert one_line_error(code, err, str(tmp_path))


@pytest.mark.parametrize("command", ["load", "separation", "pulloff", "cycle", "fit"])
def test_heights_reach_every_physical_command(command):
    """--heights is in every command with a physical contact (fit's gw model too), and the contact gets it."""
    from asperity.cli import build_parser
    from asperity.cli._build import contact_from_args

    data = ["data.csv"] if command == "fit" else []
    args = build_parser().parse_args([command, *data, *AU_NEW, "--heights", "weibull:skew=0.5"])
    assert contact_from_args(args).heights.spec == "weibull:skew=0.5"
    assert PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6)).heights.spec == "gaussian"  # without it
