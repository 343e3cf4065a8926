r"""Real materials: elastic constants, Burgers vector and work of adhesion, with a table.

The model (Adams, Müftü & Mohd Azhar) has **one elastic rough body on a rigid flat**:
:math:`E^* = E/(1-\nu^2)`, :math:`G^* = 2G`, :math:`E^*/G = 2/(1-\nu)`, forces in units of
:math:`Gb^2` and friction stresses in units of :math:`G^*`.  A :class:`Material` is such a
body: Young's modulus ``E`` (Pa), Poisson's ratio ``nu``, Burgers vector ``b`` (m), work of
adhesion ``w`` (J/m^2) and optionally the Dugdale range ``h`` (m) or stress ``sigma0`` (Pa),
the hardness ``H`` (Pa) and the Nix-Gao indentation-size-effect pair ``H0`` (Pa), ``h_star``
(m) for the elastic-plastic law (docs/plasticity.md).

**Two elastic bodies** (:func:`pair`).  Contact mechanics combines them into
:math:`E^* = [(1-\nu_1^2)/E_1 + (1-\nu_2^2)/E_2]^{-1}` (Hertz, Johnson 1985 §4.2) and the
paper's :math:`G^* = 2G_1G_2/(G_1+G_2)` (its Eq 2 normalisation).  The model only ever sees
:math:`E^*` (normal force, Eqs 6, 14-17) and :math:`G^*` (friction stress, Eq 2), linked by
:math:`E^*/G = 2/(1-\nu)` with :math:`G = G^*/2`.  So a pair is mapped onto an *equivalent
single body on a rigid flat* with

.. math::
    G = G^*/2,\qquad \nu_{eff} = 1 - G^*/E^*,\qquad E_{eff} = (1+\nu_{eff})\,G^*,

which reproduces both :math:`E^*` and :math:`G^*` exactly, so every formula of the model
(and ``N G b^2`` as the force unit) holds unchanged.  Why: the alternative of keeping one
body's :math:`\nu` would make :math:`E^*/G` inconsistent with the pair's :math:`E^*` and
:math:`G^*`, i.e. the normal and friction forces would be scaled by different moduli.  A
rigid second body recovers the body itself (:math:`\nu_{eff} = \nu`), and two identical
bodies give :math:`\nu_{eff} = \nu`, :math:`E^* = E/2(1-\nu^2)`, :math:`G^* = G`.
:math:`\nu_{eff}` must be a Poisson's ratio the model accepts, -1 < nu_eff < 0.5; a pair
outside raises :class:`ValueError` (it has no equivalent isotropic body).  Since
:math:`1-\nu_i = 2G_i(1-\nu_i^2)/E_i`, one finds
:math:`\nu_{eff} = (\nu_1/G_1 + \nu_2/G_2)/(1/G_1 + 1/G_2)`, the compliance-weighted mean
of the two Poisson's ratios, so two valid bodies always give a valid :math:`\nu_{eff}`;
the check only guards rounding at the limits.

The table ``asperity/data/materials.csv`` (:func:`material`, :func:`material_names`,
:func:`material_table`) holds handbook values with a source for every number; missing
values are empty, never guessed.

References
----------
.. [1] K. L. Johnson, *Contact Mechanics*, Cambridge University Press (1985), §4.2.
.. [2] Adams, Müftü, Mohd Azhar, Eqs (2), (6), (14)-(16).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, field

from ._validation import check_optional_positive, check_scalar_poisson, check_scalar_positive, check_text
from .material_table import TABLE_UNITS, material_names, material_table, table_row
from .units import format_si

__all__ = ["TABLE_UNITS", "Material", "as_material", "material", "material_names", "material_table", "pair"]

@dataclass(frozen=True)
class Material:
    r"""An elastic body against a rigid flat, in SI units.

    Parameters
    ----------
    name : str
        Label.
    E : float or pint.Quantity
        Young's modulus (Pa), > 0.
    nu : float
        Poisson's ratio, -1 < nu < 0.5.
    b : float or pint.Quantity, optional
        Burgers vector magnitude (m), > 0; None if unknown (a contact then needs one).
    w : float or pint.Quantity, optional
        Work of adhesion (J/m^2), >= 0; None if unknown.
    h : float or pint.Quantity, optional
        Dugdale range (m), > 0 (Maugis: :math:`w = \sigma_0 h`).  None: a contact uses
        :math:`h = b` as in the paper.
    sigma0 : float or pint.Quantity, optional
        Dugdale stress (Pa), > 0, an alternative to ``h`` (needs ``w``; sets
        :math:`h = w/\sigma_0`).  Giving both requires :math:`w = \sigma_0 h`.
    components : tuple of str
        For a :func:`pair`, the names of the two bodies; empty for one body.
    H : float or pint.Quantity, optional
        Hardness (Pa), > 0: the mean pressure of a fully plastic contact (the table lists
        Vickers hardness).  None if unknown (no plasticity index, no yield check).
    H0 : float or pint.Quantity, optional
        Nix-Gao large-indent hardness :math:`H_0` (Pa), > 0, paired with ``h_star``.
    h_star : float or pint.Quantity, optional
        Nix-Gao size-effect length :math:`h^*` (m), >= 0, paired with ``H0``.
    bodies : tuple of Material
        For a :func:`pair`, the two bodies themselves (their own ``E`` and ``nu``); empty
        for one body on a rigid flat.

    Attributes
    ----------
    G : float
        Shear modulus :math:`E/2(1+\nu)` (Pa).
    E_star : float
        Composite modulus against a rigid flat :math:`E/(1-\nu^2)` (Pa).
    G_star : float
        Effective shear modulus :math:`2G` (Pa), the unit of the friction stress (Eq 2).

    Examples
    --------
    >>> au = Material("Au", E=78e9, nu=0.44, b=2.885e-10, w=3.012)
    >>> round(au.G / 1e9, 2)
    27.08
    """

    name: str
    E: float
    nu: float
    b: float | None = None
    w: float | None = None
    h: float | None = None
    sigma0: float | None = None
    components: tuple[str, ...] = ()
    H: float | None = None
    H0: float | None = None
    h_star: float | None = None
    bodies: tuple[Material, ...] = field(default=(), repr=False, compare=False)

    def __post_init__(self):
        setattr_ = functools.partial(object.__setattr__, self)
        setattr_("name", check_text(self.name, "name"))
        setattr_("E", check_scalar_positive(self.E, "E", "Pa"))
        setattr_("nu", check_scalar_poisson(self.nu))
        setattr_("b", check_optional_positive(self.b, "b", "m"))
        setattr_("w", check_optional_positive(self.w, "w", "J/m^2", allow_zero=True))
        setattr_("h", check_optional_positive(self.h, "h", "m"))
        setattr_("sigma0", check_optional_positive(self.sigma0, "sigma0", "Pa"))
        if isinstance(self.components, str) or not isinstance(self.components, tuple | list):
            raise TypeError(f"components must be a tuple of two names, got {self.components!r}")
        setattr_("components", tuple(check_text(c, "components") for c in self.components))
        if not isinstance(self.bodies, tuple | list) or len(self.bodies) not in (0, 2) or \
                not all(isinstance(x, Material) for x in self.bodies):
            raise TypeError(f"bodies must be () or a tuple of two Materials, got {self.bodies!r}")
        setattr_("bodies", tuple(self.bodies))
        if self.bodies and not self.components:
            setattr_("components", tuple(x.name for x in self.bodies))
        setattr_("H", check_optional_positive(self.H, "H", "Pa"))
        setattr_("H0", check_optional_positive(self.H0, "H0", "Pa"))
        setattr_("h_star", check_optional_positive(self.h_star, "h_star", "m", allow_zero=True))
        self._check_dugdale()

    def _check_dugdale(self):
        if self.sigma0 is None:
            return
        if not self.w:
            raise ValueError(f"sigma0 (Dugdale stress) needs a positive work of adhesion w; "
                             f"{self.name!r} has w = {self.w!r}")
        h = self.w / self.sigma0
        if not 0.0 < h < math.inf:
            raise ValueError(f"sigma0 (Dugdale stress) = {self.sigma0:g} Pa with w = {self.w:g} J/m^2 gives a Dugdale "
                             f"range h = w/sigma0 = {h:g} m, not a positive finite double: give physical values")
        if self.h is None:
            object.__setattr__(self, "h", h)
        elif not math.isclose(self.h, h, rel_tol=1e-9):
            raise ValueError(f"h and sigma0 disagree: w = sigma0*h requires h = {h:.6g} m, got h = {self.h!r}")

    @property
    def G(self) -> float:
        """Shear modulus E/(2(1+nu)) in Pa."""
        return self.E / (2.0 * (1.0 + self.nu))

    @property
    def E_star(self) -> float:
        """Composite Young's modulus E/(1-nu^2) against a rigid flat, in Pa."""
        return self.E / (1.0 - self.nu**2)

    @property
    def G_star(self) -> float:
        """Effective shear modulus 2G in Pa (friction stresses are tau_f/G*)."""
        return 2.0 * self.G

    @property
    def is_pair(self) -> bool:
        """True for two elastic bodies (:func:`pair`), False for one body on a rigid flat."""
        return bool(self.bodies)

    def body_dict(self) -> dict:
        """This body alone: ``{'name', 'E_Pa', 'nu', 'rigid'}`` (``rigid`` is False)."""
        return {"name": self.name, "E_Pa": self.E, "nu": self.nu, "rigid": False}

    def describe(self) -> str:
        """One line naming the bodies in contact, e.g. ``'Au (E 78 GPa, nu 0.44) on a rigid flat'``."""
        def body(m):
            return f"{m.name} (E {format_si(m.E, 'Pa')}, nu {m.nu:.4g})"
        if self.bodies:
            return f"{body(self.bodies[0])} on {body(self.bodies[1])}"
        return f"{body(self)} on a rigid flat"

    def to_dict(self) -> dict:
        """Plain dict for strict JSON: ``name``, ``body1``, ``body2`` (``{'name': 'rigid flat',
        'rigid': True, ...}`` for one body), the equivalent body's ``E_Pa``, ``nu``, ``E_star_Pa``,
        ``G_star_Pa`` and ``b_m``, ``w_J_m2``, ``h_m``, ``sigma0_Pa`` (None where unknown)."""
        one, two = self.bodies if self.bodies else (self, None)
        rigid = {"name": "rigid flat", "E_Pa": None, "nu": None, "rigid": True}
        return {"name": self.name, "body1": one.body_dict(), "body2": rigid if two is None else two.body_dict(),
                "E_Pa": self.E, "nu": self.nu, "E_star_Pa": self.E_star, "G_star_Pa": self.G_star,
                "b_m": self.b, "w_J_m2": self.w, "h_m": self.h, "sigma0_Pa": self.sigma0}



def as_material(body, name: str = "body") -> Material:
    """A :class:`Material` from a Material (returned as is) or a table name (:func:`material`).

    Parameters
    ----------
    body : Material or str
        The body, or its name in the table (case-insensitive; pairs such as ``'Au/Au'``).
    name : str
        Parameter name for the error message.

    Returns
    -------
    Material

    Raises
    ------
    TypeError
        If ``body`` is neither a Material nor a string.
    ValueError
        For a name not in the table (the message lists the known ones).
    """
    if isinstance(body, Material):
        return body
    if isinstance(body, str):
        try:
            return material(body)
        except ValueError as err:
            raise ValueError(f"{name}: {err}") from None
    raise TypeError(f"{name} must be an asperity.materials.Material or a material name from the table "
                    f"(e.g. 'Au'), got {type(body).__name__} {body!r}")


def _pair_b(first: Material, second: Material, b):
    if b is not None:
        return b
    known = {x for x in (first.b, second.b) if x is not None}
    if len(known) > 1 and not math.isclose(first.b, second.b, rel_tol=1e-9):
        raise ValueError(f"{first.name!r} and {second.name!r} have different Burgers vectors "
                         f"({first.b:.4g} m, {second.b:.4g} m); pass b= explicitly (command line: --b)")
    return first.b if first.b is not None else second.b


def _effective_poisson(one: Material, two: Material) -> float:
    """1 - G*/E* as the 1/G-weighted mean of the two Poisson's ratios (no cancellation)."""
    mean = (one.nu / one.G + two.nu / two.G) / (1.0 / one.G + 1.0 / two.G)
    return min(max(mean, min(one.nu, two.nu)), max(one.nu, two.nu))  # a mean: rounding only


def _check_effective_poisson(nu_eff: float, label: str) -> float:
    if not -1.0 < nu_eff < 0.5:
        raise ValueError(f"pair {label!r}: effective Poisson's ratio nu_eff = 1 - G*/E* = {nu_eff:.6g} "
                         "lies outside (-1, 0.5); no equivalent isotropic body on a rigid flat exists")
    return nu_eff


def pair(first, second, *, w=None, b=None, h=None, H=None, name: str | None = None) -> Material:
    r"""The equivalent single body (on a rigid flat) of two elastic bodies in contact.

    Parameters
    ----------
    first, second : Material or str
        The two bodies (a name is looked up with :func:`material`).
    w : float or pint.Quantity, optional
        Work of adhesion of the interface (J/m^2).  Default: for two bodies of the same
        name, that body's ``w`` (its self-adhesion); otherwise None (unknown; Dupré's
        :math:`\gamma_1+\gamma_2-\gamma_{12}` needs the interface energy).
    b : float or pint.Quantity, optional
        Burgers vector (m).  Default: the bodies' common ``b``, or the one that is known;
        different values raise :class:`ValueError` (choose one explicitly).
    h : float or pint.Quantity, optional
        Dugdale range (m).
    H : float or pint.Quantity, optional
        Hardness of the pair (Pa) for the elastic-plastic law.  Default: for two bodies of
        the same name, that body's ``H`` (with its ``H0``, ``h_star``); otherwise None
        (unknown: which body yields, and how, is the user's to say).
    name : str, optional
        Default ``"first/second"``.

    Returns
    -------
    Material
        With :math:`E^* = [(1-\nu_1^2)/E_1 + (1-\nu_2^2)/E_2]^{-1}`,
        :math:`G^* = 2G_1G_2/(G_1+G_2)`,
        :math:`\nu = 1 - G^*/E^* = (\nu_1/G_1 + \nu_2/G_2)/(1/G_1 + 1/G_2)`,
        :math:`E = (1+\nu)G^*`, so that ``E_star`` and ``G_star`` are the pair's.

    Raises
    ------
    ValueError
        If :math:`\nu_{eff} = 1 - G^*/E^*` lies outside (-1, 0.5), or the Burgers vectors
        differ and ``b`` is not given.

    References
    ----------
    Johnson, *Contact Mechanics* (1985) §4.2; Adams et al., Eq (2) (:math:`G^*`).
    """
    one, two = as_material(first, "first"), as_material(second, "second")
    for body, what in ((one, "first"), (two, "second")):
        if body.bodies:
            raise ValueError(f"{what} must be one body, got the pair {body.name!r}")
    g_star = 2.0 * one.G * two.G / (one.G + two.G)
    label = f"{one.name}/{two.name}" if name is None else check_text(name, "name")
    nu_eff = _check_effective_poisson(_effective_poisson(one, two), label)
    same = one.name.lower() == two.name.lower()
    if w is None and same:
        w = one.w
    H0, h_star = (one.H0, one.h_star) if same and H is None else (None, None)
    if H is None and same:
        H = one.H
    return Material(label, E=(1.0 + nu_eff) * g_star, nu=nu_eff, b=_pair_b(one, two, b), w=w, h=h,
                    components=(one.name, two.name), H=H, H0=H0, h_star=h_star, bodies=(one, two))


def material(name: str) -> Material:
    """The :class:`Material` of a table row (case-insensitive name), or of two rows ``'A/B'``.

    A single body (``'Au'``) is that body **on a rigid flat**.  A pair row (e.g.
    ``'Au/Au'``, ``'Au/mica'``) gives :func:`pair` of its components with the row's work
    of adhesion (None where the table has none).  Any other ``'A/B'`` of two table names
    gives :func:`pair` of the two bodies: its work of adhesion is the body's own for
    ``A == B`` and unknown (None) otherwise, and the Burgers vectors must agree.

    Parameters
    ----------
    name : str
        A name from :func:`material_names`, or ``'A/B'`` of two of them.

    Returns
    -------
    Material

    Raises
    ------
    TypeError
        If ``name`` is not a string.
    ValueError
        For an unknown name (the message lists the known ones) or a row without ``E``/``nu``.

    Examples
    --------
    >>> material("au").b
    2.885e-10
    >>> material("Au/Au").components
    ('Au', 'Au')
    """
    check_text(name, "name")
    row = table_row(name)
    if row is None:
        parts = name.split("/")
        if len(parts) != 2 or not all(p.strip() for p in parts) or any(table_row(p) is None for p in parts):
            raise ValueError(f"unknown material {name!r}; known: {', '.join(material_names())} "
                             "(or two of them as 'A/B')")
        try:
            return pair(*(material(p.strip()) for p in parts))
        except ValueError as err:
            raise ValueError(f"{name}: {err} (e.g. asperity.bodies.contact_material({name!r}, b=...))") from None
    if row["kind"] == "pair":
        first, second = row["components"].split(";")
        return pair(first, second, w=row["work_of_adhesion_J_m2"], name=row["name"])
    if row["E_Pa"] is None or row["nu"] is None:
        raise ValueError(f"material {row['name']!r} has no E/nu in the table")
    return Material(row["name"], E=row["E_Pa"], nu=row["nu"], b=row["b_m"], w=row["work_of_adhesion_J_m2"],
                    H=row["hardness_Pa"], H0=row["ise_H0_Pa"], h_star=row["ise_h_star_m"])


