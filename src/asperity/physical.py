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

Regime helpers: :func:`tabor_parameter`, :func:`maugis_parameter`,
:func:`adhesion_regime` (Johnson-Greenwood adhesion map) and
:func:`fuller_tabor_parameter` (roughness versus adhesion).

References
----------
.. [1] Adams, Müftü, Mohd Azhar, "A nano-scale multi-asperity contact and friction model",
   Eqs (6), (7), (14)-(17), (20).
.. [2] J. A. Greenwood, J. B. P. Williamson, Proc. R. Soc. A 295 (1966) 300.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field

import numpy as np

from . import groups
from ._csv import columns_to_csv, columns_to_dataframe
from ._validation import as_float_array, check_nonnegative, check_positive
from .curves import CurveResult, Model, PullOff
from .friction_stress import ConstantShear, FrictionLaw
from .heights import GAUSSIAN, HeightDistribution
from .materials import Material, material
from .maugis_dugdale import md_lambda
from .multi_asperity import D_MAX, D_MIN
from .quantities import CURVE_COLUMNS
from .units import to_si

__all__ = [
    "Surface",
    "PhysicalContact",
    "PhysicalCurve",
    "PhysicalPullOff",
    "PHYSICAL_COLUMNS",
    "surface_from_groups",
    "work_of_adhesion_from_gamma",
    "tabor_parameter",
    "maugis_parameter",
    "adhesion_regime",
    "fuller_tabor_parameter",
]

#: Columns of a :class:`PhysicalCurve`: attribute -> (CSV/DataFrame column, SI unit, meaning),
#: derived from :data:`asperity.quantities.CURVE_COLUMNS`.
PHYSICAL_COLUMNS = {name: (q.si_name, q.si_unit, q.si_meaning) for name, q in CURVE_COLUMNS.items()}


def _out(x):
    """A 0-d result as float, otherwise the array."""
    x = np.asarray(x, dtype=float)
    return float(x) if x.ndim == 0 else x


def _scalar_positive(value, unit: str, name: str) -> float:
    x = check_positive(to_si(value, unit, name), name)
    if x.ndim != 0:
        raise ValueError(f"{name} must be a scalar, got an array of shape {x.shape}")
    return float(x)


@dataclass(frozen=True)
class Surface:
    r"""A Greenwood-Williamson rough surface in SI units.

    Parameters
    ----------
    sigma_s : float or pint.Quantity
        Standard deviation of summit heights (m), > 0.
    R : float or pint.Quantity
        Summit radius of curvature (m), > 0.
    eta : float or pint.Quantity
        Summit density (1/m^2), > 0.
    area : float or pint.Quantity
        Nominal contact area (m^2), > 0.

    Attributes
    ----------
    N : float
        Number of summits :math:`\eta A` in the nominal area.
    alpha : float
        Roughness parameter :math:`(\sigma_s/R)^{1/2}` (Eq 7).

    Examples
    --------
    >>> Surface(sigma_s=2e-9, R=1e-6, eta=1e12, area=1e-6).N
    1000000.0
    """

    sigma_s: float
    R: float
    eta: float
    area: float

    def __post_init__(self):
        for name, unit in (("sigma_s", "m"), ("R", "m"), ("eta", "1/m^2"), ("area", "m^2")):
            object.__setattr__(self, name, _scalar_positive(getattr(self, name), unit, name))

    @property
    def N(self) -> float:
        """Number of asperities (summits) in the nominal area."""
        return self.eta * self.area

    @property
    def alpha(self) -> float:
        """Surface roughness parameter (sigma_s/R)^(1/2) (Eq 7)."""
        return math.sqrt(self.sigma_s / self.R)


@dataclass(frozen=True)
class PhysicalCurve:
    """A curve in SI units; columns and units in :data:`PHYSICAL_COLUMNS`.

    ``d`` [m], ``P`` [N], ``F`` [N], ``mu`` [-], ``area`` [m^2], ``pressure`` [Pa] (= P/area),
    ``contacts`` [number of asperities].  ``dimensionless`` is the model's own
    :class:`~asperity.CurveResult`; ``parameters`` the inputs and groups.
    """

    d: np.ndarray
    P: np.ndarray
    F: np.ndarray
    mu: np.ndarray
    area: np.ndarray
    pressure: np.ndarray
    contacts: np.ndarray
    dimensionless: CurveResult = field(repr=False, compare=False)
    parameters: dict = field(default_factory=dict, compare=False)
    nominal_area: float = math.nan

    @property
    def area_fraction(self) -> np.ndarray:
        """Real over nominal contact area.  The GW model (independent asperities) needs it
        well below 1; above ~0.1 neighbouring contacts interact and the results degrade."""
        return self.area / self.nominal_area

    def __len__(self) -> int:
        return int(np.size(self.d))

    def columns(self) -> dict[str, np.ndarray]:
        """Column name (with unit, e.g. ``'P_N'``) -> array, in the order of :data:`PHYSICAL_COLUMNS`."""
        return {col: np.asarray(getattr(self, attr)) for attr, (col, _, _) in PHYSICAL_COLUMNS.items()}

    def to_dataframe(self):
        """The curve as a :class:`pandas.DataFrame` (needs pandas); units in ``attrs['units']``."""
        units = {col: unit for col, unit, _ in PHYSICAL_COLUMNS.values()}
        return columns_to_dataframe(self.columns(), {**self.parameters, "units": units})

    def to_csv(self, path_or_buffer=None) -> str | None:
        """Write CSV (header of column names with units, e.g. ``d_m,P_N,...``); return it if no path."""
        return columns_to_csv(self.columns(), path_or_buffer)


@dataclass(frozen=True)
class PhysicalPullOff:
    """Pull-off force in newtons (>= 0) and the separation in metres where it occurs.

    ``d`` is NaN when ``exists`` is False.  ``dimensionless`` is the model's :class:`~asperity.PullOff`.
    """

    force: float
    d: float
    exists: bool
    dimensionless: PullOff = field(repr=False, compare=False)


class PhysicalContact:
    r"""A real material against a rigid flat through a real rough surface, in SI units.

    Parameters
    ----------
    material : Material or str
        The elastic body (a name is looked up in the table); for two elastic bodies pass
        :func:`asperity.materials.pair`.  Needs a Burgers vector ``b``.
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
    heights : HeightDistribution
        Summit heights in units of :math:`\sigma_s` (default Gaussian, Eq 19).

    Examples
    --------
    >>> from asperity.materials import material
    >>> c = PhysicalContact(material("Au"), Surface(2e-9, 1e-6, 1e12, 1e-6), adhesion=False)
    >>> round(c.alpha, 4), round(c.beta, 1)
    (0.0447, 155.0)
    """

    def __init__(self, material: Material | str, surface: Surface, *, h=None, friction=None,
                 adhesion: bool = True, heights: HeightDistribution = GAUSSIAN):
        self.material = _as_material(material)
        if not isinstance(surface, Surface):
            raise ValueError(f"surface must be an asperity.physical.Surface, got {surface!r}")
        self.surface = surface
        if self.material.b is None:
            raise ValueError(f"material {self.material.name!r} has no Burgers vector b (m); "
                             "give one, e.g. dataclasses.replace(material, b=2.9e-10)")
        self.adhesion = bool(adhesion)
        self.w = _adhesion_w(self.material, self.adhesion)
        self.h = self.material.b if h is None and self.material.h is None else \
            _scalar_positive(self.material.h if h is None else h, "m", "h")
        self.friction = self._friction_law(friction)
        self.heights = heights

    def _friction_law(self, friction) -> FrictionLaw | None:
        if friction is None or isinstance(friction, FrictionLaw):
            return friction
        tau = _scalar_positive(friction, "Pa", "friction (shear strength tau)")
        return ConstantShear(tau / self.G_star)

    # -- material and surface -----------------------------------------------------------
    @property
    def b(self) -> float:
        """Burgers vector (m)."""
        return self.material.b

    @property
    def nu(self) -> float:
        """Poisson's ratio (for a pair: the effective 1 - G*/E*)."""
        return self.material.nu

    @property
    def E_star(self) -> float:
        """Composite Young's modulus (Pa)."""
        return self.material.E_star

    @property
    def G(self) -> float:
        """Shear modulus of the force unit G b^2 (Pa); G* = 2G."""
        return self.material.G

    @property
    def G_star(self) -> float:
        """Effective shear modulus 2G (Pa), the unit of friction stress."""
        return self.material.G_star

    @property
    def N(self) -> float:
        """Number of asperities eta * area."""
        return self.surface.N

    # -- groups -------------------------------------------------------------------------
    @property
    def alpha(self) -> float:
        """Roughness parameter (sigma_s/R)^(1/2) (Eq 7)."""
        return float(groups.roughness_alpha(self.surface.sigma_s, self.surface.R))

    @property
    def beta(self) -> float:
        """Friction regime parameter (R sigma_s)^(1/2)/b (Eq 7)."""
        return float(groups.regime_beta(self.surface.sigma_s, self.surface.R, self.b))

    @property
    def gamma(self) -> float:
        """Adhesion parameter w/(E* b) (Eq 16); 0 without adhesion."""
        return float(groups.adhesion_gamma(self.w, self.E_star, self.b)) if self.w > 0 else 0.0

    @property
    def h_over_b(self) -> float:
        """Dugdale range over Burgers vector."""
        return self.h / self.b

    @property
    def lam(self) -> float:
        """Maugis parameter from the groups (Eq 15); equal to Eq (14) with sigma0 = w/h; 0 without adhesion."""
        if self.gamma == 0.0:
            return 0.0
        return float(groups.maugis_lambda(self.alpha, self.beta, self.gamma, self.h_over_b))

    @property
    def force_scale(self) -> float:
        """Force unit N G b^2 (N)."""
        return self.N * self.G * self.b**2

    @property
    def area_scale(self) -> float:
        """Area unit N pi b^2 (m^2)."""
        return self.N * math.pi * self.b**2

    @functools.cached_property
    def model(self) -> Model:
        """The dimensionless :class:`~asperity.Model` with these alpha, beta, gamma, nu, h/b."""
        kwargs = {} if self.friction is None else {"friction": self.friction}
        return Model(self.alpha, self.beta, self.gamma, nu=self.nu, h_over_b=self.h_over_b,
                     heights=self.heights, **kwargs)

    def parameters(self) -> dict:
        """Inputs, groups and scales (SI units) as a flat dict."""
        s = self.surface
        return {"material": self.material.name, "E_star_Pa": self.E_star, "G_Pa": self.G, "nu": self.nu,
                "b_m": self.b, "w_J_m2": self.w, "h_m": self.h, "sigma_s_m": s.sigma_s, "R_m": s.R,
                "eta_per_m2": s.eta, "area_m2": s.area, "N": self.N, "alpha": self.alpha, "beta": self.beta,
                "gamma": self.gamma, "lambda": self.lam, "force_scale_N": self.force_scale,
                "area_scale_m2": self.area_scale, "friction": repr(self.model.params.friction)}

    # -- curves -------------------------------------------------------------------------
    def separation_curve(self, d) -> PhysicalCurve:
        """Forces, mu, area, pressure and contacts at separations ``d`` (m, or a pint length)."""
        d = as_float_array(to_si(d, "m", "d"), "d").ravel()
        d_bar = d / self.surface.sigma_s
        if np.any((d_bar < D_MIN) | (d_bar > D_MAX)):
            raise ValueError(f"d (separation) must lie in [{D_MIN * self.surface.sigma_s:g}, "
                             f"{D_MAX * self.surface.sigma_s:g}] m ({D_MIN:g} to {D_MAX:g} sigma_s)")
        return self._physical(self.model.separation_curve(d_bar), d=d)

    def load_curve(self, P) -> PhysicalCurve:
        """All quantities at the stable separation for each normal load ``P`` (N, or a pint force).

        Raises
        ------
        ValueError
            If a load is not positive without adhesion, or more tensile than the pull-off
            force with adhesion (the message gives the limit in newtons).
        """
        P = as_float_array(to_si(P, "N", "P"), "P").ravel()
        try:
            curve = self.model.load_curve(P / self.force_scale)
        except ValueError as err:
            raise ValueError(f"{err} (loads in units of N G b^2 = {self.force_scale:.6g} N)") from None
        return self._physical(curve, P=P)

    def pull_off(self, d_max: float | None = None) -> PhysicalPullOff:
        """Pull-off force (N) and its separation (m).

        ``d_max`` bounds the search in units of sigma_s (default: see :meth:`asperity.Model.pull_off`).
        """
        po = self.model.pull_off(d_max)
        return PhysicalPullOff(force=po.force * self.force_scale, d=po.d * self.surface.sigma_s,
                               exists=po.exists, dimensionless=po)

    def _physical(self, curve: CurveResult, *, d=None, P=None) -> PhysicalCurve:
        fs, area = self.force_scale, curve.area * self.area_scale
        P = curve.P * fs if P is None else P
        with np.errstate(divide="ignore", invalid="ignore"):
            pressure = np.where(area > 0, P / np.where(area > 0, area, 1.0), np.nan)
        return PhysicalCurve(d=curve.d * self.surface.sigma_s if d is None else d, P=P, F=curve.F * fs,
                             mu=curve.mu, area=area, pressure=pressure, contacts=curve.contacts * self.N,
                             dimensionless=curve, parameters=self.parameters(),
                             nominal_area=self.surface.area)


def _as_material(body) -> Material:
    if isinstance(body, Material):
        return body
    if isinstance(body, str):
        return material(body)
    raise ValueError(f"material must be an asperity.materials.Material or a table name, got {body!r}")


def _adhesion_w(body: Material, adhesion: bool) -> float:
    if not adhesion:
        return 0.0
    if body.w is None:
        raise ValueError(f"material {body.name!r} has no work of adhesion w (J/m^2): give it one "
                         "(dataclasses.replace(material, w=...)) or pass adhesion=False for the Hertz model")
    return body.w


# -- inverse conversions ---------------------------------------------------------------------

def surface_from_groups(alpha, beta, b, eta, area) -> Surface:
    r"""The :class:`Surface` with given :math:`\alpha`, :math:`\beta` (Eq 20).

    .. math:: \sigma_s = \alpha\beta b,\qquad R = \beta b/\alpha

    Parameters
    ----------
    alpha, beta : float
        Roughness and friction-regime parameters (Eq 7), > 0.
    b : float or pint.Quantity
        Burgers vector (m), > 0.
    eta : float or pint.Quantity
        Summit density (1/m^2), > 0.
    area : float or pint.Quantity
        Nominal area (m^2), > 0.

    References
    ----------
    Adams et al., Eq (20).
    """
    alpha = _scalar_positive(alpha, "", "alpha")
    beta = _scalar_positive(beta, "", "beta")
    b = _scalar_positive(b, "m", "b")
    return Surface(sigma_s=alpha * beta * b, R=beta * b / alpha, eta=eta, area=area)


def work_of_adhesion_from_gamma(gamma, E_star, b):
    r"""Work of adhesion :math:`w = \gamma E^* b` (J/m^2), the inverse of Eq (16).

    Parameters
    ----------
    gamma : array_like
        Adhesion parameter, >= 0.
    E_star : array_like or pint.Quantity
        Composite Young's modulus (Pa), > 0.
    b : array_like or pint.Quantity
        Burgers vector (m), > 0.

    References
    ----------
    Adams et al., Eq (16).
    """
    gamma = check_nonnegative(to_si(gamma, "", "gamma"), "gamma")
    E_star = check_positive(to_si(E_star, "Pa", "E_star"), "E_star")
    b = check_positive(to_si(b, "m", "b"), "b")
    return _out(gamma * E_star * b)


# -- adhesion regimes ------------------------------------------------------------------------

def tabor_parameter(R, w, E_star, z0):
    r"""Tabor parameter :math:`\mu_T = (R w^2 / E^{*2} z_0^3)^{1/3}`.

    The ratio of the elastic neck height at pull-off to the range of surface forces:
    small values mean DMT-like (stiff, long-range), large values JKR-like contact.

    Parameters
    ----------
    R : array_like or pint.Quantity
        Sphere (summit) radius (m), > 0.
    w : array_like or pint.Quantity
        Work of adhesion (J/m^2), > 0.
    E_star : array_like or pint.Quantity
        Composite Young's modulus (Pa), > 0.
    z0 : array_like or pint.Quantity
        Equilibrium spacing of the surface-force law (m), > 0 (about 0.2-0.4 nm).

    Returns
    -------
    float or ndarray
        :math:`\mu_T` (dimensionless), broadcast over the inputs.

    Notes
    -----
    For a Lennard-Jones force law the Dugdale model with the same maximum stress and
    work of adhesion gives :math:`\lambda \approx 1.16\,\mu_T` (Johnson & Greenwood 1997).

    References
    ----------
    .. [1] D. Tabor, J. Colloid Interface Sci. 58 (1977) 2-13.
    .. [2] K. L. Johnson, J. A. Greenwood, J. Colloid Interface Sci. 192 (1997) 326-333.
    """
    R = check_positive(to_si(R, "m", "R"), "R")
    w = check_positive(to_si(w, "J/m^2", "w"), "w")
    E_star = check_positive(to_si(E_star, "Pa", "E_star"), "E_star")
    z0 = check_positive(to_si(z0, "m", "z0"), "z0")
    return _out(np.cbrt(R * w**2 / (E_star**2 * z0**3)))


def maugis_parameter(R, w, E_star, sigma0):
    r"""Maugis parameter :math:`\lambda = 2\sigma_0 (R/\pi w K^2)^{1/3}`, :math:`K = \tfrac43E^*` (Eq 14).

    Parameters
    ----------
    R : array_like or pint.Quantity
        Sphere (summit) radius (m), > 0.
    w : array_like or pint.Quantity
        Work of adhesion (J/m^2), > 0.
    E_star : array_like or pint.Quantity
        Composite Young's modulus (Pa), > 0.
    sigma0 : array_like or pint.Quantity
        Dugdale stress (Pa), > 0; :math:`\sigma_0 = w/h` for a Dugdale range ``h``.

    Returns
    -------
    float or ndarray
        :math:`\lambda` (dimensionless).

    References
    ----------
    .. [1] D. Maugis, J. Colloid Interface Sci. 150 (1992) 243-269.
    .. [2] Adams et al., Eq (14); :func:`asperity.maugis_dugdale.md_lambda`.
    """
    return _out(md_lambda(to_si(sigma0, "Pa", "sigma0"), to_si(w, "J/m^2", "w"), to_si(R, "m", "R"),
                          to_si(E_star, "Pa", "E_star")))


def adhesion_regime(lam, *, dmt_below: float = 0.1, jkr_above: float = 5.0):
    r"""Name the single-asperity adhesion regime of a Maugis parameter.

    ``'DMT'`` for :math:`\lambda <` ``dmt_below``, ``'JKR'`` for :math:`\lambda >`
    ``jkr_above``, ``'Maugis-Dugdale'`` in between (boundaries included).

    Parameters
    ----------
    lam : array_like
        Maugis parameter :math:`\lambda \ge 0` (e.g. :attr:`PhysicalContact.lam` or
        :func:`maugis_parameter`).
    dmt_below, jkr_above : float
        Thresholds, 0 < dmt_below < jkr_above.  Defaults 0.1 and 5 follow the
        Johnson-Greenwood adhesion map, where the DMT and JKR solutions are adequate
        below and above them; the full map also depends on the load, so these are the
        load-independent bounds.

    Returns
    -------
    str or ndarray of str
        A string for a scalar ``lam``, otherwise an array of the same shape.

    References
    ----------
    .. [1] K. L. Johnson, J. A. Greenwood, "An adhesion map for the contact of elastic
       spheres", J. Colloid Interface Sci. 192 (1997) 326-333.
    """
    lam = check_nonnegative(lam, "lam")
    lo = float(check_positive(dmt_below, "dmt_below"))
    hi = float(check_positive(jkr_above, "jkr_above"))
    if not lo < hi:
        raise ValueError(f"dmt_below must be < jkr_above, got {lo:g} and {hi:g}")
    names = np.where(lam < lo, "DMT", np.where(lam > hi, "JKR", "Maugis-Dugdale"))
    return str(names) if names.ndim == 0 else names


def fuller_tabor_parameter(sigma, R, w, E_star):
    r"""Fuller-Tabor adhesion parameter :math:`\theta = E^*\sigma^{3/2}/(R^{1/2} w)`.

    The elastic force pushing one summit of radius :math:`R` a depth :math:`\sigma`
    into the flat, :math:`\tfrac43E^*R^{1/2}\sigma^{3/2}`, over its adhesive force scale
    :math:`\pi w R`, is :math:`\tfrac{4}{3\pi}\theta`.  In Fuller & Tabor's GW + JKR
    analysis the pull-off force of the rough contact, relative to a smooth one, falls
    steeply as :math:`\theta` grows: roughness defeats adhesion when the elastic term wins.

    Parameters
    ----------
    sigma : array_like or pint.Quantity
        Standard deviation of summit heights (m), > 0.
    R : array_like or pint.Quantity
        Summit radius (m), > 0.
    w : array_like or pint.Quantity
        Work of adhesion :math:`\Delta\gamma` (J/m^2), > 0.
    E_star : array_like or pint.Quantity
        Composite (plane-strain) modulus :math:`[(1-\nu_1^2)/E_1+(1-\nu_2^2)/E_2]^{-1}` (Pa), > 0.

    Returns
    -------
    float or ndarray
        :math:`\theta` (dimensionless).

    Notes
    -----
    Convention: :math:`E^*` is the composite modulus of this library (not the JKR
    :math:`K = \tfrac43E^*`) and :math:`w` the work of adhesion.  Later papers write the
    parameter with other moduli or prefactors (e.g. the :math:`\tfrac{4}{3\pi}\theta`
    above); thresholds are only comparable within one convention.

    References
    ----------
    .. [1] K. N. G. Fuller, D. Tabor, "The effect of surface roughness on the adhesion of
       elastic solids", Proc. R. Soc. A 345 (1975) 327-342.
    """
    sigma = check_positive(to_si(sigma, "m", "sigma"), "sigma")
    R = check_positive(to_si(R, "m", "R"), "R")
    w = check_positive(to_si(w, "J/m^2", "w"), "w")
    E_star = check_positive(to_si(E_star, "Pa", "E_star"), "E_star")
    return _out(E_star * sigma**1.5 / (np.sqrt(R) * w))
