"""Reference for :mod:`asperity.multi_asperity` and the curves: Greenwood-Williamson integrals
(Eqs 5, 6, 10, 18, 21) by adaptive quadrature, the load by bracketing, pull-off by minimisation.

The integrals are computed with adaptive Gauss-Kronrod quadrature
(:func:`scipy.integrate.quad`, ``epsabs=0``, ``epsrel=1e-11``) in the variable ``s`` with
``u = u_end + s**2``, which removes the square-root behaviour of the MD solution at the end
of the stable branch, with the range split at every kink: the Hurtado-Kim radii
``a_bar = a1, a2`` and the sign changes of the per-asperity MD load.  :func:`load_point`
and :func:`pull_off` scan and bracket on top of :func:`separation_point`: brute force.
"""

from __future__ import annotations

import math

import numpy as np
from scipy import integrate, optimize

from .common import finite, positive
from .friction_stress import hk_tau
from .groups import conversion_factors
from .maugis_dugdale_branch import branch_D_for_A, branch_end, branch_P_zeros, branch_point_offset

__all__ = ["separation_point", "load_point", "pull_off"]

_SQRT2PI = math.sqrt(2.0 * math.pi)
#: Quadrature settings of the outer Greenwood-Williamson integrals.
_EPSREL = 1e-11
_LIMIT = 400
#: Truncation of the height integral: z_max = max(d, 0) + _Z_TAIL.
_Z_TAIL = 12.0


class Params:
    """Validated model parameters and derived constants (Eqs. 2, 3, 15, 17)."""

    __slots__ = (
        "alpha",
        "beta",
        "gamma",
        "nu",
        "h_over_b",
        "tau_f1",
        "tau_f2",
        "a1",
        "a2",
        "hk_slope",
        "hertz_pref",
        "lam",
        "delta_hat",
        "P_hat",
        "A_hat",
        "key",
    )

    def __init__(self, alpha, beta, gamma, nu, h_over_b, tau_f1, tau_f2, a1, a2):
        self.alpha = positive("alpha", alpha)
        self.beta = positive("beta", beta)
        self.gamma = finite("gamma", gamma)
        if self.gamma < 0.0:
            raise ValueError(f"gamma must be >= 0, got {gamma!r}")
        self.nu = finite("nu", nu)
        if not -1.0 < self.nu < 0.5:
            raise ValueError(f"nu must satisfy -1 < nu < 0.5, got {nu!r}")
        self.h_over_b = positive("h_over_b", h_over_b)
        self.tau_f1 = positive("tau_f1", tau_f1)
        self.tau_f2 = positive("tau_f2", tau_f2)
        self.a1 = positive("a1", a1)
        self.a2 = positive("a2", a2)
        if not self.a2 > self.a1:
            raise ValueError(f"a2 must be > a1, got a1={a1!r}, a2={a2!r}")
        # Eq. 3: slope of the straight log-log line of Eq. 2 (any log base).
        self.hk_slope = math.log(self.tau_f2 / self.tau_f1) / math.log(self.a2 / self.a1)
        # Eq. 6 prefactor.
        self.hertz_pref = (4.0 / 3.0) * (2.0 / (1.0 - self.nu)) * self.alpha * self.beta**2
        if self.gamma > 0.0:
            f = conversion_factors(self.alpha, self.beta, self.gamma, nu=self.nu, h_over_b=self.h_over_b)
            self.lam = f["lambda"]
            self.delta_hat = f["delta_hat"]
            self.P_hat = f["P_hat"]
            self.A_hat = f["A_hat"]
        else:
            self.lam = self.delta_hat = self.P_hat = self.A_hat = None
        self.key = (
            self.alpha,
            self.beta,
            self.gamma,
            self.nu,
            self.h_over_b,
            self.tau_f1,
            self.tau_f2,
            self.a1,
            self.a2,
        )


class _Local:
    """Per-asperity state as a function of the integration variable ``s``.

    ``u = u_end + s^2``; returns ``(a_bar, P_bar)``.
    """

    def __init__(self, p):
        self.p = p
        if p.gamma == 0.0:
            self.u_end = 0.0
            self.s_breaks = [p.a1 / p.beta, p.a2 / p.beta]
            self.s_Pzero = []
        else:
            lam = p.lam
            self.lam = lam
            _, A_end, D_end, _ = branch_end(lam)
            self.u_end = float(p.delta_hat * D_end)
            breaks = []
            for ak in (p.a1, p.a2):
                dD = branch_D_for_A(lam, ak * p.A_hat)
                if dD is not None:
                    breaks.append(math.sqrt(p.delta_hat * float(dD)))
            self.s_breaks = breaks
            self.s_Pzero = [math.sqrt(p.delta_hat * float(v)) for v in branch_P_zeros(lam)]

    def __call__(self, s):
        p = self.p
        if p.gamma == 0.0:
            return p.beta * s, p.hertz_pref * s**3
        A, P = branch_point_offset(self.lam, s * s / p.delta_hat)
        return A / p.A_hat, P / p.P_hat


def _quantity(name, loc, a, P):
    if name == "contacts":
        return 1.0
    if name == "P":
        return P
    if name == "area":
        return a * a
    if name == "F":  # integrand of Eq 10: 2 pi tau(a) a^2
        p = loc.p
        return 2.0 * math.pi * hk_tau(a, tau_f1=p.tau_f1, tau_f2=p.tau_f2, a1=p.a1, a2=p.a2) * a * a
    raise KeyError(name)


def _integrate_density(d, p, names, dens):
    """The integrals for a non-Gaussian height density ``dens`` (a RefDensity of .heights):
    the same substitution u = u_end + s^2, split also at the density's support edges and
    at unit steps through its bulk; truncated where the density is negligible."""
    loc = _Local(p)
    z0 = d + loc.u_end
    z_hi = min(dens.hi, max(z0, dens.z_top) + (dens.z_top - dens.z_bottom))
    if z_hi <= max(z0, dens.lo):
        return dict.fromkeys(names, 0.0)
    s_max = math.sqrt(z_hi - z0)
    marks = [max(z0, dens.lo), *dens.breaks()] + [float(k) for k in range(math.ceil(max(z0, -12.0)), 13)]
    marks += [max(z0, dens.lo) + 2.0**-k for k in range(1, 14)]  # a light tail falls within 1e-2 of the end
    s_marks = [math.sqrt(z - z0) for z in marks if z0 < z < z_hi]
    pts = sorted({0.0, s_max, *[s_ for s_ in loc.s_breaks + loc.s_Pzero + s_marks if 0.0 < s_ < s_max]})
    out = {}
    for name in names:

        def f(s, name=name):
            w = 2.0 * s * dens.pdf(z0 + s * s)
            if w == 0.0:
                return 0.0
            a, P = loc(s)
            return w * _quantity(name, loc, a, P)

        total = 0.0
        for lo, hi in zip(pts[:-1], pts[1:], strict=True):
            val, err, info, *msg = integrate.quad(f, lo, hi, epsabs=0.0, epsrel=_EPSREL, limit=_LIMIT, full_output=1)
            if msg and err > 1e-8 * abs(val) and err > 1e-300:
                raise ArithmeticError(f"quadrature of {name!r} at d={d!r} failed: {msg[0]} (err={err:g})")
            total += val
        out[name] = float(total)
    return out


def _integrate(d, p, names, dens=None):
    """Integrals of Eqs. 5, 6/18, 10, 21 at separation ``d`` for the given quantities."""
    if dens is not None:
        return _integrate_density(d, p, names, dens)
    loc = _Local(p)
    z0 = d + loc.u_end  # lowest in-contact height
    # truncation z_max = max(d, 0) + 12, i.e. u_max = max(-d, 0) + 12: the s grid
    # does not depend on d for d >= 0, so the per-asperity cache is shared.
    s_max = math.sqrt(max(-d, 0.0) + _Z_TAIL - loc.u_end)
    # extra breakpoints around the bulk of phi when the contact region starts far below it
    s_phi = []
    if z0 < -3.0:
        s_phi = [math.sqrt(zk - z0) for zk in (-6.0, -3.0, 0.0, 3.0, 6.0) if zk - 1.0 > z0]
    pts = sorted({0.0, s_max, *[s for s in loc.s_breaks + loc.s_Pzero + s_phi if 0.0 < s < s_max]})
    if z0 > 0.0:
        # phi(z0 + s^2) = phi(z0) exp(-z0 s^2 - s^4/2): integrate the rest, scale at the end
        scale = math.exp(-0.5 * z0 * z0) / _SQRT2PI

        def weight(s):
            v = s * s
            return 2.0 * s * math.exp(-z0 * v - 0.5 * v * v)
    else:
        scale = 1.0 / _SQRT2PI

        def weight(s):
            z = z0 + s * s
            return 2.0 * s * math.exp(-0.5 * z * z)

    out = {}
    for name in names:

        def f(s, name=name):
            w = weight(s)
            if w == 0.0:
                return 0.0
            a, P = loc(s)
            return w * _quantity(name, loc, a, P)

        total = 0.0
        for lo, hi in zip(pts[:-1], pts[1:], strict=True):
            val, err, info, *msg = integrate.quad(f, lo, hi, epsabs=0.0, epsrel=_EPSREL, limit=_LIMIT, full_output=1)
            if msg and err > 1e-8 * abs(val) and err > 1e-300:
                raise ArithmeticError(f"quadrature of {name!r} at d={d!r} failed: {msg[0]} (err={err:g})")
            total += val
        out[name] = float(total * scale)
    return out


def _params(alpha, beta, gamma, nu, h_over_b, tau_f1, tau_f2, a1, a2):
    return Params(alpha, beta, gamma, nu, h_over_b, tau_f1, tau_f2, a1, a2)


_NAMES = ("contacts", "P", "F", "area")


def separation_point(
    d, alpha, beta, gamma=0.0, *, nu=0.3, h_over_b=1.0, tau_f1=1 / 43, tau_f2=1 / 43 / 30, a1=28.0, a2=8e4,
    heights=None
):
    """Contacts, load, friction and area per asperity at one separation.

    Computes, with ``u = z - d`` and the standard normal height density
    ``phi`` (Eq. 19), integrating over the in-contact asperities
    ``z >= d + u_end`` (``u_end = 0`` for Hertz, ``delta_hat Delta_end`` with
    adhesion):

    * ``contacts = int phi dz`` (Eq. 5, ``n/N``),
    * ``P = int P_bar(u) phi dz`` (Eq. 6 for Hertz, Eq. 18 with the MD load
      ``P_M/P_hat`` of Eqs. 11-13, 17 with adhesion),
    * ``F = int 2 pi tau_bar(a_bar) a_bar^2 phi dz`` (Eq. 10 with Eq. 2),
    * ``area = int a_bar^2 phi dz`` (Eq. 21, ``A/(N pi b^2)``).

    Parameters
    ----------
    d : float
        Dimensionless separation ``d/sigma``.
    alpha, beta : float
        Surface roughness and friction regime parameters (Eq. 7), > 0.
    gamma : float, optional
        Surface energy / compliance coefficient (Eq. 16), >= 0; 0 means no
        adhesion (Hertz).
    nu : float, optional
        Poisson's ratio, ``-1 < nu < 0.5``.
    h_over_b : float, optional
        Maximum adhesion distance over Burgers vector (Eq. 15).
    tau_f1, tau_f2, a1, a2 : float, optional
        Hurtado-Kim constants of Eq. 2 (``a1 < a2``).
    heights : RefDensity, optional
        A height density of :mod:`.heights` (default: the standard normal, Eq. 19).

    Returns
    -------
    dict
        Float values under ``'contacts'``, ``'P'``, ``'F'``, ``'area'``.
    """
    d = finite("d", d)
    p = _params(alpha, beta, gamma, nu, h_over_b, tau_f1, tau_f2, a1, a2)
    return _integrate(d, p, _NAMES, heights)


def load_point(P, alpha, beta, gamma=0.0, *, nu=0.3, h_over_b=1.0, tau_f1=1 / 43, tau_f2=1 / 43 / 30, a1=28.0, a2=8e4,
               heights=None):
    """State at the smallest separation where the mean load per asperity equals ``P``.

    ``P_bar(d) -> +inf`` as ``d -> -inf``.  Without adhesion ``P_bar(d)`` is
    strictly decreasing and the root is bracketed by expansion.  With adhesion
    ``P_bar(d)`` need not be monotone: ``d`` is scanned upward in steps of 0.25
    from ``d = -2`` (or lower, until ``P_bar > P``) and the first bracketed
    sign change is refined with :func:`scipy.optimize.brentq` (a crossing
    pair closer together than the scan step could be missed).

    Parameters
    ----------
    P : float
        Target mean load per asperity ``P/(N G b^2)`` (> 0 when ``gamma == 0``).
    alpha, beta, gamma, nu, h_over_b, tau_f1, tau_f2, a1, a2, heights
        As in :func:`separation_point`.

    Returns
    -------
    dict
        ``'d'`` plus the keys of :func:`separation_point`.
    """
    P = finite("P", P)
    p = _params(alpha, beta, gamma, nu, h_over_b, tau_f1, tau_f2, a1, a2)
    if p.gamma == 0.0 and not P > 0.0:
        raise ValueError(f"P must be > 0 without adhesion, got {P!r}")

    def g(d):
        return _integrate(d, p, ("P",), heights)["P"] - P

    lo = 0.0 if p.gamma == 0.0 else -2.0
    glo = g(lo)
    while not glo > 0:
        lo -= 1.0
        if lo < -40:
            raise ValueError(f"P={P!r} not reached for d >= -40")
        glo = g(lo)
    if p.gamma == 0.0:
        step = 1.0
        hi = lo + step
        while g(hi) > 0:
            lo = hi
            step *= 1.5
            hi = lo + step
            if hi > 40:
                raise ValueError(f"P={P!r} too small to be reached (d > 40)")
    else:
        hi = lo + 0.25
        while g(hi) > 0:
            lo = hi
            hi = lo + 0.25
            if hi > 40:
                raise ValueError(f"P={P!r} not reached for d <= 40")
    d = optimize.brentq(g, lo, hi, xtol=1e-13, rtol=1e-15, maxiter=200)
    out = {"d": float(d)}
    out.update(_integrate(d, p, _NAMES, heights))
    return out


def pull_off(
    alpha, beta, gamma, *, d_max=10.0, nu=0.3, h_over_b=1.0, tau_f1=1 / 43, tau_f2=1 / 43 / 30, a1=28.0, a2=8e4,
    heights=None
):
    """Pull-off force per asperity: ``max(0, -min_{d <= d_max} P_bar(d))``.

    A grid scan of ``P_bar(d)`` (step 0.25, extended to the left while the
    minimum sits on the left edge) followed by bounded Brent minimisation
    around the best grid point.

    Parameters
    ----------
    alpha, beta, gamma, nu, h_over_b, tau_f1, tau_f2, a1, a2, heights
        As in :func:`separation_point`.
    d_max : float, optional
        Largest separation considered.

    Returns
    -------
    dict
        ``{'pull_off': float, 'd': float}`` with ``'d'`` the separation where
        ``P_bar`` is smallest (``d_max`` if ``P_bar`` decreases up to there).
    """
    d_max = finite("d_max", d_max)
    p = _params(alpha, beta, gamma, nu, h_over_b, tau_f1, tau_f2, a1, a2)

    def _P_of_d(x, p):
        return _integrate(x, p, ("P",), heights)["P"]

    step = 0.25
    start = min(-1.0, d_max - 4.0)
    grid = list(np.arange(start, d_max, step)) + [d_max]
    vals = [_P_of_d(x, p) for x in grid]
    while int(np.argmin(vals)) == 0:
        new = grid[0] - step
        grid.insert(0, new)
        vals.insert(0, _P_of_d(new, p))
        if new < -40:
            raise ArithmeticError("pull_off: P_bar has no minimum for d >= -40")
    i = int(np.argmin(vals))
    if i == len(grid) - 1:
        dmin, pmin = grid[i], vals[i]
    else:
        lo, hi = grid[i - 1], grid[i + 1]
        res = optimize.minimize_scalar(
            lambda x: _P_of_d(x, p), bounds=(lo, hi), method="bounded", options={"xatol": 1e-7, "maxiter": 200}
        )
        dmin, pmin = float(res.x), float(res.fun)
        if vals[i] < pmin:
            dmin, pmin = grid[i], vals[i]
    return {"pull_off": float(max(0.0, -pmin)), "d": float(dmin)}
