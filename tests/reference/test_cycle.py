"""asperity.reference.cycle against closed forms and its own definitions: Hertz moments, the
Gaussian tail of the contact counts, the paper's curve beyond the transition zone, the energy of
closed loops, bad input.

Nothing here compares with the fast path (that is tests/test_cycle_vs_reference.py).
"""

import math

import pytest
from scipy import integrate

from asperity.reference import cycle as ref
from asperity.reference import multi_asperity
from asperity.reference.maugis_dugdale_branch import branch_point_offset
from asperity.reference.multi_asperity import Params

from .test_multi_asperity import closed_moment

ADHESIVE = [(0.003, 1000.0, 1e-3), (0.02, 50.0, 2e-2)]  # lambda 0.78 and 1.13 (lambda_c = 0.938)


def tail(z):
    return 0.5 * math.erfc(z / math.sqrt(2.0))


@pytest.mark.parametrize("d", [-1.0, 0.4, 2.0])
def test_hertz_cycle_is_the_gw_moments(d):
    pref = (4.0 / 3.0) * (2.0 / 0.7) * 0.01 * 1000.0**2
    for res in (ref.approach_point(d, 0.01, 1000.0), ref.retract_point(d, -1.5, 0.01, 1000.0)):
        assert res["P"] == pytest.approx(pref * closed_moment(d, 1.5), rel=1e-10)
        assert res["area"] == pytest.approx(1000.0**2 * closed_moment(d, 1), rel=1e-10)
    assert ref.cycle_energy(-1.0, 5.0, 0.01, 1000.0, 0.0) == 0.0


@pytest.mark.parametrize("p", ADHESIVE)
def test_contact_counts_are_gaussian_tails(p):
    u_end = ref.branch_end_penetration(*p)
    d_min = -0.3
    for d in (d_min, d_min - 0.5 * u_end, d_min - u_end + 0.4):
        assert ref.approach_point(d, *p)["contacts"] == pytest.approx(tail(d), rel=1e-10)
        lowest = max(d + u_end, d_min)  # touched on approach (u_in = 0) and not yet snapped off
        assert ref.retract_point(d, d_min, *p)["contacts"] == pytest.approx(tail(lowest), rel=1e-10)


@pytest.mark.parametrize("p", ADHESIVE)
def test_retraction_beyond_the_zone_and_approach_from_the_branch_end_are_the_papers_curve(p):
    u_end = ref.branch_end_penetration(*p)
    d = 0.7
    paper = multi_asperity.separation_point(d, *p)
    retract = ref.retract_point(d, d + u_end - 0.2, *p)
    approach = ref.approach_point(d, *p, u_in=u_end)
    for key in ("contacts", "P", "F", "area"):
        assert retract[key] == pytest.approx(paper[key], rel=1e-9)
        assert approach[key] == pytest.approx(paper[key], rel=1e-9)


@pytest.mark.parametrize("p", ADHESIVE)
def test_retraction_starts_where_the_approach_ends(p):
    a = ref.approach_point(-0.2, *p)
    r = ref.retract_point(-0.2, -0.2, *p)
    for key in a:
        assert r[key] == pytest.approx(a[key], rel=1e-12)


def loop_energy(p):
    """-int_{u_end}^0 P(u) du of one asperity, by quadrature in s (u = u_end + s^2) of the
    per-asperity Maugis-Dugdale solution."""
    q = Params(*p, 0.3, 1.0, 1 / 43, 1 / 43 / 30, 28.0, 8e4)
    u_end = ref.branch_end_penetration(*p)

    def f(s):
        return 2 * s * branch_point_offset(q.lam, s * s / q.delta_hat)[1] / q.P_hat

    return -integrate.quad(f, 0.0, math.sqrt(-u_end), epsabs=0.0, epsrel=1e-12, limit=200)[0]


@pytest.mark.parametrize("p", ADHESIVE)
def test_closed_loops_energy_is_the_count_times_the_loop_energy(p):
    u_end = ref.branch_end_penetration(*p)
    d_min, d_max = -0.5, 12.0 - u_end  # every stuck asperity snaps off before d_max
    count = tail(d_min) - tail(d_max + u_end)
    assert ref.cycle_energy(d_min, d_max, *p) == pytest.approx(count * loop_energy(p), rel=1e-9)


def test_bad_input():
    with pytest.raises(ValueError, match="u_in"):
        ref.approach_point(0.0, *ADHESIVE[0], u_in=0.5)
    with pytest.raises(ValueError, match="d must be >= d_min"):
        ref.retract_point(0.0, 1.0, *ADHESIVE[0])
    with pytest.raises(ValueError, match="d_min must be < d_max"):
        ref.cycle_energy(1.0, 0.0, *ADHESIVE[0])
    with pytest.raises(ValueError, match="d_min"):
        ref.retract_pull_off(float("nan"), 1.0, *ADHESIVE[0])
