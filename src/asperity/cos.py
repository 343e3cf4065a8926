r"""The Carpick-Ogletree-Salmeron (COS) transition equation: contact radius against load.

AFM friction-load data are often fitted with :math:`F = \tau\pi a(P)^2`, and Carpick,
Ogletree and Salmeron proposed one closed form for :math:`a(P)` spanning the JKR-DMT
transition, with a transition parameter :math:`\alpha_t` (``alpha_t``):

.. math::
    a(P) = a_0\left(\frac{\alpha_t + \sqrt{1 - P/P_c}}{1 + \alpha_t}\right)^{2/3},
    \qquad P \ge P_c < 0,

where :math:`a_0` is the radius at zero load and :math:`P_c` the (negative) critical load,
the load-controlled pull-off.  :math:`\alpha_t = 1` is JKR **exactly** (with
:math:`P_c = -\tfrac32\pi wR`, :math:`a_0 = (6\pi wR^2/K)^{1/3}`) and :math:`\alpha_t = 0`
is DMT exactly (:math:`P_c = -2\pi wR`, :math:`a_0 = (2\pi wR^2/K)^{1/3}`); in between it
approximates the Maugis-Dugdale solution.  The friction force is then

.. math::
    F(P) = F_0\left(\frac{\alpha_t + \sqrt{1 - P/P_c}}{1 + \alpha_t}\right)^{4/3},
    \qquad F_0 = \tau\pi a_0^2 ,

three parameters :math:`(F_0, P_c, \alpha_t)`: the form AFM users fit.

COS relate :math:`\alpha_t` to the Maugis parameter and give :math:`P_c` and :math:`a_0` in
Maugis' units (:math:`\hat P_c = P_c/\pi wR`, :math:`\hat a_0 = a_0(K/\pi wR^2)^{1/3}`,
:math:`K = \tfrac43E^*`) as fits to the Maugis-Dugdale solution:

.. math::
    \lambda = -0.924\ln(1 - 1.02\,\alpha_t),\qquad
    \hat P_c = -\frac74 + \frac14\,\frac{4.04\lambda^{1.4} - 1}{4.04\lambda^{1.4} + 1},\qquad
    \hat a_0 = 1.54 + 0.279\,\frac{2.28\lambda^{1.3} - 1}{2.28\lambda^{1.3} + 1}.

They are approximations: the first maps :math:`\alpha_t \to 1/1.02 \approx 0.980` to
:math:`\lambda = \infty` (it is undefined for larger :math:`\alpha_t`), and at
:math:`\lambda = 0` the last gives :math:`\hat a_0 = 1.261` against DMT's exact
:math:`2^{1/3} = 1.2599`.  :func:`cos_lambda`, :func:`cos_alpha`,
:func:`cos_pull_off_hat` and :func:`cos_radius_hat` implement them; the tests measure how
far they are from the exact :mod:`asperity.maugis_dugdale` solution.

*Sources and what was verified.*  The paper itself (Carpick, Ogletree, Salmeron, J. Colloid
Interface Sci. 211 (1999) 395-400) was not available here.  The constants 0.924, 1.02,
7/4, 1/4, 4.04, 1.4, 1.54, 0.279, 2.28 and 1.3 and the equation numbers (7), (10), (11a),
(12a), (12b) are as quoted in an open implementation (woodem/woo, ``pkg/dem/Hertz.cpp``,
an older version, "COS eq (10)", "(12a)", "(12b)"); they were **not** checked against the
printed paper.  What was checked: the general equation reproduces JKR and DMT exactly at
:math:`\alpha_t = 1, 0` (derived here, and tested), the limits of :math:`\hat P_c` and
:math:`\hat a_0` (-3/2, -2; :math:`6^{1/3}`, :math:`2^{1/3}` to 0.2 %), and the three
fits against the exact Maugis-Dugdale solution over :math:`0.01 \le \lambda \le 100`
(``tests/test_cos.py`` states the deviations found).

References
----------
.. [1] R. W. Carpick, D. F. Ogletree, M. Salmeron, "A general equation for fitting contact
   area and friction vs load measurements", J. Colloid Interface Sci. 211 (1999) 395-400,
   Eqs (7), (10), (11a), (12a), (12b) (numbers as quoted, see above).
.. [2] D. Maugis, J. Colloid Interface Sci. 150 (1992) 243-269.
"""

from __future__ import annotations

import numpy as np

from ._validation import as_float_array, check_broadcast, check_finite_result, check_positive, check_range

__all__ = ["ALPHA_T_MAX", "cos_contact_radius", "cos_friction", "cos_lambda", "cos_alpha", "cos_pull_off_hat",
           "cos_radius_hat"]

#: Largest transition parameter the lambda conversion accepts: 1/1.02 maps to lambda = infinity.
ALPHA_T_MAX = 1.0 / 1.02


def _shape(P, Pc, alpha_t):
    r"""(alpha_t + sqrt(1 - P/Pc)) / (1 + alpha_t), validated, broadcast."""
    P = as_float_array(P, "P", allow_empty=True)
    Pc = as_float_array(Pc, "Pc")
    if np.any(Pc >= 0):
        raise ValueError(f"Pc (critical load, the pull-off load) must be < 0, got {Pc!r}")
    alpha_t = check_range(alpha_t, "alpha_t", 0.0, 1.0)
    check_broadcast(P=P, Pc=Pc, alpha_t=alpha_t)
    with np.errstate(all="ignore"):
        ratio = check_finite_result(P / Pc, "P/Pc", P=P, Pc=Pc)
    if np.any(ratio > 1.0 + 1e-15):
        raise ValueError("P (load) must be >= Pc (the critical load, negative): no contact below it")
    return (alpha_t + np.sqrt(np.maximum(1.0 - ratio, 0.0))) / (1.0 + alpha_t)


def cos_contact_radius(P, *, a0, Pc, alpha_t):
    r"""Contact radius from the COS transition equation (Carpick, Ogletree & Salmeron 1999, Eq 7).

    .. math::
        a = a_0\left(\frac{\alpha_t + \sqrt{1 - P/P_c}}{1 + \alpha_t}\right)^{2/3}

    :math:`\alpha_t = 1` with :math:`P_c = -\tfrac32\pi wR`, :math:`a_0 = (6\pi wR^2/K)^{1/3}`
    is JKR exactly; :math:`\alpha_t = 0` with :math:`P_c = -2\pi wR`,
    :math:`a_0 = (2\pi wR^2/K)^{1/3}` is DMT exactly.

    Parameters
    ----------
    P : array_like
        Normal load :math:`P` (any force unit, that of ``Pc``), >= ``Pc``.
    a0 : array_like
        Contact radius at zero load :math:`a_0` (any length unit; the result has it), > 0.
    Pc : array_like
        Critical (pull-off) load :math:`P_c`, < 0.
    alpha_t : array_like
        Transition parameter :math:`\alpha_t`, 0 (DMT) <= alpha_t <= 1 (JKR).

    Returns
    -------
    ndarray
        Contact radius :math:`a`, the broadcast shape of the inputs.

    Raises
    ------
    ValueError
        If an input is not real and finite or out of range, or a load is below ``Pc``.

    Examples
    --------
    >>> round(float(cos_contact_radius(-1.0, a0=1.0, Pc=-1.0, alpha_t=1.0)) ** 1.5, 12)  # (1/2)^(2/3)
    0.5

    References
    ----------
    Carpick, Ogletree & Salmeron (1999), Eq (7).
    """
    a0 = check_positive(a0, "a0")
    shape = _shape(P, Pc, alpha_t)
    check_broadcast(a0=a0, P=shape)
    with np.errstate(all="ignore"):
        a = a0 * shape ** (2.0 / 3.0)
    return check_finite_result(a, "the COS contact radius", a0=a0, P=P, Pc=Pc)


def cos_friction(P, *, F0, Pc, alpha_t):
    r"""Friction force :math:`F = \tau\pi a^2` with the COS contact radius.

    .. math::
        F = F_0\left(\frac{\alpha_t + \sqrt{1 - P/P_c}}{1 + \alpha_t}\right)^{4/3},
        \qquad F_0 = \tau\pi a_0^2

    Parameters
    ----------
    P : array_like
        Normal load :math:`P` (the unit of ``Pc``), >= ``Pc``.
    F0 : array_like
        Friction force at zero load :math:`F_0 = \tau\pi a_0^2`, > 0 (the result has its unit).
    Pc : array_like
        Critical (pull-off) load :math:`P_c`, < 0.
    alpha_t : array_like
        Transition parameter :math:`\alpha_t`, 0 (DMT) <= alpha_t <= 1 (JKR).

    Returns
    -------
    ndarray
        Friction force :math:`F`, the broadcast shape of the inputs.

    Raises
    ------
    ValueError
        If an input is not real and finite or out of range, or a load is below ``Pc``.

    Examples
    --------
    >>> float(cos_friction(0.0, F0=2.0, Pc=-1.0, alpha_t=0.3))
    2.0

    References
    ----------
    Carpick, Ogletree & Salmeron (1999), Eq (7); Bowden & Tabor, :math:`F = \tau A`.
    """
    F0 = check_positive(F0, "F0")
    F0 = check_positive(F0, "F0")
    shape = _shape(P, Pc, alpha_t)
    check_broadcast(F0=F0, P=shape)
    with np.errstate(over="ignore"):
        F = F0 * shape ** (4.0 / 3.0)
    return check_finite_result(F, "the friction force", F0=F0, P=P, Pc=Pc)


def cos_lambda(alpha_t):
    r"""Maugis parameter from the COS transition parameter (COS Eq 10, an approximation).

    .. math:: \lambda = -0.924\ln(1 - 1.02\,\alpha_t)

    Parameters
    ----------
    alpha_t : array_like
        Transition parameter, :math:`0 \le \alpha_t < 1/1.02` (:data:`ALPHA_T_MAX`, where
        :math:`\lambda \to \infty`).

    Returns
    -------
    ndarray
        :math:`\lambda`, the shape of ``alpha_t``.

    Raises
    ------
    ValueError
        If ``alpha_t`` is not real and finite or outside :math:`[0, 1/1.02)`.

    Examples
    --------
    >>> float(cos_lambda(0.0))
    0.0

    References
    ----------
    Carpick, Ogletree & Salmeron (1999), Eq (10) (as quoted; see the module docstring).
    """
    alpha_t = as_float_array(alpha_t, "alpha_t")
    if np.any((alpha_t < 0) | (alpha_t >= ALPHA_T_MAX)):
        raise ValueError(f"alpha_t must lie in [0, 1/1.02 = {ALPHA_T_MAX:.6g}) for the conversion to lambda "
                         f"(1/1.02 maps to lambda = infinity), got {alpha_t!r}")
    return -0.924 * np.log1p(-1.02 * alpha_t)


def cos_alpha(lam):
    r"""COS transition parameter from the Maugis parameter: the inverse of :func:`cos_lambda`.

    .. math:: \alpha_t = \frac{1 - e^{-\lambda/0.924}}{1.02}

    Parameters
    ----------
    lam : array_like
        Maugis parameter :math:`\lambda`, >= 0.

    Returns
    -------
    ndarray
        :math:`\alpha_t`, in :math:`[0, 1/1.02)`, the shape of ``lam``.

    Raises
    ------
    ValueError
        If ``lam`` is not real and finite or negative.

    Examples
    --------
    >>> round(float(cos_lambda(cos_alpha(2.0))), 12)
    2.0

    References
    ----------
    Carpick, Ogletree & Salmeron (1999), Eq (10) (as quoted; see the module docstring).
    """
    lam = as_float_array(lam, "lam")
    if np.any(lam < 0):
        raise ValueError(f"lam (Maugis parameter) must be >= 0, got {lam!r}")
    with np.errstate(over="ignore"):  # lam near the largest double: -lam/0.924 = -inf, alpha -> 1/1.02
        return -np.expm1(-lam / 0.924) / 1.02


def cos_pull_off_hat(lam):
    r"""Critical load :math:`\hat P_c = P_c/\pi wR` against :math:`\lambda` (COS Eq 12a, a fit to Maugis-Dugdale).

    .. math::
        \hat P_c = -\frac74 + \frac14\,\frac{4.04\lambda^{1.4} - 1}{4.04\lambda^{1.4} + 1}

    -2 (DMT) at :math:`\lambda = 0`, -3/2 (JKR) as :math:`\lambda \to \infty`; dimensional
    :math:`P_c = \hat P_c\pi wR` (COS Eq 11a).

    Parameters
    ----------
    lam : array_like
        Maugis parameter :math:`\lambda`, >= 0.

    Returns
    -------
    ndarray
        :math:`\hat P_c`, the shape of ``lam``.

    Raises
    ------
    ValueError
        If ``lam`` is not real and finite or negative.

    Examples
    --------
    >>> float(cos_pull_off_hat(0.0))
    -2.0

    References
    ----------
    Carpick, Ogletree & Salmeron (1999), Eqs (11a), (12a) (as quoted; see the module docstring).
    """
    lam = as_float_array(lam, "lam")
    if np.any(lam < 0):
        raise ValueError(f"lam (Maugis parameter) must be >= 0, got {lam!r}")
    with np.errstate(over="ignore"):  # x = inf for a huge lambda: the JKR limit, exactly
        x = 4.04 * lam**1.4
    return -1.75 + 0.25 * (1.0 - 2.0 / (x + 1.0))


def cos_radius_hat(lam):
    r"""Zero-load radius :math:`\hat a_0 = a_0(K/\pi wR^2)^{1/3}` against :math:`\lambda` (COS Eq 12b, a fit).

    .. math::
        \hat a_0 = 1.54 + 0.279\,\frac{2.28\lambda^{1.3} - 1}{2.28\lambda^{1.3} + 1}

    1.261 at :math:`\lambda = 0` (DMT's exact :math:`2^{1/3} = 1.2599`) and 1.819 as
    :math:`\lambda \to \infty` (JKR's :math:`6^{1/3} = 1.8171`).

    Parameters
    ----------
    lam : array_like
        Maugis parameter :math:`\lambda`, >= 0.

    Returns
    -------
    ndarray
        :math:`\hat a_0`, the shape of ``lam``.

    Raises
    ------
    ValueError
        If ``lam`` is not real and finite or negative.

    Examples
    --------
    >>> round(float(cos_radius_hat(0.0)), 3)
    1.261

    References
    ----------
    Carpick, Ogletree & Salmeron (1999), Eq (12b) (as quoted; see the module docstring).
    """
    lam = as_float_array(lam, "lam")
    if np.any(lam < 0):
        raise ValueError(f"lam (Maugis parameter) must be >= 0, got {lam!r}")
    with np.errstate(over="ignore"):  # x = inf for a huge lambda: the JKR limit, exactly
        x = 2.28 * lam**1.3
    return 1.54 + 0.279 * (1.0 - 2.0 / (x + 1.0))
