"""The quantity registry: every derived table agrees with it, ranges mean what they say."""

import math

import pytest

from asperity import quantities
from asperity.curves import COLUMNS, CurveResult
from asperity.physical import PHYSICAL_COLUMNS, PhysicalCurve
from asperity.quantities import CURVE_COLUMNS, MODEL_PARAMETERS, PLASTIC_COLUMNS, quantity


def test_curve_columns_are_the_result_fields():
    assert list(COLUMNS) == list(CURVE_COLUMNS)
    fields = [f for f in CurveResult.__dataclass_fields__ if f not in ("parameters", "d_local", *PLASTIC_COLUMNS)]
    assert fields == list(CURVE_COLUMNS)
    assert all(name in CurveResult.__dataclass_fields__ for name in PLASTIC_COLUMNS)
    assert all(name in PhysicalCurve.__dataclass_fields__ for name in PLASTIC_COLUMNS)
    assert all(name in PhysicalCurve.__dataclass_fields__ for name in PHYSICAL_COLUMNS)
    assert [col for col, _, _ in PHYSICAL_COLUMNS.values()] == ["d_m", "P_N", "F_N", "mu", "area_m2",
                                                               "pressure_Pa", "contacts"]


def test_model_parameters_match_model_signature():
    import inspect

    from asperity.asperity_law import ModelParameters
    from asperity.friction_stress import A1, A2, TAU_F1, TAU_F2

    sig = inspect.signature(ModelParameters)
    for name in ("alpha", "beta", "gamma", "nu", "h_over_b"):
        assert name in sig.parameters and name in MODEL_PARAMETERS
        default = sig.parameters[name].default
        if default is not inspect.Parameter.empty:
            assert MODEL_PARAMETERS[name].default == default
    for name, value in (("tau_f1", TAU_F1), ("tau_f2", TAU_F2), ("a1", A1), ("a2", A2)):
        assert MODEL_PARAMETERS[name].default == value


@pytest.mark.parametrize("name,inside,outside", [
    ("alpha", [1e-9, 1.0], [0.0, -1.0]),
    ("gamma", [0.0, 1e-3], [-1e-9]),
    ("nu", [-0.99, 0.0, 0.49], [-1.0, 0.5]),
])
def test_ranges(name, inside, outside):
    q = quantity(name)
    assert all(q.contains(v) for v in inside)
    assert not any(q.contains(v) for v in outside)
    assert name in q.range_text() and name in q.help()


def test_typical_ranges_inside_valid_ranges():
    for registry in (quantities.MODEL_PARAMETERS, quantities.PHYSICAL_PARAMETERS):
        for q in registry.values():
            if q.typical:
                lo, hi = q.typical
                assert lo < hi and q.contains(lo) and q.contains(hi), q.name
                assert not q.log or lo > 0
            if q.default is not None:
                assert q.contains(q.default) and math.isfinite(q.default)


def test_unknown_quantity_lists_names():
    with pytest.raises(ValueError, match="unknown quantity 'zeta'.*alpha"):
        quantity("zeta")


def test_fit_parameters_registry():
    from asperity.quantities import FIT_PARAMETERS, PHYSICAL_PARAMETERS

    assert quantity("alpha_t") is FIT_PARAMETERS["alpha_t"] and quantity("alpha_t").contains(1.0)
    assert not quantity("alpha_t").contains(1.01) and not quantity("Pc").contains(0.0)
    assert quantity("Pc").contains(-1.0) and quantity("P0").si_name == "P0_N"
    for name, si in (("tau1", "tau1_Pa"), ("tau2", "tau2_Pa"), ("sigma0", "sigma0_Pa"), ("tau", "tau_Pa")):
        assert PHYSICAL_PARAMETERS[name].si_name == si and PHYSICAL_PARAMETERS[name].log
    names = [q.si_name or q.name for reg in (FIT_PARAMETERS, PHYSICAL_PARAMETERS) for q in reg.values()]
    assert len(names) == len(set(names))
