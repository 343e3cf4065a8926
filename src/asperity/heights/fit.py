r"""Fit the height distributions to measured summit heights and rank them.

The summit heights are standardised by their mean and (population) standard deviation,
as the model's :math:`\sigma_s` is measured, and each family is fitted *with that
standardisation imposed*, so only its shape parameters are free:

=============  ========  ==========================================================
family         shape     fit
=============  ========  ==========================================================
gaussian       0         none
exponential    0         none (possible only if no summit lies below -1 sigma_s)
weibull        1         maximum likelihood in the skewness (support below the data)
pearson3       1         maximum likelihood in the skewness (support around the data)
johnson        2         the sample skewness and kurtosis (Johnson's moment fit)
mixture        3         maximum likelihood by EM (keeps the sample mean and variance)
=============  ========  ==========================================================

They are ranked by Akaike's information criterion of the fitted log-likelihood,
:math:`AIC = 2k - 2\ln L` (k shape parameters; the two moments every family shares are
not counted): the lowest wins.  The Kolmogorov-Smirnov distance
:math:`D = \sup|F_N - F|` is reported beside it (not used to rank: with fitted parameters
it has no simple null distribution).  A family whose support excludes a measured summit
has :math:`\ln L = -\infty` and is listed last.  The empirical distribution (the data
themselves, smoothed) is not ranked.

References
----------
.. [1] H. Akaike, IEEE Trans. Autom. Control 19 (1974) 716.
.. [2] A. P. Dempster, N. M. Laird, D. B. Rubin, J. R. Statist. Soc. B 39 (1977) 1 (EM).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy import optimize

from .base import HeightDistribution
from .empirical import Empirical
from .exponential import Exponential
from .gaussian import GAUSSIAN
from .johnson import Johnson
from .mixture import Mixture
from .pearson import PearsonIII
from .samples import check_samples, sample_moments, standardise
from .weibull import SKEW_RANGE as WEIBULL_SKEW
from .weibull import Weibull

__all__ = ["FitResult", "HeightsFit", "fit_heights", "log_likelihood", "ks_distance"]


def log_likelihood(dist: HeightDistribution, z) -> float:
    """:math:`\\sum\\ln\\phi(z_i)` of standardised heights (-inf if one lies outside the support)."""
    f = dist.pdf(np.asarray(z, dtype=float))
    if np.any(f <= 0):
        return -math.inf
    return float(np.sum(np.log(f)))


def ks_distance(dist: HeightDistribution, z) -> float:
    """Kolmogorov-Smirnov distance :math:`\\sup_z|F_N(z) - F(z)|` of standardised heights."""
    z = np.sort(np.asarray(z, dtype=float))
    F = 1.0 - dist.sf(z)
    n = z.size
    i = np.arange(1, n + 1)
    return float(max(np.max(i / n - F), np.max(F - (i - 1) / n)))


@dataclass(frozen=True)
class FitResult:
    """One family fitted to the summit heights.

    Attributes
    ----------
    name : str
        Family (a key of :data:`asperity.heights.DISTRIBUTIONS`).
    distribution : HeightDistribution or None
        The fitted distribution (None if the family cannot hold the data).
    log_likelihood : float
        :math:`\\ln L` of the standardised heights (-inf if impossible).
    parameters : int
        Number of fitted shape parameters k.
    aic : float
        :math:`2k - 2\\ln L` (inf if impossible).
    ks : float
        Kolmogorov-Smirnov distance (NaN if impossible).
    note : str
        How it was fitted, or why it is impossible.
    """

    name: str
    distribution: HeightDistribution | None
    log_likelihood: float
    parameters: int
    aic: float
    ks: float
    note: str = ""

    @property
    def spec(self) -> str | None:
        """Command-line spelling of the fitted distribution (None if impossible)."""
        return None if self.distribution is None else self.distribution.spec

    def to_dict(self) -> dict:
        """Plain dict; non-finite numbers become None (strict JSON)."""
        def num(x):
            return float(x) if math.isfinite(x) else None
        return {"name": self.name, "spec": self.spec, "log_likelihood": num(self.log_likelihood),
                "parameters": self.parameters, "aic": num(self.aic), "ks": num(self.ks), "note": self.note}


@dataclass(frozen=True)
class HeightsFit:
    """Measured summit heights, their moments and the fitted families ranked by AIC.

    Attributes
    ----------
    n : int
        Number of summit heights.
    skewness, kurtosis : float
        Sample skewness and kurtosis (moment estimators; 0 and 3 for a Gaussian).
    ranking : tuple of FitResult
        Fitted families, lowest AIC first.
    empirical : Empirical
        The kernel estimate of the same heights (not ranked).
    """

    n: int
    skewness: float
    kurtosis: float
    ranking: tuple[FitResult, ...]
    empirical: Empirical = field(repr=False)

    @property
    def best(self) -> HeightDistribution:
        """The distribution ranked first (lowest AIC)."""
        return self.ranking[0].distribution

    def to_dict(self) -> dict:
        """Plain dict for strict JSON: moments, ranking (best first) and the best spelling."""
        return {"n": self.n, "skewness": self.skewness, "kurtosis": self.kurtosis, "best": self.best.spec,
                "ranking": [r.to_dict() for r in self.ranking], "statistic": "AIC (lowest first)"}

    def table(self) -> str:
        """The ranking as text lines."""
        lines = [f"{'rank':<5}{'family':<13}{'AIC':>12}{'KS':>9}  spelling"]
        for i, r in enumerate(self.ranking, 1):
            aic = f"{r.aic:12.2f}" if math.isfinite(r.aic) else f"{'-':>12}"
            ks = f"{r.ks:9.4f}" if math.isfinite(r.ks) else f"{'-':>9}"
            lines.append(f"{i:<5}{r.name:<13}{aic}{ks}  {r.spec or r.note}")
        return "\n".join(lines)


def _result(name, dist, z, k, note) -> FitResult:
    if dist is None:
        return FitResult(name, None, -math.inf, k, math.inf, math.nan, note)
    ll = log_likelihood(dist, z)
    if not math.isfinite(ll):
        return FitResult(name, None, -math.inf, k, math.inf, math.nan, "a summit lies outside its support")
    return FitResult(name, dist, ll, k, 2 * k - 2 * ll, ks_distance(dist, z), note)


def _ml_skew(cls, z, lo, hi):
    """Maximum-likelihood skewness of a one-parameter family over [lo, hi] (bounded Brent;
    a skewness below 1e-3 in magnitude is taken as 0, the smallest Pearson III admits)."""
    def make(s):
        return cls(skew=0.0 if abs(s) < 1e-3 else float(s))

    def nll(s):
        ll = log_likelihood(make(s), z)
        return 1e300 if not math.isfinite(ll) else -ll
    grid = np.linspace(lo, hi, 31)
    vals = [nll(s) for s in grid]
    i = int(np.argmin(vals))
    if vals[i] >= 1e300:
        return None
    a, b = grid[max(i - 1, 0)], grid[min(i + 1, grid.size - 1)]
    res = optimize.minimize_scalar(nll, bounds=(a, b), method="bounded", options={"xatol": 1e-7})
    s = float(res.x) if res.fun <= vals[i] else float(grid[i])
    return make(s)


def _em_mixture(z, iterations=2000):
    """Two-Gaussian maximum likelihood by EM from a split at the median (mean and variance kept)."""
    lo, hi = z[z <= np.median(z)], z[z > np.median(z)]
    if min(lo.size, hi.size) < 2:  # (nearly) a point mass on one side: no two-component fit
        return None
    w, m, s = np.array([0.5, 0.5]), np.array([lo.mean(), hi.mean()]), np.array([lo.std(), hi.std()]) + 0.05
    last = -math.inf
    for _ in range(iterations):
        dens = w[:, None] / s[:, None] * np.exp(-0.5 * ((z[None, :] - m[:, None]) / s[:, None]) ** 2)
        total = dens.sum(axis=0)
        ll = float(np.sum(np.log(total)))
        r = dens / total
        w = r.mean(axis=1)
        if np.any(w < 1e-6):
            return None
        m = (r * z).sum(axis=1) / (w * z.size)
        s = np.sqrt(np.maximum((r * (z - m[:, None]) ** 2).sum(axis=1) / (w * z.size), 0.05**2))
        if ll - last < 1e-10 * abs(ll):
            break
        last = ll
    return Mixture(float(w[0]), float(m[0]), float(s[0]), float(m[1]), float(s[1]))


def fit_heights(samples) -> HeightsFit:
    """Fit every family to measured summit heights and rank them by AIC (module docstring).

    Parameters
    ----------
    samples : array_like
        Summit heights in any unit, 1-D, finite, at least 20, not all equal.

    Returns
    -------
    HeightsFit
        Sample skewness and kurtosis, the ranking (``best`` first) and the empirical
        distribution.

    Raises
    ------
    ValueError
        For bad samples (:func:`~asperity.heights.samples.check_samples`).

    Examples
    --------
    >>> z = np.random.default_rng(1).weibull(1.5, 2000)   # skewness ~1.07
    >>> fit = fit_heights(z)
    >>> fit.ranking[0].name in ("weibull", "pearson3", "johnson"), round(fit.skewness, 1)
    (True, 1.1)

    References
    ----------
    Akaike (1974); Dempster, Laird & Rubin (1977); Johnson (1949) for the moment fit.
    """
    x = check_samples(samples)
    z = standardise(x)
    skew, kurt = sample_moments(x)
    results = [_result("gaussian", GAUSSIAN, z, 0, "Eq 19"),
               _result("exponential", Exponential(), z, 0, "")]
    w_lo, w_hi = WEIBULL_SKEW
    results.append(_result("weibull", _ml_skew(Weibull, z, w_lo, w_hi), z, 1, "maximum likelihood"))
    results.append(_result("pearson3", _ml_skew(PearsonIII, z, -2.0, 2.0), z, 1, "maximum likelihood"))
    try:
        johnson = Johnson(skew=min(max(skew, -3.0), 3.0), kurt=kurt)
        note = "moment fit"
    except ValueError as err:
        johnson, note = None, f"no moment fit: {err}"
    results.append(_result("johnson", johnson, z, 2, note))
    results.append(_result("mixture", _em_mixture(z), z, 3, "maximum likelihood (EM)"))
    ranking = tuple(sorted(results, key=lambda r: (r.aic, r.name)))
    return HeightsFit(n=int(x.size), skewness=skew, kurtosis=kurt, ranking=ranking,
                      empirical=Empirical.from_samples(x))
