r"""The Jackson-Green elastic-plastic asperity law: its spec (:class:`JacksonGreen`) and the law in the model's units.

:class:`JacksonGreen` is what a user gives (``Model(..., law=JacksonGreen(H_over_E=...))``,
``--law jackson-green``): the hardness over the contact modulus and the optional Nix-Gao
size effect, checked.  :class:`JacksonGreenLaw` is the per-asperity law it builds for a
model (a :class:`~asperity.asperity_law.ContactLaw`): Hertz below yield, the Jackson-Green
fits of the contact area and load above it (:mod:`asperity.jackson_green_fits`), the
Nix-Gao size effect on the critical interference (:mod:`asperity.nix_gao`).  The registry
of laws, :func:`~asperity.elastic_plastic.make_law`, the critical penetration and the
plastic fraction are in :mod:`asperity.elastic_plastic`, which re-exports both classes;
docs/plasticity.md has the equations and the choices.

References
----------
.. [1] R. L. Jackson, I. Green, J. Tribol. 127 (2005) 343-354.
.. [2] W. D. Nix, H. Gao, J. Mech. Phys. Solids 46 (1998) 411-425.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from scipy import optimize

from ._validation import (
    as_float_array,
    check_scalar_real,
    check_scalar_sign,
)
from .asperity_law import AsperityLaw, ModelParameters
from .heights import GAUSSIAN, HeightDistribution
from .jackson_green import E_Y_MAX, OMEGA_T, jg_yield_coefficient, jg_yield_from_hardness
from .jackson_green_fits import OMEGA_STAR_MAX, jg_area_fit, jg_load_fit, jg_load_transition
from .nix_gao import ng_interference, ng_scaled_interference
from .tabulation import D_MAX, D_MIN

__all__ = ["JacksonGreen", "JacksonGreenLaw"]


@dataclass(frozen=True)
class JacksonGreen:
    r"""The Jackson-Green elastic-plastic law (a law spec), with the optional Nix-Gao size effect.

    Parameters
    ----------
    H_over_E : float
        Hardness over composite modulus :math:`H/E^*`, :math:`0 < H/E^* \le 0.142` (yield
        strain :math:`S_y/E^* = (H/E^*)/2.84 \le 0.05`); with the size effect, :math:`H_0/E^*`.
    h_star_over_sigma : float
        Nix-Gao length over the summit-height deviation, :math:`h^*/\sigma \ge 0`; 0 (default)
        turns the size effect off.

    Examples
    --------
    >>> from asperity import Model
    >>> m = Model(0.05, 1000.0, law=JacksonGreen(H_over_E=0.005))
    >>> c = m.load_curve([1e3])
    >>> bool(0 < c.plastic[0] <= c.contacts[0])
    True
    """

    H_over_E: float
    h_star_over_sigma: float = 0.0
    name: ClassVar[str] = "jackson-green"
    plastic: ClassVar[bool] = True

    def __post_init__(self):
        H = check_scalar_real(self.H_over_E, "H_over_E")
        if not 0.0 < H or H / 2.84 > E_Y_MAX:
            raise ValueError(f"H_over_E (hardness H/E*) must lie in (0, {E_Y_MAX * 2.84:.3g}] for the Jackson-Green "
                             f"law (yield strain S_y/E* = H/(2.84 E*) <= {E_Y_MAX:g}), got {self.H_over_E!r}")
        object.__setattr__(self, "H_over_E", H)
        object.__setattr__(self, "h_star_over_sigma",
                           check_scalar_sign(self.h_star_over_sigma, "h_star_over_sigma", positive=False))

    def contact_law(self, params: ModelParameters) -> JacksonGreenLaw:
        """The :class:`JacksonGreenLaw` for ``params``."""
        return JacksonGreenLaw(params, self.H_over_E, self.h_star_over_sigma)


class JacksonGreenLaw:
    r"""The Jackson-Green elastic-plastic asperity in the model's units (a :class:`~asperity.asperity_law.ContactLaw`).

    Hertz below the transitions (exactly :class:`~asperity.asperity_law.AsperityLaw` without
    adhesion), Jackson & Green's area and load fits above; see the module docstring.

    Parameters
    ----------
    params : ModelParameters
        The model's parameters; :math:`\gamma` must be 0 and :math:`0 \le \nu < 0.5`.
    H_over_E : float
        Hardness :math:`H/E^*` (:math:`H_0/E^*` with the size effect), in (0, 0.142].
    h_star_over_sigma : float
        Nix-Gao length :math:`h^*/\sigma \ge 0` (default 0: no size effect).

    Attributes
    ----------
    params, u_end, scale, breakpoints :
        As in :class:`~asperity.asperity_law.ContactLaw` (:math:`\bar u_{end} = 0`).
    u_c : float
        Critical penetration :math:`\omega_c/\sigma` (yield starts; :math:`\omega^* = 1`).
    u_x, u_t : float
        Penetrations where the load (:math:`\omega^*_x`) and the area (:math:`\omega^* = 1.9`)
        leave Hertz.
    omega_x : float
        :math:`\omega^*_x`, the load's switch in units of the (local) critical interference.

    Raises
    ------
    ValueError
        If :math:`\gamma > 0` (no consistent adhesion with a plastic core), :math:`\nu` lies
        outside [0, 0.5), an input is out of range, or with the size effect the yield strain
        at the onset of yield exceeds 0.05 (outside the fits).
    """

    name = "jackson-green"

    def __init__(self, params: ModelParameters, H_over_E, h_star_over_sigma=0.0):
        if not isinstance(params, ModelParameters):
            raise ValueError(f"params must be ModelParameters, got {type(params).__name__}")
        if params.adhesive:
            raise ValueError(
                f"the Jackson-Green law has no adhesion: gamma must be 0, got gamma={params.gamma:g}.  The model's "
                "adhesion (Maugis-Dugdale) assumes an elastic sphere; with a plastic core its contact radius and "
                "adhesive zone have no consistent counterpart, so the combination is refused")
        if not 0.0 <= params.nu < 0.5:
            raise ValueError(f"nu (Poisson's ratio) must lie in [0, 0.5) for the Jackson-Green law "
                             f"(C(nu) is fitted there), got {params.nu:g}")
        spec = JacksonGreen(H_over_E, h_star_over_sigma)  # validates
        self.params = params
        self.H_over_E, self.h_star = spec.H_over_E, spec.h_star_over_sigma
        self._elastic = AsperityLaw(params)  # Hertz, with the scale checks and the friction law
        self.u_end, self.scale = 0.0, 1.0
        self.C = float(jg_yield_coefficient(params.nu))
        self.e_y0 = float(jg_yield_from_hardness(self.H_over_E))
        with np.errstate(all="ignore"):
            self.u_c0 = float((0.5 * np.pi * self.C * np.float64(self.e_y0)) ** 2 / np.float64(params.alpha) ** 2)
        # the separations reach D_MIN (1e4 sigma) and the fits hold to omega* = OMEGA_STAR_MAX: u_c >= 1e-8 sigma
        u_c_min = (D_MAX - D_MIN) / OMEGA_STAR_MAX
        if not u_c_min <= self.u_c0 < math.inf:
            raise ValueError(f"H_over_E = {self.H_over_E:g} with alpha = {params.alpha:g} gives a critical "
                             f"interference omega_c/sigma_s = {self.u_c0:.3g}, outside [{u_c_min:g}, inf) where the "
                             f"Jackson-Green fits cover the model's separations (omega/omega_c <= {OMEGA_STAR_MAX:g})")
        self.u_c = float(ng_interference(1.0, self.u_c0, self.h_star))
        e_y_max = float(self._e_y(np.array([self.u_c]))[0])
        if e_y_max > E_Y_MAX:
            raise ValueError(f"with the size effect the yield strain at the onset of yield, {e_y_max:.3g}, exceeds "
                             f"{E_Y_MAX:g} (outside the Jackson-Green fits): lower h_star_over_sigma "
                             f"({self.h_star:g}) or H_over_E ({self.H_over_E:g})")
        self.omega_x = self._load_switch()
        self.u_x = float(ng_interference(self.omega_x, self.u_c0, self.h_star))
        self.u_t = float(ng_interference(OMEGA_T, self.u_c0, self.h_star))
        #: Hertz force per asperity over u^(3/2): P/(G b^2) = pc_scale * u^(3/2).
        self.pc_scale = (8.0 / 3.0) / (1.0 - params.nu) * params.alpha * params.beta**2
        self.breakpoints = tuple(sorted({self.u_c, self.u_x, self.u_t, *self._friction_breakpoints()}))

    def __repr__(self) -> str:
        return f"JacksonGreenLaw(H_over_E={self.H_over_E!r}, h_star_over_sigma={self.h_star!r})"

    def parameters(self) -> dict:
        """The law's name and options (recorded with a curve's parameters)."""
        return {"law": self.name, "H_over_E": self.H_over_E, "h_star_over_sigma": self.h_star}

    # -- the size effect ----------------------------------------------------------------
    def _e_y(self, u):
        """Local yield strain S_y/E* at penetrations u > 0."""
        if self.h_star == 0.0:
            return np.full(np.shape(u), self.e_y0)
        return self.e_y0 * np.sqrt(1.0 + self.h_star / u)

    def _load_switch(self) -> float:
        """omega*_x: where the load fit (with the local yield strain) falls below Hertz."""
        if self.h_star == 0.0:
            return float(jg_load_transition(self.e_y0, self.params.nu))
        nu = self.params.nu

        def gap(w):
            u = ng_interference(w, self.u_c0, self.h_star)
            return jg_load_fit(w, self._e_y(u), nu) - np.asarray(w) ** 1.5

        grid = np.linspace(1.0, 8.0, 141)
        values = gap(grid)
        below = np.flatnonzero(values <= 0.0)
        if values[0] <= 0.0 or below.size == 0:
            raise ValueError(f"the Jackson-Green load fit does not cross Hertz above yield for H_over_E = "
                             f"{self.H_over_E:g}, h_star_over_sigma = {self.h_star:g}, nu = {nu:g}")
        k = int(below[0])
        return float(optimize.brentq(lambda w: float(gap(w)), grid[k - 1], grid[k], xtol=1e-15,
                                     rtol=4 * np.finfo(float).eps))

    # -- the law ----------------------------------------------------------------------------
    def _radius(self, u: float) -> float:
        """Contact radius a/b at one penetration u > u_t (JG's area fit)."""
        w = float(ng_scaled_interference(u, self.u_c0, self.h_star))
        return self.params.beta * float(np.sqrt(u / w * jg_area_fit(w, float(self._e_y(np.array([u]))[0]))))

    def _friction_breakpoints(self) -> tuple[float, ...]:
        r"""Penetrations where the law's radius crosses the friction law's breakpoint radii.

        Below the area's switch the radius is Hertz's, :math:`\bar u = (\bar a_k/\beta)^2`; above,
        the law's radius exceeds Hertz's, so the crossing lies in :math:`[\bar u_t, (\bar a_k/\beta)^2]`.
        A crossing beyond the deepest penetration the model reaches, :data:`D_MAX` - :data:`D_MIN`,
        is left out (a breakpoint radius larger than any contact of these asperities: e.g. the
        Hurtado-Kim radius :math:`a_2 b` of 23 um on nanometre summits).
        """
        beta, reach = self.params.beta, D_MAX - D_MIN
        out = []
        for a_k in self.params.friction.breakpoints():
            u_hertz = (a_k / beta) ** 2
            if u_hertz <= self.u_t:
                out.append(u_hertz)
                continue
            top = min(u_hertz, reach)
            if self._radius(top) < a_k:
                continue
            out.append(float(optimize.brentq(lambda u, a_k=a_k: self._radius(u) - a_k, self.u_t, top,
                                             xtol=1e-15 * top, rtol=4 * np.finfo(float).eps)))
        return tuple(out)

    def evaluate(self, u_bar):
        """Contact radius :math:`\\bar a` and force :math:`P/(Gb^2)` at penetrations ``u_bar``.

        Hertz (:class:`~asperity.asperity_law.AsperityLaw`) where the area and load have not
        left it; Jackson & Green's fits beyond :math:`\\bar u_t` (area) and :math:`\\bar u_x`
        (load).  Non-positive penetrations give zero.
        """
        u = as_float_array(u_bar, "u_bar", allow_empty=True)
        a, P = self._elastic.evaluate(u)
        on = u > min(self.u_x, self.u_t)
        if np.any(on):
            uu = u[on]
            w = ng_scaled_interference(uu, self.u_c0, self.h_star)
            e_y = self._e_y(uu)
            u_c = uu / w  # local critical penetration
            area_on = uu > self.u_t
            if np.any(area_on):
                a_on = a[on]
                a_on[area_on] = self.params.beta * np.sqrt(u_c[area_on] * jg_area_fit(w[area_on], e_y[area_on]))
                a[on] = a_on
            load_on = uu > self.u_x
            if np.any(load_on):
                P_on = P[on]
                P_on[load_on] = (self.pc_scale * u_c[load_on] ** 1.5
                                 * jg_load_fit(w[load_on], e_y[load_on], self.params.nu))
                P[on] = P_on
        return a, P

    def friction(self, a_bar):
        """Friction force :math:`F_f/(Gb^2) = 2\\pi\\bar\\tau_f\\bar a^2` (Eq 10 integrand)."""
        return self._elastic.friction(a_bar)

    def plastic_fraction(self, d, heights: HeightDistribution = GAUSSIAN):
        """Fraction of all asperities past the critical interference at separations ``d``
        (:func:`~asperity.elastic_plastic.plastic_fraction` with :attr:`u_c`)."""
        from .elastic_plastic import plastic_fraction  # that module imports this one

        return plastic_fraction(d, self.u_c, heights)
