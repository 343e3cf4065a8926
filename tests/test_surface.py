"""asperity.surface: the GW Surface and its inversion from the groups (Eq 20)."""

import math

import numpy as np
import pint
import pytest

from asperity.quantities import PHYSICAL_PARAMETERS
from asperity.surface import Surface, surface_from_groups

u = pint.UnitRegistry()

SIGMA, RADIUS, ETA, AREA = 2e-9, 1e-6, 1e12, 1e-6  # the hand-calculation surface


@pytest.fixture
def surface():
    return Surface(sigma_s=SIGMA, R=RADIUS, eta=ETA, area=AREA)


def test_surface(surface):
    assert surface.N == pytest.approx(1e6)
    assert surface.alpha == pytest.approx(math.sqrt(2e-3))


@pytest.mark.parametrize("kwargs, message", [
    ({"sigma_s": -1e-9}, r"sigma_s must be > 0"), ({"R": 0.0}, r"R must be > 0"),
    ({"eta": [1e12, 1e13]}, r"eta must be a scalar"), ({"area": 1 * u.m}, r"area must have units compatible with m\^2"),
    ({"sigma_s": 2 * u.GPa}, r"sigma_s must have units compatible with m"),
])
def test_surface_validation(kwargs, message):
    base = {"sigma_s": SIGMA, "R": RADIUS, "eta": ETA, "area": AREA}
    with pytest.raises(ValueError, match=message):
        Surface(**{**base, **kwargs})


def test_surface_from_groups_validates():
    with pytest.raises(ValueError, match="alpha must be > 0"):
        surface_from_groups(0.0, 100.0, 2.5e-10, 1e12, 1e-6)


def test_surface_from_groups_is_eq20():
    """sigma_s = alpha beta b, R = beta b / alpha, by hand."""
    s = surface_from_groups(0.02, 300.0, 0.25 * u.nm, "1e12/m^2", 1 * u.mm**2)
    assert s.sigma_s == pytest.approx(0.02 * 300.0 * 2.5e-10, rel=1e-14)
    assert s.R == pytest.approx(300.0 * 2.5e-10 / 0.02, rel=1e-14)
    assert (s.eta, s.area) == (pytest.approx(1e12), pytest.approx(1e-6))
    assert s.alpha == pytest.approx(0.02, rel=1e-14)


def test_field_names_are_the_registry_names():
    # The quantities, then a label that is not one (and not compared).
    assert [f for f in Surface.__dataclass_fields__] == ["sigma_s", "R", "eta", "area", "source"]
    for name in ("sigma_s", "R", "eta", "area"):
        assert name in PHYSICAL_PARAMETERS
    assert not Surface.__dataclass_fields__["source"].compare
    assert Surface(1e-9, 1e-6, 1e12, 1e-6, source="a") == Surface(1e-9, 1e-6, 1e12, 1e-6)


def test_strings_with_units():
    s = Surface(sigma_s="2nm", R="1um", eta="1e12/m^2", area="1mm^2")
    assert (s.sigma_s, s.R, s.eta, s.area) == pytest.approx((SIGMA, RADIUS, ETA, AREA), rel=1e-15)
    assert s.N == pytest.approx(ETA * AREA)
    assert s.alpha == pytest.approx(math.sqrt(SIGMA / RADIUS))


@pytest.mark.parametrize("value, message", [
    (None, "sigma_s must be a real number"), (True, "boolean"), (2e-9 + 1j, "complex"),
    (float("inf"), "finite"), ("2", "needs a unit"), (np.array([[2e-9]]), "must be a scalar"),
])
def test_bad_values_name_the_field(value, message):
    with pytest.raises(ValueError, match=message):
        Surface(sigma_s=value, R=RADIUS, eta=ETA, area=AREA)


# -- rms roughness and summit heights (Nayak) -------------------------------------------------

def test_nayak_relation_by_hand():
    from asperity.surface import NAYAK_SIGMA_S, nayak_summit_sigma

    assert NAYAK_SIGMA_S == 0.8968
    for alpha_n in (1.0, 1.5, 5.0, 10.0, 100.0):
        assert nayak_summit_sigma(3e-9, alpha_n) == pytest.approx(3e-9 * (1 - 0.8968 / alpha_n) ** 0.5, rel=1e-15)
    # Broadband limit: summit heights spread like all heights.
    assert nayak_summit_sigma(1.0, 1e12) == pytest.approx(1.0, rel=1e-12)


def test_nayak_relation_equals_the_spectral_estimator():
    from asperity.surface import nayak_summit_sigma
    from asperity.topography.spectral import summit_sigma

    for alpha_n in (1.2, 3.0, 30.0):
        assert nayak_summit_sigma(2e-9, alpha_n) == pytest.approx(summit_sigma(4e-18, alpha_n), rel=1e-14)


def test_surface_from_rms():
    s = Surface.from_rms("5nm", "1um", "1e12/m^2", "1mm^2", alpha_n=10)
    assert s == Surface((1 - 0.08968) ** 0.5 * 5e-9, 1e-6, 1e12, 1e-6)
    assert s.source == "rms 5 nm with alpha_N = 10 (Nayak)"


@pytest.mark.parametrize("kwargs, error, message", [
    ({"alpha_n": 0.99}, ValueError, r"alpha_n .* must be >= 1"),
    ({"alpha_n": float("nan")}, ValueError, r"alpha_n must be finite"),
    ({"alpha_n": None}, ValueError, r"alpha_n must be a real number"),
    ({"rms": -1e-9}, ValueError, r"rms must be > 0"),
    ({"rms": "1 N"}, ValueError, r"rms must have units compatible with m"),
])
def test_surface_from_rms_errors(kwargs, error, message):
    base = {"rms": 5e-9, "R": 1e-6, "eta": 1e12, "area": 1e-6, "alpha_n": 10.0}
    with pytest.raises(error, match=message):
        Surface.from_rms(**{**base, **kwargs})


def test_from_rms_needs_the_bandwidth():
    with pytest.raises(TypeError, match="alpha_n"):
        Surface.from_rms(5e-9, 1e-6, 1e12, 1e-6)


def test_source_must_be_text():
    with pytest.raises(TypeError, match="source must be a string"):
        Surface(1e-9, 1e-6, 1e12, 1e-6, source=3)
