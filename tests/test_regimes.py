"""asperity.regimes: Tabor, Maugis and Fuller-Tabor parameters, the adhesion regime."""

import math

import numpy as np
import pint
import pytest

from asperity.maugis_dugdale import md_lambda
from asperity.regimes import adhesion_regime, fuller_tabor_parameter, maugis_parameter, tabor_parameter

u = pint.UnitRegistry()


def test_tabor_parameter():
    R, w, E, z0 = 1e-6, 0.1, 1e11, 0.3e-9
    assert tabor_parameter(R, w, E, z0) == pytest.approx((R * w**2 / (E**2 * z0**3)) ** (1 / 3), rel=1e-14)
    assert tabor_parameter(1 * u.um, 0.1 * u.J / u.m**2, 100 * u.GPa, 0.3 * u.nm) == pytest.approx(
        tabor_parameter(R, w, E, z0), rel=1e-13)
    out = tabor_parameter([1e-6, 8e-6], w, E, z0)
    assert out.shape == (2,) and out[1] == pytest.approx(2 * out[0])
    with pytest.raises(ValueError, match="z0 must be > 0"):
        tabor_parameter(R, w, E, 0.0)


def test_maugis_parameter_is_eq14():
    R, w, E, s0 = 1e-6, 0.1, 1e11, 3e8
    K = 4 / 3 * E
    assert maugis_parameter(R, w, E, s0) == pytest.approx(2 * s0 * (R / (math.pi * w * K**2)) ** (1 / 3), rel=1e-14)
    lam = maugis_parameter(R, w, E, s0)
    np.testing.assert_allclose(maugis_parameter(R, w, E, [s0, 2 * s0]), [lam, 2 * lam], rtol=1e-14)
    with pytest.raises(ValueError, match="w must have units"):
        maugis_parameter(R, 1 * u.Pa, E, s0)


def test_adhesion_regime():
    assert adhesion_regime(0.05) == "DMT"
    assert adhesion_regime(0.1) == "Maugis-Dugdale"
    assert adhesion_regime(5.0) == "Maugis-Dugdale"
    assert adhesion_regime(5.1) == "JKR"
    assert list(adhesion_regime([0.0, 1.0, 100.0])) == ["DMT", "Maugis-Dugdale", "JKR"]
    assert adhesion_regime(0.5, dmt_below=1.0, jkr_above=3.0) == "DMT"
    with pytest.raises(ValueError, match="dmt_below must be < jkr_above"):
        adhesion_regime(1.0, dmt_below=5.0, jkr_above=0.1)
    with pytest.raises(ValueError, match="lam must be >= 0"):
        adhesion_regime(-1.0)


def test_fuller_tabor_parameter():
    sigma, R, w, E = 2e-9, 1e-6, 0.1, 1e11
    theta = fuller_tabor_parameter(sigma, R, w, E)
    assert theta == pytest.approx(E * sigma**1.5 / (math.sqrt(R) * w), rel=1e-14)
    hertz_over_adhesion = (4 / 3) * E * math.sqrt(R) * sigma**1.5 / (math.pi * w * R)
    assert hertz_over_adhesion == pytest.approx(4 / (3 * math.pi) * theta, rel=1e-14)
    assert fuller_tabor_parameter(2 * u.nm, 1 * u.um, w, E) == pytest.approx(theta, rel=1e-13)
    assert fuller_tabor_parameter([sigma, 4 * sigma], R, w, E)[1] == pytest.approx(8 * theta)


def test_maugis_parameter_and_md_lambda_take_one_order():
    """maugis_parameter and md_lambda take (R, w, E_star, sigma0), like tabor_parameter(R, w, E_star, z0)."""
    R, w, E, s0 = 2e-6, 0.3, 7e10, 5e8
    assert maugis_parameter(R, w, E, s0) == pytest.approx(float(md_lambda(R, w, E, s0)), rel=1e-15)
    # lambda grows as R^(1/3) and linearly in sigma0; swapping R and sigma0 would break both
    assert maugis_parameter(8 * R, w, E, s0) == pytest.approx(2 * maugis_parameter(R, w, E, s0), rel=1e-14)
    np.testing.assert_allclose(md_lambda(R, w, E, [s0, 3 * s0]), 3 ** np.array([0, 1]) * md_lambda(R, w, E, s0),
                               rtol=1e-14)
    # sigma0 = w/z0 in Eq 14 against Tabor's definition: lambda = 2 (E*^2/pi K^2)^(1/3) mu_T = 2 (9/16 pi)^(1/3) mu_T
    z0 = 0.3e-9
    lam = maugis_parameter(R, w, E, w / z0)
    mu_T = tabor_parameter(R, w, E, z0)
    assert lam == pytest.approx(2 * (9 / (16 * math.pi)) ** (1 / 3) * mu_T, rel=1e-13)
    with pytest.raises(ValueError, match="sigma0 must be > 0"):
        maugis_parameter(R, w, E, 0.0)
