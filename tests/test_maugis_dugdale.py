"""Maugis-Dugdale single asperity (Eqs 11-14) and its JKR, DMT and Hertz limits."""

import math

import mpmath as mp
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from asperity import dmt, hertz, jkr
from asperity import maugis_dugdale as md
from asperity._maugis_dugdale_brackets import md_first_bracket


def eq11_residual_mp(A, t, lam):
    """Eq (11) in the paper's m form, evaluated at 50 digits."""
    with mp.workdps(50):
        A, t, lam = mp.mpf(A), mp.mpf(t), mp.mpf(lam)
        m = mp.sqrt(1 + t * t)
        r = mp.sqrt(m * m - 1)
        lhs = (lam * A**2 / 2 * (r + (m * m - 2) * mp.atan(r))
               + 4 * lam**2 * A / 3 * (r * mp.atan(r) - m + 1))
        return float(lhs - 1)


@pytest.mark.parametrize("t", [1e-6, 1e-3, 0.1, 0.49, 0.51, 2.0, 50.0, 1e5])
@pytest.mark.parametrize("lam", [1e-3, 0.5, 1.0, 30.0])
def test_radius_solves_eq11_to_rounding(t, lam):
    A = float(md.md_radius(t, lam))
    assert abs(eq11_residual_mp(A, t, lam)) < 1e-13


def test_first_bracket_series_matches_high_precision():
    for t in [1e-8, 1e-4, 0.01, 0.3, 0.4999, 0.5001, 3.0]:
        with mp.workdps(60):
            exact = float(mp.mpf(t) + (mp.mpf(t) ** 2 - 1) * mp.atan(mp.mpf(t)))
        assert md_first_bracket(np.float64(t)) == pytest.approx(exact, rel=2e-15)


def test_lambda_c_matches_direct_search():
    # Independent of the asymptotic formula: does Delta(t) have an interior minimum?
    t = np.logspace(-3, 4, 20001)

    def has_min(lam):
        D = md.md_curve(t, lam)[2]
        return bool(np.any(np.diff(D) > 1e-13))

    assert md.LAMBDA_C == pytest.approx(0.93795, abs=5e-5)
    assert not has_min(0.93)
    assert has_min(0.95)


def test_jkr_limit():
    lam = 1e4
    end = md.md_branch_end(lam)
    A_jkr, P_jkr = jkr.jkr_pull_off("displacement")
    assert end.A == pytest.approx(A_jkr, rel=1e-3) and A_jkr == pytest.approx(6 ** (-1 / 3))
    assert end.P == pytest.approx(-5 / 6, rel=1e-3)
    po = md.md_pull_off(lam, "load")
    assert po.P == pytest.approx(-1.5, rel=1e-3)
    assert po.A == pytest.approx(1.5 ** (1 / 3), rel=1e-3)
    # whole curve at the same radius
    A, P, D = md.md_curve(np.logspace(-6, -3, 7), lam)
    np.testing.assert_allclose(P, jkr.jkr_load(A), rtol=2e-3, atol=2e-3)
    np.testing.assert_allclose(D, jkr.jkr_penetration(A), rtol=2e-3, atol=2e-3)


def test_dmt_limit():
    lam = 1e-8
    assert md.md_pull_off(lam, "load").P == pytest.approx(dmt.DMT_PULL_OFF, rel=1e-6)
    assert md.md_branch_end(lam).P == pytest.approx(-2.0, rel=1e-6)
    delta = np.array([0.5, 1.0, 4.0])
    A, P, _ = md.md_solve(delta, lam)
    np.testing.assert_allclose(P, dmt.dmt_load(A), rtol=1e-3)
    np.testing.assert_allclose(delta, dmt.dmt_penetration(A), rtol=1e-3)


def test_dmt_approach_is_sqrt_lambda():
    # Delta_end ~ -(8/3) sqrt(lam/pi) as lam -> 0: DMT is reached only as lam^(1/2).
    for lam in [1e-4, 1e-6, 1e-8]:
        assert md.md_branch_end(lam).delta == pytest.approx(-(8 / 3) * math.sqrt(lam / math.pi),
                                                            rel=3 * math.sqrt(lam))


def test_hertz_at_large_penetration():
    # Adhesion's share of the load falls like A^(-3/2) (JKR: sqrt(6 A^3) / A^3).
    A, P, _ = md.md_solve(np.array([1e6, 1e10]), 1.0)
    rel = np.abs(P / hertz.hertz_load_md(A) - 1)
    assert rel[0] < 1e-4 and rel[1] < 1e-7
    np.testing.assert_allclose(hertz.hertz_penetration_md(A), [1e6, 1e10], rtol=1e-4)


@pytest.mark.parametrize("lam", [0.05, 0.5, 0.9, 0.99, 2.0, 20.0])
def test_solve_inverts_penetration(lam):
    end = md.md_branch_end(lam)
    delta = np.concatenate([end.delta + np.logspace(-8, 0, 9) * abs(end.delta),
                            np.linspace(0.1, 50, 11)])
    A, P, t = md.md_solve(delta, lam)
    A2, P2, D2 = md.md_curve(t, lam)
    np.testing.assert_allclose(D2, delta, rtol=1e-12, atol=1e-13)
    np.testing.assert_allclose(A, A2, rtol=1e-15)
    assert np.all(np.diff(A) > 0)  # stable branch: A grows with Delta


@given(st.floats(1e-3, 1e3), st.floats(0.0, 100.0), st.floats(0.0, 100.0))
def test_radius_increases_with_penetration(lam, x, y):
    end = md.md_branch_end(lam)
    lo, hi = sorted((end.delta + x, end.delta + y))
    A, _, _ = md.md_solve(np.array([lo, hi]), lam)
    assert A[1] >= A[0]


def test_branch_end_is_minimum_of_delta():
    for lam in [1.0, 3.0, 100.0]:
        end = md.md_branch_end(lam)
        t = end.t * np.array([0.9, 0.99, 1.01, 1.1])
        D = md.md_curve(t, lam)[2]
        assert np.all(D > end.delta)


def test_load_pull_off_below_displacement_pull_off():
    for lam in [0.1, 1.0, 10.0]:
        assert md.md_pull_off(lam, "load").P <= md.md_pull_off(lam, "displacement").P


def test_lambda_from_physical():
    # Eq 14 by hand for sigma0 = 1 GPa, w = 1 J/m^2, R = 1 um, E* = 100 GPa
    K = 4 / 3 * 100e9
    expected = 2 * 1e9 * (1e-6 / (math.pi * 1.0 * K**2)) ** (1 / 3)
    assert md.md_lambda(1e-6, 1.0, 100e9, 1e9) == pytest.approx(expected, rel=1e-14)


@pytest.mark.parametrize("call, name", [
    (lambda: md.md_solve([0.0], -1.0), "lam"),
    (lambda: md.md_solve([np.nan], 1.0), "delta"),
    (lambda: md.md_solve([-5.0], 1.0), "delta"),
    (lambda: md.md_radius([0.0], 1.0), "t"),
    (lambda: md.md_pull_off(1.0, "force"), "control"),
    (lambda: md.md_branch_end(np.inf), "lam"),
])
def test_bad_input(call, name):
    with pytest.raises(ValueError, match=name):
        call()


def test_lambda_range_and_far_jkr():
    end = md.md_branch_end(1e12)  # far JKR: the scan for the turning point reaches t ~ 1/lam
    assert end.P == pytest.approx(-5 / 6, rel=1e-9) and end.A == pytest.approx(6 ** (-1 / 3), rel=1e-9)
    assert md.md_pull_off(1e12, "load").P == pytest.approx(-1.5, rel=1e-9)
    for lam in (2e12, 1e-13):
        with pytest.raises(ValueError, match="lam"):
            md.md_branch_end(lam)
    with pytest.raises(ValueError, match=r"delta, lam must have shapes that broadcast together"):
        md.md_solve([0.1, 0.2, 0.3], [1.0, 2.0])
    with pytest.raises(ValueError, match="t = sqrt"):
        md.md_curve([1e300], 1.0)


@given(st.floats(1e-10, 1e10), st.floats(1e-6, 1e6))
def test_radius_inverse(lam, A):
    t = md.md_t_of_radius(np.array([A]), lam)
    assert md.md_radius(t, lam)[0] == pytest.approx(A, rel=1e-12)


def curve_mp(t, lam):
    """Eqs (11)-(13) in the paper's m form, A from the quadratic formula (to be run at 60 digits)."""
    t, lam = mp.mpf(t), mp.mpf(lam)
    m = mp.sqrt(1 + t * t)
    c2 = lam / 2 * (t + (m * m - 2) * mp.atan(t))
    c1 = 4 * lam**2 / 3 * (t * mp.atan(t) - m + 1)
    A = (-c1 + mp.sqrt(c1 * c1 + 4 * c2)) / (2 * c2)
    return A, A**3 - lam * A * A * (t + m * m * mp.atan(t)), A * A - 4 * lam * A * t / 3


@pytest.mark.parametrize("lam", [1e-3, 0.5, 3.0, 100.0])
@pytest.mark.parametrize("t", [1e-4, 0.01, 0.3, 0.49, 0.51, 2.0, 50.0, 1e4])
def test_curve_and_its_derivatives_match_mpmath(t, lam):
    A, P, D, dA, dP, dD = (float(x) for x in md.md_curve(t, lam, derivatives=True))
    with mp.workdps(60):
        ref = curve_mp(t, lam)
        dref = [mp.diff(lambda x, k=k: curve_mp(x, lam)[k], t) for k in range(3)]
        # dP and dD are differences of terms that nearly cancel for t >> 1: the size of the terms
        g, dg = t + (1 + t * t) * mp.atan(t), 2 + 2 * t * mp.atan(t)
        a, da = ref[0], dref[0]
        size_P = float(3 * a * a * abs(da) + lam * (2 * a * abs(da) * g + a * a * dg))
        size_D = float(2 * a * abs(da) + 4 * lam * (abs(da) * t + a) / 3)
    for got, want in zip((A, P, D, dA), (*ref, dref[0]), strict=True):
        assert got == pytest.approx(float(want), rel=1e-14)
    assert abs(dP - float(dref[1])) <= 1e-14 * size_P
    assert abs(dD - float(dref[2])) <= 1e-14 * size_D
    # without derivatives: the same first three, bit for bit
    assert tuple(md.md_curve(t, lam)) == (A, P, D)


@pytest.mark.parametrize("lam", [1e-12, 1e-3, 1.0, 1e12])
def test_t_of_radius_round_trip_and_limits(lam):
    A = np.geomspace(1e-6, 1e6, 13)
    np.testing.assert_allclose(md.md_radius(md.md_t_of_radius(A, lam), lam), A, rtol=1e-12)
    t_max = md.md_t_of_radius(md.A_MAX, lam)  # the largest radius handled, and its t
    assert float(md.md_radius(t_max, lam)) == pytest.approx(md.A_MAX, rel=1e-10)
    with pytest.raises(ValueError, match=r"A \(contact radius\) must lie in"):
        md.md_t_of_radius(md.A_MAX * (1 + 1e-12), lam)
    with pytest.raises(ValueError, match="A"):
        md.md_t_of_radius(1e-200, lam)  # below the radius at t = 1e100


@pytest.mark.parametrize("lam", [1e-12, 1e-3, 1.0, 1e12])
def test_curve_overflow_limit(lam):
    # At the radius bound A_MAX everything is finite, with no warning (pytest turns warnings
    # into errors); just beyond it the curve refuses t, naming it and its valid range.
    t_min = float(md.md_t_of_radius(md.A_MAX, lam))
    out = md.md_curve(t_min, lam, derivatives=True)
    assert all(np.isfinite(x) for x in out) and float(out[0]) == pytest.approx(md.A_MAX, rel=1e-10)
    for call in (md.md_curve, md.md_radius, md.md_load, md.md_penetration):
        with pytest.raises(ValueError, match=r"t = sqrt\(m\^2 - 1\) must lie in \[") as err:
            call(t_min * (1 - 1e-8), lam)
        assert f"{t_min:.6g}" in str(err.value)


BAD_VALUES = [None, True, np.bool_(False), 1 + 2j, np.array([1 + 0j]), {"t": 1.0}, "1.0", b"1",
              np.ma.masked_array([1.0, 2.0], mask=[False, True]), [1.0, None], np.nan, np.inf, [[1.0], [1.0, 2.0]]]


@pytest.mark.parametrize("bad", BAD_VALUES, ids=repr)
def test_bad_types_name_the_parameter(bad):
    for call, name in ((lambda: md.md_curve(bad, 1.0), "t"), (lambda: md.md_curve(1.0, bad), "lam"),
                       (lambda: md.md_radius(bad, 1.0), "t"), (lambda: md.md_t_of_radius(bad, 1.0), "A"),
                       (lambda: md.md_t_of_radius(1.0, bad), "lam"), (lambda: md.md_solve(bad, 1.0), "delta"),
                       (lambda: md.md_solve(1.0, bad), "lam"), (lambda: md.md_branch_end(bad), "lam"),
                       (lambda: md.md_pull_off(bad), "lam")):
        with pytest.raises(ValueError, match=f"^{name}"):
            call()


def test_derivatives_flag_must_be_a_bool():
    with pytest.raises(TypeError, match="derivatives"):
        md.md_curve(1.0, 1.0, derivatives="yes")


def test_t_of_radius_on_floats_equals_the_array_path():
    # A few radii (the friction breakpoints) take a Python-float path; it must agree with the arrays'.
    rng = np.random.default_rng(7)
    for _ in range(300):
        lam = 10 ** rng.uniform(-12, 12)
        A = 10 ** rng.uniform(-6, 30)
        one = md.md_t_of_radius([A], lam)[0]
        many = md.md_t_of_radius(np.full(6, A), lam)[0]
        assert one == pytest.approx(many, rel=1e-13)
        assert float(md.md_radius(one, lam)) == pytest.approx(A, rel=1e-12)


def test_the_dimensionless_solutions_broadcast_over_lambda_like_ufuncs():
    """md_solve, md_solve_load, md_branch_end and md_pull_off over an array of lambda equal
    their scalar calls element by element (one solve per distinct lambda, repeats included)."""
    from asperity.maugis_dugdale_load import md_solve_load
    lam = np.array([[1e-6], [0.3], [md.LAMBDA_C], [1.0], [1e3], [0.3]])  # a repeat: grouped
    delta = np.array([0.5, 2.0, 40.0])
    A, P, t = md.md_solve(delta, lam)
    assert A.shape == P.shape == t.shape == (6, 3)
    for i, x in enumerate(lam[:, 0]):
        for j, dj in enumerate(delta):
            assert (A[i, j], P[i, j], t[i, j]) == tuple(md.md_solve(dj, float(x)))
    loads = np.array([0.0, 3.0, 100.0])
    A2, D2, t2 = md_solve_load(loads, lam)
    for i, x in enumerate(lam[:, 0]):
        assert A2[i].tolist() == md_solve_load(loads, float(x))[0].tolist()
        assert D2[i].tolist() == md_solve_load(loads, float(x))[1].tolist()
    for control in ("load", "displacement"):
        po = md.md_pull_off(lam[:, 0], control)
        assert po.P.shape == (6,)
        for i, x in enumerate(lam[:, 0]):
            one = md.md_pull_off(float(x), control)
            assert (po.t[i], po.A[i], po.P[i], po.delta[i]) == (one.t, one.A, one.P, one.delta)
    # The adhesion map: pull-off from DMT (-2) to JKR (-3/2) under load control, monotonic in lambda.
    curve = md.md_pull_off(np.geomspace(1e-4, 1e4, 41)).P
    assert curve[0] == pytest.approx(-2.0, abs=1e-3) and curve[-1] == pytest.approx(-1.5, abs=1e-3)
    assert np.all(np.diff(curve) >= 0)
    end = md.md_branch_end([0.3, 1e6])
    assert np.isinf(end.t[0]) and end.P[1] == pytest.approx(-5 / 6, rel=1e-6)
    assert end.to_dict()["t"][0] is None and end.to_dict()["P"][1] == float(end.P[1])
    assert isinstance(md.md_branch_end(1.0).P, float)
    with pytest.raises(ValueError, match=r"delta \(penetration\) must lie in .* for lam=0.3"):
        md.md_solve([-5.0], [1e3, 0.3])
    with pytest.raises(ValueError, match=r"lam \(Maugis parameter\) must lie in"):
        md.md_pull_off([1.0, 1e13])
