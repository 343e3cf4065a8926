r"""Jackson-Green (2005) geometric hardness of an elastic-plastic sphere, and the yield strength from it.

A fully plastic contact of radius :math:`a` on a sphere of radius :math:`R` carries the mean
pressure :math:`H_G`; JG fit their FEM results by

.. math::
    \frac{H_G}{S_y} = 2.84\Big[1 - \exp\big(-0.82\,(a/R)^{-0.7}\big)\Big],

which tends to :math:`2.84` for the small contacts of asperities, so that a hardness
:math:`H` gives the yield strength :math:`S_y = H/2.84` (Tabor's classical
:math:`H \approx 2.8\,Y` to 1.4 %).  The critical values and the fits that use these are
in :mod:`asperity.jackson_green` and :mod:`asperity.jackson_green_fits`.

All functions broadcast like NumPy ufuncs.

References
----------
.. [1] R. L. Jackson, I. Green, "A finite element study of elasto-plastic hemispherical
   contact against a rigid flat", J. Tribol. 127 (2005) 343-354: the geometric hardness.
.. [2] D. Tabor, The Hardness of Metals, Oxford (1951): :math:`H \approx 2.8\,Y`.
"""

from __future__ import annotations

import numpy as np

from ._validation import check_nonnegative, check_positive

__all__ = ["HG_LIMIT", "HG_RATE", "HG_POWER", "jg_yield_from_hardness", "jg_hardness_ratio"]

#: JG 2005: small-contact limit of the geometric hardness, :math:`H_G/S_y \to 2.84`.
HG_LIMIT = 2.84
#: JG 2005: :math:`H_G/S_y = 2.84[1 - e^{-0.82(a/R)^{-0.7}}]`, the rate 0.82.
HG_RATE = 0.82
#: JG 2005: the power 0.7 of :math:`a/R` in the geometric hardness.
HG_POWER = 0.7


def jg_yield_from_hardness(H):
    r"""Yield strength from hardness, :math:`S_y = H/2.84` (JG's small-contact hardness limit).

    .. math::
        S_y = H / 2.84

    JG's geometric hardness :math:`H_G/S_y = 2.84[1 - e^{-0.82(a/R)^{-0.7}}]` tends to 2.84
    for the small contacts of asperities, so the hardness of the law is :math:`2.84\,S_y`.

    Parameters
    ----------
    H : array_like
        Hardness :math:`H > 0`, any pressure unit (or dimensionless, e.g. :math:`H/E^*`).

    Returns
    -------
    ndarray
        :math:`S_y` in the unit of ``H``, the shape of ``H``.

    Raises
    ------
    ValueError
        If ``H`` is not real, finite and positive.

    Examples
    --------
    >>> float(jg_yield_from_hardness(2.84))
    1.0

    References
    ----------
    Jackson & Green (2005), geometric hardness; Tabor (1951).
    """
    return check_positive(H, "H") / HG_LIMIT


def jg_hardness_ratio(a_over_R):
    r"""JG's geometric hardness, :math:`H_G/S_y = 2.84[1 - e^{-0.82(a/R)^{-0.7}}]`.

    .. math::
        \frac{H_G}{S_y} = 2.84\Big[1 - \exp\big(-0.82\,(a/R)^{-0.7}\big)\Big]

    The mean pressure of a fully plastic contact falls as the contact grows relative to the
    sphere; for the small contacts of asperities it is :math:`2.84\,S_y`.

    Parameters
    ----------
    a_over_R : array_like
        Contact radius over sphere radius, :math:`a/R \ge 0` (0 gives the limit 2.84).

    Returns
    -------
    ndarray
        :math:`H_G/S_y`, the shape of ``a_over_R``.

    Raises
    ------
    ValueError
        If ``a_over_R`` is not real, finite and >= 0.

    Examples
    --------
    >>> [round(float(x), 4) for x in jg_hardness_ratio([0.0, 0.1, 1.0])]
    [2.84, 2.7934, 1.5892]

    References
    ----------
    Jackson & Green (2005), geometric hardness.
    """
    r = check_nonnegative(a_over_R, "a_over_R")
    with np.errstate(divide="ignore"):
        return HG_LIMIT * (1.0 - np.exp(-HG_RATE * r ** (-HG_POWER)))
