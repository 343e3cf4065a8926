r"""Fitting the model, and the single-asperity friction laws AFM users fit, to measured data.

Users arrive with measurements (friction force against load from an AFM or a
nanotribometer, normal force against separation, pull-off forces) and ask the inverse
question: which parameters explain my data, how sure am I, and which model explains it
best?  This package answers it (``pip install 'asperity[fit]'``: lmfit):

* :func:`fit_friction_load`, :func:`fit_force_separation`, :func:`fit_pull_off`: one data
  set; :func:`fit_joint`: several, sharing named parameters; :func:`compare_models`:
  several models ranked by AIC.
* Models (:data:`MODELS`): the multi-asperity model of the paper (``gw``, dimensionless or
  physical through :class:`~asperity.physical.PhysicalContact`), the single-asperity laws
  :math:`F = \tau\pi a(P)^2` with Hertz, JKR, DMT and the exact Maugis-Dugdale radius
  (``hertz``, ``jkr``, ``dmt``, ``md``), the Carpick-Ogletree-Salmeron form (``cos``) and
  Amontons with an adhesion offset (``amontons``).
* Data (:class:`Dataset`): :func:`read_data` (CSV, columns found by header names and
  units), :func:`friction_load_data`, :func:`force_separation_data`, :func:`pull_off_data`.
* Results (:class:`FitResult`, :class:`Comparison`): values, standard errors, 95 %
  intervals (profile likelihood where the covariance is unreliable), correlations,
  residuals, chi-square, AIC/BIC, warnings that name what the data cannot determine, the
  fitted curve, ``to_dict()`` (strict JSON) and ``plot()``.

The modules: :mod:`~asperity.fit.data` and :mod:`~asperity.fit.read` (data),
:mod:`~asperity.fit.models` and :mod:`~asperity.fit.gw` (models),
:mod:`~asperity.fit.engine` (parameters, weights, residuals), :mod:`~asperity.fit.runner`,
:mod:`~asperity.fit.uncertainty` and :mod:`~asperity.fit.profile` (minimiser, errors,
identifiability, profile likelihoods),
:mod:`~asperity.fit.result` and :mod:`~asperity.fit.plot` (results),
:mod:`~asperity.fit.api`, :mod:`~asperity.fit.joint` and :mod:`~asperity.fit.compare` (the
functions above).  lmfit is imported only when a fit runs,
so ``import asperity.fit`` works without it.  See docs/fitting.md.
"""

from .api import fit_force_separation, fit_friction_load, fit_pull_off
from .compare import compare_models
from .data import KINDS, Dataset, force_separation_data, friction_load_data, pull_off_data
from .engine import LOSSES, WEIGHTS
from .joint import fit_joint
from .models import MODELS, FitCurve, FitModel, ParameterSpec, get_model
from .read import read_data
from .result import Comparison, FitResult, ParameterEstimate
from .runner import CI_METHODS

__all__ = [
    "fit_friction_load",
    "fit_force_separation",
    "fit_pull_off",
    "fit_joint",
    "compare_models",
    "Dataset",
    "KINDS",
    "read_data",
    "friction_load_data",
    "force_separation_data",
    "pull_off_data",
    "MODELS",
    "FitModel",
    "FitCurve",
    "ParameterSpec",
    "get_model",
    "FitResult",
    "ParameterEstimate",
    "Comparison",
    "WEIGHTS",
    "LOSSES",
    "CI_METHODS",
]
