r"""Both summit estimators on one measured surface, compared, with reasons to distrust them.

:func:`analyse_surface` reads a file (or takes a surface already read), runs
:func:`~asperity.topography.spectral.spectral_summits` and
:func:`~asperity.topography.detected.detected_summits`, and lists what looks unreliable
(the thresholds below).  It also reports the shape of the detected summit heights
(skewness, kurtosis) and the height distributions of :mod:`asperity.heights` fitted to
them, ranked by AIC (:func:`asperity.heights.fit_heights`); the best one's spelling (e.g.
``pearson3:skew=-0.41``) or the summits written to a file
(:meth:`SurfaceAnalysis.write_summits`, then ``empirical:FILE`` or ``best:FILE``) hand the
shape to the model.  With a Burgers vector it adds the paper's groups (Eq 7),

.. math::
    \alpha = (\sigma_s/R)^{1/2},\qquad \beta = (R\sigma_s)^{1/2}/b .

References
----------
.. [1] Adams, Müftü, Mohd Azhar, "A nano-scale multi-asperity contact and friction model", Eq (7).
.. [2] Nayak, P. R. (1971). J. Lubr. Technol. (ASME) 93, 398-407.
.. [3] McCool, J. I. (1986). Wear 107, 37-60.
"""

from __future__ import annotations

import math
import os
import warnings
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .._validation import check_optional_positive
from .._warnings import AsperityWarning
from ..groups import regime_beta, roughness_alpha
from ..heights import MIN_SAMPLES, HeightsFit, fit_heights, write_samples
from ..materials import as_material
from ..surface import Surface
from .detected import detected_summit_heights, detected_summits
from .read import read_topography
from .spectral import spectral_summits
from .summits import SummitParameters, plain

__all__ = [
    "SurfaceAnalysis",
    "analyse_surface",
    "RATIO_TOLERANCE",
    "SIGMA_TOLERANCE",
    "MIN_ALPHA_N",
    "MIN_SPACING_PIXELS",
    "MIN_RADIUS_PIXELS",
    "MIN_SUMMITS",
    "MAX_ANISOTROPY",
    "MAX_RMS_SLOPE",
    "METHODS",
]

#: The two summit estimators, by name: spectral moments (Nayak/McCool) and summit detection.
METHODS = ("spectral", "detected")

#: Largest ratio of the two methods' R or eta before a warning.
RATIO_TOLERANCE = 1.5
#: Largest relative difference of the two methods' sigma_s before a warning.
SIGMA_TOLERANCE = 0.30
#: Smallest bandwidth parameter alpha_N for which Nayak's sigma_s and R are trusted.
MIN_ALPHA_N = 5.0
#: Smallest summit spacing, in pixels, for summit curvatures to be resolved.
MIN_SPACING_PIXELS = 5.0
#: Smallest mean summit radius, in pixels.
MIN_RADIUS_PIXELS = 3.0
#: Fewest detected summits (peaks) for statistics.
MIN_SUMMITS = 30
#: Largest ratio of the mean square slopes along x and y of an "isotropic" map.
MAX_ANISOTROPY = 1.5
#: Largest rms slope: the contact theories assume slopes well below 1.
MAX_RMS_SLOPE = 1.0


@dataclass(frozen=True)
class SurfaceAnalysis:
    """Summit parameters of one measured surface by both methods.

    Attributes
    ----------
    spectral, detected : SummitParameters
        Results of :func:`~asperity.topography.spectral_summits` and
        :func:`~asperity.topography.detected_summits`.
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
    heights : HeightsFit or None
        Skewness and kurtosis of the detected summit heights and the fitted height
        distributions, ranked (None with fewer than 20 summits).
    summit_heights : ndarray or None
        The detected summit (line scan: peak) heights above the mean plane [m].
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
    heights: HeightsFit | None = None
    summit_heights: np.ndarray | None = field(default=None, repr=False, compare=False)

    def surface(self, area, method: str = "spectral") -> Surface:
        """The GW :class:`~asperity.surface.Surface` of one method's summits over a nominal ``area``.

        Parameters
        ----------
        area : float, pint.Quantity or str
            Nominal contact area (m^2), > 0.
        method : {'spectral', 'detected'}
            Which estimate: spectral moments (Nayak/McCool, default) or summit detection.

        Returns
        -------
        Surface
            ``sigma_s``, ``R``, ``eta`` of that method; ``source`` names the file and method.

        Raises
        ------
        ValueError
            For an unknown ``method`` or an ``area`` not > 0.
        """
        if not isinstance(method, str) or method not in METHODS:
            raise ValueError(f"method must be one of {', '.join(map(repr, METHODS))}, got {method!r}")
        summits = getattr(self, method)
        label = f"{method} summits{' (Nayak/McCool)' if method == 'spectral' else ''}"
        return summits.surface(area, source=f"{self.source}, {label}" if self.source else label)

    def to_dict(self) -> dict[str, Any]:
        """Nested plain dictionary for strict JSON output (NaN and infinity as None)."""
        out = {k: plain(getattr(self, k)) for k in
               ("dim", "nb_grid_pts", "physical_sizes", "pixel_size", "n_points", "b", "groups", "source")}
        out["spectral"] = self.spectral.to_dict()
        out["detected"] = self.detected.to_dict()
        out["heights"] = None if self.heights is None else self.heights.to_dict()
        out["warnings"] = list(self.warnings)
        return out

    def write_summits(self, path) -> None:
        """Write the detected summit heights [m], one per line under the header ``z_m``, atomically.

        ``--heights empirical:FILE`` or ``best:FILE`` (:func:`asperity.heights.parse_heights`)
        read them back.

        Raises
        ------
        ValueError
            If fewer than 20 summits were detected.
        """
        if self.summit_heights is None or self.summit_heights.size < MIN_SAMPLES:
            raise ValueError(f"only {0 if self.summit_heights is None else self.summit_heights.size} summits "
                             f"detected: at least {MIN_SAMPLES} are needed for a height distribution")
        write_samples(path, self.summit_heights, header="z_m")

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
            row = f"{p.method:<10}{p.sigma_s * 1e9:>14.4g}{p.R * 1e6:>12.4g}{p.eta * 1e-12:>15.4g}{n:>9}"
            if self.groups is not None:
                g = self.groups.get(p.method)  # absent when sigma_s = 0
                row += f"{g['alpha']:>10.4g}{g['beta']:>10.4g}" if g else f"{'-':>10}{'-':>10}"
            lines.append(row)
        s = self.spectral
        lines.append(f"rms height {s.sigma * 1e9:.4g} nm, alpha_N = {s.alpha_n:.3g}")
        if self.heights is not None:
            h = self.heights
            what = "peak" if self.dim == 1 else "summit"
            lines.append(f"{what} heights ({h.n}): skewness {h.skewness:.3g}, kurtosis {h.kurtosis:.3g} "
                         "(Gaussian: 0, 3); distributions ranked by AIC:")
            lines += ["  " + line for line in h.table().splitlines()]
            lines.append(f"model: --heights {h.best.spec} (or --summits FILE, then --heights best:FILE or "
                         "empirical:FILE)")
        lines += [f"warning: {w}" for w in self.warnings]
        return "\n".join(lines)


def analyse_surface(path_or_topography, *, material=None, b=None, heights: bool = True,
                    **read_kwargs) -> SurfaceAnalysis:
    """Summit parameters of a measured surface by both methods, with diagnostics.

    Parameters
    ----------
    path_or_topography : str, os.PathLike or SurfaceTopography topography
        A file for :func:`~asperity.topography.read_topography`, or a topography/line
        scan already read.
    material : Material, str or object, optional
        A :class:`~asperity.materials.Material`, a material name from the table, or
        anything with a Burgers-vector attribute ``b`` [m]; used if ``b`` is not given.
    b : float, pint.Quantity or str, optional
        Burgers vector [m], > 0; if given (or via ``material``), the dimensionless groups
        :math:`\\alpha = (\\sigma_s/R)^{1/2}` and :math:`\\beta = (R\\sigma_s)^{1/2}/b`
        (Eq 7 of the paper) are reported for each method.
    heights : bool
        Fit the height distributions to the detected summit heights (default True; about
        0.1-1 s).
    **read_kwargs
        ``physical_sizes`` (metres), ``unit`` (of the stored heights), ``channel_index``,
        ``fill_undefined`` for :func:`~asperity.topography.read_topography`; only with a file.

    Returns
    -------
    SurfaceAnalysis
        ``warnings`` lists, as strings: the reader's notes on a file (e.g. a ``.npy``
        map's pixels more than twice as long one way: they are listed here, not issued as
        Python warnings); the two methods disagree (by more than a factor
        1.5 in :math:`R` or :math:`\\eta`, or 30 % in :math:`\\sigma_s`); the bandwidth
        parameter :math:`\\alpha_N < 5` (Nayak's relations are unreliable); the
        resolution is too coarse (summits fewer than 5 pixels apart, or :math:`R`
        under 3 pixels); fewer than 30 summits; an anisotropic map (mean square slopes
        along x and y differ by more than a factor 1.5); an rms slope above 1 (a wrong
        height unit or scan size, or a surface beyond the theories' small slopes); and, for a line scan, that
        summit values are inferred from one profile assuming isotropy (and the fitted
        heights are those of profile peaks); fewer than 20 summits for a height fit.
        ``heights`` holds the summit-height skewness, kurtosis and the ranked fits.

    Raises
    ------
    TypeError
        If ``path_or_topography`` is neither a path nor a SurfaceTopography object, if
        ``material`` has no Burgers vector attribute, or if ``read_kwargs`` are given
        with a topography object.
    ValueError
        For a file :func:`~asperity.topography.read_topography` cannot read, or a
        degenerate surface (flat, tilted plane, constant, too few points, no summits);
        with a file, the message starts with its name.

    Examples
    --------
    >>> result = analyse_surface("scan.txt", physical_sizes=("5um", "5um"), unit="nm")  # doctest: +SKIP
    >>> result.spectral.surface(1e-6)  # doctest: +SKIP
    """
    b_value = _burgers(material, b)
    source, read_notes = None, []
    if isinstance(path_or_topography, str | os.PathLike):
        topo, read_notes = _read_with_notes(path_or_topography, read_kwargs)
        source = os.fsdecode(os.fspath(path_or_topography))
    elif not all(hasattr(path_or_topography, a) for a in ("heights", "dim", "nb_grid_pts", "detrend")):
        raise TypeError(f"path_or_topography must be a file path (str or os.PathLike) or a SurfaceTopography "
                        f"topography or line scan, got {type(path_or_topography).__name__}")
    elif read_kwargs:
        raise TypeError(f"{sorted(read_kwargs)} only apply when reading a file")
    else:
        topo = path_or_topography
    if not isinstance(heights, bool):
        raise TypeError(f"heights must be True or False, got {heights!r}")
    try:
        topo = topo if topo.unit in (None, "m") else topo.to_unit("m")
        spectral, detected = spectral_summits(topo), detected_summits(topo)
        z = detected_summit_heights(topo)
    except ValueError as err:
        if source is None:
            raise
        raise ValueError(f"{source}: {err}") from None
    fit, notes = None, []
    if heights and z.size >= MIN_SAMPLES and np.std(z) > 1e-12 * np.max(np.abs(z)):
        fit = fit_heights(z)
        if topo.dim == 1:
            notes.append("line scan: the height distributions are fitted to profile peaks, which are lower and "
                         "less skewed than the surface's summits")
    elif heights:
        notes.append(f"{z.size} summits of {'equal heights' if z.size >= MIN_SAMPLES else 'too few'}: no height "
                     f"distribution fitted (at least {MIN_SAMPLES} of different heights are needed)")
    pixel = tuple(float(p) for p in topo.pixel_size)
    return SurfaceAnalysis(
        spectral=spectral, detected=detected, dim=topo.dim,
        nb_grid_pts=tuple(int(n) for n in topo.nb_grid_pts),
        physical_sizes=tuple(float(s) for s in topo.physical_sizes), pixel_size=pixel,
        n_points=int(np.prod(topo.nb_grid_pts)),
        warnings=read_notes + _diagnose(spectral, detected, pixel, topo.dim) + _no_burgers(material, b_value) + notes,
        b=b_value, groups=None if b_value is None else _groups(spectral, detected, b_value),
        source=source, heights=fit, summit_heights=z)


def _read_with_notes(path, read_kwargs: dict):
    """The topography and the reader's notes (its :class:`~asperity.AsperityWarning` messages,
    e.g. long .npy pixels), which belong in the analysis's ``warnings`` (so that ``asperity
    surface --format json`` holds them) instead of being issued; other warnings pass on."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        topo = read_topography(path, **read_kwargs)
    notes = []
    for w in caught:
        if issubclass(w.category, AsperityWarning):
            notes.append(" ".join(str(w.message).split()))
        else:
            warnings.warn_explicit(w.message, w.category, w.filename, w.lineno, source=w.source)
    return topo, list(dict.fromkeys(notes))


def _burgers(material, b):
    """Burgers vector [m] from ``b`` or ``material.b``; None if neither is given."""
    if b is None and material is not None:
        if isinstance(material, str):
            material = as_material(material, "material")
        if not hasattr(material, "b"):
            raise TypeError(f"material {material!r} has no Burgers vector attribute 'b'")
        b = material.b
    return check_optional_positive(b, "b (Burgers vector)", "m")


def _no_burgers(material, b) -> list[str]:
    if material is not None and b is None:
        name = material if isinstance(material, str) else getattr(material, "name", material)
        return [f"material {name!r} has no Burgers vector b: alpha, beta not computed"]
    return []


def _groups(spectral, detected, b):
    """alpha = sqrt(sigma_s/R), beta = sqrt(R sigma_s)/b (Eq 7) for each method."""
    return {p.method: {"alpha": float(roughness_alpha(p.sigma_s, p.R)),
                       "beta": float(regime_beta(p.sigma_s, p.R, b))}
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
    slope = math.sqrt(dim * spectral.m2) if spectral.m2 is not None else math.nan  # isotropic: m2 per direction
    if slope > MAX_RMS_SLOPE:
        out.append(f"rms slope {slope:.3g} (rms height {spectral.sigma:.3g} m): the contact theories assume slopes "
                   "well below 1; check the height unit (unit=, --unit) and the scan size (physical_sizes=, --size)")
    if dim == 1:
        out.append("line scan: summit parameters are inferred from one profile assuming an "
                   "isotropic Gaussian surface; measure a map if possible")
    return out


def _disagreement(spectral, detected) -> list[str]:
    out = []
    for key in ("R", "eta"):
        a, d = getattr(spectral, key), getattr(detected, key)
        if max(a, d) > RATIO_TOLERANCE * min(a, d):
            out.append(f"spectral and detected {key} differ by a factor {max(a, d) / min(a, d):.3g} "
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
        if p.R < MIN_RADIUS_PIXELS * pixel:
            out.append(f"{p.method}: mean summit radius is only {p.R / pixel:.2g} pixels")
    if detected.n_summits < MIN_SUMMITS:
        out.append(f"only {detected.n_summits} summits (peaks) detected (< {MIN_SUMMITS}): "
                   f"too few for statistics; scan a larger area")
    return out
