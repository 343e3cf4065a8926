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
