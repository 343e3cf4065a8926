r"""The fitting functions, named after the data they fit.

:func:`fit_friction_load`, :func:`fit_force_separation` and :func:`fit_pull_off` fit one
data set; :func:`~asperity.fit.joint.fit_joint` fits several at once, sharing named
parameters; :func:`~asperity.fit.compare.compare_models` fits several models to the same data
and ranks them by AIC.  They take the same options:

``vary``
    Names of the parameters to fit (default: the model's, see :mod:`asperity.fit.models`);
    every other parameter is held at its value.
``fix``
    ``{name: value}``: hold these at the value.  A name both fixed and varied is an error.
``start``
    ``{name: value}``: start values (defaults: the model's, estimated from the data where
    possible).
``bounds``
    ``{name: (lo, hi)}`` in linear units (None for open); they must contain the start.
``expr``
    ``{name: "expression"}``: tie a parameter to others (lmfit syntax, linear names), e.g.
    ``{"tau2_Pa": "tau1_Pa / 30"}`` for the Hurtado-Kim strengths in a fixed ratio (a
    contact with a constant shear strength has the one ``tau_Pa``).
``weights``
    ``'auto'`` (default), ``'column'``, ``'relative'`` or ``'none'`` (see
    :mod:`asperity.fit.engine`).
``loss``
    ``'linear'`` (default), ``'soft_l1'`` or ``'huber'`` (robust, for outliers).
``ci``
    ``'auto'`` (default: Wald where the covariance is reliable, profile likelihood where it is
    not), ``'wald'`` or ``'profile'``.
``contact``, ``material``
    The :class:`~asperity.physical.PhysicalContact` of the physical ``gw`` model; the material
    (its :math:`E^*`, and starts for ``w_J_m2``, ``sigma0_Pa``) of the single-asperity laws.

In a joint fit a parameter named in ``shared`` (default: every parameter) is one parameter
for all data sets; any other gets one copy per data set, named ``<name>_<i>`` (``alpha_1``,
``alpha_2``, ...).  In ``vary``, ``fix``, ``start``, ``bounds`` a base name (``alpha``)
means every copy.

Data may be a :class:`~asperity.fit.data.Dataset` or the path of a CSV file (read with
:func:`~asperity.fit.read.read_data`, with ``units`` and ``drop_nan``).
"""

from __future__ import annotations

from .models import get_model
from .profile import PROFILE_BUDGET
from .read import as_dataset
from .result import FitResult
from .runner import fit_problem

__all__ = ["fit_friction_load", "fit_force_separation", "fit_pull_off"]


def fit_friction_load(data, model="gw", *, vary=None, fix=None, start=None, bounds=None, expr=None, contact=None,
                      material=None, weights="auto", loss="linear", ci="auto", units=None, drop_nan=False,
                      grid=200, restarts="auto", profile_budget=PROFILE_BUDGET) -> FitResult:
    r"""Fit a model to friction force (or coefficient) against normal load.

    .. math::
        \min_\theta \sum_i \rho\Big(\Big[\frac{F(P_i;\theta) - F_i}{s_i}\Big]^2\Big)

    with :math:`F(P;\theta)` the model's friction (``mu`` data: :math:`F/P`), :math:`s_i` the
    weights and :math:`\rho` the loss (see :mod:`asperity.fit.api` for every option).

    Parameters
    ----------
    data : Dataset or path
        Friction-load data (:func:`~asperity.fit.data.friction_load_data`) or a CSV file.
    model : str or FitModel
        ``'gw'`` (default), ``'hertz'``, ``'jkr'``, ``'dmt'``, ``'md'``, ``'cos'``, ``'amontons'``.
    vary : sequence of str, optional
        Parameters to fit (default: the model's).
    fix, start, bounds, expr : dict, optional
        Held values, start values, ``(lo, hi)`` bounds, expressions, by parameter name.
    contact : PhysicalContact, optional
        For ``'gw'`` on physical data.
    material : Material or str, optional
        For the single-asperity laws (their modulus).
    weights : {'auto', 'column', 'relative', 'none'}
        Residual weighting.
    loss : {'linear', 'soft_l1', 'huber'}
        Loss function.
    ci : {'auto', 'wald', 'profile'}
        How the 95 % intervals are found.
    units : dict, optional
        Units of columns without one, when reading a file.
    drop_nan : bool
        Drop rows holding NaN when reading a file (counted in the warnings).
    grid : int
        Points of the fitted curve.
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
        Values, standard errors, intervals, correlations, residuals, chi-square, AIC/BIC,
        warnings, the fitted curve.

    Raises
    ------
    ValueError
        For unreadable or invalid data, a model that cannot fit them, or invalid options (an
        unknown or both fixed and varied parameter, bounds excluding the start, fewer points
        than free parameters).

    Examples
    --------
    >>> import numpy as np
    >>> from asperity.fit import friction_load_data
    >>> P = np.linspace(0.0, 5.0, 12)
    >>> res = fit_friction_load(friction_load_data(P, 0.3 * (P + 1.0)), "amontons", weights="none")
    >>> round(res.parameters["mu0"].value, 6), round(res.parameters["P0"].value, 6)
    (0.3, 1.0)

    References
    ----------
    Carpick, Ogletree & Salmeron (1999); Adams et al.; M. Newville et al., LMFIT.
    """
    data = as_dataset(data, "friction", units, drop_nan)
    return fit_problem([data], [get_model(model, material=material, contact=contact)], vary=vary, fix=fix, start=start,
                bounds=bounds, expr=expr, weights=weights, loss=loss, ci=ci, grid=grid, restarts=restarts,
                profile_budget=profile_budget)


def fit_force_separation(data, model="gw", *, vary=None, fix=None, start=None, bounds=None, expr=None, contact=None,
                         material=None, weights="auto", loss="linear", ci="auto", units=None, drop_nan=False,
                         grid=200, restarts="auto", profile_budget=PROFILE_BUDGET) -> FitResult:
    r"""Fit a model to normal force against separation.

    .. math::
        \min_\theta \sum_i \rho\Big(\Big[\frac{P(d_i - d_0;\theta) - P_i}{s_i}\Big]^2\Big)

    The separation offset ``d0`` (``d0_m``) is held at 0 unless varied.  For a single
    asperity the penetration is :math:`\delta = d_0 - d` (displacement control).

    Parameters
    ----------
    data : Dataset or path
        Force-separation data (:func:`~asperity.fit.data.force_separation_data`) or a CSV file.
    model : str or FitModel
        ``'gw'`` (default), ``'hertz'``, ``'jkr'``, ``'dmt'`` or ``'md'``.
    vary : sequence of str, optional
        Parameters to fit (default: the model's).
    fix, start, bounds, expr : dict, optional
        Held values, start values, bounds, expressions.
    contact : PhysicalContact, optional
        For ``'gw'`` on physical data.
    material : Material or str, optional
        For the single-asperity laws.
    weights : {'auto', 'column', 'relative', 'none'}
        Residual weighting (``'auto'``: the uncertainty column, else none).
    loss : {'linear', 'soft_l1', 'huber'}
        Loss function.
    ci : {'auto', 'wald', 'profile'}
        How the 95 % intervals are found.
    units : dict, optional
        Units of columns without one, when reading a file.
    drop_nan : bool
        Drop rows holding NaN when reading a file.
    grid : int
        Points of the fitted curve.
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

    Raises
    ------
    ValueError
        As :func:`fit_friction_load`.

    Examples
    --------
    >>> import numpy as np
    >>> import asperity
    >>> from asperity.fit import force_separation_data
    >>> d = np.linspace(-0.5, 2.5, 15)
    >>> data = force_separation_data(d, asperity.separation_curve(d, 0.01, 1000.0, 2e-3).P)
    >>> res = fit_force_separation(data, vary=["gamma"], start={"gamma": 1e-3})
    >>> round(res.parameters["gamma"].value, 8)
    0.002

    References
    ----------
    Adams et al., Eqs (6), (18) and Fig 7.
    """
    data = as_dataset(data, "force", units, drop_nan)
    return fit_problem([data], [get_model(model, material=material, contact=contact)], vary=vary, fix=fix, start=start,
                bounds=bounds, expr=expr, weights=weights, loss=loss, ci=ci, grid=grid, restarts=restarts,
                profile_budget=profile_budget)


def fit_pull_off(data, model="gw", *, vary=None, fix=None, start=None, bounds=None, expr=None, contact=None,
                 material=None, weights="auto", loss="linear", ci="auto", units=None, drop_nan=False,
                 restarts="auto", profile_budget=PROFILE_BUDGET) -> FitResult:
    r"""Fit a model to pull-off forces, one per surface or condition.

    .. math::
        \min_\theta \sum_i \rho\Big(\Big[\frac{P_{po}(\theta, c_i) - P_{po,i}}{s_i}\Big]^2\Big)

    with :math:`c_i` the row's condition columns (e.g. ``alpha`` or ``R_m`` per row).

    Parameters
    ----------
    data : Dataset or path
        Pull-off data (:func:`~asperity.fit.data.pull_off_data`) or a CSV file.
    model : str or FitModel
        ``'gw'`` (default), ``'jkr'``, ``'dmt'`` or ``'md'``.
    vary : sequence of str, optional
        Parameters to fit (default: the model's).
    fix, start, bounds, expr : dict, optional
        Held values, start values, bounds, expressions.
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

    Raises
    ------
    ValueError
        As :func:`fit_friction_load`.

    Examples
    --------
    >>> import math
    >>> from asperity.fit import pull_off_data
    >>> R = [10e-9, 20e-9, 40e-9]
    >>> data = pull_off_data([1.5 * math.pi * 0.2 * r for r in R], conditions={"R_m": R}, physical=True)
    >>> res = fit_pull_off(data, "jkr", fix={"E_star_Pa": 1e11})
    >>> round(res.parameters["w_J_m2"].value, 9)
    0.2

    References
    ----------
    Johnson, Kendall & Roberts (1971); Maugis (1992); Adams et al., Table 1.
    """
    data = as_dataset(data, "pull_off", units, drop_nan)
    return fit_problem([data], [get_model(model, material=material, contact=contact)], vary=vary, fix=fix, start=start,
                bounds=bounds, expr=expr, weights=weights, loss=loss, ci=ci, restarts=restarts,
                profile_budget=profile_budget)
