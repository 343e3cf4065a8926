r"""DMT adhesive contact (the :math:`\lambda \to 0` limit of Maugis-Dugdale).

In Maugis' units the contact keeps its Hertz radius and penetration while the
adhesive ring outside it pulls with :math:`2\pi w R`:

.. math::
    P = A^3 - 2, \qquad \Delta = A^2,

so the pull-off load is :math:`-2` (:math:`-2\pi w R`) under either control.

References
----------
.. [1] B. V. Derjaguin, V. M. Muller, Yu. P. Toporov, J. Colloid Interface Sci. 53
   (1975) 314.
"""

from __future__ import annotations

import numpy as np

from ._validation import check_overflow, check_radius

__all__ = ["dmt_load", "dmt_penetration", "DMT_PULL_OFF"]

#: DMT pull-off load P/(pi w R).
DMT_PULL_OFF = -2.0

_FLOAT_MAX = float(np.finfo(float).max)


def dmt_load(A):
    r"""DMT load in Maugis' units, :math:`P/(\pi wR) = A^3 - 2`.

    .. math::
        \frac{P}{\pi wR} = A^3 - 2,\qquad A = a\Big(\frac{K}{\pi wR^2}\Big)^{1/3}

    Parameters
    ----------
    A : array_like
        Contact radius in Maugis' units, :math:`0 \le A \le \mathrm{DBL\_MAX}^{1/3}`
        (about 5.6e102; beyond, the load overflows).  May be empty.

    Returns
    -------
    ndarray
        :math:`P/(\pi wR)`, the shape of ``A``.

    Raises
    ------
    ValueError
        If ``A`` is not real and finite, negative, or the load would overflow.

    Examples
    --------
    >>> float(dmt_load(0.0)) == DMT_PULL_OFF
    True

    References
    ----------
    Derjaguin, Muller & Toporov (1975); Maugis (1992).
    """
    A = check_radius(A)
    with np.errstate(over="ignore"):
        P = A**3 - 2.0
    return check_overflow(P, "A", np.cbrt(_FLOAT_MAX), A)


def dmt_penetration(A):
    r"""DMT penetration in Maugis' units, :math:`\Delta = A^2` (Hertzian).

    .. math::
        \Delta = A^2,\qquad \Delta = u\Big(\frac{K^2}{\pi^2w^2R}\Big)^{1/3}

    Parameters
    ----------
    A : array_like
        Contact radius in Maugis' units, :math:`0 \le A \le \mathrm{DBL\_MAX}^{1/2}`
        (about 1.3e154; beyond, the penetration overflows).  May be empty.

    Returns
    -------
    ndarray
        :math:`\Delta`, the shape of ``A``.

    Raises
    ------
    ValueError
        If ``A`` is not real and finite, negative, or the penetration would overflow.

    Examples
    --------
    >>> float(dmt_penetration(3.0))
    9.0

    References
    ----------
    Derjaguin, Muller & Toporov (1975); Maugis (1992).
    """
    A = check_radius(A)
    with np.errstate(over="ignore"):
        D = A**2
    return check_overflow(D, "A", np.sqrt(_FLOAT_MAX), A)
