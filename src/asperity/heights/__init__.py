r"""Statistics of summit heights: the :math:`\phi(\bar z)` of Eqs (5)-(10), Gaussian and beyond.

Heights are in units of the summit-height standard deviation :math:`\sigma_s`, measured
from the mean summit height: every distribution is standardised to zero mean and unit
variance, so :math:`\sigma_s` keeps its meaning in :math:`\alpha` and :math:`\beta` (Eq 7)
and only the *shape* changes.  Real summit heights are skewed (worn, polished,
plateau-honed, coated surfaces); the families here span the shapes measured:

=================  ===================================  ========================================
name               class                                for
=================  ===================================  ========================================
``gaussian``       :class:`Gaussian` (Eq 19)            the paper; ground, bead-blasted surfaces
``exponential``    :class:`Exponential`                 GW's closed forms; the upper tail of
                                                        many surfaces
``weibull``        :class:`Weibull` (skewness)          skewed machined surfaces (Yu &
                                                        Polycarpou), -1 <= Sk <= 2
``pearson3``       :class:`PearsonIII` (skewness)       either sign of skew, |Sk| <= 2
``johnson``        :class:`Johnson` (skew, kurtosis)    any measured (Sk, Ku): S_U, S_B, S_L
``mixture``        :class:`Mixture`                     plateau-honed (two-process) surfaces
``empirical``      :class:`Empirical`                   measured summits, as they are
=================  ===================================  ========================================

Each implements :class:`HeightDistribution` (density, its derivatives, survival function,
the GW moment :math:`F_n`); :data:`DISTRIBUTIONS` names them, :func:`parse_heights` reads
the command-line spelling (``weibull:skew=0.5``) and :func:`fit_heights` fits them to
measured summit heights and ranks them.  The model's integrals take any of them
(``heights=`` of every curve function, :class:`asperity.Model` and
:class:`asperity.physical.PhysicalContact`); see docs/heights.md.

References
----------
.. [1] J. A. Greenwood, J. B. P. Williamson, Proc. R. Soc. A 295 (1966) 300.
.. [2] Adams et al., Eq (19).
.. [3] N. Yu, A. A. Polycarpou, J. Tribol. 124 (2002) 367; 126 (2004) 225.
.. [4] N. L. Johnson, Biometrika 36 (1949) 149.
.. [5] J. I. McCool, Wear 107 (1986) 37.
"""

from .base import EDGE_BAND, SF_FLOOR, TAIL, HeightDistribution, check_heights, gw_moment_quadrature
from .empirical import Empirical
from .exponential import Exponential
from .fit import FitResult, HeightsFit, fit_heights
from .gaussian import GAUSSIAN, Gaussian
from .johnson import Johnson
from .mixture import Mixture
from .pearson import PearsonIII
from .registry import DISTRIBUTIONS, SPELLINGS, distribution, parse_heights
from .samples import MIN_SAMPLES, read_samples, sample_moments, write_samples
from .weibull import Weibull

__all__ = [
    "HeightDistribution",
    "Gaussian",
    "GAUSSIAN",
    "Exponential",
    "Weibull",
    "PearsonIII",
    "Johnson",
    "Mixture",
    "Empirical",
    "DISTRIBUTIONS",
    "SPELLINGS",
    "distribution",
    "parse_heights",
    "fit_heights",
    "FitResult",
    "HeightsFit",
    "read_samples",
    "write_samples",
    "MIN_SAMPLES",
    "sample_moments",
    "check_heights",
    "gw_moment_quadrature",
    "TAIL",
    "SF_FLOOR",
    "EDGE_BAND",
]
