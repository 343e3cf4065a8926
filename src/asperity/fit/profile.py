r"""Profile-likelihood intervals of a fit's parameters.

Where the covariance of :mod:`asperity.fit.uncertainty` is not reliable (its Wald interval
fails :func:`~asperity.fit.uncertainty.wald_reliable`), a parameter's 95 % interval is its
profile likelihood: the parameter held at values stepping outward from the best fit, first
by its standard error and then by steps growing 1.6 times, the others re-fitted with
lmfit's minimiser at each, and the crossing of the level found by Brent's method.  The level
is :math:`\Delta\chi^2 = \chi^2_{1,0.95} = 3.84` with stated uncertainties, and lmfit's
F-test otherwise.

The profiles of nearly degenerate parameters (a pair correlated at :math:`|r| \approx 0.999`)
can wander decades away, where one model evaluation costs far more than at the best fit:
they run under a budget of seconds (``profile_budget``, default :data:`PROFILE_BUDGET`),
checked before each evaluation.  A parameter whose profile did not finish keeps its Wald
interval, with a warning that it is approximate.

References
----------
.. [1] W. H. Press, S. A. Teukolsky, W. T. Vetterling, B. P. Flannery, *Numerical Recipes*,
   3rd ed., Cambridge University Press (2007), §15.6 (confidence limits, profile chi-square).
.. [2] M. Newville et al., LMFIT: Non-linear least-squares minimization and curve-fitting for
   Python, Zenodo (2014), doi:10.5281/zenodo.11813.
"""

from __future__ import annotations

import math
import time

import numpy as np
from scipy import stats

__all__ = ["PROFILE_STEPS", "PROFILE_BUDGET", "profile_intervals", "chi2_probability"]

#: Steps the profile takes outward before it calls a side flat: the first of one standard error
#: (fitted coordinates), each next 1.6 times longer (20 steps reach about 2e4 standard errors).
PROFILE_STEPS = 20
#: Seconds all the profile likelihoods of one fit may take (checked before each evaluation, so
#: the overrun is at most one evaluation); ``math.inf`` for no limit.
PROFILE_BUDGET = 60.0


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
