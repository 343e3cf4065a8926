"""asperity.reference.groups against closed forms: the conversions reduce to Hertz (Eqs 6, 8, 15, 17).

Nothing here compares with the fast path: every expected value is a closed form.
"""

import math

import mpmath

from asperity.reference import groups as ref


def closed_moment(d, k):
    """int_d^inf (z-d)^k phi(z) dz = Gamma(k+1) exp(-d^2/4) D_{-k-1}(d) / sqrt(2 pi)."""
    with mpmath.workdps(40):
        d = mpmath.mpf(d)
        val = mpmath.gamma(k + 1) * mpmath.exp(-d * d / 4) * mpmath.pcfd(-k - 1, d) / mpmath.sqrt(2 * mpmath.pi)
        return float(val)


def rel(a, b):
    return abs(a - b) / abs(b)


def test_conversion_factors_reduce_to_hertz():
    alpha, beta, gamma, nu = 0.013, 420.0, 0.002, 0.25
    f = ref.conversion_factors(alpha, beta, gamma, nu=nu)
    # Delta = A^2 maps to u = a^2/beta^2 (Eq. 8)
    assert rel(f["delta_hat"] * f["A_hat"] ** 2, 1 / beta**2) < 1e-14
    # P_M = A_M^3 maps to the Hertz load (4/3)(2/(1-nu)) alpha beta^2 u^1.5 (Eq. 6)
    a_bar = 7.0
    u = a_bar**2 / beta**2
    hertz = (4 / 3) * (2 / (1 - nu)) * alpha * beta**2 * u**1.5
    assert rel((a_bar * f["A_hat"]) ** 3 / f["P_hat"], hertz) < 1e-13
    lam = (9 * beta * gamma**2 / (2 * math.pi * alpha)) ** (1 / 3)
    assert rel(f["lambda"], lam) < 1e-14
