"""Hertz asperity (Eqs 6, 8) in the paper's and in Maugis' units: closed forms, overflow limits, bad input."""

import re

import numpy as np
import pytest

from asperity import hertz

FLOAT_MAX = np.finfo(float).max


def test_paper_units_by_hand():
    # a = beta sqrt(u); P/(G b^2) = (4/3) (2/(1-nu)) alpha beta^2 u^(3/2): E*/G = 2/(1-nu)
    u = np.array([-1.0, 0.0, 0.25, 4.0])
    np.testing.assert_allclose(hertz.hertz_radius(u, 30.0), [0.0, 0.0, 15.0, 60.0], rtol=1e-15)
    np.testing.assert_allclose(hertz.hertz_force(u, 0.02, 30.0, nu=0.25),
                               (4 / 3) * (2 / 0.75) * 0.02 * 900 * np.array([0, 0, 0.125, 8.0]), rtol=1e-15)


def test_maugis_units():
    A = np.array([0.0, 0.5, 3.0])
    np.testing.assert_allclose(hertz.hertz_load_md(A), A**3, rtol=0)
    np.testing.assert_allclose(hertz.hertz_penetration_md(A), A**2, rtol=0)


def test_force_overflow_limit():
    alpha, beta, nu = 0.01, 1000.0, 0.3
    c = (8 / 3) / (1 - nu) * alpha * beta**2
    u_max = (FLOAT_MAX / c) ** (2 / 3)
    assert np.isfinite(hertz.hertz_force(u_max * (1 - 1e-12), alpha, beta, nu))  # no warning either
    with pytest.raises(ValueError, match=r"^u_bar must be <= ") as err:
        hertz.hertz_force([1.0, u_max * (1 + 1e-12)], alpha, beta, nu)
    assert f"{u_max:.6g}" in str(err.value)
    # a tiny scale: u^(3/2) itself overflows first, at DBL_MAX^(2/3)
    with pytest.raises(ValueError, match="u_bar must be <= " + re.escape(f"{FLOAT_MAX ** (2 / 3):.6g}")):
        hertz.hertz_force(1e300, 1e-300, 1.0)
    # beta^2 overflows whatever alpha is
    beta_max = np.sqrt(FLOAT_MAX)
    assert np.isfinite(hertz.hertz_force(0.0, 1e-300, beta_max * (1 - 1e-12)))
    with pytest.raises(ValueError, match=r"^beta must be <= "):
        hertz.hertz_force(0.0, 1e-300, beta_max * (1 + 1e-12))


def test_radius_overflow_limit():
    beta = 1e200
    u_max = (FLOAT_MAX / beta) ** 2
    assert np.isfinite(hertz.hertz_radius(u_max * (1 - 1e-12), beta))
    with pytest.raises(ValueError, match=r"^u_bar must be <= "):
        hertz.hertz_radius(u_max * (1 + 1e-12), beta)


@pytest.mark.parametrize("func, limit", [(hertz.hertz_load_md, np.cbrt(FLOAT_MAX)),
                                         (hertz.hertz_penetration_md, np.sqrt(FLOAT_MAX))])
def test_maugis_units_overflow_limit(func, limit):
    assert np.isfinite(func(limit * (1 - 1e-12)))
    with pytest.raises(ValueError, match=r"^A must be <= "):
        func(limit * (1 + 1e-12))


BAD = [None, True, 1j, {"u": 1}, "1.0", np.ma.masked_array([1.0], mask=[True]), np.nan, np.inf]


@pytest.mark.parametrize("bad", BAD, ids=repr)
def test_bad_input_names_the_parameter(bad):
    for call, name in ((lambda: hertz.hertz_radius(bad, 10.0), "u_bar"), (lambda: hertz.hertz_radius(1.0, bad), "beta"),
                       (lambda: hertz.hertz_force(bad, 0.1, 10.0), "u_bar"),
                       (lambda: hertz.hertz_force(1.0, bad, 10.0), "alpha"),
                       (lambda: hertz.hertz_force(1.0, 0.1, 10.0, bad), "nu"),
                       (lambda: hertz.hertz_load_md(bad), "A"), (lambda: hertz.hertz_penetration_md(bad), "A")):
        with pytest.raises(ValueError, match=f"^{name}"):
            call()


def test_physical_shell():
    import math

    R, E_star = 1e-6, 2e9
    K = 4 / 3 * E_star
    P = np.array([0.0, 1e-6, 3e-3])
    np.testing.assert_allclose(hertz.hertz_contact_radius(P, R=R, E_star=E_star) ** 3, P * R / K, rtol=1e-14)
    delta = np.array([0.0, 1e-9, 1e-7])
    np.testing.assert_allclose(hertz.hertz_normal_force(delta, R=R, E_star=E_star), K * math.sqrt(R) * delta**1.5,
                               rtol=1e-15)
    # a^2 = R delta links the two (Johnson 1985, Eq 4.22)
    a = hertz.hertz_contact_radius(hertz.hertz_normal_force(delta, R=R, E_star=E_star), R=R, E_star=E_star)
    np.testing.assert_allclose(a**2, R * delta, rtol=1e-14)
    with pytest.raises(ValueError, match="without adhesion"):
        hertz.hertz_contact_radius([-1e-9], R=R, E_star=E_star)
    with pytest.raises(ValueError, match="without adhesion"):
        hertz.hertz_normal_force([-1e-9], R=R, E_star=E_star)
    with pytest.raises(ValueError, match="^E_star must be > 0"):
        hertz.hertz_contact_radius([1.0], R=R, E_star=0.0)
