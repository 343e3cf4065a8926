r"""A Greenwood-Williamson rough surface in SI units, and its link to the paper's groups.

The Greenwood-Williamson (GW) model describes a nominally flat rough surface by three
summit statistics and the nominal area it covers:

=================  ============================================  ==============
symbol             meaning                                       unit
=================  ============================================  ==============
``sigma_s``        standard deviation of summit heights          m
``R``              mean summit radius of curvature               m
``eta``            summit density (summits per nominal area)     1/m\ :sup:`2`
``area``           nominal contact area :math:`A_0`              m\ :sup:`2`
=================  ============================================  ==============

The names are those of :data:`asperity.quantities.PHYSICAL_PARAMETERS`;
:class:`asperity.topography.SummitParameters` uses the same three.  The surface holds
:math:`N = \eta A_0` asperities, and with the Burgers vector :math:`b` of the material it
gives the paper's roughness and friction-regime parameters (Eq 7),

.. math::
    \alpha = (\sigma_s/R)^{1/2},\qquad \beta = (R\sigma_s)^{1/2}/b,

which :func:`surface_from_groups` inverts (Eq 20):
:math:`\sigma_s = \alpha\beta b`, :math:`R = \beta b/\alpha`.

Every input accepts a float in SI units, a pint ``Quantity`` or a string with a unit
such as ``'2nm'`` (``pip install 'asperity[units]'``).

References
----------
.. [1] J. A. Greenwood, J. B. P. Williamson, "Contact of nominally flat surfaces",
   Proc. R. Soc. A 295 (1966) 300-319.
.. [2] Adams, Müftü, Mohd Azhar, "A nano-scale multi-asperity contact and friction model",
   Eqs (7), (20).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ._validation import check_scalar_positive
from .quantities import PHYSICAL_PARAMETERS

__all__ = ["Surface", "surface_from_groups"]

#: The fields of a :class:`Surface`, with their entries in the quantity registry.
SURFACE_PARAMETERS = {name: PHYSICAL_PARAMETERS[name] for name in ("sigma_s", "R", "eta", "area")}


@dataclass(frozen=True)
class Surface:
    r"""A Greenwood-Williamson rough surface in SI units.

    Parameters
    ----------
    sigma_s : float, pint.Quantity or str
        Standard deviation of summit heights :math:`\sigma_s` (m), > 0.
    R : float, pint.Quantity or str
        Mean summit radius of curvature :math:`R` (m), > 0.
    eta : float, pint.Quantity or str
        Summit density :math:`\eta` (1/m^2), > 0.
    area : float, pint.Quantity or str
        Nominal contact area :math:`A_0` (m^2), > 0.

    Attributes
    ----------
    N : float
        Number of summits :math:`\eta A_0` in the nominal area.
    alpha : float
        Roughness parameter :math:`(\sigma_s/R)^{1/2}` (Eq 7).

    Raises
    ------
    ValueError
        For a value that is not one finite number > 0, or a quantity of the wrong
        dimension; the message names the field and its unit.

    Examples
    --------
    >>> Surface(sigma_s=2e-9, R=1e-6, eta=1e12, area=1e-6).N
    1000000.0
    """

    sigma_s: float
    R: float
    eta: float
    area: float

    def __post_init__(self):
        for name, q in SURFACE_PARAMETERS.items():
            object.__setattr__(self, name, check_scalar_positive(getattr(self, name), name, q.si_unit))

    @property
    def N(self) -> float:
        """Number of asperities (summits) :math:`\\eta A_0` in the nominal area."""
        return self.eta * self.area

    @property
    def alpha(self) -> float:
        """Surface roughness parameter :math:`(\\sigma_s/R)^{1/2}` (Eq 7)."""
        return math.sqrt(self.sigma_s / self.R)


def surface_from_groups(alpha, beta, b, eta, area) -> Surface:
    r"""The :class:`Surface` with given roughness and friction-regime parameters (Eq 20).

    .. math:: \sigma_s = \alpha\beta b,\qquad R = \beta b/\alpha

    Parameters
    ----------
    alpha : float
        Roughness parameter :math:`\alpha = (\sigma_s/R)^{1/2}` (Eq 7), > 0.
    beta : float
        Friction-regime parameter :math:`\beta = (R\sigma_s)^{1/2}/b` (Eq 7), > 0.
    b : float, pint.Quantity or str
        Burgers vector :math:`b` (m), > 0.
    eta : float, pint.Quantity or str
        Summit density :math:`\eta` (1/m^2), > 0.
    area : float, pint.Quantity or str
        Nominal area :math:`A_0` (m^2), > 0.

    Returns
    -------
    Surface
        With :math:`\sigma_s = \alpha\beta b` and :math:`R = \beta b/\alpha`.

    References
    ----------
    Adams et al., Eq (20).

    Examples
    --------
    >>> s = surface_from_groups(0.01, 100.0, 2.5e-10, 1e12, 1e-6)
    >>> round(s.sigma_s * 1e10, 12), round(s.R * 1e6, 12)
    (2.5, 2.5)
    """
    alpha = check_scalar_positive(alpha, "alpha", "")
    beta = check_scalar_positive(beta, "beta", "")
    b = check_scalar_positive(b, "b", "m")
    return Surface(sigma_s=alpha * beta * b, R=beta * b / alpha, eta=eta, area=area)
