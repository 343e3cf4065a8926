"""Reference for :mod:`asperity.groups`: Maugis parameter and unit conversions (Eqs 15, 17), in mpmath."""

from __future__ import annotations

from .common import MP, finite, mpmath, positive

__all__ = ["conversion_factors"]


def conversion_factors(alpha, beta, gamma, *, nu=0.3, h_over_b=1.0):
    """Maugis parameter and Maugis <-> model unit conversions (Eqs. 15, 17).

    Derivation (with ``sigma = alpha beta b``, ``R = b beta/alpha`` (Eq. 20),
    ``w = gamma E* b`` (Eq. 16), ``K = 4E*/3``, ``E*/G = 2/(1-nu)``):

    * ``P_bar = P/(G b^2) = P_M pi w R/(G b^2) = P_M (2 pi beta gamma)/((1-nu) alpha)``
      so ``P_hat = (1-nu) alpha/(2 pi beta gamma)``.  (The paper prints
      ``alpha**2``; that is a typo: with it Hertz would not be recovered.)
    * ``u_bar = Delta_M delta_hat`` with
      ``delta_hat = (3 pi gamma/(4 alpha^2 beta))**(2/3)``.
    * ``a_bar = A_M/A_hat`` with ``A_hat = (4/(3 pi gamma) (alpha/beta)^2)**(1/3)``.
    * ``lambda = (b/h) (9 beta gamma^2/(2 pi alpha))**(1/3)`` (Eq. 15).

    As a check, ``delta_hat A_hat^2 = 1/beta^2`` so the Hertz limit
    ``Delta_M = A_M^2`` maps to ``u_bar = a_bar^2/beta^2`` (Eq. 8), and
    ``A_M^3/P_hat`` maps to Eq. 6.

    Parameters
    ----------
    alpha, beta : float
        Roughness and friction-regime parameters (Eq. 7), > 0.
    gamma : float
        Surface energy / compliance coefficient (Eq. 16), > 0.
    nu : float, optional
        Poisson's ratio.
    h_over_b : float, optional
        Maximum adhesion distance over Burgers vector.

    Returns
    -------
    dict
        Keys ``'lambda'``, ``'delta_hat'``, ``'P_hat'``, ``'A_hat'``.
    """
    alpha = positive("alpha", alpha)
    beta = positive("beta", beta)
    gamma = positive("gamma", gamma)
    nu = finite("nu", nu)
    if not -1.0 < nu < 0.5:
        raise ValueError(f"nu must satisfy -1 < nu < 0.5, got {nu!r}")
    h_over_b = positive("h_over_b", h_over_b)
    with MP.workdps(30):
        a, b, g = mpmath.mpf(alpha), mpmath.mpf(beta), mpmath.mpf(gamma)
        lam = mpmath.cbrt(9 * b * g**2 / (2 * mpmath.pi * a)) / mpmath.mpf(h_over_b)
        delta_hat = (3 * mpmath.pi * g / (4 * a**2 * b)) ** (mpmath.mpf(2) / 3)
        P_hat = (1 - mpmath.mpf(nu)) * a / (2 * mpmath.pi * b * g)
        A_hat = mpmath.cbrt(4 / (3 * mpmath.pi * g) * (a / b) ** 2)
        return {"lambda": float(lam), "delta_hat": float(delta_hat), "P_hat": float(P_hat), "A_hat": float(A_hat)}
