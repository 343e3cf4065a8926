r"""The stable Maugis-Dugdale branch: its end, the critical :math:`\lambda_c`, points on it, pull-off.

Along the parametric curve of :mod:`asperity.maugis_dugdale` (Eqs 11-13 in
:math:`t = \sqrt{m^2-1}`), one asperity is stable under displacement control while
:math:`d\Delta/dA > 0`.  Above the critical Maugis parameter :math:`\lambda_c \approx
0.938` the curve :math:`\Delta(A)` has an interior minimum (:math:`d\Delta/dt = 0`),
which ends the stable branch; below it the branch runs to :math:`A \to 0`, where
:math:`At \to x_0` with

.. math::
    \tfrac{\pi\lambda}{4}x_0^2 + \tfrac{4\lambda^2}{3}\big(\tfrac{\pi}{2}-1\big)x_0 = 1,
    \qquad \Delta_{end} = -\tfrac43\lambda x_0, \qquad P_{end} = -\tfrac{\pi}{2}\lambda x_0^2.

:math:`\lambda_c` is where :math:`\Delta - \Delta(A{=}0) = cA^2 + O(A^3)` changes the sign
of :math:`c`.  The pull-off load is the load at the end of the stable branch under
displacement control, and the minimum of :math:`P` over the whole curve under load
control (JKR: :math:`-5/6` and :math:`-3/2`; DMT: :math:`-2` under both).
:func:`~asperity.maugis_dugdale_solve.md_solve` finds the point of the stable branch at a
given penetration: the per-asperity law of the multi-asperity integrals.  The functions
broadcast over :math:`\lambda` (:func:`for_each_lambda`: one solution per distinct value).

:mod:`asperity.maugis_dugdale` holds the curve (Eqs 11-14) and re-exports every public
name of this module.  The ranges handled (:data:`LAMBDA_RANGE`, :data:`A_MAX`) live here
because both modules check them; the curve is imported from :mod:`asperity.maugis_dugdale`
on first use, since that module imports this one.

References
----------
.. [1] D. Maugis, "Adhesion of spheres: the JKR-DMT transition using a Dugdale
   model", J. Colloid Interface Sci. 150 (1992) 243-269.
.. [2] K. L. Johnson, J. A. Greenwood, "An adhesion map for the contact of elastic
   spheres", J. Colloid Interface Sci. 192 (1997) 326-333.
"""

from __future__ import annotations

import functools
from dataclasses import astuple, dataclass

import numpy as np
from scipy import optimize

from ._validation import check_positive
from ._validation_files import short_repr

__all__ = ["LAMBDA_C", "LAMBDA_RANGE", "A_MAX", "DELTA_MAX", "BranchPoint", "check_lambda", "for_each_lambda",
           "md_branch_end", "md_pull_off"]

#: Range of the Maugis parameter handled (DMT and JKR are within 1e-6 of their limits far inside).
LAMBDA_RANGE = (1e-12, 1e12)


def check_lambda(lam):
    """The Maugis parameter as a float array within :data:`LAMBDA_RANGE`.

    Raises
    ------
    ValueError
        If ``lam`` is not a real number or array of real numbers in
        ``[1e-12, 1e12]`` (use :mod:`asperity.dmt` below and :mod:`asperity.jkr` above).
    """
    lam = check_positive(lam, "lam")
    lo, hi = LAMBDA_RANGE
    if ((lam < lo) | (lam > hi)).any():
        raise ValueError(f"lam (Maugis parameter) must lie in [{lo:g}, {hi:g}] (use asperity.dmt below and "
                         f"asperity.jkr above), got {short_repr(lam)}")
    return lam


def for_each_lambda(solve, lam, *arrays, outputs: int = 1):
    r"""``solve(lam, *arrays)`` with a scalar lambda, once for each distinct value of ``lam``.

    The Maugis-Dugdale curve is solved for one :math:`\lambda` at a time (its tables and
    brackets depend on it); this applies such a solver to arrays, like a ufunc.

    Parameters
    ----------
    solve : callable
        ``solve(lam_value, *arrays_subset)`` with a Python float and the elements of
        ``arrays`` where ``lam`` equals it (1-d, or the full broadcast arrays when ``lam``
        holds one value); returns one array, or a tuple of ``outputs`` arrays, of their shape.
    lam : ndarray
        Maugis parameters (already checked: :func:`check_lambda`).
    arrays : ndarray
        The other inputs (positional, ``*arrays``), broadcast with ``lam`` (first).
    outputs : int
        Number of arrays ``solve`` returns (1: a single array, not a tuple).

    Returns
    -------
    ndarray or tuple of ndarray
        The results in the broadcast shape of ``lam`` and ``arrays``.

    Raises
    ------
    ValueError
        Whatever ``solve`` raises for a value of ``lam`` (the first failing value, in
        increasing order), or if the shapes do not broadcast.

    Examples
    --------
    >>> for_each_lambda(lambda lam, x: lam * x, np.array([1.0, 2.0, 1.0]), np.array(3.0)).tolist()
    [3.0, 6.0, 3.0]

    References
    ----------
    Maugis (1992): the curve depends on :math:`\lambda` alone in these units.
    """
    if np.ndim(lam) == 0 and all(np.ndim(a) <= 1 for a in arrays) and len(arrays) <= 1:  # one lambda: as it is
        result = solve(float(lam), *arrays)
        parts = result if outputs > 1 else (result,)
        shape = np.shape(arrays[0]) if arrays else ()
        out = tuple(np.asarray(r, dtype=float) if np.shape(r) == shape else
                    np.broadcast_to(np.asarray(r, dtype=float), shape).copy() for r in parts)
        return out if outputs > 1 else out[0]
    lam, *arrays = np.broadcast_arrays(lam, *arrays)
    values = np.unique(lam)

    def parts(result):
        return result if outputs > 1 else (result,)

    if values.size <= 1:  # one lambda (or none: empty arrays) is solved in one call
        result = parts(solve(float(values[0]) if values.size else 1.0, *arrays))
        out = tuple(np.broadcast_to(np.asarray(r, dtype=float), lam.shape).copy() for r in result)
    else:
        out = tuple(np.empty(lam.shape) for _ in range(outputs))
        for value in values:
            mask = lam == value
            for o, r in zip(out, parts(solve(float(value), *(a[mask] for a in arrays))), strict=True):
                o[mask] = r
    return out if outputs > 1 else out[0]


#: Largest contact radius A the curve handles.  For large A the curve is Hertz-like,
#: A^2 t^3 ~ 3/(2 lam), and its largest output is the load's t-derivative,
#: dP/dt ~ -3 A^3/t ~ -A^(11/3) lam^(1/3): at lam = 1e12 it overflows near A = 6e82.
#: 1e80 keeps every output of md_curve finite over all of LAMBDA_RANGE.
A_MAX = 1e80
#: Largest penetration Delta that md_solve accepts.  For large A, Delta -> A^2 and A ~ t^(-3/2);
#: md_solve brackets its root within two decades of t, where A can be 10^3 times larger, and
#: that must stay below A_MAX: (A_MAX/1e3)^2 = 1e154, rounded down to 1e150.
DELTA_MAX = 1e150


def _md_curve(t, lam, derivatives=False):
    """:func:`asperity.maugis_dugdale.md_curve`, imported on first use (that module imports this one)."""
    from .maugis_dugdale import md_curve

    return md_curve(t, lam, derivatives)


def _x0(lam):
    """Limit of A t as A -> 0: root of (pi lam/4) x^2 + (4 lam^2/3)(pi/2 - 1) x - 1 = 0."""
    q2 = 0.25 * np.pi * lam
    q1 = (4.0 / 3.0) * lam * lam * (0.5 * np.pi - 1.0)
    return 2.0 / (q1 + np.sqrt(q1 * q1 + 4.0 * q2))


def _small_a_curvature(lam):
    """c in Delta - Delta(A=0) = c A^2 + O(A^3) near A = 0; the branch reaches A = 0 iff c > 0."""
    x0 = _x0(lam)
    dF = 0.5 * np.pi * lam * x0 + (4.0 / 3.0) * lam * lam * (0.5 * np.pi - 1.0)
    c2 = (0.25 * np.pi * lam + 2.0 * lam * lam / (3.0 * x0)) / dF
    return 1.0 - (4.0 / 3.0) * lam * c2


#: Critical Maugis parameter: below it the stable branch runs to A -> 0.
LAMBDA_C = float(optimize.brentq(_small_a_curvature, 0.5, 1.5, xtol=1e-15, rtol=1e-15))


@dataclass(frozen=True)
class BranchPoint:
    """A point of the Maugis-Dugdale curve, in Maugis' units (arrays of points for an array of lambda).

    Attributes
    ----------
    t : float or ndarray
        Curve parameter :math:`\\sqrt{m^2-1}`, ``inf`` for the limit :math:`A \\to 0`.
    A : float or ndarray
        Contact radius :math:`a(K/\\pi wR^2)^{1/3}`.
    P : float or ndarray
        Load :math:`P/(\\pi wR)` (negative: tensile).
    delta : float or ndarray
        Penetration :math:`\\Delta = u(K^2/\\pi^2w^2R)^{1/3}`.
    """

    t: float
    A: float
    P: float
    delta: float

    def to_dict(self) -> dict:
        """The point as a dict (``t`` = inf becomes None, as strict JSON wants; arrays become
        nested lists)."""
        def plain(v):
            if np.ndim(v):
                return [plain(x) for x in v]
            return None if not np.isfinite(v) else float(v)

        return {k: plain(v) for k, v in (("t", self.t), ("A", self.A), ("P", self.P), ("delta", self.delta))}


def _branch_points(point, lam) -> BranchPoint:
    """``point(lam)`` (a BranchPoint of one float lambda) for each element of ``lam``: a BranchPoint
    of floats for a scalar, of arrays of ``lam``'s shape otherwise."""
    lam = check_lambda(lam)
    if lam.ndim == 0:
        return point(float(lam))
    fields = for_each_lambda(lambda x: astuple(point(x)), lam, outputs=4)
    return BranchPoint(*fields)


def _limit_point(lam: float) -> BranchPoint:
    """The end A -> 0 of the curve (t -> inf), in closed form."""
    x0 = float(_x0(lam))
    return BranchPoint(t=np.inf, A=0.0, P=-0.5 * np.pi * lam * x0 * x0, delta=-(4.0 / 3.0) * lam * x0)


def _point(lam: float, t: float) -> BranchPoint:
    A, P, D = _md_curve(np.float64(t), lam)
    return BranchPoint(t=t, A=float(A), P=float(P), delta=float(D))


def _first_sign_change(column: int, lam: float, hi=16.0, n=400):
    """log10 t of the first change from < 0 to >= 0 of a t-derivative (4: dP/dt, 5: dDelta/dt), or None."""
    def func(t):
        return _md_curve(t, lam, True)[column]

    lo = min(-12.0, np.log10(1e-3 / lam))  # JKR-like curves turn at t ~ 1/lam
    s = np.linspace(lo, hi, n)
    vals = func(10.0**s)
    idx = np.flatnonzero(vals >= 0)
    if idx.size == 0 or idx[0] == 0:
        return None
    i = idx[0]

    def f(x):
        return float(func(10.0**x))

    if (f(s[i - 1]) < 0) == (f(s[i]) < 0):
        # The derivative is flat to rounding (DMT-like curves): its sign on the grid was noise,
        # and the grid point is as good a turning point as any.
        return s[i]
    return optimize.brentq(f, s[i - 1], s[i], xtol=1e-14, rtol=1e-15)


@functools.lru_cache(maxsize=4096)
def _branch_end(lam: float) -> BranchPoint:
    if lam < LAMBDA_C:
        return _limit_point(lam)
    s = _first_sign_change(5, lam)
    if s is None:  # lam within rounding of LAMBDA_C: the minimum sits at A -> 0
        return _branch_end(np.nextafter(LAMBDA_C, 0.0))
    return _point(lam, 10.0**s)


def md_branch_end(lam) -> BranchPoint:
    r"""End of the stable, displacement-controlled branch of one Maugis-Dugdale asperity.

    Above :math:`\lambda_c` (:data:`LAMBDA_C`) it is the minimum of :math:`\Delta(A)`,
    :math:`d\Delta/dA = 0`; below, the limit :math:`A \to 0`, where :math:`At \to x_0`:

    .. math::
        \frac{\pi\lambda}{4}x_0^2 + \frac{4\lambda^2}{3}\Big(\frac{\pi}{2}-1\Big)x_0 = 1,
        \qquad \Delta_{end} = -\frac43\lambda x_0,\qquad P_{end} = -\frac{\pi}{2}\lambda x_0^2.

    The load there is the pull-off force under displacement control.

    Parameters
    ----------
    lam : array_like
        Maugis parameter :math:`\lambda` in ``[1e-12, 1e12]`` (:data:`LAMBDA_RANGE`).

    Returns
    -------
    BranchPoint
        ``t`` (``inf`` below :math:`\lambda_c`), radius ``A``, load ``P`` = :math:`P/(\pi wR)`
        and penetration ``delta`` there, in Maugis' units: floats for a scalar ``lam``,
        arrays of its shape otherwise.

    Raises
    ------
    ValueError
        If ``lam`` is not real or lies outside :data:`LAMBDA_RANGE`.

    Examples
    --------
    >>> end = md_branch_end(1e6)  # near JKR: -5/6 at A = 6^(-1/3)
    >>> round(end.P, 4), round(end.A, 4)
    (-0.8333, 0.5503)

    References
    ----------
    Maugis (1992); Johnson & Greenwood (1997); Adams et al., Eqs (11)-(13), (18).
    """
    lo, hi = LAMBDA_RANGE
    if type(lam) is float and lo <= lam <= hi:  # the integrals' path: one checked float
        return _branch_end(lam)
    return _branch_points(_branch_end, lam)


def md_pull_off(lam, control: str = "load") -> BranchPoint:
    r"""Pull-off point of one Maugis-Dugdale asperity.

    .. math::
        P_{load} = \min_{t > 0} P(t), \qquad P_{displacement} = P(t_{end})

    Parameters
    ----------
    lam : array_like
        Maugis parameter :math:`\lambda` in ``[1e-12, 1e12]`` (:data:`LAMBDA_RANGE`).
    control : {'load', 'displacement'}
        ``'load'`` (default): the minimum of :math:`P` over the whole curve (JKR: :math:`-3/2`
        at :math:`A = (3/2)^{1/3}`; DMT: :math:`-2`).  ``'displacement'``: the load at the end
        of the stable branch, :func:`md_branch_end` (JKR: :math:`-5/6` at :math:`A = 6^{-1/3}`).

    Returns
    -------
    BranchPoint
        Where pull-off happens: ``t``, ``A``, ``delta``, and ``P`` the (negative) pull-off
        load :math:`P/(\pi wR)`; floats for a scalar ``lam``, arrays of its shape otherwise
        (the adhesion map's pull-off against :math:`\lambda` is one call).

    Raises
    ------
    ValueError
        If ``lam`` is outside :data:`LAMBDA_RANGE` or ``control`` is neither name.

    Examples
    --------
    >>> round(md_pull_off(1e6, "load").P, 4), round(md_pull_off(1e-8, "load").P, 4)
    (-1.5, -2.0)

    References
    ----------
    Maugis (1992), Johnson & Greenwood (1997).
    """
    if not isinstance(control, str) or control not in ("load", "displacement"):
        raise ValueError(f"control must be 'load' or 'displacement', got {control!r}")
    return _branch_points(_branch_end if control == "displacement" else _load_pull_off, lam)


@functools.lru_cache(maxsize=1024)
def _load_pull_off(lam: float) -> BranchPoint:
    limit = _limit_point(lam)
    s = _first_sign_change(4, lam)
    if s is None:
        return limit
    point = _point(lam, 10.0**s)
    return limit if point.P > limit.P else point
