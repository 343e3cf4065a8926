"""Docstrings: their examples run (doctest), the user-facing functions carry full numpydoc,
and no signature shows an object address (``heights=<... object at 0x...>``)."""

import doctest
import importlib
import inspect
import pkgutil
import re

import pytest

import asperity

#: Modules whose examples must run.
DOCTEST_MODULES = ["asperity.curves", "asperity.groups", "asperity.multi_asperity", "asperity.tabulation",
                   "asperity.load_control",
                   "asperity.branch_inversion",
                   "asperity.pull_off_search", "asperity.asperity_law", "asperity.maugis_dugdale",
                   "asperity._maugis_dugdale_brackets", "asperity.maugis_dugdale_branch",
                   "asperity.maugis_dugdale_solve",
                   "asperity.hertz",
                   "asperity.jkr", "asperity.jkr_branch", "asperity.dmt",
                   "asperity.bodies", "asperity.surface", "asperity.physical",
                   "asperity.physical_description", "asperity.units",
                   "asperity.jackson_green", "asperity.jackson_green_fits", "asperity.jackson_green_hardness",
                   "asperity.nix_gao", "asperity.elastic_plastic", "asperity.jackson_green_law",
                   "asperity.plasticity", "asperity.cycle",
                   "asperity.cycle_run", "asperity.cycle_band", "asperity.instrument", "asperity.physical_cycle",
                   "asperity.sweeps.run",
                   "asperity.maugis_dugdale_load", "asperity.maugis_units", "asperity.cos", "asperity.amontons",
                   "asperity.fit.api", "asperity.fit.joint", "asperity.fit.compare",
                   "asperity.persson", "asperity.icha.field", "asperity.icha.solver", "asperity.icha.summits",
                   "asperity.icha.contact", "asperity.icha.rectangle",
                   "asperity.heights.base", "asperity.heights.gaussian", "asperity.heights.exponential",
                   "asperity.heights.weibull", "asperity.heights.pearson", "asperity.heights.johnson",
                   "asperity.heights.mixture", "asperity.heights.empirical", "asperity.heights.registry",
                   "asperity.heights.fit", "asperity.interaction", "asperity.materials", "asperity.fit.gw",
                   "asperity.validation.spots", "asperity.explorer.labels", "asperity.explorer.state",
                   "asperity.explorer.wording"]

#: Functions users call (README, docs/model.md): each carries the full numpydoc, not a pointer.
FULL_DOCS = {
    "asperity.curves": ["separation_curve", "load_curve", "pull_off"],
    "asperity.multi_asperity": ["contact_fraction", "normal_force", "friction_force", "real_contact_area"],
    "asperity.maugis_dugdale": ["md_radius", "md_load", "md_penetration", "md_curve", "md_t_of_radius"],
    "asperity._maugis_dugdale_brackets": ["md_first_bracket", "md_brackets", "md_radius_from_brackets",
                                          "md_t_of_radius_unchecked"],
    "asperity.maugis_dugdale_branch": ["md_branch_end", "md_pull_off", "for_each_lambda"],
    "asperity.maugis_dugdale_solve": ["md_solve"],
    "asperity.hertz": ["hertz_radius", "hertz_force", "hertz_load_md", "hertz_penetration_md", "hertz_contact_radius",
                       "hertz_normal_force"],
    "asperity.jkr": ["jkr_load", "jkr_penetration", "jkr_pull_off", "jkr_solve_load", "jkr_solve", "jkr_contact_radius",
                     "jkr_normal_force", "jkr_pull_off_force"],
    "asperity.dmt": ["dmt_load", "dmt_penetration", "dmt_solve_load", "dmt_solve", "dmt_contact_radius",
                     "dmt_normal_force", "dmt_pull_off_force"],
    "asperity.maugis_dugdale_load": ["md_solve_load", "md_contact_radius", "md_normal_force", "md_pull_off_force"],
    "asperity.cos": ["cos_contact_radius", "cos_friction", "cos_lambda", "cos_alpha", "cos_pull_off_hat",
                     "cos_radius_hat"],
    "asperity.amontons": ["amontons_friction"],
    "asperity.fit.api": ["fit_friction_load", "fit_force_separation", "fit_pull_off"],
    "asperity.fit.joint": ["fit_joint"],
    "asperity.fit.compare": ["compare_models"],
    "asperity.load_control": ["start_separation", "bracket_low", "force_grid", "stable_branch"],
    "asperity.branch_inversion": ["branch_guess", "invert_branch"],
    "asperity.pull_off_search": ["find_pull_off"],
    "asperity.bodies": ["contact_material"],
    "asperity.surface": ["nayak_summit_sigma"],
    "asperity.units": ["format_si"],
    "asperity.jackson_green": ["jg_yield_coefficient", "jg_critical_interference",
                               "jg_critical_load", "jg_critical_area", "jg_area_exponent", "jg_radius_ratio"],
    "asperity.jackson_green_hardness": ["jg_yield_from_hardness", "jg_hardness_ratio"],
    "asperity.jackson_green_fits": ["jg_area_fit", "jg_area", "jg_load_fit", "jg_load_transition", "jg_load"],
    "asperity.nix_gao": ["ng_hardness", "ng_scaled_interference", "ng_interference", "ng_critical_interference"],
    "asperity.elastic_plastic": ["critical_penetration", "plastic_fraction", "make_law"],
    "asperity.plasticity": ["plasticity_index", "plastic_share"],
    "asperity.cycle": ["cycle", "preload_curve"],
    "asperity.physical_cycle": ["physical_cycle", "physical_preload_curve"],
    "asperity.instrument": ["base_displacement"],
    "asperity.sweeps.run": ["sweep"],
    "asperity.persson": ["persson_area_fraction", "bgt_area_fraction", "rms_slope"],
    "asperity.icha": ["icha_contact", "icha_curve", "map_summits", "merge_spots", "hertz_displacement", "hertz_excess",
                      "boussinesq_rectangle_mean"],
    "asperity.heights": ["parse_heights", "fit_heights"],
}


def test_every_module_with_examples_is_listed():
    """A review found a wrong example (cgp_shift's 9.5779) in a module the list had missed."""
    import pathlib

    root = pathlib.Path(asperity.__file__).parent
    unlisted = []
    for path in sorted(root.rglob("*.py")):
        if ">>>" not in path.read_text(encoding="utf-8"):
            continue
        name = ".".join(("asperity", *path.relative_to(root).with_suffix("").parts)).removesuffix(".__init__")
        if name not in DOCTEST_MODULES:
            finder = doctest.DocTestFinder()
            examples = [e for t in finder.find(importlib.import_module(name)) for e in t.examples]
            if any(not e.options.get(doctest.SKIP) for e in examples):  # examples that would run
                unlisted.append(name)
    assert not unlisted, f"add to DOCTEST_MODULES: {unlisted}"


@pytest.mark.parametrize("name", DOCTEST_MODULES)
def test_examples_run(name):
    module = importlib.import_module(name)
    result = doctest.testmod(module, optionflags=doctest.NORMALIZE_WHITESPACE)
    assert result.attempted > 0 and result.failed == 0, result


@pytest.mark.parametrize("module, name", [(m, f) for m, names in FULL_DOCS.items() for f in names])
def test_full_numpydoc(module, name):
    func = getattr(importlib.import_module(module), name)
    doc = inspect.getdoc(func)
    for section in ("Parameters", "Returns", "Raises", "Examples", "References"):
        if section == "Parameters" and not inspect.signature(func).parameters:
            continue
        assert re.search(rf"^{section}\n-+$", doc, re.M), f"{module}.{name} has no {section} section"
    assert not re.search(r"^\s*See :(meth|func|class):", doc, re.M), f"{module}.{name} points elsewhere"
    params = doc.split("Parameters\n----------\n", 1)[-1].split("\n\n")[0] if "Parameters" in doc else ""
    for p in inspect.signature(func).parameters:
        assert re.search(rf"^(\w+, )*{p}(, \w+)* : \S", params, re.M), f"{module}.{name}: {p!r} is not documented"


def _public_modules():
    names = ["asperity"]
    for info in pkgutil.walk_packages(asperity.__path__, "asperity."):
        if not any(part.startswith("_") for part in info.name.split(".")[1:]):
            names.append(info.name)
    return names


def _callables(module):
    for name in getattr(module, "__all__", []):
        obj = getattr(module, name)
        if callable(obj):
            yield f"{module.__name__}.{name}", obj
            if inspect.isclass(obj):
                for attr, member in vars(obj).items():
                    if callable(member) and not attr.startswith("_"):
                        yield f"{module.__name__}.{name}.{attr}", member


def test_no_object_address_in_any_signature():
    bad, checked = [], 0
    for modname in _public_modules():
        module = importlib.import_module(modname)
        for qualname, obj in _callables(module):
            try:
                sig = str(inspect.signature(obj))
            except (TypeError, ValueError):  # builtins without a signature
                continue
            checked += 1
            if " at 0x" in sig:
                bad.append(f"{qualname}{sig}")
    assert checked > 100
    assert not bad, "\n".join(bad)


def test_heights_repr():
    assert repr(asperity.heights.GAUSSIAN) == "Gaussian()"
    assert "heights=Gaussian()" in str(inspect.signature(asperity.curves.load_curve))


def test_no_control_characters_in_text_files():
    """A docstring held a backspace ('\\b' of '\\big' in a non-raw string, then a raw one
    kept the byte): no source, test or document may hold a control character other than
    tab and newline."""
    import pathlib
    import re

    root = pathlib.Path(__file__).resolve().parents[1]
    bad = re.compile(r"[\x00-\x08\x0b-\x1f\x7f]")
    found = [f"{p.relative_to(root)}:{n}" for pattern in ("src/**/*.py", "tests/**/*.py", "benchmarks/**/*.py",
                                                          "examples/**/*.py", "docs/*.md", "*.md")
             for p in root.glob(pattern)
             for n, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1) if bad.search(line)]
    assert not found, found


def test_no_control_characters_in_docstrings():
    """The same in the docstrings as Python reads them: '\\bar' in a non-raw docstring is a
    backspace and 'ar' (found in jackson_green_law), '\\tau' a tab and 'au'."""
    import importlib
    import inspect
    import pkgutil
    import re

    bad = re.compile(r"[\x00-\x09\x0b-\x1f\x7f]")
    found = []
    for info in pkgutil.walk_packages(asperity.__path__, "asperity.", onerror=lambda name: None):
        if info.name.endswith("__main__"):
            continue
        try:
            module = importlib.import_module(info.name)
        except ModuleNotFoundError:  # an optional extra not installed; the sources are checked as text above
            continue
        objects = [module, *(v for _, v in inspect.getmembers(module) if getattr(v, "__module__", None) == info.name)]
        for obj in list(objects):
            if inspect.isclass(obj):
                objects += [m for m in vars(obj).values() if inspect.isfunction(m) or isinstance(m, property)]
        found += [f"{info.name}: {getattr(o, '__qualname__', o)!s:.60}" for o in objects
                  if isinstance(getattr(o, "__doc__", None), str) and bad.search(o.__doc__)]
    assert not found, found
