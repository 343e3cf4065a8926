r"""Model comparison: several models fitted to the same data, ranked by AIC.

The options are those of :mod:`asperity.fit.api`; each model takes the ones naming its
parameters.  Nested models deserve care: a model that contains the generating one (COS at
alpha_t = 1 is JKR exactly, Maugis-Dugdale contains JKR and DMT as limits) fits as well and
AIC only charges it 2 per extra parameter.
"""

from __future__ import annotations

from .base import FitModel
from .build import parameter_names
from .models import MODELS, contact_refusal, get_model, material_refusal, model_class
from .profile import PROFILE_BUDGET
from .read import as_dataset
from .result import Comparison
from .runner import fit_problem

__all__ = ["compare_models"]


def compare_models(data, models=("jkr", "dmt", "md", "cos", "amontons"), *, kind=None, vary=None, fix=None,
                   start=None, bounds=None, contact=None, material=None, weights="auto", loss="linear", ci="auto",
                   units=None, drop_nan=False, grid=200, restarts="auto", profile_budget=PROFILE_BUDGET) -> Comparison:
    r"""Fit several models to the same data and rank them by AIC.

    .. math::
        \mathrm{AIC} = n\ln(\chi^2/n) + 2k,\qquad w_m = \frac{e^{-\Delta_m/2}}{\sum e^{-\Delta/2}}

    (:math:`k` free parameters, :math:`\Delta_m` the AIC above the best, :math:`w_m` the
    Akaike weight).  Options name parameters of any of the models; each model takes those it
    has (an option naming a parameter of none of them is an error; a model left with no
    ``vary`` name varies its defaults).  Every model sees the same data and weighting.

    Parameters
    ----------
    data : Dataset or path
        The data (one data set).
    models : sequence of str or FitModel
        Model names or models, e.g. ``GWFit(heights=...)`` (default: the single-asperity
        friction laws and the empirical forms).
    kind : {'friction', 'force', 'pull_off'}, optional
        The data kind when reading a file (default: from its columns).
    vary : sequence of str, optional
        Parameters to fit.
    fix, start, bounds : dict, optional
        Held values, start values, bounds.
    contact : PhysicalContact, optional
        For ``'gw'`` on physical data.
    material : Material or str, optional
        For the single-asperity laws.
    weights : {'auto', 'column', 'relative', 'none'}
        Residual weighting.
    loss : {'linear', 'soft_l1', 'huber'}
        Loss function.
    ci : {'auto', 'wald', 'profile'}
        How the 95 % intervals are found.
    units : dict, optional
        Units of columns without one, when reading a file.
    drop_nan : bool
        Drop rows holding NaN when reading a file.
    grid : int
        Points of each fitted curve.
    restarts : {'auto', 'always', 'never'}
        Repeat a fit that looks stuck in a local minimum from other starts (each free
        parameter moved both ways: a decade, or within its bounds)
        (:func:`asperity.fit.runner.run`).
    profile_budget : float
        Seconds the profile likelihoods of each model's fit may take in all (default 60;
        ``math.inf``: no limit); a profile not finished keeps its Wald interval, with a warning.

    Returns
    -------
    Comparison
        The fits, ranked by AIC (best first).

    Raises
    ------
    ValueError
        As :func:`fit_friction_load`, for an empty or repeated model list, and for an option
        naming a parameter no model has.

    Examples
    --------
    >>> import numpy as np
    >>> from asperity.fit import friction_load_data
    >>> P = np.linspace(0.0, 5.0, 12)
    >>> table = compare_models(friction_load_data(P, 0.3 * (P + 1.0)), ["cos", "amontons"], weights="none")
    >>> table.best.model
    'amontons'

    References
    ----------
    H. Akaike, IEEE Trans. Autom. Control 19 (1974) 716; K. P. Burnham, D. R. Anderson, Model
    Selection and Multimodel Inference, Springer (2002).
    """
    names = [models] if isinstance(models, str | FitModel) else models
    if not isinstance(names, list | tuple) or not all(isinstance(n, str | FitModel) for n in names):
        raise TypeError(f"models must be a model name or a list of names (or FitModel objects), got "
                        f"{type(models).__name__}")
    labels = [m.name if isinstance(m, FitModel) else str(m).strip().lower() for m in names]
    if not names or len(set(labels)) != len(labels):
        twice = sorted({x for x in labels if labels.count(x) > 1})
        raise ValueError("models must be a non-empty list of distinct models, got " +
                         (f"{', '.join(map(repr, twice))} more than once" if twice else "none"))
    unknown = [m for m in names if not isinstance(m, FitModel) and m.strip().lower() not in MODELS]
    if unknown:
        raise ValueError(f"unknown model {unknown[0]!r}; valid: {', '.join(MODELS)}")
    classes = [m if isinstance(m, FitModel) else model_class(m.strip().lower()) for m in names]
    if material is not None and not any(c.uses_material for c in classes):
        raise ValueError(material_refusal(*labels))
    if contact is not None and not any(c.uses_contact for c in classes):
        raise ValueError(contact_refusal(*labels))
    data = as_dataset(data, kind, units, drop_nan)
    # the material goes to the models that take one (the laws), the contact to gw
    built = [get_model(m, material=material if c.uses_material else None,
                       contact=contact if c.uses_contact else None) for m, c in zip(names, classes, strict=True)]
    for m in built:
        m.check(data)
    vary = None if vary is None else parameter_names(vary, "vary")
    for opt, value in (("fix", fix), ("start", start), ("bounds", bounds)):
        if value is not None and not isinstance(value, dict):
            raise TypeError(f"{opt} must be a dict of parameter name -> value, got {type(value).__name__}")
    options = {"vary": vary, "fix": fix, "start": start, "bounds": bounds}
    known = set().union(*(m.specs(data) for m in built))
    for opt, value in options.items():
        unknown = sorted(set(value or ()) - known)
        if unknown:
            raise ValueError(f"{opt}: unknown parameter {unknown[0]!r}; the models' parameters are "
                             f"{', '.join(sorted(known))}")
    results = []
    for m in built:
        own = set(m.specs(data))
        mine = {k: _restrict(v, own) for k, v in options.items()}
        if not mine["vary"]:
            mine["vary"] = None
        results.append(fit_problem([data], [m], weights=weights, loss=loss, ci=ci, grid=grid, restarts=restarts,
                                   profile_budget=profile_budget, **mine))
    ranked = sorted(results, key=lambda r: (not r.success, r.aic if r.aic == r.aic else float("inf")))
    return Comparison(tuple(ranked))


def _restrict(option, names):
    """The part of a user option (dict or list of names) naming parameters in ``names``."""
    if option is None:
        return None
    if isinstance(option, dict):
        return {k: v for k, v in option.items() if k in names}
    return [k for k in option if k in names]
