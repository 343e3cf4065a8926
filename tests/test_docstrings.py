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
DOCTEST_MODULES = ["asperity.curves", "asperity.multi_asperity", "asperity.tabulation", "asperity.load_control",
                   "asperity.pull_off_search", "asperity.asperity_law", "asperity.maugis_dugdale",
                   "asperity.maugis_dugdale_branch", "asperity.hertz", "asperity.jkr", "asperity.dmt",
                   "asperity.heights.base", "asperity.heights.gaussian", "asperity.heights.exponential",
                   "asperity.heights.weibull", "asperity.heights.pearson", "asperity.heights.johnson",
                   "asperity.heights.mixture", "asperity.heights.empirical", "asperity.heights.registry",
                   "asperity.heights.fit"]

#: Functions users call (README, docs/model.md): each carries the full numpydoc, not a pointer.
FULL_DOCS = {
    "asperity.curves": ["separation_curve", "load_curve", "pull_off"],
    "asperity.multi_asperity": ["contact_fraction", "normal_force", "friction_force", "real_contact_area"],
    "asperity.maugis_dugdale": ["md_radius", "md_load", "md_penetration", "md_curve", "md_t_of_radius"],
    "asperity.maugis_dugdale_branch": ["md_solve", "md_branch_end", "md_pull_off"],
    "asperity.hertz": ["hertz_radius", "hertz_force", "hertz_load_md", "hertz_penetration_md"],
    "asperity.jkr": ["jkr_load", "jkr_penetration", "jkr_pull_off"],
    "asperity.dmt": ["dmt_load", "dmt_penetration"],
    "asperity.load_control": ["start_separation", "bracket_low", "force_grid", "stable_branch", "branch_guess",
                              "invert_branch"],
    "asperity.pull_off_search": ["find_pull_off"],
    "asperity.heights": ["parse_heights", "fit_heights"],
}


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
