"""Cycles of a physical contact (asperity.physical_cycle): SI scaling of every result against the
dimensionless cycle, units, and bad input naming the parameter."""

import json
import math

import numpy as np
import pytest

from asperity.cycle import cycle, preload_curve
from asperity.physical import PhysicalContact, Surface

SURFACE = Surface(2e-9, 1e-6, 1e12, 1e-6)

#: Gold asperities this rough yield; the elastic cycle warns as every curve does (tested below).
pytestmark = pytest.mark.filterwarnings("ignore::asperity.plasticity.PlasticityWarning")


@pytest.fixture(scope="module")
def contact():
    return PhysicalContact("Au", SURFACE)


def test_scaling_of_a_cycle(contact):
    sigma, fs, N = SURFACE.sigma_s, contact.force_scale, contact.N
    pc = contact.cycle(preload="1mN", n=40)
    dc = cycle(contact.alpha, contact.beta, contact.gamma, nu=contact.nu, h_over_b=contact.h_over_b,
               preload=1e-3 / fs, n=40)
    assert pc.preload_N == pytest.approx(1e-3, rel=1e-9)
    np.testing.assert_allclose(pc.retract.d, dc.retract.d * sigma, rtol=1e-14)
    np.testing.assert_allclose(pc.retract.P, dc.retract.P * fs, rtol=1e-14)
    np.testing.assert_allclose(pc.approach.contacts, dc.approach.contacts * N, rtol=1e-14)
    assert pc.energy_J == pytest.approx(dc.energy * fs * sigma, rel=1e-14)
    assert pc.energy_J_m2 == pytest.approx(pc.energy_J / SURFACE.area, rel=1e-14)
    assert pc.loop_energy_J == pytest.approx(dc.loop_energy * fs / N * sigma, rel=1e-14)
    assert pc.loop_count == pytest.approx(dc.loop_fraction * N, rel=1e-14)
    assert pc.pull_off.force == pytest.approx(dc.pull_off.force * fs, rel=1e-12)
    assert pc.pull_off.d == pytest.approx(dc.pull_off.d * sigma, rel=1e-12)
    assert math.isinf(pc.stiffness_N_m)


def test_spring_in_newtons_per_metre(contact):
    sigma, fs = SURFACE.sigma_s, contact.force_scale
    k = 2.0e3  # N/m
    pc = contact.cycle(preload=1e-3, n=200, stiffness="2000N/m")
    dc = cycle(contact.alpha, contact.beta, contact.gamma, nu=contact.nu, h_over_b=contact.h_over_b,
               preload=1e-3 / fs, n=200, stiffness=k * sigma / fs)
    assert pc.stiffness_N_m == pytest.approx(k, rel=1e-14)
    np.testing.assert_allclose(pc.retract.d_base, dc.retract.d_base * sigma, rtol=1e-12)
    np.testing.assert_allclose(pc.retract.d_base, pc.retract.d - pc.retract.P / k, rtol=1e-9, atol=1e-18)
    assert pc.jump_energy_J == pytest.approx(dc.jump_energy * fs * sigma, rel=1e-12)
    assert len(pc.jumps) == len(dc.jumps)
    cols = pc.columns()
    assert list(cols) == ["branch", "d_base_m", "d_m", "P_N", "F_N", "mu", "area_m2", "pressure_Pa", "contacts",
                          "jump"]
    json.dumps(pc.to_dict(), allow_nan=False)


def test_an_unstable_closest_approach_is_stated_in_metres_and_newtons_per_metre(contact):
    """A user trial: a physical cycle whose d_min the spring never holds was refused in the
    model's units ('stiffness 0.64 ... d_min = -100'); now in m and N/m, the same numbers
    scaled (the dimensionless refusal, from the same model, gives them in sigma)."""
    from asperity.instrument import UnstableClosestApproach

    sigma, fs = SURFACE.sigma_s, contact.force_scale
    with pytest.raises(UnstableClosestApproach) as dim:
        cycle(contact.alpha, contact.beta, contact.gamma, nu=contact.nu, h_over_b=contact.h_over_b,
              d_min=1.0, n=40, stiffness=100.0 * sigma / fs)
    assert "from d/sigma = " in str(dim.value) and "d_min = 1 is never" in str(dim.value)
    with pytest.raises(UnstableClosestApproach, match=r"^the approach jumps into contact from d = \S+ m at stiffness "
                       r"100 N/m: its end d_min = 2e-09 m is never a stable state") as phys:
        contact.cycle(d_min="2nm", n=40, stiffness="100N/m")
    assert phys.value.d_from == pytest.approx(dim.value.d_from * sigma, rel=1e-12)
    assert phys.value.stiffness == pytest.approx(100.0, rel=1e-12) and phys.value.d_min == pytest.approx(2e-9)


@pytest.mark.parametrize("spelling", ["inf", "Infinity", "infN/m", "inf nN/nm", None, float("inf")])
def test_an_infinite_stiffness_in_every_spelling_is_displacement_control(contact, spelling):
    """A review: the command line took 'inf' and 'infN/m' but the library refused them."""
    assert math.isinf(contact.cycle(preload=1e-3, n=4, stiffness=spelling).stiffness_N_m)


@pytest.mark.parametrize("spelling, needle", [("infkg", "'kg' is not a unit compatible with N/m"),
                                              ("-inf", "stiffness")])
def test_an_infinite_stiffness_with_a_wrong_unit_is_refused(contact, spelling, needle):
    with pytest.raises(ValueError, match=needle):
        contact.cycle(preload=1e-3, n=4, stiffness=spelling)


def test_lengths_and_forces_with_units(contact):
    a = contact.cycle(d_min="1nm", d_max="20nm", n=20, u_in="-0.01nm")
    b = contact.cycle(d_min=1e-9, d_max=2e-8, n=20, u_in=-1e-11)
    assert a.energy_J == b.energy_J and a.d_min_m == pytest.approx(1e-9) and a.u_in_m == pytest.approx(-1e-11)
    c = contact.cycle(d_min=1e-9, d=["1nm", "2nm", "3nm"])
    assert len(c.approach) == 3 and c.approach.d[1] == pytest.approx(2e-9)


def test_preload_curve(contact):
    fs, sigma = contact.force_scale, SURFACE.sigma_s
    P = np.array([1e-4, 1e-3, 1e-2])
    pc = contact.preload_curve(P)
    dc = preload_curve(P / fs, contact.alpha, contact.beta, contact.gamma, nu=contact.nu, h_over_b=contact.h_over_b)
    np.testing.assert_allclose(pc.pull_off_N, dc.pull_off * fs, rtol=1e-12)
    np.testing.assert_allclose(pc.energy_J, dc.energy * fs * sigma, rtol=1e-12)
    np.testing.assert_allclose(pc.energy_J_m2, pc.energy_J / SURFACE.area, rtol=1e-14)
    assert list(pc.columns()) == ["preload_N", "d_min_m", "pull_off_N", "d_pull_off_m", "energy_J", "energy_J_m2",
                                  "loop_count", "friction_hysteresis_N_m"]
    assert pc.to_csv().startswith("preload_N,d_min_m,")


@pytest.mark.parametrize("kwargs, needle", [
    ({"preload": "-1mN"}, "preload"),
    ({"preload": "1nm"}, "preload"),
    ({"preload": 1e-3, "stiffness": "-0.1N/m"}, "stiffness"),
    ({"preload": 1e-3, "stiffness": 0.0}, "stiffness"),
    ({"d_min": "5nm", "d_max": "1nm"}, "d_min"),
    ({"d_min": "1N"}, "d_min"),
    ({"preload": "1e12N"}, "preload"),
])
def test_bad_input(contact, kwargs, needle):
    with pytest.raises(ValueError, match=needle):
        contact.cycle(**kwargs)


def test_bad_preload_curve(contact):
    with pytest.raises(ValueError, match="preload"):
        contact.preload_curve([1e-3, -1e-3])


def test_names_come_from_the_registry(contact):
    from asperity.quantities import CYCLE_QUANTITIES as Q

    pc = contact.preload_curve([1e-3])
    dc = preload_curve([1.0], 0.01, 1000.0, 1e-3)
    assert all(name in Q for name in dc.columns())
    si = {q.si_name for q in Q.values()}
    assert set(pc.columns()) <= si
    c = contact.cycle(preload=1e-3, n=5)
    scalars = {k for part in ("pull_off", "energy") for k in c.to_dict()[part] if k != "exists"}
    assert scalars - {"force_N", "d_m"} <= si


def test_inputs_are_checked_in_the_users_units(contact):
    """Found by a review: a negative physical preload was quoted in N G b^2, u_in in sigma,
    'inf N/m' (which the command line suggests) refused, 2-D lists flattened silently and
    too many values blamed on their range."""
    a = contact.cycle(preload=5e-6, stiffness="inf N/m", n=40)
    b = contact.cycle(preload=5e-6, n=40)
    assert a.stiffness_N_m == math.inf and a.energy_J == b.energy_J
    low = contact.model.law.u_end * contact.surface.sigma_s
    cases = [(dict(stiffness="-inf N/m"), "must be > 0 N/m, or inf for displacement control, got -inf"),
             (dict(stiffness=math.nan), "or inf for displacement control, got nan"),
             (dict(u_in="1nm"), f"must lie in \\[{low:.6g}, 0\\] m for this contact .* got 1e-09 m")]
    for kwargs, needle in cases:
        with pytest.raises(ValueError, match=needle):
            contact.cycle(preload=5e-6, n=40, **kwargs)
    for preload, needle in (([1e-6, -1e-6], "must be > 0 N, got min -1e-06 N"), ([[1e-6]], "1-D"),
                            (np.full(1_000_001, 1e-6), "at most 1000000 values, got 1000001")):
        with pytest.raises(ValueError, match=needle):
            contact.preload_curve(preload)
    with pytest.raises(ValueError, match="1-D"):
        contact.cycle(preload=5e-6, d=[[1e-9, 2e-9]])


def test_dimensionless_lists_are_one_dimensional_and_counted():
    p = (0.02, 50.0, 0.02)
    for kwargs, needle in ((dict(d=[[1.0, 2.0], [3.0, 4.0]]), "d must be a number or a 1-D"),
                           (dict(d=np.linspace(0.0, 5.0, 1_000_001)), "at most 1000000 values, got 1000001")):
        with pytest.raises(ValueError, match=needle):
            cycle(*p, d_min=0.0, **kwargs)
    with pytest.raises(ValueError, match="preload must be a number or a 1-D"):
        preload_curve([[1.0, 2.0]], *p)
    for k in (-math.inf, math.nan):
        with pytest.raises(ValueError, match=r"valid range 1e-100 <= stiffness <= inf\), got"):
            cycle(*p, d_min=0.0, stiffness=k)


def test_an_elastic_cycle_warns_when_the_asperities_yield():
    """A review: cycles were the only curves not checked for yield (the header promised notes)."""
    import warnings

    from asperity.plasticity import PlasticityWarning

    contact = PhysicalContact("Au", Surface(2e-9, 100e-9, 2e14, 1e-12))
    with pytest.warns(PlasticityWarning, match="past the critical interference"):
        contact.cycle(preload="5uN", n=30)
    # a smooth surface (psi = 0.51) lightly loaded without adhesion: nothing yields, no warning
    smooth = PhysicalContact("Au", Surface(0.1e-9, 100e-6, 1e12, 1e-8), adhesion=False)
    assert smooth.plasticity_index < 0.6
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        smooth.cycle(preload="1uN", n=30)


def test_a_plastic_cycle_says_it_has_no_unloading_and_counts_the_yielded():
    """A review: --law jackson-green gave a reversible loop with no word and no plastic column."""
    from asperity import AsperityWarning
    from asperity.elastic_plastic import plastic_fraction

    contact = PhysicalContact("Au", Surface(2e-9, 100e-9, 2e14, 1e-12), plasticity="jackson-green", adhesion=False)
    with pytest.warns(AsperityWarning, match="jackson-green law has no unloading"):
        c = contact.cycle(preload="5uN", n=30)
    for branch in (c.approach, c.retract):
        assert "plastic" in branch.columns()
        expected = plastic_fraction(branch.d / contact.surface.sigma_s, contact.u_c, contact.heights) * contact.N
        np.testing.assert_allclose(branch.plastic, expected, rtol=1e-12)
    assert np.max(c.approach.plastic) > 0 and c.energy_J == 0.0


def test_a_cycles_warnings_point_at_the_users_line():
    """A review: through PhysicalContact.cycle the PlasticityWarning pointed at asperity's own
    wrapper; every warning of a cycle now names the caller's file, whichever route."""
    import warnings

    from asperity.physical_cycle import physical_cycle

    contact = PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6))
    plastic = PhysicalContact("Au", Surface(2e-9, 100e-9, 2e14, 1e-12), plasticity="jackson-green", adhesion=False)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        contact.cycle(preload="3000N", n=10)  # yields, and more than 10 % of the area
        physical_cycle(contact, preload="3000N", n=10)
        plastic.cycle(preload="5uN", n=12)  # no unloading
    assert len(caught) == 5 and {w.filename for w in caught} == {__file__}, [(w.filename, w.message) for w in caught]


@pytest.mark.parametrize("kwargs, words", [
    ({"d_min": -1.0}, "d_min (closest approach) must lie in ["),          # metres: -1 m, not -5e8 sigma_s
    ({"d_min": "3um"}, "got 3e-06 m"),
    ({"d_min": "1nm", "d_max": "1m"}, "d_max (start and end of the cycle) must lie in ("),
    ({}, "give exactly one of d_min"),
    ({"d_min": "1nm", "preload": "1uN"}, "give exactly one of d_min"),
    ({"d_min": "0nm", "d": ["1nm", "50nm"]}, "d (separations) must lie in [d_min, d_max] = [0, "),
])
def test_separations_are_checked_in_metres(kwargs, words):
    # A helper's trial: physical_cycle(d_min=-1.0) said "got -499999999.99999994 (separations in
    # units of sigma_s ...)"; the ranges are now said in metres.
    from asperity.physical import PhysicalContact, Surface
    from asperity.physical_cycle import physical_cycle

    contact = PhysicalContact("Au", Surface(2e-9, 100e-9, 2e14, 1e-12), plastic_threshold=1.0)
    if "d" in kwargs:
        kwargs = {**kwargs, "d": [float(x[:-2]) * 1e-9 for x in kwargs["d"]]}
    with pytest.raises(ValueError) as err:
        physical_cycle(contact, **kwargs)
    assert words in str(err.value) and "units of sigma_s" not in str(err.value)
