"""Synthetic band-limited surfaces: the same surface on every grid, the asked-for slope and spectrum."""

import math

import numpy as np
import pytest

pytest.importorskip("SurfaceTopography")
from asperity.validation.surfaces import synthetic_surface  # noqa: E402


@pytest.mark.parametrize("kind", ["self-affine", "gaussian"])
def test_same_surface_on_two_grids(kind):
    a = synthetic_surface(kind, 2e-6, 32, short_cutoff=2e-6 / 8, seed=4)
    b = synthetic_surface(kind, 2e-6, 64, short_cutoff=2e-6 / 8, seed=4)
    np.testing.assert_allclose(b.heights()[::2, ::2], a.heights(), atol=1e-12 * np.abs(a.heights()).max())
    assert a.is_periodic and a.physical_sizes == (2e-6, 2e-6)
    # the rms slope by fine finite differences approaches the requested 0.1
    assert synthetic_surface(kind, 2e-6, 256, short_cutoff=2e-6 / 8, seed=4).rms_gradient() == \
        pytest.approx(0.1, rel=0.01)


def test_spectrum_is_band_limited():
    t = synthetic_surface("self-affine", 1e-6, 64, short_cutoff=1e-6 / 8, long_cutoff=0.5e-6, seed=1)
    spec = np.abs(np.fft.fft2(t.heights())) ** 2
    q = np.hypot(*np.meshgrid(np.fft.fftfreq(64), np.fft.fftfreq(64), indexing="ij")) * 64  # in 1/L
    assert spec[q > 8 + 1e-9].max() <= 1e-20 * spec.max()
    assert spec[0, 0] <= 1e-20 * spec.max()


@pytest.mark.parametrize("kwargs", [dict(kind="bumpy"), dict(grid=16), dict(short_cutoff=1e-6), dict(hurst=1.2),
                                    dict(rms_slope=-1.0), dict(grid=True)])
def test_bad_input(kwargs):
    args = dict(kind="self-affine", size=2e-6, grid=32, short_cutoff=2e-6 / 8)
    args.update(kwargs)
    with pytest.raises(ValueError):
        synthetic_surface(args.pop("kind"), args.pop("size"), args.pop("grid"), **args)


def test_gaussian_correlation_length():
    # Autocorrelation exp(-r^2/ell^2), ell = 6/q_s: averaged over eight surfaces and both axes (loose bound).
    ell = 6.0 / (2 * math.pi / (4e-6 / 16)) / (4e-6 / 128)  # in pixels
    lag = round(ell)
    values = []
    for seed in range(8):
        h = np.asarray(synthetic_surface("gaussian", 4e-6, 128, short_cutoff=4e-6 / 16, seed=seed).heights())
        acf = np.fft.ifft2(np.abs(np.fft.fft2(h)) ** 2).real
        values.append((acf[lag, 0] + acf[0, lag]) / (2 * acf[0, 0]))
    assert np.mean(values) == pytest.approx(math.exp(-(lag / ell) ** 2), abs=0.08)
