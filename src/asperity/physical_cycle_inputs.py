r"""The inputs of a physical cycle, checked in SI units before the model sees them.

:func:`asperity.physical_cycle.physical_cycle` takes lengths in metres, forces in newtons
and a spring stiffness in N/m, and runs the dimensionless cycle (:mod:`asperity.cycle_run`)
on :math:`\bar d = d/\sigma_s`, :math:`\bar P = P/(NGb^2)`, :math:`\bar k = k\sigma_s/(NGb^2)`.
What can be checked in the user's units is checked here, so that an error names the value
the user gave (a closest approach of -1 m is reported in metres, not as
:math:`-5\times10^8\,\sigma_s`): the lengths (:func:`length_input`), the spring
(:func:`cycle_stiffness`), the jump-in penetration (:func:`cycle_u_in`) and the separations
of the cycle (:func:`check_cycle_separations`).  Anything the model still refuses is
reported with the two scales (:func:`scaled_error`).

References
----------
.. [1] Adams et al., Eqs (7), (16), (17) (the scales :math:`\sigma_s`, :math:`NGb^2`).
"""

from __future__ import annotations

import math

import numpy as np

from ._validation import as_float_array, check_scalar_positive, scalar
from .instrument import STIFFNESS_MIN, UnstableClosestApproach
from .physical import PhysicalContact
from .tabulation import D_MIN
from .units import to_si

__all__ = ["length_input", "infinite_stiffness", "cycle_stiffness", "cycle_u_in", "check_cycle_separations",
           "scaled_error"]


def length_input(value, name: str, required: bool = False):
    """A length in metres from a number (m), a string with a unit or a pint quantity.

    Parameters
    ----------
    value : float, str, pint.Quantity or None
        The length (None: not given).
    name : str
        Its name, for the messages.
    required : bool
        Whether None is refused.

    Returns
    -------
    float or None

    Raises
    ------
    TypeError, ValueError
        For None when required, a value that is not one finite length.
    """
    if value is None and required:
        raise TypeError(f"{name} must be a length (m, or a pint length), got None")
    return None if value is None else float(scalar(as_float_array(to_si(value, "m", name), name), name))


def infinite_stiffness(text: str, name: str = "stiffness") -> bool:
    """Whether ``text`` spells an infinite stiffness (displacement control), with or without a
    stiffness unit: ``'inf'``, ``'Infinity'``, ``'+inf'``, ``'infN/m'``, ``'inf nN/nm'``.

    Parameters
    ----------
    text : str
        The stiffness as written.
    name : str
        Its name, for the message.

    Returns
    -------
    bool
        True for an infinite stiffness; False for anything else (a finite value, ``'-inf'``).

    Raises
    ------
    TypeError
        For ``text`` that is not a string.
    ValueError
        For infinity followed by something that is not a unit of stiffness (``'infkg'``).
    """
    if not isinstance(text, str):
        raise TypeError(f"{name} must be a string here, got {type(text).__name__} {text!r}")
    stripped = text.strip()
    for word in ("+infinity", "infinity", "+inf", "inf"):
        if stripped.lower().startswith(word):
            rest = stripped[len(word):].strip()
            if rest:  # a unit: it must be one of stiffness
                try:
                    to_si(f"1 {rest}", "N/m", name)
                except ValueError:
                    raise ValueError(f"{name} = {text!r}: {rest!r} is not a unit compatible with N/m (e.g. 'inf N/m', "
                                     "or 'inf' alone: displacement control)") from None
            return True
    return False


def cycle_stiffness(contact: PhysicalContact, stiffness) -> float:
    r"""The spring's stiffness in the model's units, :math:`\bar k = k\sigma_s/(NGb^2)`.

    Parameters
    ----------
    contact : PhysicalContact
        The contact (its :math:`\sigma_s` and :math:`NGb^2`).
    stiffness : float, str, pint.Quantity or None
        N/m, > 0; None or infinity (in any spelling of :func:`infinite_stiffness`):
        displacement control.

    Returns
    -------
    float
        :math:`\bar k` (``inf`` for displacement control).

    Raises
    ------
    ValueError
        For a stiffness that is not positive, or whose :math:`\bar k` falls below
        :data:`asperity.instrument.STIFFNESS_MIN` or overflows.
    """
    if stiffness is None or (isinstance(stiffness, str) and infinite_stiffness(stiffness)):
        return math.inf
    if not isinstance(stiffness, bool):  # inf (displacement control) in any spelling: 'inf N/m', a Quantity
        try:
            raw = to_si(stiffness, "N/m", "stiffness")
            value = float(raw) if isinstance(raw, float | int | np.floating | np.integer) else None
        except (TypeError, ValueError):
            value = None
        if value is not None and math.isinf(value) and value > 0:
            return math.inf
        if value is not None and not value > 0:
            raise ValueError(f"stiffness (the instrument's spring) must be > 0 N/m, or inf for displacement control, "
                             f"got {value!r}")
    k = check_scalar_positive(stiffness, "stiffness", "N/m")
    with np.errstate(all="ignore"):
        k_bar = float(np.float64(k) * contact.surface.sigma_s / contact.force_scale)
    if not STIFFNESS_MIN <= k_bar < math.inf:
        raise ValueError(f"stiffness = {k:g} N/m is out of range for this contact: k sigma_s/(N G b^2) = {k_bar:g} "
                         f"must lie in [{STIFFNESS_MIN:g}, inf) (N G b^2 = {contact.force_scale:.6g} N, sigma_s = "
                         f"{contact.surface.sigma_s:.6g} m)")
    return k_bar


def cycle_u_in(contact: PhysicalContact, u_in_m: float) -> float:
    r"""The jump-in penetration ``u_in`` [m], checked to lie in :math:`[\bar u_{end}\sigma_s, 0]`.

    Parameters
    ----------
    contact : PhysicalContact
        The contact (the end of its asperities' stable branch).
    u_in_m : float
        Penetration at which an approaching asperity jumps into contact, m.

    Returns
    -------
    float
        ``u_in_m``.

    Raises
    ------
    ValueError
        Naming the range in metres.
    """
    low = float(contact.model.law.u_end) * contact.surface.sigma_s
    if not low <= u_in_m <= 0.0:
        raise ValueError(f"u_in (penetration at which an approaching asperity jumps into contact) must lie in "
                         f"[{low:.6g}, 0] m for this contact (from the end of the stable branch to first touch), "
                         f"got {u_in_m:g} m")
    return u_in_m


def check_cycle_separations(contact: PhysicalContact, d_min, preload_given: bool, d_max, d=None) -> None:
    r"""The separations of a cycle in metres: the checks of :func:`asperity.cycle_run.compute_cycle`
    on :math:`\bar d = d/\sigma_s`, said in metres.

    ``d_max`` in :math:`(\bar d_{lo}\sigma_s, \bar d_{top}\sigma_s]`; exactly one of ``d_min`` and
    a preload; ``d_min`` in :math:`[\bar d_{lo}\sigma_s, d_{max})`; the separations ``d``
    within :math:`[d_{min}, d_{max}]` (when ``d_min`` is given: a preload's closest approach is
    found by the model, which then checks them).  :math:`\bar d_{lo}` is
    :data:`asperity.tabulation.D_MIN`, :math:`\bar d_{top}` the model's ``d_top``;
    :math:`d_{max}` defaults to the model's ``d_search``.

    Parameters
    ----------
    contact : PhysicalContact
        The contact (its :math:`\sigma_s` and model).
    d_min, d_max : float or None
        Closest approach and start of the cycle, m.
    preload_given : bool
        Whether a preload was given instead of ``d_min``.
    d : ndarray, optional
        Separations at which to evaluate the branches, m.

    Raises
    ------
    ValueError
        Naming the range in metres.
    """
    sigma, model = contact.surface.sigma_s, contact.model
    lo, top = D_MIN * sigma, model.d_top * sigma
    if d_max is not None and not lo < d_max <= top:
        raise ValueError(f"d_max (start and end of the cycle) must lie in ({lo:.6g}, {top:.6g}] m for this contact, "
                         f"got {d_max:g} m")
    if (d_min is None) != preload_given:
        raise ValueError("give exactly one of d_min (closest approach, a length) and preload (largest compressive "
                         "load, a force)")
    end = model.d_search * sigma if d_max is None else d_max
    if d_min is not None and not lo <= d_min < end:
        raise ValueError(f"d_min (closest approach) must lie in [{lo:.6g}, {end:.6g}) m for this contact (below the "
                         f"start of the cycle, d_max), got {d_min:g} m")
    if d is not None and d_min is not None and np.size(d) and np.any((d < d_min) | (d > end)):
        raise ValueError(f"d (separations) must lie in [d_min, d_max] = [{d_min:.6g}, {end:.6g}] m, got values "
                         f"from {np.min(d):g} to {np.max(d):g} m")


def scaled_error(contact: PhysicalContact, err: ValueError) -> ValueError:
    """``err`` of the dimensionless model with the scales of its numbers appended.

    Parameters
    ----------
    contact : PhysicalContact
        The contact (its :math:`\\sigma_s` and :math:`NGb^2`).
    err : ValueError
        The model's error.

    Returns
    -------
    ValueError
    """
    if isinstance(err, UnstableClosestApproach):  # the same in metres and N/m
        sigma = contact.surface.sigma_s
        k = err.stiffness * contact.force_scale / sigma
        return UnstableClosestApproach(err.d_from * sigma, err.d_min * sigma, k, length=" m", stiffness_unit=" N/m")
    return ValueError(f"{err} (separations in units of sigma_s = {contact.surface.sigma_s:.6g} m, forces in "
                      f"N G b^2 = {contact.force_scale:.6g} N)")
