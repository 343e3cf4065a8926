"""asperity.reference.friction_stress against the closed form of Eq (2): constant in regions 1 and 3,
a straight line in log-log between them."""

import math

import pytest

from asperity.reference import friction_stress as ref


def test_regions_one_and_three_are_constant():
    assert ref.hk_tau(0.0) == ref.hk_tau(28.0) == 1 / 43
    assert ref.hk_tau(8e4) == ref.hk_tau(1e9) == 1 / 43 / 30


@pytest.mark.parametrize("x", [0.1, 0.5, 0.9])
def test_region_two_is_a_line_in_log_log(x):
    # at a = a1^(1-x) a2^x the stress is tau1^(1-x) tau2^x
    a1, a2, t1, t2 = 3.0, 3e3, 0.02, 0.002
    a = a1 ** (1 - x) * a2**x
    assert ref.hk_tau(a, tau_f1=t1, tau_f2=t2, a1=a1, a2=a2) == pytest.approx(t1 ** (1 - x) * t2**x, rel=1e-14)


def test_continuous_at_the_corners():
    for a, tau in ((28.0, 1 / 43), (8e4, 1 / 43 / 30)):
        for side in (1 - 1e-12, 1 + 1e-12):
            assert ref.hk_tau(a * side) == pytest.approx(tau, rel=1e-10)
    assert math.isclose(ref.hk_tau(math.sqrt(28.0 * 8e4)), math.sqrt((1 / 43) * (1 / 43 / 30)), rel_tol=1e-14)
