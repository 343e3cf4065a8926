"""``asperity fit``: the command line gives exactly what asperity.fit gives, and refuses bad data in one line."""

import json
import math
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import asperity
from asperity import fit, jkr

from .helpers import one_line_error, run, strict_json

pytest.importorskip("lmfit")

R, W, TAU, E_STAR = 20e-9, 0.3, 5e8, 1e11


def write(path, header, rows):
    path.write_text(header + "\n" + "".join(",".join(repr(float(x)) for x in row) + "\n" for row in rows))
    return path


@pytest.fixture
def line(tmp_path):
    P = np.linspace(0.5, 5.0, 12)
    F = 0.3 * (P + 1.0) * (1 + 0.02 * np.random.default_rng(3).standard_normal(12))
    return write(tmp_path / "line.csv", "P,F", zip(P, F, strict=True))


@pytest.fixture
def afm(tmp_path):
    P = np.linspace(-1.3 * math.pi * W * R, 50e-9, 25)
    F = TAU * math.pi * jkr.jkr_contact_radius(P, R=R, w=W, E_star=E_STAR) ** 2
    F = F * (1 + 0.02 * np.random.default_rng(7).standard_normal(P.size))
    return write(tmp_path / "afm.csv", "load [nN],friction [nN],friction_err [nN]",
                 zip(P * 1e9, F * 1e9, 0.02 * F * 1e9, strict=True))


def same(cli_text, result):
    assert strict_json(cli_text) == json.loads(json.dumps(result.to_dict()))


@pytest.mark.parametrize("argv, kwargs", [
    (["--model", "amontons"], {"model": "amontons"}),
    (["--model", "amontons", "--vary", "mu0", "--fix", "P0=1"], {"model": "amontons", "vary": ["mu0"],
                                                                  "fix": {"P0": 1.0}}),
    (["--model", "amontons", "--start", "P0=0.5,mu0=0.2", "--bounds", "P0=:3,mu0=0.01:"],
     {"model": "amontons", "start": {"P0": 0.5, "mu0": 0.2}, "bounds": {"P0": (None, 3.0), "mu0": (0.01, None)}}),
    (["--model", "cos", "--weights", "none", "--ci", "wald"], {"model": "cos", "weights": "none", "ci": "wald"}),
    (["--model", "cos", "--restarts", "always", "--ci", "wald"], {"model": "cos", "restarts": "always", "ci": "wald"}),
    (["--model", "amontons", "--restarts", "never"], {"model": "amontons", "restarts": "never"}),
    (["--model", "cos", "--ci", "profile", "--profile-budget", "1e-9"],
     {"model": "cos", "ci": "profile", "profile_budget": 1e-9}),
    (["--model", "amontons", "--ci", "profile", "--profile-budget", "inf"],
     {"model": "amontons", "ci": "profile", "profile_budget": math.inf}),
    (["--model", "amontons", "--loss", "huber", "--weights", "relative"],
     {"model": "amontons", "loss": "huber", "weights": "relative"}),
    (["--model", "gw", "--vary", "gamma", "--fix", "alpha=0.01,beta=100", "--ci", "wald"],
     {"model": "gw", "vary": ["gamma"], "fix": {"alpha": 0.01, "beta": 100.0}, "ci": "wald"}),
])
def test_json_is_the_library_result(capsys, line, argv, kwargs):
    code, out, err = run(capsys, "fit", str(line), *argv, "--format", "json")
    assert code == 0, err
    same(out, fit.fit_friction_load(line, **kwargs))


def test_laws_with_material_and_radius_and_units(capsys, afm):
    from asperity.materials import material

    si = material("Si")
    code, out, err = run(capsys, "fit", str(afm), "--model", "jkr", "--material", "Si", "--radius", "20nm",
                         "--format", "json")
    assert code == 0, err
    same(out, fit.fit_friction_load(afm, "jkr", material=si, fix={"R_m": 20e-9}))
    code, out, err = run(capsys, "fit", str(afm), "--model", "jkr", "--fix", "E_star_Pa=100GPa,R_m=20nm",
                         "--vary", "w_J_m2,tau_Pa", "--format", "json")
    assert code == 0, err
    res = fit.fit_friction_load(afm, "jkr", vary=["w_J_m2", "tau_Pa"], fix={"E_star_Pa": 1e11, "R_m": 2e-8})
    same(out, res)
    assert res.values["w_J_m2"] == pytest.approx(W, rel=0.1) and res.weights == ("column",)


def test_compare_json_is_ranked_by_aic(capsys, afm):
    code, out, err = run(capsys, "fit", str(afm), "--compare", "jkr,dmt,amontons", "--fix",
                         "E_star_Pa=1e11,R_m=2e-8", "--format", "json")
    assert code == 0, err
    listed = strict_json(out)
    table = fit.compare_models(afm, ["jkr", "dmt", "amontons"], fix={"E_star_Pa": 1e11, "R_m": 2e-8})
    assert listed == json.loads(json.dumps(table.to_list()))
    assert [d["model"] for d in listed][0] == "jkr"
    assert [d["aic"] for d in listed] == sorted(d["aic"] for d in listed)


def test_joint_fit_of_several_files(capsys, tmp_path):
    P = np.linspace(0.5, 5.0, 10)
    a = write(tmp_path / "a.csv", "P,F", zip(P, 0.3 * (P + 1.0), strict=True))
    b = write(tmp_path / "b.csv", "P,F", zip(P, 0.3 * (P + 2.0), strict=True))
    code, out, err = run(capsys, "fit", str(a), str(b), "--model", "amontons", "--shared", "mu0", "--weights",
                         "none", "--format", "json")
    assert code == 0, err
    same(out, fit.fit_joint([a, b], "amontons", shared=["mu0"], weights="none"))
    assert set(strict_json(out)["parameters"]) == {"mu0", "P0_1", "P0_2"}


def test_units_flags_kind_and_drop_nan(capsys, tmp_path):
    path = tmp_path / "u.csv"
    path.write_text("load,friction\n1,0.6\n2,0.9\n,1.0\n3,1.2\n4,1.5\n")
    code, out, err = run(capsys, "fit", str(path), "--model", "amontons", "--load-unit", "nN", "--friction-unit",
                         "nN", "--drop-nan", "--kind", "friction", "--format", "json")
    assert code == 0, err
    res = fit.fit_friction_load(path, "amontons", units={"load": "nN", "friction": "nN"}, drop_nan=True)
    same(out, res)
    assert "dropped 1 row(s)" in " ".join(res.warnings)
    sep = tmp_path / "sep.csv"
    d = np.linspace(-2.0, 0.0, 8)
    force = 4 / 3 * 1e11 * math.sqrt(2e-8) * (-d * 1e-9) ** 1.5 * 1e9
    write(sep, "separation,force", zip(d, force, strict=True))
    code, out, err = run(capsys, "fit", str(sep), "--model", "hertz", "--separation-unit", "nm", "--load-unit", "nN",
                         "--vary", "R_m", "--start", "R_m=10nm", "--fix", "E_star_Pa=1e11", "--format", "json")
    assert code == 0, err
    assert strict_json(out)["parameters"]["R_m"]["value"] == pytest.approx(2e-8, rel=1e-8)


@pytest.mark.filterwarnings("ignore::asperity.plasticity.PlasticityWarning")  # gold yields: a note in the fit
def test_gw_physical_with_the_contact_flags(capsys, tmp_path):
    from asperity.physical import PhysicalContact, Surface

    contact = PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6))
    P = np.geomspace(1e-3, 1.0, 12)
    path = write(tmp_path / "au.csv", "load [N],friction [N]", zip(P, contact.load_curve(P).F * 1.1, strict=True))
    flags = ["--material", "Au", "--sigma-s", "2nm", "--R", "1um", "--eta", "1e12/m^2", "--area", "1mm^2"]
    code, out, err = run(capsys, "fit", str(path), "--model", "gw", *flags, "--vary", "tau1_Pa,tau2_Pa",
                         "--ci", "wald", "--format", "json")
    assert code == 0, err
    res = fit.fit_friction_load(path, "gw", contact=contact, vary=["tau1_Pa", "tau2_Pa"], ci="wald",
                                fix={"R_m": 1e-6})
    # the contact the fit starts from, then the fit (the old spellings are aliases)
    assert strict_json(out) == json.loads(json.dumps({"contact": contact.to_dict(), **res.to_dict()}))
    old = ["--material", "Au", "--sigma", "2nm", "--radius", "1um", "--density", "1e12/m^2", "--area", "1mm^2"]
    code, out, err = run(capsys, "fit", str(path), "--model", "gw", *old, "--vary", "tau1_Pa,tau2_Pa",
                         "--ci", "wald")
    assert code == 0 and out == "".join(f"# {line}\n" for line in contact.describe().splitlines()) + res.summary()


@pytest.mark.filterwarnings("ignore::asperity.plasticity.PlasticityWarning")  # gold yields: a note in the fit
@pytest.mark.parametrize("vary", [[], ["--vary", "tau_Pa"]])
def test_gw_physical_with_tau_fits_the_one_constant_shear_strength(capsys, tmp_path, vary):
    """Found by a user trial: with --tau the header said 'constant shear strength' while the
    fit varied the two Hurtado-Kim strengths, and '--vary tau_Pa' was unknown."""
    from asperity.friction_stress import ConstantShear
    from asperity.physical import PhysicalContact, Surface

    contact = PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6), adhesion=False,
                              friction=ConstantShear(50e6 / 54.17e9))
    P = np.geomspace(1e-3, 1.0, 12)
    path = write(tmp_path / "au.csv", "load [N],friction [N]",
                 zip(P, PhysicalContact("Au", contact.surface, adhesion=False).load_curve(P).area * 8e7, strict=True))
    flags = ["--material", "Au", "--no-adhesion", "--sigma-s", "2nm", "--R", "1um", "--eta", "1e12/m^2",
             "--area", "1mm^2", "--tau", f"{50e6 / 54.17e9 * contact.G_star}Pa"]
    code, out, err = run(capsys, "fit", str(path), "--model", "gw", *flags, *vary, "--ci", "wald", "--format", "json")
    assert code == 0, err
    res = fit.fit_friction_load(path, "gw", contact=contact, ci="wald")
    got = strict_json(out)
    assert got == json.loads(json.dumps({"contact": contact.to_dict(), **res.to_dict()}))
    assert got["parameters"]["tau_Pa"]["value"] == pytest.approx(8e7, rel=1e-6) and "tau1_Pa" not in got["parameters"]
    code, out, err = run(capsys, "fit", str(path), "--model", "gw", *flags, "--vary", "tau1_Pa")
    assert one_line_error(code, err, "tau1_Pa") and "tau_Pa" in err


def test_table_output_plot_and_file(capsys, line, tmp_path):
    pytest.importorskip("matplotlib")
    out_file, png = tmp_path / "fit.txt", tmp_path / "fit.png"
    code, out, err = run(capsys, "fit", str(line), "--model", "amontons", "-o", str(out_file), "--plot", str(png))
    assert code == 0 and out == "" and err == ""
    assert out_file.read_text() == fit.fit_friction_load(line, "amontons").summary()
    assert png.read_bytes()[:4] == b"\x89PNG"


MISSING_COLUMN = "x,y\n1,2\n"
CASES = {
    "missing column": ("P,time\n1,2\n", [], "missing columns"),
    "ambiguous columns": ("P,F,mu\n1,2,0.1\n", [], "ambiguous columns"),
    "non-numeric cell": ("P,F\n1,2\n3,abc\n", [], "'abc' is not a number"),
    "NaN row": ("P,F\n1,2\n3,\n", [], "empty or NaN cell in column 'F'"),
    "negative friction": ("P,F\n1,2\n3,-4\n", [], "negative friction"),
    "too few points": ("P,F\n1,2\n", [], "1 data point cannot fix 2 free parameters"),
    "unknown unit": ("load [furlongs],friction [nN]\n1,2\n2,3\n3,4\n", [], "load"),
    "wrong dimension": ("load [nm],friction [nN]\n1,2\n2,3\n3,4\n", [], "compatible with N"),
    "inconsistent units": ("P,friction [nN]\n1,2\n2,3\n3,4\n", [], "inconsistent units"),
    "unit against flag": ("load [mN],friction [nN]\n1,2\n2,3\n3,4\n", ["--load-unit", "uN"], "inconsistent units"),
    "no unit": ("load,friction [nN]\n1,2\n2,3\n3,4\n", [], "has no unit"),
    "space separated": ("load [nN] friction [nN]\n1 2\n2 3\n3 4\n", [], "is one column: separate the columns"),
    "digit separator": ("load [nN],friction [nN]\n1_0,2\n2,3\n3,4\n", [], "'1_0' is not a number"),
    "underflow": ("load [nN],friction [nN]\n1e-400,2\n2,3\n3,4\n", [], "smaller than the smallest double"),
    "fixed and varied": ("P,F\n1,2\n2,3\n3,4\n", ["--vary", "mu0", "--fix", "mu0=1"], "both fixed and varied"),
    "bounds exclude start": ("P,F\n1,2\n2,3\n3,4\n", ["--bounds", "P0=5:6", "--start", "P0=1"],
                             "exclude its start value"),
    "bad fix": ("P,F\n1,2\n2,3\n3,4\n", ["--fix", "mu0"], "--fix: expected NAME=VALUE"),
    "bad bound": ("P,F\n1,2\n2,3\n3,4\n", ["--bounds", "P0=1"], "--bounds: expected P0=LO:HI"),
    "unknown parameter": ("P,F\n1,2\n2,3\n3,4\n", ["--vary", "zeta"], "unknown parameter 'zeta'"),
    "empty file": ("", [], "no header line"),
    "material ignored": ("P,F\n1,2\n2,3\n3,4\n", ["--material", "Au"],
                         "material: model 'amontons' takes no material"),
    "zero budget": ("P,F\n1,2\n2,3\n3,4\n", ["--profile-budget", "0"], "expected seconds > 0 or inf, got '0'"),
    "nan budget": ("P,F\n1,2\n2,3\n3,4\n", ["--profile-budget", "nan"], "expected seconds > 0 or inf"),
    "word budget": ("P,F\n1,2\n2,3\n3,4\n", ["--profile-budget", "soon"], "expected seconds > 0 or inf"),
    "budget without profiles": ("P,F\n1,2\n2,3\n3,4\n", ["--ci", "wald", "--profile-budget", "5"],
                                "--profile-budget limits the profile likelihoods, which --ci wald never computes"),
    "contact ignored": ("P,F\n1,2\n2,3\n3,4\n", ["--sigma-s", "2nm", "--R", "1um", "--eta", "1e12/m^2", "--area",
                                                  "1mm^2", "--material", "Si"],
                        "--sigma-s, --eta, --area: surface options make a physical contact, which only the "
                        "rough-surface model gw takes; model amontons takes none"),
    "model and compare": ("P,F\n1,2\n2,3\n3,4\n", ["--compare", "cos"], "give --model or --compare, not both"),
}


@pytest.mark.parametrize("case", list(CASES))
def test_bad_data_one_line_exit_2_nothing_written(capsys, tmp_path, case):
    text, extra, needle = CASES[case]
    data = tmp_path / "bad.csv"
    data.write_text(text)
    out_file, png = tmp_path / "keep.txt", tmp_path / "fit.png"
    out_file.write_text("old content")
    code, out, err = run(capsys, "fit", str(data), "--model", "amontons", *extra, "-o", str(out_file),
                         "--plot", str(png))
    assert one_line_error(code, err, needle), err
    assert out == "" and out_file.read_text() == "old content" and not png.exists()


def test_missing_file_and_missing_lmfit(capsys, monkeypatch, line, tmp_path):
    code, out, err = run(capsys, "fit", str(tmp_path / "nope.csv"))
    assert one_line_error(code, err, "cannot read data file")
    monkeypatch.setitem(sys.modules, "lmfit", None)
    code, out, err = run(capsys, "fit", str(line), "--model", "amontons")
    assert one_line_error(code, err, "fitting needs lmfit: pip install 'asperity[fit]'")


def test_help_and_startup(capsys):
    with pytest.raises(SystemExit) as exc:
        asperity.cli.main(["fit", "--help"])
    assert exc.value.code == 0
    out = " ".join(capsys.readouterr().out.split())
    for word in ("--model", "--vary", "--fix", "--bounds", "--compare", "--weights", "--loss", "--format", "--plot",
                 "--drop-nan", "--load-unit", "friction [nN]", "w_J_m2", "--material", "--shared",
                 "--profile-budget"):
        assert word in out, word
    from asperity.fit.profile import PROFILE_BUDGET

    assert f"(default {PROFILE_BUDGET:g}; inf: no limit;" in out  # the help's default is the library's
    probe = textwrap.dedent("""
        import sys
        from asperity.cli import main
        try:
            main(['fit', '--help'])
        except SystemExit:
            pass
        print(sorted(m for m in sys.modules if m.split('.')[0] in ('numpy', 'scipy', 'lmfit', 'pandas')))
    """)
    res = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True)
    assert res.stdout.strip().splitlines()[-1] == "[]"


@pytest.mark.parametrize("extra, needle", [
    (["--law", "jackson-green"], "applies to the rough-surface model gw"),
    (["--hardness", "1GPa"], "applies to the rough-surface model gw"),
    (["--size-effect"], "only to the rough-surface model with a physical contact"),
    (["--plastic-threshold", "0.1"], "only to the rough-surface model with a physical contact"),
    (["--heights", "weibull:skew=0.5", "--law", "elastic"], "apply to the rough-surface model gw")])
def test_contact_options_without_a_contact_are_refused(capsys, line, extra, needle):
    """The law and height options are refused by the single-asperity laws, never ignored."""
    code, out, err = run(capsys, "fit", str(line), "--model", "amontons", *extra)
    assert out == "" and one_line_error(code, err, needle)
    assert all(option in err for option in extra if option.startswith("--"))  # each one named


def test_heights_of_the_dimensionless_gw_fit(capsys, tmp_path):
    """--heights without a physical contact fits the dimensionless gw model with those summit
    heights, exactly as GWFit(heights=...) in the API; the single-asperity laws refuse it."""
    import json

    from asperity.fit import fit_friction_load
    from asperity.fit.gw import GWFit
    from asperity.heights import Weibull

    model = asperity.Model(0.01, 1000.0, 1e-3, heights=Weibull(skew=0.5))
    P = np.geomspace(1.0, 1e4, 15)
    F = model.load_curve(P).F * (1 + 0.02 * np.random.default_rng(4).standard_normal(P.size))
    path = tmp_path / "w.csv"
    path.write_text("P,F,F_err\n" + "".join(f"{p!r},{f!r},{0.02 * f!r}\n" for p, f in zip(P.tolist(), F.tolist(),
                                                                                          strict=True)))
    code, out, err = run(capsys, "fit", str(path), "--heights", "weibull:skew=0.5", "--format", "json")
    assert code == 0, err
    got = json.loads(out)
    ref = fit_friction_load(str(path), GWFit(heights=Weibull(skew=0.5)))
    assert got["model"] == ref.model == "gw (heights weibull:skew=0.5)"
    for name in ("alpha", "beta", "gamma"):
        assert got["parameters"][name]["value"] == pytest.approx(ref.values[name], rel=1e-12)
    gaussian = fit_friction_load(str(path), "gw")
    assert gaussian.values["alpha"] != pytest.approx(ref.values["alpha"], rel=1e-6)  # the heights matter
    code, out, err = run(capsys, "fit", str(path), "--heights", "exponential", "--model", "jkr")
    assert out == "" and one_line_error(code, err, "--heights applies to the rough-surface model gw")
    code, out, err = run(capsys, "fit", str(path), "--heights", "exponential", "--compare", "gw,amontons")
    assert code == 0 and "gw (heights exponential)" in out, err


def test_jackson_green_law_of_the_dimensionless_gw_fit(capsys, tmp_path):
    """--law jackson-green --hardness H/E* [--h-star h*/sigma] on dimensionless data fits
    GWFit(law=JacksonGreen(...)) exactly as the API; the other contact options stay refused."""
    from asperity.elastic_plastic import JacksonGreen
    from asperity.fit.gw import GWFit

    P = np.geomspace(1.0, 1e4, 20)
    F = asperity.Model(0.05, 1000.0, law=JacksonGreen(0.004)).load_curve(P).F
    F = F * (1 + 0.02 * np.random.default_rng(2).standard_normal(P.size))
    path = write(tmp_path / "jg.csv", "P,F", zip(P, F, strict=True))
    argv = ["fit", str(path), "--law", "jackson-green", "--hardness", "0.006", "--h-star", "0.5",
            "--vary", "alpha,beta,H_over_E", "--ci", "wald", "--format", "json"]
    code, out, err = run(capsys, *argv)
    assert code == 0, err
    same(out, fit.fit_friction_load(str(path), GWFit(law=JacksonGreen(0.006, 0.5)),
                                    vary=["alpha", "beta", "H_over_E"], ci="wald"))
    assert strict_json(out)["model"] == "gw (jackson-green H/E*=0.006 h*/sigma=0.5)"
    for extra, needle in ((["--law", "jackson-green"], "give --hardness H/E*"),
                          (["--law", "jackson-green", "--hardness", "0.01", "--size-effect"],
                           "--size-effect applies only to the rough-surface model with a physical contact"),
                          (["--model", "cos", "--law", "jackson-green", "--hardness", "0.01"],
                           "apply to the rough-surface model gw"),
                          (["--law", "jackson-green", "--hardness", "hard"], "--hardness: expected a number")):
        code, out, err = run(capsys, "fit", str(path), *extra)
        assert out == "" and one_line_error(code, err, needle), (extra, err)


@pytest.mark.parametrize("argv, needle", [
    (["--fix", "E_star_Pa=50GPa,R_m=0"], "fix R_m = 0 is outside its valid range (tip (sphere) radius; 0 < R_m < inf)"),
    (["--fix", "E_star_Pa=50GPa,R_m=-20nm"], "fix R_m = -2e-08 is outside its valid range"),
    (["--R", "0nm", "--E", "50GPa", "--nu", "0.3"], "R_m = 0 is outside its valid range"),
    (["--fix", "E_star_Pa=50GPa,R_m=20nm", "--start", "w_J_m2=-1"], "start w_J_m2 = -1 is outside its valid range"),
])
def test_a_held_value_outside_its_range_is_named_before_the_starts_use_it(capsys, afm, argv, needle):
    """Found by a review: R = 0 raised ZeroDivisionError (a traceback, status 1) in the data-driven
    start of w, and a negative R was reported as a negative w."""
    code, _, err = run(capsys, "fit", str(afm), "--model", "jkr", *argv)
    assert one_line_error(code, err, needle), err
    with pytest.raises(ValueError, match="R_m = 0 is outside its valid range"):
        fit.fit_friction_load(fit.read_data(str(afm)), "jkr", fix={"E_star_Pa": 5e10, "R_m": 0.0})


@pytest.fixture
def mu_file(tmp_path):
    P = np.geomspace(1.0, 1e4, 12)
    mu = asperity.Model(alpha=0.01, beta=1000.0, gamma=1e-3).load_curve(P).mu
    return write(tmp_path / "mu.csv", "P,mu", zip(P, mu, strict=True))


@pytest.mark.parametrize("argv, needle", [
    (["--vary", "alpha", "--fix", "beta=1000", "--nu", "0.2"], "--nu: without a body"),
    (["--vary", "alpha", "--fix", "beta=1000", "--tau-f1", "0.03"], "--tau-f1: applies only to the rough-surface"),
    (["--vary", "alpha", "--fix", "beta=1000,beta=2000"], "--fix: beta is given twice"),
    (["--vary", "alpha", "--start", "alpha=0.02,alpha=0.03", "--fix", "beta=1000"], "--start: alpha is given twice"),
    (["--vary", "alpha,gamma", "--fix", "beta=1e200"], "fix beta: 1e+200 is beyond +-1e+150"),
])
def test_options_the_fit_would_ignore_or_overflow_on_are_refused(capsys, mu_file, argv, needle):
    """Found by a review: --nu and --tau-f1 were accepted and ignored by the dimensionless fit,
    the last of two --fix values was used, and fix beta=1e200 ended in lmfit's OverflowError."""
    code, _, err = run(capsys, "fit", str(mu_file), *argv)
    assert one_line_error(code, err, needle), err


@pytest.mark.parametrize("extra, needle", [
    (["--tau", "50MPa"], "--tau: applies only"), (["--b", "1nm"], "--b: applies only"),
    (["--h", "5nm"], "--h: applies only"), (["--no-adhesion"], "--no-adhesion: applies only"),
    (["--fix", "R_m=20nm"], "--R and --fix R_m=... set the same parameter"),
    (["--w", "0.1J/m^2", "--fix", "w_J_m2=0.2J/m^2"], "--w and --fix w_J_m2=... set the same parameter"),
])
def test_a_law_fit_refuses_options_it_would_ignore(capsys, afm, extra, needle):
    code, _, err = run(capsys, "fit", str(afm), "--model", "md", "--material", "Au", "--R", "20nm", *extra)
    assert one_line_error(code, err, needle), err


def test_an_open_lower_bound_of_a_log_parameter_is_its_natural_one(capsys, mu_file):
    code, out, err = run(capsys, "fit", str(mu_file), "--vary", "alpha,gamma", "--fix", "beta=1000",
                         "--bounds", "gamma=:0.1", "--format", "json")
    assert code == 0, err
    api = fit.fit_friction_load(fit.read_data(str(mu_file)), "gw", vary=["alpha", "gamma"], fix={"beta": 1000.0},
                                bounds={"gamma": (None, 0.1)})
    assert strict_json(out)["parameters"]["gamma"]["value"] == api.values["gamma"]


def test_no_degrees_of_freedom_without_uncertainties_gives_no_standard_error(tmp_path):
    """Found by a review: one point, one free parameter: standard error 0 and a zero-width interval."""
    data = fit.read_data(str(write(tmp_path / "one.csv", "P,mu", [(10.0, 1.2)])))
    res = fit.fit_friction_load(data, "gw", vary=["alpha"], fix={"beta": 1000.0})
    p = res.parameters["alpha"]
    assert p.stderr is None and p.ci95 == (None, None)
    assert any("no degrees of freedom and no stated uncertainties" in w for w in res.warnings)
