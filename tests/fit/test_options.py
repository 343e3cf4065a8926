"""Options of the fits: vary, fix, start, bounds, expr, weights, and every refusal."""

import math

import numpy as np
import pytest

from asperity import jkr
from asperity.fit import (
    compare_models,
    fit_force_separation,
    fit_friction_load,
    fit_joint,
    force_separation_data,
    friction_load_data,
    get_model,
)
from asperity.materials import material

P = np.linspace(0.5, 5.0, 10)
LINE = friction_load_data(P, 0.3 * (P + 1.0))


def test_vary_fix_start_bounds_expr():
    res = fit_friction_load(LINE, "amontons", vary=["mu0"], fix={"P0": 1.0}, weights="none")
    assert res.parameters["P0"].vary is False and res.parameters["P0"].method == "fixed"
    assert res.values["mu0"] == pytest.approx(0.3, rel=1e-9) and res.n_free == 1
    res = fit_friction_load(LINE, "amontons", bounds={"P0": (None, 0.5)}, start={"P0": 0.2}, ci="wald")
    assert res.values["P0"] == pytest.approx(0.5, rel=1e-6) and "at its upper bound" in res.parameters["P0"].note
    res = fit_friction_load(LINE, "amontons", expr={"P0": "mu0 * 10 / 3"}, weights="none")
    assert res.values["P0"] == pytest.approx(res.values["mu0"] * 10 / 3) and res.parameters["P0"].method == "expr"


def test_expression_between_log_scaled_parameters():
    import asperity

    Pg = np.geomspace(1.0, 1e3, 15)
    data = friction_load_data(Pg, asperity.load_curve(Pg, 0.01, 1000.0, 1e-3,
                                                      friction=asperity.HurtadoKim(0.02, 0.02)).F)
    res = fit_friction_load(data, "gw", vary=["tau_f1"], fix={"alpha": 0.01, "beta": 1000.0, "gamma": 1e-3},
                            expr={"tau_f2": "tau_f1"}, start={"tau_f1": 0.01}, ci="wald")
    assert res.values["tau_f1"] == pytest.approx(0.02, rel=1e-6) and res.values["tau_f2"] == res.values["tau_f1"]


@pytest.mark.parametrize("kwargs, match", [
    ({"vary": ["mu0"], "fix": {"mu0": 0.3}}, "'mu0' is both fixed and varied"),
    ({"fix": {"nope": 1.0}}, "fix: unknown parameter 'nope'; the parameters are mu0, P0"),
    ({"vary": ["zeta"]}, "vary: unknown parameter 'zeta'"),
    ({"bounds": {"P0": (2.0, 3.0)}, "start": {"P0": 1.0}}, r"the bounds of P0 \[2, 3\] exclude its start value 1"),
    ({"bounds": {"P0": (3.0, 2.0)}}, "need lo < hi"),
    ({"bounds": {"P0": 3.0}}, r"expected \(lo, hi\)"),
    ({"bounds": {"mu0": (-1.0, 2.0)}}, "lower bound must be >= 0 .*fitted in log10"),
    ({"start": {"mu0": -0.1}}, "outside its valid range"),
    ({"fix": {"P0": "x"}}, "fix P0: expected a number"),
    ({"fix": {"P0": float("nan")}}, "expected a finite number"),
    ({"vary": []}, "no parameter varies"),
    ({"weights": "column"}, "needs an uncertainty column"),
    ({"weights": "squared"}, "weights must be one of"),
    ({"loss": "cauchy"}, "loss must be one of"),
    ({"ci": "bootstrap"}, "ci must be one of"),
    ({"restarts": "sometimes"}, "restarts must be one of auto, always, never"),
])
def test_refused_options(kwargs, match):
    with pytest.raises(ValueError, match=match):
        fit_friction_load(LINE, "amontons", **kwargs)


def test_refused_models_and_data():
    with pytest.raises(ValueError, match="unknown model 'wgw'; valid: gw, hertz"):
        fit_friction_load(LINE, "wgw")
    with pytest.raises(ValueError, match="model 'jkr' works in SI units"):
        fit_friction_load(LINE, "jkr")
    with pytest.raises(ValueError, match="model 'cos' cannot fit force data"):
        fit_force_separation(force_separation_data([0.0, 1.0], [1.0, 0.0]), "cos")
    with pytest.raises(ValueError, match="model 'gw' on physical data needs a contact"):
        fit_friction_load(friction_load_data(P, P, physical=True), "gw")
    with pytest.raises(ValueError, match="expected friction-load data, got force-separation"):
        fit_friction_load(force_separation_data([0.0, 1.0], [1.0, 0.0]))
    with pytest.raises(ValueError, match="data must be a Dataset or the path"):
        fit_friction_load([1, 2, 3])
    with pytest.raises(ValueError, match=r"1 data point cannot fix 2 free parameters \(mu0, P0\)"):
        fit_friction_load(friction_load_data([1.0], [0.3]), "amontons")
    with pytest.raises(ValueError, match="parameter 'R_m' .* has no value"):
        fit_friction_load(friction_load_data(P * 1e-9, P * 1e-9, physical=True), "jkr", fix={"E_star_Pa": 1e11})
    with pytest.raises(ValueError, match="relative' needs nonzero data"):
        fit_friction_load(friction_load_data([1.0, 2.0, 3.0], [0.0, 1.0, 2.0]), "amontons", weights="relative")


def test_weights_auto():
    assert fit_friction_load(LINE, "amontons").weights == ("relative",)
    d = np.linspace(0.0, 2.0, 6)
    sep = force_separation_data(-d * 1e-9, 4 / 3 * 1e11 * math.sqrt(2e-8) * (d * 1e-9) ** 1.5, physical=True)
    res = fit_force_separation(sep, "hertz", vary=["R_m"], fix={"E_star_Pa": 1e11}, start={"R_m": 1e-8})
    assert res.weights == ("none",) and res.values["R_m"] == pytest.approx(2e-8, rel=1e-8)


def test_joint_names_copies_and_shares():
    a = friction_load_data(P, 0.3 * (P + 1.0), name="a")
    b = friction_load_data(P, 0.3 * (P + 2.0), name="b")
    res = fit_joint([a, b], "amontons", shared=["mu0"], weights="none")
    assert set(res.parameters) == {"mu0", "P0_1", "P0_2"} and len(res.curves) == 2 and res.n_points == 20
    res = fit_joint([a, b], ["amontons", "cos"], shared=[], fix={"P0": 1.5}, weights="none")
    assert res.model == "amontons+cos" and res.parameters["P0_1"].value == 1.5
    with pytest.raises(ValueError, match="shared: unknown parameter"):
        fit_joint([a, b], "amontons", shared=["nope"])
    with pytest.raises(ValueError, match="one model .* for all 2 data sets or one per data set"):
        fit_joint([a, b], ["amontons"])
    with pytest.raises(ValueError, match="non-empty list"):
        fit_joint(a, "amontons")


def test_compare_options_and_refusals():
    table = compare_models(LINE, ["amontons", "cos"], fix={"P0": 1.0}, weights="none")
    assert {r.model for r in table.results} == {"amontons", "cos"}
    amontons = next(r for r in table.results if r.model == "amontons")
    assert amontons.parameters["P0"].vary is False
    with pytest.raises(ValueError, match="fix: unknown parameter 'w_J_m2'"):
        compare_models(LINE, ["amontons", "cos"], fix={"w_J_m2": 1.0})
    with pytest.raises(ValueError, match="^models must be a non-empty list of distinct models, got 'cos' more than "
                                         "once$"):
        compare_models(LINE, ["cos", "COS"])
    from asperity.fit.gw import GWFit
    from asperity.heights import parse_heights

    gw = GWFit(heights=parse_heights("weibull:skew=0.5"))
    with pytest.raises(ValueError, match=r"^models .* got 'gw \(heights weibull:skew=0\.5\)' more than once$"):
        compare_models(LINE, [gw, gw])   # named by the model's name, not its repr
    with pytest.raises(ValueError, match="got 'gw' more than once"):
        compare_models(LINE, ["gw", GWFit()])


@pytest.mark.parametrize("model", ["amontons", "cos", "gw", "GW"])
def test_a_material_for_a_model_without_one_is_refused(model):
    """material= is refused, never ignored, by the models that take none (found by a review:
    `asperity fit --material` on dimensionless data was silently ignored)."""
    from asperity.fit.gw import GWFit

    with pytest.raises(ValueError, match=f"^material: model '{model.lower()}' takes no material; only the single-"):
        fit_friction_load(LINE, model, material="Au")
    with pytest.raises(ValueError, match="^material: model 'gw' takes no material"):
        fit_friction_load(LINE, GWFit(), material="Au")
    with pytest.raises(ValueError, match="^material: models 'cos', 'amontons' take no material"):
        compare_models(LINE, ["cos", "amontons"], material="Si")


def test_compare_passes_the_material_to_the_laws_only():
    """In a comparison of laws and empirical forms the material goes to the laws; the
    empirical forms are fitted as without it."""
    P = np.linspace(1e-9, 5e-8, 20)
    F = 1e9 * np.pi * jkr.jkr_contact_radius(P, R=20e-9, w=0.2, E_star=material("Si").E_star) ** 2
    data = friction_load_data(P, F, physical=True)
    table = compare_models(data, ["jkr", "cos"], material="Si", fix={"R_m": 20e-9}, ci="wald")
    got = {r.model: r for r in table.results}
    alone = fit_friction_load(data, "cos", ci="wald")
    assert got["cos"].values == alone.values
    assert got["jkr"].values["E_star_Pa"] == material("Si").E_star
    with pytest.raises(ValueError, match="unknown model"):
        compare_models(LINE, ["cos", "nope"])


def test_compare_ranks_plastic_models_of_different_hardness():
    """Two Jackson-Green models that differ only in their held hardness have different
    names, so one comparison ranks them: the one holding the generating H/E* first, its
    chi-square that of its own fit."""
    from asperity import Model
    from asperity.elastic_plastic import JacksonGreen
    from asperity.fit.gw import GWFit

    P = np.geomspace(1.0, 1e4, 25)
    F = Model(0.05, 1000.0, law=JacksonGreen(0.004)).load_curve(P).F
    F = F * (1 + 0.01 * np.random.default_rng(5).standard_normal(P.size))
    data = friction_load_data(P, F)
    true, wrong = GWFit(law=JacksonGreen(0.004)), GWFit(law=JacksonGreen(0.04))
    assert true.name != wrong.name
    table = compare_models(data, [wrong, true], vary=["alpha", "beta"], ci="wald")
    assert [r.model for r in table.results] == [true.name, wrong.name]
    alone = fit_friction_load(data, GWFit(law=JacksonGreen(0.004)), vary=["alpha", "beta"], ci="wald")
    assert table.best.chisqr == pytest.approx(alone.chisqr, rel=1e-12)
    with pytest.raises(ValueError, match="more than once"):
        compare_models(data, [GWFit(law=JacksonGreen(0.004)), true])


def test_get_model_registry():
    assert get_model("JKR").name == "jkr"
    m = get_model("gw")
    assert get_model(m) is m


def test_option_types_are_named_errors():
    """Options of a wrong type are errors naming the option (found by tests/test_fuzz_api.py)."""
    from asperity.fit import compare_models, fit_friction_load, fit_joint
    from asperity.fit.data import friction_load_data

    P = np.linspace(0.5, 5.0, 8)
    data = friction_load_data(P, 0.3 * (P + 1.0))
    for kwargs, error, needle in (({"vary": True}, TypeError, "^vary must be"), ({"fix": ["mu0"]}, TypeError, "^fix"),
                                  ({"grid": None}, TypeError, "^grid"), ({"grid": -1}, ValueError, "^grid"),
                                  ({"weights": None}, ValueError, "^weights"), ({"ci": 1}, ValueError, "^ci"),
                                  ({"units": True}, TypeError, "^units")):
        with pytest.raises(error, match=needle):
            fit_friction_load(data, "amontons", **kwargs)
    with pytest.raises(TypeError, match="^vary"):
        compare_models(data, ["amontons", "cos"], vary=0.0)
    with pytest.raises(TypeError, match="^models"):
        compare_models(data, None)
    with pytest.raises(TypeError, match="^shared"):
        fit_joint([data, data], "amontons", shared=True)
    with pytest.raises(ValueError, match="^datasets"):
        fit_joint(None, "amontons")
    assert fit_friction_load(data, "amontons", vary="mu0", fix={"P0": 1.0}).parameters["mu0"].value == \
        pytest.approx(0.3, rel=1e-6)  # one name is a list of one


def test_a_contact_for_a_model_without_one_is_refused():
    """Found by a review: contact= was silently ignored by cos, amontons and the laws."""
    from asperity.physical import PhysicalContact
    from asperity.surface import Surface

    contact = PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6), adhesion=False)
    for model in ("cos", "amontons", "jkr"):
        with pytest.raises(ValueError, match=f"^contact: model '{model}' takes no contact; only the rough-surface"):
            get_model(model, contact=contact)
    with pytest.raises(ValueError, match="^contact: models 'cos', 'amontons' take no contact"):
        compare_models(LINE, ["cos", "amontons"], contact=contact)


def test_a_law_object_and_material_are_given_once():
    """Found by a review: JKRFit(material='Au') with material='Si' silently used gold."""
    from asperity.fit.laws import JKRFit

    with pytest.raises(ValueError, match="^material: model 'jkr' was built with material 'Au'; give the material once"):
        get_model(JKRFit(material="Au"), material="Si")
    assert get_model(JKRFit(), material="Si").material == material("Si")
    assert get_model(JKRFit(material="Si"), material="Si").material == material("Si")


def test_an_unknown_model_is_named_before_the_material():
    with pytest.raises(ValueError, match="^unknown model 'jkrr'; valid:"):
        compare_models(LINE, ["jkrr", "cos"], material="Si")


def test_gw_objects_with_a_contact_a_material_or_pull_off_data():
    """Found by a review: GWFit() given contact= was refused with a wrong message, GWFit(material=)
    was ignored, and the Jackson-Green law 'fitted' pull-off data with a model of zero force."""
    from asperity.elastic_plastic import JacksonGreen
    from asperity.fit import fit_pull_off, pull_off_data
    from asperity.fit.gw import GWFit
    from asperity.heights import Weibull
    from asperity.physical import PhysicalContact
    from asperity.surface import Surface

    contact = PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6), adhesion=False)
    plain = get_model(GWFit(), contact=contact)
    assert plain.contact is contact and type(plain) is GWFit
    with pytest.raises(ValueError, match="has its own summit heights or law, but a physical fit takes those of its"):
        get_model(GWFit(heights=Weibull(skew=0.5)), contact=contact)
    with pytest.raises(ValueError, match="^material: model 'gw' takes no material"):
        GWFit(material="Au")
    data = pull_off_data([1.0, 2.0, 3.0], conditions={"beta": [100.0, 200.0, 300.0]})
    with pytest.raises(ValueError, match="the Jackson-Green law has no adhesion, hence no pull-off force"):
        fit_pull_off(data, GWFit(law=JacksonGreen(0.01)))


def test_a_log_parameter_varied_from_zero_says_what_to_give():
    from asperity.elastic_plastic import JacksonGreen
    from asperity.fit.gw import GWFit

    P = np.geomspace(1.0, 1e3, 10)
    data = friction_load_data(P, 0.01 * P)
    with pytest.raises(ValueError, match="^parameter 'h_star_over_sigma' = 0 cannot be varied from there: it is fitted "
                                         "in log10, so its start must be > 0"):
        fit_friction_load(data, GWFit(law=JacksonGreen(0.01)), vary=["alpha", "h_star_over_sigma"])


def test_a_model_outside_its_domain_at_the_start_names_the_held_values():
    """A hardness held so low that the plastic model cannot be evaluated anywhere near the
    start: the error says the start (held values) is the cause, names the held parameters
    and keeps the library's reason; a fit that ends outside the domain from a valid start
    would instead ask for better starts."""
    from asperity import Model
    from asperity.elastic_plastic import JacksonGreen
    from asperity.fit.gw import GWFit

    P = np.geomspace(1.0, 1e4, 20)
    data = friction_load_data(P, Model(0.05, 1000.0, law=JacksonGreen(0.004)).load_curve(P).F)
    with pytest.raises(ValueError, match=r"cannot be evaluated at the start values \(H_over_E = 1e-09.*"
                                         r"change the held values \(H_over_E, .*\) or the start values$"):
        fit_friction_load(data, GWFit(law=JacksonGreen(1e-9)), ci="wald")


def test_zero_data_under_auto_weights_and_all_zero_data_are_refused():
    """Found by a review: a zero friction under the default (relative) weights gave a
    chi-square of 1e200 and 'undetermined' parameters with status 0; all-zero data too."""
    P = np.array([0.0, 10.0, 20.0, 30.0, 40.0])
    data = friction_load_data(P, np.array([0.0, 2.1, 4.2, 5.9, 8.1]))
    with pytest.raises(ValueError, match=r"weights='auto' weighs by 1/\|value\| .* = 0 at row 1; give an "
                                         r"uncertainty column or use weights='none'"):
        fit_friction_load(data, "amontons")
    ok = fit_friction_load(data, "amontons", weights="none", ci="wald")
    assert ok.values["mu0"] == pytest.approx(0.2, abs=0.01)
    with pytest.raises(ValueError, match="every F is 0: there is nothing to fit|every .* is 0"):
        fit_friction_load(friction_load_data(P[1:], np.zeros(4)), "cos", weights="none")


def test_maugis_dugdale_on_pull_off_data_with_a_radius_per_row():
    """Found by a review: KeyError 'R_m' (a traceback on the command line) from the derived
    lambda, which has no single value when each row has its own tip radius."""
    from asperity.fit import fit_pull_off, pull_off_data
    from asperity.maugis_dugdale_load import md_pull_off_force

    si = material("Si")
    R = np.array([10e-9, 20e-9, 40e-9, 80e-9])
    F = np.array([md_pull_off_force(R=r, w=0.1, E_star=si.E_star, lam=2.0) for r in R])
    data = pull_off_data(F, conditions={"R_m": R}, physical=True)
    res = fit_pull_off(data, "md", material="Si", ci="wald")
    assert "lam" not in res.derived and res.values["w_J_m2"] > 0


@pytest.mark.parametrize("ci", ["wald", "profile"])
def test_nano_scaled_parameters_report_in_si_units(ci):
    """The offset P0_N (newtons) is fitted in nanonewtons inside the engine; its value, standard
    error and 95 % interval must be those of the same data fitted dimensionlessly (P0 in the
    model's own unit, not scaled), times 1e-9 (a review: removing either conversion went
    unnoticed by the other tests)."""
    rng = np.random.default_rng(8)
    P = np.linspace(1.0, 50.0, 15)
    F = 0.3 * (P + 4.0) * (1 + 0.02 * rng.standard_normal(P.size))
    plain = fit_friction_load(friction_load_data(P, F), "amontons", ci=ci)
    si = fit_friction_load(friction_load_data(P * 1e-9, F * 1e-9, physical=True), "amontons", ci=ci)
    a, b = plain.parameters["P0"], si.parameters["P0_N"]
    assert b.value == pytest.approx(a.value * 1e-9, rel=1e-6)
    assert b.stderr == pytest.approx(a.stderr * 1e-9, rel=1e-4)
    np.testing.assert_allclose(b.ci95, np.array(a.ci95) * 1e-9, rtol=1e-4)
    assert si.parameters["mu0"].ci95 == pytest.approx(plain.parameters["mu0"].ci95, rel=1e-4)


def test_a_value_at_a_bound_is_the_bound():
    """A review: a parameter at its bound printed one ulp inside it (lmfit's sin() map of a
    bounded parameter): 2.9999999999999996e-09 for 3e-09."""
    P = np.linspace(1, 50, 15) * 1e-9
    for hi in (3e-9, 3.3e-9, 7e-10):
        res = fit_friction_load(friction_load_data(P, 0.3 * (P + 4e-9), physical=True), "amontons",
                                bounds={"P0_N": (0, hi)}, start={"P0_N": hi / 2}, ci="wald")
        assert res.values["P0_N"] == hi and res.parameters["P0_N"].note == "at its upper bound"
    # a log-scaled parameter: 10**log10(0.2) is 0.20000000000000004, outside the bound (a second review)
    P = np.linspace(1.0, 50.0, 15)
    for bounds, value in (((0.1, 0.2), 0.2), ((0.31, 0.5), 0.31)):
        res = fit_friction_load(friction_load_data(P, 0.3 * (P + 4.0)), "amontons", bounds={"mu0": bounds})
        assert res.values["mu0"] == value and res.parameters["mu0"].value == value


@pytest.mark.parametrize("bounds, inside", [((0.0, 0.25), (0.0, 0.25)), ((0.5, None), (0.5, np.inf)),
                                            ((0.31, 0.4), (0.31, 0.4))])
def test_a_default_start_outside_the_bounds_is_moved_inside(bounds, inside):
    """Bounds without a start used to be refused when the model's default start (mu0 = 0.3)
    lay outside them; the start was ours, so it is moved inside and the fit runs."""
    P = np.linspace(1.0, 50.0, 15)
    res = fit_friction_load(friction_load_data(P, 0.3 * (P + 4.0)), "amontons", bounds={"mu0": bounds}, ci="wald")
    assert inside[0] <= res.values["mu0"] <= inside[1] and res.success
    with pytest.raises(ValueError, match="exclude its start value 0.3"):
        fit_friction_load(friction_load_data(P, 0.3 * (P + 4.0)), "amontons", bounds={"mu0": (0.5, 1.0)},
                          start={"mu0": 0.3})


def test_an_expression_may_name_a_scaled_parameter_defined_after_it():
    """A review: 'mu0 = P0_N * k' raised NameError (P0_N was defined after the expression)."""
    P = np.linspace(1, 50, 15) * 1e-9
    res = fit_friction_load(friction_load_data(P, 0.3 * (P + 4e-9), physical=True), "amontons",
                            expr={"mu0": "P0_N*7.5e7"}, ci="wald")
    assert res.values["P0_N"] == pytest.approx(4e-9, rel=1e-9) and res.values["mu0"] == pytest.approx(0.3, rel=1e-9)


def test_null_directions_of_a_tall_jacobian_need_no_square_matrix():
    """A review: the SVD asked for the (points x points) matrix, 7 TiB for a million rows (a
    MemoryError traceback); 300000 rows would need 720 GB that way."""
    from asperity.fit.uncertainty import null_directions

    x = np.linspace(1.0, 2.0, 300_000)
    jac = np.c_[x, 2.0 * x, np.ones_like(x)]  # the first two columns are dependent
    (names, weights), = null_directions(jac, ["a", "b", "c"])
    assert names == ["a", "b"] and abs(weights[0] / weights[1]) == pytest.approx(2.0, rel=1e-9)


@pytest.mark.parametrize("rows", ["0,0\n0,0\n0,0\n0,0\n", "1,0\n2,0\n3,0\n4,0\n"])
def test_all_zero_friction_is_refused_before_any_start(tmp_path, rows):
    """A review: Amontons' start divided by a zero slope (ZeroDivisionError; a RuntimeWarning and
    a misleading message about mu0 with nonzero loads)."""
    import warnings

    path = tmp_path / "zeros.csv"
    path.write_text("load [nN],friction [nN]\n" + rows)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(ValueError, match="every F_N is 0: there is nothing to fit"):
            fit_friction_load(str(path), "amontons")


def test_a_held_parameter_without_a_value_is_refused_not_filled_from_the_data(tmp_path):
    """A user trial: vary=['w_J_m2'] on JKR friction data held tau at a start the fit had made
    from the data (6.75e7 Pa for 5e7), and w came out 0.026 for 0.05, unnoted.  A held
    parameter is the user's to give."""
    from asperity.fit import friction_load_data

    P = np.linspace(-5e-9, 5e-8, 12)
    data = friction_load_data(P, 5e7 * np.pi * 1e-16 * (1 + P / 1e-7), physical=True)
    with pytest.raises(ValueError, match=r"parameter 'tau_Pa' \(.*\) is held \(not in vary\) and has no value: "
                                         r"give it \(fix tau_Pa=\.\.\.\) or vary it too"):
        fit_friction_load(data, "jkr", material="Si", fix={"R_m": 2e-8}, vary=["w_J_m2"])
    r = fit_friction_load(data, "jkr", material="Si", fix={"R_m": 2e-8, "tau_Pa": 5e7}, vary=["w_J_m2"], ci="wald")
    assert r.values["tau_Pa"] == 5e7
