r"""The fitting itself: parameters, weighted residuals, lmfit's minimizer, the uncertainty analysis.

One fit is a list of *terms*, a data set and its model each, and a set of *global*
parameters: a parameter shared by several terms is one global parameter; a joint fit gives
the others one copy per term (``alpha_1``, ``alpha_2``).

**Parameters** become :class:`lmfit.Parameters`: a log-scaled quantity
(:mod:`asperity.quantities`) that varies is fitted as ``log10_<name>`` with ``<name> =
10**log10_<name>`` an expression, so bounds, starts and results stay in linear units while
the optimiser works in decades.  User expressions (``expr``) are in linear names.

**Residuals** of a point: :math:`r_i = (f(x_i) - y_i)/s_i` with

* ``weights='column'``: :math:`s_i = \sqrt{\sigma_{y,i}^2 + (f'(x_i)\sigma_{x,i})^2}`, the
  stated uncertainties (the x part, effective variance, Orear 1982, when an x uncertainty
  column is given; :math:`f'\sigma_x` as the secant :math:`[f(x+\sigma_x) - f(x-\sigma_x)]/2`
  at the current parameters, which stays finite next to a pull-off where the tangent does not);
* ``'relative'``: :math:`s_i = |f(x_i)|`, relative residuals (friction spans decades),
  iteratively reweighted: a first fit with :math:`s_i = |y_i|`, then re-fits with the
  model's values at the previous fit until they change by less than 1e-6
  (:meth:`Problem.reweight`);
* ``'none'``: uniform, :math:`s_i = \mathrm{rms}(y)` of the data set, so that data sets in
  different units (normal force in newtons, relative friction) weigh alike in a joint fit;
* ``'auto'`` (default): ``column`` when the data carry uncertainties, else ``relative``
  for friction and pull-off data and ``none`` for force-separation data (which cross zero).

**Minimiser**: :meth:`lmfit.Minimizer.least_squares` (SciPy's trust-region reflective
method with bounds, ``x_scale='jac'``), loss ``linear``, ``soft_l1`` or ``huber``.  A robust
loss first fits with the linear loss, then refits with ``f_scale`` = 1.4826 x the median
absolute residual of that fit, so "outlier" means a few times the typical scatter.

References
----------
.. [1] J. Orear, "Least squares when both variables have uncertainties", Am. J. Phys. 50
   (1982) 912.
.. [2] M. Newville et al., LMFIT: Non-Linear Least-Squares Minimization and Curve-Fitting
   for Python, https://lmfit.github.io/lmfit-py/.
"""

from __future__ import annotations

import math
from collections import OrderedDict
from dataclasses import dataclass, field, replace

import numpy as np

from .._optional import require
from .data import Dataset
from .models import FitModel, ParameterSpec

__all__ = ["WEIGHTS", "LOSSES", "PENALTY", "SCALED_UNITS", "DATA_STARTS", "Term", "GlobalParameter", "Problem",
           "resolve_weights"]

#: Weighting choices.
WEIGHTS = ("auto", "column", "relative", "none")
#: Loss functions (scipy.optimize.least_squares).
LOSSES = ("linear", "soft_l1", "huber")
#: Residual of a point whose model cannot be evaluated at the parameters tried.
PENALTY = 1e100
#: A log-scaled parameter is fitted within 10**-LOG_LIMIT .. 10**LOG_LIMIT.
LOG_LIMIT = 300.0
_LOG_PREFIX = "log10_"
_SCALED_PREFIX = "scaled_"
#: A linear parameter in these SI units is fitted in nanometres or nanonewtons: SciPy's finite
#: differences step by at least 1.5e-8 of the fitted value's unit, which for an offset of a
#: few nanometres in metres was 15 nm (found by a review: d0_m could not be fitted).
SCALED_UNITS = {"m": 1e-9, "N": 1e-9}
#: Parameters whose default is a held value (0) but which, varied without a start, start where
#: the data say (the single-asperity laws' force-curve offset: from 0 it may be undetermined).
DATA_STARTS = frozenset({"d0_m"})
_CACHE = 64


@dataclass
class GlobalParameter:
    """A parameter of the fit as lmfit sees it (linear units), with its origin."""

    name: str
    spec: ParameterSpec
    value: float | None
    vary: bool
    lo: float
    hi: float
    expr: str | None = None
    members: list = field(default_factory=list)  # (term index, local name)

    @property
    def fitted_name(self) -> str:
        """The lmfit name the optimiser varies: ``log10_<name>`` for a log-scaled parameter,
        ``scaled_<name>`` for one in units of :attr:`scale`."""
        if self.log:
            return f"{_LOG_PREFIX}{self.name}"
        return f"{_SCALED_PREFIX}{self.name}" if self.scale != 1.0 else self.name

    @property
    def log(self) -> bool:
        return self.spec.log and (self.vary or self.expr is not None)

    @property
    def scale(self) -> float:
        """The unit the optimiser sees a linear parameter in (:data:`SCALED_UNITS`; 1 otherwise)."""
        if self.spec.log or not (self.vary or self.expr is not None):
            return 1.0
        return SCALED_UNITS.get(self.spec.unit, 1.0)

    @property
    def per_unit(self) -> float:
        """How many of :attr:`scale` make one SI unit (1e9 for nanometres), an exact integer: a
        value is scaled by multiplying by it and brought back by dividing by it, so that a
        decimal value such as a bound of 3 nm comes back as 3e-09 m exactly (dividing by the
        inexact 1e-9 and multiplying back gave 2.9999999999999997e-09)."""
        return float(round(1.0 / self.scale))

    def linear(self, z: float) -> float:
        """A value in the fitted coordinate (log10, scaled or plain) in linear units."""
        return 10.0**z if self.log else z / self.per_unit


class Term:
    """One data set, its model and the map from the model's parameter names to global ones."""

    def __init__(self, data: Dataset, model: FitModel, names: dict[str, str]):
        self.data, self.model, self.names = data, model, names
        self._cache: OrderedDict = OrderedDict()
        self._shifts: dict = {}
        self.evaluations = 0
        self.relative_scale = None  # |model| at the last fit for weights='relative' (Problem.reweight)

    def local(self, values: dict) -> dict:
        return {loc: values[glob] for loc, glob in self.names.items()}

    def clamped_note(self, clamped: int, params: dict) -> str:
        """The fit's warning for ``clamped`` points of this data set that the model could not
        reach (loads below its pull-off, separations past its branch).  When that is at least
        half of them it says how little the fit describes, and for a force curve names this
        set's own offset if it is held (a user trial: a force curve fitted with its offset held
        at 0 had every point past the branch and a confident w whose interval missed the truth)."""
        what = {"friction": "load(s) lie below the model's pull-off load (no contact there); they were compared "
                            "with its friction at pull-off",
                "force": "separation(s) lie beyond the model's range (past its stable branch); they were compared "
                         "with its force at the end of the branch"}.get(self.data.kind, "point(s) clamped")
        note = f"{self.data.name}: at the best fit {clamped} {what}"
        n = len(self.data)
        if 2 * clamped <= n:
            return note
        note += (": every point, so the fit describes none of the data and its values and intervals mean nothing"
                 if clamped == n else ": most of the points, so its values and intervals describe little of the data")
        if self.data.kind != "force":
            return note
        # this data set's own offset (in a joint fit its copy, d0_m_2, or the shared d0_m)
        offset = next((self.names[local] for local in ("d0_m", "d0") if local in self.names), None)
        if offset is not None and not params[offset].vary and params[offset].expr is None:
            return note + (f"; the offset {offset} is held (at {params[offset].value:.4g}): vary it (vary=[..., "
                           f"'{offset}'], command line --vary ...,{offset}) or check the separations' zero")
        return note + "; check the separations' zero and sign"

    def predict(self, local: dict, data: Dataset | None = None):
        """(model values at the data points, number clamped), cached by the parameter values."""
        data = self.data if data is None else data
        key = (id(data), tuple(sorted((k, float(v)) for k, v in local.items())))
        hit = self._cache.get(key)
        if hit is None:
            self.evaluations += 1
            hit = self.model.predict(data, local)
            self._cache[key] = hit
            if len(self._cache) > _CACHE:
                self._cache.popitem(last=False)
        return hit

    def sigma(self, local: dict, weights: str) -> np.ndarray:
        """The residual scale s_i of each point under ``weights``."""
        d = self.data
        if weights == "none":
            rms = float(np.sqrt(np.mean(d.y**2)))
            return np.full(len(d), rms if rms > 0 else 1.0)
        if weights == "relative":
            return np.abs(d.y) if self.relative_scale is None else self.relative_scale
        var = np.zeros(len(d)) if d.y_err is None else d.y_err**2
        if d.x_err is not None:
            var = var + self.x_spread(local) ** 2
        return np.sqrt(var)

    def x_spread(self, local: dict) -> np.ndarray:
        """The model's change over each point's x uncertainty, :math:`|f(x+\\sigma_x) - f(x-\\sigma_x)|/2`.

        The secant over :math:`\\pm\\sigma_x`, not the tangent times :math:`\\sigma_x`: both
        agree where the model is linear on the scale of :math:`\\sigma_x`, but next to a
        pull-off the tangent is infinite, which removed that point's residual (a review found
        the work of adhesion fitted to put the pull-off exactly at the lowest load, with a
        standard error 50 times too small).  Loads below a model's pull-off are clamped to
        it, so the secant stays finite.  For friction coefficients (x a positive load) the
        step down is at most half the load.
        """
        d = self.data
        up = d.x_err
        down = np.minimum(d.x_err, 0.5 * d.x) if d.quantity == "mu" else d.x_err
        hi = self.predict(local, self._shifted(up))[0]
        lo = self.predict(local, self._shifted(-down))[0]
        with np.errstate(divide="ignore", invalid="ignore"):
            slope = np.where(up + down > 0, (hi - lo) / (up + down), 0.0)
        return np.abs(slope) * d.x_err

    def _shifted(self, h):
        """The data set with x shifted by ``h`` (kept for the fit: the cache of :meth:`predict`
        names data sets by their id)."""
        key = h.tobytes()
        if key not in self._shifts:
            self._shifts[key] = replace(self.data, x=self.data.x + h, y_err=None, x_err=None)
        return self._shifts[key]


def resolve_weights(data: Dataset, weights: str) -> str:
    """The weighting actually used for ``data`` (``'auto'`` resolved; ``'column'`` checked)."""
    if weights not in WEIGHTS:
        raise ValueError(f"weights must be one of {', '.join(WEIGHTS)}, got {weights!r}")
    if np.all(data.y == 0):
        raise ValueError(f"{data.name}: every {data.y_name} is 0: there is nothing to fit")
    has = data.y_err is not None or data.x_err is not None
    asked = weights
    if weights == "auto":
        weights = "column" if has else ("none" if data.kind == "force" else "relative")
    if weights == "column" and not has:
        raise ValueError(f"weights='column' needs an uncertainty column ({data.name}: e.g. F_err, mu_err, P_err, "
                         "friction_err [nN]); use 'relative' or 'none'")
    if weights == "relative" and np.any(data.y == 0):
        i = int(np.flatnonzero(data.y == 0)[0])
        how = ("weights='auto' weighs by 1/|value| without an uncertainty column, and "
               if asked == "auto" else "weights='relative' needs nonzero data, ")
        raise ValueError(f"{how}{data.name} has {data.y_name} = 0 at row {i + 1}; give an uncertainty column or "
                         "use weights='none' (command line: --weights none)")
    return weights


@dataclass
class Problem:
    """The terms, the global parameters and the options of one fit."""

    terms: list
    params: dict  # name -> GlobalParameter, in order
    weights: list  # resolved, per term
    loss: str
    failures: int = 0
    last_failure: str = ""

    @property
    def n_points(self) -> int:
        return sum(len(t.data) for t in self.terms)

    @property
    def free(self) -> list:
        return [p for p in self.params.values() if p.vary and p.expr is None]

    def values(self, lmfit_params) -> dict:
        """Global linear values from lmfit's parameters."""
        v = lmfit_params.valuesdict()
        return {name: float(v[name]) for name in self.params}

    def residual(self, lmfit_params) -> np.ndarray:
        """Weighted residuals of every term, concatenated.

        Where a model cannot be evaluated (parameters outside its domain, tried by the
        optimiser or a profile), the term's residuals are :data:`PENALTY`, so the step is
        rejected; :attr:`failures` counts such evaluations.
        """
        try:
            values = self.values(lmfit_params)
        except (RuntimeError, OverflowError, ValueError) as err:  # an expression lmfit cannot evaluate
            self.failures += 1
            self.last_failure = str(err)
            return np.full(self.n_points, PENALTY)
        out = []
        for term, weights in zip(self.terms, self.weights, strict=True):
            local = term.local(values)
            try:
                r = (term.predict(local)[0] - term.data.y) / term.sigma(local, weights)
            except (ValueError, ZeroDivisionError, OverflowError, FloatingPointError) as err:
                self.failures += 1
                self.last_failure = str(err)
                r = np.full(len(term.data), PENALTY)
            out.append(r)
        r = np.concatenate(out)
        return np.where(np.isfinite(r), r, PENALTY)

    def reweight(self, lmfit_params) -> float:
        """Relative weights from the model at ``lmfit_params``: :math:`s_i = |f(x_i)|` (where it is
        0, :math:`|y_i|`) for every term weighted ``'relative'``; the largest relative change of a
        weight.  Iterated with a re-fit (iteratively reweighted least squares), this removes the
        bias of weighting by the data themselves, which gives the points whose noise is negative
        more weight (a review measured -2.5 % on tau and 58 % coverage of the 68 % intervals at
        10 % noise)."""
        values = self.values(lmfit_params)
        change = 0.0
        for term, weights in zip(self.terms, self.weights, strict=True):
            if weights != "relative":
                continue
            try:
                f = np.abs(term.predict(term.local(values))[0])
            except (ValueError, ZeroDivisionError, OverflowError, FloatingPointError):
                continue  # the model cannot be evaluated there: the fit's own checks say so
            new = np.where((f > 0) & np.isfinite(f), f, np.abs(term.data.y))
            old = term.sigma(term.local(values), "relative")
            change = max(change, float(np.max(np.abs(new - old) / old)))
            term.relative_scale = new
        return change

    def lmfit_parameters(self):
        """The :class:`lmfit.Parameters` of the problem (see the module docstring)."""
        lmfit = require("lmfit", purpose="fitting", extra="fit")
        params = lmfit.Parameters()
        # the linear names of log and scaled parameters first, then the user's expressions (which
        # may name any of them, in any order: found by a review, 'mu0 = P0_N * k' failed)
        defined, expressions = [], []
        for p in self.params.values():
            later = defined if p.expr is None else expressions
            if p.log:  # within +-LOG_LIMIT decades, so that 10**x stays finite
                lo = max(math.log10(p.lo), -LOG_LIMIT) if p.lo > 0 else -LOG_LIMIT
                hi = min(math.log10(p.hi), LOG_LIMIT) if math.isfinite(p.hi) else LOG_LIMIT
                if p.expr is None:
                    params.add(p.fitted_name, value=math.log10(p.value), min=lo, max=hi, vary=p.vary)
                else:
                    later.append((p.fitted_name, f"log10({p.expr})"))
                later.append((p.name, f"10**{p.fitted_name}"))
            elif p.scale != 1.0:
                k = p.per_unit
                if p.expr is None:
                    params.add(p.fitted_name, value=p.value * k, min=p.lo * k, max=p.hi * k, vary=p.vary)
                else:
                    later.append((p.fitted_name, f"({p.expr}) * {k!r}"))
                later.append((p.name, f"{p.fitted_name} / {k!r}"))
            elif p.expr is None:
                params.add(p.name, value=p.value, min=p.lo, max=p.hi, vary=p.vary)
            else:
                later.append((p.name, p.expr))
        for name, expr in defined + expressions:
            params.add(name, expr=expr)
        return params
