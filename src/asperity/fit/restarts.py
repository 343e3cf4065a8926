"""Restarts of a fit that looks stuck in a local minimum: when (:func:`suspicious`) and from
where (:func:`restart_points`).

The minimiser (SciPy's trust-region reflective method) is local.  :func:`asperity.fit.runner.run`
repeats a fit that did not converge, left data points out of the model's reach or, with
stated uncertainties, has an improbable chi-square, from starts with each free parameter
moved both ways in turn, and keeps the lowest chi-square.  A heuristic, not a global
optimiser (docs/fitting.md, "Starts matter").
"""

from __future__ import annotations

import math

from scipy import stats

__all__ = ["RESTARTS", "RESTART_DECADES", "suspicious", "restart_points"]

#: Restart choices of :func:`run`.
RESTARTS = ("auto", "always", "never")
#: A restart moves one log-scaled parameter by this many decades (both ways).
RESTART_DECADES = 1.0


def suspicious(problem, result, absolute) -> bool:
    """True if a finished local fit looks like a local minimum worth restarting from elsewhere.

    A fit is suspicious if it did not converge, if a term has data points the model cannot
    reach at the fitted parameters (clamped: loads below its pull-off, separations past its
    branch), or, with stated uncertainties (``absolute``), if the chi-square is improbable
    (p < 1e-3).  Without uncertainties the quality cannot be judged and only the first two
    apply.
    """
    if result.aborted or not result.success or not math.isfinite(result.chisqr):
        return True
    values = problem.values(result.params)
    for term in problem.terms:
        try:
            if term.predict(term.local(values))[1]:
                return True
        except ValueError:
            return True
    return bool(absolute and result.nfree > 0 and stats.chi2.sf(result.chisqr, result.nfree) < 1e-3)


def restart_points(params):
    """The starts of a restart: each free parameter moved away from its start in turn, both ways.

    A log-scaled parameter moves by +-:data:`RESTART_DECADES`; a linear one between two finite
    bounds to a tenth of the way in from each bound (an exponent in [0, 1]: 0.1 and 0.9); a
    linear one with an open side by half its value either way (1.5 and 0.5 times it; one at
    0 is left).  A review found a COS fit stopped in a local minimum (alpha_t 0.3 for data
    of 0) that moving only the log-scaled parameters could not leave.

    Parameters
    ----------
    params : lmfit.Parameters
        The original start (log-scaled parameters fitted as ``log10_<name>``).

    Returns
    -------
    list of lmfit.Parameters
        Up to ``2 n`` copies for ``n`` free parameters (moves outside a bound, or to the
        start itself, are left out).
    """
    out = []
    for name, p in params.items():
        if not (p.vary and p.expr is None):
            continue
        if name.startswith("log10_"):
            moves = (p.value + RESTART_DECADES, p.value - RESTART_DECADES)
        elif math.isfinite(p.min) and math.isfinite(p.max):
            moves = (p.min + 0.1 * (p.max - p.min), p.max - 0.1 * (p.max - p.min))
        else:
            moves = (1.5 * p.value, 0.5 * p.value) if p.value != 0 else ()
        for value in moves:
            if p.min <= value <= p.max and value != p.value:
                trial = params.copy()
                trial[name].value = value
                out.append(trial)
    return out
