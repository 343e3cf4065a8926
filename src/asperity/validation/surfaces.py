r"""Synthetic rough surfaces for checks: self-affine and Gaussian-correlated, band-limited.

Both are drawn by Fourier filtering of Gaussian noise (SurfaceTopography's
:func:`~SurfaceTopography.Generation.fourier_synthesis`) with a power spectrum that is
zero above the short-wavelength cutoff :math:`q_s = 2\pi/\lambda_s`:

* **self-affine**: :math:`C(q) \propto q^{-2-2H}` for :math:`q_L \le q \le q_s`, flat below
  the long-wavelength cutoff :math:`q_L = 2\pi/\lambda_L` (Hurst exponent :math:`H`);
* **Gaussian-correlated**: :math:`C(q) \propto \exp(-q^2\ell^2/4)`, the spectrum of the
  autocorrelation :math:`\exp(-r^2/\ell^2)`, with :math:`\ell = 6/q_s` (the spectrum is
  :math:`e^{-9}` of its peak at the cutoff).

The heights are scaled to a given rms slope :math:`\langle|\nabla h|^2\rangle^{1/2}`.  A
surface is drawn once on its base grid (:math:`\lambda_s` spanning
:data:`BASE_PIXELS_PER_WAVELENGTH` pixels) and brought to any finer grid by zero-padding its
spectrum, so every grid holds the *same* band-limited surface: a grid refinement changes the
discretisation only.  Periodic.

References
----------
.. [1] T. D. B. Jacobs, T. Junge, L. Pastewka, Surf. Topogr.: Metrol. Prop. 5 (2017) 013001.
.. [2] S. B. Ramisetti et al., J. Phys.: Condens. Matter 23 (2011) 215004.
"""

from __future__ import annotations

import math

import numpy as np

from .._optional import require
from .._validation import check_scalar_positive, check_scalar_range

__all__ = ["synthetic_surface", "SURFACE_KINDS", "BASE_PIXELS_PER_WAVELENGTH", "MAX_GRID"]

#: Kinds of :func:`synthetic_surface`.
SURFACE_KINDS = ("self-affine", "gaussian")
#: Pixels per shortest wavelength on the grid the spectrum is drawn on (>= 2, Nyquist).
BASE_PIXELS_PER_WAVELENGTH = 4
#: Most grid points per axis of a synthetic surface (a 4096^2 map holds 134 MB of heights).
MAX_GRID = 4096


def synthetic_surface(kind, size, grid, *, short_cutoff, rms_slope=0.1, hurst=0.8, long_cutoff=None, seed=0):
    """A periodic, band-limited synthetic surface in metres (see the module docstring).

    Parameters
    ----------
    kind : {'self-affine', 'gaussian'}
        Power spectrum.
    size : float
        Side of the square scan [m], > 0.
    grid : int
        Points per side, at least ``BASE_PIXELS_PER_WAVELENGTH * size / short_cutoff`` and at
        most :data:`MAX_GRID`.
    short_cutoff : float
        Shortest wavelength :math:`\\lambda_s` [m], > 0, at most ``size / 4``.
    rms_slope : float
        Rms gradient :math:`\\langle|\\nabla h|^2\\rangle^{1/2}` [-], > 0.
    hurst : float
        Hurst exponent, 0 < H < 1 (self-affine only).
    long_cutoff : float, optional
        Long-wavelength cutoff :math:`\\lambda_L` [m] in (``short_cutoff``, ``size``]
        (self-affine only; default ``size``).
    seed : int
        Seed of the random numbers, >= 0: equal seeds give equal surfaces on every grid.

    Returns
    -------
    SurfaceTopography.Topography
        ``grid x grid`` heights [m], periodic, unit 'm'.

    Raises
    ------
    ValueError
        For an unknown kind, a grid too coarse for the cutoff (or above :data:`MAX_GRID`), or
        parameters out of range.
    TypeError
        For a seed that is not a non-negative integer.
    """
    if not isinstance(kind, str) or kind not in SURFACE_KINDS:
        raise ValueError(f"kind must be one of {SURFACE_KINDS}, got {kind!r}")
    size = check_scalar_positive(size, "size", "m")
    lam_s = check_scalar_positive(short_cutoff, "short_cutoff", "m")
    slope = check_scalar_positive(rms_slope, "rms_slope", "")
    if lam_s > size / 4:
        raise ValueError(f"short_cutoff must be at most size/4 = {size / 4:g} m, got {lam_s:g}")
    ratio = size / lam_s
    if ratio > MAX_GRID / BASE_PIXELS_PER_WAVELENGTH:
        raise ValueError(f"size/short_cutoff = {ratio:.3g} needs more than {MAX_GRID} points per axis "
                         f"({BASE_PIXELS_PER_WAVELENGTH} per shortest wavelength): raise short_cutoff or lower size")
    base = 2 * math.ceil(BASE_PIXELS_PER_WAVELENGTH * ratio / 2)
    if isinstance(grid, bool) or not isinstance(grid, int | np.integer) or not base <= grid <= MAX_GRID:
        raise ValueError(f"grid must be an integer in [{base}, {MAX_GRID}] ({BASE_PIXELS_PER_WAVELENGTH} points per "
                         f"shortest wavelength for size = {size:g} m, short_cutoff = {lam_s:g} m), got {grid!r}")
    if isinstance(seed, bool) or not isinstance(seed, int | np.integer) or seed < 0:
        raise TypeError(f"seed must be a non-negative integer, got {seed!r}")
    if kind == "self-affine":
        hurst = check_scalar_range(hurst, "hurst", 0.0, 1.0, what="Hurst exponent")
        if not 0 < hurst < 1:
            raise ValueError(f"hurst (Hurst exponent) must lie in (0, 1), got {hurst!r}")
        lam_l = size if long_cutoff is None else check_scalar_positive(long_cutoff, "long_cutoff", "m")
        if not lam_s < lam_l <= size:
            raise ValueError(f"long_cutoff must lie in (short_cutoff, size] = ({lam_s:g}, {size:g}] m, got {lam_l:g}")
    st = require("SurfaceTopography", purpose="synthetic surfaces", extra="topography")
    generation = require("SurfaceTopography.Generation", purpose="synthetic surfaces", extra="topography")
    rng = np.random.default_rng(seed)
    if kind == "self-affine":
        topo = generation.fourier_synthesis((base, base), (size, size), hurst=float(hurst), rms_slope=1.0,
                                            short_cutoff=lam_s, long_cutoff=lam_l, rng=rng)
    else:
        ell = 6.0 / (2 * math.pi / lam_s)
        topo = generation.fourier_synthesis((base, base), (size, size), psd=lambda q: np.exp(-(q * ell) ** 2 / 4),
                                            short_cutoff=lam_s, rng=rng)
    h = np.asarray(topo.heights(), dtype=float)
    h = (h - h.mean()) * slope / _spectral_slope(h, size)  # exact for a band-limited surface, any grid
    return st.Topography(_fourier_refine(h, int(grid)), (size, size), periodic=True, unit="m")


def _spectral_slope(h, size):
    """Rms gradient of the periodic map ``h`` of side ``size`` from its Fourier coefficients."""
    n = h.shape[0]
    q = 2 * math.pi * np.fft.fftfreq(n, d=size / n)
    q2 = q[:, None] ** 2 + q[None, :] ** 2
    return math.sqrt(float(np.sum(q2 * np.abs(np.fft.fft2(h)) ** 2)) / n**4)


def _fourier_refine(h, n):
    """Band-limited interpolation of the periodic square map ``h`` to ``n x n`` (zero-padded spectrum)."""
    m = h.shape[0]
    if n == m:
        return h
    spec = np.fft.rfft2(h)
    out = np.zeros((n, n // 2 + 1), dtype=complex)
    k = m // 2
    out[:k, :k] = spec[:k, :k]
    out[-k:, :k] = spec[-k:, :k]
    return np.fft.irfft2(out, s=(n, n)) * (n * n) / (m * m)
