"""Reference for :mod:`asperity.heights`: the standardised height densities from their definitions.

Each family is rebuilt here from its textbook definition, with its parameters found in
multiple precision (:mod:`mpmath`, 30 digits) by root finding on the moment formulas
written out again, not taken from the fast path:

* exponential: ``exp(-(z + 1))``, ``z >= -1``;
* Weibull with skewness S: shape c solving ``(G3 - 3 G1 G2 + 2 G1^3)/(G2 - G1^2)^(3/2) = S``,
  ``Gk = Gamma(1 + k/c)``, then ``z = (w - G1)/sqrt(G2 - G1^2)``;
* Pearson III with skewness S: gamma of shape ``4/S^2`` and scale ``|S|/2`` shifted to zero
  mean (mirrored for S < 0);
* Johnson S_U / S_B with skewness S and kurtosis K: the moments of ``sinh((x - g)/d)`` (the
  sinh written as exponentials, ``E[exp(a x)] = exp(a^2/2)``) and of ``1/(1 + exp(-(x - g)/d))``
  (:func:`mpmath.quad` over the normal variable), matched by :func:`mpmath.findroot` in
  (g, d), then standardised;
* two-Gaussian mixture: mean and variance removed;
* any Gaussian mixture (the empirical estimate): its components standardised; its GW moments
  sum the parabolic-cylinder closed form of each component (:func:`mpmath.pcfd`).

:class:`RefDensity` gives a float density (for :func:`scipy.integrate.quad` in
:mod:`.multi_asperity`), its support, a truncation height, and :func:`gw_moment_ref`,
:func:`moments_ref` integrate it with :func:`mpmath.quad`.  Nothing here imports
anything else from :mod:`asperity`.
"""

from __future__ import annotations

import math

from .common import MP, finite, mpmath

__all__ = ["RefDensity", "reference_density", "gw_moment_ref", "moments_ref"]

_DPS = 30


class RefDensity:
    """A standardised height density: ``pdf(z)`` (float), ``mp_pdf(z)`` (mpf), support and truncation.

    Attributes
    ----------
    name : str
        Family.
    lo, hi : float
        Support (``-inf``/``inf`` if unbounded).
    z_top : float
        A height above which the density is negligible (for truncating integrals).
    z_bottom : float
        A height below which it is negligible.
    """

    def __init__(self, name, mp_pdf, lo, hi, z_bottom, z_top, float_pdf=None):
        self.name = name
        self.mp_pdf = mp_pdf
        self.lo, self.hi = lo, hi
        self.z_bottom, self.z_top = z_bottom, z_top
        self._float_pdf = float_pdf

    def pdf(self, z: float) -> float:
        """Density at z, as a float (0 outside the support)."""
        z = float(z)
        if not self.lo <= z <= self.hi:
            return 0.0
        if self._float_pdf is not None:
            return self._float_pdf(z)
        with MP.workdps(20):
            return float(self.mp_pdf(mpmath.mpf(z)))

    def breaks(self):
        """Finite support edges."""
        return [e for e in (self.lo, self.hi) if math.isfinite(e)]


def _gaussian():
    c = 1 / mpmath.sqrt(2 * mpmath.pi)
    return RefDensity("gaussian", lambda z: c * mpmath.exp(-z * z / 2), -math.inf, math.inf, -12.0, 12.0,
                      lambda z: math.exp(-z * z / 2) / math.sqrt(2 * math.pi))


def _exponential():
    return RefDensity("exponential", lambda z: mpmath.exp(-(z + 1)), -1.0, math.inf, -1.0, 60.0,
                      lambda z: math.exp(-(z + 1)))


def _weibull(skew):
    skew = finite("skew", skew)
    with MP.workdps(_DPS):
        def sk(c):
            g1, g2, g3 = (mpmath.gamma(1 + k / c) for k in (1, 2, 3))
            return (g3 - 3 * g1 * g2 + 2 * g1**3) / (g2 - g1**2) ** 1.5

        # bracket the shape on a log grid (skewness falls with c), then refine
        grid = [mpmath.mpf(1) * 1.1**k for k in range(0, 60)]
        vals = [sk(c) - skew for c in grid]
        j = next(i for i in range(len(grid) - 1) if vals[i] >= 0 >= vals[i + 1])
        c = mpmath.findroot(lambda c: sk(c) - skew, (grid[j], grid[j + 1]), solver="illinois", tol=1e-50, maxsteps=200)
        g1, g2 = mpmath.gamma(1 + 1 / c), mpmath.gamma(1 + 2 / c)
        sd = mpmath.sqrt(g2 - g1**2)
        lo = -g1 / sd

    def pdf(z):
        w = g1 + sd * z
        return sd * c * w ** (c - 1) * mpmath.exp(-(w**c)) if w > 0 else mpmath.mpf(0)

    fc, fg1, fsd = float(c), float(g1), float(sd)

    def fpdf(z):
        w = fg1 + fsd * z
        return fsd * fc * w ** (fc - 1) * math.exp(-(w**fc)) if w > 0 else 0.0

    return RefDensity("weibull", pdf, float(lo), math.inf, float(lo), 60.0, fpdf)


def _pearson3(skew):
    skew = finite("skew", skew)
    if skew == 0:
        return _gaussian()
    with MP.workdps(_DPS):
        s = mpmath.mpf(skew)
        k = 4 / s**2
        th = abs(s) / 2
        edge = -2 / s  # the mean of the gamma variable is k th = 2/|s|
        norm = mpmath.gamma(k) * th**k

    def pdf(z):
        x = (z - edge) if skew > 0 else (edge - z)
        return x ** (k - 1) * mpmath.exp(-x / th) / norm if x > 0 else mpmath.mpf(0)

    e, fk, fth, log_norm = float(edge), float(k), float(th), float(mpmath.log(norm))

    def fpdf(z):
        x = (z - e) if skew > 0 else (e - z)
        return math.exp((fk - 1) * math.log(x) - x / fth - log_norm) if x > 0 else 0.0

    return RefDensity("pearson3", pdf, e if skew > 0 else -math.inf, math.inf if skew > 0 else e,
                      e if skew > 0 else -70.0, 70.0 if skew > 0 else e, fpdf)


def _normal_moments(transform):
    """Mean, variance, skewness, kurtosis of transform(x), x standard normal (mpmath.quad)."""
    c = 1 / mpmath.sqrt(2 * mpmath.pi)
    w = lambda x: c * mpmath.exp(-x * x / 2)  # noqa: E731
    pts = [-mpmath.inf, -6, -3, -1, 0, 1, 3, 6, mpmath.inf]
    m1 = mpmath.quad(lambda x: transform(x) * w(x), pts)
    cm = [mpmath.quad(lambda x, j=j: (transform(x) - m1) ** j * w(x), pts) for j in (2, 3, 4)]
    return m1, cm[0], cm[1] / cm[0] ** 1.5, cm[2] / cm[0] ** 2


def _johnson(skew, kurt):
    skew, kurt = finite("skew", skew), finite("kurt", kurt)
    with MP.workdps(20):  # the fit by quadrature is slow: 20 digits (the tests compare to 1e-10)
        # the lognormal line Ku(omega) = omega^4 + 2 omega^3 + 3 omega^2 - 3 with
        # (omega - 1)(omega + 2)^2 = skew^2 separates S_U (above) from S_B (below)
        w = mpmath.findroot(lambda w: (w - 1) * (w + 2) ** 2 - skew**2, 1 + abs(skew) / 3 + 1e-6)
        bounded = kurt < w**4 + 2 * w**3 + 3 * w**2 - 3
        if bounded:
            def tr(g, dl):
                return lambda x: 1 / (1 + mpmath.exp(-(x - g) / dl))
        else:
            def tr(g, dl):
                return lambda x: mpmath.sinh((x - g) / dl)

        def su_moments(g, dl):
            # E[sinh((x-g)/dl)^j]: expand the sinh into exponentials, E[e^(a x)] = e^(a^2/2)
            raw = [sum(mpmath.binomial(j, i) * (-1) ** i * mpmath.exp(-(j - 2 * i) * g / dl + (j - 2 * i) ** 2
                                                                       / (2 * dl * dl)) for i in range(j + 1)) / 2**j
                   for j in range(1, 5)]
            m = raw[0]
            c2 = raw[1] - m * m
            c3 = raw[2] - 3 * m * raw[1] + 2 * m**3
            c4 = raw[3] - 4 * m * raw[2] + 6 * m * m * raw[1] - 3 * m**4
            return m, c2, c3 / c2**1.5, c4 / c2**2

        def residual(g, dl):
            _, _, s, k = _normal_moments(tr(g, dl)) if bounded else su_moments(g, dl)
            return [s - skew, k - kurt]

        with MP.workdps(10):  # a coarse start: the best point of a grid
            best = None
            for dl in (0.6, 1.0, 1.7, 3.0):
                for g in (-3, -1.5, -0.5, 0, 0.5, 1.5, 3):
                    g_ = -g if not bounded else g
                    try:
                        r = residual(mpmath.mpf(g_), mpmath.mpf(dl))
                    except (ZeroDivisionError, ValueError):
                        continue
                    e = abs(r[0]) + abs(r[1])
                    if best is None or e < best[0]:
                        best = (e, g_, dl)
        g, dl = mpmath.findroot(lambda g, dl: residual(g, dl), (mpmath.mpf(best[1]), mpmath.mpf(best[2])),
                                tol=1e-30)
        T = tr(g, dl)
        mean, var, _, _ = _normal_moments(T) if bounded else su_moments(g, dl)
        sd = mpmath.sqrt(var)
        c = 1 / mpmath.sqrt(2 * mpmath.pi)
        if bounded:
            lo, hi = (T(-mpmath.inf) - mean) / sd, (T(mpmath.inf) - mean) / sd

            def pdf(z):
                y = z * sd + mean
                if not 0 < y < 1:
                    return mpmath.mpf(0)
                x = g + dl * mpmath.log(y / (1 - y))
                return sd * dl / (y * (1 - y)) * c * mpmath.exp(-x * x / 2)

            fg, fdl, fsd, fmean = (float(v) for v in (g, dl, sd, mean))

            def fpdf(z):
                y = z * fsd + fmean
                if not 0 < y < 1:
                    return 0.0
                x = fg + fdl * math.log(y / (1 - y))
                return fsd * fdl / (y * (1 - y)) * math.exp(-x * x / 2) / math.sqrt(2 * math.pi)

            return RefDensity("johnson", pdf, float(lo), float(hi), float(lo), float(hi), fpdf)

        def pdf(z):
            y = z * sd + mean
            x = g + dl * mpmath.asinh(y)
            return sd * dl / mpmath.sqrt(1 + y * y) * c * mpmath.exp(-x * x / 2)

        fg, fdl, fsd, fmean = (float(v) for v in (g, dl, sd, mean))

        def fpdf(z):
            y = z * fsd + fmean
            x = fg + fdl * math.asinh(y)
            return fsd * fdl / math.sqrt(1 + y * y) * math.exp(-x * x / 2) / math.sqrt(2 * math.pi)

        top = float((T(mpmath.mpf(10.5)) - mean) / sd)
        bottom = float((T(mpmath.mpf(-10.5)) - mean) / sd)
        return RefDensity("johnson", pdf, -math.inf, math.inf, bottom, top, fpdf)


def _gauss_mix(weights, means, sds, name):
    with MP.workdps(_DPS):
        w = [mpmath.mpf(x) for x in weights]
        total = sum(w)
        w = [x / total for x in w]
        m = [mpmath.mpf(x) for x in means]
        s = [mpmath.mpf(x) for x in sds]
        mean = sum(wi * mi for wi, mi in zip(w, m, strict=True))
        var = sum(wi * (si**2 + (mi - mean) ** 2) for wi, mi, si in zip(w, m, s, strict=True))
        sd = mpmath.sqrt(var)
        m = [(mi - mean) / sd for mi in m]
        s = [si / sd for si in s]
        c = 1 / mpmath.sqrt(2 * mpmath.pi)

    def pdf(z):
        return sum(wi / si * c * mpmath.exp(-((z - mi) / si) ** 2 / 2) for wi, mi, si in zip(w, m, s, strict=True))

    fw, fm, fs = ([float(v) for v in x] for x in (w, m, s))

    def fpdf(z):
        return sum(wi / si * math.exp(-((z - mi) / si) ** 2 / 2)
                   for wi, mi, si in zip(fw, fm, fs, strict=True)) / math.sqrt(2 * math.pi)

    top = float(max(mi + 12 * si for mi, si in zip(m, s, strict=True)))
    bottom = float(min(mi - 12 * si for mi, si in zip(m, s, strict=True)))
    dens = RefDensity(name, pdf, -math.inf, math.inf, bottom, top, fpdf)
    dens.components = (w, m, s)
    return dens


def reference_density(name: str, **params) -> RefDensity:
    """The reference density of a family from its definition (module docstring).

    Parameters
    ----------
    name : str
        ``gaussian``, ``exponential``, ``weibull`` (skew), ``pearson3`` (skew), ``johnson``
        (skew, kurt), ``mixture`` (w, m1, s1, m2, s2) or ``gauss_mixture`` (weights, means,
        sds: any Gaussian mixture, e.g. an empirical estimate's components).
    **params
        The family's parameters.

    Returns
    -------
    RefDensity
    """
    if name == "gaussian":
        return _gaussian()
    if name == "exponential":
        return _exponential()
    if name == "weibull":
        return _weibull(params["skew"])
    if name == "pearson3":
        return _pearson3(params["skew"])
    if name == "johnson":
        return _johnson(params["skew"], params["kurt"])
    if name == "mixture":
        w = finite("w", params["w"])
        return _gauss_mix((w, 1 - w), (params["m1"], params["m2"]), (params["s1"], params["s2"]), "mixture")
    if name == "gauss_mixture":
        return _gauss_mix(params["weights"], params["means"], params["sds"], "gauss_mixture")
    raise ValueError(f"unknown reference density {name!r}")


def _points(dens: RefDensity, a, b):
    """Integration breakpoints in [a, b]: support edges, unit steps through the bulk."""
    pts = {a, b}
    pts.update(e for e in dens.breaks() if a < e < b)
    lo, hi = max(a, -12.0), min(b, 12.0)
    k = math.ceil(lo)
    while k < hi:
        if a < k < b:
            pts.add(float(k))
        k += 1
    return sorted(pts)


def gw_moment_ref(dens: RefDensity, d, order) -> float:
    """GW moment ``int_d^inf (z - d)^n phi(z) dz`` with :func:`mpmath.quad` (30 digits).

    Parameters
    ----------
    dens : RefDensity
        The density.
    d : float
        Separation.
    order : float
        n >= 0.

    Returns
    -------
    float
    """
    d, n = finite("d", d), finite("order", order)
    if getattr(dens, "components", None) is not None:  # Gaussian mixture: parabolic-cylinder closed form
        with MP.workdps(_DPS):
            dm = mpmath.mpf(d)
            total = 0
            for wi, mi, si in zip(*dens.components, strict=True):
                x = (dm - mi) / si  # int_x^inf (t - x)^n phi(t) dt = Gamma(n+1) e^(-x^2/4) D_(-n-1)(x)/sqrt(2 pi)
                g = mpmath.gamma(n + 1) * mpmath.exp(-x * x / 4) * mpmath.pcfd(-n - 1, x) / mpmath.sqrt(2 * mpmath.pi)
                total += wi * si**n * g
            return float(total)
    a = max(d, dens.lo, dens.z_bottom)
    b = min(dens.hi, max(a, dens.z_top) + (dens.z_top - dens.z_bottom))
    if not a < b:
        return 0.0
    with MP.workdps(_DPS):
        pts = _points(dens, a, b)
        pts = [mpmath.mpf(p) for p in pts]
        dm = mpmath.mpf(d)
        # refine next to the lower end: far in a light tail the integrand falls within 1e-2
        extra = {pts[0] + mpmath.mpf(2) ** -k for k in range(1, 14) if pts[0] + 2.0**-k < b}
        if dens.mp_pdf(pts[0] + mpmath.mpf("1e-9")) < 1e-8 * dens.mp_pdf(mpmath.mpf(0)):  # far in a tail
            extra |= {pts[0] + mpmath.mpf(k) / 256 for k in range(1, 129) if pts[0] + k / 256 < b}
        pts = sorted(set(pts) | extra)
        return float(mpmath.quad(lambda z: (z - dm) ** n * dens.mp_pdf(z), pts))


def moments_ref(dens: RefDensity):
    """``(total, mean, variance, skewness, kurtosis)`` of the density by :func:`mpmath.quad`."""
    with MP.workdps(_DPS):
        a = max(dens.lo, dens.z_bottom)
        b = min(dens.hi, dens.z_top)
        pts = [mpmath.mpf(p) for p in _points(dens, a, b)]
        m = [mpmath.quad(lambda z, k=k: z**k * dens.mp_pdf(z), pts) for k in range(5)]
        mean = m[1] / m[0]
        c2 = m[2] / m[0] - mean**2
        c3 = m[3] / m[0] - 3 * mean * m[2] / m[0] + 2 * mean**3
        c4 = m[4] / m[0] - 4 * mean * m[3] / m[0] + 6 * mean**2 * m[2] / m[0] - 3 * mean**4
        return float(m[0]), float(mean), float(c2), float(c3 / c2**1.5), float(c4 / c2**2)
