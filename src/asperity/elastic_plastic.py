r"""Per-asperity laws selectable by name: the paper's elastic law and the Jackson-Green elastic-plastic law.

:data:`LAWS` maps a name to a *law spec*, a small frozen dataclass holding the material's
plasticity in dimensionless form; ``spec.contact_law(params)`` builds the
:class:`~asperity.asperity_law.ContactLaw` that :class:`~asperity.curves.Model` integrates:

=================  ============================  =============================================
name               spec                          per-asperity law
=================  ============================  =============================================
``elastic``        :class:`Elastic`              Hertz or Maugis-Dugdale (the paper's, default)
``jackson-green``  :class:`JacksonGreen`         :class:`JacksonGreenLaw`, no adhesion
=================  ============================  =============================================

**Jackson-Green in the model's units.**  With :math:`\bar u = \omega/\sigma`,
:math:`\alpha = (\sigma/R)^{1/2}`, the hardness :math:`H/E^*` and :math:`e_y = S_y/E^* =
(H/E^*)/2.84` (:func:`~asperity.jackson_green.jg_yield_from_hardness`):

.. math::
    \bar u_{c0} = \frac{\omega_{c0}}{\sigma} = \frac{(\pi C e_y/2)^2}{\alpha^2},\qquad
    \bar a_c^2 = \beta^2\bar u_c,\qquad
    \frac{P_c}{Gb^2} = \frac43\frac{2}{1-\nu}\alpha\beta^2\bar u_c^{3/2},

(the Hertz radius and force at :math:`\bar u_c`), so :math:`\bar a = \beta(\bar u_c\,A/A_c)^{1/2}`
and :math:`P/(Gb^2) = (P_c/Gb^2)(P/P_c)` with :math:`A/A_c` and :math:`P/P_c` of
:func:`~asperity.jackson_green_fits.jg_area` and :func:`~asperity.jackson_green_fits.jg_load` at
:math:`\omega^* = \bar u/\bar u_c`.  The plasticity index of Greenwood and Williamson,
:math:`\psi = (E^*/H)(\sigma/R)^{1/2} = \alpha/(H/E^*)`, gives
:math:`\bar u_{c0} = (\pi C/(2\cdot2.84))^2/\psi^2`.

**Size effect** (:mod:`asperity.nix_gao`): with the Nix-Gao length :math:`h^*/\sigma > 0` the
hardness at penetration :math:`\bar u` is :math:`H\sqrt{1 + h^*/(\sigma\bar u)}`, so
:math:`\bar u_c(\bar u) = \bar u_{c0}(1 + h^*/\sigma\bar u)`, :math:`e_y(\bar u) = e_{y0}
\sqrt{1 + h^*/\sigma\bar u}` and :math:`\omega^* = \bar u/\bar u_c(\bar u)`; with
:math:`h^* = 0` the law is the plain one.

**Regime boundaries** (:attr:`JacksonGreenLaw.breakpoints`): the critical interference
:math:`\bar u_c` (:math:`\omega^* = 1`, yield starts; the *plastic fraction* counts
asperities beyond it), the load's switch :math:`\bar u_x` (:math:`\omega^*_x`,
:func:`~asperity.jackson_green_fits.jg_load_transition`), the area's switch :math:`\bar u_t`
(:math:`\omega^* = 1.9`), and the Hurtado-Kim radii mapped through the law's radius.

**Adhesion.**  The Jackson-Green law has none: it needs :math:`\gamma = 0`.  The model's
adhesion is Maugis-Dugdale, whose contact radius and adhesive zone come from the elastic
half-space solution; with a plastic core they have no consistent counterpart, so the
combination raises :class:`ValueError` instead of guessing (docs/plasticity.md).

References
----------
.. [1] R. L. Jackson, I. Green, J. Tribol. 127 (2005) 343-354.
.. [2] J. A. Greenwood, J. B. P. Williamson, Proc. R. Soc. A 295 (1966) 300-319
   (plasticity index).
.. [3] W. D. Nix, H. Gao, J. Mech. Phys. Solids 46 (1998) 411-425.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
from scipy import optimize

from ._validation import as_float_array, check_finite_result, check_nonnegative, check_positive, scalar
from .asperity_law import AsperityLaw, ModelParameters
from .heights import GAUSSIAN, HeightDistribution
from .jackson_green import E_Y_MAX, OMEGA_T, jg_yield_coefficient, jg_yield_from_hardness
from .jackson_green_fits import OMEGA_STAR_MAX, jg_area_fit, jg_load_fit, jg_load_transition
from .nix_gao import ng_interference, ng_scaled_interference
from .tabulation import D_MAX, D_MIN

__all__ = [
    "Elastic",
    "JacksonGreen",
    "JacksonGreenLaw",
    "LAWS",
    "make_law",
    "critical_penetration",
    "plastic_fraction",
]


def _scalar(value, name: str, *, positive: bool) -> float:
    check = check_positive if positive else check_nonnegative
    return float(scalar(check(value, name), name))


def critical_penetration(alpha, nu, H_over_E, h_star_over_sigma=0.0) -> float:
    r"""Penetration at which an asperity starts to yield, :math:`\bar u_c = \omega_c/\sigma`.

    .. math::
        \bar u_{c0} = \frac{(\pi C e_y/2)^2}{\alpha^2},\quad e_y = \frac{H/E^*}{2.84},\quad
        C = 1.295\,e^{0.736\nu};\qquad
        \bar u_c = \bar u_{c0}\,\frac{1 + \sqrt{1 + 4(h^*/\sigma)/\bar u_{c0}}}{2}

    Jackson & Green's critical interference in units of :math:`\sigma`, with the
    self-consistent Nix-Gao size effect (:func:`~asperity.nix_gao.ng_critical_interference`).

    Parameters
    ----------
    alpha : float
        Roughness :math:`\alpha = (\sigma/R)^{1/2} > 0` (Eq 7).
    nu : float
        Poisson's ratio, :math:`0 \le \nu < 0.5` (the range of JG's :math:`C(\nu)`).
    H_over_E : float
        Hardness over composite modulus :math:`H/E^* > 0` (:math:`H_0/E^*` with the size effect).
    h_star_over_sigma : float
        Nix-Gao length over :math:`\sigma`, :math:`h^*/\sigma \ge 0` (0: no size effect).

    Returns
    -------
    float
        :math:`\bar u_c > 0`.

    Raises
    ------
    ValueError
        If an input is not a real finite scalar in its range.

    Examples
    --------
    >>> psi = 0.01 / 0.002  # plasticity index alpha / (H/E*)
    >>> u_c = critical_penetration(0.01, 0.3, 0.002)
    >>> C = 1.295 * 2.718281828459045 ** (0.736 * 0.3)
    >>> round(u_c * psi**2 / (3.141592653589793 * C / (2 * 2.84)) ** 2, 12)
    1.0

    References
    ----------
    Jackson & Green (2005), critical interference; Greenwood & Williamson (1966); Nix & Gao (1998).
    """
    alpha = _scalar(alpha, "alpha", positive=True)
    H = _scalar(H_over_E, "H_over_E", positive=True)
    h = _scalar(h_star_over_sigma, "h_star_over_sigma", positive=False)
    C = float(jg_yield_coefficient(float(scalar(as_float_array(nu, "nu"), "nu"))))
    with np.errstate(all="ignore"):
        u_c0 = (0.5 * np.pi * C * np.float64(H) / 2.84) ** 2 / np.float64(alpha) ** 2
        if not 0.0 < u_c0 < math.inf:  # under- or overflow
            raise ValueError(f"the critical penetration leaves double precision for alpha = {alpha!r}, "
                             f"H_over_E = {H!r}: give values of physical size")
        u_c = ng_interference(1.0, u_c0, h)
    return float(check_finite_result(u_c, "the critical penetration", alpha=alpha, H_over_E=H,
                                     h_star_over_sigma=h))


def plastic_fraction(d, u_c, heights: HeightDistribution = GAUSSIAN):
    r"""Fraction of all asperities past the critical interference, :math:`n_p/N = \int_{\bar d + \bar u_c}^\infty\phi`.

    .. math::
        \frac{n_p}{N} = \int_{\bar d + \bar u_c}^\infty \phi(\bar z)\,d\bar z

    Parameters
    ----------
    d : array_like
        Separations :math:`d/\sigma`, finite.
    u_c : float
        Critical penetration :math:`\bar u_c = \omega_c/\sigma > 0` (:func:`critical_penetration`).
    heights : HeightDistribution
        Asperity heights (default Gaussian, Eq 19).

    Returns
    -------
    ndarray
        :math:`n_p/N` in [0, 1], the shape of ``d``.

    Raises
    ------
    ValueError
        If ``d`` or ``u_c`` is not real and finite or ``u_c <= 0``.

    Examples
    --------
    >>> round(float(plastic_fraction(-1.0, 1.0)), 12)  # asperities above the mean height
    0.5

    References
    ----------
    Greenwood & Williamson (1966); Adams et al., Eq (5).
    """
    d = as_float_array(d, "d", allow_empty=True)
    u_c = _scalar(u_c, "u_c", positive=True)
    if not isinstance(heights, HeightDistribution):
        raise ValueError("heights must be a HeightDistribution (e.g. asperity.GAUSSIAN)")
    return np.asarray(heights.sf(d + u_c), dtype=float)


@dataclass(frozen=True)
class Elastic:
    """The paper's per-asperity law: Hertz, or Maugis-Dugdale with adhesion (a law spec)."""

    name: ClassVar[str] = "elastic"
    plastic: ClassVar[bool] = False

    def contact_law(self, params: ModelParameters) -> AsperityLaw:
        """The :class:`~asperity.asperity_law.AsperityLaw` for ``params``."""
        return AsperityLaw(params)


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
        H = _scalar(self.H_over_E, "H_over_E", positive=True)
        if H / 2.84 > E_Y_MAX:
            raise ValueError(f"H_over_E (hardness H/E*) must lie in (0, {E_Y_MAX * 2.84:.3g}] for the Jackson-Green "
                             f"law (yield strain S_y/E* = H/(2.84 E*) <= {E_Y_MAX:g}), got {self.H_over_E!r}")
        object.__setattr__(self, "H_over_E", H)
        object.__setattr__(self, "h_star_over_sigma",
                           _scalar(self.h_star_over_sigma, "h_star_over_sigma", positive=False))

    def contact_law(self, params: ModelParameters) -> JacksonGreenLaw:
        """The :class:`JacksonGreenLaw` for ``params``."""
        return JacksonGreenLaw(params, self.H_over_E, self.h_star_over_sigma)


#: Law name -> law spec class (command-line choices read it).
LAWS = {"elastic": Elastic, "jackson-green": JacksonGreen}


def make_law(name: str, *, H_over_E=None, h_star_over_sigma=None):
    r"""The law spec called ``name`` in :data:`LAWS`, with its options.

    Parameters
    ----------
    name : str
        ``'elastic'`` or ``'jackson-green'`` (case-insensitive).
    H_over_E : float, optional
        Hardness :math:`H/E^*` (needed by, and only by, ``'jackson-green'``).
    h_star_over_sigma : float, optional
        Nix-Gao length :math:`h^*/\sigma` (``'jackson-green'`` only; default 0).

    Returns
    -------
    Elastic or JacksonGreen

    Raises
    ------
    ValueError
        For an unknown name (the message lists the known ones), a missing hardness, or
        options the law does not take.

    Examples
    --------
    >>> make_law("jackson-green", H_over_E=0.01)
    JacksonGreen(H_over_E=0.01, h_star_over_sigma=0.0)

    References
    ----------
    Jackson & Green (2005); Nix & Gao (1998); docs/plasticity.md.
    """
    if not isinstance(name, str):
        raise TypeError(f"name (the per-asperity law) must be a string, one of {', '.join(LAWS)}; got {name!r}")
    key = name.strip().lower()
    if key not in LAWS:
        raise ValueError(f"name: unknown law {name!r}; known: {', '.join(LAWS)}")
    if key == "elastic":
        if H_over_E is not None or h_star_over_sigma is not None:
            raise ValueError("the elastic law takes no hardness (H_over_E) or size effect (h_star_over_sigma); "
                             "use the law 'jackson-green'")
        return Elastic()
    if H_over_E is None:
        raise ValueError("the law 'jackson-green' needs the hardness H_over_E = H/E*")
    return JacksonGreen(H_over_E, 0.0 if h_star_over_sigma is None else h_star_over_sigma)


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
        """Penetrations where the law's radius crosses the friction law's breakpoint radii.

        Below the area's switch the radius is Hertz's, :math:`\bar u = (\bar a_k/\beta)^2`; above,
        the law's radius exceeds Hertz's, so the crossing lies in :math:`[\bar u_t, (\bar a_k/\beta)^2]`.
        """
        beta = self.params.beta
        out = []
        for a_k in self.params.friction.breakpoints():
            u_hertz = (a_k / beta) ** 2
            if u_hertz <= self.u_t:
                out.append(u_hertz)
            else:
                out.append(float(optimize.brentq(lambda u, a_k=a_k: self._radius(u) - a_k, self.u_t, u_hertz,
                                                 xtol=1e-15 * u_hertz, rtol=4 * np.finfo(float).eps)))
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
        (:func:`plastic_fraction` with :attr:`u_c`)."""
        return plastic_fraction(d, self.u_c, heights)
