r"""The model in physical units: a real material, a real surface, forces in newtons.

The paper's dimensionless groups (Eqs 7, 15, 16) follow from SI inputs,

.. math::
    \alpha = (\sigma_s/R)^{1/2},\quad \beta = (R\sigma_s)^{1/2}/b,\quad
    \gamma = \frac{w}{E^*b},\quad
    \lambda = \frac{b}{h}\Big(\frac{9\beta\gamma^2}{2\pi\alpha}\Big)^{1/3},

and the results scale back with :math:`N = \eta A_0` asperities: forces by
:math:`NGb^2` (newtons), real contact area by :math:`N\pi b^2` (m^2), separations by
:math:`\sigma_s` (m).  :math:`\sigma_s` is the standard deviation of summit heights,
:math:`R` the summit radius, :math:`\eta` the summit density and :math:`A_0` the nominal
area.  For two elastic bodies use :func:`asperity.materials.pair`, which maps the pair
onto an equivalent body on a rigid flat (see :mod:`asperity.materials`).

Every physical input accepts a float in SI units or a pint ``Quantity``
(``pip install 'asperity[units]'``).

This module holds the contact (:class:`PhysicalContact`) and its results
(:class:`PhysicalCurve`, :class:`PhysicalPullOff`, columns in :data:`PHYSICAL_COLUMNS`).
A contact states what it computes (:meth:`PhysicalContact.describe`,
:meth:`PhysicalContact.to_dict`): both bodies, :math:`E^*`, :math:`G^*`, :math:`w`,
:math:`h`, :math:`b`, the groups, :math:`\lambda` with its adhesion regime and :math:`N`.

**The GW assumption.**  Greenwood-Williamson asperities are independent, which needs a
real contact area :math:`A` well below the nominal area :math:`A_0`.  Every curve carries
``area_fraction`` :math:`= A/A_0`; a call whose largest fraction passes
:data:`AREA_FRACTION_CAUTION` (10 %: neighbouring contacts interact, the results degrade)
or :data:`AREA_FRACTION_LIMIT` (100 %: more contact than surface, not physical) issues one
:class:`AreaFractionWarning`, a :class:`UserWarning` users can filter
(``warnings.simplefilter("ignore", asperity.AreaFractionWarning)``) or turn into errors.
The surface lives in :mod:`asperity.surface` (:class:`~asperity.surface.Surface`,
:func:`~asperity.surface.surface_from_groups`) and the regime helpers in
:mod:`asperity.regimes` (:func:`~asperity.regimes.tabor_parameter`,
:func:`~asperity.regimes.maugis_parameter`, :func:`~asperity.regimes.adhesion_regime`,
:func:`~asperity.regimes.fuller_tabor_parameter`); both are re-exported here, so
``from asperity.physical import Surface`` keeps working.

References
----------
.. [1] Adams, Müftü, Mohd Azhar, "A nano-scale multi-asperity contact and friction model",
   Eqs (6), (7), (14)-(17), (20).
.. [2] J. A. Greenwood, J. B. P. Williamson, Proc. R. Soc. A 295 (1966) 300.
"""

from __future__ import annotations

import functools
import math
import warnings

import numpy as np

from ._validation import (
    check_1d,
    check_bool,
    check_finite_result,
    check_scalar_positive,
)
from ._warnings import AsperityWarning
from .curves import CurveResult, Model
from .elastic_plastic import LAWS
from .friction_stress import ConstantShear, FrictionLaw
from .groups import work_of_adhesion_from_gamma
from .heights import GAUSSIAN, HeightDistribution, check_heights
from .interaction import interaction_for_surface
from .load_control import LoadOutOfRange
from .materials import Material, as_material
from .multi_asperity import D_MAX, D_MIN
from .physical_description import ContactDescription
from .physical_groups import ContactGroups
from .physical_results import (
    AREA_FRACTION_CAUTION,
    AREA_FRACTION_LIMIT,
    PHYSICAL_COLUMNS,
    PHYSICAL_PLASTIC_COLUMNS,
    AreaFractionWarning,
    PhysicalCurve,
    PhysicalPullOff,
    warn_area_fraction,
)
from .plasticity import PLASTIC_THRESHOLD, ContactPlasticity, resolve_plasticity
from .regimes import adhesion_regime, fuller_tabor_parameter, maugis_parameter, tabor_parameter
from .surface import Surface, surface_from_groups
from .units import is_quantity, to_si

__all__ = [
    "Surface",
    "PhysicalContact",
    "PhysicalCurve",
    "PhysicalPullOff",
    "PHYSICAL_COLUMNS",
    "PHYSICAL_PLASTIC_COLUMNS",
    "AreaFractionWarning",
    "AREA_FRACTION_CAUTION",
    "AREA_FRACTION_LIMIT",
    "warn_area_fraction",
    "surface_from_groups",
    "work_of_adhesion_from_gamma",
    "tabor_parameter",
    "maugis_parameter",
    "adhesion_regime",
    "fuller_tabor_parameter",
]


class PhysicalContact(ContactGroups, ContactDescription, ContactPlasticity):
    r"""A real material against a rigid flat through a real rough surface, in SI units.

    Parameters
    ----------
    material : Material or str
        The elastic body: a table name, ``'Au'`` (gold **on a rigid flat**, the paper's
        set-up) or ``'Au/Au'`` (**two** gold bodies: :math:`E^*` and :math:`G^*` halve, so
        the forces differ), or a :class:`~asperity.materials.Material`;
        :func:`asperity.bodies.contact_material` builds one with values of one's own
        (``w``, ``E``, ``nu``, a second body, ``b``, ``h``) and
        :func:`asperity.materials.pair` two bodies.  Needs a Burgers vector ``b``.
    surface : Surface
        Summit statistics and nominal area.
    h : float or pint.Quantity, optional
        Dugdale range (m).  Default: the material's ``h``, else its Burgers vector
        (the paper's :math:`h = b`).
    friction : FrictionLaw, float or pint.Quantity, optional
        A dimensionless law (:class:`~asperity.HurtadoKim`, :class:`~asperity.ConstantShear`;
        stress in units of :math:`G^* = 2G`), or a constant interfacial shear strength
        :math:`\tau` in Pa, used as ``ConstantShear(tau / G*)``.  Default: Hurtado-Kim with
        the paper's constants.
    adhesion : bool
        True (default): Maugis-Dugdale adhesion with the material's work of adhesion
        ``w``; a material without ``w`` raises :class:`ValueError`.  ``w = 0`` gives
        :math:`\gamma = 0`, the Hertz model.  False: :math:`\gamma = 0` (Hertz) whatever ``w``.
    heights : HeightDistribution or str
        Summit heights in units of :math:`\sigma_s` (default Gaussian, Eq 19); or a spec string (``'weibull:skew=0.5'``,
        :func:`asperity.heights.parse_heights`).
    interaction : str, optional
        Asperity interaction, a name of :data:`asperity.interaction.INTERACTIONS`:
        ``'none'`` (default, plain GW) or ``'cgp2008'``, the mean-field correction of
        Ciavarella, Greenwood & Paggi (2008) over this surface's nominal area (non-adhesive:
        needs ``adhesion=False``); then separations are measured from the undeformed surface.
    plasticity : str, optional
        The per-asperity law, a name of :data:`asperity.elastic_plastic.LAWS`: ``'elastic'``
        (default; Hertz or Maugis-Dugdale) or ``'jackson-green'`` (elastic-plastic, needs a
        hardness and no adhesion: pass ``adhesion=False``).
    hardness : float or pint.Quantity, optional
        Hardness :math:`H` (Pa); default: the material's ``H``.  With the size effect,
        :math:`H_0` (default: the material's ``H0``).  Gives :attr:`plasticity_index`,
        :attr:`critical_interference` and, with the elastic law, the yield check.
    size_effect : bool, optional
        Nix-Gao indentation size effect, :math:`H = H_0(1 + h^*/\omega)^{1/2}` at each
        asperity's interference :math:`\omega`.  Default None: on if ``h_star`` is given.
    h_star : float or pint.Quantity, optional
        Nix-Gao length :math:`h^*` (m); default: the material's ``h_star``.
    plastic_threshold : float
        With the elastic law, a curve on which more than this share of the asperities in
        contact is past the critical interference warns (:class:`~asperity.PlasticityWarning`);
        default :data:`~asperity.plasticity.PLASTIC_THRESHOLD` = 0.01.

    Raises
    ------
    TypeError
        If ``material``, ``surface``, ``adhesion`` or ``heights`` has the wrong type.
    ValueError
        For a material without Burgers vector, or without work of adhesion when
        ``adhesion`` is True, or a value out of range (the message names it).

    Examples
    --------
    >>> c = PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6), adhesion=False)
    >>> round(c.alpha, 4), round(c.beta, 1)
    (0.0447, 155.0)
    >>> print(c.describe().splitlines()[0])
    contact: Au (E 78 GPa, nu 0.44) on a rigid flat
    """

    def __init__(self, material: Material | str, surface: Surface, *, h=None, friction=None,
                 adhesion: bool = True, heights: HeightDistribution = GAUSSIAN, plasticity: str | None = None,
                 hardness=None, size_effect: bool | None = None, h_star=None,
                 plastic_threshold: float = PLASTIC_THRESHOLD, interaction=None):
        self.material = as_material(material, "material")
        if not isinstance(surface, Surface):
            raise TypeError(f"surface must be an asperity.surface.Surface, got {type(surface).__name__}")
        self.surface = surface
        if self.material.b is None:
            raise ValueError(f"material {self.material.name!r} has no Burgers vector b (m); give one, e.g. "
                             "asperity.bodies.contact_material(material, b=2.9e-10) (command line: --b)")
        self.adhesion = check_bool(adhesion, "adhesion")
        self.w = _adhesion_w(self.material, self.adhesion)
        self.h = self.material.b if h is None and self.material.h is None else \
            check_scalar_positive(self.material.h if h is None else h, "h", "m")
        self.friction = self._friction_law(friction)
        self.heights = check_heights(heights)
        s = surface
        self.interaction = interaction_for_surface(interaction, eta=s.eta, area=s.area, b=self.material.b,
                                                   sigma_s=s.sigma_s, nu=self.material.nu)
        if self.interaction.active and self.gamma > 0:
            raise ValueError(f"interaction {self.interaction.name!r} (Ciavarella, Greenwood & Paggi 2008) is "
                             "derived for non-adhesive contact; pass adhesion=False or interaction='none' "
                             "(command line: --no-adhesion)")
        self.law, self.hardness, self.h_star = resolve_plasticity(self.material, plasticity, hardness,
                                                                  size_effect, h_star)
        if not (math.isfinite(self.force_scale) and math.isfinite(self.area_scale)):
            raise ValueError(f"the force unit N G b^2 = {self.force_scale:g} N is not finite: N = eta * area = "
                             f"{self.N:g} summits is too many; give a smaller area (or eta)")
        self.plastic_threshold = check_scalar_positive(plastic_threshold, "plastic_threshold", allow_zero=True)
        if self.plastic_threshold > 1.0:
            raise ValueError(f"plastic_threshold must lie in [0, 1], got {plastic_threshold!r}")
        if LAWS[self.law].plastic:
            if self.gamma > 0.0:
                raise ValueError(f"plasticity={self.law!r} has no adhesion, but material {self.material.name!r} has "
                                 f"a work of adhesion w = {self.w:g} J/m^2 (Maugis-Dugdale cannot be combined with a "
                                 "plastic core consistently): pass adhesion=False "
                                 "(command line: --no-adhesion)")
            self._law_spec = LAWS[self.law](self.H_over_E, self.h_star / self.surface.sigma_s)  # validated here

    def _friction_law(self, friction) -> FrictionLaw | None:
        if friction is None or isinstance(friction, FrictionLaw):
            return friction
        tau = check_scalar_positive(friction, "friction (shear strength tau)", "Pa")
        ratio = tau / self.G_star
        if not 0.0 < ratio < math.inf:
            raise ValueError(f"friction (shear strength tau) = {tau:g} Pa is out of range for G* = {self.G_star:g} Pa: "
                             "tau/G* must be a positive, finite double")
        return ConstantShear(ratio)

    @functools.cached_property
    def model(self) -> Model:
        """The dimensionless :class:`~asperity.Model` with these alpha, beta, gamma, nu, h/b and law."""
        kwargs = {} if self.friction is None else {"friction": self.friction}
        if LAWS[self.law].plastic:
            kwargs["law"] = self._law_spec
        try:
            return Model(self.alpha, self.beta, self.gamma, nu=self.nu, h_over_b=self.h_over_b,
                         heights=self.heights, interaction=self.interaction, **kwargs)
        except ValueError as err:  # name what the user gave, not only the groups made of it
            s = self.surface
            raise ValueError(f"{err}; from sigma_s = {s.sigma_s:g} m, R = {s.R:g} m, b = {self.b:g} m (alpha = "
                             "(sigma_s/R)^(1/2), beta = (R sigma_s)^(1/2)/b, Eq 7)") from None

    # -- curves -------------------------------------------------------------------------
    def separation_curve(self, d) -> PhysicalCurve:
        """Forces, mu, area, pressure and contacts at separations ``d`` (m, or a pint length)."""
        d = check_1d(to_si(d, "m", "d"), "d")
        with np.errstate(all="ignore"):
            d_bar = d / self.surface.sigma_s
        if np.any((d_bar < D_MIN) | (d_bar > D_MAX)):
            raise ValueError(f"d (separation) must lie in [{D_MIN * self.surface.sigma_s:g}, "
                             f"{D_MAX * self.surface.sigma_s:g}] m ({D_MIN:g} to {D_MAX:g} sigma_s)")
        return self._physical(self.model.separation_curve(d_bar), d=d)  # warns: see _physical

    def load_curve(self, P) -> PhysicalCurve:
        """All quantities at the stable separation for each normal load ``P`` (N, or a pint force).

        Raises
        ------
        ValueError
            If a load is not positive without adhesion, or more tensile than the pull-off
            force with adhesion (the message gives the limit in newtons).
        """
        P = check_1d(to_si(P, "N", "P"), "P")
        with np.errstate(all="ignore"):
            P_bar = check_finite_result(P / self.force_scale, "P/(N G b^2)", P=P)
        try:
            curve = self.model.load_curve(P_bar)
        except LoadOutOfRange as err:  # the same in newtons and metres
            d_end = None if err.d_end is None else err.d_end * self.surface.sigma_s
            what = err.what if d_end is None else f"the force at d = {d_end:.4g} m"
            raise LoadOutOfRange(err.floor * self.force_scale, float(np.min(P)), what, err.exclusive, " N",
                                 d_end) from None
        except ValueError as err:
            raise ValueError(f"{err} (loads in units of N G b^2 = {self.force_scale:.6g} N)") from None
        return self._physical(curve, P=P)

    def pull_off(self, d_max: float | None = None) -> PhysicalPullOff:
        """Pull-off force (N) and its separation (m), with the real contact area there.

        ``d_max`` bounds the search: a number in units of sigma_s, or a length with its unit
        (``'20nm'``, a pint quantity; command line: ``--d-max 20nm``); default: see
        :meth:`asperity.Model.pull_off`.  Issues an :class:`AreaFractionWarning` if the area at
        pull-off passes 10 % of the nominal area.
        """
        given = d_max
        if isinstance(d_max, str) or is_quantity(d_max):  # a length: in units of sigma_s below
            d_max = check_scalar_positive(to_si(d_max, "m", "d_max"), "d_max", "m") / self.surface.sigma_s
        if d_max is not None:
            d_max = check_scalar_positive(d_max, "d_max")
        try:
            po = self.model.pull_off(d_max)
        except ValueError as err:
            if given is d_max:
                raise
            raise ValueError(f"{err} (d_max = {given} is {d_max:.6g} sigma_s, sigma_s = {self.surface.sigma_s:g} m)") \
                from None
        if not po.exists and given is not None and self.model.params.adhesive:  # a user trial: d_max=20e-9
            shown = f" ({given})" if isinstance(given, str) else ""  # (metres meant) searched 2e-8 sigma_s
            warnings.warn(AsperityWarning(  # and said 'no pull-off'
                f"no tensile force for d <= d_max = {d_max:.4g} sigma_s{shown}: a pull-off, if any, lies beyond; a "
                "plain number is in units of sigma_s, a length needs its unit ('20nm')"), stacklevel=2)
        area = 0.0
        if po.exists:
            at = self.model.separation_curve([po.d])
            area, touching = float(at.area[0]) * self.area_scale, float(at.contacts[0]) * self.N
            # an expectation over many surfaces: with N independent summits the number touching is
            # binomial, and none touches with probability (1 - n/N)^N (e^-n for many summits)
            none = math.exp(self.N * math.log1p(-min(touching / self.N, 1.0))) if touching < self.N else 0.0
            if none > 0.5:
                warnings.warn(AsperityWarning(
                    f"the pull-off force, {po.force * self.force_scale:.3g} N, is carried by {_below_one(touching)} "
                    f"asperities in contact on average (an expectation over many such surfaces): a real contact of "
                    f"this surface has none in contact there with probability {none:.3g}, so it would most likely "
                    "show no pull-off"), stacklevel=2)
        warn_area_fraction(area / self.surface.area, stacklevel=2, where=" at pull-off")
        return PhysicalPullOff(force=po.force * self.force_scale, d=po.d * self.surface.sigma_s,
                               exists=po.exists, dimensionless=po, area=area, nominal_area=self.surface.area)

    def cycle(self, *, d_min=None, preload=None, d_max=None, d=None, n=200, stiffness=None, u_in=0.0):
        """An approach-retract cycle in SI units: :func:`asperity.physical_cycle.physical_cycle` for this contact
        (``preload`` in N, ``d_min``, ``d_max``, ``d``, ``u_in`` in m, ``stiffness`` in N/m)."""
        from .physical_cycle import physical_cycle

        return physical_cycle(self, d_min=d_min, preload=preload, d_max=d_max, d=d, n=n, stiffness=stiffness,
                              u_in=u_in)

    def preload_curve(self, preload, *, d_max=None, u_in=0.0):
        """Pull-off and energy dissipated against preload (N), in SI units:
        :func:`asperity.physical_cycle.physical_preload_curve` for this contact."""
        from .physical_cycle import physical_preload_curve

        return physical_preload_curve(self, preload, d_max=d_max, u_in=u_in)

    def _physical(self, curve: CurveResult, *, d=None, P=None) -> PhysicalCurve:
        """The SI curve of a dimensionless one; one :class:`AreaFractionWarning` if its area is too large."""
        fs, area = self.force_scale, curve.area * self.area_scale
        P = curve.P * fs if P is None else P
        with np.errstate(divide="ignore", invalid="ignore"):
            pressure = np.where(area > 0, P / np.where(area > 0, area, 1.0), np.nan)
        plastic = curve.plastic  # the plastic law's column; the elastic law is only checked
        if plastic is None:
            self.warn_if_yielding(curve.d if curve.d_local is None else curve.d_local, curve.contacts, stacklevel=4)
        result = PhysicalCurve(d=curve.d * self.surface.sigma_s if d is None else d, P=P, F=curve.F * fs,
                               mu=curve.mu, area=area, pressure=pressure, contacts=curve.contacts * self.N,
                               dimensionless=curve, parameters=self.parameters(),
                               nominal_area=self.surface.area, plastic=None if plastic is None else plastic * self.N)
        for message in result.validity_warnings():  # -> the caller of load_curve/separation_curve
            warnings.warn(message, AreaFractionWarning, stacklevel=3)
        return result


def _below_one(x: float) -> str:
    """``x`` < 1 with 3 significant digits, or as many more as keep it below 1 ('0.99998', not '1')."""
    for digits in range(3, 18):
        text = f"{x:.{digits}g}"
        if float(text) < 1.0:
            return text
    return repr(x)


def _adhesion_w(body: Material, adhesion: bool) -> float:
    if not adhesion:
        return 0.0
    if body.w is None:
        raise ValueError(f"material {body.name!r} has no work of adhesion w (J/m^2): give it one "
                         "(dataclasses.replace(material, w=...)) or pass adhesion=False for the Hertz model "
                         "(command line: --w or --no-adhesion; asperity sweep: --w, 0J/m^2 for none)")
    return body.w
