"""asperity.reference.maugis_dugdale_load against closed forms: the JKR and DMT limits of the
load-controlled radius, and the curve it must lie on.  Nothing here uses the fast path."""

import math

import pytest

from asperity.reference import maugis_dugdale as ref_md
from asperity.reference import maugis_dugdale_load as ref


@pytest.mark.parametrize("P", [-1.4, 0.0, 5.0])
def test_jkr_limit(P):
    # JKR: P = A^3 - sqrt(6 A^3) on the branch A^3 >= 3/2, i.e. A^(3/2) = (sqrt 6 + sqrt(6 + 4P))/2
    A, _ = ref.md_load_point(P, 1e5)
    assert A == pytest.approx(((math.sqrt(6) + math.sqrt(6 + 4 * P)) / 2) ** (2 / 3), rel=1e-6)


@pytest.mark.parametrize("P", [-1.9, 0.0, 5.0])
def test_dmt_limit(P):
    # DMT: A^3 = P + 2, Delta = A^2 (MD approaches it as lambda^(1/2) in Delta)
    A, D = ref.md_load_point(P, 1e-8)
    assert A == pytest.approx((P + 2) ** (1 / 3), rel=1e-6)
    assert D == pytest.approx(A * A, rel=1e-3)


def test_point_lies_on_the_curve():
    A, D = ref.md_load_point(0.3, 0.8)
    # t from Eq 13 on this A: the curve at that t has the same A and load
    lam = 0.8
    t = (A * A - D) * 3 / (4 * lam * A)
    A2, P2, D2 = ref_md.md_curve(t, lam)
    assert (A2, P2) == (pytest.approx(A, rel=1e-12), pytest.approx(0.3, abs=1e-12))


def test_below_pull_off_is_an_error():
    with pytest.raises(ValueError, match="pull-off"):
        ref.md_load_point(-2.5, 1.0)
