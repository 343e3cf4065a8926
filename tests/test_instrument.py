"""The instrument's spring (asperity.instrument) on a synthetic force law with known answers.

The force P(d) = -c exp(-(d - 1)^2) (a tensile well) held by a spring of stiffness k: where
P'(d) = 2c (d - 1) exp(-(d - 1)^2) exceeds k the equilibrium d - P/k = Z is unstable.  The folds
are roots of P' = k (found here by brentq), the landings roots of Z(d) = Z_fold, the jump
energies integrals by scipy.integrate.quad: all independent of the module.
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy import integrate, optimize

from asperity.instrument import base_displacement, jump_energy, spring_path

C = 10.0


def P(x):
    return -C * np.exp(-((x - 1.0) ** 2))


def dP(x):
    return 2.0 * C * (x - 1.0) * np.exp(-((x - 1.0) ** 2))


def force(x, order):
    x = np.asarray(x, dtype=float)
    return P(x), (dP(x) if order else None)


def run(k, branch, n=400):
    d = np.linspace(-3.0, 5.0, n)
    if branch == "approach":
        d = d[::-1]
    return spring_path(d, P(d), dP(d), dP(d), k, force, branch=branch, d_top=50.0)


@pytest.mark.parametrize("branch", ["approach", "retract"])
@pytest.mark.parametrize("k", [2.0, 5.0])
def test_folds_landings_and_energies(branch, k):
    pts, jump, jumps = run(k, branch)
    assert len(jumps) == 1 and jump.sum() == 1
    j = jumps[0]
    # The fold: P'(d) = k on the side the path arrives from.
    peak = 1.0 + math.sqrt(0.5)  # P' is largest here
    lo, hi = (peak, 5.0) if branch == "approach" else (1.0, peak)
    fold = optimize.brentq(lambda x: dP(x) - k, lo, hi, xtol=1e-14)
    assert j.d_from == pytest.approx(fold, abs=1e-9)
    Z = fold - P(fold) / k
    assert j.d_base == pytest.approx(Z, abs=1e-12)
    lo, hi = (-3.0, 1.0) if branch == "approach" else (peak, 50.0)  # a jump out may land beyond the path
    land = optimize.brentq(lambda x: x - P(x) / k - Z, lo, hi, xtol=1e-14)
    assert j.d_to == pytest.approx(land, abs=1e-9)
    energy = integrate.quad(lambda x: P(x) - k * (x - Z), j.d_from, j.d_to, epsabs=0, epsrel=1e-12)[0]
    assert jump_energy(j, force, k) == pytest.approx(abs(energy), rel=1e-10)
    # The visited base positions move one way only.
    Zs = base_displacement(pts, P(pts), k)
    steps = np.diff(Zs) * (1.0 if branch == "retract" else -1.0)
    assert np.all(steps >= -1e-12)
    assert pts[np.flatnonzero(jump)[0]] == j.d_to


@settings(max_examples=30, deadline=None)
@given(st.floats(min_value=0.1, max_value=100.0), st.sampled_from(["approach", "retract"]))
def test_stable_when_stiffer_than_the_force(k, branch):
    pts, jump, jumps = run(k, branch, n=200)
    stiff = k > 2.0 * C * math.sqrt(0.5) * math.exp(-0.5)  # max P'
    assert (jumps == []) == stiff
    if stiff:
        np.testing.assert_array_equal(np.sort(pts), np.linspace(-3.0, 5.0, 200))
    Zs = base_displacement(pts, P(pts), k)
    assert np.all(np.diff(Zs) * (1.0 if branch == "retract" else -1.0) >= -1e-12)


def test_infinite_stiffness_is_the_separation():
    d = np.array([0.0, 1.0])
    np.testing.assert_array_equal(base_displacement(d, [3.0, -2.0], math.inf), d)


def test_jump_out_beyond_d_top_lands_where_the_force_vanishes():
    d = np.linspace(-3.0, 2.0, 200)
    pts, jump, jumps = spring_path(d, P(d), dP(d), dP(d), 0.5, force, branch="retract", d_top=2.5)
    j = jumps[-1]
    assert j.P_to == 0.0 and j.d_to == pytest.approx(j.d_base) and pts[-1] == j.d_to
    # energy: the force up to d_top, then the spring alone
    numeric = integrate.quad(lambda x: P(x) - 0.5 * (x - j.d_base), j.d_from, 2.5, epsrel=1e-12)[0]
    tail = 0.25 * (j.d_base - 2.5) ** 2
    assert jump_energy(j, force, 0.5, d_top=2.5) == pytest.approx(numeric + tail, rel=1e-10)


def test_approach_ending_inside_a_jump_is_refused():
    d = np.linspace(5.0, 1.2, 100)  # ends between the fold and the landing
    with pytest.raises(ValueError, match="never a stable state"):
        spring_path(d, P(d), dP(d), dP(d), 2.0, force, branch="approach")


def test_base_displacement_broadcasts_over_the_stiffness():
    d, P = np.array([1.0, 2.0, -3.0]), np.array([10.0, -5.0, 0.5])
    k = np.array([[0.5], [10.0], [math.inf]])
    Z = base_displacement(d, P, k)
    assert Z.shape == (3, 3)
    for i in range(3):
        assert Z[i].tolist() == base_displacement(d, P, float(k[i, 0])).tolist()
    assert Z[2].tolist() == d.tolist()  # an infinitely stiff spring: displacement control
    assert Z[0].tolist() == (d - P / 0.5).tolist()
    assert isinstance(base_displacement(1.0, 2.0, 4.0), np.float64)
    with pytest.raises(ValueError, match=r"stiffness .* must be >= 1e-100 .* got -1.0"):
        base_displacement(d, P, [1.0, -1.0, 2.0])
    with pytest.raises(ValueError, match=r"d, P, stiffness must have shapes that broadcast together"):
        base_displacement(d, P, [1.0, 2.0])
    with pytest.raises(ValueError, match=r"the base displacement overflows double precision"):
        base_displacement(1.0, 1e300, 1e-100)


def test_jump_energy_of_a_soft_spring_and_a_narrow_distribution():
    # A helper's trial: the retraction jump crosses 22 sigma while the force of a narrow height
    # distribution dies within ~1 sigma; fixed panels (4 x 16 nodes) gave 6880.8 for 6916.1.
    # Here the energy is re-integrated independently (Simpson on 40001 points of the library's
    # own retraction curve, evaluated through cycle(d=...)).
    from asperity.cycle import cycle
    from asperity.heights import Mixture

    p = dict(h_over_b=1e-3, heights=Mixture(0.99, 0.0, 0.005, -1.0, 0.005))
    c = cycle(0.02, 50, 0.02, preload=50.0, stiffness=30.0, n=200, **p)
    jump = next(j for j in c.jumps if j.branch == "retract")
    xs = np.linspace(jump.d_from, jump.d_to, 40001)
    inside = xs <= c.d_max
    P = np.zeros_like(xs)
    P[inside] = cycle(0.02, 50, 0.02, d_min=c.d_min, d=xs[inside], **p).retract.P
    own = integrate.simpson(P - 30.0 * (xs - jump.d_base), x=xs)
    assert jump.energy == pytest.approx(abs(own), rel=1e-6)


def test_jump_energy_is_exact_for_a_polynomial_force():
    from asperity.instrument import Jump

    def force(x, order):
        return (x**3 - 2 * x,)
    j = Jump(branch="retract", d_from=0.5, d_to=7.25, d_base=1.0, P_from=0.0, P_to=0.0, energy=0.0)
    exact = integrate.quad(lambda x: x**3 - 2 * x - 4.0 * (x - 1.0), 0.5, 7.25)[0]
    assert jump_energy(j, force, 4.0, kinks=(2.0, 3.5)) == pytest.approx(abs(exact), rel=1e-13)


def test_jump_energy_with_a_nan_force_is_nan_and_cheap():
    # A review: a NaN panel never agreed with its halves, and the panels doubled for 40 levels (24 GB).
    from asperity.instrument import Jump

    calls = []

    def force(x, order):
        calls.append(x.size)
        return (np.where(x > 3, np.nan, 1.0),)
    j = Jump(branch="retract", d_from=0.5, d_to=7.25, d_base=1.0, P_from=0.0, P_to=0.0, energy=0.0)
    assert math.isnan(jump_energy(j, force, 4.0)) and sum(calls) < 10**4


def test_jump_energy_wholly_beyond_the_top():
    # A review: both ends beyond d_top integrated the spring from d_top (70.125 for 60.125).
    from asperity.instrument import Jump

    j = Jump(branch="retract", d_from=4.0, d_to=7.25, d_base=1.0, P_from=0.0, P_to=0.0, energy=0.0)
    exact = abs(integrate.quad(lambda x: -4.0 * (x - 1.0), 4.0, 7.25)[0])
    assert jump_energy(j, lambda x, o: (np.zeros_like(x),), 4.0, d_top=3.0) == pytest.approx(exact, rel=1e-14)
