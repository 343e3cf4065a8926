"""asperity.nix_gao: the Nix-Gao hardness and its mapping onto an asperity's interference."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from asperity import nix_gao as ng


def test_hardness_by_hand():
    assert float(ng.ng_hardness(0.5e-6, 0.58e9, 1.6e-6)) == pytest.approx(0.58e9 * math.sqrt(1 + 3.2), rel=1e-15)
    assert float(ng.ng_hardness(1e-9, 2.0, 0.0)) == 2.0  # no size effect
    # deep indents tend to H0
    assert float(ng.ng_hardness(1.0, 2.0, 1e-6)) == pytest.approx(2.0, rel=1e-6)


@settings(max_examples=80, deadline=None)
@given(w0=st.floats(1e-12, 1e3), h=st.floats(0.0, 1e4), target=st.floats(1e-3, 1e3))
def test_interference_inverts_the_scaled_interference(w0, h, target):
    omega = float(ng.ng_interference(target, w0, h))
    assert float(ng.ng_scaled_interference(omega, w0, h)) == pytest.approx(target, rel=1e-10)


@settings(max_examples=80, deadline=None)
@given(w0=st.floats(1e-12, 1e3), h=st.floats(0.0, 1e6))
def test_critical_interference_is_self_consistent(w0, h):
    wc = float(ng.ng_critical_interference(w0, h))
    # yield where omega reaches the critical interference of the hardness at that depth
    assert wc == pytest.approx(w0 * (1.0 + h / wc), rel=1e-12)
    assert wc >= w0


def test_critical_interference_limits():
    assert float(ng.ng_critical_interference(3e-12, 0.0)) == 3e-12
    w0, h = 1e-12, 1e-6  # h* >> omega_c0: omega_c -> sqrt(omega_c0 h*)
    assert float(ng.ng_critical_interference(w0, h)) == pytest.approx(math.sqrt(w0 * h), rel=1e-3)


def test_scaled_interference_without_size_effect_and_at_zero():
    w = np.array([0.0, 0.5, 2.0])
    assert np.array_equal(ng.ng_scaled_interference(w, 0.5, 0.0), w / 0.5)
    assert float(ng.ng_scaled_interference(0.0, 1.0, 5.0)) == 0.0


def test_scaled_interference_increases():
    w = np.geomspace(1e-6, 1e3, 500)
    assert np.all(np.diff(ng.ng_scaled_interference(w, 1e-3, 2.0)) > 0)


@pytest.mark.parametrize("call, match", [
    (lambda: ng.ng_hardness(0.0, 1.0, 1.0), r"h must be > 0"),
    (lambda: ng.ng_hardness(1.0, 1.0, -1.0), r"h_star must be >= 0"),
    (lambda: ng.ng_scaled_interference(1.0, 0.0, 1.0), r"omega_c0 must be > 0"),
    (lambda: ng.ng_interference(-1.0, 1.0, 1.0), r"omega_star must be >= 0"),
    (lambda: ng.ng_critical_interference(float("inf"), 1.0), r"omega_c0 must be finite"),
])
def test_bad_input(call, match):
    with pytest.raises(ValueError, match=match):
        call()
