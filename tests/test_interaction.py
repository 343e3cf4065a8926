"""The mean-field interaction of Ciavarella, Greenwood & Paggi (2008): closed forms, limits, hooks."""

import math

import numpy as np
import pytest

from asperity.curves import Model, load_curve, separation_curve
from asperity.interaction import (
    CGP_MEAN_COMPLIANCE,
    INTERACTIONS,
    MeanFieldInteraction,
    NoInteraction,
    as_interaction,
    cgp_compliance,
    cgp_shift,
    interaction_for_surface,
    interaction_names,
)
from asperity.physical import PhysicalContact, Surface

# Elastic comparisons on gold, which yields at these loads: the plasticity note is expected.
pytestmark = pytest.mark.filterwarnings("ignore::asperity.plasticity.PlasticityWarning")


SURFACE = Surface(sigma_s=2e-9, R=1e-6, eta=1e12, area=1e-6)


def test_mean_compliance_of_a_circle():
    # Mean displacement of a uniformly loaded circle: 16 p a / (3 pi E*) (Johnson 1985, 3.4), by quadrature:
    # u(r) = (4 p a / pi E*) E(r/a) (complete elliptic integral of the 2nd kind), averaged over the disc.
    from scipy import integrate, special

    mean, _ = integrate.quad(lambda r: 4 / math.pi * special.ellipe(r * r) * 2 * r, 0, 1)
    assert mean == pytest.approx(16 / (3 * math.pi), rel=1e-10)
    assert CGP_MEAN_COMPLIANCE == pytest.approx(mean / math.sqrt(math.pi), rel=1e-10)


def test_cgp_shift_closed_form_and_broadcast():
    p = np.array([0.0, 1e6, -2e6])
    got = cgp_shift(p, 1e-6, 1e11)
    a0 = math.sqrt(1e-6 / math.pi)
    np.testing.assert_allclose(got, 16 * p * a0 / (3 * math.pi * 1e11), rtol=1e-14)
    assert isinstance(cgp_shift(1.0, 1.0, 1.0), float)


def test_compliance_matches_the_physical_shift():
    c = PhysicalContact("Au", SURFACE, adhesion=False)
    k = cgp_compliance(SURFACE.eta, SURFACE.area, c.b, SURFACE.sigma_s, c.nu)
    P_bar = 3.7
    p = P_bar * c.force_scale / SURFACE.area
    assert k * P_bar * SURFACE.sigma_s == pytest.approx(cgp_shift(p, SURFACE.area, c.E_star), rel=1e-12)


@pytest.mark.parametrize("bad", [0.0, -1.0, math.nan, math.inf, "x", None, True, [1.0, 2.0]])
def test_compliance_refuses_bad_input(bad):
    with pytest.raises((ValueError, TypeError)):
        cgp_compliance(bad, 1e-6, 2.9e-10, 2e-9)


def test_load_control_area_unchanged_separation_shifted():
    P = np.geomspace(1e-3, 1.0, 7)
    plain = PhysicalContact("Au", SURFACE, adhesion=False)
    mf = PhysicalContact("Au", SURFACE, adhesion=False, interaction="cgp2008")
    a, b = plain.load_curve(P), mf.load_curve(P)
    # The area-load relation is unchanged (Ciavarella et al. 2008): every asperity sits where plain GW puts it.
    np.testing.assert_allclose(b.area, a.area, rtol=1e-12)
    np.testing.assert_allclose(b.F, a.F, rtol=1e-12)
    np.testing.assert_allclose(b.contacts, a.contacts, rtol=1e-12)
    np.testing.assert_allclose(a.d - b.d, cgp_shift(P / SURFACE.area, SURFACE.area, plain.E_star), rtol=1e-9)


def test_separation_control_round_trip_and_reduced_load():
    plain = PhysicalContact("Au", SURFACE, adhesion=False)
    mf = PhysicalContact("Au", SURFACE, adhesion=False, interaction="cgp2008")
    d = np.linspace(-3e-9, 6e-9, 9)
    s_plain, s_mf = plain.separation_curve(d), mf.separation_curve(d)
    assert np.all(s_mf.P < s_plain.P) and np.all(s_mf.area < s_plain.area)
    # the load found at d, put back under load control, gives d again
    np.testing.assert_allclose(mf.load_curve(s_mf.P).d, d, atol=1e-15)
    # and the asperities sit at d + Delta(P): plain GW there carries the same load
    shift = cgp_shift(s_mf.P / SURFACE.area, SURFACE.area, plain.E_star)
    np.testing.assert_allclose(plain.separation_curve(d + shift).P, s_mf.P, rtol=1e-9)


def test_reduces_to_gw_as_density_goes_to_zero():
    # At a fixed load per asperity the nominal pressure, hence the shift k P, scales with eta: the
    # correction fades linearly, at first order |dP/P| = k |dP/dd| (the load is P(d + k P)).
    d = np.array([0.0, 1.0, 2.0])
    alpha = Surface(2e-9, 1e-6, 1e12, 1e-6).alpha
    plain = separation_curve(d, alpha, 1000.0)
    slope = (separation_curve(d + 1e-5, alpha, 1000.0).P - separation_curve(d - 1e-5, alpha, 1000.0).P) / 2e-5
    devs = []
    for eta in (1e12, 1e9, 1e6, 1e4):
        k = cgp_compliance(eta, 1e-6, 2.884e-10, 2e-9)
        devs.append(np.abs(separation_curve(d, alpha, 1000.0, interaction=MeanFieldInteraction(k)).P / plain.P - 1))
    assert np.all(np.diff(np.array(devs), axis=0) < 0)
    np.testing.assert_allclose(devs[-1], k * np.abs(slope), rtol=1e-3)


def test_reduces_to_gw_as_load_goes_to_zero():
    m = Model(0.01, 1000.0, interaction=MeanFieldInteraction(0.05))
    P = np.geomspace(1e-8, 1e-2, 4)
    np.testing.assert_allclose(m.load_curve(P).d - Model(0.01, 1000.0).load_curve(P).d, -0.05 * P, rtol=1e-9,
                               atol=1e-13)


def test_default_is_plain_gw_unchanged():
    P = np.geomspace(1.0, 1e4, 5)
    a = load_curve(P, 0.01, 1000.0)
    for value in (None, "none", "NONE", NoInteraction(), MeanFieldInteraction(0.0)):
        b = load_curve(P, 0.01, 1000.0, interaction=value)
        np.testing.assert_array_equal(a.d, b.d)
        np.testing.assert_array_equal(a.area, b.area)
    assert "interaction" not in a.parameters


def test_registry_and_errors():
    assert interaction_names() == ["none", "cgp2008"] == list(INTERACTIONS)
    with pytest.raises(ValueError, match="cgp2008"):
        as_interaction("bogus")
    with pytest.raises(ValueError, match="needs the surface"):
        Model(0.01, 1000.0, interaction="cgp2008")
    with pytest.raises(ValueError, match="non-adhesive"):
        Model(0.01, 1000.0, 1e-3, interaction=MeanFieldInteraction(0.1))
    with pytest.raises(ValueError, match="non-adhesive"):
        PhysicalContact("Au", SURFACE, interaction="cgp2008")
    with pytest.raises(ValueError):
        MeanFieldInteraction(-1.0)
    with pytest.raises(ValueError):
        interaction_for_surface(3, eta=1e12, area=1e-6, b=2.9e-10, sigma_s=2e-9)
    assert isinstance(interaction_for_surface(None, eta=1, area=1, b=1, sigma_s=1), NoInteraction)


def test_yield_check_uses_the_separations_the_asperities_feel():
    """With an interaction the yield check counts at the local separations: a share, never above 100 %."""
    import re
    import warnings

    from asperity.elastic_plastic import plastic_fraction
    from asperity.physical import PhysicalContact, Surface
    from asperity.plasticity import PlasticityWarning, plastic_share

    contact = PhysicalContact("Au", Surface(2e-9, 1e-6, 1e13, 1e-8), adhesion=False, interaction="cgp2008")
    loads = np.geomspace(1e-4, 1.0, 7)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", PlasticityWarning)
        curve = contact.load_curve(loads)
    inner = curve.dimensionless
    assert inner.d_local is not None and np.all(inner.d_local > inner.d)  # the interaction separates them
    share = plastic_share(plastic_fraction(inner.d_local, contact.u_c, contact.heights), inner.contacts)
    assert np.all((share >= 0) & (share <= 1))
    (w,) = [w for w in caught if issubclass(w.category, PlasticityWarning)]
    reported = float(re.search(r"up to ([0-9.]+)%", str(w.message)).group(1)) / 100
    assert reported == pytest.approx(share.max(), abs=6e-4)
