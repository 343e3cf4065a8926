"""asperity.reference.multi_asperity against closed forms: parabolic-cylinder GW moments, Hertz,
Hurtado-Kim regions, the Gaussian tail of the contact fraction, validation.

Nothing here compares with the fast path: every expected value is a closed form.
"""

import math

import mpmath
import pytest

from asperity.reference import groups, maugis_dugdale_branch
from asperity.reference import multi_asperity as ref
from asperity.reference.gw_moment import gw_moment


def closed_moment(d, k):
    """int_d^inf (z-d)^k phi(z) dz = Gamma(k+1) exp(-d^2/4) D_{-k-1}(d) / sqrt(2 pi)."""
    with mpmath.workdps(40):
        d = mpmath.mpf(d)
        val = mpmath.gamma(k + 1) * mpmath.exp(-d * d / 4) * mpmath.pcfd(-k - 1, d) / mpmath.sqrt(2 * mpmath.pi)
        return float(val)


def rel(a, b):
    return abs(a - b) / abs(b)


@pytest.mark.parametrize("k", [0, 1, 1.5])
@pytest.mark.parametrize("d", [-3.0, -0.7, 0.0, 0.4, 2.0, 6.5])
def test_gw_moment_parabolic_cylinder(d, k):
    assert rel(gw_moment(d, k), closed_moment(d, k)) < 1e-13


def test_gw_moment_gaussian_tail():
    # order 0 is the normal upper tail
    for d in (-1.0, 0.5, 3.0):
        assert rel(gw_moment(d, 0), 0.5 * math.erfc(d / math.sqrt(2))) < 1e-14


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


@pytest.mark.parametrize("d", [0.5, -0.3])
def test_adhesive_contacts_is_gaussian_tail(d):
    alpha, beta, gamma = 0.01, 1000.0, 0.001
    f = groups.conversion_factors(alpha, beta, gamma)
    D_end = maugis_dugdale_branch.md_branch_end(f["lambda"])[1]
    res = ref.separation_point(d, alpha, beta, gamma)
    z0 = d + f["delta_hat"] * D_end
    assert rel(res["contacts"], 0.5 * math.erfc(z0 / math.sqrt(2))) < 1e-10
    # adhesion enlarges contacts and area compared with Hertz
    hertz = ref.separation_point(d, alpha, beta, 0.0)
    assert res["area"] > hertz["area"] and res["P"] < hertz["P"]


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
