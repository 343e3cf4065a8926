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

from ._validation import check_radius as _radius

__all__ = ["dmt_load", "dmt_penetration", "DMT_PULL_OFF"]

#: DMT pull-off load P/(pi w R).
DMT_PULL_OFF = -2.0



def dmt_load(A):
    """DMT load :math:`P/(\\pi w R) = A^3 - 2`."""
    return _radius(A) ** 3 - 2.0


def dmt_penetration(A):
    """DMT penetration :math:`\\Delta = A^2` (Hertzian)."""
    return _radius(A) ** 2
