"""The integrals for non-factorising heights (asperity.height_sums): tabulated in d, interpolated.

Against the Gaussian's own factorised path (the engine run on the Gaussian), the Hertz
closed forms F_n of every family, finite differences, and the kernel/direct equivalence.
"""

import dataclasses

import numpy as np
import pytest

from asperity.asperity_law import AsperityLaw, ModelParameters
from asperity.height_sums import HeightSums
from asperity.heights import GAUSSIAN, Exponential, Gaussian, Johnson, PearsonIII
from asperity.heights.mixture import KernelGaussian
from asperity.tabulation import Tabulation

from .heights_cases import CASES, fast

ALPHA, BETA, NU = 0.01, 1000.0, 0.3


@dataclasses.dataclass(frozen=True)
class SlowGaussian(Gaussian):
    """The Gaussian sent through the interpolating engine instead of its factorised sums."""

    fast_sums = False


def rel(a, b, scale):
    return np.max(np.abs(a - b) / np.maximum(scale, 1e-300))


@pytest.mark.parametrize("params", [(0.01, 1000.0, 0.0), (0.01, 1000.0, 1e-3), (0.02, 50.0, 2e-2)])
def test_engine_reproduces_the_gaussian_path(params):
    p = ModelParameters(*params)
    exact, engine = Tabulation(p, -6.0, 20.0), Tabulation(p, -6.0, 20.0, SlowGaussian())
    assert engine.height_sums is not None and exact.height_sums is None
    d = np.random.default_rng(3).uniform(-6.0, 20.0, 400)
    ref = exact.sums(d, order=2)
    got = engine.sums(d, order=2)
    scale = np.abs(ref[0])
    assert rel(got[0], ref[0], scale) < 1e-12  # relative, also far in the tail (d = 20)
    # derivatives, relative to max(|S_j|, |S_0|) per column: spectral differentiation of the
    # interpolant costs a few digits (~n^4 eps (2/W)^2 for the second)
    for j, tol in ((1, 1e-10), (2, 5e-10)):
        assert rel(got[j], ref[j], np.maximum(np.abs(ref[j]), scale)) < tol


@pytest.mark.parametrize("case", list(CASES))
def test_hertz_integrals_are_the_gw_moments(case):
    """Without adhesion n/N = F_0, A/(N pi b^2) = beta^2 F_1, P/(NGb^2) = (4/3)(2/(1-nu)) alpha beta^2 F_3/2."""
    dist = fast(case)
    tab = Tabulation(ModelParameters(ALPHA, BETA), -5.0, 8.1, dist)
    d = np.linspace(-5.0, 8.0, 53) + 0.0123
    S = tab.sums(d)[0]
    F0, F1, F15 = (dist.moment(d, n) for n in (0, 1, 1.5))
    live = F0 > 1e-250
    np.testing.assert_allclose(S[live, 0], F0[live], rtol=1e-11)
    np.testing.assert_allclose(S[live, 3], BETA**2 * F1[live], rtol=1e-11)
    np.testing.assert_allclose(S[live, 1], 4 / 3 * 2 / (1 - NU) * ALPHA * BETA**2 * F15[live], rtol=1e-11)


@pytest.mark.parametrize("dist", [Exponential(), PearsonIII(-1.2), Johnson(-0.5, 3.2)], ids=repr)
def test_derivatives_are_those_of_the_integrals(dist):
    tab = Tabulation(ModelParameters(0.01, 1000.0, 1e-3), -4.0, 6.0, dist)
    d = np.array([-3.3, -1.7, -0.4, 0.9, 2.2, 4.1])
    h = 1e-3
    S0, S1, S2 = tab.sums(d, order=2)
    Sp2, Sp, Sm, Sm2 = (tab.sums(d + k * h)[0] for k in (2, 1, -1, -2))
    fd1 = (-Sp2 + 8 * Sp - 8 * Sm + Sm2) / (12 * h)  # five-point stencils, error ~ h^4
    fd2 = (-Sp2 + 16 * Sp - 30 * S0 + 16 * Sm - Sm2) / (12 * h * h)
    scale = np.maximum(np.abs(S1), np.abs(S0))
    assert rel(S1, fd1, scale) < 1e-8
    assert rel(S2, fd2, np.maximum(np.abs(S2), scale)) < 1e-6


def test_support_edges_meeting_the_law_are_resolved():
    # the exponential's jump meets the Maugis-Dugdale branch end at d* = -1 - u_end: the sums
    # stay continuous across it and agree with the closed form on both sides (Hertz)
    e = Exponential()
    tab = Tabulation(ModelParameters(ALPHA, BETA), -3.0, 3.0, e)
    d = -1.0 + np.array([-1e-3, -1e-7, -1e-11, 0.0, 1e-11, 1e-7, 1e-3])
    S = tab.sums(d)[0]
    np.testing.assert_allclose(S[:, 0], e.moment(d, 0), rtol=1e-12)
    np.testing.assert_allclose(S[:, 1], 4 / 3 * 2 / (1 - NU) * ALPHA * BETA**2 * e.moment(d, 1.5), rtol=1e-11)


def test_zero_beyond_a_bounded_support():
    p = PearsonIII(-1.2)  # heights end at 2/1.2 above the mean
    tab = Tabulation(ModelParameters(ALPHA, BETA), -2.0, 4.0, p)
    edge = p.support[1]
    S = tab.sums(np.array([edge - 1e-3, edge + 1e-9, edge + 1.0]), order=1)
    assert np.all(S[0][0] > 0) and np.all(S[0][1:] == 0) and np.all(S[1][1:] == 0)


def test_wider_tabulation_inherits_the_computed_panels():
    p = ModelParameters(0.01, 1000.0, 1e-3)
    dist = Exponential()
    tab = Tabulation(p, -3.0, 5.0, dist)
    d = np.linspace(-3.0, 5.0, 41)
    first = tab.sums(d)[0]
    computed = int((tab.height_sums._state > 0).sum())
    wide = tab.extended(-8.0, 12.0)
    assert int((wide.height_sums._state > 0).sum()) >= computed
    np.testing.assert_allclose(wide.sums(d)[0], first, rtol=1e-14)
    fresh = Tabulation(p, -8.0, 12.0, dist)
    np.testing.assert_allclose(fresh.sums(d)[0], first, rtol=1e-12)


def test_kernel_translates_equal_the_direct_mixture():
    emp = fast("empirical")
    law = AsperityLaw(ModelParameters(0.01, 1000.0, 1e-3))
    kernel = HeightSums(law, emp, -4.0, 6.0)

    class Direct(type(emp)):  # the same mixture, summed component by component
        def translates(self):
            return None

    direct = HeightSums(law, Direct(emp.means, emp.weights, emp.sd), -4.0, 6.0)
    d = np.linspace(-4.0, 6.0, 37)
    a, b = kernel.sums(d, order=1), direct.sums(d, order=1)
    assert rel(a[0], b[0], np.abs(b[0])) < 1e-11
    assert rel(a[1], b[1], np.maximum(np.abs(b[1]), np.abs(b[0]))) < 1e-9
    assert KernelGaussian(0.3) == KernelGaussian(0.3) and "0.3" in repr(KernelGaussian(0.3))


def test_separations_outside_the_range_are_refused():
    tab = Tabulation(ModelParameters(ALPHA, BETA), -1.0, 1.0, Exponential())
    with pytest.raises(ValueError, match="outside the range"):
        tab.sums([40.0])
    assert tab.sums([]) [0].shape == (0, 4)


def test_the_gaussian_keeps_its_own_path():
    tab = Tabulation(ModelParameters(ALPHA, BETA), -1.0, 1.0, GAUSSIAN)
    assert tab.height_sums is None and tab.heights.fast_sums


@pytest.mark.parametrize("case", list(CASES))
@pytest.mark.parametrize("gamma", [0.0, 1e-3])
def test_contact_fraction_never_passes_one(case, gamma):
    # deep in contact every asperity touches: n/N = integral of phi = 1, and the quadrature's
    # round-off (a few ulps above 1 before the clip) must not make it more than all of them
    dist = fast(case)
    tab = Tabulation(ModelParameters(ALPHA, BETA, gamma), -25.0, 5.0, dist)
    d = np.linspace(-25.0, 5.0, 3001)
    n = tab.sums(d, order=1)[0][:, 0]
    assert np.all(n <= 1.0) and np.all(n >= 0.0)
    assert n[0] == pytest.approx(1.0, abs=1e-12)
