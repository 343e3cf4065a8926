"""Reference for :mod:`asperity.jackson_green`, :mod:`asperity.nix_gao` and
:mod:`asperity.elastic_plastic`: the Jackson-Green asperity and its Greenwood-Williamson integrals.

Written from the equations only (Jackson & Green, J. Tribol. 127 (2005) 343; Nix & Gao,
J. Mech. Phys. Solids 46 (1998) 411; the handling of JG's load jump in docs/plasticity.md),
scalar, with different numerics from the fast path:

* the self-consistent critical interference with the size effect,
  ``omega_c = omega_c0 (1 + h/omega_c)``, and every transition ``omega*(u) = w`` are found
  by bracketed root solves (:func:`scipy.optimize.brentq`), not by the quadratic's closed
  form;
* the load's switch ``omega*_x`` is the first sign change of ``P_fit - P_hertz`` on a fine
  scan above ``omega* = 1``, refined by ``brentq``;
* the Greenwood-Williamson integrals (Eqs 5, 6, 10, 21) are adaptive Gauss-Kronrod
  (:func:`scipy.integrate.quad`, ``epsrel=1e-12``) in ``s`` with ``u = s**2``, split at every
  transition, at the Hurtado-Kim radii (found by root solves on the contact radius) and
  around the peak of the Gaussian density.

Units are the model's: penetration ``u = (z - d)/sigma``, radius ``a/b``, force ``P/(G b^2)``.
"""

from __future__ import annotations

import math

from scipy import integrate, optimize

from .common import finite, positive
from .friction_stress import hk_tau

__all__ = ["jg_asperity", "jg_critical_penetration", "jg_separation_point", "jg_load_point"]

_NAMES = ("contacts", "P", "F", "area", "plastic")


class _JG:
    """One Jackson-Green asperity in the model's units (scalar)."""

    def __init__(self, alpha, beta, nu, H_over_E, h_star, tau_f1, tau_f2, a1, a2):
        self.alpha, self.beta = positive("alpha", alpha), positive("beta", beta)
        self.nu = finite("nu", nu)
        if not 0.0 <= self.nu < 0.5:
            raise ValueError(f"nu must lie in [0, 0.5), got {nu!r}")
        self.H = positive("H_over_E", H_over_E)
        self.h = finite("h_star", h_star)
        if self.h < 0:
            raise ValueError(f"h_star must be >= 0, got {h_star!r}")
        self.hk = {"tau_f1": tau_f1, "tau_f2": tau_f2, "a1": a1, "a2": a2}
        # JG: C = 1.295 exp(0.736 nu); omega_c = (pi C S_y / (2 E*))^2 R; S_y = H / 2.84.
        self.C = 1.295 * math.exp(0.736 * self.nu)
        self.ey0 = self.H / 2.84
        self.uc0 = (math.pi * self.C * self.ey0 / 2.0) ** 2 / self.alpha**2  # omega_c0 / sigma = (..)^2 R/sigma
        self.hertz = (4.0 / 3.0) * (2.0 / (1.0 - self.nu)) * self.alpha * self.beta**2  # Eq 6 prefactor
        self.u_c = self._u_of_w(1.0)
        self.w_x = self._load_switch()
        self.u_x = self._u_of_w(self.w_x)
        self.u_t = self._u_of_w(1.9)

    # Nix-Gao: H(u) = H0 sqrt(1 + h/u), so omega_c(u) = omega_c0 (1 + h/u) and e_y(u) = e_y0 sqrt(1 + h/u).
    def ey(self, u):
        return self.ey0 if self.h == 0.0 else self.ey0 * math.sqrt(1.0 + self.h / u)

    def uc(self, u):
        return self.uc0 if self.h == 0.0 else self.uc0 * (1.0 + self.h / u)

    def w(self, u):
        return u / self.uc(u)

    def _u_of_w(self, target):
        """The penetration where omega*(u) = target (omega* increases with u)."""
        if self.h == 0.0:
            return target * self.uc0
        hi = target * self.uc0 + 1.0
        while self.w(hi) < target:
            hi *= 2.0
        return optimize.brentq(lambda u: self.w(u) - target, 1e-300, hi, xtol=1e-300, rtol=1e-15, maxiter=500)

    # Jackson & Green's fits, in omega* and the local e_y.
    @staticmethod
    def area_ratio(w, ey):
        """A/A_c: Hertz below 1.9, w (w/1.9)^B with B = 0.14 exp(23 e_y) above."""
        return w if w <= 1.9 else w * (w / 1.9) ** (0.14 * math.exp(23.0 * ey))

    def load_fit(self, w, ey):
        a_over_R = math.pi * self.C * ey / 2.0 * math.sqrt(self.area_ratio(w, ey))
        HG = 2.84 * (1.0 - math.exp(-0.82 * a_over_R ** (-0.7)))
        return (math.exp(-0.25 * w ** (5.0 / 12.0)) * w**1.5
                + 4.0 * HG / self.C * (1.0 - math.exp(-(w ** (5.0 / 9.0)) / 25.0)) * w)

    def _gap(self, w):
        return self.load_fit(w, self.ey(self._u_of_w(w))) - w**1.5

    def _load_switch(self):
        n = 7000
        prev_w, prev_g = 1.0, self._gap(1.0)
        if not prev_g > 0:
            raise ValueError("load fit below Hertz at yield")
        for i in range(1, n + 1):
            w = 1.0 + 7.0 * i / n
            g = self._gap(w)
            if g <= 0:
                return optimize.brentq(self._gap, prev_w, w, xtol=1e-15, rtol=1e-15, maxiter=500)
            prev_w = w
        raise ValueError("load fit does not cross Hertz for omega* <= 8")

    def point(self, u):
        """(a_bar, P_bar) at penetration u."""
        if u <= 0.0:
            return 0.0, 0.0
        a_hertz = self.beta * math.sqrt(u)  # Eq 8
        P_hertz = self.hertz * u**1.5  # Eq 6 integrand
        w, ey, uc = self.w(u), self.ey(u), self.uc(u)
        a = a_hertz if u <= self.u_t else self.beta * math.sqrt(uc * self.area_ratio(w, ey))
        P = P_hertz if u <= self.u_x else self.hertz * uc**1.5 * self.load_fit(w, ey)
        return a, P

    def hk_breaks(self):
        """Penetrations where a_bar(u) crosses the Hurtado-Kim radii a1, a2."""
        out = []
        for ak in (self.hk["a1"], self.hk["a2"]):
            hi = 1e-6
            while self.point(hi)[0] < ak:
                hi *= 2.0
            out.append(optimize.brentq(lambda u, ak=ak: self.point(u)[0] - ak, 0.0, hi, xtol=1e-300, rtol=1e-15,
                                       maxiter=500))
        return out


def _make(alpha, beta, nu, H_over_E, h_star, tau_f1, tau_f2, a1, a2):
    return _JG(alpha, beta, nu, H_over_E, h_star, tau_f1, tau_f2, a1, a2)


def jg_asperity(u, alpha, beta, nu, H_over_E, h_star=0.0, *, tau_f1=1 / 43, tau_f2=1 / 43 / 30, a1=28.0, a2=8e4):
    """Contact radius ``a/b``, force ``P/(G b^2)`` and friction ``F/(G b^2)`` of one asperity at penetration ``u``.

    Returns
    -------
    dict
        ``'a'``, ``'P'``, ``'F'`` and the transitions ``'u_c'``, ``'u_x'``, ``'u_t'`` (in sigma).
    """
    jg = _make(alpha, beta, nu, H_over_E, h_star, tau_f1, tau_f2, a1, a2)
    a, P = jg.point(finite("u", u))
    F = 2.0 * math.pi * hk_tau(a, **jg.hk) * a * a
    return {"a": a, "P": P, "F": F, "u_c": jg.u_c, "u_x": jg.u_x, "u_t": jg.u_t}


def jg_critical_penetration(alpha, nu, H_over_E, h_star=0.0):
    """omega_c / sigma, by a root solve of omega*(u) = 1."""
    return _make(alpha, 1.0, nu, H_over_E, h_star, 1 / 43, 1 / 43 / 30, 28.0, 8e4).u_c


def _integrate(d, jg, names):
    phi = 1.0 / math.sqrt(2.0 * math.pi)

    def density(u):
        return phi * math.exp(-0.5 * (d + u) ** 2)

    def integrand(s, name):
        u = s * s
        a, P = jg.point(u)
        q = {"contacts": 1.0, "P": P, "area": a * a,
             "F": 2.0 * math.pi * hk_tau(a, **jg.hk) * a * a, "plastic": 1.0 if u > jg.u_c else 0.0}[name]
        return q * density(u) * 2.0 * s

    u_top = max(-d, 0.0) + 12.0
    points = {0.0, u_top, jg.u_c, jg.u_x, jg.u_t, *jg.hk_breaks()}
    if -d > 0:
        points |= {max(-d - 4.0, 0.0), -d, -d + 4.0}
    edges = sorted(math.sqrt(p) for p in points if 0.0 <= p <= u_top)
    out = {}
    for name in names:
        total = 0.0
        for lo, hi in zip(edges[:-1], edges[1:], strict=True):
            if hi > lo:
                total += integrate.quad(integrand, lo, hi, args=(name,), epsabs=0.0, epsrel=1e-12, limit=400)[0]
        out[name] = total
    return out


def jg_separation_point(d, alpha, beta, nu, H_over_E, h_star=0.0, *, tau_f1=1 / 43, tau_f2=1 / 43 / 30, a1=28.0,
                        a2=8e4):
    """Contacts, P, F, area and the plastic fraction per asperity at separation ``d`` (Eqs 5, 6, 10, 21).

    ``plastic`` is the fraction of all asperities past the critical interference; it is also
    checked here against its closed form ``ndtr(-(d + u_c))`` by the tests.

    Returns
    -------
    dict
        Float values under ``'contacts'``, ``'P'``, ``'F'``, ``'area'``, ``'plastic'``.
    """
    jg = _make(alpha, beta, nu, H_over_E, h_star, tau_f1, tau_f2, a1, a2)
    return _integrate(finite("d", d), jg, _NAMES)


def jg_load_point(P, alpha, beta, nu, H_over_E, h_star=0.0, *, tau_f1=1 / 43, tau_f2=1 / 43 / 30, a1=28.0, a2=8e4):
    """The separation carrying the load ``P > 0`` per asperity, and the quantities there.

    ``P_bar(d)`` decreases strictly (no adhesion): bracket by expansion, refine with ``brentq``.

    Returns
    -------
    dict
        ``'d'`` plus the keys of :func:`jg_separation_point`.
    """
    P = positive("P", P)
    jg = _make(alpha, beta, nu, H_over_E, h_star, tau_f1, tau_f2, a1, a2)

    def g(d):
        return _integrate(d, jg, ("P",))["P"] - P

    lo, hi = -1.0, 1.0
    while g(lo) <= 0:
        lo -= 2.0
    while g(hi) > 0:
        hi += 2.0
    d = optimize.brentq(g, lo, hi, xtol=1e-14, rtol=1e-15, maxiter=200)
    out = {"d": float(d)}
    out.update(_integrate(d, jg, _NAMES))
    return out
