"""``import asperity``: lazy, and every public name and submodule reachable as before."""

import subprocess
import sys

import pytest

import asperity

SUBMODULES = ["jkr", "dmt", "hertz", "maugis_dugdale", "friction_stress", "groups", "heights", "curves",
              "physical", "materials", "multi_asperity", "asperity_law", "quantities", "units", "studies", "cli",
              "cycle", "physical_cycle", "instrument", "fit", "cos", "amontons", "maugis_dugdale_load"]


def test_public_names_are_the_defining_modules_objects():
    import asperity.curves
    import asperity.cycle
    import asperity.elastic_plastic
    import asperity.friction_stress
    import asperity.heights
    import asperity.maugis_dugdale
    import asperity.multi_asperity
    import asperity.physical_results
    import asperity.plasticity
    import asperity.sweeps

    for name in asperity.__all__:
        value = getattr(asperity, name)
        if name == "__version__":
            assert value == asperity._version.__version__
            continue
        homes = [m for m in (asperity.curves, asperity.cycle, asperity.friction_stress, asperity.heights,
                             asperity.maugis_dugdale, asperity.multi_asperity, asperity.elastic_plastic,
                             asperity.plasticity, asperity.sweeps, asperity.physical_results) if hasattr(m, name)]
        assert homes and getattr(homes[0], name) is value, name


def test_from_import_and_star_import():
    from asperity import load_curve, md_solve  # noqa: F401

    namespace = {}
    exec("from asperity import *", namespace)
    assert set(asperity.__all__) <= set(namespace)


@pytest.mark.parametrize("name", SUBMODULES)
def test_submodules_are_attributes(name):
    # In a fresh interpreter, so that no earlier import has set the attribute already.
    res = subprocess.run([sys.executable, "-c", f"import asperity; print(asperity.{name}.__name__)"],
                         capture_output=True, text=True, check=True)
    assert res.stdout.strip() == f"asperity.{name}"
    assert name in dir(asperity)


def test_unknown_attribute():
    with pytest.raises(AttributeError, match="no attribute 'nosuchthing'"):
        asperity.nosuchthing  # noqa: B018
    with pytest.raises(AttributeError):
        asperity._private_thing  # noqa: B018
    assert not hasattr(asperity, "nosuchthing")


def test_dir_lists_public_names():
    assert set(asperity.__all__) <= set(dir(asperity))


def test_fit_import_without_lmfit():
    # lmfit is imported only when a fit runs; reading data and building models need none of it.
    code = ("import sys; sys.modules['lmfit'] = None\n"
            "import asperity.fit as f\n"
            "d = f.friction_load_data([1.0, 2.0, 3.0], [1.0, 1.5, 2.0])\n"
            "try:\n    f.fit_friction_load(d, 'amontons')\nexcept ImportError as e:\n    print(e)")
    res = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert res.stdout.strip() == "fitting needs lmfit: pip install 'asperity[fit]'"
