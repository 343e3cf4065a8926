"""asperity: nano- to macro-scale multi-asperity contact, adhesion and friction.

Greenwood-Williamson statistics of asperity heights, the Hurtado-Kim scale-dependent
friction stress and Maugis-Dugdale adhesion, after Adams, Müftü and Mohd Azhar,
"A nano-scale multi-asperity contact and friction model".

Layers, each importing only downward:

* single-asperity laws: :mod:`~asperity.friction_stress`, :mod:`~asperity.hertz`,
  :mod:`~asperity.jkr`, :mod:`~asperity.dmt`, :mod:`~asperity.maugis_dugdale`
* dimensionless groups and height statistics: :mod:`~asperity.groups`,
  :mod:`~asperity.heights`
* multi-asperity integrals: :mod:`~asperity.asperity_law`,
  :mod:`~asperity.multi_asperity`
* curves: :mod:`~asperity.curves`; the paper's figures: :mod:`~asperity.studies`;
  the command line: :mod:`~asperity.cli`
"""

from ._version import __version__
from .curves import CurveResult, Model, PullOff, load_curve, pull_off, separation_curve
from .friction_stress import ConstantShear, HurtadoKim
from .heights import GAUSSIAN, Gaussian, HeightDistribution
from .maugis_dugdale import LAMBDA_C, md_branch_end, md_pull_off, md_solve
from .multi_asperity import (
    contact_fraction,
    friction_force,
    mean_pressure,
    normal_force,
    real_contact_area,
)

__all__ = [
    "__version__",
    "CurveResult",
    "Model",
    "PullOff",
    "load_curve",
    "pull_off",
    "separation_curve",
    "ConstantShear",
    "HurtadoKim",
    "GAUSSIAN",
    "Gaussian",
    "HeightDistribution",
    "LAMBDA_C",
    "md_branch_end",
    "md_pull_off",
    "md_solve",
    "contact_fraction",
    "friction_force",
    "mean_pressure",
    "normal_force",
    "real_contact_area",
]
