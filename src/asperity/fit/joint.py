r"""Joint fits: several data sets at once, sharing named parameters (same material, several roughnesses).

A parameter named in ``shared`` (default: every parameter) is one parameter for all data sets;
any other gets one copy per data set, named ``<name>_<i>`` (``alpha_1``, ``alpha_2``, ...).
The options are those of :mod:`asperity.fit.api`.
"""

from __future__ import annotations

from .models import get_model
from .profile import PROFILE_BUDGET
from .read import as_dataset
from .result import FitResult
from .runner import fit_problem

__all__ = ["fit_joint"]


def fit_joint(datasets, models="gw", *, shared=None, vary=None, fix=None, start=None, bounds=None, expr=None,
              contact=None, material=None, weights="auto", loss="linear", ci="auto", units=None, drop_nan=False,
              grid=200, restarts="auto", profile_budget=PROFILE_BUDGET) -> FitResult:
    r"""Fit several data sets at once, sharing named parameters.

    .. math::
        \min_\theta \sum_k \sum_i \rho\Big(\Big[\frac{f_k(x_{ki};\theta_k) - y_{ki}}{s_{ki}}\Big]^2\Big),
        \qquad \theta_k = (\theta_{shared}, \theta_{own,k})

    Parameters
    ----------
    datasets : sequence of Dataset or path
        The data sets (any kinds; a path's kind is found from its columns).
    models : str, FitModel or sequence
        One model for all, or one per data set.
    shared : sequence of str, optional
        Parameters common to all data sets (default: all); the others get one copy per data
        set, ``<name>_<i>`` with ``i`` from 1.
    vary : sequence of str, optional
        Parameters to fit (default: the models'); a base name means every copy.
    fix, start, bounds, expr : dict, optional
        Held values, start values, bounds, expressions.
    contact : PhysicalContact or sequence, optional
        For ``'gw'`` on physical data: one for all or one per data set.
    material : Material or str, optional
        For the single-asperity laws.
    weights : {'auto', 'column', 'relative', 'none'}
        Residual weighting (resolved per data set).
    loss : {'linear', 'soft_l1', 'huber'}
        Loss function.
    ci : {'auto', 'wald', 'profile'}
        How the 95 % intervals are found.
    units : dict, optional
        Units of columns without one, when reading files.
    drop_nan : bool
        Drop rows holding NaN when reading files.
    grid : int
        Points of each fitted curve.
    restarts : {'auto', 'always', 'never'}
        Repeat a fit that looks stuck in a local minimum from other starts (each free
        parameter moved both ways: a decade, or within its bounds)
        (:func:`asperity.fit.runner.run`).
    profile_budget : float
        Seconds the profile likelihoods may take in all (default 60; ``math.inf``: no
        limit); a profile not finished keeps its Wald interval, with a warning.

    Returns
    -------
    FitResult
        ``curves`` and ``fitted`` hold one entry per data set.

    Raises
    ------
    ValueError
        As :func:`fit_friction_load`, and for fewer than one data set or a models/contacts list
        of the wrong length.

    Examples
    --------
    >>> import numpy as np
    >>> from asperity.fit import friction_load_data
    >>> P = np.linspace(1.0, 5.0, 8)
    >>> a = friction_load_data(P, 0.3 * (P + 1.0))
    >>> b = friction_load_data(P, 0.3 * (P + 2.0))
    >>> res = fit_joint([a, b], "amontons", shared=["mu0"], weights="none")
    >>> [round(res.parameters[k].value, 6) for k in ("mu0", "P0_1", "P0_2")]
    [0.3, 1.0, 2.0]

    References
    ----------
    M. Newville et al., LMFIT (Parameters shared between data sets).
    """
    if not isinstance(datasets, list | tuple) or not datasets:
        raise ValueError(f"datasets must be a non-empty list of Datasets or paths, got {type(datasets).__name__}")
    try:
        datasets = [as_dataset(d, None, units, drop_nan) for d in datasets]
    except ValueError as err:
        raise ValueError(f"datasets: {err}") from None
    n = len(datasets)
    models = [models] * n if isinstance(models, str) or not hasattr(models, "__len__") else list(models)
    contacts = list(contact) if isinstance(contact, list | tuple) else [contact] * n
    if len(models) != n or len(contacts) != n:
        raise ValueError(f"models: give one model (and contact) for all {n} data sets or one per data set")
    built = [get_model(m, material=material, contact=c) for m, c in zip(models, contacts, strict=True)]
    return fit_problem(datasets, built, shared=shared, vary=vary, fix=fix, start=start, bounds=bounds, expr=expr,
                weights=weights, loss=loss, ci=ci, grid=grid, restarts=restarts,
                profile_budget=profile_budget)
