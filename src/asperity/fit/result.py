r"""The result of a fit (:class:`FitResult`) and of a model comparison (:class:`Comparison`).

A :class:`FitResult` holds, for each parameter, a :class:`ParameterEstimate` (best value,
standard error, 95 % interval, whether it varied, and why an error or interval is missing),
the correlation matrix of the free parameters, the weighted residuals, chi-square, reduced
chi-square, AIC and BIC, the number of points, the warnings (identifiability, clamped
loads, convergence, the data reader's notes), and the fitted curve of each data set on a
fine grid.  :meth:`FitResult.to_dict` gives strict JSON (NaN and infinity become null):

.. code-block:: text

    {"model": ..., "parameters": {name: {"value", "stderr", "ci95": [lo, hi], "vary"}},
     "chisqr", "aic", "bic", "n_points", "warnings": [...]}

:meth:`FitResult.plot` draws data, fit and residuals.  A :class:`Comparison` ranks several
fits of the same data by AIC (:math:`n\ln(\chi^2/n) + 2k`, lmfit's definition; BIC with
:math:`k\ln n`) and gives Akaike weights.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .._csv import columns_to_dataframe, rows_to_csv
from .._json import json_safe

__all__ = ["ParameterEstimate", "FitResult", "Comparison"]


@dataclass(frozen=True)
class ParameterEstimate:
    """One parameter of a fit.

    Attributes
    ----------
    name : str
        Fit name (``alpha``, ``w_J_m2``; ``alpha_2`` for a per-data-set copy in a joint fit).
    value : float
        Best value (linear units).
    stderr : float or None
        Standard error (linear units; for a log-scaled parameter
        :math:`\\ln 10 \\cdot p \\cdot s_{\\log_{10} p}`; for an expression lmfit's propagation),
        None when the data cannot determine it or the parameter is fixed.
    ci95 : tuple
        ``(lo, hi)`` 95 % interval; an end is None where the data give no limit; ``(None,
        None)`` for a fixed or undetermined parameter.
    vary : bool
        Whether it was fitted.
    unit : str
        Unit.
    log : bool
        Fitted in log10.
    method : str
        ``'wald'``, ``'profile'``, ``'fixed'``, ``'expr'`` or ``'undetermined'``.
    note : str
        Why a standard error or an end of the interval is missing (empty otherwise).
    """

    name: str
    value: float
    stderr: float | None
    ci95: tuple
    vary: bool
    unit: str = "1"
    log: bool = False
    method: str = "fixed"
    note: str = ""

    def to_dict(self) -> dict:
        """``{"value", "stderr", "ci95", "vary"}`` (strict JSON: non-finite -> None)."""
        return json_safe({"value": self.value, "stderr": self.stderr, "ci95": list(self.ci95), "vary": self.vary})


@dataclass(frozen=True)
class FitResult:
    """A fit of one or several data sets (see the module docstring).

    Attributes
    ----------
    model : str
        Model name (``'jkr'``; ``'jkr+md'`` for a joint fit of different models).
    kind : str
        Data kind (``'friction'``, ``'force'``, ``'pull_off'``; ``'+'``-joined if several).
    parameters : dict
        name -> :class:`ParameterEstimate`, every parameter (fixed ones too).
    correlation : ndarray
        Correlation matrix of the free parameters (fitted coordinates), order of
        ``correlation_names``; NaN where undetermined.
    correlation_names : tuple of str
        Names of the free parameters.
    residuals : ndarray
        Weighted residuals :math:`(f_i - y_i)/s_i` of all points.
    chisqr, redchi, aic, bic : float
        Sum of squared weighted residuals, its value per degree of freedom, and the
        information criteria.
    n_points, n_free : int
        Data points and free parameters.
    weights : tuple of str
        Weighting used per data set (``'column'``, ``'relative'``, ``'none'``).
    loss : str
        Loss function.
    warnings : tuple of str
        Everything the user should know about the fit.
    datasets : tuple of Dataset
        The data fitted.
    fitted : tuple of ndarray
        Model values at each data set's points.
    curves : tuple
        Fitted curve of each data set on a fine grid (:class:`~asperity.CurveResult` or
        :class:`~asperity.physical.PhysicalCurve` for ``gw``, else
        :class:`~asperity.fit.models.FitCurve`).
    derived : dict
        Quantities following from the fit (the Maugis parameter ``lam``, ...).
    nfev : int
        Residual evaluations of the fit (Jacobian columns included).
    model_evaluations : int
        Model evaluations actually computed (the rest were cached), profiles included.
    profile_nfev : int
        Residual evaluations spent on profile-likelihood intervals.
    success : bool
        Whether the minimiser converged.
    message : str
        The minimiser's message.
    report : str
        lmfit's fit report (in the fitted coordinates).
    """

    model: str
    kind: str
    parameters: dict
    correlation: np.ndarray
    correlation_names: tuple
    residuals: np.ndarray
    chisqr: float
    redchi: float
    aic: float
    bic: float
    n_points: int
    n_free: int
    weights: tuple
    loss: str
    warnings: tuple
    datasets: tuple = field(repr=False)
    fitted: tuple = field(repr=False)
    curves: tuple = field(repr=False)
    derived: dict = field(default_factory=dict)
    nfev: int = 0
    model_evaluations: int = 0
    profile_nfev: int = 0
    success: bool = True
    message: str = ""
    report: str = field(default="", repr=False)

    @property
    def curve(self):
        """The fitted curve of the first (or only) data set."""
        return self.curves[0]

    @property
    def values(self) -> dict:
        """name -> best value."""
        return {k: p.value for k, p in self.parameters.items()}

    def to_dict(self) -> dict:
        """The result as strict JSON (see the module docstring for the keys)."""
        return json_safe({"model": self.model,
                          "parameters": {k: p.to_dict() for k, p in self.parameters.items()},
                          "chisqr": self.chisqr, "aic": self.aic, "bic": self.bic, "n_points": self.n_points,
                          "warnings": list(self.warnings)})

    def columns(self) -> dict:
        """One row per parameter: name, value, stderr, ci95_lo, ci95_hi, vary, unit, method, note."""
        rows = self.rows()
        return {k: [r[k] for r in rows] for k in (rows[0] if rows else {})}

    def rows(self) -> list[dict]:
        """The parameter table as a list of dicts (see :meth:`columns`)."""
        return [{"name": p.name, "value": p.value, "stderr": p.stderr, "ci95_lo": p.ci95[0], "ci95_hi": p.ci95[1],
                 "vary": p.vary, "unit": p.unit, "method": p.method, "note": p.note} for p in self.parameters.values()]

    def to_csv(self, path_or_buffer=None):
        """The parameter table as CSV (written atomically to a path if given)."""
        return rows_to_csv(self.rows(), None, path_or_buffer)

    def to_dataframe(self):
        """The parameter table as a pandas DataFrame (needs ``asperity[frame]``)."""
        return columns_to_dataframe(self.columns(), {"model": self.model, "chisqr": self.chisqr, "aic": self.aic})

    def summary(self) -> str:
        """A readable table: parameters, goodness of fit, warnings."""
        lines = [f"model {self.model} ({self.kind} data, {self.n_points} points, {self.n_free} free, weights "
                 f"{'/'.join(dict.fromkeys(self.weights))}, loss {self.loss})"]
        width = max(len(k) for k in self.parameters) if self.parameters else 4
        for p in self.parameters.values():
            if not p.vary:
                err = "" if p.stderr is None else f"+- {p.stderr:.3g} "
                lines.append(f"  {p.name:<{width}}  {p.value:<12.6g} {err}({p.method}{' ' + p.note if p.note else ''}) "
                             f"{p.unit}")
                continue
            err = "undetermined" if p.stderr is None else f"+- {p.stderr:.3g}"
            lo, hi = ("-" if x is None else f"{x:.6g}" for x in p.ci95)
            lines.append(f"  {p.name:<{width}}  {p.value:<12.6g} {err:<14} 95% [{lo}, {hi}] ({p.method}) {p.unit}")
        lines.append(f"  chi-square {self.chisqr:.6g}, reduced {self.redchi:.6g}, AIC {self.aic:.6g}, "
                     f"BIC {self.bic:.6g}; {self.nfev} evaluations")
        for k, v in self.derived.items():
            lines.append(f"  derived {k} = {v:.6g}")
        lines += [f"  warning: {w}" for w in self.warnings]
        return "\n".join(lines) + "\n"

    def plot(self, path=None, *, fmt=None):
        """Data, fitted curve and weighted residuals of each data set (needs matplotlib).

        Parameters
        ----------
        path : str or os.PathLike, optional
            Save the figure there (atomically); the format from the suffix unless ``fmt``.
        fmt : str, optional
            Image format (``'png'``, ``'svg'``, ...).

        Returns
        -------
        matplotlib.figure.Figure
        """
        from .plot import plot_fit

        return plot_fit(self, path, fmt=fmt)


@dataclass(frozen=True)
class Comparison:
    """Several models fitted to the same data, ranked by AIC (best first).

    Attributes
    ----------
    results : tuple of FitResult
        The fits, best (lowest AIC) first; failed fits last.
    """

    results: tuple

    def __len__(self) -> int:
        return len(self.results)

    @property
    def best(self) -> FitResult:
        """The fit with the lowest AIC."""
        return self.results[0]

    def rows(self) -> list[dict]:
        """One row per model: model, n_free, chisqr, redchi, aic, bic, delta_aic, weight, warnings."""
        aics = np.array([r.aic for r in self.results], dtype=float)
        finite = np.isfinite(aics)
        best = aics[finite].min() if np.any(finite) else math.nan
        delta = aics - best
        w = np.where(finite, np.exp(-0.5 * np.where(finite, delta, 0.0)), 0.0)
        w = w / w.sum() if w.sum() > 0 else w
        return [{"model": r.model, "n_free": r.n_free, "chisqr": r.chisqr, "redchi": r.redchi, "aic": r.aic,
                 "bic": r.bic, "delta_aic": float(d), "akaike_weight": float(x), "warnings": len(r.warnings)}
                for r, d, x in zip(self.results, delta, w, strict=True)]

    def columns(self) -> dict:
        """The ranking as columns (see :meth:`rows`)."""
        rows = self.rows()
        return {k: [r[k] for r in rows] for k in rows[0]}

    def to_list(self) -> list:
        """The fits' :meth:`FitResult.to_dict`, ranked by AIC: the command line's JSON."""
        return [r.to_dict() for r in self.results]

    def to_csv(self, path_or_buffer=None):
        """The ranking as CSV."""
        return rows_to_csv(self.rows(), None, path_or_buffer)

    def to_dataframe(self):
        """The ranking as a pandas DataFrame (needs ``asperity[frame]``)."""
        return columns_to_dataframe(self.columns(), {})

    def summary(self) -> str:
        """A readable ranking."""
        width = max([10, *(len(str(r["model"])) for r in self.rows())])
        lines = [f"{'model':<{width}} {'k':>2} {'chi-square':>12} {'AIC':>12} {'dAIC':>9} {'weight':>7}"]
        for r in self.rows():
            lines.append(f"{r['model']:<{width}} {r['n_free']:>2} {r['chisqr']:>12.5g} {r['aic']:>12.5g} "
                         f"{r['delta_aic']:>9.3g} {r['akaike_weight']:>7.3f}")
        return "\n".join(lines) + "\n"
