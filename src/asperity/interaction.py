r"""Interaction between asperities: the mean-field correction of Greenwood-Williamson.

The Greenwood-Williamson (GW) model lets every asperity deform on its own: the
displacement of one asperity does not feel the pressure on its neighbours.  Ciavarella,
Greenwood & Paggi (2008) include that interaction in the simplest consistent way: the
pressure carried by all asperity contacts is spread uniformly over the nominal area
:math:`A_0` as the nominal pressure :math:`\bar p = P/A_0`, and the deformation it
causes, treated as uniform, is added to every asperity.  The surface sinks by

.. math::
    \Delta = c_A\,\frac{\bar p\,\sqrt{A_0}}{E^*}, \qquad
    c_A = \frac{16}{3\pi^{3/2}} \approx 0.9578 ,

the mean displacement of a uniformly loaded circle of area :math:`A_0`
(radius :math:`a_0 = \sqrt{A_0/\pi}`, mean displacement :math:`16\bar p a_0/3\pi E^*`,
Johnson 1985, §3.4) (:func:`cgp_shift`), so an asperity of height :math:`z` is
compressed by :math:`z - d - \Delta` when the flat stands at :math:`d` from the
*undeformed* mean summit plane.  The GW integrals are evaluated at the local separation
:math:`d_{loc} = d + \Delta(P)`, solved together with the load.  In the model's units
(separation over :math:`\sigma_s`, load over :math:`NGb^2`, :math:`E^*/G = 2/(1-\nu)`)

.. math::
    \frac{\Delta}{\sigma_s} = k\,\bar P,\qquad
    k = c_A\,\frac{1-\nu}{2}\,\frac{\eta\,b^2\sqrt{A_0}}{\sigma_s}
    \quad(:func:`cgp_compliance`).

What it changes, and what it does not (Ciavarella et al. 2008, abstract and §3):

* the load and the real area at a given separation fall (the separation is, in effect,
  larger by :math:`\Delta`); the approach needed to carry a load grows;
* **the area-load relation is unchanged**: at a given load every asperity sits at the
  same local separation as in plain GW, so the areas, the number of contacts and the
  friction (Hurtado-Kim on each contact's radius) under load control are plain GW's;
* the correction grows without bound with :math:`\sqrt{A_0}`: it is the long-range,
  "cluster" part of the elastic interaction (the parallel the authors draw with the
  Holm-Greenwood clustering term of constriction resistance).

Assumptions: non-adhesive, elastic contact (the source treats no adhesion, so an
adhesive model refuses it); a nominally flat contact under uniform nominal pressure;
deformation spread uniformly (no local clustering of contacts); the nominal area a
circle (a square of the same area has a mean compliance 1.2 % lower: :math:`c_A = 0.9464`).  In a periodic
boundary-element cell the uniform part of the displacement is a rigid shift of the
mean plane: it leaves the real area, the spots and the mean gap of the deformed
surfaces unchanged, and shows only in the approach of the flat to the undeformed surface.

Selection by name: :data:`INTERACTIONS` maps ``'none'`` (plain GW, the default) and
``'cgp2008'`` to their classes; :func:`as_interaction` checks a value and
:func:`interaction_for_surface` builds one from SI surface data.

References
----------
.. [1] M. Ciavarella, J. A. Greenwood, M. Paggi, "Inclusion of 'interaction' in the
   Greenwood and Williamson contact theory", Wear 265 (2008) 729-734.
.. [2] K. L. Johnson, *Contact Mechanics*, Cambridge University Press (1985), §3.4
   (uniform pressure on a circular region: mean displacement :math:`16pa/3\pi E^*`).
.. [3] J. A. Greenwood, J. B. P. Williamson, Proc. R. Soc. A 295 (1966) 300-319.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ._validation import (
    as_float_array,
    check_broadcast,
    check_finite_result,
    check_poisson,
    check_positive,
    check_scalar_positive,
    scalar,
)
from .units import to_si

__all__ = [
    "CGP_MEAN_COMPLIANCE",
    "NoInteraction",
    "MeanFieldInteraction",
    "INTERACTIONS",
    "interaction_names",
    "as_interaction",
    "interaction_for_surface",
    "cgp_shift",
    "cgp_compliance",
]

#: :math:`c_A = 16/(3\pi^{3/2})`: mean displacement of a uniformly loaded circle of area
#: :math:`A_0` in units of :math:`\bar p\sqrt{A_0}/E^*` (Johnson 1985, §3.4).
CGP_MEAN_COMPLIANCE = 16.0 / (3.0 * math.pi**1.5)


def cgp_shift(p, area, E_star):
    r"""Uniform sinking of the surface under the nominal pressure (Ciavarella et al. 2008).

    .. math::
        \Delta = c_A\,\frac{\bar p\sqrt{A_0}}{E^*},\qquad c_A = \frac{16}{3\pi^{3/2}}

    the mean displacement of a circle of area :math:`A_0` under the uniform pressure
    :math:`\bar p` (Johnson 1985, §3.4), added to the separation of every asperity.

    Parameters
    ----------
    p : array_like
        Nominal pressure :math:`\bar p = P/A_0` [Pa], real and finite (negative: tensile).
    area : array_like
        Nominal contact area :math:`A_0` [m^2], > 0.
    E_star : array_like
        Composite Young's modulus :math:`E^*` [Pa], > 0.

    Returns
    -------
    float or ndarray
        :math:`\Delta` [m]: a float for scalar inputs, else the broadcast shape of the inputs.

    References
    ----------
    Ciavarella, Greenwood & Paggi, Wear 265 (2008) 729, §2; Johnson (1985), §3.4.

    Examples
    --------
    >>> round(cgp_shift(1e6, 1e-6, 1e11) * 1e9, 4)  # 1 MPa over 1 mm^2 on E* = 100 GPa: nm
    9.578
    """
    p = as_float_array(to_si(p, "Pa", "p"), "p", allow_empty=True)
    area = check_positive(to_si(area, "m^2", "area"), "area")
    E_star = check_positive(to_si(E_star, "Pa", "E_star"), "E_star")
    check_broadcast(p=p, area=area, E_star=E_star)
    with np.errstate(all="ignore"):
        out = CGP_MEAN_COMPLIANCE * p * np.sqrt(area) / E_star
    out = check_finite_result(out, "the shift Delta", p=p, area=area, E_star=E_star)
    return float(out) if out.ndim == 0 else out


def cgp_compliance(eta, area, b, sigma_s, nu=0.3) -> float:
    r"""Dimensionless mean-field compliance :math:`k` of Ciavarella et al. (2008), model units.

    .. math::
        \frac{\Delta}{\sigma_s} = k\,\frac{P}{NGb^2},\qquad
        k = c_A\,\frac{1-\nu}{2}\,\frac{\eta\,b^2\sqrt{A_0}}{\sigma_s}

    from :func:`cgp_shift` with :math:`\bar p = NGb^2\bar P/A_0 = \eta Gb^2\bar P` and the
    model's :math:`E^* = 2G/(1-\nu)`.

    Parameters
    ----------
    eta : float
        Summit density :math:`\eta` [1/m^2], > 0.
    area : float
        Nominal area :math:`A_0` [m^2], > 0.
    b : float
        Burgers vector :math:`b` [m] (the model's length unit), > 0.
    sigma_s : float
        Standard deviation of summit heights :math:`\sigma_s` [m], > 0.
    nu : float
        Poisson's ratio, -1 < nu < 0.5 (default 0.3).

    Returns
    -------
    float
        :math:`k \ge 0` [-]: :math:`\sigma_s` of uniform sinking per unit of :math:`P/(NGb^2)`.

    References
    ----------
    Ciavarella, Greenwood & Paggi, Wear 265 (2008) 729.
    """
    eta = check_scalar_positive(eta, "eta", "1/m^2")
    area = check_scalar_positive(area, "area", "m^2")
    b = check_scalar_positive(b, "b", "m")
    sigma_s = check_scalar_positive(sigma_s, "sigma_s", "m")
    nu = scalar(check_poisson(nu), "nu")
    with np.errstate(all="ignore"):
        k = np.float64(CGP_MEAN_COMPLIANCE * (1.0 - nu) / 2.0 * eta) * b * b * math.sqrt(area) / sigma_s
    return float(check_finite_result(k, "the compliance k", eta=eta, area=area, b=b, sigma_s=sigma_s))


@dataclass(frozen=True)
class NoInteraction:
    """Independent asperities (plain Greenwood-Williamson): no shift."""

    name = "none"
    active = False

    def shift(self, P):
        """Uniform sinking :math:`\\Delta/\\sigma_s` under loads ``P`` (model units): zero."""
        return np.zeros_like(np.asarray(P, dtype=float))


@dataclass(frozen=True)
class MeanFieldInteraction:
    r"""Uniform mean-field interaction of Ciavarella, Greenwood & Paggi (2008), model units.

    Parameters
    ----------
    compliance : float
        :math:`k \ge 0`: uniform sinking :math:`\Delta/\sigma_s = k P/(NGb^2)`
        (:func:`cgp_compliance`); 0 is plain GW.

    Notes
    -----
    Under load control the local separation is plain GW's and the reported (apparent)
    separation is :math:`d = d_{loc} - kP`; under separation control
    :math:`d_{loc} - k\bar P(d_{loc}) = d` is solved by :meth:`local_separation`.
    """

    compliance: float
    name = "cgp2008"

    def __post_init__(self):
        k = check_scalar_positive(self.compliance, "compliance", allow_zero=True)
        object.__setattr__(self, "compliance", k)

    @property
    def active(self) -> bool:
        """Whether the correction changes anything (compliance > 0)."""
        return self.compliance > 0.0

    def shift(self, P):
        """Uniform sinking :math:`\\Delta/\\sigma_s = kP` under loads ``P`` (model units)."""
        return self.compliance * np.asarray(P, dtype=float)

    def local_separation(self, d, load):
        r"""Local separations :math:`d_{loc}` with :math:`d_{loc} - k\bar P(d_{loc}) = d`.

        Parameters
        ----------
        d : ndarray
            Apparent separations :math:`d/\sigma_s` (from the undeformed mean summit plane).
        load : callable
            ``load(x) -> (P, dP/dx)`` of plain GW at local separations ``x`` (arrays),
            with :math:`P \ge 0` decreasing (non-adhesive).

        Returns
        -------
        ndarray
            :math:`d_{loc} \ge d`, to 1e-12 relative.  The root is unique:
            :math:`x - k\bar P(x)` increases with :math:`x`.
        """
        d = np.asarray(d, dtype=float)
        lo = d.copy()
        hi = d + self.compliance * load(d)[0]
        x = hi.copy()
        for _ in range(100):
            P, dP = load(x)
            g = x - self.compliance * P - d
            lo = np.where(g <= 0, x, lo)
            hi = np.where(g >= 0, x, hi)
            with np.errstate(divide="ignore", invalid="ignore"):
                step = x - g / (1.0 - self.compliance * dP)
            inside = np.isfinite(step) & (step > lo) & (step < hi)
            x_new = np.where(inside, step, 0.5 * (lo + hi))
            if np.all(np.abs(x_new - x) <= 1e-12 * np.maximum(1.0, np.abs(x))):
                return x_new
            x = x_new
        return x


#: Interaction corrections by name: ``'none'`` (plain GW) and ``'cgp2008'``.
INTERACTIONS = {"none": NoInteraction, "cgp2008": MeanFieldInteraction}


def interaction_names() -> list[str]:
    """Names of :data:`INTERACTIONS`, for menus and command-line choices."""
    return list(INTERACTIONS)


def _unknown(value) -> ValueError:
    return ValueError(f"interaction must be one of {', '.join(map(repr, INTERACTIONS))}, "
                      f"None, or an interaction object, got {value!r}")


def as_interaction(value, *, adhesive: bool = False):
    """An interaction object from ``value`` (None, ``'none'`` or an interaction object).

    Parameters
    ----------
    value : None, str, NoInteraction or MeanFieldInteraction
        ``None`` or ``'none'``: plain GW.  A named correction needs physical surface data:
        build it with :func:`interaction_for_surface` (as
        :class:`~asperity.physical.PhysicalContact` does).
    adhesive : bool
        Whether the model has adhesion; the mean-field correction of Ciavarella et al.
        (2008) is non-adhesive and is refused then.

    Raises
    ------
    ValueError
        For an unknown name, a named correction without its data, or adhesion with an
        active correction.
    """
    if value is None:
        return NoInteraction()
    if isinstance(value, str):
        key = value.strip().lower()
        if key == "none":
            return NoInteraction()
        if key in INTERACTIONS:
            raise ValueError(f"interaction {value!r} needs the surface's eta, A0, b and sigma_s: pass "
                             f"MeanFieldInteraction(cgp_compliance(...)), or use PhysicalContact(..., "
                             f"interaction={key!r})")
        raise _unknown(value)
    if not isinstance(value, NoInteraction | MeanFieldInteraction):
        raise _unknown(value)
    if adhesive and value.active:
        raise ValueError(f"interaction {value.name!r} (Ciavarella, Greenwood & Paggi 2008) is derived for "
                         "non-adhesive contact; use gamma = 0 (adhesion=False) or interaction='none'")
    return value


def interaction_for_surface(name, *, eta, area, b, sigma_s, nu=0.3):
    """The interaction ``name`` of :data:`INTERACTIONS` for a surface in SI units.

    Parameters
    ----------
    name : str or None
        ``'none'`` (or None) or ``'cgp2008'``; an interaction object is returned unchanged.
    eta, area, b, sigma_s : float
        Summit density [1/m^2], nominal area [m^2], Burgers vector [m], summit height
        deviation [m], all > 0 (see :func:`cgp_compliance`).
    nu : float
        Poisson's ratio (default 0.3).

    Returns
    -------
    NoInteraction or MeanFieldInteraction

    Raises
    ------
    ValueError
        For an unknown name.
    """
    if name is None or isinstance(name, NoInteraction | MeanFieldInteraction):
        return as_interaction(name)
    if not isinstance(name, str) or name.strip().lower() not in INTERACTIONS:
        raise _unknown(name)
    if name.strip().lower() == "none":
        return NoInteraction()
    return MeanFieldInteraction(cgp_compliance(eta, area, b, sigma_s, nu))
