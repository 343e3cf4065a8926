r"""Dimensionless groups of the model (Eqs 7, 15-17, 20).

=================  ===========================================  ==========
symbol             definition                                   equation
=================  ===========================================  ==========
alpha              :math:`(\sigma/R)^{1/2}` surface roughness   Eq 7
beta               :math:`(R\sigma)^{1/2}/b` friction regime    Eq 7
gamma              :math:`w/(E^* b)` adhesion/compliance        Eq 16
lambda             Maugis parameter from alpha, beta, gamma     Eq 15
delta_hat          :math:`\bar u = \Delta_M\hat\delta`          Eq 17
P_hat              :math:`\bar P = P_M/\hat P`                  Eq 17
A_hat              :math:`\bar a = A_M/\hat A`                  Eq 17
sigma/b, R/b       :math:`\alpha\beta`, :math:`\beta/\alpha`    Eq 20
=================  ===========================================  ==========

One body is elastic (:math:`E`, :math:`\nu`), the other rigid and flat, so
:math:`E^* = E/(1-\nu^2)`, :math:`G = E/2(1+\nu)` and :math:`E^*/G = 2/(1-\nu)`.

**Correction to Eq (17).**  The paper prints
:math:`\hat P = (1-\nu)\alpha^2/(2\pi\beta\gamma)`.  From :math:`\bar P = P/(Gb^2)`,
:math:`P_M = P/(\pi w R)`, :math:`w = \gamma E^* b`, :math:`R = b\beta/\alpha`:
:math:`\bar P = P_M\,\pi\gamma\beta(E^*/G)/\alpha`, i.e.
:math:`\hat P = (1-\nu)\alpha/(2\pi\beta\gamma)`.  Only this form tends to Eq (6) as
:math:`\gamma \to 0`; :func:`load_scale` takes ``form='printed'`` to show the other.

References
----------
Adams, Müftü, Mohd Azhar, Eqs (7), (15)-(17), (20).
"""

from __future__ import annotations

import numpy as np

from ._validation import (
    check_broadcast,
    check_finite_result,
    check_nonnegative,
    check_poisson,
    check_positive,
    check_text,
)
from .units import is_quantity, to_si

__all__ = [
    "roughness_alpha",
    "regime_beta",
    "adhesion_gamma",
    "work_of_adhesion_from_gamma",
    "composite_modulus",
    "modulus_ratio",
    "maugis_lambda",
    "penetration_scale",
    "load_scale",
    "radius_scale",
    "sigma_over_b",
    "radius_over_b",
]


def _groups(alpha, beta, gamma):
    """alpha, beta, gamma as validated float arrays (all > 0: these scales need adhesion)."""
    alpha, beta, gamma = check_positive(alpha, "alpha"), check_positive(beta, "beta"), check_positive(gamma, "gamma")
    check_broadcast(alpha=alpha, beta=beta, gamma=gamma)
    return alpha, beta, gamma


def roughness_alpha(sigma, R):
    r"""Surface roughness parameter :math:`\alpha = (\sigma/R)^{1/2}` (Eq 7).

    Parameters
    ----------
    sigma : array_like or pint.Quantity
        Standard deviation of asperity (summit) heights, > 0.
    R : array_like or pint.Quantity
        Asperity radius of curvature, > 0 (same unit as ``sigma``; quantities are converted
        to metres).

    References
    ----------
    Adams et al., Eq (7).
    """
    sigma, R = _lengths(sigma=sigma, R=R)
    check_broadcast(sigma=sigma, R=R)
    with np.errstate(all="ignore"):
        return check_finite_result(np.sqrt(sigma / R), "alpha", sigma=sigma, R=R)


def _kinds(value) -> set:
    """'quantity' and/or 'number': what ``value`` holds (lists, tuples and object arrays element by element)."""
    if is_quantity(value) or isinstance(value, str):
        return {"quantity"}
    if isinstance(value, list | tuple) or (isinstance(value, np.ndarray) and value.dtype == object):
        items = value.ravel() if isinstance(value, np.ndarray) else value
        return set().union(*(_kinds(x) for x in items)) if len(items) else {"number"}
    return {"number"}


def _lengths(**values):
    """The lengths of a ratio, each > 0: all quantities (in metres) or all plain numbers (in one
    unit, whichever); a mix would divide metres by nanometres, so it is refused."""
    kinds = {name: _kinds(v) for name, v in values.items()}
    if len(set().union(*kinds.values())) > 1:
        given = [name for name, k in kinds.items() if "quantity" in k]
        plain = [name for name, k in kinds.items() if "number" in k]
        raise ValueError(f"{', '.join(values)} must be all quantities or all plain numbers in one length unit; got "
                         f"quantities in {', '.join(given)} and plain numbers in {', '.join(plain)}")
    return [check_positive(to_si(v, "m", name), name) for name, v in values.items()]


def regime_beta(sigma, R, b):
    r"""Friction regime parameter :math:`\beta = (R\sigma)^{1/2}/b` (Eq 7).

    Parameters
    ----------
    sigma, R, b : array_like or pint.Quantity
        Summit height deviation, summit radius and Burgers vector, > 0 (numbers in one length
        unit; quantities are converted to metres).

    References
    ----------
    Adams et al., Eq (7).
    """
    sigma, R, b = _lengths(sigma=sigma, R=R, b=b)
    check_broadcast(sigma=sigma, R=R, b=b)
    with np.errstate(all="ignore"):
        return check_finite_result(np.sqrt(sigma * R) / b, "beta", sigma=sigma, R=R, b=b)


def adhesion_gamma(w, E_star, b):
    r"""Surface energy/compliance coefficient :math:`\gamma = w/(E^* b)` (Eq 16).

    Parameters
    ----------
    w : array_like or pint.Quantity
        Work of adhesion (J/m^2), >= 0 (0: no adhesion, gamma = 0).
    E_star : array_like or pint.Quantity
        Composite Young's modulus (Pa), > 0.
    b : array_like or pint.Quantity
        Burgers vector (m), > 0.

    References
    ----------
    Adams et al., Eq (16).
    """
    w = check_nonnegative(to_si(w, "J/m^2", "w"), "w")
    E_star, b = check_positive(to_si(E_star, "Pa", "E_star"), "E_star"), check_positive(to_si(b, "m", "b"), "b")
    check_broadcast(w=w, E_star=E_star, b=b)
    with np.errstate(all="ignore"):
        return check_finite_result(w / (E_star * b), "gamma", w=w, E_star=E_star, b=b)


def work_of_adhesion_from_gamma(gamma, E_star, b):
    r"""Work of adhesion :math:`w = \gamma E^* b` (J/m^2), the inverse of Eq (16).

    Parameters
    ----------
    gamma : array_like
        Adhesion parameter, >= 0.
    E_star : array_like or pint.Quantity
        Composite Young's modulus (Pa), > 0.
    b : array_like or pint.Quantity
        Burgers vector (m), > 0.

    References
    ----------
    Adams et al., Eq (16).

    .. math:: w = \gamma E^* b

    Returns
    -------
    float or ndarray
        :math:`w` (J/m^2), broadcast over the inputs.
    """
    gamma = check_nonnegative(to_si(gamma, "", "gamma"), "gamma")
    E_star = check_positive(to_si(E_star, "Pa", "E_star"), "E_star")
    b = check_positive(to_si(b, "m", "b"), "b")
    check_broadcast(gamma=gamma, E_star=E_star, b=b)
    with np.errstate(all="ignore"):
        w = gamma * E_star * b
    out = check_finite_result(w, "w", gamma=gamma, E_star=E_star, b=b)
    return float(out) if np.ndim(out) == 0 else out


def composite_modulus(E, nu):
    r"""Composite modulus :math:`E^* = E/(1-\nu^2)` of an elastic body against a rigid flat.

    .. math:: E^* = \frac{E}{1-\nu^2}

    Parameters
    ----------
    E : array_like
        Young's modulus (Pa), > 0: a number, a pint quantity or a string with a unit
        (``'70GPa'``).
    nu : array_like
        Poisson's ratio, -1 < nu < 0.5.

    Returns
    -------
    float or ndarray
        :math:`E^*` (Pa), the broadcast shape of the inputs.

    Raises
    ------
    ValueError
        If an input is out of its range, not real and finite, or the shapes do not broadcast.

    Examples
    --------
    >>> round(float(composite_modulus("70GPa", 0.3)) / 1e9, 3)
    76.923

    References
    ----------
    K. L. Johnson, *Contact Mechanics* (1985), Eq (4.22) with a rigid counterface.
    """
    E, nu = check_positive(to_si(E, "Pa", "E"), "E"), check_poisson(nu)
    check_broadcast(E=E, nu=nu)
    with np.errstate(all="ignore"):
        return check_finite_result(E / (1.0 - nu**2), "E*", E=E, nu=nu)


def modulus_ratio(nu):
    r""":math:`E^*/G = 2/(1-\nu)`, used to pass from :math:`E^*` to :math:`G` units (Eq 6)."""
    return 2.0 / (1.0 - check_poisson(nu))


def maugis_lambda(alpha, beta, gamma, h_over_b=1.0):
    r"""Maugis parameter from the paper's groups (Eq 15).

    .. math::
        \lambda = \frac{b}{h}\Big(\frac{9\beta\gamma^2}{2\pi\alpha}\Big)^{1/3}

    Parameters
    ----------
    alpha, beta, gamma : array_like
        The model's groups, all > 0.
    h_over_b : array_like
        Dugdale range over Burgers vector, :math:`h/b > 0` (paper: 1).

    References
    ----------
    Adams et al., Eq (15).
    """
    alpha, beta, gamma = _groups(alpha, beta, gamma)
    h_over_b = check_positive(h_over_b, "h_over_b")
    check_broadcast(alpha=alpha, beta=beta, gamma=gamma, h_over_b=h_over_b)
    with np.errstate(all="ignore"):
        lam = np.cbrt(9.0 * beta * gamma**2 / (2.0 * np.pi * alpha)) / h_over_b
    return check_finite_result(lam, "lambda", alpha=alpha, beta=beta, gamma=gamma, h_over_b=h_over_b)


def penetration_scale(alpha, beta, gamma):
    r""":math:`\hat\delta = (3\pi\gamma/4\alpha^2\beta)^{2/3}`, with :math:`\bar u = \Delta_M\hat\delta` (Eq 17).

    References
    ----------
    Adams et al., Eq (17).
    """
    alpha, beta, gamma = _groups(alpha, beta, gamma)
    with np.errstate(all="ignore"):
        scale = np.cbrt(3.0 * np.pi * gamma / (4.0 * alpha**2 * beta)) ** 2
    return check_finite_result(scale, "delta_hat", alpha=alpha, beta=beta, gamma=gamma)


def load_scale(alpha, beta, gamma, nu=0.3, form: str = "derived"):
    r""":math:`\hat P` with :math:`\bar P = P_M/\hat P` (Eq 17, corrected).

    Parameters
    ----------
    alpha, beta, gamma : array_like
        The model's groups, > 0.
    nu : array_like
        Poisson's ratio.
    form : {'derived', 'printed'}
        ``'derived'`` (default): :math:`(1-\nu)\alpha/(2\pi\beta\gamma)`, which follows from
        the definitions and tends to Eq (6) as :math:`\gamma\to 0`.  ``'printed'``: the
        paper's :math:`(1-\nu)\alpha^2/(2\pi\beta\gamma)`, kept only for comparison.

    References
    ----------
    Adams et al., Eq (17); see ``docs/decisions.md``.
    """
    alpha, beta, gamma = _groups(alpha, beta, gamma)
    nu = check_poisson(nu)
    check_broadcast(alpha=alpha, beta=beta, gamma=gamma, nu=nu)
    if check_text(form, "form") not in ("derived", "printed"):
        raise ValueError(f"form must be 'derived' or 'printed', got {form!r}")
    with np.errstate(all="ignore"):
        scale = (1.0 - nu) * alpha ** (1 if form == "derived" else 2) / (2.0 * np.pi * beta * gamma)
    return check_finite_result(scale, "P_hat", alpha=alpha, beta=beta, gamma=gamma)


def radius_scale(alpha, beta, gamma):
    r""":math:`\hat A = [4(\alpha/\beta)^2/(3\pi\gamma)]^{1/3}`, with :math:`\bar a = A_M/\hat A` (Eq 17).

    References
    ----------
    Adams et al., Eq (17).
    """
    alpha, beta, gamma = _groups(alpha, beta, gamma)
    with np.errstate(all="ignore"):
        scale = np.cbrt(4.0 * (alpha / beta) ** 2 / (3.0 * np.pi * gamma))
    return check_finite_result(scale, "A_hat", alpha=alpha, beta=beta, gamma=gamma)


def sigma_over_b(alpha, beta):
    r""":math:`\sigma/b = \alpha\beta` (Eq 20)."""
    alpha, beta = check_positive(alpha, "alpha"), check_positive(beta, "beta")
    check_broadcast(alpha=alpha, beta=beta)
    with np.errstate(all="ignore"):
        return check_finite_result(alpha * beta, "sigma/b", alpha=alpha, beta=beta)


def radius_over_b(alpha, beta):
    r""":math:`R/b = \beta/\alpha` (Eq 20)."""
    alpha, beta = check_positive(alpha, "alpha"), check_positive(beta, "beta")
    check_broadcast(alpha=alpha, beta=beta)
    with np.errstate(all="ignore"):
        return check_finite_result(beta / alpha, "R/b", alpha=alpha, beta=beta)
