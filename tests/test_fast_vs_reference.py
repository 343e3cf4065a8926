"""The fast path against the independent slow path (asperity.reference) to 1e-8."""

import numpy as np
import pytest

import asperity
from asperity import reference

# alpha 1e-3..0.3, beta 1e1..1e6, gamma 0..5e-2, with separations over -3..5.
CASES = [
    ((1e-3, 10.0, 0.0), (-3.0, 0.5, 5.0)),
    ((0.3, 1e6, 0.0), (-1.0, 2.0)),
    ((0.01, 1000.0, 1e-3), (-3.0, 0.0, 1.0, 2.0, 3.0)),
    ((0.002, 1000.0, 1e-3), (-1.0, 0.5)),
    ((0.05, 1e4, 1e-2), (-2.0, 1.5, 4.0)),
    ((0.3, 10.0, 5e-2), (-3.0, 1.0, 5.0)),
    ((1e-3, 1e6, 5e-2), (0.0, 2.5)),
    ((0.01, 100.0, 1e-4), (-0.5, 3.5)),
    ((0.1, 1e5, 1e-3), (1.0, 5.0)),
    ((3e-3, 300.0, 3e-2), (-2.5, 2.0)),
    ((0.02, 50.0, 2e-2), (0.0, 2.0)),  # lambda above lambda_c: interior branch end
    ((0.3, 30.0, 0.0759), (0.0, 3.5)),  # lambda = lambda_c to 1e-4: fourth-root branch end
    ((0.3, 10.0, 0.1315), (5.0,)),
]


@pytest.mark.parametrize("params, ds", CASES, ids=[str(c[0]) for c in CASES])
def test_separation_points(params, ds):
    fast = asperity.separation_curve(np.array(ds), *params)
    dry = asperity.separation_curve(np.array(ds), params[0], params[1], 0.0)
    for i, d in enumerate(ds):
        ref = reference.separation_point(d, *params)
        for key in ("contacts", "F", "area"):
            assert getattr(fast, key)[i] == pytest.approx(ref[key], rel=1e-8), (key, d)
        # P is a difference of compressive and tensile parts; compare where it is not a
        # near-cancellation, to its compressive (Hertz) scale.
        assert fast.P[i] == pytest.approx(ref["P"], rel=1e-8, abs=1e-9 * dry.P[i]), ("P", d)


@pytest.mark.parametrize("params", [(0.003, 1000, 1e-3), (0.01, 100, 1e-3)])
def test_pull_off(params):
    fast = asperity.pull_off(*params)
    ref = reference.pull_off(*params)
    assert fast.force == pytest.approx(ref["pull_off"], rel=1e-8)
    assert fast.d == pytest.approx(ref["d"], abs=1e-5)


@pytest.mark.parametrize("params, P", [((0.01, 1000, 0.0), 10.0), ((0.01, 1000, 1e-3), 3.0)])
def test_load_point(params, P):
    fast = asperity.load_curve([P], *params)
    ref = reference.load_point(P, *params)
    assert fast.d[0] == pytest.approx(ref["d"], rel=1e-9, abs=1e-9)
    for key in ("contacts", "F", "area"):
        assert getattr(fast, key)[0] == pytest.approx(ref[key], rel=1e-8)


# -- other height distributions (asperity.heights) against the reference densities --------------
from .heights_cases import CURVE_CASES, fast  # noqa: E402
from .heights_cases import reference as reference_heights  # noqa: E402

HEIGHT_PARAMS = [(0.01, 1000.0, 0.0), (0.01, 1000.0, 1e-3), (0.05, 1e4, 1e-2)]


@pytest.mark.parametrize("case", CURVE_CASES)
@pytest.mark.parametrize("params", HEIGHT_PARAMS, ids=str)
def test_separation_points_with_other_heights(case, params):
    ds = np.array([-2.5, -0.8, 0.5, 2.0])
    fast_curve = asperity.separation_curve(ds, *params, heights=fast(case))
    dry = asperity.separation_curve(ds, params[0], params[1], 0.0, heights=fast(case))
    for i, d in enumerate(ds):
        ref = reference.separation_point(d, *params, heights=reference_heights(case))
        for key in ("contacts", "F", "area"):
            assert getattr(fast_curve, key)[i] == pytest.approx(ref[key], rel=1e-8, abs=1e-300), (key, d)
        assert fast_curve.P[i] == pytest.approx(ref["P"], rel=1e-8, abs=1e-9 * dry.P[i]), ("P", d)



@pytest.mark.parametrize("case", ["pearson3-1.2"])
def test_load_point_with_other_heights(case):
    params = (0.01, 1000.0, 1e-3)
    fast_curve = asperity.load_curve([3.0], *params, heights=fast(case))
    ref = reference.load_point(3.0, *params, heights=reference_heights(case))
    assert fast_curve.d[0] == pytest.approx(ref["d"], rel=1e-9, abs=1e-9)
    for key in ("contacts", "F", "area"):
        assert getattr(fast_curve, key)[0] == pytest.approx(ref[key], rel=1e-8)


@pytest.mark.parametrize("case, params", [("exponential", (0.002, 1000.0, 1e-3))])
def test_pull_off_with_other_heights(case, params):
    # With exponential heights the most tensile force sits at a kink of P(d), where the lowest
    # asperities reach the end of the adhesive branch (d = -1 - u_end): the reference's bounded
    # Brent search stops ~1e-8 short of it, so the fast pull-off is at least as tensile, and the
    # reference force at the fast separation is the fast force.
    got = asperity.pull_off(*params, heights=fast(case))
    ref = reference.pull_off(*params, heights=reference_heights(case))
    assert got.exists and got.force == pytest.approx(ref["pull_off"], rel=1e-7)
    assert got.force >= ref["pull_off"] * (1 - 1e-9)  # both searches stop within ~1e-10 at the kink
    at = reference.separation_point(got.d, *params, heights=reference_heights(case))["P"]
    assert -at == pytest.approx(got.force, rel=1e-9)  # the force carried by a Taylor step across the kink
    assert got.d == pytest.approx(ref["d"], abs=1e-5)


def test_exponential_heights_lose_the_pull_off():
    # positively skewed heights: the highest asperities hold the surfaces apart; at alpha = 0.003
    # the Gaussian has a pull-off (Table 1: 320) and the exponential none: P > 0 at every separation
    assert asperity.pull_off(0.003, 1000.0, 1e-3).exists
    po = asperity.pull_off(0.003, 1000.0, 1e-3, heights=fast("exponential"))
    assert not po.exists and po.force == 0.0
    ref = reference.separation_point(0.5, 0.003, 1000.0, 1e-3, heights=reference_heights("exponential"))
    assert ref["P"] > 0
