"""The stable Maugis-Dugdale branch (asperity.maugis_dugdale_branch): limits of md_solve,
pull-off in the DMT limit, the re-exports and BranchPoint.to_dict."""

import json
import math

import numpy as np
import pytest

from asperity import maugis_dugdale as md
from asperity import maugis_dugdale_branch as branch


def test_reexported_from_maugis_dugdale():
    from asperity import maugis_dugdale_solve as solve

    for name in branch.__all__ + solve.__all__:
        assert getattr(md, name) is getattr(branch, name, None) or getattr(md, name) is getattr(solve, name)


@pytest.mark.parametrize("lam", [1e-12, 1e-3, 1.0, 1e12])
def test_solve_at_and_beyond_the_penetration_limit(lam):
    # At DELTA_MAX: finite, no warning (they are errors under pytest), and on the curve.
    A, P, t = md.md_solve([md.DELTA_MAX], lam)
    assert np.all(np.isfinite([A, P, t]))
    assert float(md.md_penetration(t, lam)[0]) == pytest.approx(md.DELTA_MAX, rel=1e-12)
    assert float(A[0]) == pytest.approx(math.sqrt(md.DELTA_MAX), rel=1e-6)  # Hertz: Delta = A^2
    with pytest.raises(ValueError, match=r"^delta \(penetration\) must lie in \[.*1e\+150\]"):
        md.md_solve([1.0, np.nextafter(md.DELTA_MAX, np.inf)], lam)


def test_issue_7_overflow_is_an_error():
    # `asperity md --delta 1e300` printed P = inf with exit status 0.
    with pytest.raises(ValueError, match="delta"):
        md.md_solve([1e300], 1.0)


@pytest.mark.parametrize("lam", [6.052779976193355e-12, 4.064644395709628e-09, 1.710341000337838e-07, 1e-6,
                                 6.832607387157405e-07])
def test_load_pull_off_in_the_dmt_limit(lam):
    # dP/dt is flat to rounding here: its sign on the scan grid is noise, which used to end in
    # "f(a) and f(b) must have different signs" from brentq.
    po = md.md_pull_off(lam, "load")
    assert po.P == pytest.approx(-2.0, abs=3 * math.sqrt(lam))
    assert po.P <= md.md_pull_off(lam, "displacement").P + 1e-12


def test_branch_point_to_dict_is_strict_json():
    below = md.md_branch_end(0.5)  # runs to A -> 0: t = inf
    d = below.to_dict()
    assert d["t"] is None and d["A"] == 0.0 and d["P"] == below.P
    json.loads(json.dumps(d, allow_nan=False))
    above = md.md_branch_end(5.0).to_dict()
    assert set(above) == {"t", "A", "P", "delta"} and all(isinstance(v, float) for v in above.values())


def test_lambda_range_is_checked_by_both_modules():
    lo, hi = md.LAMBDA_RANGE
    for lam in (lo, hi):
        md.md_branch_end(lam)
        md.md_curve(1.0, lam)
    for lam in (np.nextafter(lo, 0), np.nextafter(hi, np.inf)):
        for call in (md.md_branch_end, md.md_pull_off, lambda x: md.md_curve(1.0, x), lambda x: md.md_solve(0.0, x)):
            with pytest.raises(ValueError, match=r"^lam \(Maugis parameter\) must lie in"):
                call(lam)
