"""Building a fit's problem from data sets, models and the user's options (vary, fix, start,
bounds, expr, shared): the global parameters of :mod:`asperity.fit.engine`, their starts
(given, held, or data-driven from the models) and the checks of every option.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from .engine import DATA_STARTS, LOSSES, GlobalParameter, Problem, Term, resolve_weights

__all__ = ["build_problem", "parameter_names"]


def parameter_names(option, name: str) -> list[str]:
    """``vary``/``shared`` (named ``name``): one parameter name or a list, tuple or set of names, as a list.

    Raises
    ------
    TypeError
        For anything else, naming ``name``.
    """
    names = [option] if isinstance(option, str) else option
    if not isinstance(names, list | tuple | set | frozenset) or not all(isinstance(k, str) for k in names):
        raise TypeError(f"{name} must be a parameter name or a list of names, got {type(option).__name__} "
                        f"{option!r:.60}")
    return list(names)


def _expand(option, name: str, params: dict, base_names: dict, per_row=()) -> dict:
    """User keys (global names, or a base name meaning every copy) -> global names;
    ``per_row``: names the data give row by row (pull-off conditions)."""
    if option is None:
        return {}
    if name == "vary":
        items = ((k, None) for k in parameter_names(option, name))
    elif isinstance(option, dict):
        items = option.items()
    else:
        raise TypeError(f"{name} must be a dict of parameter name -> value, got {type(option).__name__} "
                        f"{option!r:.60}")
    out = {}
    for key, value in items:
        key = str(key)
        targets = [key] if key in params else base_names.get(key, [])
        if not targets and key in per_row:  # a user trial: --R beside a file's R column
            raise ValueError(f"{name}: {key} is given row by row by the data (its conditions: a column of the "
                             "file), so it is neither fitted nor set here")
        if not targets:
            raise ValueError(f"{name}: unknown parameter {key!r}; the parameters are {', '.join(params)}")
        for t in targets:
            out[t] = value
    return out


def build_problem(datasets, models, *, shared=None, vary=None, fix=None, start=None, bounds=None, expr=None,
                  weights="auto", loss="linear") -> Problem:
    """Check the options and build the :class:`Problem` of a fit (see :mod:`asperity.fit` for the options).

    Raises
    ------
    ValueError
        For a model that cannot fit its data, an unknown parameter, a parameter both fixed and
        varied, a bound that excludes a start value given (a default start outside the bounds is
        moved inside), a log-scaled parameter at or below 0,
        a missing value, fewer points than free parameters, or an unknown weighting or loss.
    """
    if loss not in LOSSES:
        raise ValueError(f"loss must be one of {', '.join(LOSSES)}, got {loss!r}")
    terms, params, base_names = [], {}, {}
    joint = len(datasets) > 1
    share_all = shared is None
    shared = set() if shared is None else set(parameter_names(shared, "shared"))
    for i, (data, model) in enumerate(zip(datasets, models, strict=True)):
        model.check(data)
        if np.all(data.y == 0):  # before the starts, which divide by the data (found by a review)
            raise ValueError(f"{data.name}: every {data.y_name} is 0: there is nothing to fit")
        names, specs = {}, model.specs(data)
        unused = [k for k in data.conditions if k not in specs]
        if unused:  # a user trial: a file's per-row E was read and never used, without a word
            data = replace(data, notes=(*data.notes, f"{data.name}: ignored condition(s) {', '.join(unused)}: the "
                                        f"{model.name} model has no such parameter"))
        for local, spec in specs.items():
            if local in data.conditions:  # given per row by the data
                continue
            glob = local if (not joint or share_all or local in shared) else f"{local}_{i + 1}"
            names[local] = glob
            base_names.setdefault(local, [])
            if glob not in base_names[local]:
                base_names[local].append(glob)
            if glob not in params:
                params[glob] = GlobalParameter(glob, spec, spec.value, spec.vary, spec.lo, spec.hi)
            params[glob].members.append((i, local))
        terms.append(Term(data, model, names))
    unknown = shared - set(base_names)
    if unknown:
        raise ValueError(f"shared: unknown parameter(s) {', '.join(sorted(unknown))}; the parameters are "
                         f"{', '.join(base_names)}")
    rows = {k for t in terms for k in t.data.conditions}
    vary_set = None if vary is None else _expand(vary, "vary", params, base_names, rows)
    fix = _expand(fix, "fix", params, base_names, rows)
    start = _expand(start, "start", params, base_names, rows)
    bounds = _expand(bounds, "bounds", params, base_names, rows)
    expr = _expand(expr, "expr", params, base_names, rows)
    both = sorted(set(fix) & set(vary_set or ()))
    if both:
        raise ValueError(f"parameter {both[0]!r} is both fixed and varied; give it in one of fix and vary")
    for name, p in params.items():
        if vary_set is not None:
            p.vary = name in vary_set
        if name in fix:
            p.vary, p.value = False, _number(fix[name], f"fix {name}")
        if name in start:
            p.value = _number(start[name], f"start {name}")
        elif p.vary and name not in fix and p.spec.name in DATA_STARTS:
            p.value = None  # varied without a start: the model's data-driven one (_fill_starts)
        if name in expr:
            p.expr = str(expr[name])
        if name in bounds:
            p.lo, p.hi = _bounds(bounds[name], name)
            if not p.spec.log and any(math.isfinite(b) and abs(b) > MAX_MAGNITUDE for b in (p.lo, p.hi)):
                raise ValueError(f"bounds {name}: a finite bound must lie within +-{MAX_MAGNITUDE:g} (None or inf: "
                                 f"open), got ({p.lo!r}, {p.hi!r})")  # (a log-scaled one is fitted in log10)
        if p.value is not None and not p.spec.valid(p.value):  # before the models' starts use it
            how = "fix" if name in fix else "start" if name in start else "default"
            raise ValueError(f"{how} {name} = {p.value:g} is outside its valid range ({p.spec.meaning}; "
                             f"{p.spec.range_text()})")
    _fill_starts(terms, params)
    for name, p in params.items():  # a start of ours outside the user's bounds is moved inside
        if p.vary and p.expr is None and name not in start and p.value is not None and not p.lo <= p.value <= p.hi \
                and name in bounds:
            p.value = _inside(p.value, p.lo, p.hi, p.log)
    if not any(p.vary and p.expr is None for p in params.values()):
        raise ValueError("no parameter varies: give at least one in vary (--vary)")
    _check_values(params)
    problem = Problem(terms, params, [resolve_weights(t.data, weights) for t in terms], loss)
    n_free = len(problem.free)
    if n_free == 0:
        raise ValueError("no parameter varies: give at least one in vary (--vary)")
    if problem.n_points < n_free:
        raise ValueError(f"{problem.n_points} data point{'s' if problem.n_points != 1 else ''} cannot fix {n_free} "
                         f"free parameter{'s' if n_free != 1 else ''} "
                         f"({', '.join(p.name for p in problem.free)}): fix some or add data")
    return problem


#: Largest magnitude of a held or start value: lmfit's bounded parameters overflow near 1.3e154
#: (a review found fix beta=1e200 ending in a traceback).
MAX_MAGNITUDE = 1e150


def _number(value, what) -> float:
    try:
        x = float(value)
    except (TypeError, ValueError, OverflowError):
        raise ValueError(f"{what}: expected a number, got {value!r}") from None
    if isinstance(value, bool) or not math.isfinite(x):
        raise ValueError(f"{what}: expected a finite number, got {value!r}")
    if abs(x) > MAX_MAGNITUDE:
        raise ValueError(f"{what}: {x:g} is beyond +-{MAX_MAGNITUDE:g}, which the fit cannot handle (give a value "
                         "of physical size)")
    return x


def _bounds(value, name):
    try:
        lo, hi = value
    except (TypeError, ValueError):
        raise ValueError(f"bounds {name}: expected (lo, hi), got {value!r}") from None
    lo = -math.inf if lo is None else float(lo)
    hi = math.inf if hi is None else float(hi)
    if not lo < hi or math.isnan(lo) or math.isnan(hi):
        raise ValueError(f"bounds {name}: need lo < hi, got ({lo!r}, {hi!r})")
    return lo, hi


def _inside(value, lo, hi, log):
    """A start inside (lo, hi) for a default start ``value`` outside: the middle of finite
    bounds, else the reflection of ``value`` in the bound it passed (as far inside as it was
    outside); for a parameter fitted in log10, the same in log10 (a lower bound 0 is -inf)."""
    if log:
        if value <= 0:  # refused by _check_values with its own message
            return value
        z = _inside(math.log10(value), math.log10(lo) if lo > 0 else -math.inf,
                    math.log10(hi) if math.isfinite(hi) else math.inf, False)
        return 10.0**z
    if math.isfinite(lo) and math.isfinite(hi):
        return 0.5 * (lo + hi)
    edge = lo if value < lo else hi
    return 2.0 * edge - value


def _fill_starts(terms, params):
    """Ask each model for data-driven starts of the parameters still without a value."""
    for term in terms:
        local = {loc: params[glob].value for loc, glob in term.names.items()}
        if all(v is not None for v in local.values()) or not hasattr(term.model, "start"):
            continue
        rows = {k: float(np.median(v)) for k, v in term.data.conditions.items()}
        filled = term.model.start(term.data, {**local, **rows})
        for loc, glob in term.names.items():  # a held parameter is the user's to give (a user trial:
            # vary=['w_J_m2'] held tau at a start made from the data, unnoted)
            if params[glob].value is None and params[glob].vary and filled.get(loc) is not None:
                params[glob].value = float(filled[loc])


def _check_values(params):
    for name, p in params.items():
        if p.value is None and p.expr is None and not p.vary:
            raise ValueError(f"parameter {name!r} ({p.spec.meaning}, {p.spec.unit}) is held (not in vary) and has "
                             f"no value: give it (fix {name}=...) or vary it too")
        if p.value is None and p.expr is None:
            raise ValueError(f"parameter {name!r} ({p.spec.meaning}, {p.spec.unit}) has no value: give it "
                             f"(fix {name}=... to hold it, or start {name}=... to vary it from there)")
        if p.expr is not None:
            continue
        if not math.isfinite(p.value):
            raise ValueError(f"parameter {name!r} must be finite, got {p.value!r}")
        q_lo, q_hi = p.spec.lo, p.spec.hi
        if p.vary and p.spec.log and q_lo <= p.value <= 0:
            raise ValueError(f"parameter {name!r} = {p.value:g} cannot be varied from there: it is fitted in log10, "
                             f"so its start must be > 0 (give start {name}=...)")
        if p.value < q_lo or p.value > q_hi or (p.vary and p.spec.log and p.value <= 0):
            raise ValueError(f"parameter {name!r} = {p.value:g} is outside its valid range ({p.spec.meaning}; "
                             f"{q_lo:g} .. {q_hi:g}{', > 0: fitted in log10' if p.spec.log else ''})")
        if not (p.lo <= p.value <= p.hi):
            raise ValueError(f"the bounds of {name} [{p.lo:g}, {p.hi:g}] exclude its start value {p.value:g}")
        if p.log and p.lo == -math.inf:  # an open lower bound ('gamma=:0.1'): the quantity's own, 0
            p.lo = max(p.spec.lo, 0.0)
        if p.log and p.lo < 0:
            raise ValueError(f"bounds of {name}: the lower bound must be >= 0 ({name} is fitted in log10), "
                             f"got {p.lo:g}")
