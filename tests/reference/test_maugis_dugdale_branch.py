"""asperity.reference.maugis_dugdale_branch against closed forms: JKR and DMT limits,
lambda_c, the A -> 0 branch end, and the explicit curve.

Nothing here compares with the fast path: every expected value is a closed form.
"""

import math

import mpmath
import pytest

from asperity.reference import maugis_dugdale as ref_curve
from asperity.reference import maugis_dugdale_branch as ref


def closed_moment(d, k):
    """int_d^inf (z-d)^k phi(z) dz = Gamma(k+1) exp(-d^2/4) D_{-k-1}(d) / sqrt(2 pi)."""
    with mpmath.workdps(40):
        d = mpmath.mpf(d)
        val = mpmath.gamma(k + 1) * mpmath.exp(-d * d / 4) * mpmath.pcfd(-k - 1, d) / mpmath.sqrt(2 * mpmath.pi)
        return float(val)


def rel(a, b):
    return abs(a - b) / abs(b)


@pytest.mark.parametrize("A", [0.7, 1.0, 2.0, 5.0])
def test_md_point_jkr_limit(A):
    delta = A * A - math.sqrt(8 * A / 3)
    P = A**3 - math.sqrt(6 * A**3)
    Am, Pm = ref.md_point(delta, 1e4)
    assert rel(Am, A) < 1e-8
    assert abs(Pm - P) < 1e-8


@pytest.mark.parametrize("A", [1.0, 2.0, 4.0])
def test_md_point_dmt_limit(A):
    # DMT: Delta = A^2, P = A^3 - 2; the MD curve approaches it like lambda^(1/2)
    errs = []
    for lam in (1e-4, 1e-6):
        Am, Pm = ref.md_point(A * A, lam)
        errs.append((abs(Am / A - 1), abs(Pm - (A**3 - 2))))
    assert errs[1][0] < 2e-3 and errs[1][1] < 1e-2
    assert errs[1][0] < 0.2 * errs[0][0] and errs[1][1] < 0.2 * errs[0][1]


@pytest.mark.parametrize("lam", [0.05, 0.5, 0.95, 3.0])
def test_md_point_inverts_explicit_curve(lam):
    # Eqs. 11-13 evaluated explicitly at m = sqrt(1 + t^2) on the stable branch
    A_end = ref.md_branch_end(lam)[0]
    for t in (1e-6, 1e-2, 0.3, 3.0):
        A, P, D = ref_curve.md_curve(t, lam)
        if A <= 1.5 * A_end:
            continue
        Am, Pm = ref.md_point(D, lam)
        assert rel(Am, A) < 1e-11
        assert abs(Pm - P) <= 1e-11 * max(1.0, abs(P))


def test_md_pull_off_limits():
    assert abs(ref.md_pull_off(1e-8, "load") + 2.0) < 1e-8
    assert abs(ref.md_pull_off(1e4, "load") + 1.5) < 1e-7
    assert abs(ref.md_pull_off(1e4, "displacement") + 5 / 6) < 1e-7
    A_end, D_end, P_end = ref.md_branch_end(1e4)
    assert rel(A_end, 6 ** (-1 / 3)) < 1e-6
    assert abs(D_end - (A_end**2 - math.sqrt(8 * A_end / 3))) < 1e-6
    with pytest.raises(ValueError, match="control"):
        ref.md_pull_off(1.0, "force")


def test_lambda_c():
    assert abs(ref_curve.md_lambda_c() - 0.93795) < 1e-4
    assert ref.md_branch_end(0.93)[0] == 0.0
    assert ref.md_branch_end(0.95)[0] > 0.0


def test_branch_end_below_lambda_c_closed_form():
    # A_M -> 0: x = A t solves (lam pi/4) x^2 + (4 lam^2/3)(pi/2-1) x = 1,
    # Delta_end = -(4/3) lam x, P_end = -(pi/2) lam x^2
    lam = 0.4
    c2, c1 = lam * math.pi / 4, 4 * lam**2 / 3 * (math.pi / 2 - 1)
    x = 2 / (c1 + math.sqrt(c1 * c1 + 4 * c2))
    A_end, D_end, P_end = ref.md_branch_end(lam)
    assert A_end == 0.0
    assert rel(D_end, -4 * lam * x / 3) < 1e-14
    assert rel(P_end, -math.pi * lam * x * x / 2) < 1e-14
    # the explicit curve approaches the end from above
    A, P, D = ref_curve.md_curve(1e6, lam)
    assert D > D_end and D - D_end < 1e-9


def test_md_point_below_branch_end_raises():
    for lam in (0.3, 2.0):
        D_end = ref.md_branch_end(lam)[1]
        with pytest.raises(ValueError, match="below the end"):
            ref.md_point(D_end - 1e-6, lam)
