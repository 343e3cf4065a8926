r"""Greenwood-Williamson summit parameters of measured surfaces.

Reads an AFM height map or a profilometer line scan with SurfaceTopography and
estimates the three surface inputs of the Greenwood-Williamson (GW) model,

=================  ===========================================  ===========
symbol             meaning                                      unit
=================  ===========================================  ===========
``sigma_s``        standard deviation of summit heights         m
``radius``         mean summit radius of curvature :math:`R`    m
``density``        summit density :math:`\eta` (per area)       1/m\ :sup:`2`
=================  ===========================================  ===========

in two independent ways:

* :func:`spectral_summits` -- from the spectral moments :math:`m_0, m_2, m_4`
  through the random-process relations of Nayak (1971) as summarised by
  McCool (1986), valid for an isotropic Gaussian surface;
* :func:`detected_summits` -- by finding the summits (local maxima) on the grid
  and measuring their heights and curvatures directly.

:func:`analyse_surface` runs both, compares them and lists what looks unreliable.

**Spectral moments.**  McCool's moments are *profile* moments of an isotropic
surface :math:`h(x, y)`:

.. math::

    m_0 = \langle h^2 \rangle, \qquad
    m_2 = \langle (\partial h/\partial x)^2 \rangle, \qquad
    m_4 = \langle (\partial^2 h/\partial x^2)^2 \rangle ,

the same in every direction.  For a map they are computed from area averages that
do not single out a direction (Nayak 1971; Longuet-Higgins 1957: :math:`m_{20} = m_{02} = m_2`,
:math:`m_{40} = m_{04} = 3 m_{22} = m_4` for an isotropic surface):

.. math::

    m_0 = S_q^2, \qquad
    \langle |\nabla h|^2 \rangle = m_{20} + m_{02} = 2 m_2, \qquad
    \langle (\nabla^2 h)^2 \rangle = m_{40} + 2 m_{22} + m_{04} = \tfrac{8}{3} m_4 .

SurfaceTopography's ``rms_gradient`` is :math:`\langle |\nabla h|^2\rangle^{1/2}` and
its ``rms_curvature_from_area`` is half the rms Laplacian,
:math:`\langle (\nabla^2 h/2)^2\rangle^{1/2}`, hence

.. math::

    m_2 = \tfrac12\,\mathrm{rms\_gradient}^2, \qquad
    m_4 = \tfrac38 \langle (\nabla^2 h)^2\rangle = \tfrac32\,\mathrm{rms\_curvature\_from\_area}^2 .

For a line scan, :math:`m_0 = R_q^2`, :math:`m_2 = R_{\Delta q}^2`,
:math:`m_4 = R_{\Delta\Delta q}^2` (``Rq``, ``Rdq``, ``Rddq``; the older names
``rms_*_from_profile`` are deprecated aliases of these).  All derivatives are
SurfaceTopography's finite differences on the measured grid (upwind for slopes,
central for curvatures), i.e. the moments include everything the instrument
resolved, down to the pixel.

**Summit statistics** (Nayak 1971, as collected by McCool 1986), with the bandwidth
parameter :math:`\alpha_N = m_0 m_4 / m_2^2 \ge 1`:

.. math::

    \eta = \frac{m_4}{6\pi\sqrt3\, m_2}, \qquad
    R = \frac{3}{8}\sqrt{\frac{\pi}{m_4}}, \qquad
    \sigma_s = \Bigl(1 - \frac{0.8968}{\alpha_N}\Bigr)^{1/2} \sqrt{m_0}, \qquad
    \bar z_s = \frac{4}{\sqrt{\pi \alpha_N}} \sqrt{m_0} .

:math:`R` is the reciprocal of the mean summit curvature
:math:`\bar\kappa_s = \tfrac83\sqrt{m_4/\pi}`, the curvature of a summit being the
mean of its two principal curvatures, :math:`\kappa = -(h_{xx}+h_{yy})/2`.  Averaged
over *all* summits this value does not depend on :math:`\alpha_N` (the Hessian of a
stationary Gaussian field is independent of its gradient); it is the large-:math:`\alpha_N`
limit only for the curvature of the high summits.  :math:`\bar z_s` is the mean summit
height above the mean plane, which the GW separation is measured from.

References
----------
.. [1] Greenwood, J. A., Williamson, J. B. P. (1966). Contact of nominally flat
   surfaces. Proc. R. Soc. Lond. A 295, 300-319.
.. [2] Nayak, P. R. (1971). Random process model of rough surfaces. J. Lubr. Technol.
   (ASME) 93, 398-407.
.. [3] McCool, J. I. (1986). Comparison of models for the contact of rough surfaces.
   Wear 107, 37-60.
.. [4] Longuet-Higgins, M. S. (1957). The statistical analysis of a random, moving
   surface. Phil. Trans. R. Soc. Lond. A 249, 321-387.
.. [5] Rice, S. O. (1944). Mathematical analysis of random noise. Bell Syst. Tech. J.
   23, 282-332.
"""

from __future__ import annotations

import math
import os
import warnings
from dataclasses import asdict, dataclass, field
from typing import Any

import numpy as np

__all__ = [
    "SummitParameters",
    "SurfaceAnalysis",
    "read_topography",
    "spectral_summits",
    "detected_summits",
    "analyse_surface",
]

_INSTALL_HINT = "pip install 'asperity[topography]'"

#: Nayak's constant in the summit-height variance (Nayak 1971; McCool 1986).
NAYAK_SIGMA_S = 0.8968
#: Same constant for the heights of profile peaks, :math:`\pi/2 - 1` (Rice 1944).
RICE_SIGMA_P = math.pi / 2 - 1

#: Thresholds of :func:`analyse_surface` (see its docstring).
RATIO_TOLERANCE = 1.5
SIGMA_TOLERANCE = 0.30
MIN_ALPHA_N = 5.0
MIN_SPACING_PIXELS = 5.0
MIN_RADIUS_PIXELS = 3.0
MIN_SUMMITS = 30
MAX_ANISOTROPY = 1.5


# --------------------------------------------------------------------------- results
@dataclass(frozen=True)
class SummitParameters:
    """GW summit parameters of one surface, estimated by one method.

    Attributes
    ----------
    sigma_s : float
        Standard deviation of summit heights [m].
    radius : float
        Mean summit radius :math:`R` [m], the reciprocal of the mean summit curvature.
    density : float
        Summit density :math:`\\eta` [1/m^2].
    method : str
        ``'spectral'`` or ``'detected'``.
    sigma : float
        Rms height :math:`\\sqrt{m_0}` of the detrended surface [m].
    mean_summit_height : float
        Mean summit height above the mean plane [m].
    m0, m2, m4 : float or None
        Profile spectral moments [m^2], [-], [1/m^2] (None where not used).
    alpha_n : float or None
        Bandwidth parameter :math:`\\alpha_N = m_0 m_4/m_2^2` [-].
    n_summits : int or None
        Number of summits (or profile peaks) found; None for the spectral method.
    anisotropy : float or None
        Ratio of the larger to the smaller mean square slope along x and y (maps only).
    source : str
        ``'map'`` or ``'line scan'``.
    """

    sigma_s: float
    radius: float
    density: float
    method: str
    sigma: float
    mean_summit_height: float
    m0: float | None = None
    m2: float | None = None
    m4: float | None = None
    alpha_n: float | None = None
    n_summits: int | None = None
    anisotropy: float | None = None
    source: str = "map"

    @property
    def spacing(self) -> float:
        """Mean distance between summits, :math:`\\eta^{-1/2}` [m]."""
        return 1.0 / math.sqrt(self.density)

    def surface(self, area):
        """The GW :class:`~asperity.physical.Surface` of these summits over a nominal ``area`` (m^2)."""
        from .physical import Surface

        return Surface(sigma_s=self.sigma_s, R=self.radius, eta=self.density, area=area)

    def to_dict(self) -> dict[str, Any]:
        """Plain-``float``/``int``/``str`` dictionary, ready for :func:`json.dumps`."""
        return {k: _plain(v) for k, v in asdict(self).items()}


@dataclass(frozen=True)
class SurfaceAnalysis:
    """Summit parameters of one measured surface by both methods.

    Attributes
    ----------
    spectral, detected : SummitParameters
        Results of :func:`spectral_summits` and :func:`detected_summits`.
    dim : int
        1 for a line scan, 2 for a map.
    nb_grid_pts : tuple of int
        Number of points along x (and y).
    physical_sizes : tuple of float
        Scan size along x (and y) [m].
    pixel_size : tuple of float
        Grid spacing along x (and y) [m].
    n_points : int
        Total number of height values.
    warnings : list of str
        Reasons to distrust the numbers (not Python warnings).
    b : float or None
        Burgers vector [m] used for ``groups``.
    groups : dict or None
        ``{'spectral': {'alpha': .., 'beta': ..}, 'detected': {...}}``, Eq 7 of the paper.
    source : str or None
        File the surface was read from.
    """

    spectral: SummitParameters
    detected: SummitParameters
    dim: int
    nb_grid_pts: tuple[int, ...]
    physical_sizes: tuple[float, ...]
    pixel_size: tuple[float, ...]
    n_points: int
    warnings: list[str] = field(default_factory=list)
    b: float | None = None
    groups: dict[str, dict[str, float]] | None = None
    source: str | None = None

    def to_dict(self) -> dict[str, Any]:
        """Nested plain dictionary for JSON output."""
        out = {k: _plain(getattr(self, k)) for k in
               ("dim", "nb_grid_pts", "physical_sizes", "pixel_size", "n_points", "b", "groups", "source")}
        out["spectral"] = self.spectral.to_dict()
        out["detected"] = self.detected.to_dict()
        out["warnings"] = list(self.warnings)
        return out

    def summary(self) -> str:
        """A few lines for a terminal."""
        kind = "line scan" if self.dim == 1 else "map"
        size = " x ".join(f"{s * 1e6:.4g}" for s in self.physical_sizes)
        grid = " x ".join(str(n) for n in self.nb_grid_pts)
        px = " x ".join(f"{p * 1e9:.4g}" for p in self.pixel_size)
        lines = [f"{kind}: {size} um, {grid} points, pixel {px} nm"
                 + (f"  [{self.source}]" if self.source else ""),
                 f"{'method':<10}{'sigma_s [nm]':>14}{'R [um]':>12}{'eta [1/um^2]':>15}{'summits':>9}"
                 + ("" if self.groups is None else f"{'alpha':>10}{'beta':>10}")]
        for p in (self.spectral, self.detected):
            n = "-" if p.n_summits is None else str(p.n_summits)
            row = f"{p.method:<10}{p.sigma_s * 1e9:>14.4g}{p.radius * 1e6:>12.4g}{p.density * 1e-12:>15.4g}{n:>9}"
            if self.groups is not None:
                g = self.groups.get(p.method)  # absent when sigma_s = 0
                row += f"{g['alpha']:>10.4g}{g['beta']:>10.4g}" if g else f"{'-':>10}{'-':>10}"
            lines.append(row)
        s = self.spectral
        lines.append(f"rms height {s.sigma * 1e9:.4g} nm, alpha_N = {s.alpha_n:.3g}")
        lines += [f"warning: {w}" for w in self.warnings]
        return "\n".join(lines)


def _plain(value):
    """Convert NumPy scalars/tuples to JSON-friendly Python objects."""
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    if isinstance(value, (tuple, list)):
        return [_plain(v) for v in value]
    if isinstance(value, np.integer):
        return int(value)
    if isinstance(value, np.floating):
        return float(value)
    return value


# --------------------------------------------------------------------------- reading
def _surface_topography():
    """Import SurfaceTopography lazily (its MPI stub warns when mpi4py is absent)."""
    try:
        with warnings.catch_warnings():
            warnings.filterwarnings("ignore", message="Could not import mpi4py", category=ImportWarning)
            import SurfaceTopography
    except ImportError as err:
        raise ImportError(f"reading measured surfaces needs SurfaceTopography: {_INSTALL_HINT}") from err
    return SurfaceTopography


def read_topography(path, *, physical_sizes=None, unit=None, channel_index=None, fill_undefined=False):
    """Read an AFM map or profilometer line scan into a SurfaceTopography object in metres.

    Parameters
    ----------
    path : str or os.PathLike
        Any file format SurfaceTopography reads (text matrix with header, x3p, NetCDF,
        npy, Gwyddion, DI, Bruker, ...).
    physical_sizes : tuple of float, optional
        Scan size along x (and y), in ``unit``; only for files that do not store it.
    unit : str, optional
        Length unit (``'m'``, ``'um'``/``'µm'``, ``'nm'``, ...) of heights and sizes;
        only for files that do not store it.
    channel_index : int, optional
        Data channel to read (default: the file's default channel).
    fill_undefined : bool, optional
        Undefined (NaN/masked) heights raise :class:`ValueError` unless True, in which
        case they are filled by harmonic interpolation.  Default False.

    Returns
    -------
    SurfaceTopography.Topography or SurfaceTopography.UniformLineScan
        Heights and sizes in metres (``unit == 'm'``).

    Raises
    ------
    ValueError
        If the file is missing, empty, unreadable, has no physical size or unit (the
        message says which keyword to pass), or has undefined data.
    ImportError
        If SurfaceTopography is not installed.

    Notes
    -----
    Warnings raised by SurfaceTopography while reading are re-issued with the file
    name, never dropped (only its notice that mpi4py is missing is ignored).
    """
    st = _surface_topography()
    name = os.fspath(path)
    if not os.path.isfile(name):
        raise ValueError(f"{name}: no such file")
    if os.path.getsize(name) == 0:
        raise ValueError(f"{name}: file is empty")
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        topo = _read(st, name, physical_sizes, unit, channel_index)
    for w in caught:
        warnings.warn(f"{name}: {w.message}", w.category, stacklevel=2)
    return _finish(topo, name, fill_undefined)


def _read(st, name, physical_sizes, unit, channel_index):
    """Open ``name`` with SurfaceTopography; every failure becomes a ValueError naming the file."""
    try:
        with open(name, "rb") as fobj, st.open_topography(fobj) as reader:
            channel = _channel(name, reader, channel_index)
            _check_metadata(name, channel, physical_sizes, unit)
            kwargs = {"channel_index": channel.index}
            if channel.physical_sizes is None:
                kwargs["physical_sizes"] = tuple(physical_sizes)
            if channel.unit is None:
                kwargs["unit"] = unit
            return reader.topography(**kwargs)
    except ValueError as err:
        if str(err).startswith(name):
            raise
        raise ValueError(f"{name}: cannot read topography ({_reason(err)})") from None
    except Exception as err:  # SurfaceTopography raises many exception types
        raise ValueError(f"{name}: not a readable topography file ({_reason(err)})") from None


def _channel(name, reader, channel_index):
    """The requested data channel of an open reader."""
    if channel_index is None:
        return reader.default_channel
    if not 0 <= channel_index < len(reader.channels):
        raise ValueError(f"{name}: no channel {channel_index}; the file has {len(reader.channels)} channel(s): "
                         + ", ".join(repr(c.name) for c in reader.channels))
    return reader.channels[channel_index]


def _reason(err) -> str:
    """One line describing a SurfaceTopography read error."""
    if type(err).__name__ == "CannotDetectFileFormat":
        return "no SurfaceTopography reader recognises the format"
    lines = [line.strip() for line in str(err).splitlines() if line.strip()]
    return f"{type(err).__name__}: {lines[0]}" if lines else type(err).__name__


def _check_metadata(name, channel, physical_sizes, unit):
    """Reject empty channels and missing physical sizes/units before reading the heights."""
    if channel.nb_grid_pts is None or min(channel.nb_grid_pts) < 3:
        raise ValueError(f"{name}: contains no height data (grid {channel.nb_grid_pts})")
    if channel.physical_sizes is None and physical_sizes is None:
        raise ValueError(f"{name}: the file does not store the scan size; pass "
                         f"physical_sizes=(Lx, Ly) for a map or (L,) for a line scan, in `unit`")
    if physical_sizes is not None and not _valid_sizes(physical_sizes, channel.dim):
        raise ValueError(f"{name}: physical_sizes must be {channel.dim} positive number(s) for this "
                         f"{'map' if channel.dim == 2 else 'line scan'}, got {physical_sizes!r}")
    if channel.unit is None and unit is None:
        raise ValueError(f"{name}: the file does not store the length unit; pass unit='m', 'um' or 'nm'")
    if channel.physical_sizes is not None and physical_sizes is not None:
        raise ValueError(f"{name}: the file already stores the scan size {tuple(channel.physical_sizes)}; "
                         f"do not pass physical_sizes")
    if channel.unit is not None and unit is not None:
        raise ValueError(f"{name}: the file already stores the unit {channel.unit!r}; do not pass unit")


def _valid_sizes(physical_sizes, dim) -> bool:
    try:
        sizes = np.asarray(physical_sizes, dtype=float)
    except (TypeError, ValueError):
        return False
    return sizes.shape == (dim,) and bool(np.all(np.isfinite(sizes) & (sizes > 0)))


def _finish(topo, name, fill_undefined):
    """Check the heights, fill undefined data if asked, convert to metres."""
    if not topo.is_uniform:
        raise ValueError(f"{name}: nonuniformly sampled line scan; resample it with "
                         f"topography.to_uniform(...) and pass the topography instead of the file")
    if topo.has_undefined_data:
        n_bad = int(np.ma.count_masked(topo.heights()))
        if not fill_undefined:
            raise ValueError(f"{name}: {n_bad} of {topo.heights().size} heights are undefined (NaN); "
                             f"pass fill_undefined=True to fill them by harmonic interpolation")
        topo = topo.interpolate_undefined_data()
    heights = np.ma.getdata(topo.heights())
    if not np.all(np.isfinite(heights)):
        raise ValueError(f"{name}: heights contain infinite or NaN values")
    try:
        metres = topo.to_unit("m")
        metres.heights()  # the conversion is lazy: force it so a bad unit fails here
    except Exception:
        raise ValueError(f"{name}: unit {topo.unit!r} is not a length unit (m, mm, um, nm, ...)") from None
    return metres


# --------------------------------------------------------------------------- preparation
def _prepare(topography):
    """Validate a SurfaceTopography object; return it in metres with the mean plane removed."""
    if not hasattr(topography, "heights") or not hasattr(topography, "dim"):
        raise TypeError(f"expected a SurfaceTopography topography or line scan, got {type(topography).__name__}")
    if not topography.is_uniform:
        raise ValueError("nonuniform line scan: resample it with topography.to_uniform(...) first")
    if topography.physical_sizes is None:
        raise ValueError("the topography has no physical size; read it with physical_sizes=...")
    if topography.has_undefined_data:
        raise ValueError("the topography has undefined data; fill it (interpolate_undefined_data) first")
    if min(topography.nb_grid_pts) < 5:
        raise ValueError(f"too few points for summit statistics: {topography.nb_grid_pts}")
    if topography.unit not in (None, "m"):
        topography = topography.to_unit("m")
    # A periodic surface has no trend; removing a tilt would break its periodicity.
    return topography.detrend("center" if topography.is_periodic else "height")


def _moments(topo):
    """Profile spectral moments (m0, m2, m4) and the x/y slope anisotropy; see module docstring."""
    if topo.dim == 1:
        return float(topo.Rq()) ** 2, float(topo.Rdq()) ** 2, float(topo.Rddq()) ** 2, None
    m0 = float(topo.Sq()) ** 2
    m2 = float(topo.rms_gradient()) ** 2 / 2
    m4 = 1.5 * float(topo.rms_curvature_from_area()) ** 2
    return m0, m2, m4, _anisotropy(topo)


def _anisotropy(topo):
    """Larger over smaller mean square slope along x and y (upwind differences); None if flat."""
    h = np.asarray(np.ma.getdata(topo.heights()), dtype=float)
    dx, dy = topo.pixel_size
    m2x = np.mean(np.diff(h, axis=0) ** 2) / dx**2
    m2y = np.mean(np.diff(h, axis=1) ** 2) / dy**2
    return float(max(m2x, m2y) / min(m2x, m2y)) if min(m2x, m2y) > 0 else None


def _sigma_factor(alpha_n, constant):
    """:math:`(1 - c/\\alpha_N)^{1/2}`, clipped at zero."""
    return math.sqrt(max(1.0 - constant / alpha_n, 0.0))


# --------------------------------------------------------------------------- spectral
def spectral_summits(topography) -> SummitParameters:
    r"""GW summit parameters from spectral moments (Nayak 1971; McCool 1986).

    The mean plane (line) is removed first.  For a map,
    :math:`m_0 = S_q^2`, :math:`m_2 = \mathrm{rms\_gradient}^2/2`,
    :math:`m_4 = \tfrac32\,\mathrm{rms\_curvature\_from\_area}^2`
    (:math:`= \tfrac38\langle(\nabla^2 h)^2\rangle`); for a line scan
    :math:`m_0 = R_q^2`, :math:`m_2 = R_{\Delta q}^2`, :math:`m_4 = R_{\Delta\Delta q}^2`.
    Then, with :math:`\alpha_N = m_0 m_4/m_2^2`,

    .. math::

        \eta = \frac{m_4}{6\pi\sqrt3\,m_2},\quad
        R = 0.375\sqrt{\pi/m_4},\quad
        \sigma_s = \sqrt{1 - 0.8968/\alpha_N}\,\sqrt{m_0},\quad
        \bar z_s = 4\sqrt{m_0/(\pi\alpha_N)} .

    Parameters
    ----------
    topography : SurfaceTopography.Topography or SurfaceTopography.UniformLineScan
        Uniform grid, heights and sizes in ``topography.unit`` (taken as metres if None).

    Returns
    -------
    SummitParameters
        ``method='spectral'``, ``n_summits=None``; SI units.

    Notes
    -----
    Valid for an isotropic Gaussian surface.  A line scan is taken to be one profile
    of such a surface.  The relations for :math:`\sigma_s` and :math:`\bar z_s` lose
    accuracy for small :math:`\alpha_N` (below about 5).

    References
    ----------
    Nayak (1971), J. Lubr. Technol. 93, 398-407.
    McCool (1986), Wear 107, 37-60.
    Greenwood & Williamson (1966), Proc. R. Soc. A 295, 300-319.
    """
    topo = _prepare(topography)
    m0, m2, m4, anisotropy = _moments(topo)
    if m2 <= 0 or m4 <= 0:
        raise ValueError("the surface is flat (zero slope or curvature): no summits")
    alpha_n = m0 * m4 / m2**2
    return SummitParameters(
        sigma_s=_sigma_factor(alpha_n, NAYAK_SIGMA_S) * math.sqrt(m0),
        radius=0.375 * math.sqrt(math.pi / m4),
        density=m4 / (6 * math.pi * math.sqrt(3) * m2),
        method="spectral", sigma=math.sqrt(m0),
        mean_summit_height=4 * math.sqrt(m0 / (math.pi * alpha_n)),
        m0=m0, m2=m2, m4=m4, alpha_n=alpha_n, anisotropy=anisotropy,
        source="map" if topo.dim == 2 else "line scan")


# --------------------------------------------------------------------------- detection
def _local_maxima_2d(h):
    """Interior 8-neighbour maxima of ``h``: boolean mask of shape ``(nx-2, ny-2)``.

    A point must exceed its 4 'forward' neighbours (+x, +y, and the two diagonals
    ahead in x) and be >= its 4 'backward' ones, so a plateau of equal heights counts
    once.  The border rows and columns are never summits.
    """
    c = h[1:-1, 1:-1]
    nx, ny = h.shape
    peak = np.ones(c.shape, dtype=bool)
    for di, dj in ((1, -1), (1, 0), (1, 1), (0, 1)):
        peak &= c > h[1 + di:nx - 1 + di, 1 + dj:ny - 1 + dj]
        peak &= c >= h[1 - di:nx - 1 - di, 1 - dj:ny - 1 - dj]
    return peak


def _local_maxima_1d(h):
    """Interior 3-point peaks (``h[i-1] <= h[i] > h[i+1]``): mask of length ``n-2``."""
    c = h[1:-1]
    return (c > h[2:]) & (c >= h[:-2])


def _summit_curvatures_2d(h, peak, dx, dy):
    """Mean curvature :math:`-(h_{xx}+h_{yy})/2` at the peaks, central differences."""
    c = h[1:-1, 1:-1]
    hxx = (h[2:, 1:-1] - 2 * c + h[:-2, 1:-1]) / dx**2
    hyy = (h[1:-1, 2:] - 2 * c + h[1:-1, :-2]) / dy**2
    return -(hxx + hyy)[peak] / 2


def detected_summits(topography) -> SummitParameters:
    r"""GW summit parameters from the summits found on the grid.

    After removing the mean plane (line):

    * **map** -- summits are interior 8-neighbour local maxima (border rows and columns
      excluded; plateaus count once).  The summit curvature is the mean of the two
      principal curvatures, :math:`\kappa = -(h_{xx}+h_{yy})/2`, from central
      differences; :math:`R = 1/\bar\kappa`, :math:`\sigma_s` is the standard deviation
      of the summit heights and :math:`\eta` the number of summits divided by the
      interior area :math:`(n_x-2)(n_y-2)\Delta x\Delta y`.
    * **line scan** -- profile peaks are interior 3-point maxima, with peak density
      :math:`D_p` (per length), mean peak curvature :math:`\bar\kappa_p = -\overline{h''}`
      and peak-height deviation :math:`\sigma_p`.  They are converted to summit values
      of the isotropic Gaussian surface the profile is taken from, using its profile
      moments (Nayak 1971; McCool 1986; Rice 1944):
      :math:`D_p = \sqrt{m_4/m_2}/2\pi` and :math:`\eta = m_4/(6\pi\sqrt3 m_2)` give
      :math:`\eta = \tfrac{2\pi}{3\sqrt3} D_p^2`;
      :math:`\bar\kappa_p = \sqrt{\pi m_4/2}` and :math:`\bar\kappa_s = \tfrac83\sqrt{m_4/\pi}`
      give :math:`R = 3\pi/(8\sqrt2\,\bar\kappa_p)`;
      :math:`\sigma_p^2 = m_0(1 - (\pi/2-1)/\alpha_N)` and
      :math:`\sigma_s^2 = m_0(1 - 0.8968/\alpha_N)` give
      :math:`\sigma_s = \sigma_p\,[(1-0.8968/\alpha_N)/(1-(\pi/2-1)/\alpha_N)]^{1/2}`,
      with :math:`\alpha_N` from the profile's moments.

    :math:`R` is the reciprocal of the *mean curvature*, not the mean of the radii:
    this is the quantity of Nayak's and McCool's theory (so both methods estimate the
    same thing), and it is robust, whereas nearly flat summits give arbitrarily large
    radii that dominate a mean of radii.

    Parameters
    ----------
    topography : SurfaceTopography.Topography or SurfaceTopography.UniformLineScan
        Uniform grid, heights and sizes in ``topography.unit`` (taken as metres if None).

    Returns
    -------
    SummitParameters
        ``method='detected'``; ``n_summits`` counts summits (map) or profile peaks.

    Raises
    ------
    ValueError
        If no summit with positive curvature is found.

    References
    ----------
    Greenwood & Williamson (1966), Proc. R. Soc. A 295, 300-319.
    Nayak (1971), J. Lubr. Technol. 93, 398-407.
    McCool (1986), Wear 107, 37-60.
    Rice, S. O. (1944), Mathematical analysis of random noise, Bell Syst. Tech. J. 23, 282-332.
    """
    topo = _prepare(topography)
    h = np.asarray(np.ma.getdata(topo.heights()), dtype=float)
    if topo.dim == 2:
        return _detected_map(h, topo.pixel_size)
    return _detected_profile(topo, h)


def _check_summits(kappa):
    if kappa.size == 0:
        raise ValueError("no summits found on the surface")
    mean = float(np.mean(kappa))
    if not mean > 0:
        raise ValueError("the detected summits have no positive mean curvature")
    return mean


def _detected_map(h, pixel_size):
    dx, dy = (float(p) for p in pixel_size)
    peak = _local_maxima_2d(h)
    kappa = _summit_curvatures_2d(h, peak, dx, dy)
    mean_kappa = _check_summits(kappa)
    z = h[1:-1, 1:-1][peak]
    area = (h.shape[0] - 2) * (h.shape[1] - 2) * dx * dy
    return SummitParameters(
        sigma_s=float(np.std(z)), radius=1.0 / mean_kappa, density=z.size / area,
        method="detected", sigma=float(np.std(h)), mean_summit_height=float(np.mean(z)),
        n_summits=int(z.size), source="map")


def _detected_profile(topo, h):
    dx = float(topo.pixel_size[0])
    peak = _local_maxima_1d(h)
    kappa = -(h[2:] - 2 * h[1:-1] + h[:-2])[peak] / dx**2
    mean_kappa = _check_summits(kappa)
    z = h[1:-1][peak]
    peak_density = z.size / ((h.size - 2) * dx)
    m0, m2, m4, _ = _moments(topo)
    alpha_n = m0 * m4 / m2**2
    ratio = _sigma_factor(alpha_n, NAYAK_SIGMA_S) / _sigma_factor(alpha_n, RICE_SIGMA_P)
    return SummitParameters(
        sigma_s=float(np.std(z)) * ratio, radius=3 * math.pi / (8 * math.sqrt(2) * mean_kappa),
        density=2 * math.pi / (3 * math.sqrt(3)) * peak_density**2,
        method="detected", sigma=float(np.std(h)), mean_summit_height=float(np.mean(z)),
        m0=m0, m2=m2, m4=m4, alpha_n=alpha_n, n_summits=int(z.size), source="line scan")


# --------------------------------------------------------------------------- analysis
def analyse_surface(path_or_topography, *, material=None, b=None, **read_kwargs) -> SurfaceAnalysis:
    """Summit parameters of a measured surface by both methods, with diagnostics.

    Parameters
    ----------
    path_or_topography : str, os.PathLike or SurfaceTopography topography
        A file for :func:`read_topography`, or a topography/line scan already read.
    material : object, optional
        Anything with a Burgers-vector attribute ``b`` [m]; used if ``b`` is not given.
    b : float, optional
        Burgers vector [m]; if given (or via ``material``), the dimensionless groups
        :math:`\\alpha = (\\sigma_s/R)^{1/2}` and :math:`\\beta = (R\\sigma_s)^{1/2}/b`
        (Eq 7 of the paper) are reported for each method.
    **read_kwargs
        ``physical_sizes``, ``unit``, ``channel_index``, ``fill_undefined`` for
        :func:`read_topography`.

    Returns
    -------
    SurfaceAnalysis
        ``warnings`` lists, as strings: the two methods disagree (by more than a factor
        1.5 in :math:`R` or :math:`\\eta`, or 30 % in :math:`\\sigma_s`); the bandwidth
        parameter :math:`\\alpha_N < 5` (Nayak's relations are unreliable); the
        resolution is too coarse (summits fewer than 5 pixels apart, or :math:`R`
        under 3 pixels); fewer than 30 summits; an anisotropic map (mean square slopes
        along x and y differ by more than a factor 1.5); and, for a line scan, that
        summit values are inferred from one profile assuming isotropy.
    """
    b_value = _burgers(material, b)
    source = None
    topo = path_or_topography
    if isinstance(path_or_topography, (str, os.PathLike)):
        source = os.fspath(path_or_topography)
        topo = read_topography(path_or_topography, **read_kwargs)
    elif read_kwargs:
        raise TypeError(f"{sorted(read_kwargs)} only apply when reading a file")
    topo = topo if topo.unit in (None, "m") else topo.to_unit("m")
    spectral, detected = spectral_summits(topo), detected_summits(topo)
    pixel = tuple(float(p) for p in topo.pixel_size)
    return SurfaceAnalysis(
        spectral=spectral, detected=detected, dim=topo.dim,
        nb_grid_pts=tuple(int(n) for n in topo.nb_grid_pts),
        physical_sizes=tuple(float(s) for s in topo.physical_sizes), pixel_size=pixel,
        n_points=int(np.prod(topo.nb_grid_pts)),
        warnings=_diagnose(spectral, detected, pixel, topo.dim) + _no_burgers(material, b_value),
        b=b_value, groups=None if b_value is None else _groups(spectral, detected, b_value),
        source=source)


def _burgers(material, b):
    """Burgers vector [m] from ``b`` or ``material.b``; None if neither is given."""
    if b is None and material is not None:
        if not hasattr(material, "b"):
            raise TypeError(f"material {material!r} has no Burgers vector attribute 'b'")
        b = material.b
    if b is None:
        return None
    b = float(b)
    if not (b > 0 and math.isfinite(b)):
        raise ValueError(f"Burgers vector b must be > 0 and finite, got {b!r}")
    return b


def _no_burgers(material, b) -> list[str]:
    if material is not None and b is None:
        return [f"material {getattr(material, 'name', material)!r} has no Burgers vector b: alpha, beta not computed"]
    return []


def _groups(spectral, detected, b):
    """alpha = sqrt(sigma_s/R), beta = sqrt(R sigma_s)/b (Eq 7) for each method."""
    from .groups import regime_beta, roughness_alpha

    return {p.method: {"alpha": float(roughness_alpha(p.sigma_s, p.radius)),
                       "beta": float(regime_beta(p.sigma_s, p.radius, b))}
            for p in (spectral, detected) if p.sigma_s > 0}


def _diagnose(spectral, detected, pixel, dim) -> list[str]:
    """Human-readable reasons to distrust the results."""
    out = _disagreement(spectral, detected)
    if spectral.alpha_n < MIN_ALPHA_N:
        out.append(f"bandwidth parameter alpha_N = {spectral.alpha_n:.3g} < {MIN_ALPHA_N:g}: "
                   f"Nayak's summit relations (sigma_s, R) are unreliable for narrow-band surfaces")
    out += _resolution(spectral, detected, min(pixel))
    if spectral.anisotropy is not None and spectral.anisotropy > MAX_ANISOTROPY:
        out.append(f"anisotropic surface: mean square slopes along x and y differ by a factor "
                   f"{spectral.anisotropy:.3g}; the isotropic relations do not apply")
    if dim == 1:
        out.append("line scan: summit parameters are inferred from one profile assuming an "
                   "isotropic Gaussian surface; measure a map if possible")
    return out


def _disagreement(spectral, detected) -> list[str]:
    out = []
    for name, key in (("R", "radius"), ("eta", "density")):
        a, d = getattr(spectral, key), getattr(detected, key)
        if max(a, d) > RATIO_TOLERANCE * min(a, d):
            out.append(f"spectral and detected {name} differ by a factor {max(a, d) / min(a, d):.3g} "
                       f"(spectral {a:.4g}, detected {d:.4g})")
    a, d = spectral.sigma_s, detected.sigma_s
    if abs(a - d) > SIGMA_TOLERANCE * max(a, d):
        out.append(f"spectral and detected sigma_s differ by {abs(a - d) / max(a, d):.0%} "
                   f"(spectral {a:.4g} m, detected {d:.4g} m)")
    return out


def _resolution(spectral, detected, pixel) -> list[str]:
    out = []
    for p in (spectral, detected):
        if p.spacing < MIN_SPACING_PIXELS * pixel:
            out.append(f"{p.method}: summits are only {p.spacing / pixel:.2g} pixels apart; the scan "
                       f"resolution is too coarse for summit curvatures")
        if p.radius < MIN_RADIUS_PIXELS * pixel:
            out.append(f"{p.method}: mean summit radius is only {p.radius / pixel:.2g} pixels")
    if detected.n_summits < MIN_SUMMITS:
        out.append(f"only {detected.n_summits} summits (peaks) detected (< {MIN_SUMMITS}): "
                   f"too few for statistics; scan a larger area")
    return out
