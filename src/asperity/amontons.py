r"""Amontons' law with an adhesion offset: friction proportional to the load plus an adhesive load.

.. math::
    F = \mu_0\,(P + P_0),\qquad P \ge -P_0,

the usual fallback for multi-asperity contacts, where many asperities of different sizes
average the sub-linear :math:`F \propto a^2 \propto P^{2/3}` of one asperity into a nearly
linear law, and adhesion acts as an extra internal load :math:`P_0` (Derjaguin's
two-term law).  It is here as the baseline that :func:`asperity.fit.compare_models` ranks
the physical models against.  Broadcasts like a ufunc.

References
----------
.. [1] B. V. Derjaguin, "Molekulartheorie der äußeren Reibung", Z. Physik 88 (1934) 661.
.. [2] B. Bhushan, Introduction to Tribology, Wiley (2013), ch. 5 (Amontons' laws,
   adhesion offset).
"""

from __future__ import annotations

import numpy as np

from ._validation import as_float_array, check_broadcast, check_finite_result, check_nonnegative

__all__ = ["amontons_friction"]


def amontons_friction(P, *, mu0, P0):
    r"""Friction force of Amontons' law with an adhesion offset, :math:`F = \mu_0(P + P_0)`.

    .. math:: F = \mu_0\,(P + P_0),\qquad P \ge -P_0

    Parameters
    ----------
    P : array_like
        Normal load :math:`P` (any force unit, that of ``P0``), at least :math:`-P_0`.
    mu0 : array_like
        Friction coefficient :math:`\mu_0`, >= 0.
    P0 : array_like
        Adhesion offset :math:`P_0` (the unit of ``P``), real: > 0 for an adhesive contact.

    Returns
    -------
    ndarray
        Friction force :math:`F` (the unit of ``P``), >= 0, the broadcast shape of the inputs.

    Raises
    ------
    ValueError
        If an input is not real and finite, ``mu0 < 0`` or a load is below :math:`-P_0`
        (friction would be negative).

    Examples
    --------
    >>> float(amontons_friction(2.0, mu0=0.5, P0=1.0))
    1.5

    References
    ----------
    Derjaguin (1934); Bhushan (2013), ch. 5.
    """
    P = as_float_array(P, "P", allow_empty=True)
    mu0 = check_nonnegative(mu0, "mu0")
    P0 = as_float_array(P0, "P0")
    check_broadcast(P=P, mu0=mu0, P0=P0)
    with np.errstate(all="ignore"):
        total = check_finite_result(P + P0, "P + P0", P=P, P0=P0)
    if np.any(total < 0):
        raise ValueError("P (load) must be >= -P0 (the adhesion offset): the friction force would be negative")
    with np.errstate(all="ignore"):
        F = mu0 * total
    return check_finite_result(F, "the friction force", mu0=mu0, P=P, P0=P0)
