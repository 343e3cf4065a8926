r"""Uncertainties of a fit and what the data cannot determine.

The standard errors come from lmfit's covariance :math:`(J^TJ)^{-1}` of the weighted
residuals at the best fit, in the *fitted* coordinates (log10 of a log-scaled parameter),
scaled by the reduced chi-square unless the weights are stated uncertainties
(``weights='column'``, absolute :math:`\sigma`).  Three things make them meaningless, and
each is reported instead of a number:

* **A singular Jacobian**: a direction in parameter space along which the residuals do not
  change (to :data:`RANK_TOL` relative to the largest singular value of the column-scaled
  Jacobian).  The parameters with a weight above 0.1 in that direction cannot be fixed
  separately: only a combination of them is determined.  They get no standard error and no
  interval; the others get theirs from the pseudo-inverse (conditional on the undetermined
  combination).
* **A bound that is active**: the best value sits on a bound (within 1e-6 of the bound's
  distance scale), so the data push the parameter outside its allowed range.
* **A flat profile**: the profile likelihood does not rise enough (to the 95 % level)
  before a bound or in many steps, so the data give no limit on that side.

Strong correlation (:math:`|r| >` :data:`CORRELATION_LIMIT`) between two identifiable
parameters is a warning naming the pair; their intervals stay, computed with the
correlation.

95 % intervals: Wald (:math:`\hat p \pm q\,s`, in the fitted coordinates, so a log-scaled
parameter gets an asymmetric interval; :math:`q` = 1.96 with stated uncertainties, else
Student's t) where the covariance is reliable, and the profile likelihood (the parameter
held at values stepping outward by its standard error, then by growing steps, the others
re-fitted with lmfit's minimiser at each, the level's crossing root-found) where it is
not.  *Reliable* is tested, not assumed (:func:`wald_reliable`): at the two points where
the Wald ellipse reaches the ends of the parameter's interval, the chi-square must rise by
the amount the quadratic approximation predicts (:math:`q^2 s^2`) to within
:data:`WALD_TOLERANCE` (a factor 1.5 either way), and both points must lie within the
bounds.  The profile's level is :math:`\Delta\chi^2 = \chi^2_{1,0.95} = 3.84` with stated
uncertainties, and lmfit's F-test otherwise.

The profile likelihoods themselves are in :mod:`asperity.fit.profile`.
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["RANK_TOL", "JACOBIAN_STEP", "CORRELATION_LIMIT", "WALD_TOLERANCE", "central_jacobian",
           "null_directions", "pseudo_covariance", "correlated_pairs", "wald_interval", "wald_reliable"]

#: Relative singular value below which the Jacobian counts as singular (of the central-difference
#: Jacobian of :func:`central_jacobian`, accurate to about 1e-8).
RANK_TOL = 1e-6
#: Step of :func:`central_jacobian` in the fitted coordinates (decades for log-scaled parameters;
#: relative to the value for the others).
JACOBIAN_STEP = 1e-4
#: |correlation| above which a pair of parameters is reported.
CORRELATION_LIMIT = 0.95
#: How far (as a factor) the chi-square rise at the ends of a Wald interval may differ from the
#: quadratic prediction before the profile likelihood replaces it.
WALD_TOLERANCE = 1.5


def central_jacobian(residual, params, var_names, log_names) -> np.ndarray:
    """Jacobian of ``residual`` at ``params`` by central differences in the fitted coordinates.

    Steps of :data:`JACOBIAN_STEP` (decades for the names in ``log_names``, else relative to
    the value, absolute 1e-4 at 0), one-sided at a bound.  More accurate than the optimiser's
    forward differences, so an exactly degenerate direction shows as a singular value near
    1e-8 of the largest, well below :data:`RANK_TOL`.

    Parameters
    ----------
    residual : callable
        ``residual(lmfit.Parameters) -> ndarray``.
    params : lmfit.Parameters
        The point (best fit).
    var_names : list of str
        The varied (fitted) parameter names.
    log_names : set of str
        Fitted names that are log10 coordinates.

    Returns
    -------
    ndarray
        (n residuals, p parameters).
    """
    work = params.copy()
    columns = []
    for name in var_names:
        par = work[name]
        x = par.value
        h = JACOBIAN_STEP if name in log_names else JACOBIAN_STEP * (abs(x) if x != 0 else 1.0)
        up, down = x + h, x - h
        if up > par.max:
            up = x
        if down < par.min:
            down = x
        par.value = up
        r_up = residual(work)
        par.value = down
        r_down = residual(work)
        par.value = x
        columns.append((r_up - r_down) / (up - down))
    return np.stack(columns, axis=1) if columns else np.zeros((0, 0))


def _scaled(jac):
    norms = np.linalg.norm(jac, axis=0)
    norms = np.where(norms > 0, norms, 1.0)
    return jac / norms, norms


def null_directions(jac, names) -> list[tuple[list[str], np.ndarray]]:
    """Directions the residuals do not depend on: (parameters involved, weights) per direction.

    Parameters
    ----------
    jac : ndarray
        Jacobian of the weighted residuals, (n points, p parameters), fitted coordinates.
    names : sequence of str
        The p parameter names.

    Returns
    -------
    list
        One ``(names, weights)`` per null direction: the parameters with a weight above 0.1
        in the unit right-singular vector, and those weights.  Empty if the Jacobian has full
        rank.
    """
    jac = np.asarray(jac, dtype=float)
    if jac.size == 0:
        return []
    scaled, _ = _scaled(jac)
    zero = np.linalg.norm(jac, axis=0) == 0
    # the right-singular vectors only: (parameters x parameters), never the (points x points) of
    # full_matrices=True (a review: 7 TiB for a million rows)
    _, s, vt = np.linalg.svd(scaled, full_matrices=jac.shape[0] < jac.shape[1])
    s = np.concatenate([s, np.zeros(max(0, jac.shape[1] - s.size))])
    out = []
    for i in np.flatnonzero(zero):  # a parameter the residuals do not depend on at all
        out.append(([names[i]], np.eye(jac.shape[1])[i]))
    top = s.max() if s.size else 0.0
    _, norms = _scaled(jac)
    for k in range(jac.shape[1]):
        if s[k] <= RANK_TOL * top:
            if np.any(zero & (np.abs(vt[k]) > 0.5)):
                continue
            v = vt[k] / norms  # back to the fitted coordinates
            v = v / np.linalg.norm(v)
            v = v if v[np.argmax(np.abs(v))] > 0 else -v
            involved = [names[i] for i in np.flatnonzero(np.abs(v) > 0.1)]
            out.append((involved, v))
    return out


def pseudo_covariance(jac, scale: float) -> np.ndarray:
    """Covariance from the pseudo-inverse of :math:`J^TJ` (directions below :data:`RANK_TOL` dropped).

    Parameters
    ----------
    jac : ndarray
        Jacobian (n, p) of the weighted residuals.
    scale : float
        Variance factor (the reduced chi-square, or 1 for stated uncertainties).

    Returns
    -------
    ndarray
        (p, p) covariance in the fitted coordinates.
    """
    scaled, norms = _scaled(np.asarray(jac, dtype=float))
    _, s, vt = np.linalg.svd(scaled, full_matrices=False)
    keep = s > RANK_TOL * (s.max() if s.size else 0.0)
    inv = (vt[keep].T / s[keep] ** 2) @ vt[keep]
    return scale * inv / np.outer(norms, norms)


def correlated_pairs(corr, names, limit: float = CORRELATION_LIMIT) -> list[tuple[str, str, float]]:
    """Pairs of parameters with :math:`|r| >` ``limit``, strongest first: ``(name, name, r)``."""
    corr = np.asarray(corr, dtype=float)
    pairs = [(names[i], names[j], float(corr[i, j])) for i in range(len(names)) for j in range(i + 1, len(names))
             if np.isfinite(corr[i, j]) and abs(corr[i, j]) > limit]
    return sorted(pairs, key=lambda p: -abs(p[2]))


def wald_interval(value: float, se: float, quantile: float, log: bool) -> tuple[float, float]:
    """Wald 95 % interval :math:`\\hat p \\pm q s` in the fitted coordinates, returned in linear units.

    ``value`` and ``se`` are in the fitted coordinates (log10 for ``log``).
    """
    lo, hi = value - quantile * se, value + quantile * se
    return (10.0**lo, 10.0**hi) if log else (lo, hi)


def wald_reliable(residual, result, cov, i, quantile, absolute) -> bool:
    r"""Whether the quadratic approximation holds over the Wald interval of free parameter ``i``.

    Moves to :math:`\hat\theta \pm q\,\Sigma e_i/\sqrt{\Sigma_{ii}}` (the points of the Wald
    ellipse at the ends of parameter ``i``'s interval, the others at their conditional best)
    and compares the rise of chi-square there with the prediction :math:`q^2 s^2`
    (:math:`s^2` = 1 with stated uncertainties, else the reduced chi-square).

    Parameters
    ----------
    residual : callable
        ``residual(lmfit.Parameters) -> ndarray`` (weighted residuals).
    result : lmfit.MinimizerResult
        The best fit.
    cov : ndarray
        Covariance of the free parameters (fitted coordinates), order of ``result.var_names``.
    i : int
        Index of the parameter.
    quantile : float
        :math:`q`.
    absolute : bool
        Stated uncertainties.

    Returns
    -------
    bool
        True if both rises are within a factor :data:`WALD_TOLERANCE` of the prediction and
        both points lie within the bounds.
    """
    if not (np.isfinite(cov[i, i]) and cov[i, i] > 0):
        return False
    step = quantile * cov[:, i] / math.sqrt(cov[i, i])
    expected = quantile**2 * (1.0 if absolute else result.chisqr / max(result.nfree, 1))
    if not expected > 0:
        return True  # an exact fit: every interval has zero width
    names = list(result.var_names)
    for sign in (-1.0, 1.0):
        params = result.params.copy()
        for j, name in enumerate(names):
            value = result.params[name].value + sign * step[j]
            if not params[name].min <= value <= params[name].max:
                return False
            params[name].value = value
        rise = float(np.sum(np.square(residual(params)))) - result.chisqr
        if not (1.0 / WALD_TOLERANCE <= rise / expected <= WALD_TOLERANCE):
            return False
    return True
