r"""A physical contact's moduli, Burgers vector and dimensionless groups, from its material and surface.

:class:`ContactGroups` gives :class:`asperity.physical.PhysicalContact` the properties the
paper's model needs from SI inputs: :math:`b`, :math:`\nu`, :math:`E^*`, :math:`G`,
:math:`G^*`, :math:`N = \eta A_0`, the groups :math:`\alpha = (\sigma_s/R)^{1/2}`,
:math:`\beta = (R\sigma_s)^{1/2}/b` (Eq 7), :math:`\gamma = w/E^*b` (Eq 16),
:math:`h/b`, :math:`\lambda` (Eq 15), the units of force :math:`NGb^2` and area
:math:`N\pi b^2`, and the single-asperity adhesion regime.  It reads ``material``,
``surface``, ``w`` and ``h`` of the contact.

References
----------
.. [1] Adams, Müftü, Mohd Azhar, "A nano-scale multi-asperity contact and friction model",
   Eqs (7), (14)-(16).
"""

from __future__ import annotations

import math

from . import groups
from .regimes import adhesion_regime

__all__ = ["ContactGroups"]


class ContactGroups:
    """Moduli, Burgers vector, groups and units of a contact with ``material``, ``surface``, ``w``, ``h``."""

    # -- material and surface -----------------------------------------------------------
    @property
    def b(self) -> float:
        """Burgers vector (m)."""
        return self.material.b

    @property
    def nu(self) -> float:
        """Poisson's ratio (for a pair: the effective 1 - G*/E*)."""
        return self.material.nu

    @property
    def E_star(self) -> float:
        """Composite Young's modulus (Pa)."""
        return self.material.E_star

    @property
    def G(self) -> float:
        """Shear modulus of the force unit G b^2 (Pa); G* = 2G."""
        return self.material.G

    @property
    def G_star(self) -> float:
        """Effective shear modulus 2G (Pa), the unit of friction stress."""
        return self.material.G_star

    @property
    def N(self) -> float:
        """Number of asperities eta * area."""
        return self.surface.N

    # -- groups -------------------------------------------------------------------------
    @property
    def alpha(self) -> float:
        """Roughness parameter (sigma_s/R)^(1/2) (Eq 7)."""
        return float(groups.roughness_alpha(self.surface.sigma_s, self.surface.R))

    @property
    def beta(self) -> float:
        """Friction regime parameter (R sigma_s)^(1/2)/b (Eq 7)."""
        return float(groups.regime_beta(self.surface.sigma_s, self.surface.R, self.b))

    @property
    def gamma(self) -> float:
        """Adhesion parameter w/(E* b) (Eq 16); 0 without adhesion."""
        return float(groups.adhesion_gamma(self.w, self.E_star, self.b)) if self.w > 0 else 0.0

    @property
    def h_over_b(self) -> float:
        """Dugdale range over Burgers vector."""
        return self.h / self.b

    @property
    def lam(self) -> float:
        """Maugis parameter from the groups (Eq 15); equal to Eq (14) with sigma0 = w/h; 0 without adhesion."""
        if self.gamma == 0.0:
            return 0.0
        return float(groups.maugis_lambda(self.alpha, self.beta, self.gamma, self.h_over_b))

    @property
    def force_scale(self) -> float:
        """Force unit N G b^2 (N)."""
        return self.N * (self.G * self.b**2)

    @property
    def area_scale(self) -> float:
        """Area unit N pi b^2 (m^2)."""
        return self.N * math.pi * self.b**2

    @property
    def regime(self) -> str:
        """Single-asperity adhesion regime of :attr:`lam`: ``'DMT'``, ``'Maugis-Dugdale'``,
        ``'JKR'`` (:func:`~asperity.regimes.adhesion_regime`), or ``'Hertz'`` without adhesion."""
        return "Hertz" if self.gamma == 0.0 else adhesion_regime(self.lam)
