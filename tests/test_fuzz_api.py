"""Property-based fuzzing of the public API: bad values get a ValueError or TypeError naming the parameter.

Every public callable is enumerated from the ``__all__`` of every public module (plus the
methods users call, :data:`METHODS`), so a function added later is fuzzed too: it needs
an entry in :data:`VALID` (one valid call) or a reason in :data:`SKIP`, or
:func:`test_every_public_callable_is_fuzzed` fails and says so.

For each callable, hypothesis replaces one parameter of its valid call by a value of a
wrong type or out of range (None, booleans, complex numbers, strings, bytes, dicts, ragged
or 2-D lists, masked arrays, dates, objects, directories, NaN, infinity, huge and negative
numbers, arbitrary floats and integers) and asserts the contract:

* either a :class:`ValueError` or :class:`TypeError` whose message names the parameter,
* or a finite result (NaN only where documented: mu and pressure without load, the
  separation of a pull-off that does not exist), and a 2-D value where a curve wants a
  1-D one is an error;
* never another exception (AttributeError, IndexError, a raw NumPy or pint error) and
  never a warning (pytest turns warnings into errors).

Four examples per callable by default (about 800 calls, well under a minute), the same on
every run (derandomized: ``ASPERITY_FUZZ_RANDOM=1`` draws new ones);
``ASPERITY_FUZZ_EXAMPLES=N`` draws N, and ``ASPERITY_FUZZ_EXHAUSTIVE=1`` tries every
(callable, parameter, listed bad value) combination once (about 4000 calls): slower, for
checking a change by hand.
"""

from __future__ import annotations

import dataclasses
import datetime
import functools
import importlib
import inspect
import math
import os
import pkgutil
import re
import tempfile

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import asperity
from asperity import AsperityWarning

from . import fuzz_examples

#: Public modules whose ``__all__`` callables are fuzzed.  ``cli`` has its own fuzz suite
#: (tests/cli/test_fuzz_cli.py); ``reference`` is the test oracle, not the user's API.
EXCLUDED_PACKAGES = ("asperity.cli", "asperity.reference")


def public_modules() -> list[str]:
    names = ["asperity"]
    for info in pkgutil.walk_packages(asperity.__path__, "asperity."):
        if not any(part.startswith("_") for part in info.name.split(".")[1:]) and \
                not info.name.startswith(EXCLUDED_PACKAGES):
            names.append(info.name)
    return names


def public_callables() -> dict[str, object]:
    """'module.name' -> callable, for every callable in a public module's ``__all__`` defined there."""
    found = {}
    for module_name in public_modules():
        module = importlib.import_module(module_name)
        for name in getattr(module, "__all__", []):
            obj = getattr(module, name)
            if callable(obj) and getattr(obj, "__module__", None) == module_name:
                found[f"{module_name}.{name}"] = obj
    return found


# -- valid calls ----------------------------------------------------------------------------------

@functools.cache
def _params():
    from asperity.asperity_law import ModelParameters

    return ModelParameters(0.01, 1000.0, 1e-3)


@functools.cache
def _tab():
    from asperity.tabulation import Tabulation

    return Tabulation(_params(), -3.0, 6.0)


@functools.cache
def _branch():
    from asperity.load_control import force_grid

    return force_grid(_tab(), 0.0, 4.0)  # increasing separations, decreasing force


@functools.cache
def _surface():
    from asperity.surface import Surface

    return Surface(2e-9, 1e-6, 1e12, 1e-6)


@functools.cache
def _topography():
    from asperity.topography.summits import prepare

    pytest.importorskip("SurfaceTopography")
    from SurfaceTopography.Generation import fourier_synthesis

    topo = fourier_synthesis((48, 48), (2e-6, 2e-6), 0.8, rms_height=5e-9, short_cutoff=0.2e-6, long_cutoff=1e-6,
                             rng=np.random.default_rng(5))
    return topo, prepare(topo)


@functools.cache
def _scan_file(tmp: str) -> str:
    topo, _ = _topography()
    path = os.path.join(tmp, "scan.npy")
    np.save(path, topo.heights() * 1e9)
    return path


@functools.cache
def _analysis():
    from asperity.topography import analyse_surface

    return analyse_surface(_topography()[0])


MODEL = {"alpha": 0.01, "beta": 1000.0, "gamma": 1e-3}


def _valid_table(tmp: str) -> dict[str, callable]:
    """'callable' -> function returning the keyword arguments of one valid call (built lazily)."""
    a = np.array([0.5, 1.0])
    grid, P, dP = (lambda: _branch()[0]), (lambda: _branch()[1]), (lambda: _branch()[2])
    table = {
        "asperity.asperity_law.ModelParameters": lambda: dict(MODEL),
        "asperity.asperity_law.AsperityLaw": lambda: {"params": _params()},
        "asperity.asperity_law.check_law": lambda: {"law": None, "params": _params()},
        "asperity.asperity_law.check_parameters": lambda: {"params": _params(), "name": "params"},
        "asperity.bodies.contact_material": lambda: {"material": "Au", "w": 0.1},
        "asperity.curves.Model": lambda: dict(MODEL),
        "asperity.curves.separation_curve": lambda: {"d": [0.5, 1.0], **MODEL},
        "asperity.curves.load_curve": lambda: {"P": [1.0, 10.0], **MODEL},
        "asperity.curves.pull_off": lambda: {"alpha": 0.003, "beta": 1000.0, "gamma": 1e-3},
        "asperity.dmt.dmt_load": lambda: {"A": a},
        "asperity.dmt.dmt_penetration": lambda: {"A": a},
        "asperity.friction_stress.HurtadoKim": lambda: {},
        "asperity.friction_stress.ConstantShear": lambda: {"tau": 0.01},
        "asperity.friction_stress.hk_slope_intercept": lambda: {},
        "asperity.friction_stress.hk_friction_stress": lambda: {"a_bar": [1.0, 100.0]},
        "asperity.friction_stress.hk_friction_force": lambda: {"a_bar": [1.0, 100.0]},
        "asperity.groups.roughness_alpha": lambda: {"sigma": 1e-9, "R": 1e-6},
        "asperity.groups.regime_beta": lambda: {"sigma": 1e-9, "R": 1e-6, "b": 2.5e-10},
        "asperity.groups.adhesion_gamma": lambda: {"w": 1.0, "E_star": 1e11, "b": 2.5e-10},
        "asperity.groups.composite_modulus": lambda: {"E": 1e11, "nu": 0.3},
        "asperity.groups.modulus_ratio": lambda: {"nu": 0.3},
        "asperity.groups.maugis_lambda": lambda: {**MODEL, "h_over_b": 1.0},
        "asperity.groups.penetration_scale": lambda: dict(MODEL),
        "asperity.groups.load_scale": lambda: {**MODEL, "nu": 0.3, "form": "derived"},
        "asperity.groups.radius_scale": lambda: dict(MODEL),
        "asperity.groups.sigma_over_b": lambda: {"alpha": 0.01, "beta": 1000.0},
        "asperity.groups.radius_over_b": lambda: {"alpha": 0.01, "beta": 1000.0},
        "asperity.hertz.hertz_radius": lambda: {"u_bar": [0.1, 1.0], "beta": 1000.0},
        "asperity.hertz.hertz_force": lambda: {"u_bar": [0.1, 1.0], "alpha": 0.01, "beta": 1000.0, "nu": 0.3},
        "asperity.hertz.hertz_load_md": lambda: {"A": a},
        "asperity.hertz.hertz_penetration_md": lambda: {"A": a},
        "asperity.jkr_branch.jkr_load": lambda: {"A": a},
        "asperity.jkr_branch.jkr_penetration": lambda: {"A": a},
        "asperity.jkr_branch.jkr_pull_off": lambda: {"control": "load"},
        "asperity.load_control.start_separation": lambda: {"params": _params(), "P_max": 10.0, "d_hi": 5.0},
        "asperity.load_control.bracket_low": lambda: {"tab": _tab(), "P_max": 10.0, "d_lo": 0.0, "d_hi": 5.0},
        "asperity.load_control.force_grid": lambda: {"tab": _tab(), "d_lo": 0.0, "d_hi": 4.0},
        "asperity.load_control.stable_branch": lambda: {"tab": _tab(), "d_lo": 0.0, "d_hi": 4.0},
        "asperity.branch_inversion.branch_guess": lambda: {"P": [P()[3]], "grid": grid(), "Pg": P(), "dPg": dP()},
        "asperity.branch_inversion.invert_branch": lambda: {"tab": _tab(), "P": [P()[3]], "grid": grid(), "Pg": P(),
                                                        "dPg": dP()},
        "asperity.materials.Material": lambda: {"name": "x", "E": 1e11, "nu": 0.3},
        "asperity.materials.as_material": lambda: {"body": "Au"},
        "asperity.materials.material": lambda: {"name": "Au"},
        "asperity.materials.pair": lambda: {"first": "Au", "second": "Ag", "b": 2.9e-10},
        "asperity.material_table.table_row": lambda: {"name": "Au"},
        "asperity.maugis_dugdale.md_radius": lambda: {"t": a, "lam": 1.0},
        "asperity.maugis_dugdale.md_load": lambda: {"t": a, "lam": 1.0},
        "asperity.maugis_dugdale.md_penetration": lambda: {"t": a, "lam": 1.0},
        "asperity.maugis_dugdale.md_curve": lambda: {"t": a, "lam": 1.0, "derivatives": False},
        "asperity.maugis_dugdale.md_t_of_radius": lambda: {"A": [1.0, 2.0], "lam": 1.0},  # a list: scalar-checked
        "asperity.maugis_dugdale.md_lambda": lambda: {"R": 1e-6, "w": 1.0, "E_star": 1e11, "sigma0": 1e9},
        "asperity.maugis_dugdale_branch.check_lambda": lambda: {"lam": 1.0},
        "asperity.maugis_dugdale_branch.md_branch_end": lambda: {"lam": 1.0},
        "asperity.maugis_dugdale_solve.md_solve": lambda: {"delta": [0.0, 1.0], "lam": 1.0},
        "asperity.maugis_dugdale_branch.md_pull_off": lambda: {"lam": 1.0, "control": "load"},
        "asperity.multi_asperity.contact_fraction": lambda: {"d": [0.5, 1.0], **MODEL},
        "asperity.multi_asperity.normal_force": lambda: {"d": [0.5, 1.0], **MODEL},
        "asperity.multi_asperity.friction_force": lambda: {"d": [0.5, 1.0], **MODEL},
        "asperity.multi_asperity.real_contact_area": lambda: {"d": [0.5, 1.0], **MODEL},
        "asperity.multi_asperity.mean_pressure": lambda: {"P": [1.0], "area": [2.0], "nu": 0.3},
        "asperity.multi_asperity.friction_coefficient": lambda: {"F": [1.0], "P": [2.0]},
        "asperity.physical.PhysicalContact": lambda: {"material": "Au", "surface": _surface()},
        "asperity.groups.work_of_adhesion_from_gamma": lambda: {"gamma": 1e-3, "E_star": 1e11, "b": 2.5e-10},
        "asperity.physical_results.warn_area_fraction": lambda: {"fraction": 0.01},
        "asperity.pull_off_search.find_pull_off": lambda: {"tab": _tab(), "d_lo": -3.0, "d_hi": 5.0},
        "asperity.quadrature.gauss_legendre": lambda: {"n": 8},
        "asperity.quadrature.panel_edges": lambda: {"start": 0.0, "stop": 1.0, "first": 0.1},
        "asperity.quadrature.composite_nodes": lambda: {"edges": [0.0, 0.5, 1.0], "n": 4},
        "asperity.quadrature.chebyshev_basis": lambda: {"n": 8},
        "asperity.quadrature.legendre_to_chebyshev": lambda: {"n": 8},
        "asperity.quantities.quantity": lambda: {"name": "alpha"},
        "asperity.regimes.tabor_parameter": lambda: {"R": 1e-6, "w": 1.0, "E_star": 1e11, "z0": 3e-10},
        "asperity.regimes.maugis_parameter": lambda: {"R": 1e-6, "w": 1.0, "E_star": 1e11, "sigma0": 1e9},
        "asperity.regimes.adhesion_regime": lambda: {"lam": 1.0},
        "asperity.regimes.fuller_tabor_parameter": lambda: {"sigma": 1e-9, "R": 1e-6, "w": 1.0, "E_star": 1e11},
        "asperity.studies.friction.fig3_checks": lambda: {},
        "asperity.studies.friction.fig4_checks": lambda: {},
        "asperity.studies.friction.fig5_checks": lambda: {},
        "asperity.studies.friction.fig6_checks": lambda: {},
        "asperity.studies.pressure.fig9_checks": lambda: {},
        "asperity.studies.separation.fig7_checks": lambda: {},
        "asperity.studies.separation.fig8_checks": lambda: {},
        "asperity.studies.report.reproduce": lambda: {"out_dir": os.path.join(tmp, "paper")},
        "asperity.studies.table1.write_table1_csv": lambda: {"path": os.path.join(tmp, "t1.csv"), "rows": [
            {"alpha": 0.003, "beta": 1000.0, "gamma": 1e-3, "paper": 320.1, "computed": 320.1, "ratio": 1.0}]},
        "asperity.studies.table1.printed_load_scale_factor": lambda: dict(MODEL),
        "asperity.surface.Surface": lambda: {"sigma_s": 2e-9, "R": 1e-6, "eta": 1e12, "area": 1e-6},
        "asperity.surface.surface_from_groups": lambda: {"alpha": 0.01, "beta": 1000.0, "b": 2.5e-10, "eta": 1e12,
                                                         "area": 1e-6},
        "asperity.surface.nayak_summit_sigma": lambda: {"rms": 1e-9, "alpha_n": 10.0},
        "asperity.tabulation.Tabulation": lambda: {"params": _params(), "d_min": 0.0, "d_max": 5.0},
        "asperity.tabulation.check_separation": lambda: {"d": [0.5, 1.0]},
        "asperity.tabulation.check_tabulation": lambda: {"tab": _tab(), "d_lo": 0.0, "d_hi": 1.0},
        "asperity.topography.analysis.analyse_surface": lambda: {"path_or_topography": _topography()[0]},
        "asperity.topography.detected.local_maxima_2d": lambda: {"h": _heights2d()},
        "asperity.topography.detected.local_maxima_1d": lambda: {"h": _heights2d()[0]},
        "asperity.topography.detected.summit_curvatures": lambda: {
            "h": _heights2d(), "peak": _peaks(), "dx": 1e-8, "dy": 1e-8},
        "asperity.topography.detected.detected_summits": lambda: {"topography": _topography()[0]},
        "asperity.topography.read.read_topography": lambda: {"path": _scan_file(tmp), "physical_sizes": ("2um",),
                                                             "unit": "nm"},
        "asperity.topography.spectral.bandwidth_alpha": lambda: {"m0": 1e-18, "m2": 1e-4, "m4": 1e10},
        "asperity.topography.spectral.summit_density": lambda: {"m2": 1e-4, "m4": 1e10},
        "asperity.topography.spectral.summit_radius": lambda: {"m4": 1e10},
        "asperity.topography.spectral.summit_sigma": lambda: {"m0": 1e-18, "alpha_n": 10.0},
        "asperity.topography.spectral.mean_summit_height": lambda: {"m0": 1e-18, "alpha_n": 10.0},
        "asperity.topography.spectral.spectral_summits": lambda: {"topography": _topography()[0]},
        "asperity.topography.summits.prepare": lambda: {"topography": _topography()[0]},
        "asperity.topography.summits.moments": lambda: {"topography": _topography()[1]},
        "asperity.topography.summits.plain": lambda: {"value": 1.0},
        "asperity.units.to_si": lambda: {"value": 1.0, "unit": "m", "name": "x"},
        "asperity.units.parse_quantity": lambda: {"text": "2nm", "unit": "m", "name": "x"},
        "asperity.units.is_quantity": lambda: {"value": 1.0},
        "asperity.units.format_si": lambda: {"value": 1.0, "unit": "m"},
        **fuzz_examples.valid_calls(tmp),
    }
    # Methods users call: 'Class.method' -> (instance factory, valid kwargs).
    for name, (_, kwargs) in _methods(tmp).items():
        table[name] = kwargs
    return table


def _heights2d():
    return np.asarray(_topography()[1].heights(), dtype=float)


def _peaks():
    from asperity.topography.detected import local_maxima_2d

    return local_maxima_2d(_heights2d())


def _methods(tmp: str) -> dict[str, tuple]:
    """'Class.method' -> (factory of the instance, function returning valid kwargs)."""
    from asperity.curves import Model
    from asperity.friction_stress import ConstantShear, HurtadoKim
    from asperity.physical import PhysicalContact
    from asperity.surface import Surface

    model = functools.cache(lambda: Model(**MODEL))
    contact = functools.cache(lambda: PhysicalContact("Au", _surface(), plastic_threshold=1.0))  # no yield note
    return {
        "asperity.curves.Model.load_curve": (model, lambda: {"P": [1.0, 10.0]}),
        "asperity.curves.Model.separation_curve": (model, lambda: {"d": [0.5, 1.0]}),
        "asperity.curves.Model.pull_off": (model, lambda: {"d_max": 5.0}),
        "asperity.curve_result.CurveResult.to_csv": (lambda: model().load_curve([1.0]),
                                               lambda: {"path_or_buffer": os.path.join(tmp, "c.csv")}),
        "asperity.physical.PhysicalContact.load_curve": (contact, lambda: {"P": [1e-3, 1e-2]}),
        "asperity.physical.PhysicalContact.separation_curve": (contact, lambda: {"d": [1e-9, 2e-9]}),
        "asperity.physical.PhysicalContact.pull_off": (contact, lambda: {"d_max": 5.0}),
        "asperity.physical_results.PhysicalCurve.to_csv": (lambda: contact().load_curve([1e-3]),
                                                           lambda: {"path_or_buffer": os.path.join(tmp, "p.csv")}),
        "asperity.surface.Surface.from_rms": (lambda: Surface, lambda: {"rms": 5e-9, "R": 1e-6, "eta": 1e12,
                                                                        "area": 1e-6, "alpha_n": 10.0}),
        "asperity.friction_stress.HurtadoKim.stress": (HurtadoKim, lambda: {"a_bar": [1.0, 100.0]}),
        "asperity.friction_stress.ConstantShear.stress": (ConstantShear, lambda: {"a_bar": [1.0, 100.0]}),
        "asperity.topography.analysis.SurfaceAnalysis.surface": (_analysis, lambda: {"area": 1e-6,
                                                                                      "method": "spectral"}),
        "asperity.topography.summits.SummitParameters.surface": (lambda: _analysis().spectral,
                                                                 lambda: {"area": 1e-6}),
        **fuzz_examples.methods(tmp),
    }


#: Public callables not fuzzed, with the reason.
SKIP = {
    "asperity.asperity_law.ContactLaw": "a Protocol (not instantiated)",
    "asperity.friction_stress.FrictionLaw": "a Protocol (not instantiated)",
    "asperity.physical_results.AreaFractionWarning": "a warning category",
    "asperity.load_control.LoadOutOfRange": "an error class the library raises (its message is tested)",
    "asperity.instrument.UnstableClosestApproach": "an error class the library raises (its message is tested)",
    "asperity.material_table.material_names": "no parameters",
    "asperity.material_table.material_table": "no parameters",
    "asperity.units.unit_registry": "no parameters",
    "asperity.studies.table1.table1_rows": "no parameters",
    **{f"asperity.studies.{m}.fig{n}_data": "no parameters" for m, ns in
       (("friction", (3, 4, 5, 6)), ("separation", (7, 8)), ("pressure", (9,))) for n in ns},
    # Result records: frozen dataclasses the library fills from its own computations.
    **{name: "a result record the library builds" for name in (
        "asperity.curve_result.CurveResult", "asperity.load_control.Branch",
        "asperity.maugis_dugdale_branch.BranchPoint",
        "asperity.physical_results.PhysicalCurve", "asperity.physical_results.PhysicalPullOff",
        "asperity.pull_off_search.PullOff", "asperity.quantities.Quantity", "asperity.studies.figures.FigureSpec",
        "asperity.topography.analysis.SurfaceAnalysis", "asperity.topography.summits.SummitParameters")},
    **fuzz_examples.SKIP,
}

#: Ratios whose result is NaN where undefined and infinite where it overflows, by design (documented):
#: mu = F/P without load (NaN) and under a vanishing load (inf), the pressure without contact.
RATIOS = {"asperity.multi_asperity.friction_coefficient", "asperity.multi_asperity.mean_pressure"}
#: Callables that return (part of) their input unchecked by design: conversions and plain data.
PASS_THROUGH = {"asperity.units.to_si": "converts quantities and strings, passes numbers through",
                "asperity.topography.summits.plain": "turns NumPy scalars into plain data, passes others through",
                "asperity.units.is_quantity": "answers True or False for anything",
                "asperity.instrument.check_stiffness": "passes inf through: displacement control (documented)"}
#: Where a message names the parameter by another word: (callable, parameter) -> the word,
#: or a function of the valid keyword arguments giving it (a label the caller passes).
ALIASES = {
    ("asperity.materials.material", "name"): "material",
    ("asperity.quantities.quantity", "name"): "quantity",
    ("asperity.materials.as_material", "body"): lambda kw: kw.get("name", "body"),
    ("asperity.units.to_si", "value"): lambda kw: kw["name"],
    ("asperity.units.parse_quantity", "text"): lambda kw: kw["name"],
    ("asperity.units.parse_quantity", "unit"): lambda kw: kw["name"],  # '' (dimensionless) is valid: '2nm' is not
    ("asperity.topography.analysis.analyse_surface", "path_or_topography"): "path",
    ("asperity.interaction.as_interaction", "value"): "interaction",
    ("asperity.interaction.interaction_for_surface", "name"): "interaction",
    ("asperity.fit.models.get_model", "name"): "model",
    ("asperity.heights.registry.parse_heights", "spec"): "heights",
    ("asperity.fit.joint.fit_joint", "models"): "model",
    ("asperity.fit.compare.compare_models", "models"): "model",
}

#: Results that may hold NaN: the friction coefficient and mean pressure without load, the
#: separation of a pull-off that does not exist.  mu and pressure may also be infinite: F/P
#: under a vanishing load (documented, tests/test_curves.py).
NAN_OK = {"mu", "pressure", "d", "pull_off", "d_m", "area_fraction", "nominal_area",
          # a cycle's pull-off separation where there is none, its friction at zero load where the force
          # keeps its sign; the approach of a periodic boundary-element cell (documented in their records)
          "d_pull_off", "d_pull_off_m", "friction_zero_load", "friction_zero_load_N", "separation", "sep_bem_m",
          "correlation",  # a fit's correlation where undetermined (asperity.fit.FitResult)
          "ks"}  # a height family that cannot hold the summits (asperity.heights.fit.FitResult, documented)
#: ... and infinite: mu, pressure (above), and a cycle's spring stiffness (inf: displacement control).
#: md_branch_end's t below lambda_c; log-likelihood and AIC of a height family that cannot hold the summits.
INF_OK = {"mu", "pressure", "stiffness", "stiffness_N_m", "t", "log_likelihood", "aic"}


# -- bad values -------------------------------------------------------------------------------------

class _Opaque:
    """An object of no meaning to asperity."""

    def __repr__(self):
        return "<opaque>"


def bad_values(tmp: str) -> list:
    """Values of the wrong type or out of any range, listed (hypothesis adds arbitrary numbers)."""
    return [
        None, True, np.bool_(False), 1 + 2j, np.complex128(1j), "abc", "", b"x", {"a": 1}, [], [[1.0, 2.0], [3.0]],
        np.ones((2, 2)), np.ma.masked_array([1.0, 2.0], mask=[0, 1]), np.array(["a"]), _Opaque(), float("nan"),
        float("inf"), -float("inf"), -1.0, 0.0, 1e300, -1e300, 1e-300, np.datetime64("2020-01-01"),
        datetime.date(2020, 1, 1), [1.0, None], (1.0, "x"), tmp, 10**400 // 10**100, -(2**70), [True, 1.0],
        np.float32(np.nan), [0.3], [0.5, 1.0], np.array([2.0]), (1e-3,), [[0.5]], [1.0, 1.0, 1.0],
    ]


#: Parameters naming a file or directory get path-like bad values only (any string is a name).
PATH_PARAMS = {"path", "out_dir", "path_or_buffer", "path_or_topography"}


def path_bad_values(tmp: str) -> list:
    existing_file = os.path.join(tmp, "a-file")  # an output directory that is a file
    if not os.path.exists(existing_file):
        with open(existing_file, "w") as fh:
            fh.write("x")
    # a bytes path (not UTF-8) inside tmp: accepted as a path or refused by name, never written elsewhere
    return [None, 3.0, True, _Opaque(), {"a": 1}, os.fsencode(tmp) + b"/\xff", tmp, ""]


# -- the contract ---------------------------------------------------------------------------------

def _names_param(message: str, name: str) -> bool:
    return re.search(rf"(?<![A-Za-z0-9_]){re.escape(name)}(?![A-Za-z0-9_])", message) is not None


def _finite(value, path: str = "result", depth: int = 0) -> list[str]:
    """Where ``value`` holds infinity, or NaN outside :data:`NAN_OK`."""
    if depth > 6:
        return []
    key = path.rsplit(".", 1)[-1]
    if isinstance(value, bool | np.bool_ | str | bytes) or value is None:
        return []
    if isinstance(value, complex | np.complexfloating):
        return [f"{path} = {value!r} (complex)"]
    if isinstance(value, int | float | np.number):
        x = float(value) if not isinstance(value, int) else 0.0
        if (math.isinf(x) and key not in INF_OK) or (math.isnan(x) and key not in NAN_OK):
            return [f"{path} = {value!r}"]
        return []
    if isinstance(value, np.ndarray):
        if value.dtype.kind not in "fc":
            return []
        bad = (np.isinf(value) if key not in INF_OK else False) | (np.isnan(value) if key not in NAN_OK else False)
        return [f"{path} holds {value[bad][:3]!r}"] if np.any(bad) else []
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        out = []
        for f in dataclasses.fields(value):
            out += _finite(getattr(value, f.name), f"{path}.{f.name}", depth + 1)
        return out
    if isinstance(value, dict):
        return [m for k, v in value.items() for m in _finite(v, f"{path}.{k}", depth + 1)]
    if isinstance(value, list | tuple):
        return [m for i, v in enumerate(value[:50]) for m in _finite(v, f"{path}", depth + 1)]
    return []


def _is_curve(value) -> bool:
    from asperity.curves import CurveResult
    from asperity.physical import PhysicalCurve

    return isinstance(value, CurveResult | PhysicalCurve)


#: Warnings issued by design for valid inputs: the library's validity notes (every subclass of
#: asperity.AsperityWarning: a real contact area past 10 % of the nominal one, asperities past
#: yield under the elastic law, ...), which the command line prints as 'note:' lines.


def _show(value) -> str:
    import reprlib

    return " ".join(reprlib.repr(value).split())


def check_contract(target: str, func, kwargs: dict, name: str, bad) -> None:
    """Call ``func(**kwargs)`` with ``kwargs[name] = bad`` and assert the contract of the module docstring.

    The call runs in a fresh temporary working directory: a bad value that is a relative
    file name ('abc', a bytes path) writes there, never into the checkout, and cannot be
    read back by a later call.
    """
    with tempfile.TemporaryDirectory() as cwd:
        old = os.getcwd()
        os.chdir(cwd)
        try:
            _check_contract(target, func, kwargs, name, bad)
        finally:
            os.chdir(old)


def _check_contract(target: str, func, kwargs: dict, name: str, bad) -> None:
    call = {**kwargs, name: bad}
    shown = f"{target}({name}={_show(bad)})"
    try:
        result = func(**call)
    except (ValueError, TypeError) as err:
        message = str(err)
        alias = ALIASES.get((target, name), name)
        alias = alias(kwargs) if callable(alias) else alias
        named = _names_param(message, name) or _names_param(message, alias) or (
            name in PATH_PARAMS and isinstance(bad, str) and bad != "" and bad in message)
        assert named, f"{shown} raised {type(err).__name__} without naming {name!r}: {message}"
        return
    except Warning as w:
        if isinstance(w, AsperityWarning):
            return
        raise AssertionError(f"{shown} warned {type(w).__name__}: {w}") from w
    except Exception as err:  # noqa: BLE001 - the point: any other exception is a failure
        raise AssertionError(f"{shown} raised {type(err).__name__}: {err}") from err
    if target in PASS_THROUGH or target in RATIOS:
        return
    problems = _finite(result)
    assert not problems, f"{shown} returned a non-finite result: {problems}"
    if _is_curve(result) and np.ndim(np.asarray(bad, dtype=object)) >= 2:
        raise AssertionError(f"{shown}: a 2-D value where a 1-D one is meant gave a curve")


# -- the tests ------------------------------------------------------------------------------------

#: Examples per test (ASPERITY_FUZZ_EXAMPLES overrides).
#: The same examples on every run (a suite that passes keeps passing); ASPERITY_FUZZ_RANDOM=1 draws new ones.
DERANDOMIZE = not os.environ.get("ASPERITY_FUZZ_RANDOM")
EXAMPLES = int(os.environ.get("ASPERITY_FUZZ_EXAMPLES", 4))


@pytest.fixture(scope="module")
def tmp(tmp_path_factory):
    return str(tmp_path_factory.mktemp("fuzz"))


def _target(tmp: str, target: str):
    """(callable, valid kwargs, parameter names) of a fuzz target."""
    methods = _methods(tmp)
    if target in methods:
        factory, kwargs = methods[target]
        func = getattr(factory(), target.rsplit(".", 1)[-1])
    else:
        func = public_callables()[target]
        kwargs = _valid_table(tmp)[target]
    params = [p.name for p in inspect.signature(func).parameters.values()
              if p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD) and p.name != "self"]
    return func, kwargs, params


def test_every_public_callable_is_fuzzed(tmp):
    table = _valid_table(tmp)
    missing = [name for name in public_callables() if name not in table and name not in SKIP]
    assert not missing, ("add a valid call to VALID (tests/test_fuzz_api.py::_valid_table) or a reason to SKIP "
                         f"for: {missing}")
    stale = [name for name in [*table, *SKIP] if name not in public_callables() and name not in _methods(tmp)]
    assert not stale, f"no longer public: {stale}"


TARGETS = sorted({*_valid_table("/nonexistent")} - {"asperity.studies.report.reproduce"}) + \
    ["asperity.studies.report.reproduce"]


def _marked(target: str):
    """A target, marked as an expected failure (not run: hypothesis would spend its time shrinking) while
    it is in fuzz_examples.KNOWN_GAPS (work left)."""
    gap = fuzz_examples.KNOWN_GAPS.get(target)
    return pytest.param(target, marks=pytest.mark.xfail(reason=gap, run=False)) if gap else target


@pytest.mark.parametrize("target", [_marked(t) for t in TARGETS])
@settings(max_examples=EXAMPLES, deadline=None, derandomize=DERANDOMIZE,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(data=st.data())
def test_bad_values_are_named_errors_or_finite_results(tmp, target, data):
    func, valid, params = _target(tmp, target)
    if not params:
        return
    name = data.draw(st.sampled_from(params), label="parameter")
    values = _bad_for(tmp, name)
    numbers = st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.integers(-10**30, 10**30),
                        st.lists(st.floats(allow_nan=True, allow_infinity=True), max_size=3))
    strategy = st.sampled_from(values) if name in PATH_PARAMS else st.one_of(st.sampled_from(values), numbers)
    bad = data.draw(strategy, label=name)
    default = inspect.signature(func).parameters[name].default
    if _same(bad, default) or _same(bad, valid().get(name, inspect.Parameter.empty)):
        return  # the valid call itself
    check_contract(target, func, valid(), name, bad)


def _bad_for(tmp: str, name: str) -> list:
    if name == "out_dir":  # an existing directory is a valid output directory
        return [v for v in path_bad_values(tmp) if v != tmp] + [os.path.join(tmp, "a-file")]
    return path_bad_values(tmp) if name in PATH_PARAMS else bad_values(tmp)


def _same(a, b) -> bool:
    try:
        return type(a) is type(b) and bool(a == b)
    except (ValueError, TypeError):
        return False


@pytest.mark.skipif(not os.environ.get("ASPERITY_FUZZ_EXHAUSTIVE"), reason="set ASPERITY_FUZZ_EXHAUSTIVE=1")
def test_exhaustive(tmp):
    failures = []
    for target in TARGETS:
        func, valid, params = _target(tmp, target)
        for name in params:
            default = inspect.signature(func).parameters[name].default
            for bad in _bad_for(tmp, name):
                if _same(bad, default) or _same(bad, valid().get(name, inspect.Parameter.empty)):
                    continue
                try:
                    check_contract(target, func, valid(), name, bad)
                except AssertionError as err:
                    failures.append(str(err).splitlines()[0][:300])
    assert not failures, "\n".join(failures)


def test_numpy_values_are_shown_plainly_in_messages():
    """A review: messages showed 'array(1.e-300)', 'np.float64(0.0)' and 'array([nan])'."""
    import asperity
    from asperity.maugis_dugdale_branch import md_branch_end

    for call, needle in [(lambda: md_branch_end(np.float64(1e-300)), "got 1e-300"),
                         (lambda: asperity.Model(np.float64(0.0), 1000.0), "got 0.0"),
                         (lambda: asperity.Model(0.05, 1000.0).load_curve(np.array([np.nan, 1.0])), "got [nan, 1.0]")]:
        with pytest.raises(ValueError) as err:
            call()
        assert needle in str(err.value) and "array(" not in str(err.value) and "np.float64" not in str(err.value)


def test_shapes_that_do_not_broadcast_are_named(tmp):
    """Every pair of numeric parameters of every valid call, given shapes (3,) and (4,): a
    ValueError or TypeError naming one of them (a review found NumPy's bare 'operands could
    not be broadcast' in the Jackson-Green and Nix-Gao functions), never a result."""
    import itertools
    import numbers

    problems = []
    for target in TARGETS:
        if target == "asperity.studies.report.reproduce":
            continue
        func, kwargs, _ = _target(tmp, target)
        kwargs = kwargs()
        nums = [k for k, v in kwargs.items() if isinstance(v, numbers.Real) and not isinstance(v, bool)]
        for a, b in itertools.combinations(nums, 2):
            call = {**kwargs, a: np.full(3, kwargs[a]), b: np.full(4, kwargs[b])}
            try:
                func(**call)
                problems.append(f"{target}({a}: 3, {b}: 4) gave a result")
            except (ValueError, TypeError) as err:
                if a not in str(err) and b not in str(err):
                    problems.append(f"{target}({a}: 3, {b}: 4): {err}")
    assert not problems, "\n".join(problems)


def test_scalar_inputs_give_scalars_not_0d_arrays(tmp):
    """As a ufunc does: a review found 0-d arrays from a third of the functions (md_solve,
    jg_area, ng_*, mu, the moments, ...), NumPy scalars from the rest."""
    import numbers

    validators = ("check_", "jg_check_")
    found = []
    for target in TARGETS:
        if target.endswith("reproduce") or target.rsplit(".", 1)[-1].startswith(validators):
            continue
        func, kwargs, _ = _target(tmp, target)
        kwargs = kwargs()
        scalar = {k: (v[0] if isinstance(v, list) and v and isinstance(v[0], numbers.Real) else v)
                  for k, v in kwargs.items()}
        if scalar == kwargs:
            continue  # no list to make scalar
        try:
            result = func(**scalar)
        except (ValueError, TypeError):
            continue  # a parameter that must be a list
        parts = result if isinstance(result, tuple) else (result,)
        if any(isinstance(p, np.ndarray) and p.ndim == 0 for p in parts):
            found.append(target)
    assert not found, f"0-d arrays from scalar inputs: {found}"
