r"""JKR adhesive contact (the :math:`\lambda \to \infty` limit of Maugis-Dugdale).

In Maugis' units (:mod:`asperity.maugis_dugdale`):

.. math::
    P = A^3 - \sqrt{6A^3}, \qquad \Delta = A^2 - \sqrt{8A/3}.

Pull-off under load control: :math:`P = -3/2` at :math:`A = (3/2)^{1/3}`; under
displacement control (end of the stable branch, :math:`d\Delta/dA = 0`):
:math:`P = -5/6` at :math:`A = 6^{-1/3}`.

References
----------
.. [1] K. L. Johnson, K. Kendall, A. D. Roberts, Proc. R. Soc. A 324 (1971) 301.
.. [2] D. Maugis (1992), Eqs for the JKR limit.
"""

from __future__ import annotations

import numpy as np

from ._validation import check_radius as _radius

__all__ = ["jkr_load", "jkr_penetration", "jkr_pull_off"]



def jkr_load(A):
    """JKR load :math:`P/(\\pi w R) = A^3 - \\sqrt{6A^3}`."""
    A = _radius(A)
    return A**3 - np.sqrt(6.0 * A**3)


def jkr_penetration(A):
    """JKR penetration :math:`\\Delta = A^2 - \\sqrt{8A/3}`."""
    A = _radius(A)
    return A**2 - np.sqrt(8.0 * A / 3.0)


def jkr_pull_off(control: str = "load"):
    """JKR pull-off ``(A, P)``: load control (3/2)^(1/3), -3/2; displacement 6^(-1/3), -5/6."""
    if control == "load":
        return 1.5 ** (1.0 / 3.0), -1.5
    if control == "displacement":
        return 6.0 ** (-1.0 / 3.0), -5.0 / 6.0
    raise ValueError(f"control must be 'load' or 'displacement', got {control!r}")
