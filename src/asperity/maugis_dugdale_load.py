r"""Maugis-Dugdale contact under load control, and the physical shell of the Maugis-Dugdale laws.

An AFM tip or a colloidal probe pressed with a given load :math:`P` sits on the
*load-stable* branch of the Maugis-Dugdale curve of :mod:`asperity.maugis_dugdale`
(Eqs 11-13 in :math:`t = \sqrt{m^2-1}`): from :math:`A = \infty` (:math:`t \to 0`,
:math:`P \to \infty`) down to the load-controlled pull-off, the first minimum of
:math:`P(t)` (:func:`~asperity.maugis_dugdale.md_pull_off` with ``control='load'``), where
:math:`dP/dA = 0` and the contact jumps apart.  On that branch :math:`P(t)` decreases
strictly, so each load :math:`P \ge P_{po}` has one radius: :func:`md_solve_load` finds its
:math:`t` by safeguarded, vectorised Newton iteration in :math:`\log t`, as
:func:`~asperity.maugis_dugdale.md_solve` does for a penetration.

The physical shell works in SI units, like ContactEngineering's Adhesion reference
solutions (dimensionless core, physical shell): with :math:`K = \tfrac43E^*`,

.. math::
    a = A\Big(\frac{\pi wR^2}{K}\Big)^{1/3},\qquad P = \pi wR\,\bar P,\qquad
    \delta = \Delta\Big(\frac{\pi^2w^2R}{K^2}\Big)^{1/3},\qquad
    \lambda = 2\sigma_0\Big(\frac{R}{\pi wK^2}\Big)^{1/3}.

:func:`md_contact_radius` gives the contact radius against the load (load control),
:func:`md_normal_force` the force against the penetration (displacement control, the stable
branch of :func:`~asperity.maugis_dugdale.md_solve`), :func:`md_pull_off_force` the pull-off
force.  They take either the Dugdale stress ``sigma0`` or the Maugis parameter ``lam``, and
broadcast over every input like ufuncs.  Each distinct :math:`\lambda` is one solve (0.15-0.5
ms): loads or penetrations at one :math:`\lambda` cost little more than one, but a
sweep over radii at a fixed ``sigma0`` changes :math:`\lambda \propto R^{1/3}` at every
element (2000 radii: 0.3 s for the pull-off force, 1 s for the contact radius).

References
----------
.. [1] D. Maugis, "Adhesion of spheres: the JKR-DMT transition using a Dugdale
   model", J. Colloid Interface Sci. 150 (1992) 243-269, Eqs (11)-(14) of Adams et al.
.. [2] K. L. Johnson, J. A. Greenwood, "An adhesion map for the contact of elastic
   spheres", J. Colloid Interface Sci. 192 (1997) 326-333.
"""

from __future__ import annotations

import numpy as np

from ._validation import as_float_array, check_broadcast, check_finite_result, check_positive, ufunc_result
from ._validation_files import short_repr
from .maugis_dugdale import check_lambda, md_branch_end, md_curve, md_lambda, md_pull_off, md_solve
from .maugis_dugdale_branch import for_each_lambda
from .maugis_units import check_floor_in_si, penetration_in_maugis_units
from .units import to_si

__all__ = ["P_MAX", "md_solve_load", "md_contact_radius", "md_normal_force", "md_pull_off_force",
           "penetration_in_maugis_units"]

#: Largest load :math:`P/(\pi wR)` :func:`md_solve_load` accepts: its radius (about
#: :math:`P^{1/3}`) stays far below :data:`~asperity.maugis_dugdale.A_MAX` while bracketing.
P_MAX = 1e200


def md_solve_load(P, lam):
    r"""Contact radius and penetration of one Maugis-Dugdale asperity at a given load (load control).

    Inverts Eq (12), :math:`P(t) = A^3 - \lambda A^2[t + m^2\tan^{-1}t]` with :math:`A` from
    Eq (11), for :math:`t` on the load-stable branch, where :math:`P(t)` is strictly decreasing
    (:math:`dP/dA > 0`): from :math:`t \to 0` (:math:`A \to \infty`) to the load-controlled
    pull-off :math:`t_{po}` (:func:`~asperity.maugis_dugdale.md_pull_off`).

    .. math::
        P(t) = P,\qquad 0 < t \le t_{po},\qquad \Delta = A^2 - \tfrac43\lambda At

    Broadcasts like a ufunc over ``P`` and ``lam`` (one inversion per distinct :math:`\lambda`).

    Parameters
    ----------
    P : array_like
        Load :math:`P/(\pi wR)` (negative: tensile), from the load-controlled pull-off
        :math:`P_{po}` (JKR: -3/2, DMT: -2; within 1e-12 relative below it counts as it) to
        :data:`P_MAX`.  May be empty.
    lam : array_like
        Maugis parameter :math:`\lambda` in ``[1e-12, 1e12]``
        (:data:`~asperity.maugis_dugdale.LAMBDA_RANGE`), broadcast with ``P``.

    Returns
    -------
    A, delta, t : ndarray or numpy.float64
        Contact radius :math:`a(K/\pi wR^2)^{1/3}`, penetration
        :math:`\Delta = u(K^2/\pi^2w^2R)^{1/3}` and :math:`t = \sqrt{m^2-1}` at each load
        (the broadcast shape).

    Raises
    ------
    ValueError
        If ``lam`` is not real or out of range, ``P`` is not real and finite or lies
        outside :math:`[P_{po}(\lambda), 10^{200}]`, or the shapes do not broadcast.

    Examples
    --------
    >>> A, delta, t = md_solve_load([-1.0, 6.0], 1e-8)  # near DMT: P = A^3 - 2
    >>> [round(float(x), 6) for x in A]
    [1.0, 2.0]

    References
    ----------
    Maugis (1992); Johnson & Greenwood (1997); Adams et al., Eqs (11)-(13).
    """
    lam = check_lambda(lam)
    P = as_float_array(P, "P", allow_empty=True)
    check_broadcast(P=P, lam=lam)
    return ufunc_result(for_each_lambda(_solve_load_one, lam, P, outputs=3))


def _solve_load_one(lam: float, P):
    """(A, delta, t) at loads ``P`` for one lambda."""
    po = md_pull_off(lam, "load")
    # A load within rounding (1e-12 relative) below the pull-off, as a round trip through SI
    # units gives, is the pull-off itself.
    P = np.where((P < po.P) & (P >= po.P * (1.0 + 1e-12)), po.P, P)
    if np.any((P < po.P) | (P > P_MAX)):
        raise ValueError(f"P (load over pi w R) must lie in [{po.P:.17g}, {P_MAX:g}] for lam = {lam:g}: from the "
                         f"load-controlled pull-off to P_MAX; got values from {P.min():g} to {P.max():g}")
    t = _invert_load(P, lam, po)
    finite = np.isfinite(t)
    A, _, D = md_curve(np.where(finite, t, 1.0), lam)
    return np.where(finite, A, po.A), np.where(finite, D, po.delta), t


def _invert_load(P, lam, po):
    """t on the load-stable branch with P(t) = P (P >= po.P), vectorized (P(t) decreases in t)."""
    flat = P.ravel()
    out = np.empty_like(flat)
    if flat.size == 0:
        return out.reshape(P.shape)
    at_end = flat <= po.P
    out[at_end] = po.t
    todo = ~at_end
    if not np.any(todo):
        return out.reshape(P.shape)
    target = flat[todo]

    def load(s, derivatives=False):
        return md_curve(10.0**s, lam, derivatives)

    # Bracket in s = log10 t; P(s) decreases up to the pull-off.
    s_hi = np.log10(po.t) if np.isfinite(po.t) else 2.0
    while not np.isfinite(po.t) and load(s_hi)[1] > target.min() and s_hi < 99.0:
        s_hi += 2.0
    s_lo = min(s_hi - 1.0, 0.0)
    while load(s_lo)[1] < target.max():
        s_lo -= 2.0
    grid = np.linspace(s_lo, s_hi, 257)
    pgrid = load(grid)[1]
    j = np.clip(np.searchsorted(-pgrid, -target), 1, grid.size - 1)
    a, b = grid[j - 1], grid[j]
    with np.errstate(divide="ignore", invalid="ignore"):
        frac = (pgrid[j - 1] - target) / (pgrid[j - 1] - pgrid[j])
    s = a + (b - a) * np.where(np.isfinite(frac), np.clip(frac, 0.0, 1.0), 0.5)
    active = np.arange(target.size)
    for _ in range(100):
        if active.size == 0:
            break
        sa = s[active]
        _, Pa, _, _, dP, _ = load(sa, True)
        resid = Pa - target[active]
        a[active] = np.where(resid > 0, sa, a[active])  # keep the bracket: P decreases with s
        b[active] = np.where(resid < 0, sa, b[active])
        slope = dP * 10.0**sa * np.log(10.0)
        with np.errstate(divide="ignore", invalid="ignore"):
            step = np.where(slope < 0, -resid / slope, np.nan)
        s_new = sa + step
        bad = ~np.isfinite(s_new) | (s_new < a[active]) | (s_new > b[active])
        s_new = np.where(bad, 0.5 * (a[active] + b[active]), s_new)
        tol = 1e-14 * np.maximum(1.0, np.abs(sa))
        # Stop at a tiny step, a collapsed bracket, or a residual at rounding level (near the
        # pull-off P(t) is flat and the step cannot shrink below rounding).
        # A point whose residual is at rounding level is kept: a Newton step from it, where P is
        # flat, moved a load one ulp above the pull-off 2e-5 away (found by hypothesis in CI).
        converged = np.abs(resid) <= 4e-16 * np.maximum(np.abs(Pa), np.abs(target[active]))
        done = converged | (~bad & (np.abs(step) <= tol)) | (b[active] - a[active] <= tol)
        s[active] = np.where(converged | (done & bad), sa, s_new)
        active = active[~done]
    out[todo] = 10.0**s
    return out.reshape(P.shape)


def _scales(R, w, E_star, sigma0, lam):
    """Validated R, w, E_star (SI) and lambda as arrays that broadcast together; exactly one of sigma0, lam."""
    R = check_positive(to_si(R, "m", "R"), "R")
    w = check_positive(to_si(w, "J/m^2", "w"), "w")
    E_star = check_positive(to_si(E_star, "Pa", "E_star"), "E_star")
    if (sigma0 is None) == (lam is None):
        raise ValueError("give exactly one of sigma0 (Dugdale stress, Pa) and lam (Maugis parameter)")
    if lam is None:
        lam = md_lambda(R, w, E_star, to_si(sigma0, "Pa", "sigma0"))
        try:
            check_lambda(lam)
        except ValueError:
            raise ValueError(f"R, w, E_star, sigma0 give the Maugis parameter lam = {short_repr(lam)}, outside "
                             "[1e-12, 1e12] (lam = 2 sigma0 (R/(pi w K^2))^(1/3)): give values of physical size, "
                             "or use asperity.dmt (small lam) or asperity.jkr (large lam)") from None
    lam = check_lambda(lam)
    check_broadcast(R=R, w=w, E_star=E_star, **({"lam": lam} if sigma0 is None else {}))
    return R, w, E_star, lam


def md_contact_radius(P, *, R, w, E_star, sigma0=None, lam=None):
    r"""Contact radius of a Maugis-Dugdale sphere on a flat at load :math:`P` (load control), in metres.

    .. math::
        a = A\Big(\frac{\pi wR^2}{K}\Big)^{1/3},\qquad A = A_{MD}\big(P/(\pi wR);\ \lambda\big),
        \qquad K = \tfrac43E^*,\qquad \lambda = 2\sigma_0\Big(\frac{R}{\pi wK^2}\Big)^{1/3}

    with :math:`A_{MD}` the exact solution on the load-stable branch (:func:`md_solve_load`).
    It tends to JKR (:func:`asperity.jkr.jkr_contact_radius`) as :math:`\lambda \to \infty`
    and to DMT (:func:`asperity.dmt.dmt_contact_radius`) as :math:`\lambda \to 0`.

    Parameters
    ----------
    P : array_like
        Normal load :math:`P` (N, compressive > 0), from minus the pull-off force
        (:func:`md_pull_off_force`) up.
    R : array_like
        Sphere (tip) radius :math:`R` (m), > 0.
    w : array_like
        Work of adhesion :math:`w` (J/m^2), > 0.
    E_star : array_like
        Composite Young's modulus :math:`E^*` (Pa), > 0.
    sigma0 : array_like, optional
        Dugdale adhesive stress :math:`\sigma_0` (Pa), > 0; or give ``lam``.
    lam : array_like, optional
        Maugis parameter :math:`\lambda` in ``[1e-12, 1e12]``; or give ``sigma0``.

    Returns
    -------
    ndarray
        Contact radius :math:`a` (m), the broadcast shape of the inputs.

    Raises
    ------
    ValueError
        If an input is not real and finite or out of range, the shapes do not broadcast,
        both or neither of ``sigma0`` and ``lam`` are given, or a load is more tensile than the pull-off load.

    Examples
    --------
    >>> import math
    >>> R, w, E_star = 20e-9, 0.1, 100e9
    >>> a = float(md_contact_radius(0.0, R=R, w=w, E_star=E_star, lam=1e6))  # JKR: A^3 = 6 at P = 0
    >>> round(a / (6 * math.pi * w * R**2 / (4 / 3 * E_star)) ** (1 / 3), 4)
    1.0

    References
    ----------
    Maugis (1992), Eqs (11)-(14) of Adams et al.; Johnson & Greenwood (1997).
    """
    R, w, E, lam = _scales(R, w, E_star, sigma0, lam)
    P = as_float_array(to_si(P, "N", "P"), "P", allow_empty=True)
    check_broadcast(P=P, R=R, w=w, E_star=E, lam=lam)
    K = np.float64(4.0 / 3.0) * E
    with np.errstate(all="ignore"):
        P_hat = P / (np.pi * w * R)
    check_finite_result(P_hat, "the load P/(pi w R)", P=P, R=R, w=w)
    check_floor_in_si(P, P_hat, md_pull_off(lam).P, "P (load)", "N", "minus the Maugis-Dugdale pull-off force",
                      rtol=1e-12)  # md_solve_load's own slack
    A = md_solve_load(P_hat, lam)[0]
    with np.errstate(all="ignore"):
        a = A * np.cbrt(np.pi * w * R * R / K)
    return check_finite_result(a, "the Maugis-Dugdale contact radius", P=P, R=R, w=w, E_star=E_star)


def md_normal_force(delta, *, R, w, E_star, sigma0=None, lam=None):
    r"""Normal force of a Maugis-Dugdale sphere at penetration :math:`\delta` (displacement control), in newtons.

    .. math::
        P = \pi wR\,\bar P_{MD}(\Delta;\ \lambda),\qquad
        \Delta = \delta\Big(\frac{K^2}{\pi^2w^2R}\Big)^{1/3},\qquad K = \tfrac43E^*

    on the stable branch of :func:`~asperity.maugis_dugdale.md_solve`, down to its end
    (:func:`~asperity.maugis_dugdale.md_branch_end`), where the neck snaps.

    Parameters
    ----------
    delta : array_like
        Penetration :math:`\delta` (m) of the undeformed sphere into the flat (negative: apart),
        from the end of the stable branch up.
    R : array_like
        Sphere radius :math:`R` (m), > 0.
    w : array_like
        Work of adhesion :math:`w` (J/m^2), > 0.
    E_star : array_like
        Composite Young's modulus :math:`E^*` (Pa), > 0.
    sigma0 : array_like, optional
        Dugdale adhesive stress :math:`\sigma_0` (Pa), > 0; or give ``lam``.
    lam : array_like, optional
        Maugis parameter :math:`\lambda` in ``[1e-12, 1e12]``; or give ``sigma0``.

    Returns
    -------
    ndarray
        Normal force :math:`P` (N, compressive > 0), the broadcast shape of the inputs.

    Raises
    ------
    ValueError
        If an input is not real and finite or out of range, the shapes do not broadcast,
        both or neither of ``sigma0`` and ``lam`` are given, or a penetration lies below the end of the stable branch.

    Examples
    --------
    >>> import math
    >>> R, w, E_star = 20e-9, 0.1, 100e9
    >>> P = float(md_normal_force(1e-9, R=R, w=w, E_star=E_star, lam=1e-9))  # DMT: K R^1/2 d^3/2 - 2 pi w R
    >>> round(P / (4 / 3 * E_star * math.sqrt(R) * 1e-9**1.5 - 2 * math.pi * w * R), 4)
    1.0

    References
    ----------
    Maugis (1992), Eqs (11)-(14) of Adams et al.
    """
    R, w, E, lam = _scales(R, w, E_star, sigma0, lam)
    delta = as_float_array(to_si(delta, "m", "delta"), "delta", allow_empty=True)
    check_broadcast(delta=delta, R=R, w=w, E_star=E, lam=lam)
    delta_hat, unit = penetration_in_maugis_units(delta, R=R, w=w, E_star=E)
    check_floor_in_si(delta, delta_hat, md_branch_end(lam).delta, "delta (penetration)", "m",
                      "the end of the stable Maugis-Dugdale branch")
    with np.errstate(all="ignore"):
        F = md_solve(delta_hat, lam)[1] * unit
    return check_finite_result(F, "the Maugis-Dugdale force", delta=delta, R=R, w=w, E_star=E_star)


def md_pull_off_force(*, R, w, E_star, sigma0=None, lam=None, control: str = "load"):
    r"""Pull-off force of a Maugis-Dugdale sphere on a flat, in newtons (> 0: the load at pull-off is minus it).

    .. math::
        F_{po} = -\pi wR\,\bar P_{po}(\lambda),\qquad
        \bar P_{po} = \min_t \bar P(t)\ \text{(load control)}

    :math:`\tfrac32\pi wR` in the JKR limit (:math:`\lambda\to\infty`) and :math:`2\pi wR`
    in the DMT limit (:math:`\lambda \to 0`) under load control.

    Parameters
    ----------
    R : array_like
        Sphere radius :math:`R` (m), > 0.
    w : array_like
        Work of adhesion :math:`w` (J/m^2), > 0.
    E_star : array_like
        Composite Young's modulus :math:`E^*` (Pa), > 0.
    sigma0 : array_like, optional
        Dugdale adhesive stress :math:`\sigma_0` (Pa), > 0; or give ``lam``.
    lam : array_like, optional
        Maugis parameter :math:`\lambda` in ``[1e-12, 1e12]``; or give ``sigma0``.
    control : {'load', 'displacement'}
        Which quantity is controlled (default ``'load'``, an AFM in force spectroscopy with a
        soft cantilever); see :func:`~asperity.maugis_dugdale.md_pull_off`.

    Returns
    -------
    float or ndarray
        The pull-off force (N), > 0: a float for scalar inputs, else an array of their
        broadcast shape.

    Raises
    ------
    ValueError
        If an input is not real and finite or out of range, the shapes do not broadcast,
        both or neither of ``sigma0`` and ``lam`` are given, or ``control`` is neither name.

    Examples
    --------
    >>> import math
    >>> F = md_pull_off_force(R=1e-6, w=0.05, E_star=1e9, lam=1e8)
    >>> round(F / (1.5 * math.pi * 0.05 * 1e-6), 6)  # JKR: 3/2 pi w R
    1.0
    >>> F = md_pull_off_force(R=[1e-6, 2e-6], w=0.05, E_star=1e9, lam=[1e8, 1e-8])  # JKR, DMT
    >>> [round(float(f / (math.pi * 0.05 * 1e-6)), 6) for f in F]
    [1.5, 4.0]

    References
    ----------
    Maugis (1992); Johnson & Greenwood (1997).
    """
    R, w, E, lam = _scales(R, w, E_star, sigma0, lam)
    shape = check_broadcast(R=R, w=w, E_star=E, lam=lam)
    P_po = np.broadcast_to(md_pull_off(lam, control).P, shape)
    with np.errstate(all="ignore"):
        F = -(P_po * np.pi) * w * R
    F = check_finite_result(F, "the pull-off force", w=w, R=R)
    return float(F) if F.ndim == 0 else F
