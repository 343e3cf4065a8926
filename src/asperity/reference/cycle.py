"""Reference for :mod:`asperity.cycle`: approach and retraction points, the loop energy and the
pull-off on retraction, written from the definitions only.

With ``u = z - d`` the penetration of an asperity of height ``z`` at separation ``d``,
``u_end < 0`` the end of its stable Maugis-Dugdale branch and ``u_in`` (``u_end <= u_in <= 0``)
the penetration at which an approaching asperity jumps into contact:

* approach to ``d``: the asperities with ``z >= d + u_in`` touch;
* retraction to ``d >= d_min`` after the closest approach ``d_min``: those with
  ``z >= max(d + u_end, d_min + u_in)``;

each carries the stable-branch Maugis-Dugdale force of its penetration (Hertz without
adhesion), solved per asperity by root finding in multiple precision
(:func:`~asperity.reference.maugis_dugdale_branch.branch_point_offset`), and the integrals over
``z`` (the Gaussian density, or any of :mod:`.heights` for the points) are adaptive
Gauss-Kronrod quadrature (:func:`scipy.integrate.quad`, ``epsrel=1e-11``) in ``s`` with
``u = u_end + s**2``, split at the Hurtado-Kim radii, the sign changes of the per-asperity
load and where the density changes (a mixture's narrow component).  Nothing is tabulated;
nothing is shared with the fast path.

The energy dissipated over a cycle ``d_max -> d_min -> d_max`` (:func:`cycle_energy`) is summed
asperity by asperity: each one that touched dissipates the work of its own force over the part
of its loop it went through.
"""

from __future__ import annotations

import math

from scipy import integrate, optimize, special

from .common import finite
from .friction_stress import hk_tau
from .maugis_dugdale_branch import branch_D_for_A, branch_end, branch_P_zeros, branch_point_offset
from .multi_asperity import Params

__all__ = ["approach_point", "retract_point", "cycle_energy", "retract_pull_off", "branch_end_penetration"]

_SQRT2PI = math.sqrt(2.0 * math.pi)
_EPSREL = 1e-11
_LIMIT = 400
_Z_TAIL = 12.0
_NAMES = ("contacts", "P", "F", "area")


def _params(alpha, beta, gamma, nu, h_over_b):
    return Params(alpha, beta, gamma, nu, h_over_b, 1 / 43, 1 / 43 / 30, 28.0, 8e4)


class _Asperity:
    """One asperity's radius a/b and force P/(G b^2) against ``v = u - u_end >= 0``."""

    def __init__(self, p):
        self.p = p
        if p.gamma == 0.0:
            self.u_end = 0.0
            self.v_breaks = [(p.a1 / p.beta) ** 2, (p.a2 / p.beta) ** 2]
            self.v_zeros = []
        else:
            self.lam = p.lam
            self.u_end = float(p.delta_hat * branch_end(p.lam)[2])
            self.v_breaks = [p.delta_hat * float(v) for v in
                             (branch_D_for_A(p.lam, a * p.A_hat) for a in (p.a1, p.a2)) if v is not None]
            self.v_zeros = [p.delta_hat * float(v) for v in branch_P_zeros(p.lam)]

    def at(self, v):
        p = self.p
        if p.gamma == 0.0:
            return p.beta * math.sqrt(v), p.hertz_pref * v**1.5
        A, P = branch_point_offset(self.lam, v / p.delta_hat)
        return A / p.A_hat, P / p.P_hat

    def column(self, name, v):
        a, P = self.at(v)
        if name == "contacts":
            return 1.0
        if name == "P":
            return P
        if name == "area":
            return a * a
        p = self.p  # friction, Eq 10's integrand
        return 2.0 * math.pi * hk_tau(a, tau_f1=p.tau_f1, tau_f2=p.tau_f2, a1=p.a1, a2=p.a2) * a * a


def _quad(f, points):
    total = 0.0
    for lo, hi in zip(points[:-1], points[1:], strict=True):
        val, err, _, *msg = integrate.quad(f, lo, hi, epsabs=0.0, epsrel=_EPSREL, limit=_LIMIT, full_output=1)
        if msg and err > 1e-8 * abs(val) and err > 1e-300:
            raise ArithmeticError(f"quadrature failed: {msg[0]} (err={err:g})")
        total += val
    return total


def _marks(dens):
    """Heights where a density changes: ``(-6, -3, 0, 3, 6)`` for the Gaussian; else its support
    edges, unit steps through its bulk and each Gaussian component's centre and +-1, 3, 6 widths
    (a narrow component of a mixture)."""
    if dens is None:
        return [-6.0, -3.0, 0.0, 3.0, 6.0]
    marks = [*dens.breaks(), *range(math.ceil(max(dens.z_bottom, -12.0)), math.floor(min(dens.z_top, 12.0)) + 1)]
    components = getattr(dens, "components", None)
    if components is not None:
        for m, sd in zip(components[1], components[2], strict=True):
            marks += [float(m) + k * float(sd) for k in (-6, -3, -1, 0, 1, 3, 6)]
    return [float(z) for z in marks]


def _integrals(d, asp, u_lo, u_hi=math.inf, names=_NAMES, dens=None):
    """``int_{u_lo}^{u_hi} q(u) phi(d + u) du`` for each quantity, in ``s`` with ``u = u_end + s^2``;
    ``phi`` the standard Gaussian, or the density ``dens`` (a RefDensity of .heights)."""
    s_lo = math.sqrt(max(u_lo - asp.u_end, 0.0))
    if math.isinf(u_hi):  # truncated where the density is negligible
        u_hi = max(-d, 0.0) + _Z_TAIL if dens is None else min(dens.z_top, dens.hi) - d
    s_hi = math.sqrt(max(u_hi - asp.u_end, 0.0))
    if not s_hi > s_lo:
        return dict.fromkeys(names, 0.0)
    z0 = d + asp.u_end
    extra = [math.sqrt(zk - z0) for zk in _marks(dens) if zk > z0]
    cuts = [math.sqrt(v) for v in asp.v_breaks + asp.v_zeros] + extra
    points = sorted({s_lo, s_hi, *[s for s in cuts if s_lo < s < s_hi]})
    pdf = (lambda z: math.exp(-0.5 * z * z) / _SQRT2PI) if dens is None else dens.pdf

    def weight(s):
        return 2.0 * s * pdf(z0 + s * s)

    return {name: _quad(lambda s, name=name: weight(s) * asp.column(name, s * s), points) for name in names}


def branch_end_penetration(alpha, beta, gamma=0.0, *, nu=0.3, h_over_b=1.0):
    """``u_end``: the end of the stable branch in sigma (0 without adhesion)."""
    return _Asperity(_params(alpha, beta, gamma, nu, h_over_b)).u_end


def _u_in(asp, u_in):
    u_in = finite("u_in", u_in)
    if not asp.u_end <= u_in <= 0.0:
        raise ValueError(f"u_in must lie in [{asp.u_end!r}, 0], got {u_in!r}")
    return u_in


def approach_point(d, alpha, beta, gamma=0.0, *, u_in=0.0, nu=0.3, h_over_b=1.0, heights=None):
    """Contacts, P, F and area per asperity on approach to ``d``: ``z >= d + u_in`` touch.

    ``heights``: None (Gaussian) or a :class:`~asperity.reference.heights.RefDensity`.

    Returns
    -------
    dict
        Floats under ``'contacts'``, ``'P'``, ``'F'``, ``'area'``.
    """
    d = finite("d", d)
    asp = _Asperity(_params(alpha, beta, gamma, nu, h_over_b))
    return _integrals(d, asp, _u_in(asp, u_in), dens=heights)


def retract_point(d, d_min, alpha, beta, gamma=0.0, *, u_in=0.0, nu=0.3, h_over_b=1.0, heights=None):
    """Contacts, P, F and area per asperity on retraction to ``d >= d_min`` after the closest
    approach ``d_min``: ``z >= max(d + u_end, d_min + u_in)`` touch.

    ``heights``: None (Gaussian) or a :class:`~asperity.reference.heights.RefDensity`.

    Returns
    -------
    dict
        Floats under ``'contacts'``, ``'P'``, ``'F'``, ``'area'``.
    """
    d, d_min = finite("d", d), finite("d_min", d_min)
    if d < d_min:
        raise ValueError(f"d must be >= d_min, got d={d!r}, d_min={d_min!r}")
    asp = _Asperity(_params(alpha, beta, gamma, nu, h_over_b))
    u_in = _u_in(asp, u_in)
    return _integrals(d, asp, max(asp.u_end, d_min + u_in - d), dens=heights)


def cycle_energy(d_min, d_max, alpha, beta, gamma, *, u_in=0.0, nu=0.3, h_over_b=1.0):
    """Energy dissipated per cycle ``d_max -> d_min -> d_max`` per asperity (N G b^2 sigma).

    Asperity by asperity: the one at height ``z`` touched if ``z >= d_min + u_in`` and, stuck on
    retraction, went from penetration ``u_in`` down to ``max(u_end, z - d_max)`` (where it
    snapped off, or where the cycle ended), dissipating ``-int P(u) du`` over that stretch (its
    force on approach retraced the rest).  Summed over the heights, with the order of
    integration exchanged (the asperities that pass through ``u`` while stuck are those with
    ``d_min + u_in <= z <= d_max + u``):

        E = -int_{u_c}^{u_in} P(u) [Q(d_min + u_in) - Q(d_max + u)] du,
        u_c = max(u_end, u_in - (d_max - d_min)),

    ``Q`` the Gaussian survival function, by adaptive quadrature in ``s`` (``u = u_end + s^2``).
    """
    d_min, d_max = finite("d_min", d_min), finite("d_max", d_max)
    if not d_min < d_max:
        raise ValueError(f"d_min must be < d_max, got {d_min!r}, {d_max!r}")
    asp = _Asperity(_params(alpha, beta, gamma, nu, h_over_b))
    u_in = _u_in(asp, u_in)
    u_c = max(asp.u_end, u_in - (d_max - d_min))
    if u_c >= u_in:
        return 0.0
    s_lo, s_hi = math.sqrt(u_c - asp.u_end), math.sqrt(u_in - asp.u_end)
    cuts = [math.sqrt(v) for v in asp.v_breaks + asp.v_zeros]
    points = sorted({s_lo, s_hi, *[s for s in cuts if s_lo < s < s_hi]})
    touched = special.ndtr(-(d_min + u_in))

    def f(s):
        u = asp.u_end + s * s
        return 2.0 * s * asp.at(s * s)[1] * (touched - special.ndtr(-(d_max + u)))

    return -_quad(f, points)


def retract_pull_off(d_min, d_max, alpha, beta, gamma, *, u_in=0.0, nu=0.3, h_over_b=1.0, step=0.05):
    """Most tensile retraction force on ``[d_min, d_max]``: a scan every ``step`` (and at the end of
    the transition zone), then bounded Brent minimisation around the best point.

    Returns
    -------
    dict
        ``{'pull_off': max(0, -P_min), 'd': where}``.
    """
    d_min, d_max = finite("d_min", d_min), finite("d_max", d_max)
    asp = _Asperity(_params(alpha, beta, gamma, nu, h_over_b))
    u_in = _u_in(asp, u_in)

    def P(d):
        return _integrals(d, asp, max(asp.u_end, d_min + u_in - d), names=("P",))["P"]

    n = max(2, int(math.ceil((d_max - d_min) / step)) + 1)
    grid = sorted({d_min + (d_max - d_min) * i / (n - 1) for i in range(n)}
                  | ({d_min + u_in - asp.u_end} if d_min + u_in - asp.u_end < d_max else set()))
    vals = [P(x) for x in grid]
    i = min(range(len(grid)), key=vals.__getitem__)
    best_d, best_P = grid[i], vals[i]
    if 0 < i < len(grid) - 1:
        res = optimize.minimize_scalar(P, bounds=(grid[i - 1], grid[i + 1]), method="bounded",
                                       options={"xatol": 1e-9, "maxiter": 200})
        if res.fun < best_P:
            best_d, best_P = float(res.x), float(res.fun)
    return {"pull_off": max(0.0, -best_P), "d": best_d}
