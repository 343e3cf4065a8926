r"""Empirical summit heights: a Gaussian kernel estimate of measured summits, reduced to a fixed grid.

From :math:`N` measured summit heights, standardised by their mean and (population)
standard deviation, the density is a Gaussian kernel estimate with Silverman's bandwidth

.. math::
    h_0 = 0.9\,\min(1, \mathrm{IQR}/1.34)\,N^{-1/5}\quad(\text{at least } 0.2),

the kernel centres shrunk by :math:`a = (1-h_0^2)^{1/2}` so that the estimate keeps unit
variance (Jones 1991), then *linearly binned* onto :math:`K` equally spaced centres
spanning the lowest to the highest summit (Wand 1994): each summit splits its weight
between the two nearest centres, which keeps the mean exactly and the estimate a
Gaussian mixture of :math:`K` components of common width, whatever :math:`N`.  The centres
lie at most :math:`1.25h` apart; binning adds the variance :math:`\Delta^2/6` (:math:`\Delta`
the spacing), taken out of the kernel, whose width becomes :math:`(h^2 - \Delta^2/6)^{1/2}`.  The
mixture is then shifted and scaled to zero mean and unit variance exactly.  Its
integrals are those of a mixture (:mod:`asperity.heights.mixture`).

*The tail.*  Nothing is extrapolated beyond the data: above the highest measured summit
:math:`z_{max}` the density is the tail of the kernels on the top centres, a Gaussian of
width :math:`h` (about 0.2-0.4 sigma_s), so the share of summits above
:math:`z_{max} + 3h` is about 1/1000 of the share within :math:`h` of the top.  Separations
beyond :math:`z_{max}` (very light loads) therefore contact only this smoothing tail: the
model's light-load end there is a property of the kernel, not of the surface.
:attr:`Empirical.z_max` gives :math:`z_{max}`; a parametric fit
(:func:`asperity.heights.fit_heights`) extrapolates a tail instead.

References
----------
.. [1] B. W. Silverman, Density Estimation for Statistics and Data Analysis (1986), Eq (3.31).
.. [2] M. C. Jones, Biometrika 78 (1991) 521 (variance-corrected kernel estimate).
.. [3] M. P. Wand, J. Comput. Graph. Statist. 3 (1994) 433 (linear binning).
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass, field
from typing import ClassVar

import numpy as np

from .._validation import as_float_array, check_scalar_range
from .base import check_order
from .mixture import (
    GaussianSum,
    mixture_moment,
    mixture_stats,
)
from .samples import check_samples, read_samples, standardise

__all__ = ["Empirical", "COMPONENTS", "MIN_BANDWIDTH"]

#: Most kernel centres the estimate is binned onto (fewer when centres 1.25 h apart span the summits).
COMPONENTS = 128
#: Smallest kernel width, in sigma_s (narrower kernels resolve sampling noise, not the surface).
MIN_BANDWIDTH = 0.2


@dataclass(frozen=True, repr=False)
class Empirical(GaussianSum):
    r"""A Gaussian mixture of common width built from measured summit heights (module docstring).

    Build it with :meth:`from_samples` or :meth:`from_file`; the constructor takes the
    mixture itself and standardises it.

    Parameters
    ----------
    means : tuple of float
        Kernel centres (any unit).
    weights : tuple of float
        Their weights (>= 0, normalised to sum 1).
    sd : float
        Common kernel width (same unit), > 0.
    samples : int, optional
        Number of summit heights it was built from (information only).
    source : str, optional
        File it was read from; its :attr:`spec` is then ``'empirical:FILE'``.

    Attributes
    ----------
    z_max : float
        Highest kernel centre, the highest measured summit (standardised).

    Examples
    --------
    >>> import numpy as np
    >>> z = np.random.default_rng(0).gamma(4.0, size=500)  # skewness ~1
    >>> e = Empirical.from_samples(z)
    >>> [abs(round(x, 12)) for x in e.stats()[:2]]   # mean and variance
    [0.0, 1.0]
    >>> step = (max(e.means) - min(e.means)) / (e.components - 1)
    >>> bool(step <= 1.46 * e.sd), e.components <= COMPONENTS, e.spec is None   # 1.25 h apart, e.sd >= 0.86 h
    (True, True, True)
    """

    means: tuple = ()
    weights: tuple = ()
    sd: float = 0.3
    samples: int | None = field(default=None, compare=False)
    source: str | None = field(default=None, compare=False)
    name: ClassVar[str] = "empirical"

    def __post_init__(self):
        count = self.samples
        if count is not None and (isinstance(count, bool) or not isinstance(count, int | np.integer) or count < 0):
            raise TypeError(f"samples (the number of measured summits) must be a non-negative integer or None, "
                            f"got {self.samples!r}")
        if self.source is not None and not isinstance(self.source, str):
            raise TypeError(f"source (the file the summits came from) must be a string or None, got {self.source!r}")
        m = as_float_array(self.means, "means").ravel()
        w = as_float_array(self.weights, "weights").ravel()
        if m.size != w.size or m.size < 1:
            raise ValueError(f"means and weights must have the same length >= 1, got {m.size} and {w.size}")
        if np.any(w < 0) or not w.sum() > 0:
            raise ValueError("weights must be >= 0 with a positive sum")
        sd = check_scalar_range(self.sd, "sd", 0.0, 1e100, what="kernel width")
        if not sd > 0:
            raise ValueError(f"sd (kernel width) must be > 0, got {self.sd!r}")
        w = w / w.sum()
        with np.errstate(all="ignore"):
            mean, var, _, _ = mixture_stats(w, m, np.full(m.size, sd))
        scale = math.sqrt(var) if math.isfinite(var) else math.inf
        if not 0.0 < scale < math.inf:
            raise ValueError(f"means and sd give a variance that overflows double precision (sd = {self.sd!r}): "
                             "give heights of physical size")
        m = (m - mean) / scale
        sd = sd / scale
        setattr_ = object.__setattr__
        setattr_(self, "means", tuple(float(x) for x in m))
        setattr_(self, "weights", tuple(float(x) for x in w))
        setattr_(self, "sd", sd)
        live = w > 0
        setattr_(self, "_components", (tuple(w[live]), tuple(m[live]), tuple(np.full(live.sum(), sd))))
        top, bottom = float(m[live].max()), float(m[live].min())
        setattr_(self, "z_max", top)
        setattr_(self, "z_top", top + 10.0 * sd)
        setattr_(self, "z_bottom", bottom - 10.0 * sd)
        setattr_(self, "z_end", top + 35.0 * sd)
        setattr_(self, "resolution", min(1.0, sd))

    @classmethod
    def from_samples(cls, samples, *, components: int = COMPONENTS, source: str | None = None) -> Empirical:
        """The binned kernel estimate of measured summit heights (any unit; module docstring).

        Parameters
        ----------
        samples : array_like
            Summit heights, 1-D, finite, at least 20, not all equal.
        components : int
            Largest number of kernel centres :math:`K`, 2 to 256 (fewer, but at least 8, when
            centres 1.25 bandwidths apart already span the summits).
        source : str, optional
            File name to remember (for :attr:`spec`).

        Returns
        -------
        Empirical

        Raises
        ------
        ValueError
            For bad samples or ``components``.
        """
        z = standardise(check_samples(samples))
        if isinstance(components, bool) or not isinstance(components, int | np.integer) or not 2 <= components <= 256:
            raise ValueError(f"components must be an integer in [2, 256], got {components!r}")
        q75, q25 = np.percentile(z, [75, 25])
        h = max(MIN_BANDWIDTH, 0.9 * min(1.0, (q75 - q25) / 1.34) * z.size ** -0.2)
        c = math.sqrt(1.0 - h * h) * z
        # at most COMPONENTS centres, at most 1.25 h apart, never fewer than 8.  Linear binning adds
        # the variance step^2/6 (on average over the summits' places between two centres): the
        # kernel is narrowed by as much, so the estimate keeps the kernel estimate's spread
        # (within 2 % of the unbinned estimate in the bulk; centres 1.5 h apart without the
        # correction were 3-6 % off there and 25 % near the top, found by a review; closer
        # centres cost time: 3h/4 took the curves past 3x the Gaussian's).  The ripple of the
        # narrowed kernel on the grid, exp(-2 pi^2 h_b^2 / step^2), stays below 1e-4.
        needed = int(math.ceil((c.max() - c.min()) / (1.25 * h))) + 1
        components = min(int(components), max(8, needed))
        grid = np.linspace(c.min(), c.max(), components)
        step = grid[1] - grid[0]
        pos = np.clip((c - grid[0]) / step, 0.0, components - 1.0)
        left = np.minimum(np.floor(pos).astype(int), components - 2)
        frac = pos - left
        weights = np.bincount(left, 1.0 - frac, components) + np.bincount(left + 1, frac, components)
        h = math.sqrt(max(h * h - step * step / 6.0, 0.25 * h * h))
        return cls(tuple(grid), tuple(weights), h, samples=int(z.size),
                   source=None if source is None else os.fsdecode(source))

    @classmethod
    def from_file(cls, path, *, components: int = COMPONENTS) -> Empirical:
        """:meth:`from_samples` of a one-column file of summit heights (:func:`~asperity.heights.read_samples`).

        Parameters
        ----------
        path : str or os.PathLike
            One summit height per line, any unit.
        components : int
            Largest number of kernel centres.

        Returns
        -------
        Empirical

        Raises
        ------
        ValueError
            If the file cannot be read or holds bad or too few heights (message names the file).
        """
        return cls.from_samples(read_samples(path), components=components, source=os.fsdecode(os.fspath(path)))

    def __repr__(self) -> str:
        src = f", source={self.source!r}" if self.source else ""
        n = f"samples={self.samples}, " if self.samples else ""
        return f"Empirical({n}components={self.components}, bandwidth={self.sd:.4g}{src})"

    @property
    def components(self) -> int:
        """Number of kernel centres."""
        return len(self.means)

    @property
    def spec(self) -> str | None:
        """``'empirical:FILE'`` when read from a file, else None (no command-line spelling)."""
        return f"empirical:{self.source}" if self.source else None

    def translates(self):
        """``(weights, centres, width)``: the estimate is a sum of one Gaussian kernel's translates."""
        return self._components[0], self._components[1], self.sd

    def moment(self, d, order):
        r"""GW moment :math:`F_n(\bar d)`: a sum of Gaussian closed forms over the kernels.

        Parameters
        ----------
        d : array_like
            Separation :math:`\bar d`, finite (any shape).
        order : float
            :math:`n > -1`.

        Returns
        -------
        ndarray
            :math:`F_n(\bar d)`, shape of ``d``.
        """
        d = as_float_array(d, "d", allow_empty=True)
        n = check_order(order)
        return self._checked_moment(lambda x: mixture_moment(x, n, *self._components), d, n)
