"""asperity.topography.spectral: summit parameters from spectral moments (Nayak; McCool)."""

import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from asperity.topography import spectral_summits
from asperity.topography.spectral import (
    NAYAK_SIGMA_S,
    RICE_SIGMA_P,
    bandwidth_alpha,
    mean_summit_height,
    summit_density,
    summit_radius,
    summit_sigma,
)

from .synthetic import DX, RMS, as_map, mccool


def test_spectral_moments_are_the_exact_finite_difference_moments(wide_band):
    heights, exact, fd = wide_band
    p = spectral_summits(as_map(heights))
    for key in ("m0", "m2", "m4"):
        assert getattr(p, key) == pytest.approx(fd[key], rel=1e-9)
        # the grid resolves the spectrum: FD and continuous moments agree to a few per cent
        assert getattr(p, key) == pytest.approx(exact[key], rel=0.03)
    assert p.alpha_n == pytest.approx(fd["m0"] * fd["m4"] / fd["m2"] ** 2, rel=1e-9)
    assert p.sigma == pytest.approx(RMS, rel=1e-9)


def test_spectral_summits_follow_mccool(wide_band):
    heights, exact, fd = wide_band
    p = spectral_summits(as_map(heights))
    sigma_s, radius, eta = mccool(fd["m0"], fd["m2"], fd["m4"])
    assert (p.sigma_s, p.R, p.eta) == pytest.approx((sigma_s, radius, eta), rel=1e-9)
    assert (p.sigma_s, p.R, p.eta) == pytest.approx(mccool(exact["m0"], exact["m2"], exact["m4"]), rel=0.03)
    assert p.mean_summit_height == pytest.approx(4 * math.sqrt(fd["m0"] / (math.pi * p.alpha_n)), rel=1e-9)
    assert p.method == "spectral" and p.n_summits is None and p.source == "map"
    assert p.anisotropy == pytest.approx(1.0, abs=0.02)


def test_spectral_moments_are_unit_and_tilt_invariant(wide_band):
    heights, _, fd = wide_band
    n = heights.shape[0]
    x, y = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    tilted = heights * 1e9 + 0.02 * x - 0.01 * y + 5.0  # nm, tilted and offset: not periodic
    p = spectral_summits(as_map(tilted, periodic=False, unit="nm", pixel=DX * 1e9))
    assert p.m0 == pytest.approx(fd["m0"], rel=1e-3)
    assert p.m2 == pytest.approx(fd["m2"], rel=0.01)  # the trimmed border costs < 1 %
    assert p.m4 == pytest.approx(fd["m4"], rel=0.01)


# -- the Nayak/McCool relations, one function each ----------------------------------------------

@given(m0=st.floats(1e-20, 1e-12), m2=st.floats(1e-6, 1.0), alpha=st.floats(1.0, 1e3))
def test_relations_are_mccools(m0, m2, alpha):
    m4 = alpha * m2**2 / m0  # a surface with bandwidth alpha
    sigma_s, R, eta = mccool(m0, m2, m4)
    a = bandwidth_alpha(m0, m2, m4)
    assert a == pytest.approx(alpha, rel=1e-12)
    assert summit_sigma(m0, a) == pytest.approx(sigma_s, rel=1e-9, abs=1e-300)
    assert summit_radius(m4) == pytest.approx(R, rel=1e-12)
    assert summit_density(m2, m4) == pytest.approx(eta, rel=1e-12)
    assert mean_summit_height(m0, a) == pytest.approx(4 * math.sqrt(m0 / (math.pi * alpha)), rel=1e-12)


def test_relations_limits_and_shapes():
    # Rice's profile-peak constant pi/2 - 1 and Nayak's 0.8968; both vanish at alpha_N = c
    assert RICE_SIGMA_P == pytest.approx(0.5707963267948966, rel=1e-15) and NAYAK_SIGMA_S == 0.8968
    assert summit_sigma(4.0, NAYAK_SIGMA_S) == 0.0 and summit_sigma(4.0, 0.5) == 0.0  # clipped below c
    assert summit_sigma(4.0, 1e12) == pytest.approx(2.0, rel=1e-11)  # broad band: sigma_s -> sqrt(m0)
    assert summit_sigma(1.0, 2.0, RICE_SIGMA_P) == pytest.approx(math.sqrt(1 - RICE_SIGMA_P / 2), rel=1e-15)
    out = summit_radius([1e12, 4e12])
    assert out.shape == (2,) and out[0] == pytest.approx(2 * out[1], rel=1e-14)
    with pytest.raises(ValueError, match="m2 must be > 0"):
        bandwidth_alpha(1.0, 0.0, 1.0)
    with pytest.raises(ValueError, match="m4 must be finite"):
        summit_density(1.0, float("inf"))
    with pytest.raises(ValueError, match=r"constant must lie in \[0, 1\]"):
        summit_sigma(1.0, 2.0, 1.5)
