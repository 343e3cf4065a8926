r"""One asperity in the model's units: contact radius and force versus penetration.

This joins the single-asperity laws to the multi-asperity integrals.  For an asperity
of height :math:`\bar z` at separation :math:`\bar d` the penetration is
:math:`\bar u = \bar z - \bar d` (in units of :math:`\sigma`), and

* without adhesion (:math:`\gamma = 0`): Hertz, Eq (8) and the integrand of Eq (6);
* with adhesion (:math:`\gamma > 0`): Maugis-Dugdale through Eq (17) (corrected
  :math:`\hat P`): :math:`\Delta_M = \bar u/\hat\delta`, :math:`\bar a = A_M/\hat A`,
  :math:`\bar P = P_M/\hat P`, on the stable branch, down to its end at
  :math:`\bar u_{end} = \hat\delta\Delta_{end} < 0`.  Asperities below carry nothing.

Forces are per asperity in units of :math:`G b^2`; radii in units of :math:`b`.

:class:`ContactLaw` writes down what the integrals (:class:`~asperity.multi_asperity.Tabulation`)
use from a per-asperity law; :class:`AsperityLaw` (Hertz / Maugis-Dugdale, with a friction
law) is the default one, and an elastic-plastic law plugs in beside it.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Protocol, runtime_checkable

import numpy as np

from . import groups
from ._validation import as_float_array, check_scalar_poisson, check_scalar_positive
from .friction_stress import ConstantShear, FrictionLaw, HurtadoKim
from .hertz import hertz_force, hertz_radius
from .maugis_dugdale import A_MAX, LAMBDA_RANGE, md_branch_end, md_curve, md_solve, md_t_of_radius

__all__ = ["ModelParameters", "ContactLaw", "AsperityLaw", "check_law", "check_parameters"]


@dataclass(frozen=True)
class ModelParameters:
    """The dimensionless parameters of the model, validated once.

    Parameters
    ----------
    alpha : float
        Surface roughness parameter :math:`(\\sigma/R)^{1/2} > 0` (Eq 7).
    beta : float
        Friction regime parameter :math:`(R\\sigma)^{1/2}/b > 0` (Eq 7).
    gamma : float
        Adhesion parameter :math:`w/(E^* b) \\ge 0` (Eq 16); 0 means Hertz (no adhesion).
    nu : float
        Poisson's ratio of the elastic body, -1 < nu < 0.5 (the paper does not state it;
        0.3 by default).
    h_over_b : float
        Dugdale range over Burgers vector, :math:`h/b > 0` (paper: 1), enters Eq (15).
    friction : FrictionLaw
        Single-asperity friction stress law (default: Hurtado-Kim with the paper's values).
    """

    alpha: float
    beta: float
    gamma: float = 0.0
    nu: float = 0.3
    h_over_b: float = 1.0
    friction: FrictionLaw = field(default_factory=HurtadoKim)

    def __post_init__(self):
        for name in ("alpha", "beta", "gamma", "h_over_b"):
            value = check_scalar_positive(getattr(self, name), name, allow_zero=name == "gamma")
            object.__setattr__(self, name, value)
        object.__setattr__(self, "nu", check_scalar_poisson(self.nu))
        if not isinstance(self.friction, HurtadoKim | ConstantShear | FrictionLaw):  # the protocol check last: slow
            raise TypeError("friction must provide stress(a_bar) and breakpoints() "
                            "(e.g. HurtadoKim() or ConstantShear(tau))")

    @property
    def adhesive(self) -> bool:
        return self.gamma > 0.0


#: Largest adhesive reach below the asperity tops, in sigma, that the integrals handle.
U_END_LIMIT = 1.0e4


def _check_scales(p: ModelParameters):
    """Reject parameter sets whose scales overflow or leave the Maugis-Dugdale range; return
    (lambda, delta_hat, P_hat, A_hat) with adhesion, None without."""
    log_ab2 = np.log10(p.alpha) + 2.0 * np.log10(p.beta)
    if not (-250.0 < log_ab2 < 250.0 and -100.0 < np.log10(p.beta) < 100.0 and 1e-100 <= p.alpha < 1e100):
        raise ValueError(f"alpha={p.alpha:g}, beta={p.beta:g} lie outside what double precision handles: alpha "
                         "and beta between 1e-100 and 1e100, the force scale alpha*beta^2 within 1e-250..1e250; "
                         "use physical values")
    if not p.adhesive:
        return None
    lam = groups.maugis_lambda(p.alpha, p.beta, p.gamma, p.h_over_b)
    scales = (lam, groups.penetration_scale(p.alpha, p.beta, p.gamma), groups.load_scale(
        p.alpha, p.beta, p.gamma, p.nu), groups.radius_scale(p.alpha, p.beta, p.gamma))
    lo, hi = LAMBDA_RANGE
    if not (all(np.isfinite(x) and x > 0 for x in scales) and lo <= lam <= hi):
        raise ValueError(f"alpha={p.alpha:g}, beta={p.beta:g}, gamma={p.gamma:g}, h_over_b={p.h_over_b:g} give a "
                         f"Maugis parameter lambda = {float(lam):.3g} (Eq 15) outside [{lo:g}, {hi:g}]; "
                         + ("adhesion this weak is negligible: use gamma = 0" if lam < lo
                            else "check gamma and h_over_b (h is an atomic distance)"))
    return tuple(float(x) for x in scales)


def check_parameters(params, name: str = "params") -> ModelParameters:
    """``params`` if it is a :class:`ModelParameters`; otherwise a :class:`TypeError` naming ``name``.

    Parameters
    ----------
    params : ModelParameters
        The value to check.
    name : str
        Parameter name for the message.

    Returns
    -------
    ModelParameters

    Raises
    ------
    TypeError
        If ``params`` is not a :class:`ModelParameters`.
    """
    if not isinstance(params, ModelParameters):
        raise TypeError(f"{name} must be an asperity.asperity_law.ModelParameters, got {type(params).__name__}")
    return params


@runtime_checkable
class ContactLaw(Protocol):
    r"""What the multi-asperity integrals use from a per-asperity contact law.

    :class:`~asperity.multi_asperity.Tabulation` evaluates a law once on quadrature nodes in
    penetration and sums it against the height density, so a law is any object with these
    members (:class:`AsperityLaw` is the default; an elastic-plastic law is another).  Units
    are the model's: penetration :math:`\bar u = (z - d)/\sigma` of an asperity of height
    :math:`z` at separation :math:`d`; contact radius :math:`\bar a = a/b`; forces per
    asperity over :math:`Gb^2`, positive compressive.

    Attributes
    ----------
    params : ModelParameters
        The parameters the law was built for (:math:`\alpha, \beta, \gamma, \nu, h/b`,
        friction law); the integrals report them and use :math:`\nu` for the pressure.
    u_end : float
        Lowest penetration at which an asperity carries force, :math:`\bar u_{end} \le 0`
        (in :math:`\sigma`): 0 for Hertz, :math:`\hat\delta\Delta_{end} < 0` with adhesion
        (the end of the stable Maugis-Dugdale branch, Eq 18's lower limit).  The integrals run
        from there to infinity; the law may behave like a square or fourth root at it.
    scale : float
        Penetration (in :math:`\sigma`, > 0) over which the law changes near ``u_end``; the
        first quadrature panel is no wider (1 for Hertz).
    breakpoints : tuple of float
        Penetrations above ``u_end`` where the law or its friction is not smooth, in
        :math:`\sigma`: the Hurtado-Kim radii :math:`\bar a_1, \bar a_2` mapped to
        penetrations, an elastic-plastic law's critical interference.  Quadrature panels
        split there.

    Methods
    -------
    evaluate(u_bar)
        ``(a_bar, P)``: contact radius :math:`a/b` and force :math:`P/(Gb^2)` at the
        penetrations ``u_bar`` (ndarray, any shape; 0 below ``u_end``).
    friction(a_bar)
        Friction force :math:`F/(Gb^2)` of one asperity of contact radius ``a_bar``
        (Eq 10's integrand).
    """

    params: ModelParameters
    u_end: float
    scale: float
    breakpoints: tuple[float, ...]

    def evaluate(self, u_bar):
        """Contact radius a/b and force P/(G b^2) at penetrations u_bar (model units)."""

    def friction(self, a_bar):
        """Friction force F/(G b^2) of one asperity with contact radius a/b."""


def check_law(law, params: ModelParameters):
    """``law`` if it is a :class:`ContactLaw` built for ``params``; ``AsperityLaw(params)`` if None.

    Raises
    ------
    ValueError
        If ``law`` lacks a member of :class:`ContactLaw` or was built for other parameters.

    Examples
    --------
    >>> law = check_law(None, ModelParameters(0.01, 1000.0))
    >>> isinstance(law, ContactLaw), law.u_end
    (True, 0.0)
    """
    check_parameters(params)
    if law is None:
        return AsperityLaw(params)
    if not isinstance(law, AsperityLaw | ContactLaw):  # the first is quick, the protocol check slow
        raise ValueError("law must be a ContactLaw: it provides params, u_end, scale, breakpoints, "
                         f"evaluate(u_bar) and friction(a_bar) (e.g. AsperityLaw(params)), got {type(law).__name__}")
    if law.params != params:
        raise ValueError(f"law was built for {law.params}, not for the model's {params}")
    return law


class AsperityLaw:
    r"""Contact radius and force of one asperity versus its penetration (model units).

    The default :class:`ContactLaw`: Hertz without adhesion (:math:`\gamma = 0`), the stable
    Maugis-Dugdale branch with it, and the friction law of ``params``.

    Parameters
    ----------
    params : ModelParameters
        The model's parameters.

    Attributes
    ----------
    params, u_end, scale, breakpoints :
        As in :class:`ContactLaw`.
    lam : float
        Maugis parameter :math:`\lambda` (Eq 15; 0 without adhesion).
    end : BranchPoint
        End of the stable Maugis-Dugdale branch in Maugis' units (only with adhesion).

    Raises
    ------
    ValueError
        If the parameters overflow double precision or give :math:`\lambda` outside
        :data:`~asperity.maugis_dugdale.LAMBDA_RANGE` or an adhesive reach beyond
        :data:`U_END_LIMIT`.
    """

    def __init__(self, params: ModelParameters):
        self.params = p = check_parameters(params)
        scales = _check_scales(p)
        if p.adhesive:
            self.lam, self.delta_hat, self.P_hat, self.A_hat = scales
            self.end = md_branch_end(self.lam)
            self.u_end = self.delta_hat * self.end.delta
            if self.u_end < -U_END_LIMIT:
                raise ValueError(
                    f"alpha={p.alpha:g}, beta={p.beta:g}, gamma={p.gamma:g} hold asperities in adhesive contact "
                    f"{-self.u_end:.3g} sigma below their tops (penetration scale delta_hat = "
                    f"{self.delta_hat:.3g}); the model handles up to {U_END_LIMIT:g} sigma: raise alpha or "
                    "beta, or lower gamma")
            # Maugis-Dugdale varies on Delta ~ 1, and near the branch end on |Delta_end|.
            self.scale = self.delta_hat * min(1.0, abs(self.end.delta))
        else:
            self.lam = 0.0
            self.u_end = 0.0
            self.scale = 1.0
        self.breakpoints = self._friction_breakpoints()

    def _friction_breakpoints(self) -> tuple[float, ...]:
        """Penetrations where the contact radius crosses the friction law's breakpoints."""
        p = self.params
        radii = np.asarray(p.friction.breakpoints(), dtype=float)
        if not p.adhesive:
            return tuple(sorted((radii / p.beta) ** 2))
        targets = radii * self.A_hat
        # Radii below the branch end never occur; those beyond A_MAX lie past any penetration tabulated.
        targets = targets[(targets > self.end.A) & (targets <= A_MAX)]
        if targets.size == 0:
            return ()
        t = md_t_of_radius(targets, self.lam)
        # One or two radii: the curve point by point (its fast path for single floats).
        return tuple(sorted(self.delta_hat * float(md_curve(float(x), self.lam)[2]) for x in t))

    def evaluate(self, u_bar):
        """Contact radius :math:`\\bar a` and force :math:`P/(Gb^2)` at penetrations ``u_bar``.

        Penetrations below the end of the stable branch give zero radius and force.
        """
        p = self.params
        u = as_float_array(u_bar, "u_bar", allow_empty=True)
        if not p.adhesive:
            return hertz_radius(u, p.beta), hertz_force(u, p.alpha, p.beta, p.nu)
        a = np.zeros_like(u)
        P = np.zeros_like(u)
        on = u >= self.u_end
        if on.any():
            delta = np.maximum(u[on] / self.delta_hat, self.end.delta)
            A, PM, _ = md_solve(delta, self.lam)
            a[on] = A / self.A_hat
            P[on] = PM / self.P_hat
        return a, P

    def friction(self, a_bar):
        """Friction force :math:`F_f/(Gb^2) = 2\\pi\\bar\\tau_f\\bar a^2` (Eq 10 integrand)."""
        a = np.asarray(a_bar, dtype=float)
        return 2.0 * np.pi * self.params.friction.stress(a) * a * a
