"""asperity._validation: the shared input checks, in particular the scalar physical ones."""

import numpy as np
import pint
import pytest
from hypothesis import given
from hypothesis import strategies as st

from asperity._validation import (
    as_float_array,
    check_optional_positive,
    check_scalar_poisson,
    check_scalar_positive,
)

u = pint.UnitRegistry()


@pytest.mark.parametrize("value, message", [
    (None, "x must be a real number.*got None"), (True, "boolean"), (np.bool_(False), "boolean"),
    (1j, "complex"), (np.array([1 + 0j]), "complex"), ("abc", "real number"), ({"a": 1}, "real number"),
    (float("nan"), "finite"), ([1.0, float("inf")], "finite"), ([], "must not be empty"),
    ([1.0, True], "boolean"), ([[1.0], [np.True_]], "boolean"), ([1.0, [2.0, 3.0]], "real number"),
    (np.ma.masked_array([1.0, 2.0], [False, True]), "masked"),
    pytest.param(10**400, "finite", id="int-1e400"), pytest.param([1.0, -10**400], "finite", id="list-int-1e400"),
    pytest.param(np.longdouble("1e400"), "finite", id="longdouble-1e400"),  # a user trial
    pytest.param(np.array([True, 1.0], dtype=object), "boolean", id="object-array-bool"),  # a user trial
])
def test_as_float_array_rejects(value, message):
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a long double beyond the doubles leaked NumPy's overflow warning
        with pytest.raises(ValueError, match=message):
            as_float_array(value, "x")


def test_scalar_positive_converts_units():
    assert check_scalar_positive(2 * u.nm, "sigma_s", "m") == pytest.approx(2e-9, rel=1e-15)
    assert check_scalar_positive("2 nm", "sigma_s", "m") == pytest.approx(2e-9, rel=1e-15)
    assert check_scalar_positive(np.float32(2.0), "x") == 2.0
    assert isinstance(check_scalar_positive(np.array(3.0), "x"), float)
    assert check_scalar_positive(0, "w", "J/m^2", allow_zero=True) == 0.0


@pytest.mark.parametrize("value, unit, message", [
    (0.0, "m", r"sigma_s must be > 0 m \(valid range 0 < sigma_s < inf\), got 0.0"),
    (-1.0, None, r"sigma_s must be > 0 \(valid range"),
    ([1.0, 2.0], "m", "sigma_s must be a scalar, got an array of shape"),
    (2 * u.GPa, "m", "sigma_s must have units compatible with m"),
    ("2", "m", "sigma_s needs a unit compatible with m"),
    (True, "m", "boolean"),
])
def test_scalar_positive_messages(value, unit, message):
    with pytest.raises(ValueError, match=message):
        check_scalar_positive(value, "sigma_s", unit)


def test_scalar_nonnegative_message():
    with pytest.raises(ValueError, match=r"w must be >= 0 J/m\^2 \(valid range 0 <= w < inf\)"):
        check_scalar_positive(-1.0, "w", "J/m^2", allow_zero=True)


def test_optional_positive():
    assert check_optional_positive(None, "b", "m") is None
    assert check_optional_positive("0.25nm", "b", "m") == pytest.approx(2.5e-10)
    with pytest.raises(ValueError, match=r"b must be > 0 m or None \(missing\)"):
        check_optional_positive(0.0, "b", "m")
    assert check_optional_positive(0.0, "w", "J/m^2", allow_zero=True) == 0.0


@given(st.floats(-0.999, 0.499))
def test_poisson_accepts_its_range(nu):
    assert check_scalar_poisson(nu) == nu


@pytest.mark.parametrize("nu", [-1.0, 0.5, 2.0, float("nan"), True, "0.3 m"])
def test_poisson_rejects(nu):
    with pytest.raises(ValueError, match="nu"):
        check_scalar_poisson(nu)


def test_as_float_array_accepts_numbers():
    np.testing.assert_array_equal(as_float_array([1, 2.5], "x"), [1.0, 2.5])
    assert as_float_array(np.float32(0.5), "x").dtype == np.float64
    assert as_float_array([], "x", allow_empty=True).size == 0
