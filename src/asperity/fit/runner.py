r"""Running a fit: the minimiser, the uncertainty analysis, the warnings, the :class:`FitResult`.

:func:`run` minimises the weighted residuals of a :class:`~asperity.fit.engine.Problem`
with :meth:`lmfit.Minimizer.least_squares`, then analyses the Jacobian at the best fit
(:mod:`asperity.fit.uncertainty`): standard errors, correlations, what cannot be
determined and why, Wald or profile-likelihood 95 % intervals (``ci``: ``'auto'``,
``'wald'``, ``'profile'``), and builds the result with the fitted curves.
"""

from __future__ import annotations

import math
import warnings as pywarnings

import numpy as np
from scipy import stats

from .._optional import require
from .._validation import check_integer, check_scalar_positive
from .._warnings import AsperityWarning
from .build import build_problem
from .engine import LOSSES, WEIGHTS, Problem
from .profile import PROFILE_BUDGET, profile_intervals
from .restarts import RESTARTS, restart_points, suspicious
from .result import FitResult, ParameterEstimate
from .uncertainty import (
    central_jacobian,
    correlated_pairs,
    null_directions,
    pseudo_covariance,
    wald_interval,
    wald_reliable,
)

__all__ = ["CI_METHODS", "RESTARTS", "run", "fit_problem", "grid_for", "suspicious", "restart_points"]  # (re-exported)

#: Interval methods.
CI_METHODS = ("auto", "wald", "profile")
#: Most points of the fitted curve's grid (``grid=``).
MAX_GRID = 10**5
_LN10 = math.log(10.0)


def grid_for(data, n: int = 200) -> np.ndarray:
    """A fine grid over the data's x range: log-spaced if positive and spanning > 20x, else linear."""
    if data.kind == "pull_off":
        return data.x
    lo, hi = float(np.min(data.x)), float(np.max(data.x))
    if lo > 0 and hi / lo > 20:
        return np.geomspace(lo, hi, n)
    return np.linspace(lo, hi, n) if hi > lo else np.array([lo])


class _Counted:
    def __init__(self, fn):
        self.fn, self.calls = fn, 0

    def __call__(self, params, *args, **kws):
        self.calls += 1
        return self.fn(params)


def run(problem: Problem, *, ci: str = "auto", grid: int = 200, restarts: str = "auto",
        profile_budget: float = PROFILE_BUDGET) -> FitResult:
    """Fit ``problem`` and analyse the result (see the module docstring).

    ``restarts`` (``'auto'``, ``'always'``, ``'never'``): the local minimiser can stop in a
    local minimum of a nonlinear model (the rough-surface model's friction has plateaus
    where data points fall below the model's pull-off load).  With ``'auto'`` a fit that
    looks wrong (:func:`suspicious`) is repeated from the starts of
    :func:`restart_points` and the lowest chi-square kept; ``'always'`` does so for every
    fit.  A restart that wins is reported among the warnings.  ``profile_budget``: seconds the
    profile likelihoods may take (:func:`~asperity.fit.profile.profile_intervals`).
    """
    if ci not in CI_METHODS:
        raise ValueError(f"ci must be one of {', '.join(CI_METHODS)}, got {ci!r}")
    if restarts not in RESTARTS:
        raise ValueError(f"restarts must be one of {', '.join(RESTARTS)}, got {restarts!r}")
    lmfit = require("lmfit", purpose="fitting", extra="fit")
    absolute = all(w == "column" for w in problem.weights)
    objective = _Counted(problem.residual)
    minimizer = lmfit.Minimizer(objective, problem.lmfit_parameters(), scale_covar=not absolute)
    n_free = len(problem.free)
    kws = {"x_scale": "jac", "ftol": 1e-12, "xtol": 1e-12, "gtol": 1e-12, "max_nfev": 200 * (n_free + 1)}
    restart_note = None
    # lmfit divides by zero standard errors of degenerate fits (handled in _analyse): no warnings.
    # The library's validity warnings at the trial points say nothing about the fit: the
    # ones that hold at the best fit are collected by _result.
    with np.errstate(all="ignore"), pywarnings.catch_warnings():
        pywarnings.simplefilter("ignore", AsperityWarning)
        start = minimizer.params.copy()
        result = minimizer.least_squares(params=start.copy(), **kws)
        if restarts == "always" or (restarts == "auto" and suspicious(problem, result, absolute)):
            first = result
            for alternative in restart_points(start):
                trial = minimizer.least_squares(params=alternative, **kws)
                if not trial.aborted and math.isfinite(trial.chisqr) and (
                        result.aborted or trial.chisqr < result.chisqr * (1.0 - 1e-9)):
                    result = trial
            if result is not first:
                restart_note = (f"the fit from the given start stopped at chi-square {first.chisqr:.6g}; a restart "
                                f"from another start reached {result.chisqr:.6g} (kept): the start matters "
                                "for these data, give one near the answer if you know it")
        unsettled = None
        for _ in range(REWEIGHT_ROUNDS if "relative" in problem.weights and not result.aborted else 0):
            unsettled = problem.reweight(result.params)
            if unsettled < 1e-6:
                unsettled = None
                break
            result = minimizer.least_squares(params=result.params, **kws)
        if problem.loss != "linear" and not result.aborted:
            mad = float(np.median(np.abs(result.residual)))
            result = minimizer.least_squares(params=result.params, loss=problem.loss,
                                             f_scale=1.4826 * mad or 1.0, **kws)
        nfev = objective.calls
        analysis = _analyse(problem, minimizer, result, absolute, ci, profile_budget)
    if restart_note:
        analysis["warnings"].insert(0, restart_note + (" (chi-squares with the first weights, before the relative "
                                                       "weights were re-weighted)" if "relative" in problem.weights
                                                       else ""))
    if unsettled is not None:  # (silent before: the second review)
        analysis["warnings"].append(f"the relative weights did not settle in {REWEIGHT_ROUNDS} re-fits (the last "
                                    f"changed them by up to {unsettled:.2g}; the model is near 0 at some points): "
                                    "the values and errors are those of the last re-fit; give an uncertainty column "
                                    "or use weights='none'")
    objective_profile = objective.calls - nfev
    return _result(problem, result, analysis, nfev, objective_profile, lmfit, grid, problem.values(start))


def _unevaluable(problem, term, err, start) -> str:
    """The message for a fit that ended where ``term``'s model cannot be evaluated.

    If the model cannot be evaluated at the start either, the held values or the start put
    it outside its domain (say a hardness held too low): the message says so rather than
    asking for better starts only.
    """
    try:
        with pywarnings.catch_warnings():
            pywarnings.simplefilter("ignore", AsperityWarning)
            term.predict(term.local(start))
    except ValueError as at_start:
        held = sorted(n for n, p in problem.params.items() if not p.vary and p.expr is None)
        return (f"model {term.model.name!r} cannot be evaluated at the start values ({at_start}); change the held "
                f"values ({', '.join(held) or 'none'}) or the start values")
    return (f"the fit ended where model {term.model.name!r} cannot be evaluated ({err}); give start values "
            "closer to the data or narrower bounds")


#: Re-fits with relative weights from the model (:meth:`~asperity.fit.engine.Problem.reweight`).
REWEIGHT_ROUNDS = 10

def fit_problem(datasets, models, *, shared=None, vary=None, fix=None, start=None, bounds=None, expr=None,
                weights="auto", loss="linear", ci="auto", grid=200, restarts="auto",
                profile_budget=PROFILE_BUDGET) -> FitResult:
    """Build the problem of ``datasets`` and ``models`` (:func:`~asperity.fit.build.build_problem`); fit it.

    The options are checked here, before any work: a ValueError or TypeError names the option.
    """
    for option, value, choices in (("weights", weights, WEIGHTS), ("loss", loss, LOSSES), ("ci", ci, CI_METHODS),
                                   ("restarts", restarts, RESTARTS)):
        if not isinstance(value, str) or value not in choices:
            raise ValueError(f"{option} must be one of {', '.join(choices)}, got {value!r:.60}")
    grid = check_integer(grid, "grid", 2, MAX_GRID)
    profile_budget = check_budget(profile_budget)
    problem = build_problem(datasets, models, shared=shared, vary=vary, fix=fix, start=start, bounds=bounds,
                            expr=expr, weights=weights, loss=loss)
    return run(problem, ci=ci, grid=grid, restarts=restarts, profile_budget=profile_budget)


def check_budget(profile_budget) -> float:
    """``profile_budget`` as a float of seconds > 0 (``math.inf``: no limit), or a named error."""
    if isinstance(profile_budget, float | np.floating) and profile_budget == math.inf:
        return math.inf
    try:
        return check_scalar_positive(profile_budget, "profile_budget")
    except (ValueError, OverflowError):
        raise ValueError(f"profile_budget must be a number of seconds > 0, or math.inf for no limit (valid range "
                         f"0 < profile_budget <= inf), got {profile_budget!r:.60}") from None


def _analyse(problem, minimizer, result, absolute, ci, budget=PROFILE_BUDGET):
    """Standard errors, intervals, correlations and warnings of the free parameters."""
    var_names = list(result.var_names)
    by_fitted = {p.fitted_name: p for p in problem.params.values()}
    names = [by_fitted[v].name for v in var_names]
    x = np.array([result.params[v].value for v in var_names])
    warnings, notes = [], {}
    log_names = {v for v in var_names if by_fitted[v].log}
    jac = central_jacobian(problem.residual, result.params, var_names, log_names) if not result.aborted else None
    scale = result.redchi if not absolute else 1.0
    nulls = null_directions(jac, names) if jac is not None else [(list(names), np.ones(len(names)))]
    undetermined = {n for group, _ in nulls for n in group}
    for group, weights in nulls:
        combo = " ".join(f"{'-' if w < 0 else '+'} {abs(w):.2g} {'log10 ' if by_fitted[v].log else ''}{n}"
                         for n, v, w in zip(names, var_names, weights, strict=True) if abs(w) > 0.1).lstrip("+ ")
        warnings.append(f"the data cannot fix {', '.join(group)} separately: the fit does not change along "
                        f"{combo} (a singular Jacobian); no standard error or interval for "
                        + ("it: fix it, or give data that depend on it" if len(group) == 1
                           else "them: fix one of them"))
        for n in group:
            notes[n] = "undetermined: only a combination with " + ", ".join(g for g in group if g != n) \
                if len(group) > 1 else "undetermined: the data do not depend on it"
    if nulls or result.covar is None:
        cov = pseudo_covariance(jac, scale) if jac is not None else np.full((len(names),) * 2, np.nan)
    else:
        cov = np.array(result.covar, dtype=float)
    se = np.sqrt(np.clip(np.diag(cov), 0.0, None))
    no_scatter = not absolute and result.nfree <= 0  # the scatter that would scale them is not measured
    if no_scatter:  # (a review found standard errors of 0 and zero-width intervals reported)
        se[:] = np.nan
        warnings.append("no degrees of freedom and no stated uncertainties: the scatter of the data is unknown, "
                        "so no standard error or interval (add points, fix a parameter, or give an uncertainty "
                        "column)")
    with np.errstate(divide="ignore", invalid="ignore"):
        corr = cov / np.outer(se, se)
    for i, n in enumerate(names):
        if n in undetermined:
            corr[i, :] = corr[:, i] = np.nan
    np.fill_diagonal(corr, 1.0)
    bounds = {v: (result.params[v].min, result.params[v].max) for v in var_names}
    at_bound = {}
    for v, n, xi in zip(var_names, names, x, strict=True):
        lo, hi = bounds[v]
        start = by_fitted[v]
        scale_x = max(abs(xi), abs(math.log10(start.value) if start.log else start.value * start.per_unit), 1e-300)
        for edge, side in ((lo, "lower"), (hi, "upper")):
            if math.isfinite(edge) and abs(xi - edge) <= 1e-6 * max(scale_x, abs(edge)) and n not in undetermined:
                p = by_fitted[v]  # the user's bound itself (10**log10(0.2) is 0.20000000000000004)
                target = p.lo if side == "lower" else p.hi
                at_bound[n] = (side, target if math.isfinite(target) and (not p.log or target > 0) else p.linear(edge))
    for n, (side, edge) in at_bound.items():
        warnings.append(f"{n} ended at its {side} bound {edge:g}: the data push it beyond the allowed range; "
                        "no standard error or interval (widen the bound, fix it, or question the model)")
        notes[n] = f"at its {side} bound"
    pairs = [p for p in correlated_pairs(corr, names) if not {p[0], p[1]} & (undetermined | set(at_bound))]
    for a, b, r in pairs:
        warnings.append(f"{a} and {b} are strongly correlated (r = {r:+.3f}): the data determine mainly a "
                        "combination of them; their intervals account for the correlation")
    quantile = stats.norm.ppf(0.975) if absolute else stats.t.ppf(0.975, max(result.nfree, 1))
    intervals, methods, want_profile = {}, {}, []
    for i, (v, n) in enumerate(zip(var_names, names, strict=True)):
        if n in undetermined or n in at_bound or no_scatter:
            continue
        p = by_fitted[v]
        lo, hi = wald_interval(x[i], se[i], quantile, p.log)
        lo, hi = (p.linear(lo), p.linear(hi)) if not p.log else (lo, hi)
        intervals[n] = (max(lo, p.lo), min(hi, p.hi))
        if intervals[n] != (lo, hi):
            notes[n] = "Wald interval cut at a bound"
        methods[n] = "wald"
        if ci == "profile" or (ci == "auto" and problem.loss == "linear" and not wald_reliable(
                problem.residual, result, cov, i, quantile, absolute)):
            want_profile.append(v)
    if want_profile and not absolute and _exact(problem, result):
        want_profile = []  # the data are fitted to rounding: every interval has zero width
    if problem.loss != "linear":
        warnings.append(f"with loss={problem.loss!r} the standard errors and intervals are those of the linearised "
                        "problem (Wald): approximate; the profile likelihood needs the linear loss")
        want_profile = []
    if want_profile:
        for i, v in enumerate(var_names):
            result.params[v].stderr = float(se[i]) if np.isfinite(se[i]) and se[i] > 0 else None
        held = [v for v, n in zip(var_names, names, strict=True) if n in undetermined]  # conditional on them
        profiles = profile_intervals(minimizer, result, want_profile, absolute=absolute, bounds=bounds, budget=budget,
                                     hold=held)
        for v, (lo, hi, why_lo, why_hi) in profiles.items():
            p = by_fitted[v]
            n = p.name
            if why_lo == "budget":
                why = "asked for with ci='profile'" if ci == "profile" else "the quadratic check of it failed"
                warnings.append(f"{n}: the profile likelihood did not finish within profile_budget = {budget:g} s; "
                                f"its Wald interval is shown, approximate ({why}): raise the budget, or fix a "
                                "correlated parameter")
                notes[n] = (notes.get(n, "") + "; profile over budget, Wald interval approximate").lstrip("; ")
                continue
            if why_lo == "failed":
                warnings.append(f"{n}: the profile likelihood could not be computed ({why_hi[:160]}); its Wald "
                                "interval is shown, approximate")
                notes[n] = (notes.get(n, "") + "; profile failed, Wald interval approximate").lstrip("; ")
                continue
            intervals[n] = tuple(None if z is None else p.linear(z) for z in (lo, hi))
            methods[n] = "profile"
            for end, why, side in ((lo, why_lo, "lower"), (hi, why_hi, "upper")):
                if end is None:
                    edge = p.lo if side == "lower" else p.hi  # a bound of the user's or the quantity's, not
                    real = math.isfinite(edge) and not (p.log and edge <= 0)  # log10's internal +-300 decades
                    reason = ("the profile stays below the 95 % level up to the bound" if why == "bound" and real
                              else "the profile is flat")
                    warnings.append(f"{n}: no {side} 95 % limit ({reason}): the data do not bound it on that side")
                    notes[n] = (notes.get(n, "") + f"; no {side} limit").lstrip("; ")
    return {"names": names, "var_names": var_names, "x": x, "se": se, "corr": corr, "intervals": intervals,
            "methods": methods, "undetermined": undetermined, "at_bound": at_bound, "notes": notes,
            "warnings": warnings}


def _exact(problem, result) -> bool:
    """True if the fit reproduces the data to rounding (noiseless data)."""
    scale = sum(float(np.sum((t.data.y / t.sigma(t.local(problem.values(result.params)), w)) ** 2))
                for t, w in zip(problem.terms, problem.weights, strict=True))
    return result.chisqr <= 1e-18 * scale


def _result(problem, result, a, nfev, profile_nfev, lmfit, grid, start) -> FitResult:
    values = problem.values(result.params)
    for name, (_, edge) in a["at_bound"].items():
        # lmfit maps a bounded parameter through sin(): the bound itself comes back a few ulps
        # inside (2.9999999999999996e-09 for 3e-09); a value that close is the bound
        if abs(values[name] - edge) <= 1e-12 * abs(edge):
            values[name] = edge
    with pywarnings.catch_warnings(record=True) as caught:
        pywarnings.simplefilter("always", AsperityWarning)
        for term in problem.terms:
            try:
                term.predict(term.local(values))
            except ValueError as err:
                raise ValueError(_unevaluable(problem, term, err, start)) from None
    for w in caught:  # warnings of other libraries go on as they came
        if not issubclass(w.category, AsperityWarning):
            pywarnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
    validity = [f"at the best fit: {w.message}" for w in caught if issubclass(w.category, AsperityWarning)]
    estimates = {}
    free = dict(zip(a["names"], range(len(a["names"])), strict=True))
    for name, p in problem.params.items():
        unit, log = p.spec.unit, p.spec.log
        if name in free:
            i = free[name]
            bad = name in a["undetermined"] or name in a["at_bound"]
            stderr = None if bad or not np.isfinite(a["se"][i]) else float(
                _LN10 * values[name] * a["se"][i] if p.log else a["se"][i] / p.per_unit)
            estimates[name] = ParameterEstimate(name, values[name], stderr, a["intervals"].get(name, (None, None)),
                                                True, unit, log, a["methods"].get(name, "undetermined"),
                                                a["notes"].get(name, ""))
        elif p.expr is not None:  # lmfit propagates the covariance to an expression
            stderr = result.params[name].stderr
            stderr = float(stderr) if stderr is not None and np.isfinite(stderr) and not a["undetermined"] else None
            estimates[name] = ParameterEstimate(name, values[name], stderr, (None, None), False, unit, log, "expr",
                                                f"= {p.expr}")
        else:
            estimates[name] = ParameterEstimate(name, values[name], None, (None, None), False, unit, log, "fixed")
    warnings = [note for t in problem.terms for note in t.data.notes] + validity
    if not result.success or result.aborted:
        warnings.append(f"the fit did not converge ({result.message}); the values are the last ones tried")
    fitted, curves, derived = [], [], {}
    with pywarnings.catch_warnings():  # the validity notes at the best fit are recorded above
        pywarnings.simplefilter("ignore", AsperityWarning)
        evaluated = [(term.predict(term.local(values)), term.model.curve(term.data, term.local(values),
                                                                          grid_for(term.data, grid)))
                     for term in problem.terms]
    for i, (term, ((y_model, clamped), curve)) in enumerate(zip(problem.terms, evaluated, strict=True)):
        local = term.local(values)
        fitted.append(np.asarray(y_model, dtype=float))
        if clamped:
            warnings.append(term.clamped_note(clamped, problem.params))
        curves.append(curve)
        for k, v in term.model.derived(local).items():
            derived[k if len(problem.terms) == 1 else f"{k}_{i + 1}"] = v
    warnings += a["warnings"] + _implausible(problem, values)
    n_free = len(a["names"])
    if result.nfree <= 0:
        warnings.append("as many free parameters as data points: no degrees of freedom, the fit passes through "
                        "every point and says nothing about its quality")
    elif all(w == "column" for w in problem.weights):
        p_value = float(stats.chi2.sf(result.chisqr, result.nfree))
        if p_value < 1e-3:
            warnings.append(f"the model does not describe the data within their stated uncertainties (reduced "
                            f"chi-square {result.redchi:.3g}, p = {p_value:.2g}): the intervals assume it does")
    names = tuple(dict.fromkeys(t.model.name for t in problem.terms))
    kinds = tuple(dict.fromkeys(t.data.kind for t in problem.terms))
    return FitResult(model="+".join(names), kind="+".join(kinds), parameters=estimates, correlation=a["corr"],
                     correlation_names=tuple(a["names"]), residuals=np.asarray(result.residual, dtype=float),
                     chisqr=float(result.chisqr), redchi=float(result.redchi), aic=float(result.aic),
                     bic=float(result.bic), n_points=problem.n_points, n_free=n_free,
                     weights=tuple(problem.weights), loss=problem.loss, warnings=tuple(dict.fromkeys(warnings)),
                     datasets=tuple(t.data for t in problem.terms), fitted=tuple(fitted), curves=tuple(curves),
                     derived=derived, nfev=nfev, model_evaluations=sum(t.evaluations for t in problem.terms),
                     success=bool(result.success and not result.aborted), message=str(result.message),
                     report=lmfit.fit_report(result), profile_nfev=profile_nfev)


#: How far outside the registry's typical range (a factor) a fitted value gets a note.
IMPLAUSIBLE_FACTOR = 5.0


def _implausible(problem, values) -> list[str]:
    """Notes for fitted values far outside their typical range (a user trial: nN data labelled
    uN gave w = 100.8 J/m^2, 30 times the largest of the material table, with no note)."""
    notes = []
    for name, p in problem.params.items():
        typical = p.spec.typical
        if typical is None or not typical[0] > 0 or p.spec.unit == "1":
            continue  # (a quantity with a unit: a unit mistake in the data or a value given shows there)
        lo, hi = typical
        value = values[name]
        if not lo / IMPLAUSIBLE_FACTOR <= abs(value) <= hi * IMPLAUSIBLE_FACTOR and value != 0:
            unit = "" if p.spec.unit == "1" else f" {p.spec.unit}"
            held = "" if p.vary else " (tied)" if p.expr is not None else " (held)"
            notes.append(f"{name} = {value:.4g}{unit}{held} lies far outside its typical range ({lo:g} to "
                         f"{hi:g}{unit}): check the units of the data (their column headers) and of the values given")
    return notes
