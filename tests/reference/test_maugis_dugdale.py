"""asperity.reference.maugis_dugdale against the printed Eqs (11)-(13) and their small-t series.

Nothing here compares with the fast path: every expected value is a closed form.
"""

import math

import mpmath

from asperity.reference import maugis_dugdale as ref


def closed_moment(d, k):
    """int_d^inf (z-d)^k phi(z) dz = Gamma(k+1) exp(-d^2/4) D_{-k-1}(d) / sqrt(2 pi)."""
    with mpmath.workdps(40):
        d = mpmath.mpf(d)
        val = mpmath.gamma(k + 1) * mpmath.exp(-d * d / 4) * mpmath.pcfd(-k - 1, d) / mpmath.sqrt(2 * mpmath.pi)
        return float(val)


def rel(a, b):
    return abs(a - b) / abs(b)


def test_md_curve_small_t_series():
    # near m -> 1 Eq. 11 reduces to (2/3) lam A^2 t^3 + (2/3) lam^2 A t^2 = 1 + O(t^4)
    lam, t = 0.7, 1e-7
    A, P, D = ref.md_curve(t, lam)
    lhs = (2 / 3) * lam * A**2 * t**3 + (2 / 3) * lam**2 * A * t**2
    assert abs(lhs - 1) < 1e-6


def test_md_curve_satisfies_eqs_11_to_13_literally():
    # transcription check of Eqs. 11-13 as printed, at moderate m (no cancellation)
    lam = 0.8
    for t in (0.2, 1.0, 4.0):
        A, P, D = ref.md_curve(t, lam)
        m = math.sqrt(1 + t * t)
        s = math.sqrt(m * m - 1)
        at = math.atan(s)
        lhs = lam * A**2 / 2 * (s + (m * m - 2) * at) + 4 * lam**2 * A / 3 * (s * at - m + 1)
        assert abs(lhs - 1) < 1e-13
        assert abs(P - (A**3 - lam * A**2 * (s + m * m * at))) < 1e-13 * max(1, abs(P))
        assert abs(D - (A**2 - 4 / 3 * A * lam * s)) < 1e-13 * max(1, abs(D))
