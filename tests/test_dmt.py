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


# -- load control and the physical shell -------------------------------------------------------
import math  # noqa: E402

R, W, E_STAR = 20e-9, 0.3, 1e11


def test_solve_load_and_solve_invert_the_curve():
    A = np.geomspace(0.1, 1e50, 100)  # smaller A^3 drown in P = A^3 - 2
    np.testing.assert_allclose(dmt.dmt_solve_load(dmt.dmt_load(A))[0], A, rtol=1e-12)
    np.testing.assert_allclose(dmt.dmt_solve(dmt.dmt_penetration(A))[1], dmt.dmt_load(A), rtol=1e-14)
    with pytest.raises(ValueError, match=r"must lie in \[-2"):
        dmt.dmt_solve_load([-2.1])
    with pytest.raises(ValueError, match="no contact at negative"):
        dmt.dmt_solve([-1e-3])


def test_physical_shell():
    K = 4 / 3 * E_STAR
    P = np.array([-2 * math.pi * W * R, 0.0, 1e-7])
    a = dmt.dmt_contact_radius(P, R=R, w=W, E_star=E_STAR)
    np.testing.assert_allclose(a**3, R / K * (P + 2 * math.pi * W * R), rtol=1e-13, atol=1e-40)
    assert dmt.dmt_pull_off_force(R=R, w=W) == pytest.approx(2 * math.pi * W * R, rel=1e-15)  # -2 pi w R
    with pytest.raises(ValueError, match="DMT pull-off load"):
        dmt.dmt_contact_radius(-2.001 * math.pi * W * R, R=R, w=W, E_star=E_STAR)
    delta = np.array([0.0, 1e-9])
    np.testing.assert_allclose(dmt.dmt_normal_force(delta, R=R, w=W, E_star=E_STAR),
                               hertz.hertz_normal_force(delta, R=R, E_star=E_STAR) - 2 * math.pi * W * R, rtol=1e-14)
    with pytest.raises(ValueError, match="negative penetration"):
        dmt.dmt_normal_force([-1e-12], R=R, w=W, E_star=E_STAR)
    # w = 0 is Hertz
    np.testing.assert_allclose(dmt.dmt_contact_radius(P[1:], R=R, w=0.0, E_star=E_STAR),
                               hertz.hertz_contact_radius(P[1:], R=R, E_star=E_STAR), rtol=1e-15)
