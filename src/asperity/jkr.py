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

from ._validation import check_overflow, check_radius

__all__ = ["jkr_load", "jkr_penetration", "jkr_pull_off"]

_FLOAT_MAX = float(np.finfo(float).max)


def jkr_load(A):
    r"""JKR load in Maugis' units, :math:`P/(\pi wR) = A^3 - \sqrt{6A^3}`.

    .. math::
        \frac{P}{\pi wR} = A^3 - \sqrt{6A^3},\qquad A = a\Big(\frac{K}{\pi wR^2}\Big)^{1/3}

    Parameters
    ----------
    A : array_like
        Contact radius in Maugis' units, :math:`0 \le A \le (\mathrm{DBL\_MAX}/6)^{1/3}`
        (about 3.1e102; beyond, :math:`6A^3` overflows).  May be empty.

    Returns
    -------
    ndarray
        :math:`P/(\pi wR)`, the shape of ``A`` (negative: tensile).

    Raises
    ------
    ValueError
        If ``A`` is not real and finite, negative, or the load would overflow.

    Examples
    --------
    >>> round(float(jkr_load(1.5 ** (1 / 3))), 12)  # the load-controlled pull-off
    -1.5

    References
    ----------
    Johnson, Kendall & Roberts (1971); Maugis (1992).
    """
    A = check_radius(A)
    with np.errstate(over="ignore", invalid="ignore"):
        P = A**3 - np.sqrt(6.0 * A**3)
    return check_overflow(P, "A", np.cbrt(_FLOAT_MAX / 6.0), A)


def jkr_penetration(A):
    r"""JKR penetration in Maugis' units, :math:`\Delta = A^2 - \sqrt{8A/3}`.

    .. math::
        \Delta = A^2 - \sqrt{8A/3},\qquad \Delta = u\Big(\frac{K^2}{\pi^2w^2R}\Big)^{1/3}

    Parameters
    ----------
    A : array_like
        Contact radius in Maugis' units, :math:`0 \le A \le \mathrm{DBL\_MAX}^{1/2}`
        (about 1.3e154; beyond, :math:`A^2` overflows).  May be empty.

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
    >>> A = 6 ** (-1 / 3)  # the end of the stable branch: A^2 - sqrt(8A/3)
    >>> round(float(jkr_penetration(A)), 5)
    -0.90856

    References
    ----------
    Johnson, Kendall & Roberts (1971); Maugis (1992).
    """
    A = check_radius(A)
    with np.errstate(over="ignore"):
        D = A**2 - np.sqrt(8.0 * A / 3.0)
    return check_overflow(D, "A", np.sqrt(_FLOAT_MAX), A)


def jkr_pull_off(control: str = "load"):
    r"""JKR pull-off radius and load ``(A, P)`` in Maugis' units.

    .. math::
        \text{load control: } A = (3/2)^{1/3},\ P = -\tfrac32;\qquad
        \text{displacement control: } A = 6^{-1/3},\ P = -\tfrac56

    Parameters
    ----------
    control : {'load', 'displacement'}
        Which quantity is controlled (default ``'load'``).

    Returns
    -------
    tuple of float
        ``(A, P)``: radius :math:`a(K/\pi wR^2)^{1/3}` and load :math:`P/(\pi wR)`.

    Raises
    ------
    ValueError
        If ``control`` is neither name.

    Examples
    --------
    >>> jkr_pull_off("displacement")[1] == -5 / 6
    True

    References
    ----------
    Johnson, Kendall & Roberts (1971); Maugis (1992).
    """
    if not isinstance(control, str) or control not in ("load", "displacement"):
        raise ValueError(f"control must be 'load' or 'displacement', got {control!r}")
    if control == "load":
        return 1.5 ** (1.0 / 3.0), -1.5
    if control == "displacement":
        return 6.0 ** (-1.0 / 3.0), -5.0 / 6.0
    raise ValueError(f"control must be 'load' or 'displacement', got {control!r}")
