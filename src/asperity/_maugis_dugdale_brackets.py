r"""The brackets of the Maugis-Dugdale curve (Eqs 11-12) in :math:`t = \sqrt{m^2-1}`, and Eq (11) solved for :math:`t`.

The parametric solution of :mod:`asperity.maugis_dugdale` is built from three brackets in
:math:`t` (:func:`md_brackets`): the first cancels to :math:`\tfrac43t^3` near
:math:`t = 0` and is summed from its series there (:func:`md_first_bracket`).  Eq (11) is a
quadratic in the radius :math:`A` (:func:`md_radius_from_brackets`) and, at fixed
:math:`A`, increasing in :math:`t` (:func:`md_t_of_radius_unchecked` inverts it).  These
are the numerical kernels: they do not check their inputs; the public functions of
:mod:`asperity.maugis_dugdale` do, and call them.  Each runs on arrays or, with
``xp=FLOAT_MATH``, on one Python float (root finding along the curve).

References
----------
.. [1] D. Maugis, "Adhesion of spheres: the JKR-DMT transition using a Dugdale
   model", J. Colloid Interface Sci. 150 (1992) 243-269.
.. [2] Adams, Müftü, Mohd Azhar, Eqs (11)-(12).
"""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np

__all__ = ["T_RANGE", "FLOAT_MATH", "md_first_bracket", "md_brackets", "md_radius_from_brackets",
           "md_t_of_radius_unchecked"]

# Coefficients of the series t + (t^2 - 1) atan t = sum_k (-1)^(k+1) 4k t^(2k+1)/((2k-1)(2k+1)).
_SERIES_T = 0.5
_K = np.arange(1, 31)
_F1_COEF = (-1.0) ** (_K + 1) * 4.0 * _K / ((2 * _K - 1) * (2 * _K + 1))


#: The 30 coefficients in 8 groups of 4 (two zeros appended): sum_k c_k x^k =
#: sum_g q_g(x) (x^4)^g with q_g(x) = c_4g + c_4g+1 x + c_4g+2 x^2 + c_4g+3 x^3.
_F1_GROUPS = np.concatenate([_F1_COEF, [0.0, 0.0]]).reshape(8, 4)
_F1_GROUPS_PY = [[float(c) for c in row] for row in _F1_GROUPS]


def _series(x: float) -> float:
    """sum_k _F1_COEF[k] x^k on a Python float, with the operations of :func:`_f1` on arrays."""
    q = [c0 + x * (c1 + x * (c2 + x * c3)) for c0, c1, c2, c3 in _F1_GROUPS_PY]
    x4 = (x * x) * (x * x)
    s = q[7]
    for g in range(6, -1, -1):
        s = s * x4 + q[g]
    return s


def md_first_bracket(t):
    r"""First bracket of Maugis' Eq (11), :math:`t + (t^2-1)\tan^{-1}t`, without cancellation near 0.

    Near :math:`t = 0` the two terms cancel to :math:`\tfrac43t^3`; below :math:`t = 0.5` the
    bracket is the sum of its 30-term series

    .. math::
        t + (t^2-1)\tan^{-1}t = t^3\sum_{k\ge1}(-1)^{k+1}\frac{4k\,t^{2(k-1)}}{(2k-1)(2k+1)}

    (terms below 1e-17 relative), as eight cubics in :math:`t^2` summed by Horner's rule in
    :math:`t^8`; above it, the closed form.

    Parameters
    ----------
    t : array_like
        :math:`t = \sqrt{m^2-1} \ge 0`, real and finite; not checked (the public functions of
        :mod:`asperity.maugis_dugdale` check it).

    Returns
    -------
    ndarray or float
        The bracket, the shape of ``t`` (a NumPy float for a scalar).

    Raises
    ------
    Nothing of its own: a kernel; invalid input gives NaN or an error from NumPy.  The public
    functions of :mod:`asperity.maugis_dugdale` check their inputs before calling it.

    Examples
    --------
    >>> round(float(md_first_bracket(1e-3)) / 1e-9, 5)  # 4 t^3 / 3 - 8 t^5 / 15 + ...
    1.33333

    References
    ----------
    D. Maugis, J. Colloid Interface Sci. 150 (1992) 243-269; Adams et al., Eq (11).
    """
    t = np.asarray(t, dtype=float)
    scalar = t.ndim == 0
    t = np.atleast_1d(t)
    out = t + (t * t - 1.0) * np.arctan(t)
    small = t < _SERIES_T
    if small.any():
        ts = t[small]
        x = ts * ts
        if ts.size <= 8:  # a few values: the same sums on Python floats, much faster
            series = np.array([_series(v) for v in x.tolist()])
        else:
            c = _F1_GROUPS[:, :, None]
            q = c[:, 0] + x * (c[:, 1] + x * (c[:, 2] + x * c[:, 3]))  # (8, n)
            x4 = (x * x) * (x * x)
            series = q[7]
            for g in range(6, -1, -1):
                series = series * x4 + q[g]
        out[small] = series * ts**3
    return out[0] if scalar else out


#: :mod:`math` in NumPy's names: ``xp=FLOAT_MATH`` runs :func:`md_brackets` and
#: :func:`md_radius_from_brackets` on one Python float (much faster there than on 0-d arrays).
FLOAT_MATH = SimpleNamespace(arctan=math.atan, sqrt=math.sqrt)


def _f1_float(t: float) -> float:
    """:func:`md_first_bracket` of one Python float."""
    return _series(t * t) * t**3 if t < _SERIES_T else t + (t * t - 1.0) * math.atan(t)


def md_brackets(t, xp=np):
    r"""The three brackets of Maugis' Eqs (11)-(12) and their :math:`t`-derivatives.

    .. math::
        f_1 = t + (t^2-1)\tan^{-1}t,\qquad f_2 = t\tan^{-1}t - m + 1,\qquad
        g = t + m^2\tan^{-1}t,\qquad m = \sqrt{1+t^2},

    with :math:`f_1` from :func:`md_first_bracket` and :math:`m - 1 = t^2/(1+m)` (no
    cancellation at small :math:`t`); Eq (11) reads
    :math:`\tfrac{\lambda}{2}f_1A^2 + \tfrac{4\lambda^2}{3}f_2A = 1`, Eq (12)
    :math:`P = A^3 - \lambda A^2 g`.

    Parameters
    ----------
    t : array_like or float
        :math:`t = \sqrt{m^2-1} \ge 0`, real and finite; not checked.
    xp : module-like
        ``numpy`` (default) for arrays, or :data:`FLOAT_MATH` for one Python float.

    Returns
    -------
    tuple
        ``(f1, f2, g, df1_dt, df2_dt, dg_dt)``, each the shape of ``t``.

    Raises
    ------
    Nothing of its own: a kernel; invalid input gives NaN or an error from NumPy.  The public
    functions of :mod:`asperity.maugis_dugdale` check their inputs before calling it.

    Examples
    --------
    >>> f1, f2, g, *_ = md_brackets(1.0)
    >>> round(float(f1), 12), round(float(g) - (1 + 2 * np.pi / 4), 12)
    (1.0, 0.0)

    References
    ----------
    D. Maugis, J. Colloid Interface Sci. 150 (1992) 243-269; Adams et al., Eqs (11)-(12).
    """
    if xp is np:
        t = np.asarray(t, dtype=float)
    at = xp.arctan(t)
    m = xp.sqrt(1.0 + t * t)
    f1 = md_first_bracket(t) if xp is np else _f1_float(t)
    f2 = t * at - t * t / (1.0 + m)  # t atan t - m + 1, with m - 1 = t^2/(1 + m)
    g = t + m * m * at  # bracket of Eq (12)
    df1 = 2.0 * t * (at + t / (m * m))
    df2 = at + t / (m * m) - t / m
    dg = 2.0 + 2.0 * t * at
    return f1, f2, g, df1, df2, dg


def md_radius_from_brackets(lam, f1, f2, xp=np):
    r"""The contact radius of Maugis' Eq (11) from its brackets: the positive root of a quadratic.

    Eq (11) is :math:`a_2A^2 + a_1A - 1 = 0` with :math:`a_2 = \tfrac{\lambda}{2}f_1 \ge 0`
    and :math:`a_1 = \tfrac{4\lambda^2}{3}f_2 \ge 0`; its positive root, without
    cancellation, is :math:`A = 2/(a_1 + \sqrt{a_1^2 + 4a_2})`.

    Parameters
    ----------
    lam : array_like or float
        Maugis parameter :math:`\lambda > 0`; not checked.
    f1, f2 : array_like or float
        The first two brackets of :func:`md_brackets` (same ``xp``).
    xp : module-like
        ``numpy`` (default) for arrays, or :data:`FLOAT_MATH` for Python floats.

    Returns
    -------
    tuple
        ``(A, a1, a2)``: the radius :math:`a(K/\pi wR^2)^{1/3}` and the two coefficients.

    Raises
    ------
    Nothing of its own: a kernel; invalid input gives NaN or an error from NumPy.  The public
    functions of :mod:`asperity.maugis_dugdale` check their inputs before calling it.

    Examples
    --------
    >>> f1, f2, *_ = md_brackets(2.0)
    >>> A, a1, a2 = md_radius_from_brackets(0.5, f1, f2)
    >>> round(float(a2 * A * A + a1 * A), 12)
    1.0

    References
    ----------
    D. Maugis, J. Colloid Interface Sci. 150 (1992) 243-269; Adams et al., Eq (11).
    """
    a2 = 0.5 * lam * f1
    a1 = (4.0 / 3.0) * lam * lam * f2
    return 2.0 / (a1 + xp.sqrt(a1 * a1 + 4.0 * a2)), a1, a2


#: Range of t = sqrt(m^2 - 1) handled: t^2 and the brackets stay finite up to 1e100; at the
#: low end the radius bound :data:`A_MAX` binds first (from t ~ 1e-50).
T_RANGE = (1e-100, 1e100)



def md_t_of_radius_unchecked(A, lam):
    r"""The :math:`t` at which Maugis' Eq (11) gives the radius ``A``, without input checks.

    At fixed :math:`A` the left side of Eq (11),
    :math:`G(t) = \tfrac{\lambda}{2}A^2f_1(t) + \tfrac{4\lambda^2}{3}Af_2(t)`, increases
    from 0 to :math:`\infty`, so :math:`G = 1` has one root: safeguarded Newton on
    :math:`\log G` in :math:`\log_{10}t` (bisection where a step leaves the bracket), from the
    smaller of the small- and large-:math:`t` asymptotes, to :math:`10^{-13}` in
    :math:`\log_{10}t`.  Up to four radii run the same iteration on Python floats.
    :func:`asperity.maugis_dugdale.md_t_of_radius` checks its inputs and calls this.

    Parameters
    ----------
    A : array_like
        Contact radius :math:`a(K/\pi wR^2)^{1/3} > 0` whose root lies in :data:`T_RANGE`;
        not checked.
    lam : array_like
        Maugis parameter :math:`\lambda > 0`, broadcastable with ``A``; not checked.

    Returns
    -------
    ndarray
        :math:`t` with ``md_radius(t, lam) == A`` to about 1e-13, the shape of ``A``.

    Raises
    ------
    Nothing of its own: a kernel; invalid input gives NaN or an error from NumPy.  The public
    functions of :mod:`asperity.maugis_dugdale` check their inputs before calling it.

    Examples
    --------
    >>> t = md_t_of_radius_unchecked(np.array([0.5, 2.0]), 1.0)
    >>> f1, f2, *_ = md_brackets(t)
    >>> np.round(md_radius_from_brackets(1.0, f1, f2)[0], 12).tolist()
    [0.5, 2.0]

    References
    ----------
    D. Maugis, J. Colloid Interface Sci. 150 (1992) 243-269; Adams et al., Eq (11).
    """
    A = np.asarray(A, dtype=float)
    if A.size <= 4:  # a few radii (the friction breakpoints): the same Newton on Python floats
        lam_b = np.broadcast_to(lam, A.shape)
        return np.array([_t_of_radius_float(x, y) for x, y in zip(A.ravel().tolist(), lam_b.ravel().tolist(),
                                                                   strict=True)]).reshape(A.shape)
    c2, c1 = 0.5 * lam * A * A, (4.0 / 3.0) * lam * lam * A
    a = np.full_like(A, np.log10(T_RANGE[0]))
    b = np.full_like(A, np.log10(T_RANGE[1]))
    # Start from the asymptotes: t << 1 (f1 ~ 4t^3/3, f2 ~ t^2/2), t >> 1 (f1 ~ pi t^2/2,
    # f2 ~ (pi/2 - 1) t); the smaller root is the better one.
    small = np.minimum(np.cbrt(0.75 / c2), np.sqrt(2.0 / c1))
    q2, q1 = 0.5 * np.pi * c2, (0.5 * np.pi - 1.0) * c1
    large = 2.0 / (q1 + np.sqrt(q1 * q1 + 4.0 * q2))
    s = np.log10(np.where(small < 1.0, small, large))
    with np.errstate(divide="ignore", invalid="ignore"):
        for _ in range(200):
            t = 10.0**s
            f1, f2, _, df1, df2, _ = md_brackets(t)
            G = c2 * f1 + c1 * f2  # Eq (11)'s left side, = 1 at the root
            a, b = np.where(G < 1.0, s, a), np.where(G > 1.0, s, b)
            # Newton on log G, nearly linear in s where G is a power of t (t << 1, t >> 1).
            s_new = s - np.log(G) * G / ((c2 * df1 + c1 * df2) * t * np.log(10.0))
            bad = ~np.isfinite(s_new) | (s_new < a) | (s_new > b)
            s_new = np.where(bad, 0.5 * (a + b), s_new)
            if (np.abs(s_new - s) <= 1e-13 * np.maximum(1.0, np.abs(s))).all():
                return 10.0**s_new
            s = s_new
    return 10.0**s  # pragma: no cover - bisection converges well within 200 steps


def _t_of_radius_float(A: float, lam: float) -> float:
    """:func:`md_t_of_radius_unchecked` of one radius, on Python floats (the same iteration, one element)."""
    c2, c1 = 0.5 * lam * A * A, (4.0 / 3.0) * lam * lam * A
    a, b = math.log10(T_RANGE[0]), math.log10(T_RANGE[1])
    small = min((0.75 / c2) ** (1.0 / 3.0), math.sqrt(2.0 / c1))
    q2, q1 = 0.5 * math.pi * c2, (0.5 * math.pi - 1.0) * c1
    large = 2.0 / (q1 + math.sqrt(q1 * q1 + 4.0 * q2))
    s = math.log10(small if small < 1.0 else large)
    for _ in range(200):
        t = 10.0**s
        f1, f2, _, df1, df2, _ = md_brackets(t, FLOAT_MATH)
        G = c2 * f1 + c1 * f2
        if G < 1.0:
            a = s
        elif G > 1.0:
            b = s
        slope = (c2 * df1 + c1 * df2) * t * math.log(10.0)
        s_new = s - math.log(G) * G / slope if G > 0.0 and slope > 0.0 else math.nan
        if not (math.isfinite(s_new) and a <= s_new <= b):
            s_new = 0.5 * (a + b)
        if abs(s_new - s) <= 1e-13 * max(1.0, abs(s)):
            return 10.0**s_new
        s = s_new
    return 10.0**s  # pragma: no cover - bisection converges well within 200 steps
