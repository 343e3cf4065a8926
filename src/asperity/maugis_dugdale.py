r"""Maugis-Dugdale adhesive contact of one sphere on a flat (Eqs 11-14).

The Dugdale cohesive zone (constant tensile stress :math:`\sigma_0` over a gap
:math:`h`) spans the whole range from DMT (:math:`\lambda \to 0`) to JKR
(:math:`\lambda \to \infty`).  In Maugis' units

.. math::
    A = a\Big(\frac{K}{\pi w R^2}\Big)^{1/3},\quad
    \bar P = \frac{P}{\pi w R},\quad
    \Delta = u\Big(\frac{K^2}{\pi^2 w^2 R}\Big)^{1/3},\quad
    \lambda = 2\sigma_0\Big(\frac{R}{\pi w K^2}\Big)^{1/3},\quad K=\tfrac43 E^*,

the solution is parametric in :math:`m = c/a > 1`.  We use
:math:`t = \sqrt{m^2-1} \in (0, \infty)` instead: near :math:`m = 1` the first
bracket of Eq (11) is a difference of :math:`O(t)` terms worth
:math:`\tfrac43 t^3`, which we evaluate by its series.  Along the curve :math:`t`
runs from :math:`A = \infty` (:math:`t \to 0`) to :math:`A \to 0` (:math:`t \to \infty`).

Stability under displacement control requires :math:`d\Delta/dA > 0`.  Above
:math:`\lambda_c \approx 0.938` the curve :math:`\Delta(A)` has an interior minimum,
which ends the stable branch; below it the branch runs to :math:`A \to 0` with a
finite tensile load.  The branch end, :math:`\lambda_c`, the stable-branch solution
:func:`md_solve` (in :mod:`asperity.maugis_dugdale_solve`) and the pull-off loads live in
:mod:`asperity.maugis_dugdale_branch` and are re-exported here; the numerical kernels (the
brackets of Eqs 11-12, their series near :math:`t = 0`, Eq 11 solved for :math:`t`) in
:mod:`asperity._maugis_dugdale_brackets`.

All functions broadcast over ``t`` and ``lam`` like ufuncs, except where noted.  Inputs
that would overflow double precision are refused: contact radii up to :data:`A_MAX`
(``t`` from about :math:`10^{-50}` up) and penetrations up to :data:`DELTA_MAX`.

References
----------
.. [1] D. Maugis, "Adhesion of spheres: the JKR-DMT transition using a Dugdale
   model", J. Colloid Interface Sci. 150 (1992) 243-269.
.. [2] K. L. Johnson, J. A. Greenwood, "An adhesion map for the contact of elastic
   spheres", J. Colloid Interface Sci. 192 (1997) 326-333.
.. [3] Adams, Müftü, Mohd Azhar, Eqs (11)-(14).
"""

from __future__ import annotations

import numpy as np

from ._maugis_dugdale_brackets import (
    FLOAT_MATH,
    T_RANGE,
    md_brackets,
    md_radius_from_brackets,
    md_t_of_radius_unchecked,
)
from ._validation import as_float_array, check_broadcast, check_finite_result, check_positive, ufunc_result
from .maugis_dugdale_branch import (
    A_MAX,
    DELTA_MAX,
    LAMBDA_C,
    LAMBDA_RANGE,
    BranchPoint,
    check_lambda,
    for_each_lambda,
    md_branch_end,
    md_pull_off,
)
from .maugis_dugdale_solve import md_solve
from .units import to_si

__all__ = ["LAMBDA_C", "BranchPoint", "md_radius", "md_load", "md_penetration", "md_curve", "md_t_of_radius",
           "md_branch_end", "md_solve", "md_pull_off", "md_lambda", "LAMBDA_RANGE", "T_RANGE", "A_MAX",
           "DELTA_MAX", "check_lambda", "for_each_lambda"]

_FLOATS = (float, np.float64)
_T_LO, _T_HI = T_RANGE
_LAM_LO, _LAM_HI = LAMBDA_RANGE


def _check_t_lam(t, lam):
    """t and lam validated (types and ranges; _check_radius checks the radius bound)."""
    t = as_float_array(t, "t", allow_empty=True)
    lam = check_lambda(lam)
    check_broadcast(t=t, lam=lam)
    lo, hi = T_RANGE
    if ((t < lo) | (t > hi)).any():
        raise ValueError(f"t = sqrt(m^2 - 1) must lie in [{lo:g}, {hi:g}], got {t!r}")
    return t, lam


def _check_radius(A, t, lam):
    """Refuse t whose radius exceeds A_MAX (the curve would overflow), naming the smallest valid t.

    The bound has a 1e-9 tolerance, so md_t_of_radius(A_MAX) (good to ~1e-11 there) passes.
    """
    over = np.ravel(A > A_MAX * (1.0 + 1e-9))
    if over.any():
        i = np.flatnonzero(over)[0]
        t_i, lam_i = (float(np.broadcast_to(x, np.shape(A)).ravel()[i]) for x in (t, lam))
        t_min = float(md_t_of_radius_unchecked(np.array(A_MAX), lam_i))
        raise ValueError(f"t = sqrt(m^2 - 1) must lie in [{t_min:.6g}, {T_RANGE[1]:g}] for lam = {lam_i:g}, got t = "
                         f"{t_i:g}: smaller t give a contact radius A > A_MAX = {A_MAX:g}, where the curve "
                         "overflows double precision")


def md_radius(t, lam):
    r"""Contact radius :math:`A` from Eq (11) at :math:`t = \sqrt{m^2-1}`.

    .. math::
        \frac{\lambda A^2}{2}\big[t + (m^2-2)\tan^{-1}t\big]
        + \frac{4\lambda^2 A}{3}\big[t\tan^{-1}t - m + 1\big] = 1

    solved as a quadratic for its only positive root, without cancellation.

    Parameters
    ----------
    t : array_like
        :math:`t = \sqrt{m^2-1}`, :math:`m = c/a > 1` (cohesive-zone over contact radius):
        :math:`t \le 10^{100}`, and :math:`A \le` :data:`A_MAX` (about :math:`t \ge 10^{-50}`).
    lam : array_like
        Maugis parameter :math:`\lambda` in ``[1e-12, 1e12]`` (:data:`LAMBDA_RANGE`).

    Returns
    -------
    ndarray
        :math:`A = a (K/\pi w R^2)^{1/3}`, the broadcast shape of ``t`` and ``lam``.

    Raises
    ------
    ValueError
        If ``t`` or ``lam`` is not real and finite or lies outside its range.

    Examples
    --------
    >>> A = float(md_radius(1e-6, 1e-8))  # m -> 1: Hertz-like, (2/3) lam A^2 t^3 ~ 1
    >>> round((2 / 3) * 1e-8 * A**2 * 1e-18, 6)
    1.0

    References
    ----------
    Maugis (1992); Adams et al., Eq (11).
    """
    return md_curve(t, lam)[0]  # the same evaluation as md_load and md_penetration


def md_load(t, lam):
    r"""Load :math:`P/(\pi wR)` of the Maugis-Dugdale curve at :math:`t` (Eq 12).

    .. math::
        P = A^3 - \lambda A^2\big[t + m^2\tan^{-1}t\big],\qquad m^2 = 1 + t^2,

    with :math:`A` = :func:`md_radius` (Eq 11) at the same :math:`t`.

    Parameters
    ----------
    t : array_like
        :math:`t = \sqrt{m^2-1}`, range as in :func:`md_radius` (:math:`A \le` :data:`A_MAX`).
    lam : array_like
        Maugis parameter :math:`\lambda` in ``[1e-12, 1e12]``.

    Returns
    -------
    ndarray
        Load :math:`P/(\pi wR)` (negative: tensile), the broadcast shape of the inputs.

    Raises
    ------
    ValueError
        If ``t`` or ``lam`` is not real and finite or lies outside its range.

    Examples
    --------
    >>> A = float(md_radius(0.01, 1e-8))
    >>> round(float(md_load(0.01, 1e-8)) - (A**3 - 2.0), 3)  # DMT: P = A^3 - 2
    0.0

    References
    ----------
    Maugis (1992); Adams et al., Eq (12).
    """
    return md_curve(t, lam)[1]


def md_penetration(t, lam):
    r"""Penetration :math:`\Delta = u(K^2/\pi^2w^2R)^{1/3}` of the Maugis-Dugdale curve (Eq 13).

    .. math::
        \Delta = A^2 - \tfrac43\lambda A t,

    with :math:`A` = :func:`md_radius` (Eq 11) at the same :math:`t`.

    Parameters
    ----------
    t : array_like
        :math:`t = \sqrt{m^2-1}`, range as in :func:`md_radius` (:math:`A \le` :data:`A_MAX`).
    lam : array_like
        Maugis parameter :math:`\lambda` in ``[1e-12, 1e12]``.

    Returns
    -------
    ndarray
        Penetration :math:`\Delta` (negative: the sphere's top is above the flat).

    Raises
    ------
    ValueError
        If ``t`` or ``lam`` is not real and finite or lies outside its range.

    Examples
    --------
    >>> A = float(md_radius(0.01, 1e-8))
    >>> round(float(md_penetration(0.01, 1e-8)) / A**2, 6)  # DMT: Hertz penetration A^2
    1.0

    References
    ----------
    Maugis (1992); Adams et al., Eq (13).
    """
    return md_curve(t, lam)[2]


def md_curve(t, lam, derivatives=False):
    r"""Radius, load and penetration of the Maugis-Dugdale curve at :math:`t` (Eqs 11-13).

    .. math::
        a_2A^2 + a_1A = 1,\quad a_2 = \tfrac{\lambda}{2}\big[t + (t^2-1)\tan^{-1}t\big],\quad
        a_1 = \tfrac{4\lambda^2}{3}\big[t\tan^{-1}t - m + 1\big],

        P = A^3 - \lambda A^2\big[t + m^2\tan^{-1}t\big],\qquad \Delta = A^2 - \tfrac43\lambda At,

    with :math:`m = \sqrt{1+t^2}`; the t-derivatives differentiate these (implicitly for
    :math:`A`: :math:`A' = -(a_2'A^2 + a_1'A)/(2a_2A + a_1)`).

    Parameters
    ----------
    t : array_like
        :math:`t = \sqrt{m^2-1}`, range as in :func:`md_radius` (:math:`A \le` :data:`A_MAX`).
    lam : array_like
        Maugis parameter :math:`\lambda` in ``[1e-12, 1e12]``.
    derivatives : bool
        Also return the derivatives with respect to :math:`t` (default False).

    Returns
    -------
    tuple of ndarray
        ``(A, P, Delta)``: radius :math:`a(K/\pi wR^2)^{1/3}`, load :math:`P/(\pi wR)`,
        penetration :math:`\Delta`; with ``derivatives`` then ``(dA_dt, dP_dt, dDelta_dt)``.
        Each has the broadcast shape of the inputs.

    Raises
    ------
    ValueError
        If ``t`` or ``lam`` is not real and finite or lies outside its range.

    Examples
    --------
    >>> A, P, D, dA, dP, dD = md_curve(1.0, 2.0, derivatives=True)
    >>> bool(dA < 0)  # the radius falls as t grows
    True

    References
    ----------
    Maugis (1992); Adams et al., Eqs (11)-(13).
    """
    if not isinstance(derivatives, bool | np.bool_):
        raise TypeError(f"derivatives must be True or False, got {derivatives!r}")
    xp = np
    if type(t) in _FLOATS and type(lam) in _FLOATS and _T_LO <= t <= _T_HI and _LAM_LO <= lam <= _LAM_HI:
        xp = FLOAT_MATH  # one point (root finding along the curve): the same formulas on Python floats
        t, lam = float(t), float(lam)
    else:
        t, lam = _check_t_lam(t, lam)
    f1, f2, g, df1, df2, dg = md_brackets(t, xp)
    A, a1, a2 = md_radius_from_brackets(lam, f1, f2, xp)
    _check_radius(A, t, lam)
    P = A**3 - lam * A * A * g
    D = A * A - (4.0 / 3.0) * lam * A * t
    if not derivatives:
        return (np.float64(A), np.float64(P), np.float64(D)) if xp is FLOAT_MATH else (A, P, D)
    da2 = 0.5 * lam * df1
    da1 = (4.0 / 3.0) * lam * lam * df2
    dA = -(da2 * A * A + da1 * A) / (2.0 * a2 * A + a1)
    dD = 2.0 * A * dA - (4.0 / 3.0) * lam * (dA * t + A)
    dP = 3.0 * A * A * dA - lam * (2.0 * A * dA * g + A * A * dg)
    if xp is FLOAT_MATH:
        return tuple(np.float64(x) for x in (A, P, D, dA, dP, dD))
    return A, P, D, dA, dP, dD


def md_t_of_radius(A, lam):
    r"""The :math:`t = \sqrt{m^2-1}` at which Eq (11) gives the radius ``A``: the inverse of :func:`md_radius`.

    At fixed :math:`A` the left side of Eq (11) increases from 0 to :math:`\infty` with
    :math:`t`, so the root is unique; safeguarded Newton in :math:`\log t` finds it from the
    small- and large-:math:`t` asymptotes.

    Parameters
    ----------
    A : array_like
        Contact radius :math:`a(K/\pi wR^2)^{1/3}`, from the radius at :math:`t = 10^{100}`
        (about :math:`10^{-100}`) to :data:`A_MAX`.
    lam : array_like
        Maugis parameter :math:`\lambda` in ``[1e-12, 1e12]``.

    Returns
    -------
    ndarray
        :math:`t` with ``md_radius(t, lam) == A`` to about 1e-13, the broadcast shape.

    Raises
    ------
    ValueError
        If ``A`` or ``lam`` is not real and finite or lies outside its range.

    Examples
    --------
    >>> round(float(md_radius(md_t_of_radius(2.0, 0.5), 0.5)), 12)
    2.0

    References
    ----------
    Maugis (1992); Adams et al., Eq (11).
    """
    A = as_float_array(A, "A", allow_empty=True)
    lam = check_lambda(lam)
    check_broadcast(A=A, lam=lam)
    A, lam = np.broadcast_arrays(A, lam)
    A_min = md_radius_from_brackets(lam, *md_brackets(T_RANGE[1], FLOAT_MATH)[:2])[0]
    bad = (A < A_min) | (A > A_MAX)
    if np.any(bad):
        i = np.flatnonzero(bad.ravel())[0]
        raise ValueError(f"A (contact radius) must lie in [{A_min.ravel()[i]:.6g}, {A_MAX:g}] for "
                         f"lam = {lam.ravel()[i]:g} (t = sqrt(m^2 - 1) within [{T_RANGE[0]:g}, {T_RANGE[1]:g}]), "
                         f"got {A.ravel()[i]!r}")
    return ufunc_result(md_t_of_radius_unchecked(A, lam))


def md_lambda(R, w, E_star, sigma0):
    r"""Maugis parameter :math:`\lambda = 2\sigma_0 (R/\pi w K^2)^{1/3}`, :math:`K = \tfrac43E^*` (Eq 14).

    The arguments come in the order of the regime family
    (:func:`asperity.regimes.tabor_parameter` ``(R, w, E_star, z0)``,
    :func:`asperity.regimes.maugis_parameter` ``(R, w, E_star, sigma0)``).

    .. math::

        \lambda = 2\sigma_0\Big(\frac{R}{\pi w K^2}\Big)^{1/3},\qquad K = \tfrac43 E^*

    Parameters
    ----------
    R : array_like
        Sphere radius :math:`R` (m), > 0.
    w : array_like
        Work of adhesion :math:`w` (J/m^2), > 0.
    E_star : array_like
        Composite Young's modulus :math:`E^*` (Pa), > 0.
    sigma0 : array_like
        Dugdale adhesive stress :math:`\sigma_0 = w/h` (Pa), > 0.

    Returns
    -------
    ndarray
        :math:`\lambda` (dimensionless), broadcast over the inputs (0-d for scalars).

    References
    ----------
    Maugis (1992); Adams et al., Eq (14).
    """
    R = check_positive(to_si(R, "m", "R"), "R")
    w = check_positive(to_si(w, "J/m^2", "w"), "w")
    E_star = check_positive(to_si(E_star, "Pa", "E_star"), "E_star")
    sigma0 = check_positive(to_si(sigma0, "Pa", "sigma0"), "sigma0")
    check_broadcast(R=R, w=w, E_star=E_star, sigma0=sigma0)
    with np.errstate(all="ignore"):
        K = (4.0 / 3.0) * E_star
        lam = 2.0 * sigma0 * np.cbrt(R / (np.pi * w * K * K))
    return check_finite_result(lam, "lambda", R=R, w=w, E_star=E_star, sigma0=sigma0)
