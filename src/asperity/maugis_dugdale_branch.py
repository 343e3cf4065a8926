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
:func:`md_solve` finds the point of the stable branch at a given penetration: the
per-asperity law of the multi-asperity integrals.

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
from dataclasses import dataclass

import numpy as np
from scipy import optimize

from ._validation import as_float_array, check_positive, scalar, ufunc_result
from ._validation_files import short_repr

__all__ = ["LAMBDA_C", "LAMBDA_RANGE", "A_MAX", "DELTA_MAX", "BranchPoint", "check_lambda", "md_branch_end",
           "md_solve", "md_pull_off"]

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
    """A point of the Maugis-Dugdale curve, in Maugis' units.

    Attributes
    ----------
    t : float
        Curve parameter :math:`\\sqrt{m^2-1}`, ``inf`` for the limit :math:`A \\to 0`.
    A : float
        Contact radius :math:`a(K/\\pi wR^2)^{1/3}`.
    P : float
        Load :math:`P/(\\pi wR)` (negative: tensile).
    delta : float
        Penetration :math:`\\Delta = u(K^2/\\pi^2w^2R)^{1/3}`.
    """

    t: float
    A: float
    P: float
    delta: float

    def to_dict(self) -> dict:
        """The point as a dict (``t`` = inf becomes None, as strict JSON wants)."""
        return {k: (None if not np.isfinite(v) else float(v)) for k, v in
                (("t", self.t), ("A", self.A), ("P", self.P), ("delta", self.delta))}


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
    lam : float
        Maugis parameter :math:`\lambda`, scalar in ``[1e-12, 1e12]`` (:data:`LAMBDA_RANGE`).

    Returns
    -------
    BranchPoint
        ``t`` (``inf`` below :math:`\lambda_c`), radius ``A``, load ``P`` = :math:`P/(\pi wR)`
        and penetration ``delta`` there, in Maugis' units.

    Raises
    ------
    ValueError
        If ``lam`` is not a real scalar in :data:`LAMBDA_RANGE`.

    Examples
    --------
    >>> end = md_branch_end(1e6)  # near JKR: -5/6 at A = 6^(-1/3)
    >>> round(end.P, 4), round(end.A, 4)
    (-0.8333, 0.5503)

    References
    ----------
    Maugis (1992); Johnson & Greenwood (1997); Adams et al., Eqs (11)-(13), (18).
    """
    lam = float(scalar(check_lambda(lam), "lam"))
    return _branch_end(lam)


def md_solve(delta, lam):
    r"""Stable-branch contact radius and load of one asperity at penetration :math:`\Delta`.

    Inverts Eq (13), :math:`\Delta(t) = A^2 - \tfrac43\lambda At`, for :math:`t` on the
    stable branch (where :math:`\Delta(t)` is strictly decreasing, i.e.
    :math:`d\Delta/dA > 0`) by safeguarded Newton iteration in :math:`\log t`, then
    evaluates Eqs (11)-(12).  At the end of a branch that runs to :math:`A \to 0`
    (:math:`\lambda < \lambda_c`) it returns the limit values, with :math:`t = \infty`.
    Vectorized over ``delta``.

    Parameters
    ----------
    delta : array_like
        Penetration :math:`\Delta = u(K^2/\pi^2w^2R)^{1/3}`, from the end of the stable
        branch :math:`\Delta_{end}` (:func:`md_branch_end`, negative) to :data:`DELTA_MAX`
        (1e150).  May be empty.
    lam : float
        Maugis parameter :math:`\lambda`, scalar in ``[1e-12, 1e12]`` (:data:`LAMBDA_RANGE`).

    Returns
    -------
    A, P, t : ndarray
        Contact radius :math:`a(K/\pi wR^2)^{1/3}`, load :math:`P/(\pi wR)` and parameter
        :math:`t = \sqrt{m^2-1}` at each ``delta`` (same shape).

    Raises
    ------
    ValueError
        If ``lam`` is not a real scalar in range, or ``delta`` is not real and finite or
        lies outside :math:`[\Delta_{end}, 10^{150}]`.

    Examples
    --------
    >>> A, P, t = md_solve([1.0, 4.0], 1e-8)  # near DMT: Delta = A^2, P = A^3 - 2
    >>> [round(float(x), 2) for x in A], [round(float(x), 2) for x in P]
    ([1.0, 2.0], [-1.0, 6.0])

    References
    ----------
    Maugis (1992); Adams et al., Eqs (11)-(13).
    """
    lam = float(scalar(check_lambda(lam), "lam"))
    delta = as_float_array(delta, "delta", allow_empty=True)
    end = _branch_end(lam)
    if ((delta < end.delta) | (delta > DELTA_MAX)).any():
        raise ValueError(f"delta (penetration) must lie in [{end.delta:.17g}, {DELTA_MAX:g}] for lam={lam:g}: "
                         f"from the end of the stable branch to DELTA_MAX; got "
                         f"values from {delta.min():g} to {delta.max():g}")
    t, A, P = _invert_penetration(delta, lam, end)
    return ufunc_result((A, P, t))


def _inverse_variable(D, end):
    """y(Delta), falling with s = log10 t and nearly linear in s away from lambda ~ 1 (Delta >> 1
    or near the branch end), and dy/dDelta: log(Delta - Delta_end) where the branch runs to
    t = inf, asinh(sqrt(Delta - Delta_end)) where it ends at a minimum of Delta."""
    x = np.maximum(D - end.delta, 1e-300)
    if np.isinf(end.t):
        return np.log(x), 1.0 / x
    r = np.sqrt(x)
    return np.arcsinh(r), 0.5 / (r * np.sqrt(1.0 + x))


@functools.lru_cache(maxsize=256)
def _penetration_table(lam: float, s_lo: float, s_hi: float):
    """y (:func:`_inverse_variable`) and dy/ds on 257 points of s = log10 t in [s_lo, s_hi].

    s(y) is nearly linear, so a cubic-Hermite inverse of this table is good to about 1e-9.
    """
    grid = np.linspace(s_lo, s_hi, 257)
    t = 10.0**grid
    D, dD = _md_curve(t, lam, True)[2::3]
    y, dy = _inverse_variable(D, _branch_end(lam))
    return grid, y, dD * t * np.log(10.0) * dy


def _table_range(lam, end, lo, hi):
    """Ends (s_lo, s_hi) of s = log10 t for the table, with Delta(s_lo) >= hi and (branch to
    t = inf) Delta(s_hi) <= lo, stepping by 2 from s_hi = 2 and s_lo = min(s_hi - 1, 0): one point
    of the curve at a time (its fast path for single floats)."""
    s_hi = float(np.log10(end.t)) if np.isfinite(end.t) else 2.0
    while np.isinf(end.t) and _md_curve(10.0**s_hi, lam)[2] > lo and s_hi < 300:
        s_hi += 2.0
    s_lo = min(s_hi - 1.0, 0.0)
    while _md_curve(10.0**s_lo, lam)[2] < hi:
        s_lo -= 2.0
    return s_lo, s_hi


def _invert_penetration(delta, lam, end):
    """(t, A, P) on the stable branch with Delta(t) = delta (delta >= end.delta), vectorized.

    A cubic-Hermite inverse of a table of y(Delta) (:func:`_inverse_variable`, cached per
    lambda and range) gives each start; safeguarded Newton on y in log10 t finishes, usually
    in one or two steps, also next to the branch end where Delta(t) is flat but y is not.
    """
    flat = delta.ravel()
    t_out, A_out, P_out = (np.full_like(flat, x) for x in (end.t, end.A, end.P))
    todo = np.flatnonzero(flat > end.delta)
    if todo.size == 0:
        return (x.reshape(delta.shape) for x in (t_out, A_out, P_out))
    target = flat[todo]
    s_lo, s_hi = _table_range(lam, end, float(target.min()), float(target.max()))
    grid, ygrid, slope = _penetration_table(lam, float(s_lo), float(s_hi))
    # Table look-up for a bracket [a, b] and a cubic-Hermite start for s(y).
    y = _inverse_variable(target, end)[0]
    j = np.clip(np.searchsorted(-ygrid, -y), 1, grid.size - 1)
    a, b = grid[j - 1], grid[j]
    D0, D1 = ygrid[j - 1], ygrid[j]
    x = (y - D0) / (D1 - D0)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        H = ((2 * x - 3) * x * x + 1) * a + (3 - 2 * x) * x * x * b \
            + (D1 - D0) * x * (1 - x) * ((1 - x) / slope[j - 1] - x / slope[j])
    s = np.where(np.isfinite(H) & (H >= a) & (H <= b), H, a + (b - a) * x)
    active = np.arange(target.size)
    for _ in range(100):
        if active.size == 0:
            break
        sa = s[active]
        t = 10.0**sa
        A, P, D, dA, dP, dD = _md_curve(t, lam, True)
        resid = D - target[active]
        # Keep the bracket: Delta decreases with s.
        a[active] = np.where(resid > 0, sa, a[active])
        b[active] = np.where(resid < 0, sa, b[active])
        yD, dy = _inverse_variable(D, end)
        slope = dD * t * np.log(10.0) * dy  # dy/ds
        with np.errstate(divide="ignore", invalid="ignore"):
            step = np.where(slope < 0, -(yD - y[active]) / slope, np.nan)
        s_new = sa + step
        bad = ~np.isfinite(s_new) | (s_new < a[active]) | (s_new > b[active])
        s_new = np.where(bad, 0.5 * (a[active] + b[active]), s_new)
        tol = 1e-14 * np.maximum(1.0, np.abs(sa))
        # Stop at a residual at rounding level (near the branch end Delta(t) is flat and the
        # step cannot shrink below rounding), a tiny step or a collapsed bracket.
        done = ((np.abs(resid) <= 1e-15 * np.maximum(np.abs(D), np.abs(target[active])))
                | (~bad & (np.abs(step) <= tol)) | (b[active] - a[active] <= tol))
        # A finished step is tiny: carry A and P along it to first order.
        dt = np.where(bad, 0.0, 10.0**s_new - t)[done]
        fin = todo[active[done]]
        t_out[fin], A_out[fin], P_out[fin] = t[done] + dt, A[done] + dA[done] * dt, P[done] + dP[done] * dt
        s[active] = s_new
        active = active[~done]
    return (x.reshape(delta.shape) for x in (t_out, A_out, P_out))


def md_pull_off(lam, control: str = "load") -> BranchPoint:
    r"""Pull-off point of one Maugis-Dugdale asperity.

    .. math::
        P_{load} = \min_{t > 0} P(t), \qquad P_{displacement} = P(t_{end})

    Parameters
    ----------
    lam : float
        Maugis parameter :math:`\lambda`, scalar in ``[1e-12, 1e12]`` (:data:`LAMBDA_RANGE`).
    control : {'load', 'displacement'}
        ``'load'`` (default): the minimum of :math:`P` over the whole curve (JKR: :math:`-3/2`
        at :math:`A = (3/2)^{1/3}`; DMT: :math:`-2`).  ``'displacement'``: the load at the end
        of the stable branch, :func:`md_branch_end` (JKR: :math:`-5/6` at :math:`A = 6^{-1/3}`).

    Returns
    -------
    BranchPoint
        Where pull-off happens: ``t``, ``A``, ``delta``, and ``P`` the (negative) pull-off
        load :math:`P/(\pi wR)`.

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
    lam = float(scalar(check_lambda(lam), "lam"))
    if not isinstance(control, str) or control not in ("load", "displacement"):
        raise ValueError(f"control must be 'load' or 'displacement', got {control!r}")
    if control == "displacement":
        return _branch_end(lam)
    return _load_pull_off(lam)


@functools.lru_cache(maxsize=1024)
def _load_pull_off(lam: float) -> BranchPoint:
    limit = _limit_point(lam)
    s = _first_sign_change(4, lam)
    if s is None:
        return limit
    point = _point(lam, 10.0**s)
    return limit if point.P > limit.P else point
