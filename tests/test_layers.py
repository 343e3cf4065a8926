"""The package imports only downward through its layers (style guide, section 1).

Every module of ``src/asperity`` is parsed with :mod:`ast` (imports inside functions
included) and each import of another asperity module is checked against :data:`LAYERS`:

* a module imports only from its own layer or the layers below;
* no private name (``_x``) is imported from another module, and a private module is
  imported only by its siblings in the same package, or is one of the base helpers
  meant for everyone (:data:`SHARED_PRIVATE`);
* ``reference/`` (the independent oracle) imports nothing else from asperity, and
  nothing else imports it.

A new module must be given a layer here, or this test fails saying so.
"""

import ast
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src" / "asperity"

#: The layers, lowest first: a module (or package: its first name below ``asperity``) may
#: import from its own layer and the ones before it.  Names of modules still to come
#: (cycle, surface, regimes, fit, sweeps, validation, explorer) are placed as the style guide
#: places them.
LAYERS = [
    ("base", {"_validation", "_validation_files", "_results", "_numbers", "_csv", "_optional", "_version", "_atomic",
              "_json",
              "_warnings",
              "units", "quadrature", "quantities"}),
    ("single-asperity laws", {"friction_stress", "hertz", "jkr", "dmt", "maugis_dugdale", "_maugis_dugdale_brackets",
                              "maugis_dugdale_branch",
                              "jackson_green", "jackson_green_fits", "jackson_green_hardness", "nix_gao",
                              "maugis_dugdale_load", "maugis_dugdale_solve", "maugis_units", "jkr_branch", "cos",
                              "amontons"}),
    ("statistics, groups", {"groups", "heights"}),
    ("integrals", {"asperity_law", "tabulation", "height_sums", "multi_asperity", "elastic_plastic",
                   "jackson_green_law"}),
    ("curves", {"curves", "curve_result", "load_control", "branch_inversion", "pull_off_search", "cycle",
                "cycle_integrals", "cycle_band",
                "cycle_search", "cycle_run",
                "cycle_result", "instrument", "interaction"}),
    ("physical", {"materials", "material_table",
                  "bodies", "physical", "physical_description", "physical_groups", "physical_results",
                  "surface", "regimes",
                  "topography",
                  "plasticity", "physical_cycle", "physical_cycle_inputs", "icha", "persson"}),
    ("applications", {"fit", "sweeps", "validation", "cycle_plot"}),
    ("front ends", {"studies", "cli", "explorer", "__init__"}),
]
#: The independent slow path: imports nothing else from asperity, and nothing imports it.
ORACLE = "reference"
#: Private base modules meant to be imported by every module.
SHARED_PRIVATE = {"_validation", "_validation_files", "_results", "_numbers", "_csv", "_optional", "_version",
                  "_atomic", "_json", "_warnings"}

RANK = {name: i for i, (_, names) in enumerate(LAYERS) for name in names}


def _is_private(name: str) -> bool:
    return name.startswith("_") and not (name.startswith("__") and name.endswith("__"))


def module_path(path: Path) -> tuple[str, ...]:
    """Dotted path below asperity: ('curves',), ('studies', '_common'), ('__init__',) for the root."""
    parts = path.relative_to(SRC).with_suffix("").parts
    if parts[-1] == "__init__" and len(parts) > 1:
        parts = parts[:-1]
    return parts


def _exists(parts) -> bool:
    base = SRC.joinpath(*parts)
    return base.with_suffix(".py").exists() or (base / "__init__.py").exists()


def imports(path: Path, source: str | None = None):
    """(line, target path below asperity, imported names) for every asperity import in a file."""
    source = path.read_text(encoding="utf-8") if source is None else source
    here = module_path(path)
    package = here if path.name == "__init__.py" else here[:-1]
    if here == ("__init__",):
        package = ()
    for node in ast.walk(ast.parse(source, str(path))):
        if isinstance(node, ast.Import):
            for alias in node.names:
                top, *rest = alias.name.split(".")
                if top == "asperity":
                    yield node.lineno, tuple(rest) or ("__init__",), []
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package[:len(package) - (node.level - 1)] if node.level > 1 else package
                target = base + tuple(node.module.split(".")) if node.module else base
            elif node.module and node.module.split(".")[0] == "asperity":
                target = tuple(node.module.split(".")[1:])
            else:
                continue
            names = [a.name for a in node.names]
            if node.module is None:  # from . import x: x is a submodule, or a name of the package
                for name in names:
                    if _exists(target + (name,)):
                        yield node.lineno, target + (name,), []
                    else:
                        yield node.lineno, target or ("__init__",), [name]
            else:
                yield node.lineno, target or ("__init__",), names


def problems(path: Path, source: str | None = None) -> list[str]:
    """What is wrong with the imports of one file (empty if nothing)."""
    here = module_path(path)
    where = f"src/asperity/{path.relative_to(SRC)}"
    key = here[0]
    out = []
    if key != ORACLE and key not in RANK:
        return [f"{where}: module {key!r} has no layer: add it to LAYERS in tests/test_layers.py "
                "(the layer table of the style guide, section 1)"]
    for line, target, names in imports(path, source):
        other = target[0]
        shown = "asperity." + ".".join(target)
        if key == ORACLE:
            if other != ORACLE:
                out.append(f"{where}:{line}: the oracle imports {shown}; reference/ must import nothing else "
                           "from asperity")
            continue
        if other == ORACLE:
            out.append(f"{where}:{line}: imports the oracle {shown}; only tests and benchmarks may")
            continue
        if other not in RANK:
            out.append(f"{where}:{line}: imports {shown}, which has no layer in tests/test_layers.py LAYERS")
            continue
        if other != key and RANK[other] > RANK[key]:
            out.append(f"{where}:{line}: imports {shown} (layer {LAYERS[RANK[other]][0]!r}) from layer "
                       f"{LAYERS[RANK[key]][0]!r}: import only downward")
        for name in names:
            if _is_private(name):
                out.append(f"{where}:{line}: imports the private name {name!r} from {shown}: make it public "
                           "(documented) or keep it in its module")
        private = [p for p in target if _is_private(p)]
        same_package = target[:-1] == (here if path.name == "__init__.py" else here[:-1])
        if private and not (target in {(p,) for p in SHARED_PRIVATE} or same_package):
            out.append(f"{where}:{line}: imports the private module {shown} from outside its package")
    return out


def all_modules():
    return sorted(SRC.rglob("*.py"))


def test_every_module_imports_only_downward_and_nothing_private():
    found = [p for path in all_modules() for p in problems(path)]
    assert not found, "\n".join(found)


def test_the_table_knows_every_module():
    keys = {module_path(p)[0] for p in all_modules()}
    missing = keys - set(RANK) - {ORACLE}
    assert not missing, f"add {sorted(missing)} to LAYERS in tests/test_layers.py"


# -- the checker itself can fail -----------------------------------------------------------
@pytest.mark.parametrize("file, source, message", [
    ("hertz.py", "from .curves import Model\n", "import only downward"),
    ("heights.py", "def f():\n    from asperity.physical import Surface\n", "import only downward"),
    ("curves.py", "from .maugis_dugdale import _curve\n", "private name '_curve'"),
    ("physical.py", "from .studies._common import model\n", "private module"),
    ("curves.py", "from .reference import separation_point\n", "the oracle"),
    ("curves.py", "from . import reference\n", "the oracle"),
    ("reference/multi_asperity.py", "from ..heights import GAUSSIAN\n", "must import nothing else"),
    ("reference/multi_asperity.py", "import asperity.hertz\n", "must import nothing else"),
    ("brand_new.py", "import numpy\n", "has no layer: add it to LAYERS"),
])
def test_checker_catches(file, source, message):
    found = problems(SRC / file, source)
    assert any(message in p for p in found), found


@pytest.mark.parametrize("file, source", [
    ("curves.py", "from .tabulation import Tabulation\nfrom ._validation import scalar\n"
                  "from ._csv import columns_to_csv\n"),
    ("studies/figures.py", "from ._common import Check\nfrom .._version import __version__\n"),
    ("reference/multi_asperity.py", "from .common import MP\nfrom .maugis_dugdale_branch import branch_end\n"),
    ("maugis_dugdale_branch.py", "def f():\n    from .maugis_dugdale import md_curve\n"),
    ("asperity_law.py", "from . import groups\n"),
])
def test_checker_accepts(file, source):
    assert problems(SRC / file, source) == []
