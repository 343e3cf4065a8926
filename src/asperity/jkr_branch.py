r"""The JKR solution in Maugis' units: load and penetration of a contact radius, and their inversions.

In Maugis' units (:mod:`asperity.maugis_dugdale`), the :math:`\lambda \to \infty` limit of
Maugis-Dugdale:

.. math::
    P = A^3 - \sqrt{6A^3}, \qquad \Delta = A^2 - \sqrt{8A/3}.

Pull-off under load control: :math:`P = -3/2` at :math:`A = (3/2)^{1/3}`; under
displacement control (end of the stable branch, :math:`d\Delta/dA = 0`):
:math:`P = -5/6` at :math:`A = 6^{-1/3}`.  :mod:`asperity.jkr` re-exports these functions
beside its physical shell (SI units).

References
----------
.. [1] K. L. Johnson, K. Kendall, A. D. Roberts, Proc. R. Soc. A 324 (1971) 301.
.. [2] D. Maugis (1992), Eqs for the JKR limit.
"""

from __future__ import annotations

import numpy as np

from ._validation import as_float_array, check_overflow, check_radius

__all__ = ["jkr_load", "jkr_penetration", "jkr_pull_off", "jkr_solve_load", "jkr_solve"]

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
    with np.errstate(over="ignore", invalid="ignore"):  # inf - inf for a huge A: the named error below
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


# -- load control, displacement control and the physical shell -----------------------------
#: Radius and penetration at the end of the displacement-stable branch, A = 6^(-1/3).
_A_C = 6.0 ** (-1.0 / 3.0)
_DELTA_C = _A_C**2 - np.sqrt(8.0 * _A_C / 3.0)
#: The end of the stable JKR branch in Maugis' units, :math:`A_c^2 - \sqrt{8A_c/3}`, :math:`A_c = 6^{-1/3}`.
DELTA_END = float(_DELTA_C)


def jkr_solve_load(P):
    r"""JKR contact radius and penetration at a given load (load control), in Maugis' units.

    The load-stable branch of :math:`P = A^3 - \sqrt{6A^3}` (:math:`A^3 \ge 3/2`) solved for
    :math:`s = A^{3/2}` from :math:`s^2 - \sqrt6\,s - P = 0`:

    .. math::
        A = \Big(\frac{\sqrt6 + \sqrt{6 + 4P}}{2}\Big)^{2/3},\qquad \Delta = A^2 - \sqrt{8A/3},
        \qquad P \ge -\tfrac32

    Parameters
    ----------
    P : array_like
        Load :math:`P/(\pi wR)`, from the load-controlled pull-off -3/2 up, at most 1e300.
        May be empty.

    Returns
    -------
    A, delta : ndarray
        Contact radius :math:`a(K/\pi wR^2)^{1/3}` and penetration
        :math:`\Delta = u(K^2/\pi^2w^2R)^{1/3}`, the shape of ``P``.

    Raises
    ------
    ValueError
        If ``P`` is not real and finite or lies outside :math:`[-3/2, 10^{300}]`.

    Examples
    --------
    >>> A, delta = jkr_solve_load([-1.5, 0.0])
    >>> [round(float(x**3), 12) for x in A]  # pull-off at A^3 = 3/2; A^3 = 6 at zero load
    [1.5, 6.0]

    References
    ----------
    Johnson, Kendall & Roberts (1971); Maugis (1992).
    """
    P = as_float_array(P, "P", allow_empty=True)
    if np.any((P < -1.5) | (P > 1e300)):
        raise ValueError(f"P (load over pi w R) must lie in [-1.5, 1e300] (from the JKR pull-off), got values "
                         f"from {P.min():g} to {P.max():g}")
    s = 0.5 * (np.sqrt(6.0) + np.sqrt(6.0 + 4.0 * P))
    A = np.cbrt(s * s)
    return A, A * A - np.sqrt(8.0 * A / 3.0)


def jkr_solve(delta):
    r"""JKR contact radius and load at a given penetration (displacement control), in Maugis' units.

    Solves :math:`\Delta = A^2 - \sqrt{8A/3}` on the stable branch :math:`A \ge 6^{-1/3}`
    (:math:`d\Delta/dA \ge 0`) for :math:`x = \sqrt A` (Newton's method on the convex, increasing
    :math:`x^4 - \sqrt{8/3}\,x - \Delta`, from the right), then :math:`P = A^3 - \sqrt{6A^3}`.

    .. math::
        \Delta = A^2 - \sqrt{8A/3},\qquad P = A^3 - \sqrt{6A^3},\qquad A \ge 6^{-1/3}

    Parameters
    ----------
    delta : array_like
        Penetration :math:`\Delta = u(K^2/\pi^2w^2R)^{1/3}`, from the end of the stable branch
        :math:`\Delta_c = A_c^2 - \sqrt{8A_c/3} \approx -0.9086` at :math:`A_c = 6^{-1/3}`, up to 1e150.
        May be empty.

    Returns
    -------
    A, P : ndarray
        Contact radius :math:`a(K/\pi wR^2)^{1/3}` and load :math:`P/(\pi wR)`, the shape of
        ``delta``.

    Raises
    ------
    ValueError
        If ``delta`` is not real and finite or lies outside :math:`[\Delta_c, 10^{150}]`.

    Examples
    --------
    >>> A, P = jkr_solve([float(jkr_penetration(2.0))])
    >>> round(float(A[0]), 12), round(float(P[0]), 12) == round(float(jkr_load(2.0)), 12)
    (2.0, True)

    References
    ----------
    Johnson, Kendall & Roberts (1971); Maugis (1992).
    """
    delta = as_float_array(delta, "delta", allow_empty=True)
    if np.any((delta < _DELTA_C) | (delta > 1e150)):
        raise ValueError(f"delta (penetration) must lie in [{_DELTA_C:.17g}, 1e150] (from the end of the "
                         f"stable JKR branch), got values from {delta.min():g} to {delta.max():g}")
    c = np.sqrt(8.0 / 3.0)
    x_c = np.sqrt(_A_C)
    # Start right of the root (f(x) >= 0), then Newton descends monotonically (f convex, increasing).
    x = np.maximum(x_c, np.sqrt(np.sqrt(np.abs(delta)))) + np.cbrt(c) + 1.0
    for _ in range(200):
        f = x**4 - c * x - delta
        df = 4.0 * x**3 - c
        with np.errstate(divide="ignore", invalid="ignore"):
            step = np.where(df > 0, f / df, 0.0)
        x_new = np.maximum(x - step, x_c)
        if np.all(np.abs(x_new - x) <= 1e-15 * x):
            x = x_new
            break
        x = x_new
    A = x * x
    return A, A**3 - np.sqrt(6.0 * A**3)
