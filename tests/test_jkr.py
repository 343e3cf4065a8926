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
    with pytest.raises(ValueError, match="^A must be <= "):  # 8A/3 overflows too: inf - inf, no warning
        func(2.25e307)


@pytest.mark.parametrize("bad", [None, True, 1j, {}, "2", np.ma.masked_array([1.0], mask=[True]), -1.0, np.nan],
                         ids=repr)
def test_bad_input(bad):
    for func in (jkr.jkr_load, jkr.jkr_penetration):
        with pytest.raises(ValueError, match="^A"):
            func(bad)


# -- load control, displacement control, the physical shell ---------------------------------
import math  # noqa: E402

from asperity import hertz  # noqa: E402


def test_solve_load_inverts_the_load():
    A = np.geomspace(1.5 ** (1 / 3), 1e60, 300)
    A2, D2 = jkr.jkr_solve_load(jkr.jkr_load(A))
    np.testing.assert_allclose(A2, A, rtol=1e-13)
    np.testing.assert_allclose(D2, jkr.jkr_penetration(A), rtol=1e-12, atol=1e-14)
    assert jkr.jkr_solve_load([-1.5])[0][0] ** 3 == pytest.approx(1.5, rel=1e-15)
    with pytest.raises(ValueError, match=r"^P \(load over pi w R\) must lie in \[-1.5"):
        jkr.jkr_solve_load([-1.5 - 1e-12])


def test_solve_inverts_the_penetration_on_the_stable_branch():
    A_c = 6 ** (-1 / 3)
    A = np.concatenate([A_c * (1 + np.geomspace(1e-6, 1.0, 20)), np.geomspace(2 * A_c, 1e40, 100)])
    A2, P2 = jkr.jkr_solve(jkr.jkr_penetration(A))
    np.testing.assert_allclose(A2, A, rtol=1e-9)  # ill-conditioned only right at the branch end
    np.testing.assert_allclose(P2, jkr.jkr_load(A), rtol=1e-9, atol=1e-9)
    A_end, P_end = jkr.jkr_solve([jkr.jkr_penetration(A_c)])
    assert P_end[0] == pytest.approx(-5 / 6, rel=1e-7)  # displacement-controlled pull-off
    with pytest.raises(ValueError, match=r"^delta \(penetration\) must lie in"):
        jkr.jkr_solve([-0.91])


R, W, E_STAR = 20e-9, 0.3, 1e11


def test_contact_radius_is_jkr_equation_2():
    K = 4 / 3 * E_STAR
    P = np.array([-1.5 * math.pi * W * R, -1e-9, 0.0, 1e-8, 1e-6])
    a = jkr.jkr_contact_radius(P, R=R, w=W, E_star=E_STAR)
    Q = 3 * math.pi * W * R
    np.testing.assert_allclose(a**3, R / K * (P + Q + np.sqrt(2 * Q * P + Q * Q)), rtol=1e-13)
    # the same in Maugis' units
    A = jkr.jkr_solve_load(P / (math.pi * W * R))[0]
    np.testing.assert_allclose(a, A * (math.pi * W * R**2 / K) ** (1 / 3), rtol=1e-13)


def test_pull_off_load_is_minus_three_halves_pi_w_R():
    F = jkr.jkr_pull_off_force(R=R, w=W)
    assert F == pytest.approx(1.5 * math.pi * W * R, rel=1e-15)
    # the load-controlled branch ends exactly there: the smallest load with a radius
    A = np.linspace(0.5, 3.0, 20001)
    assert np.min(jkr.jkr_load(A)) * math.pi * W * R == pytest.approx(-F, rel=1e-7)
    assert np.isfinite(jkr.jkr_contact_radius(-F, R=R, w=W, E_star=E_STAR))
    with pytest.raises(ValueError, match="JKR pull-off load"):
        jkr.jkr_contact_radius(-F * (1 + 1e-9), R=R, w=W, E_star=E_STAR)


@pytest.mark.parametrize("w", [1e-3, 1e-6, 1e-9, 0.0])
def test_tends_to_hertz_as_w_vanishes(w):
    P = np.geomspace(1e-9, 1e-5, 7)
    a = jkr.jkr_contact_radius(P, R=R, w=w, E_star=E_STAR)
    a_h = hertz.hertz_contact_radius(P, R=R, E_star=E_STAR)
    # a^3 = a_H^3 (1 + 3x + sqrt(6x + 9x^2)), x = pi w R / P: the gap closes like sqrt(w)
    x = math.pi * w * R / P
    np.testing.assert_allclose(a / a_h, np.cbrt(1 + 3 * x + np.sqrt(6 * x + 9 * x * x)), rtol=1e-12)
    assert np.max(np.abs(a / a_h - 1)) <= 2 * math.sqrt(6 * math.pi * w * R / 1e-9) / 3 + 1e-15
    delta = np.linspace(0.0, 1e-9, 5)
    F = jkr.jkr_normal_force(delta, R=R, w=w, E_star=E_STAR)
    np.testing.assert_allclose(F, hertz.hertz_normal_force(delta, R=R, E_star=E_STAR),
                               atol=4 * math.pi * w * R + 1e-300 if w else 0.0)


def test_normal_force_is_the_stable_branch():
    K = 4 / 3 * E_STAR
    scale = (math.pi**2 * W**2 * R / K**2) ** (1 / 3)
    D = np.array([-0.9, -0.5, 0.0, 1.0, 10.0])
    F = jkr.jkr_normal_force(D * scale, R=R, w=W, E_star=E_STAR)
    np.testing.assert_allclose(F, jkr.jkr_solve(D)[1] * math.pi * W * R, rtol=1e-9)
    with pytest.raises(ValueError, match="penetration"):
        jkr.jkr_normal_force([-0.95 * scale], R=R, w=W, E_star=E_STAR)


@pytest.mark.parametrize("kwargs, match", [({"R": 0.0, "w": W, "E_star": E_STAR}, "^R must be > 0"),
                                           ({"R": R, "w": -1.0, "E_star": E_STAR}, "^w must be >= 0"),
                                           ({"R": R, "w": W, "E_star": True}, "^E_star must be a real")])
def test_bad_physical_input(kwargs, match):
    with pytest.raises(ValueError, match=match):
        jkr.jkr_contact_radius([0.0], **kwargs)


def test_normal_force_broadcasts_over_the_sphere():
    """delta, R, w and E_star broadcast like a ufunc; Hertz (w = 0) and JKR elements side by side."""
    delta = np.array([1e-9, -5e-11, 2e-9, 0.0])
    R = np.array([[1e-6], [100e-9]])
    w = np.array([0.1, 0.2, 0.0, 0.0])
    F = jkr.jkr_normal_force(delta, R=R, w=w, E_star=1e11)
    assert F.shape == (2, 4)
    for i, j in np.ndindex(F.shape):
        expected = float(jkr.jkr_normal_force(float(delta[j]), R=float(R[i, 0]), w=float(w[j]), E_star=1e11))
        assert F[i, j] == pytest.approx(expected, rel=1e-14)
    # the Hertz elements are Hertz's closed form
    np.testing.assert_allclose(F[:, 2], 4 / 3 * 1e11 * np.sqrt(R[:, 0]) * 2e-9**1.5, rtol=1e-15)
    with pytest.raises(ValueError, match="must be >= 0 without adhesion"):
        jkr.jkr_normal_force([-1e-10, -1e-10], R=1e-6, w=[0.1, 0.0], E_star=1e11)
    with pytest.raises(ValueError, match="must have shapes that broadcast"):
        jkr.jkr_normal_force([1e-9, 2e-9], R=[1e-6, 2e-6, 3e-6], w=0.1, E_star=1e11)
