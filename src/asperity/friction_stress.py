r"""Friction stress of one asperity contact: the Hurtado-Kim law (Eqs 2-4).

Hurtado and Kim's dislocation model gives a friction stress that is constant for
contact radii below :math:`\bar a_1` (region 1, AFM-like), constant and much lower above
:math:`\bar a_2` (region 3, SFA-like) and a straight line in log-log between them
(region 2).  Stresses are normalised by the effective shear modulus
:math:`G^* = 2G` (one body rigid), radii by the Burgers vector :math:`b`.

All functions broadcast like NumPy ufuncs.  Logarithms are base 10, as in the paper.

A constant-shear-stress law (:class:`ConstantShear`) sits beside
:class:`HurtadoKim` behind the same small interface (:class:`FrictionLaw`), so every
multi-asperity integral works with either.

References
----------
.. [1] Adams, Müftü, Mohd Azhar, "A nano-scale multi-asperity contact and friction
   model", Eqs (2)-(4) and (10).
.. [2] Hurtado, Kim, "Scale effects in friction of single-asperity contacts",
   Proc. R. Soc. A 455 (1999).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol, runtime_checkable

import numpy as np

from ._validation import as_float_array, check_finite_result, check_scalar_positive, ufunc_result

__all__ = [
    "TAU_F1",
    "TAU_F2",
    "A1",
    "A2",
    "FrictionLaw",
    "HurtadoKim",
    "ConstantShear",
    "hk_slope_intercept",
    "hk_friction_stress",
    "hk_friction_force",
]

#: Paper's values (Results section, from Hurtado & Kim): region-1 stress tau_f1/G*.
TAU_F1 = 1.0 / 43.0
#: Region-3 stress, tau_f1 / 30.
TAU_F2 = TAU_F1 / 30.0
#: Dimensionless contact radius a/b where region 2 starts.
A1 = 28.0
#: Dimensionless contact radius a/b where region 2 ends.
A2 = 8.0e4


def _check_hk(tau_f1, tau_f2, a1, a2):
    tau_f1 = check_scalar_positive(tau_f1, "tau_f1")
    tau_f2 = check_scalar_positive(tau_f2, "tau_f2")
    a1 = check_scalar_positive(a1, "a1")
    a2 = check_scalar_positive(a2, "a2")
    if not a2 > a1:
        raise ValueError(f"a2 must be > a1 (region 2 is a1 < a_bar < a2), got a1={a1}, a2={a2}")
    return tau_f1, tau_f2, a1, a2


def hk_slope_intercept(tau_f1=TAU_F1, tau_f2=TAU_F2, a1=A1, a2=A2):
    r"""Slope M and intercept B of region 2 of the Hurtado-Kim law (Eq 3).

    .. math::
        M = -\frac{\log(\bar\tau_{f_1}/\bar\tau_{f_2})}{\log(\bar a_2/\bar a_1)},\qquad
        B = \frac{\log\bar\tau_{f_1}\log\bar a_2 - \log\bar\tau_{f_2}\log\bar a_1}
                 {\log(\bar a_2/\bar a_1)}

    Parameters
    ----------
    tau_f1, tau_f2 : float
        Friction stress :math:`\tau_f/G^*` in regions 1 and 3 (> 0).
    a1, a2 : float
        Contact radii :math:`a/b` bounding region 2 (0 < a1 < a2).

    Returns
    -------
    M, B : float
        So that :math:`\log_{10}\bar\tau_f = M\log_{10}\bar a + B` in region 2.

    References
    ----------
    Adams et al., Eq (3).
    """
    tau_f1, tau_f2, a1, a2 = _check_hk(tau_f1, tau_f2, a1, a2)
    span = np.log10(a2) - np.log10(a1)
    slope = -(np.log10(tau_f1) - np.log10(tau_f2)) / span  # logs first: the ratio may overflow
    intercept = (np.log10(tau_f1) * np.log10(a2) - np.log10(tau_f2) * np.log10(a1)) / span
    return float(slope), float(intercept)


def hk_friction_stress(a_bar, tau_f1=TAU_F1, tau_f2=TAU_F2, a1=A1, a2=A2):
    r"""Dimensionless friction stress :math:`\bar\tau_f = \tau_f/G^*` (Eq 2).

    .. math::
        \log\bar\tau_f = \begin{cases}
            \log\bar\tau_{f_1}, & \bar a < \bar a_1\\
            M\log\bar a + B, & \bar a_1 \le \bar a \le \bar a_2\\
            \log\bar\tau_{f_2}, & \bar a > \bar a_2 \end{cases}

    Parameters
    ----------
    a_bar : array_like
        Contact radius over Burgers vector, :math:`a/b \ge 0`.
    tau_f1, tau_f2, a1, a2 : float
        Law constants (defaults: the paper's 1/43, 1/1290, 28, 8e4).

    Returns
    -------
    ndarray
        :math:`\tau_f/G^*`, same shape as ``a_bar``.  Continuous in ``a_bar``.

    References
    ----------
    Adams et al., Eq (2); Hurtado & Kim (1999).
    """
    a = as_float_array(a_bar, "a_bar", allow_empty=True)
    if np.any(a < 0):
        raise ValueError("a_bar (contact radius a/b) must be >= 0")
    slope, intercept = hk_slope_intercept(tau_f1, tau_f2, a1, a2)
    # Clipping into [a1, a2] makes the region-2 line give exactly the two plateaus.
    clipped = np.clip(a, a1, a2)
    return 10.0 ** (slope * np.log10(clipped) + intercept)


def hk_friction_force(a_bar, tau_f1=TAU_F1, tau_f2=TAU_F2, a1=A1, a2=A2):
    r"""Friction force of one asperity, :math:`F_f/(G^* b^2) = \pi\bar\tau_f\bar a^2` (Eq 4).

    The paper prints Eq (4) without the :math:`\pi` of :math:`F_f = \pi a^2\tau_f`; its
    Eq (10) keeps it (:math:`2\pi = \pi G^*/G`).  This function uses the correct
    :math:`\pi`; see ``docs/decisions.md``.

    Parameters
    ----------
    a_bar : array_like
        Contact radius :math:`a/b \ge 0`.
    tau_f1, tau_f2, a1, a2 : float
        Law constants, as in :func:`hk_friction_stress`.

    Returns
    -------
    ndarray
        :math:`F_f/(G^* b^2)`.  Multiply by 2 for :math:`F_f/(G b^2)` (:math:`G^* = 2G`).

    References
    ----------
    Adams et al., Eq (4) (with the :math:`\pi` restored) and Eq (10).
    """
    a = as_float_array(a_bar, "a_bar", allow_empty=True)
    stress = hk_friction_stress(a, tau_f1, tau_f2, a1, a2)
    with np.errstate(all="ignore"):
        force = np.pi * stress * a**2
    return check_finite_result(force, "the friction force", a_bar=a)


@runtime_checkable
class FrictionLaw(Protocol):
    """What the multi-asperity integrals need from a single-asperity friction law."""

    def stress(self, a_bar):
        """Friction stress tau_f / G* at contact radius a/b (broadcasts)."""

    def breakpoints(self) -> tuple[float, ...]:
        """Contact radii a/b where the law is not smooth (quadrature splits there)."""


@dataclass(frozen=True)
class HurtadoKim:
    """The Hurtado-Kim scale-dependent friction stress (Eqs 2-4) as a law object.

    Parameters
    ----------
    tau_f1, tau_f2 : float
        :math:`\\tau_f/G^*` in regions 1 and 3.
    a1, a2 : float
        Radii :math:`a/b` bounding region 2.
    """

    tau_f1: float = TAU_F1
    tau_f2: float = TAU_F2
    a1: float = A1
    a2: float = A2

    def __post_init__(self):
        _check_hk(self.tau_f1, self.tau_f2, self.a1, self.a2)

    def stress(self, a_bar):
        """Friction stress :math:`\\tau_f/G^*` (Eq 2)."""
        return hk_friction_stress(a_bar, self.tau_f1, self.tau_f2, self.a1, self.a2)

    def force(self, a_bar):
        """Friction force :math:`F_f/(G^* b^2)` of one asperity (Eq 4, with pi)."""
        a = as_float_array(a_bar, "a_bar", allow_empty=True)
        stress = self.stress(a)
        with np.errstate(all="ignore"):
            force = np.pi * stress * a**2
        return check_finite_result(force, "the friction force", a_bar=a)

    def breakpoints(self) -> tuple[float, ...]:
        return (self.a1, self.a2)


@dataclass(frozen=True)
class ConstantShear:
    """A scale-independent friction stress :math:`\\tau_f/G^*` = ``tau`` (Bowden-Tabor)."""

    tau: float = TAU_F1

    def __post_init__(self):  # one number (an array failed later, in NumPy's words: a user trial)
        object.__setattr__(self, "tau", check_scalar_positive(self.tau, "tau"))

    def stress(self, a_bar):
        """The constant stress, broadcast to the shape of ``a_bar``."""
        a = as_float_array(a_bar, "a_bar", allow_empty=True)
        return ufunc_result(np.full_like(a, self.tau))

    def force(self, a_bar):
        """Friction force :math:`F_f/(G^* b^2) = \\pi\\tau\\bar a^2`."""
        a = as_float_array(a_bar, "a_bar", allow_empty=True)
        stress = self.stress(a)
        with np.errstate(all="ignore"):
            force = np.pi * stress * a**2
        return check_finite_result(force, "the friction force", a_bar=a)

    def breakpoints(self) -> tuple[float, ...]:
        return ()
