"""The per-asperity law (asperity.asperity_law): the ContactLaw protocol, plugging a law into the
integrals and curves, and where AsperityLaw puts its breakpoints."""

import numpy as np
import pytest

import asperity
from asperity.asperity_law import AsperityLaw, ContactLaw, ModelParameters, check_law
from asperity.friction_stress import HurtadoKim


class HalfForce:
    """A stand-in for another law (e.g. elastic-plastic): the default radius, half the force."""

    def __init__(self, params):
        self.inner = AsperityLaw(params)
        self.params = params
        self.u_end, self.scale, self.breakpoints = self.inner.u_end, self.inner.scale, self.inner.breakpoints

    def evaluate(self, u_bar):
        a, P = self.inner.evaluate(u_bar)
        return a, 0.5 * P

    def friction(self, a_bar):
        return self.inner.friction(a_bar)


@pytest.mark.parametrize("gamma", [0.0, 1e-3])
def test_a_plugged_in_law_runs_through_model(gamma):
    params = ModelParameters(0.01, 1000.0, gamma)
    law = HalfForce(params)
    assert isinstance(law, ContactLaw) and isinstance(AsperityLaw(params), ContactLaw)
    half = asperity.Model(0.01, 1000.0, gamma, law=law)
    full = asperity.Model(0.01, 1000.0, gamma)
    d = np.linspace(-2.0, 3.0, 11)
    a, b = half.separation_curve(d), full.separation_curve(d)
    np.testing.assert_allclose(a.P, 0.5 * b.P, rtol=1e-15)
    np.testing.assert_array_equal(a.F, b.F)
    # the separation under a load P is the default model's under 2P
    P = np.array([0.5, 5.0, 50.0])
    lh, lf = half.load_curve(P), full.load_curve(2 * P)
    np.testing.assert_allclose(lh.d, lf.d, rtol=1e-10, atol=1e-12)
    np.testing.assert_allclose(lh.F, lf.F, rtol=1e-9)
    if gamma:
        assert half.pull_off().force == pytest.approx(0.5 * full.pull_off().force, rel=1e-12)


def test_check_law():
    params = ModelParameters(0.01, 1000.0)
    assert isinstance(check_law(None, params), AsperityLaw)
    law = AsperityLaw(params)
    assert check_law(law, params) is law
    with pytest.raises(ValueError, match="ContactLaw"):
        check_law(lambda u: u, params)
    with pytest.raises(ValueError, match="built for"):
        check_law(law, ModelParameters(0.02, 1000.0))
    with pytest.raises(ValueError, match="built for"):
        asperity.Model(0.01, 1000.0, 1e-3, law=law)


@pytest.mark.parametrize("gamma", [0.0, 1e-3, 2e-2])
def test_breakpoints_are_where_the_radius_crosses_a1_and_a2(gamma):
    hk = HurtadoKim(a1=5.0, a2=300.0)
    law = AsperityLaw(ModelParameters(0.02, 100.0, gamma, friction=hk))
    # radii below the branch end's never occur (with strong adhesion a1 is one of them)
    a_end = law.end.A / law.A_hat if gamma else 0.0
    expected = [r for r in (5.0, 300.0) if r > a_end]
    assert len(law.breakpoints) == len(expected) >= 1 and all(u > law.u_end for u in law.breakpoints)
    a, _ = law.evaluate(np.array(law.breakpoints))
    np.testing.assert_allclose(a, expected, rtol=1e-9)


def test_radii_beyond_the_curve_give_no_breakpoint():
    # a2 so large its Maugis radius exceeds A_MAX: no breakpoint, and no error
    law = AsperityLaw(ModelParameters(0.01, 1000.0, 1e-3, friction=HurtadoKim(a1=28.0, a2=1e150)))
    assert len(law.breakpoints) == 1
