"""Maugis-Dugdale under load control (asperity.maugis_dugdale_load): the inversion against the
curve and the independent mpmath path, the JKR and DMT limits, the physical shell."""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from asperity import dmt, jkr, reference
from asperity import maugis_dugdale as md
from asperity import maugis_dugdale_load as mdl

R, W, E_STAR = 20e-9, 0.3, 1e11


@given(st.floats(-6, 6), st.floats(0.0, 1.0), st.floats(-3, 8))
def test_inverts_the_load_on_the_load_stable_branch(log_lam, frac, log_P):
    lam = 10.0**log_lam
    po = md.md_pull_off(lam, "load")
    P = np.array([po.P + frac * (1.0 - po.P), 10.0**log_P])  # near the pull-off, and far above it
    A, delta, t = mdl.md_solve_load(P, lam)
    end = ~np.isfinite(t)  # the pull-off at the limit A -> 0 (t = inf): the closed-form end point
    assert np.all(A[end] == po.A) and np.all(P[end] == po.P)
    A2, P2, D2 = md.md_curve(t[~end], lam)
    np.testing.assert_allclose(P2, P[~end], rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(A2, A[~end], rtol=1e-15)
    np.testing.assert_allclose(D2, delta[~end], rtol=1e-15)
    assert np.all(t <= po.t)  # before the first minimum of P(t): the load-stable branch


@pytest.mark.parametrize("lam", [0.05, 0.5, 0.938, 1.0, 3.0, 30.0])
@pytest.mark.parametrize("P", [-1.0, 0.0, 2.5, 1e3])
def test_against_the_reference(lam, P):
    if P < md.md_pull_off(lam, "load").P:
        pytest.skip("below the pull-off")
    A_ref, D_ref = reference.md_load_point(P, lam)
    A, D, _ = mdl.md_solve_load([P], lam)
    assert A[0] == pytest.approx(A_ref, rel=1e-12)
    assert D[0] == pytest.approx(D_ref, rel=1e-11, abs=1e-12)


def test_pull_off_is_the_end_of_the_branch():
    for lam in (1e-3, 0.5, 2.0, 1e3):
        po = md.md_pull_off(lam, "load")
        A, D, t = mdl.md_solve_load([po.P], lam)
        assert (A[0], D[0], t[0]) == (po.A, po.delta, po.t)
        with pytest.raises(ValueError, match=r"^P \(load over pi w R\) must lie in"):
            mdl.md_solve_load([po.P - 1e-9], lam)


def test_radius_grows_with_the_load():
    P = np.linspace(md.md_pull_off(0.7).P, 50.0, 400)
    A = mdl.md_solve_load(P, 0.7)[0]
    assert np.all(np.diff(A) > 0)


@pytest.mark.parametrize("lam, tol", [(1e4, 1e-6), (1e8, 1e-13)])
def test_jkr_limit(lam, tol):
    P = np.linspace(-1.5 * math.pi * W * R * (1 - 1e-6), 80e-9, 50)
    a = mdl.md_contact_radius(P, R=R, w=W, E_star=E_STAR, lam=lam)
    np.testing.assert_allclose(a, jkr.jkr_contact_radius(P, R=R, w=W, E_star=E_STAR), rtol=tol)
    pull = mdl.md_pull_off_force(R=R, w=W, E_star=E_STAR, lam=lam)
    assert pull == pytest.approx(1.5 * math.pi * W * R, rel=tol)  # -3/2 pi w R


@pytest.mark.parametrize("lam, tol", [(1e-6, 1e-5), (1e-12, 1e-11)])
def test_dmt_limit(lam, tol):
    P = np.linspace(-2.0 * math.pi * W * R * (1 - 1e-3), 80e-9, 50)
    a = mdl.md_contact_radius(P, R=R, w=W, E_star=E_STAR, lam=lam)
    np.testing.assert_allclose(a, dmt.dmt_contact_radius(P, R=R, w=W, E_star=E_STAR), rtol=tol)
    pull = mdl.md_pull_off_force(R=R, w=W, E_star=E_STAR, lam=lam)
    assert pull == pytest.approx(2.0 * math.pi * W * R, rel=tol)  # -2 pi w R


def test_physical_shell_is_maugis_units():
    K = 4 / 3 * E_STAR
    sigma0 = 2e9
    lam = float(md.md_lambda(R, W, E_STAR, sigma0))
    assert lam == pytest.approx(2 * sigma0 * (R / (math.pi * W * K**2)) ** (1 / 3), rel=1e-15)
    P = np.array([-5e-9, 0.0, 3e-8])
    a = mdl.md_contact_radius(P, R=R, w=W, E_star=E_STAR, sigma0=sigma0)
    A = mdl.md_solve_load(P / (math.pi * W * R), lam)[0]
    np.testing.assert_allclose(a, A * (math.pi * W * R**2 / K) ** (1 / 3), rtol=1e-14)
    np.testing.assert_array_equal(a, mdl.md_contact_radius(P, R=R, w=W, E_star=E_STAR, lam=lam))
    # Force against penetration: the stable branch of md_solve
    delta = np.array([-0.5, 0.0, 2.0]) * (math.pi**2 * W**2 * R / K**2) ** (1 / 3)
    F = mdl.md_normal_force(delta, R=R, w=W, E_star=E_STAR, lam=lam)
    np.testing.assert_allclose(F, md.md_solve([-0.5, 0.0, 2.0], lam)[1] * math.pi * W * R, rtol=1e-14)
    assert mdl.md_pull_off_force(R=R, w=W, E_star=E_STAR, lam=lam, control="displacement") == pytest.approx(
        -md.md_branch_end(lam).P * math.pi * W * R, rel=1e-15)


def test_normal_force_limits():
    delta = np.linspace(0.0, 2e-9, 9)
    np.testing.assert_allclose(mdl.md_normal_force(delta, R=R, w=W, E_star=E_STAR, lam=1e-12),
                               dmt.dmt_normal_force(delta, R=R, w=W, E_star=E_STAR), rtol=1e-5)
    np.testing.assert_allclose(mdl.md_normal_force(delta, R=R, w=W, E_star=E_STAR, lam=1e8),
                               jkr.jkr_normal_force(delta, R=R, w=W, E_star=E_STAR), rtol=1e-12)


@pytest.mark.parametrize("kwargs, match", [
    ({"R": R, "w": W, "E_star": E_STAR}, "exactly one of sigma0"),
    ({"R": R, "w": W, "E_star": E_STAR, "sigma0": 1e9, "lam": 1.0}, "exactly one of sigma0"),
    ({"R": -R, "w": W, "E_star": E_STAR, "lam": 1.0}, "^R must be > 0"),
    ({"R": R, "w": 0.0, "E_star": E_STAR, "lam": 1.0}, "^w must be > 0"),
    ({"R": R, "w": W, "E_star": np.nan, "lam": 1.0}, "^E_star must be finite"),
    ({"R": R, "w": W, "E_star": E_STAR, "lam": 1e13}, "lam"),
    ({"R": [R, R], "w": [W, W, W], "E_star": E_STAR, "lam": 1.0}, "^R, w, E_star, lam must have shapes that broadcast"),
    ({"R": R, "w": W, "E_star": E_STAR, "lam": [1.0, 1e13]}, "^lam"),
    ({"R": 1e-300, "w": W, "E_star": E_STAR, "sigma0": 1e9}, "^R, w, E_star, sigma0 give the Maugis parameter"),
    ({"R": R, "w": [W, W], "E_star": E_STAR, "sigma0": [1e9, 1e9, 1e9]}, "^R, w, E_star, sigma0 must have shapes"),
])
def test_bad_physical_input(kwargs, match):
    with pytest.raises(ValueError, match=match):
        mdl.md_contact_radius([0.0], **kwargs)


@pytest.mark.parametrize("bad, match", [([np.nan], "^P must be finite"), (["x"], "^P must be a real"),
                                        ([1e201], "must lie in"), (None, "^P must be a real")])
def test_bad_load(bad, match):
    with pytest.raises(ValueError, match=match):
        mdl.md_solve_load(bad, 1.0)
    assert mdl.md_solve_load([], 1.0)[0].shape == (0,)


# -- broadcasting over the sphere, the material and lambda (like a ufunc) ----------------------
RADII = np.array([[10e-9], [1e-6], [30e-6]])  # (3, 1)
WORKS = np.array([0.05, 0.1, 0.3, 1.0])        # (4,)


def _loop(func, shape, **kwargs):
    """The scalar calls, one per element of the broadcast inputs (the slow path)."""
    arrays = np.broadcast_arrays(*kwargs.values())
    out = np.empty(shape)
    for index in np.ndindex(shape):
        out[index] = float(func(**{k: float(a[index]) for k, a in zip(kwargs, arrays, strict=True)}))
    return out


@pytest.mark.parametrize("adhesion", [{"sigma0": 1e9}, {"lam": np.array([1e-3, 0.3, 3.0, 1e4])},
                                      {"sigma0": np.array([[1e8], [1e9], [3e10]])}])
def test_physical_shell_broadcasts_like_a_ufunc(adhesion):
    """R (3, 1) with w (4,) and a Dugdale stress or lambda, scalar or array: (3, 4) results equal to
    the scalar calls, whichever lambdas the elements share."""
    common = {"R": RADII, "w": WORKS, "E_star": E_STAR, **adhesion}
    F = mdl.md_pull_off_force(**common)
    assert F.shape == (3, 4)
    np.testing.assert_allclose(F, _loop(mdl.md_pull_off_force, (3, 4), **common), rtol=1e-15)
    P = -0.5 * F  # within the load-stable branch of every element
    a = mdl.md_contact_radius(P, **common)
    np.testing.assert_allclose(a, _loop(mdl.md_contact_radius, (3, 4), P=P, **common), rtol=1e-13)
    delta = np.array([1e-10, 5e-10, 1e-9, 2e-9])
    f = mdl.md_normal_force(delta, **common)
    np.testing.assert_allclose(f, _loop(mdl.md_normal_force, (3, 4), delta=delta, **common), rtol=1e-13)
    assert isinstance(mdl.md_pull_off_force(R=R, w=W, E_star=E_STAR, lam=1.0), float)


def test_broadcast_shell_keeps_the_limits():
    """JKR (lambda -> inf) and DMT (lambda -> 0) side by side in one call."""
    lam = np.array([1e8, 1e-10])
    F = mdl.md_pull_off_force(R=R, w=W, E_star=E_STAR, lam=lam)
    np.testing.assert_allclose(F / (math.pi * W * R), [1.5, 2.0], rtol=1e-4)
    a = mdl.md_contact_radius(0.0, R=R, w=W, E_star=E_STAR, lam=lam)
    np.testing.assert_allclose(a, [float(jkr.jkr_contact_radius(0.0, R=R, w=W, E_star=E_STAR)),
                                   float(dmt.dmt_contact_radius(0.0, R=R, w=W, E_star=E_STAR))], rtol=1e-4)
    assert mdl.md_normal_force(np.empty((0, 2)), R=R, w=W, E_star=E_STAR, lam=lam).shape == (0, 2)


def test_penetration_in_maugis_units_broadcasts():
    D, unit = mdl.penetration_in_maugis_units(1e-9, R=RADII, w=WORKS, E_star=E_STAR)
    assert D.shape == (3, 4) and unit.shape == (3, 4)
    K = 4.0 / 3.0 * E_STAR
    np.testing.assert_allclose(D, 1e-9 / np.cbrt(math.pi**2 * WORKS**2 * RADII / K**2), rtol=1e-15)
    np.testing.assert_allclose(unit, math.pi * WORKS * RADII, rtol=1e-15)


@pytest.mark.parametrize("lam", [0.05, 1.0, 10.0, 1e3])
@pytest.mark.parametrize("ulps", [1, 2, 4, 16])
def test_a_load_ulps_above_the_pull_off_is_solved(lam, ulps):
    # Found by hypothesis in CI (lam = 10, frac = 2.2e-16): the residual at the pull-off was
    # already at rounding level, and a Newton step taken from there, where P(t) is flat, moved
    # the answer to P = -1.501595 for -1.501625.
    po = md.md_pull_off(lam, "load")
    P = po.P + ulps * np.spacing(abs(po.P))
    A, delta, t = mdl.md_solve_load([P], lam)
    A2, P2, D2 = md.md_curve(t, lam)
    np.testing.assert_allclose(P2, [P], rtol=1e-12, atol=1e-12)
    assert t[0] <= po.t


@pytest.mark.parametrize("lam", [None, 0.3, 1.0, 5.0])
def test_refusals_below_the_branch_are_in_si_units(lam):
    """A user trial: -5 nm was refused as 'got values from -1.31068' (Maugis' units).  Now the
    floor and the value are in metres or newtons, and the floor is where the solver's own
    range ends: just above it is solved, just below refused."""
    import re

    from asperity.jkr import jkr_normal_force
    from asperity.maugis_dugdale_load import md_contact_radius, md_normal_force

    kw = {"R": 1e-6, "w": 0.1, "E_star": 1e9}
    routes = [(jkr_normal_force, "delta (penetration)", "m", -1e-6)] if lam is None else [
        (lambda x, **k: md_normal_force(x, lam=lam, **k), "delta (penetration)", "m", -1e-6),
        (lambda x, **k: md_contact_radius(x, lam=lam, **k), "P (load)", "N", -1e-3)]
    for f, name, unit, far in routes:
        with pytest.raises(ValueError) as info:
            f([1e-9, far], **kw)
        m = re.fullmatch(rf"{re.escape(name)} must be >= (\S+) {unit} \(.*\), got (\S+) {unit}", str(info.value))
        assert m and float(m.group(2)) == far, str(info.value)
        floor = float(m.group(1))
        assert np.isfinite(f(floor * (1 - 1e-4), **kw)).all()
        with pytest.raises(ValueError, match=f"must be >= {re.escape(m.group(1))} {unit}"):
            f(floor * (1 + 1e-4), **kw)


def test_a_floor_that_differs_from_value_to_value_says_so():
    """A review: with arrays of R one value's floor was printed as the floor of all."""
    from asperity.maugis_dugdale_load import md_contact_radius

    with pytest.raises(ValueError, match=r"got -1e-07 N \(the first value below its floor; each value's R, w, E\* "
                                         r"set its own\)$"):
        md_contact_radius([-1e-7, -1e-7], R=[1e-6, 1e-8], w=0.1, E_star=1e9, lam=1.0)
    with pytest.raises(ValueError, match=r"got -1e-06 N$"):
        md_contact_radius([-1e-6, 1e-9], R=20e-9, w=0.1, E_star=100e9, lam=1.0)
