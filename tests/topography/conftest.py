"""Fixtures shared by the topography tests (computed once for the package)."""

import pytest

from asperity.topography import analyse_surface

from .synthetic import as_map, synthetic_map


@pytest.fixture(scope="package")
def wide_band():
    """512^2 map, wavelengths 16 px .. 64 px roll-off (alpha_N ~ 4)."""
    return synthetic_map(512, roll_px=64, min_px=16, seed=1)


@pytest.fixture(scope="package")
def large_surface():
    """1024^2 map, wavelengths 16 px .. 256 px roll-off (alpha_N ~ 19), ~870 summits; analysed once."""
    heights, exact, _ = synthetic_map(1024, roll_px=256, min_px=16, seed=1)
    return analyse_surface(as_map(heights), b=2.5e-10), exact
