r"""Plasticity of a physical contact: the plasticity index, the yield check and its warning.

A rough surface of summit radius :math:`R` and summit-height deviation :math:`\sigma_s`
pressed by a flat yields where asperities pass the critical interference
:math:`\omega_c`.  Greenwood and Williamson's plasticity index

.. math::
    \psi = \frac{E^*}{H}\Big(\frac{\sigma_s}{R}\Big)^{1/2} = \frac{\alpha}{H/E^*}

says how soon: for :math:`\psi < 0.6` hardly any asperity yields at any practical load, for
:math:`\psi > 1` most contacts are plastic even under light loads (GW 1966).  Chang, Etsion
and Bogy write the same group as :math:`\psi_{CEB} = (\sigma_s/\omega_c)^{1/2}` with their
:math:`\omega_c`; with Jackson and Green's :math:`\omega_c` it is
:math:`\bar u_c^{-1/2} = \psi\,2\cdot2.84/(\pi C)` (:func:`~asperity.elastic_plastic.critical_penetration`),
:math:`1.12\,\psi` at :math:`\nu = 0.3`.

:class:`~asperity.physical.PhysicalContact` computes :math:`\psi` from the material's
hardness and reports, on every curve, the number of asperities past :math:`\omega_c` (the
column ``plastic``).  With the elastic model in use it warns (:class:`PlasticityWarning`)
when, at some point of a curve, more than a threshold share of the asperities in contact
(default :data:`PLASTIC_THRESHOLD` = 1 %) is past :math:`\omega_c`: the elastic answer then
does not apply.  The warning is a normal Python warning, so it can be filtered::

    import warnings, asperity
    warnings.simplefilter("ignore", asperity.PlasticityWarning)

References
----------
.. [1] J. A. Greenwood, J. B. P. Williamson, "Contact of nominally flat surfaces",
   Proc. R. Soc. A 295 (1966) 300-319 (the plasticity index).
.. [2] W. R. Chang, I. Etsion, D. B. Bogy, "An elastic-plastic model for the contact of
   rough surfaces", J. Tribol. 109 (1987) 257-263.
.. [3] R. L. Jackson, I. Green, J. Tribol. 127 (2005) 343-354.
"""

from __future__ import annotations

import functools
import warnings

import numpy as np

from ._validation import (
    check_broadcast,
    check_finite_result,
    check_nonnegative,
    check_positive,
    check_scalar_positive,
)
from ._validation_files import short_repr
from ._warnings import AsperityWarning
from .elastic_plastic import LAWS, critical_penetration, plastic_fraction
from .materials import Material
from .units import to_si

__all__ = ["PlasticityWarning", "PLASTIC_THRESHOLD", "plasticity_index", "plastic_share", "resolve_plasticity",
           "check_yield", "ContactPlasticity"]

#: Default share of the asperities in contact past the critical interference above which
#: a curve computed with the elastic model warns (:class:`PlasticityWarning`).
PLASTIC_THRESHOLD = 0.01


class PlasticityWarning(AsperityWarning):
    """The elastic model was used where a noticeable share of the asperities has yielded."""


def plasticity_index(E_star, H, sigma_s, R):
    r"""Greenwood-Williamson plasticity index :math:`\psi = (E^*/H)(\sigma_s/R)^{1/2}`.

    .. math::
        \psi = \frac{E^*}{H}\sqrt{\frac{\sigma_s}{R}}

    Parameters
    ----------
    E_star : array_like
        Composite modulus :math:`E^*` (Pa), > 0.
    H : array_like
        Hardness :math:`H` (Pa), > 0.
    sigma_s : array_like
        Standard deviation of summit heights :math:`\sigma_s` (m), > 0.
    R : array_like
        Summit radius :math:`R` (m), > 0.

    Returns
    -------
    float or ndarray
        :math:`\psi` (dimensionless), broadcast over the inputs.

    Raises
    ------
    ValueError
        If an input is not real, finite and positive.

    Examples
    --------
    >>> round(plasticity_index(100e9, 1e9, 4e-9, 1e-6), 12)  # 100 * sqrt(4e-3)
    6.324555320337

    References
    ----------
    Greenwood & Williamson (1966), the plasticity index.
    """
    E_star, H = check_positive(to_si(E_star, "Pa", "E_star"), "E_star"), check_positive(to_si(H, "Pa", "H"), "H")
    sigma_s, R = check_positive(to_si(sigma_s, "m", "sigma_s"), "sigma_s"), check_positive(to_si(R, "m", "R"), "R")
    check_broadcast(E_star=E_star, H=H, sigma_s=sigma_s, R=R)
    with np.errstate(all="ignore"):
        out = E_star / H * np.sqrt(sigma_s / R)
    out = check_finite_result(out, "the plasticity index psi", E_star=E_star, H=H, sigma_s=sigma_s, R=R)
    return float(out) if out.ndim == 0 else out


def plastic_share(plastic, contacts):
    r"""Share of the asperities in contact that are past the critical interference, :math:`n_p/n`.

    .. math::
        \frac{n_p}{n} = \frac{\int_{\bar d + \bar u_c}^\infty\phi}{\int_{\bar d}^\infty\phi}

    Parameters
    ----------
    plastic : array_like
        Asperities past the critical interference (a fraction or a number), >= 0.
    contacts : array_like
        Asperities in contact, in the same unit, >= ``plastic``.

    Returns
    -------
    ndarray
        The share in [0, 1]; 0 where nothing touches.

    Raises
    ------
    ValueError
        If an input is not real and finite, or negative, the shapes do not broadcast, or
        ``plastic`` exceeds ``contacts``.

    Examples
    --------
    >>> plastic_share([0.0, 0.1], [0.0, 0.4]).tolist()
    [0.0, 0.25]

    References
    ----------
    Greenwood & Williamson (1966); docs/plasticity.md (the yield check).
    """
    plastic = check_nonnegative(plastic, "plastic")
    contacts = check_nonnegative(contacts, "contacts")
    check_broadcast(plastic=plastic, contacts=contacts)
    # the two integrals round apart (all plastic is 1, not 1 + 1e-16); beyond rounding, more
    # plastic contacts than contacts is a mistake
    if np.any(plastic > contacts * (1.0 + 1e-6)):
        raise ValueError("plastic (contacts beyond yield) must not exceed contacts, got "
                         f"plastic = {short_repr(plastic)} for contacts = {short_repr(contacts)}")
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        share = np.where(contacts > 0, plastic / np.where(contacts > 0, contacts, 1.0), 0.0)
    return np.minimum(share, 1.0)


def resolve_plasticity(material: Material, plasticity, hardness, size_effect, h_star):
    """The law name, hardness (Pa or None) and Nix-Gao length (m) of a physical contact.

    Without the size effect the hardness is ``hardness`` or the material's ``H``; with it
    (``size_effect=True``, or ``h_star`` given) it is :math:`H_0` = ``hardness`` or the
    material's ``H0``, and :math:`h^*` = ``h_star`` or the material's.

    Raises
    ------
    ValueError
        For an unknown law, a law that needs a hardness without one, ``size_effect=False``
        with ``h_star``, or a size effect without :math:`H_0` or :math:`h^*`.
    """
    name = "elastic" if plasticity is None else plasticity
    if not isinstance(name, str) or name.strip().lower().replace("_", "-") not in LAWS:
        raise ValueError(f"plasticity must be a law name, one of {', '.join(LAWS)}, got {plasticity!r}")
    name = name.strip().lower().replace("_", "-")
    if h_star is not None:
        h_star = check_scalar_positive(h_star, "h_star", "m", allow_zero=True)
    if size_effect is None:
        size_effect = h_star is not None and h_star > 0.0  # h_star = 0: no size effect
    if not isinstance(size_effect, bool):
        raise ValueError(f"size_effect must be True, False or None, got {size_effect!r}")
    if not size_effect:
        if h_star:
            raise ValueError("h_star (Nix-Gao length) needs size_effect=True (or None)")
        H = material.H if hardness is None else check_scalar_positive(hardness, "hardness", "Pa")
        h = 0.0
    else:
        H = material.H0 if hardness is None else check_scalar_positive(hardness, "hardness (H0)", "Pa")
        h = material.h_star if h_star is None else h_star
        lacking = [(keyword, option) for value, keyword, option in (
            (H, "hardness= (H0, Pa)", "--hardness"), (h, "h_star= (m)", "--h-star")) if value is None]
        if lacking:
            advice = " and ".join(keyword for keyword, _ in lacking)
            options = ", ".join(option for _, option in lacking)
            raise ValueError(f"size_effect=True (the size effect) needs the Nix-Gao pair H0 and h_star; material "
                             f"{material.name!r} has H0 = {material.H0!r}, h_star = {material.h_star!r}: give "
                             f"{advice} (command line: {options})")
    if LAWS[name].plastic and H is None:
        raise ValueError(f"plasticity={name!r} needs a hardness: material {material.name!r} has none; "
                         "give hardness= (Pa) (command line: --hardness)")
    return name, H, h


def check_yield(share, *, threshold, psi, critical_interference, law: str, stacklevel: int = 3) -> None:
    """Warn (:class:`PlasticityWarning`) if the elastic law is in use and ``max(share) > threshold``.

    Parameters
    ----------
    share : array_like
        Share of the asperities in contact past the critical interference, per point.
    threshold : float
        Largest share tolerated in [0, 1].
    psi : float
        Plasticity index, for the message.
    critical_interference : float
        :math:`\\omega_c` (m), for the message.
    law : str
        The law in use; only ``'elastic'`` warns.
    stacklevel : int
        Passed to :func:`warnings.warn`.
    """
    share = np.asarray(share, dtype=float)
    if law != "elastic" or share.size == 0:
        return
    worst = float(np.max(share))
    if worst > threshold:
        warnings.warn(PlasticityWarning(
            f"up to {worst:.1%} of the asperities in contact are past the critical interference for yield "
            f"(omega_c = {critical_interference:.3g} m, plasticity index psi = {psi:.3g}) but the model is elastic: "
            f"use plasticity='jackson-green' without adhesion (command line: --law jackson-green --no-adhesion), "
            f"or filter asperity.PlasticityWarning (threshold {threshold:.3g}: plastic_threshold=)"),
            stacklevel=stacklevel)


class ContactPlasticity:
    """Plasticity of a contact, for :class:`~asperity.physical.PhysicalContact` (a mixin).

    Uses the contact's ``hardness`` (Pa or None), ``h_star`` (m), ``material``, ``E_star``,
    ``nu``, ``alpha``, ``surface``, ``heights``, ``law`` and ``plastic_threshold``.
    """

    @property
    def H_over_E(self) -> float | None:
        """Hardness over composite modulus H/E* (H0/E* with the size effect); None without a hardness."""
        return None if self.hardness is None else self.hardness / self.E_star

    @property
    def plasticity_index(self) -> float:
        """Greenwood-Williamson plasticity index (E*/H)(sigma_s/R)^(1/2) (H0 with the size effect).

        Raises
        ------
        ValueError
            If the contact has no hardness.
        """
        if self.hardness is None:
            raise ValueError(f"material {self.material.name!r} has no hardness: give hardness= (Pa) "
                             "(command line: --hardness)")
        return plasticity_index(self.E_star, self.hardness, self.surface.sigma_s, self.surface.R)

    @functools.cached_property
    def u_c(self) -> float | None:
        """Critical penetration omega_c/sigma_s (Jackson-Green, with the size effect); None if unknown."""
        if self.hardness is None or not 0.0 <= self.nu < 0.5:
            return None
        return critical_penetration(self.alpha, self.nu, self.H_over_E, self.h_star / self.surface.sigma_s)

    @property
    def critical_interference(self) -> float | None:
        """Interference omega_c (m) at which an asperity starts to yield; None without a hardness
        (or for nu < 0, outside Jackson-Green's C(nu))."""
        return None if self.u_c is None else self.u_c * self.surface.sigma_s

    def warn_if_yielding(self, d_local, contacts, *, stacklevel: int = 2) -> None:
        """One :class:`~asperity.PlasticityWarning` if, at a separation ``d_local`` (:math:`d/\\sigma_s`,
        as the asperities feel it), more than :attr:`plastic_threshold` of the ``contacts``
        (:math:`n/N`) are past the critical interference; nothing for an elastic-plastic law (its
        curves carry the ``plastic`` column) or without a hardness."""
        if self.u_c is not None:
            check_yield(plastic_share(plastic_fraction(d_local, self.u_c, self.heights), contacts),
                        threshold=self.plastic_threshold, psi=self.plasticity_index,
                        critical_interference=self.critical_interference, law=self.law, stacklevel=stacklevel + 1)
