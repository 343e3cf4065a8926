r"""Maugis' units: the scales in which the JKR and Maugis-Dugdale solutions are written.

With :math:`K = \tfrac43E^*`, a sphere of radius :math:`R` and work of adhesion :math:`w`
has the units of length (penetration), radius and force

.. math::
    \ell = \Big(\frac{\pi^2w^2R}{K^2}\Big)^{1/3},\qquad
    a_0 = \Big(\frac{\pi wR^2}{K}\Big)^{1/3},\qquad F_0 = \pi wR,

in which :mod:`asperity.jkr` and :mod:`asperity.maugis_dugdale` solve their contact.
:func:`penetration_in_maugis_units` brings a penetration in metres into them, broadcasting
over the sphere's radius, work of adhesion and modulus like a ufunc.

References
----------
.. [1] D. Maugis, "Adhesion of spheres: the JKR-DMT transition using a Dugdale model",
   J. Colloid Interface Sci. 150 (1992) 243-269; Adams et al., Eqs (12)-(13).
"""

from __future__ import annotations

import numpy as np

from ._numbers import apart
from ._validation import as_float_array, check_broadcast, check_finite_result, check_positive
from .units import to_si

__all__ = ["penetration_in_maugis_units", "check_floor_in_si"]


def penetration_in_maugis_units(delta, *, R, w, E_star):
    r"""A penetration in Maugis' units, and his unit of force: :math:`(\Delta, \pi wR)`.

    .. math::
        \Delta = \delta\Big(\frac{K^2}{\pi^2w^2R}\Big)^{1/3},\qquad K = \tfrac43E^*,

    the units in which the JKR and Maugis-Dugdale solutions are written (loads in
    :math:`\pi wR`).  Both units and :math:`\Delta` are checked: values of extreme
    magnitude whose units leave double precision are refused, naming them.  Broadcasts over
    all four inputs.

    Parameters
    ----------
    delta : array_like
        Penetration :math:`\delta` (m).  May be empty.
    R : array_like
        Sphere radius :math:`R` (m), > 0.
    w : array_like
        Work of adhesion :math:`w` (J/m^2), > 0.
    E_star : array_like
        Composite Young's modulus :math:`E^*` (Pa), > 0.

    Returns
    -------
    tuple
        ``(Delta, force_unit)``: :math:`\Delta` (the broadcast shape of the inputs) and
        :math:`\pi wR` (N): a float when ``R`` and ``w`` are scalars, else an array of their
        broadcast shape.

    Raises
    ------
    ValueError
        If an input is not real, finite and positive (``delta`` real and finite), the shapes
        do not broadcast, or a unit or :math:`\Delta` leaves double precision (naming delta,
        R, w, E_star).

    Examples
    --------
    >>> D, unit = penetration_in_maugis_units(np.array([1e-9]), R=1e-6, w=0.1, E_star=1e11)
    >>> round(float(D[0]), 6), round(unit / (np.pi * 1e-7), 12)
    (5.647539, 1.0)
    >>> D, unit = penetration_in_maugis_units(1e-9, R=[1e-6, 8e-6], w=0.1, E_star=1e11)
    >>> [round(float(x), 6) for x in D], unit.shape  # Delta ~ R^(-1/3)
    ([5.647539, 2.82377], (2,))

    References
    ----------
    D. Maugis, J. Colloid Interface Sci. 150 (1992) 243-269; Adams et al., Eqs (12)-(13).
    """
    delta = as_float_array(to_si(delta, "m", "delta"), "delta", allow_empty=True)
    R = check_positive(to_si(R, "m", "R"), "R")
    w = check_positive(to_si(w, "J/m^2", "w"), "w")
    E_star = check_positive(to_si(E_star, "Pa", "E_star"), "E_star")
    check_broadcast(delta=delta, R=R, w=w, E_star=E_star)
    K = np.float64(4.0 / 3.0) * E_star
    with np.errstate(all="ignore"):
        scale = np.cbrt(np.pi**2 * w * w * R / (K * K))
        unit = np.pi * w * R
        check_finite_result([np.max(scale), np.max(1.0 / scale), np.max(unit)], "Maugis' units of length and force",
                            R=R, w=w, E_star=E_star)
        D = check_finite_result(delta / scale, "the penetration in Maugis' units", delta=delta, R=R, w=w,
                                E_star=E_star)
    return D, (float(unit) if unit.ndim == 0 else unit)


def check_floor_in_si(value, value_hat, floor_hat, name: str, unit: str, what: str, rtol: float = 0.0) -> None:
    r"""Refuse values below the end of a branch in the caller's SI units, not in Maugis' units.

    ``value`` (SI, e.g. a penetration in m or a load in N) and ``value_hat`` (the same in
    Maugis' units) broadcast with ``floor_hat`` (the branch's least value in Maugis' units);
    the floor in SI is ``floor_hat * value / value_hat`` element by element (a user trial:
    -5 nm was refused as "got values from -1.31068").  ``rtol``: the solver's own slack below
    the floor (rounding of a round trip through SI), so that this check is never stricter.

    Raises
    ------
    ValueError
        Naming ``name``, the first offending value and its own floor (R, w, E* and lambda
        set each value's), both in ``unit``.

    Examples
    --------
    >>> check_floor_in_si(np.array([-2e-9]), np.array([-2.0]), -0.9, "delta (penetration)", "m", "the end")
    Traceback (most recent call last):
    ...
    ValueError: delta (penetration) must be >= -9e-10 m (the end), got -2e-09 m
    """
    value, value_hat, floor_hat = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in
                                                       (value, value_hat, floor_hat)))
    bad = value_hat < floor_hat - rtol * np.abs(floor_hat)
    if not bad.any():
        return
    i = np.flatnonzero(bad.reshape(-1))[0]
    v, vh, fh = (x.reshape(-1)[i] for x in (value, value_hat, floor_hat))
    floor = fh * v / vh
    k = apart(floor, v)
    with np.errstate(all="ignore"):
        floors = (floor_hat * value / value_hat)[value_hat != 0]
    varied = floors.size > 1 and np.ptp(floors) > 1e-12 * abs(floor)  # R, w, E* or lambda vary
    which = " (the first value below its floor; each value's R, w, E* set its own)" if varied else ""
    raise ValueError(f"{name} must be >= {floor:.{k}g} {unit} ({what}), got {v:.{k}g} {unit}{which}")
