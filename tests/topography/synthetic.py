"""Synthetic surfaces with known spectral moments, shared by the topography tests.

Surfaces are built by Fourier synthesis with deterministic amplitudes and random phases,
so their spectral moments are known exactly:

* continuous moments  m0 = sum C,  m2 = sum C kx^2,  m4 = sum C kx^4  (averaged over x, y);
* the moments of SurfaceTopography's finite differences (upwind slope, central
  curvature) of a periodic surface are exact sums over the same spectrum with the
  difference operators' symbols  4 sin^2(k dx/2)/dx^2  in place of k^2.
"""

import math

import numpy as np

from asperity._optional import require

ST = require("SurfaceTopography", purpose="the topography tests")
DX = 10e-9  # pixel size [m]
RMS = 2e-9  # rms height [m]


def _isotropic_psd(q, q_roll, q_max, hurst):
    """Flat below q_roll, self-affine C ~ q^-2(1+H) up to q_max, zero above (unnormalised)."""
    c = (np.maximum(q, q_roll) / q_roll) ** (-2 * (1 + hurst))
    return np.where(q > q_max, 0.0, c)


def synthetic_map(n, *, roll_px, min_px, hurst=0.8, seed=0):
    """Periodic isotropic Gaussian-like surface and its exact moments.

    Returns heights (n, n) [m] and dicts of continuous and finite-difference moments.
    """
    k = 2 * np.pi * np.fft.fftfreq(n, d=DX)
    kx, ky = np.meshgrid(k, k, indexing="ij")
    q = np.hypot(kx, ky)
    c = _isotropic_psd(q, 2 * np.pi / (roll_px * DX), 2 * np.pi / (min_px * DX), hurst)
    c[0, 0] = 0.0
    c *= RMS**2 / c.sum()  # c[k] = |h_k|^2, so sum c = <h^2>
    r = np.random.default_rng(seed).random((n, n))
    r -= np.roll(r[::-1, ::-1], 1, axis=(0, 1))  # phase(-k) = -phase(k): real heights
    heights = (np.fft.ifft2(np.sqrt(c) * np.exp(2j * np.pi * r)) * n * n).real
    sx, sy = (4 / DX**2 * np.sin(kk * DX / 2) ** 2 for kk in (kx, ky))
    exact = {"m0": c.sum(), "m2": (c * (kx**2 + ky**2)).sum() / 2, "m4": (c * (kx**4 + ky**4)).sum() / 2}
    # finite differences: <|grad h|^2>/2 and 3/8 <(discrete Laplacian)^2>, as in the module
    fd = {"m0": c.sum(), "m2": (c * (sx + sy)).sum() / 2, "m4": 3 / 8 * (c * (sx + sy) ** 2).sum()}
    return heights, exact, fd


def synthetic_profile(n, *, roll_px, min_px, hurst=0.8, seed=0):
    """Periodic 1D Gaussian-like profile and its exact continuous moments."""
    k = 2 * np.pi * np.fft.rfftfreq(n, d=DX)
    c = _isotropic_psd(k, 2 * np.pi / (roll_px * DX), 2 * np.pi / (min_px * DX), hurst)
    c[0] = 0.0
    c *= RMS**2 / c.sum()  # h = sum sqrt(2 c_k) cos(k x + phi_k)
    phase = np.exp(2j * np.pi * np.random.default_rng(seed).random(k.size))
    heights = np.fft.irfft(np.sqrt(2 * c) * phase * n / 2, n)
    return heights, {"m0": c.sum(), "m2": (c * k**2).sum(), "m4": (c * k**4).sum()}


def mccool(m0, m2, m4):
    """McCool (1986) summit parameters: (sigma_s, R, eta)."""
    alpha = m0 * m4 / m2**2
    return (math.sqrt(1 - 0.8968 / alpha) * math.sqrt(m0), 0.375 * math.sqrt(math.pi / m4),
            m4 / (6 * math.pi * math.sqrt(3) * m2))


def as_map(heights, periodic=True, unit="m", pixel=DX):
    nx, ny = heights.shape
    return ST.Topography(heights, (nx * pixel, ny * pixel), periodic=periodic, unit=unit)


def paraboloid_lattice(cells, spacing_px, radius, pixel=DX):
    """Identical paraboloids -r^2/2R on a square lattice; interior = whole cells.

    The grid has cells * spacing_px + 2 points per side, so the interior points (the
    border rows and columns excluded) are exactly ``cells**2`` lattice cells.
    """
    n = cells * spacing_px + 2
    rel = ((np.arange(n) - 1) % spacing_px - (spacing_px - 1) / 2) * pixel
    x, y = np.meshgrid(rel, rel, indexing="ij")
    return ST.Topography(-(x**2 + y**2) / (2 * radius), (n * pixel, n * pixel), unit="m")
