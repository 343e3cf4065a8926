"""DMT limit in Maugis' units: Hertz shifted by the pull-off load -2, overflow limits, bad input."""

import re

import numpy as np
import pytest

from asperity import dmt, hertz

FLOAT_MAX = np.finfo(float).max


def test_hertz_shifted_by_the_pull_off():
    A = np.array([0.0, 0.7, 2.0])
    np.testing.assert_array_equal(dmt.dmt_load(A), hertz.hertz_load_md(A) + dmt.DMT_PULL_OFF)
    np.testing.assert_array_equal(dmt.dmt_penetration(A), hertz.hertz_penetration_md(A))
    assert dmt.DMT_PULL_OFF == -2.0


@pytest.mark.parametrize("func, limit", [(dmt.dmt_load, np.cbrt(FLOAT_MAX)), (dmt.dmt_penetration, np.sqrt(FLOAT_MAX))])
def test_overflow_limit(func, limit):
    assert np.isfinite(func(limit * (1 - 1e-12)))
    with pytest.raises(ValueError, match="^A must be <= " + re.escape(f"{limit:.6g}")):
        func(limit * (1 + 1e-12))


@pytest.mark.parametrize("bad", [None, False, 2j, {"A": 1}, "1", np.ma.masked_array([1.0], mask=[True]), -0.5],
                         ids=repr)
def test_bad_input(bad):
    for func in (dmt.dmt_load, dmt.dmt_penetration):
        with pytest.raises(ValueError, match="^A"):
            func(bad)
