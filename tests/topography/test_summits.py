"""asperity.topography.summits: SummitParameters and the preparation both methods share."""

import json

import numpy as np
import pytest

from asperity.quantities import PHYSICAL_PARAMETERS
from asperity.topography import SummitParameters, detected_summits, spectral_summits
from asperity.topography.summits import GW_PARAMETERS, plain

from .synthetic import ST


def test_flat_surface_rejected():
    flat = ST.Topography(np.zeros((16, 16)), (1e-6, 1e-6), unit="m")
    with pytest.raises(ValueError, match="flat"):
        spectral_summits(flat)
    with pytest.raises(ValueError, match="no summits"):
        detected_summits(flat)




def test_rejects_non_topography():
    with pytest.raises(TypeError, match="SurfaceTopography"):
        spectral_summits(np.zeros((8, 8)))


# -- degenerate surfaces ---------------------------------------------------------------------

def _plane(n=32, m=24, slope=(0.7, -0.3), offset=0.0):
    x, y = np.meshgrid(np.arange(n), np.arange(m), indexing="ij")
    return (slope[0] * x + slope[1] * y) * 1e-9 + offset


@pytest.mark.parametrize("heights", [
    np.zeros((16, 16)), np.full((16, 16), 3.3e-9), _plane(), _plane(offset=1e-3), _plane(slope=(1e3, 2e3)),
    _plane().astype(np.float32).astype(float), (_plane() + 1e-6).astype(np.float32).astype(float),
], ids=["zeros", "constant", "tilted", "tilted-offset", "steep", "float32-tilted", "float32-offset"])
@pytest.mark.parametrize("estimator", [spectral_summits, detected_summits])
def test_flat_and_tilted_planes_are_refused(heights, estimator):
    """After detrending, a plane leaves rounding noise: refused, never turned into summit numbers."""
    nx, ny = heights.shape
    with pytest.raises(ValueError, match=r"the surface is flat: .* rms height is .* at most 1e-07 of the largest"):
        estimator(ST.Topography(heights, (nx * 1e-8, ny * 1e-8), unit="m", periodic=False))


@pytest.mark.parametrize("profile", [np.zeros(64), np.full(64, -2e-9), np.linspace(0, 1e-6, 64),
                                     np.linspace(5.0, 5.5, 64)])
def test_constant_and_sloped_profiles_are_refused(profile):
    line = ST.UniformLineScan(profile, 64e-8, unit="m", periodic=False)
    for estimator in (spectral_summits, detected_summits):
        with pytest.raises(ValueError, match="the surface is flat"):
            estimator(line)


def test_real_roughness_on_a_large_offset_or_tilt_is_accepted():
    """1e-5 of the largest height is roughness (far above float64 and float32 rounding), not a plane."""
    rough = np.random.default_rng(11).standard_normal((32, 24)) * 1e-9
    for base in (_plane(offset=1e-4), _plane(slope=(100.0, 50.0))):
        heights = base + rough
        assert np.std(rough) > 1e-6 * np.max(np.abs(heights))
        p = spectral_summits(ST.Topography(heights, (32e-8, 24e-8), unit="m", periodic=False))
        assert p.sigma == pytest.approx(np.std(rough), rel=0.1)


@pytest.mark.parametrize("shape", [(7, 40), (40, 7), (3, 3)])
def test_too_few_points(shape):
    topo = ST.Topography(np.random.default_rng(1).standard_normal(shape), (1e-6, 1e-6), unit="m")
    for estimator in (spectral_summits, detected_summits):
        with pytest.raises(ValueError, match=rf"too few points .* grid \({shape[0]}, {shape[1]}\); need at least 8"):
            estimator(topo)
    with pytest.raises(ValueError, match="too few points"):
        spectral_summits(ST.UniformLineScan(np.arange(7.0), 1e-6, unit="m"))


# -- SummitParameters ------------------------------------------------------------------------

def _params(**kwargs):
    base = {"sigma_s": 2e-9, "R": 1e-6, "eta": 4e12, "method": "spectral", "sigma": 2.1e-9,
            "mean_summit_height": 1e-9}
    return SummitParameters(**{**base, **kwargs})


def test_names_are_those_of_surface_and_the_registry():
    p = _params()
    assert list(GW_PARAMETERS) == ["sigma_s", "R", "eta"]
    assert all(name in PHYSICAL_PARAMETERS for name in GW_PARAMETERS)
    s = p.surface(1e-6)
    assert (s.sigma_s, s.R, s.eta, s.area) == (2e-9, 1e-6, 4e12, 1e-6)
    assert p.spacing == pytest.approx(0.5e-6)


def test_radius_and_density_are_deprecated_aliases():
    p = _params()
    with pytest.warns(DeprecationWarning, match=r"radius is deprecated; use \.R"):
        assert p.radius == p.R
    with pytest.warns(DeprecationWarning, match=r"density is deprecated; use \.eta"):
        assert p.density == p.eta
    with pytest.raises(AttributeError):
        p.radius = 1.0


def test_to_dict_is_strict_json():
    d = _params(alpha_n=float("inf"), m0=np.float64("nan"), n_summits=np.int64(3)).to_dict()
    assert d["R"] == 1e-6 and d["eta"] == 4e12 and "radius" not in d and "density" not in d
    assert d["alpha_n"] is None and d["m0"] is None and d["n_summits"] == 3 and type(d["n_summits"]) is int
    json.loads(json.dumps(d, allow_nan=False))
    assert plain({"a": (np.float32(0.5), [np.bool_(True)])}) == {"a": [0.5, [True]]}
