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

The profiles of nearly degenerate parameters (a pair correlated at :math:`|r| \approx 0.999`)
can wander decades away, where one model evaluation costs far more than at the best fit:
they run under a budget of seconds (``profile_budget``, default :data:`PROFILE_BUDGET`),
checked before each evaluation.  A parameter whose profile did not finish keeps its Wald
interval, with a warning that it is approximate.
"""

from __future__ import annotations

import math
import time

import numpy as np
from scipy import stats

__all__ = ["RANK_TOL", "JACOBIAN_STEP", "CORRELATION_LIMIT", "WALD_TOLERANCE", "PROFILE_STEPS", "central_jacobian",
           "null_directions", "pseudo_covariance", "correlated_pairs", "wald_interval", "wald_reliable",
           "PROFILE_BUDGET", "profile_intervals", "chi2_probability"]

#: Relative singular value below which the Jacobian counts as singular (of the central-difference
#: Jacobian of :func:`central_jacobian`, accurate to about 1e-8).
RANK_TOL = 1e-6
#: Step of :func:`central_jacobian` in the fitted coordinates (decades for log-scaled parameters;
#: relative to the value for the others).
JACOBIAN_STEP = 1e-4
#: |correlation| above which a pair of parameters is reported.
CORRELATION_LIMIT = 0.95
#: Steps the profile takes outward before it calls a side flat: the first of one standard error
#: (fitted coordinates), each next 1.6 times longer (20 steps reach about 2e4 standard errors).
PROFILE_STEPS = 20
#: Seconds all the profile likelihoods of one fit may take (checked before each evaluation, so
#: the overrun is at most one evaluation); ``math.inf`` for no limit.
PROFILE_BUDGET = 60.0
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


def chi2_probability(best, new) -> float:
    """Profile level with stated uncertainties: :math:`P(\\chi^2_1 \\le \\chi^2_{new} - \\chi^2_{best})`."""
    return float(stats.chi2.cdf(max(new.chisqr - best.chisqr, 0.0), df=1))


class _OverBudget(Exception):
    """Raised inside a profile's objective when the profile budget is spent."""


def profile_intervals(minimizer, result, names, *, absolute: bool, bounds: dict, budget: float = PROFILE_BUDGET,
                      hold=()):
    """95 % profile-likelihood intervals of ``names`` (fitted coordinates), the others re-fitted.

    Parameters
    ----------
    minimizer : lmfit.Minimizer
        The minimizer of the fit (its objective is re-used with one parameter fixed).
    result : lmfit.MinimizerResult
        The best fit.
    names : list of str
        Fitted (lmfit) names of the parameters to profile.
    absolute : bool
        Stated uncertainties (:math:`\\Delta\\chi^2` level) rather than the F-test.
    bounds : dict
        Fitted name -> (lo, hi) bounds, to tell a flat profile at a bound.
    budget : float
        Seconds the profiles may take in all (``math.inf``: no limit).
    hold : sequence of str
        Fitted names held at their best values in every re-fit (the parameters the data do
        not determine: the profiles are conditional on them, as the pseudo-inverse standard
        errors are; re-fitting them walked along the flat direction at three to four times
        the cost, found by a review).

    Returns
    -------
    dict
        name -> ``(lo, hi, why_lo, why_hi)`` in fitted coordinates; a side the profile could
        not close is ``None`` with the reason (``'bound'``, ``'flat'``, or ``'budget'`` for
        a profile stopped when the budget was spent: both sides of that parameter; or
        ``'failed'`` and the root search's message when the profile could not be computed).
    """
    deadline = time.monotonic() + budget
    objective = minimizer.userfcn

    def guarded(params, *args, **kws):
        if time.monotonic() > deadline:
            raise _OverBudget
        return objective(params, *args, **kws)

    minimizer.userfcn = guarded
    try:
        return _profiles(minimizer, result, names, absolute, bounds, tuple(hold))
    finally:
        minimizer.userfcn = objective


def _profiles(minimizer, result, names, absolute, bounds, hold=()):
    """The profiles of :func:`profile_intervals` (the objective raises _OverBudget when the time is up)."""
    out = {}
    for name in names:
        try:
            out[name] = _profile(minimizer, result, name, absolute, bounds, hold)
        except _OverBudget:
            out[name] = (None, None, "budget", "budget")
        except ValueError as err:  # a root search that could not bracket (a noisy or stepped chi-square)
            out[name] = (None, None, "failed", " ".join(str(err).split()))
    return out


def _profile(minimizer, result, name, absolute, bounds, hold=()):
    """The profile of one parameter, root-found on each side of the best fit.

    The parameter is held at trial values stepping outward from the best fit, first by its
    standard error and then by steps growing 1.6 times (so :data:`PROFILE_STEPS` steps reach
    about 2e4 standard errors), the other free parameters re-fitted at each (warm-started
    from the previous trial on the same side); the first trial past the 95 % level brackets
    the end, which Brent's method finds.  (lmfit's ``conf_interval`` steps by a fifth of the
    value where the standard error exceeds it: a parameter near 0, such as the offset load
    of a contact without adhesion, took 0.07 standard errors per step and was called
    unbounded after 20 steps, found by a review.)
    """
    from scipy import optimize

    par = result.params[name]
    best, se = par.value, par.stderr if par.stderr and np.isfinite(par.stderr) else max(abs(par.value) * 0.2, 0.1)
    nfree = max(result.nfree, 1)
    others = [n for n, p in result.params.items() if p.vary and n != name and n not in hold]
    state = {}

    def refit(start, x):
        params = start.copy()
        params[name].set(value=x, vary=False)
        for held in hold:
            params[held].set(vary=False)
        if not others:
            r = minimizer.userfcn(params, *minimizer.userargs, **minimizer.userkws)
            return float(np.sum(np.square(r))), None
        fit = minimizer.least_squares(params=params, x_scale="jac", ftol=1e-10, xtol=1e-10, gtol=1e-10,
                                      max_nfev=100 * (len(others) + 1))
        ok = not fit.aborted and math.isfinite(fit.chisqr)
        return (float(fit.chisqr) if ok else math.inf), (fit.params if ok else None)

    def chisqr(x):
        # from the previous trial on this side and from the best fit, the lower kept: a warm
        # start alone can slide into another valley (Maugis-Dugdale's JKR limit), which made a
        # profile end too close (the worked example's w)
        trials = [refit(result.params, x)]
        if others and "params" in state:
            trials.append(refit(state["params"], x))
        value, params = min(trials, key=lambda t: t[0])
        if params is not None:
            state["params"] = params
        return value

    seen = {}

    def level(x):
        # Remembered: a re-fit warm-started from another trial can land elsewhere, and Brent's
        # method re-evaluates the ends of the bracket the outward search found (a sign it then
        # did not see again failed the profile of the worked example's w)
        if x not in seen:
            new = chisqr(x)
            seen[x] = (stats.chi2.cdf(max(new - result.chisqr, 0.0), df=1) - 0.95 if absolute else
                       stats.f.cdf(max(new / result.chisqr - 1.0, 0.0) * nfree, 1, nfree) - 0.95)
        return seen[x]

    lo_b, hi_b = bounds.get(name, (-math.inf, math.inf))
    ends = []
    for direction, edge in ((-1, lo_b), (1, hi_b)):
        state.clear()
        x, step = best, se
        found = None
        for _ in range(PROFILE_STEPS):
            x_new = x + direction * step
            if (direction < 0 and x_new <= edge) or (direction > 0 and x_new >= edge):
                x_new = edge
            if not np.isfinite(x_new):
                break
            if level(x_new) >= 0:
                found = optimize.brentq(level, min(x, x_new), max(x, x_new), xtol=1e-10 * max(1.0, abs(best)))
                break
            if x_new == edge:
                break
            x, step = x_new, step * 1.6
        reason = None if found is not None else ("bound" if np.isfinite(edge) and x == edge or x_new == edge
                                                 else "flat")
        ends.append((found, reason))
    return ends[0][0], ends[1][0], ends[0][1], ends[1][1]
