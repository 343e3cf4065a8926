"""The fast cycle path against the independent slow path (asperity.reference.cycle) to 1e-8, at
random parameters with the Maugis parameter below and above lambda_c, and at lambda_c itself."""

import numpy as np
import pytest

from asperity import groups, reference
from asperity.asperity_law import AsperityLaw, ModelParameters
from asperity.cycle import cycle
from asperity.maugis_dugdale import LAMBDA_C


def random_cases(seed=20261123, per_side=2):
    """(alpha, beta, gamma) drawn log-uniformly, kept while the branch end lies within 3 sigma,
    until ``per_side`` cases on each side of lambda_c."""
    rng = np.random.default_rng(seed)
    below, above = [], []
    while len(below) < per_side or len(above) < per_side:
        a, b, g = 10 ** rng.uniform(-2.5, -1), 10 ** rng.uniform(1.5, 3.5), 10 ** rng.uniform(-3.5, -1.5)
        lam = float(groups.maugis_lambda(a, b, g))
        u_end = AsperityLaw(ModelParameters(a, b, g)).u_end
        if not (0.2 < lam < 5 and -3.0 < u_end < -0.02):
            continue
        side = below if lam < LAMBDA_C else above
        if len(side) < per_side:
            side.append((float(a), float(b), float(g)))
    return below + above


CASES = random_cases() + [(0.3, 30.0, 0.0759)]  # the last at lambda = lambda_c to 1e-4


def test_cases_straddle_lambda_c():
    lams = [float(groups.maugis_lambda(*p)) for p in CASES]
    assert sum(lam < LAMBDA_C for lam in lams) >= 2 and sum(lam > LAMBDA_C for lam in lams) >= 3


def close(fast, ref, scale):
    """1e-8 relative, or 1e-9 of the branch's compressive scale where P crosses zero."""
    return fast == pytest.approx(ref, rel=1e-8, abs=1e-9 * scale)


@pytest.mark.parametrize("p", CASES, ids=[f"{p[0]:.3g},{p[1]:.3g},{p[2]:.3g}" for p in CASES])
def test_approach_and_retract_points(p):
    rng = np.random.default_rng(abs(hash(p)) % 2**32)
    u_end = AsperityLaw(ModelParameters(*p)).u_end
    d_min = float(rng.uniform(-1.0, 0.5))
    d = np.array([d_min + 0.35 * -u_end, d_min + 0.9 * -u_end, d_min - u_end + float(rng.uniform(0.1, 1.5))])
    c = cycle(*p, d_min=d_min, d=d)
    scale = abs(c.preload) + abs(c.retract.P).max()
    for i, x in enumerate(d):
        a = reference.approach_point(x, *p)
        r = reference.retract_point(x, d_min, *p)
        for key in ("contacts", "F", "area"):
            assert getattr(c.approach, key)[i] == pytest.approx(a[key], rel=1e-8), (key, x)
            assert getattr(c.retract, key)[i] == pytest.approx(r[key], rel=1e-8), (key, x)
        assert close(c.approach.P[i], a["P"], scale), ("P", x)
        assert close(c.retract.P[i], r["P"], scale), ("P", x)


@pytest.mark.parametrize("p", CASES[::2], ids=[f"{p[0]:.3g},{p[1]:.3g},{p[2]:.3g}" for p in CASES[::2]])
def test_energy(p):
    for d_max in (None, 0.6):
        c = cycle(*p, d_min=-0.4, d_max=d_max, n=5)
        assert c.energy == pytest.approx(reference.cycle_energy(-0.4, c.d_max, *p), rel=1e-8)


def test_retract_pull_off_in_the_transition_zone():
    # The pull-off lies inside the transition zone here (d_min + reach = 2.10 > d = 1.805): the
    # reference force there is the fast pull-off, and larger on either side.  (The reference's own
    # scan-and-Brent search, reference.retract_pull_off, agrees to 1e-15 but takes ~20 s.)
    p = CASES[0]
    u_end = AsperityLaw(ModelParameters(*p)).u_end
    c = cycle(*p, d_min=0.5, n=50)
    po = c.pull_off
    assert po.exists and 0.5 < po.d < 0.5 - u_end
    P = [reference.retract_point(x, 0.5, *p)["P"] for x in (po.d - 0.01, po.d, po.d + 0.01)]
    assert P[1] == pytest.approx(-po.force, rel=1e-8)
    assert P[0] > P[1] and P[2] > P[1]


def test_jump_in_below_first_touch():
    # u_in between the branch end and 0: approach, retraction and energy follow it.
    p = CASES[2]
    u_end = AsperityLaw(ModelParameters(*p)).u_end
    u_in, d_min = 0.5 * u_end, -0.2
    d = np.array([d_min + 0.2 * (u_in - u_end), d_min + (u_in - u_end) + 0.3])
    c = cycle(*p, d_min=d_min, d=d, u_in=u_in)
    for i, x in enumerate(d):
        a = reference.approach_point(x, *p, u_in=u_in)
        r = reference.retract_point(x, d_min, *p, u_in=u_in)
        for key in ("contacts", "P", "F", "area"):
            assert getattr(c.approach, key)[i] == pytest.approx(a[key], rel=1e-8), (key, x)
            assert getattr(c.retract, key)[i] == pytest.approx(r[key], rel=1e-8), (key, x)
    assert c.energy == pytest.approx(reference.cycle_energy(d_min, c.d_max, *p, u_in=u_in), rel=1e-8)


NARROW = {"w": 0.99, "m1": 0.0, "s1": 0.0021, "m2": -1.0, "s2": 0.0021}


@pytest.mark.parametrize("spec", [NARROW, {**NARROW, "s1": 0.0045, "s2": 0.003}, {**NARROW, "s1": 0.006}],
                         ids=["s=0.0021", "s=0.0045,0.003", "s=0.006"])
def test_retraction_with_a_narrow_mixture_component(spec):
    # A helper's trial: with a component 0.02 sigma wide, the loop band integrated on unit panels
    # gave contacts 1.06-1.20 (above 1) and a retraction force 10-25 % off inside the transition zone.
    from asperity.heights import Mixture
    from asperity.reference.heights import reference_density

    p, d_min = (0.02, 50.0, 0.02), -0.4
    d = np.array([-0.2, 0.3, 0.6, 1.2, 1.75])
    c = cycle(*p, d_min=d_min, d=d, heights=Mixture(**spec))
    ref = reference_density("mixture", **spec)
    for i, x in enumerate(d):
        a = reference.approach_point(x, *p, heights=ref)
        r = reference.retract_point(x, d_min, *p, heights=ref)
        for key in ("contacts", "P", "F", "area"):
            assert getattr(c.approach, key)[i] == pytest.approx(a[key], rel=1e-7, abs=1e-9), (key, x)
            assert getattr(c.retract, key)[i] == pytest.approx(r[key], rel=1e-7, abs=1e-9), (key, x)


@pytest.mark.parametrize("case", ["weibull-0.8", "pearson3-1.2", "empirical"])
def test_retraction_with_skewed_heights(case):
    from .heights_cases import fast
    from .heights_cases import reference as reference_heights

    p, d_min = CASES[1], -0.3
    u_end = AsperityLaw(ModelParameters(*p)).u_end
    d = np.array([d_min + 0.5 * -u_end, d_min - u_end + 0.4])
    c = cycle(*p, d_min=d_min, d=d, heights=fast(case))
    for i, x in enumerate(d):
        r = reference.retract_point(x, d_min, *p, heights=reference_heights(case))
        for key in ("contacts", "P", "F", "area"):
            assert getattr(c.retract, key)[i] == pytest.approx(r[key], rel=1e-7, abs=1e-9), (key, x)
