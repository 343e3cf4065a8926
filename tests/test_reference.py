"""Tests of the independent slow reference path against closed forms only.

Nothing here compares with the fast path of :mod:`asperity`; every expected
value is a closed form (parabolic-cylinder moments, JKR / DMT limits, the
explicit Maugis-Dugdale parametrisation) evaluated independently.
"""

import math

import mpmath
import pytest

from asperity import reference as ref


def closed_moment(d, k):
    """int_d^inf (z-d)^k phi(z) dz = Gamma(k+1) exp(-d^2/4) D_{-k-1}(d) / sqrt(2 pi)."""
    with mpmath.workdps(40):
        d = mpmath.mpf(d)
        val = mpmath.gamma(k + 1) * mpmath.exp(-d * d / 4) * mpmath.pcfd(-k - 1, d) / mpmath.sqrt(2 * mpmath.pi)
        return float(val)


def rel(a, b):
    return abs(a - b) / abs(b)


# ---------------------------------------------------------------------------
# Greenwood-Williamson moments
# ---------------------------------------------------------------------------
@pytest.mark.parametrize("k", [0, 1, 1.5])
@pytest.mark.parametrize("d", [-3.0, -0.7, 0.0, 0.4, 2.0, 6.5])
def test_gw_moment_parabolic_cylinder(d, k):
    assert rel(ref.gw_moment(d, k), closed_moment(d, k)) < 1e-13


def test_gw_moment_gaussian_tail():
    # order 0 is the normal upper tail
    for d in (-1.0, 0.5, 3.0):
        assert rel(ref.gw_moment(d, 0), 0.5 * math.erfc(d / math.sqrt(2))) < 1e-14


# ---------------------------------------------------------------------------
# Hertz (no adhesion) against closed forms
# ---------------------------------------------------------------------------
@pytest.mark.parametrize("d", [-1.5, 0.0, 0.7, 2.5, 5.0])
@pytest.mark.parametrize(("alpha", "beta", "nu"), [(0.01, 1000.0, 0.3), (0.2, 37.0, -0.4)])
def test_hertz_separation_closed_form(d, alpha, beta, nu):
    res = ref.separation_point(d, alpha, beta, 0.0, nu=nu)
    pref = (4.0 / 3.0) * (2.0 / (1.0 - nu)) * alpha * beta**2
    assert rel(res["P"], pref * closed_moment(d, 1.5)) < 1e-10
    assert rel(res["area"], beta**2 * closed_moment(d, 1)) < 1e-10
    assert rel(res["contacts"], closed_moment(d, 0)) < 1e-10


@pytest.mark.parametrize("d", [-1.0, 0.3, 3.0])
def test_hertz_friction_region1_closed_form(d):
    beta, tau1 = 800.0, 1 / 43
    res = ref.separation_point(d, 0.01, beta, 0.0, a1=1e20, a2=1e21)
    expect = 2 * math.pi * tau1 * beta**2 * closed_moment(d, 1)
    assert rel(res["F"], expect) < 1e-10


@pytest.mark.parametrize("d", [-0.5, 1.2])
def test_hertz_friction_region2_closed_form(d):
    # a1 tiny and a2 huge: every contact is on the log-log line of Eq. 2,
    # F = 2 pi tau1 a1^-M beta^(M+2) moment(d, (M+2)/2).
    beta, tau1, tau2, a1, a2 = 300.0, 0.02, 0.001, 1e-8, 1e12
    M = math.log(tau2 / tau1) / math.log(a2 / a1)
    res = ref.separation_point(d, 0.05, beta, 0.0, tau_f1=tau1, tau_f2=tau2, a1=a1, a2=a2)
    expect = 2 * math.pi * tau1 * a1 ** (-M) * beta ** (M + 2) * closed_moment(d, (M + 2) / 2)
    assert rel(res["F"], expect) < 1e-10


def test_hertz_friction_region3_split():
    # default Hurtado-Kim constants with beta so large that most contacts are in region 3:
    # F must lie between 2 pi tau2 beta^2 M1 and 2 pi tau1 beta^2 M1 and be continuous in d
    d = 0.5
    res = ref.separation_point(d, 0.01, 1e6, 0.0)
    m1 = closed_moment(d, 1) * 1e12
    assert 2 * math.pi * (1 / 43 / 30) * m1 < res["F"] < 2 * math.pi * (1 / 43) * m1


def test_hertz_load_point():
    alpha, beta = 0.01, 1000.0
    out = ref.load_point(250.0, alpha, beta)
    pref = (4.0 / 3.0) * (2.0 / 0.7) * alpha * beta**2
    assert rel(pref * closed_moment(out["d"], 1.5), 250.0) < 1e-10
    assert rel(out["area"], beta**2 * closed_moment(out["d"], 1)) < 1e-10


def test_hertz_has_no_pull_off():
    out = ref.pull_off(0.01, 1000.0, 0.0, d_max=3.0)
    assert out["pull_off"] == 0.0
    assert out["d"] == 3.0


# ---------------------------------------------------------------------------
# Maugis-Dugdale single asperity
# ---------------------------------------------------------------------------
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


@pytest.mark.parametrize("A", [0.7, 1.0, 2.0, 5.0])
def test_md_point_jkr_limit(A):
    delta = A * A - math.sqrt(8 * A / 3)
    P = A**3 - math.sqrt(6 * A**3)
    Am, Pm = ref.md_point(delta, 1e4)
    assert rel(Am, A) < 1e-8
    assert abs(Pm - P) < 1e-8


@pytest.mark.parametrize("A", [1.0, 2.0, 4.0])
def test_md_point_dmt_limit(A):
    # DMT: Delta = A^2, P = A^3 - 2; the MD curve approaches it like lambda^(1/2)
    errs = []
    for lam in (1e-4, 1e-6):
        Am, Pm = ref.md_point(A * A, lam)
        errs.append((abs(Am / A - 1), abs(Pm - (A**3 - 2))))
    assert errs[1][0] < 2e-3 and errs[1][1] < 1e-2
    assert errs[1][0] < 0.2 * errs[0][0] and errs[1][1] < 0.2 * errs[0][1]


@pytest.mark.parametrize("lam", [0.05, 0.5, 0.95, 3.0])
def test_md_point_inverts_explicit_curve(lam):
    # Eqs. 11-13 evaluated explicitly at m = sqrt(1 + t^2) on the stable branch
    A_end = ref.md_branch_end(lam)[0]
    for t in (1e-6, 1e-2, 0.3, 3.0):
        A, P, D = ref.md_curve(t, lam)
        if A <= 1.5 * A_end:
            continue
        Am, Pm = ref.md_point(D, lam)
        assert rel(Am, A) < 1e-11
        assert abs(Pm - P) <= 1e-11 * max(1.0, abs(P))


def test_md_curve_small_t_series():
    # near m -> 1 Eq. 11 reduces to (2/3) lam A^2 t^3 + (2/3) lam^2 A t^2 = 1 + O(t^4)
    lam, t = 0.7, 1e-7
    A, P, D = ref.md_curve(t, lam)
    lhs = (2 / 3) * lam * A**2 * t**3 + (2 / 3) * lam**2 * A * t**2
    assert abs(lhs - 1) < 1e-6


def test_md_pull_off_limits():
    assert abs(ref.md_pull_off(1e-8, "load") + 2.0) < 1e-8
    assert abs(ref.md_pull_off(1e4, "load") + 1.5) < 1e-7
    assert abs(ref.md_pull_off(1e4, "displacement") + 5 / 6) < 1e-7
    A_end, D_end, P_end = ref.md_branch_end(1e4)
    assert rel(A_end, 6 ** (-1 / 3)) < 1e-6
    assert abs(D_end - (A_end**2 - math.sqrt(8 * A_end / 3))) < 1e-6
    with pytest.raises(ValueError, match="control"):
        ref.md_pull_off(1.0, "force")


def test_lambda_c():
    assert abs(ref.md_lambda_c() - 0.93795) < 1e-4
    assert ref.md_branch_end(0.93)[0] == 0.0
    assert ref.md_branch_end(0.95)[0] > 0.0


def test_branch_end_below_lambda_c_closed_form():
    # A_M -> 0: x = A t solves (lam pi/4) x^2 + (4 lam^2/3)(pi/2-1) x = 1,
    # Delta_end = -(4/3) lam x, P_end = -(pi/2) lam x^2
    lam = 0.4
    c2, c1 = lam * math.pi / 4, 4 * lam**2 / 3 * (math.pi / 2 - 1)
    x = 2 / (c1 + math.sqrt(c1 * c1 + 4 * c2))
    A_end, D_end, P_end = ref.md_branch_end(lam)
    assert A_end == 0.0
    assert rel(D_end, -4 * lam * x / 3) < 1e-14
    assert rel(P_end, -math.pi * lam * x * x / 2) < 1e-14
    # the explicit curve approaches the end from above
    A, P, D = ref.md_curve(1e6, lam)
    assert D > D_end and D - D_end < 1e-9


def test_md_point_below_branch_end_raises():
    for lam in (0.3, 2.0):
        D_end = ref.md_branch_end(lam)[1]
        with pytest.raises(ValueError, match="below the end"):
            ref.md_point(D_end - 1e-6, lam)


# ---------------------------------------------------------------------------
# Adhesive multi-asperity quantities (closed-form pieces only)
# ---------------------------------------------------------------------------
@pytest.mark.parametrize("d", [0.5, -0.3])
def test_adhesive_contacts_is_gaussian_tail(d):
    alpha, beta, gamma = 0.01, 1000.0, 0.001
    f = ref.conversion_factors(alpha, beta, gamma)
    D_end = ref.md_branch_end(f["lambda"])[1]
    res = ref.separation_point(d, alpha, beta, gamma)
    z0 = d + f["delta_hat"] * D_end
    assert rel(res["contacts"], 0.5 * math.erfc(z0 / math.sqrt(2))) < 1e-10
    # adhesion enlarges contacts and area compared with Hertz
    hertz = ref.separation_point(d, alpha, beta, 0.0)
    assert res["area"] > hertz["area"] and res["P"] < hertz["P"]


# ---------------------------------------------------------------------------
# Validation
# ---------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("kwargs", "name"),
    [
        ({"alpha": 0.0}, "alpha"),
        ({"beta": -1.0}, "beta"),
        ({"gamma": -1e-3}, "gamma"),
        ({"nu": 0.5}, "nu"),
        ({"nu": -1.0}, "nu"),
        ({"alpha": math.nan}, "alpha"),
        ({"h_over_b": 0.0}, "h_over_b"),
    ],
)
def test_validation(kwargs, name):
    args = {"alpha": 0.01, "beta": 1000.0, "gamma": 0.0}
    args.update(kwargs)
    with pytest.raises(ValueError, match=name):
        ref.separation_point(0.0, **args)


def test_validation_d_and_load():
    with pytest.raises(ValueError, match="d"):
        ref.separation_point(math.inf, 0.01, 1000.0)
    with pytest.raises(ValueError, match="P"):
        ref.load_point(-1.0, 0.01, 1000.0, 0.0)


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
