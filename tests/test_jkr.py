"""JKR limit in Maugis' units: closed-form pull-off points, overflow limits, bad input."""

import re

import numpy as np
import pytest

from asperity import jkr

FLOAT_MAX = np.finfo(float).max


def test_load_pull_off_is_the_minimum_of_the_load():
    A, P = jkr.jkr_pull_off("load")
    assert jkr.jkr_load(A) == pytest.approx(P, rel=1e-15)
    # dP/dA = 3A^2 - (3/2) sqrt(6 A) = 0 at A^3 = 3/2
    near = jkr.jkr_load(A * np.array([0.999, 1.001]))
    assert np.all(near > P)


def test_displacement_pull_off_is_the_minimum_of_the_penetration():
    A, P = jkr.jkr_pull_off("displacement")
    assert jkr.jkr_load(A) == pytest.approx(P, rel=1e-15)
    near = jkr.jkr_penetration(A * np.array([0.999, 1.0, 1.001]))
    assert near[1] < near[0] and near[1] < near[2]
    with pytest.raises(ValueError, match="control"):
        jkr.jkr_pull_off("force")


@pytest.mark.parametrize("func, limit", [(jkr.jkr_load, np.cbrt(FLOAT_MAX / 6)),
                                         (jkr.jkr_penetration, np.sqrt(FLOAT_MAX))])
def test_overflow_limit(func, limit):
    assert np.isfinite(func(limit * (1 - 1e-12)))  # and no RuntimeWarning (an error under pytest)
    with pytest.raises(ValueError, match="^A must be <= " + re.escape(f"{limit:.6g}")):
        func([1.0, limit * (1 + 1e-12)])


@pytest.mark.parametrize("bad", [None, True, 1j, {}, "2", np.ma.masked_array([1.0], mask=[True]), -1.0, np.nan],
                         ids=repr)
def test_bad_input(bad):
    for func in (jkr.jkr_load, jkr.jkr_penetration):
        with pytest.raises(ValueError, match="^A"):
            func(bad)
