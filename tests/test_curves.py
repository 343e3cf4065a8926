"""Curves, pull-off and the paper's published numbers (Table 1, Fig 7)."""

import io

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import asperity

TABLE1 = [  # alpha, beta, gamma, printed |P|/(N G b^2)
    (0.002, 1000, 0.001, 2158.1), (0.003, 1000, 0.001, 320.1), (0.004, 1000, 0.001, 26.7),
    (0.005, 1000, 0.001, 1.0), (0.01, 100, 0.001, 2.9), (0.01, 300, 0.001, 0.005),
    (0.01, 1000, 0.005, 9.5), (0.01, 1000, 0.007, 81.2), (0.01, 1000, 0.010, 2480.8),
]


@pytest.mark.parametrize("row", TABLE1[:2])
def test_table1_first_rows_match_the_paper(row):
    alpha, beta, gamma, printed = row
    assert asperity.pull_off(alpha, beta, gamma).force == pytest.approx(printed, rel=0.05)


def test_table1_trends():
    forces = [asperity.pull_off(a, b, g).force for a, b, g, _ in TABLE1]
    assert all(f > 0 for f in forces)
    # "low alpha and high gamma increase the pull-off force dramatically"
    assert forces[0] > forces[1] > forces[2] > forces[3]
    assert forces[6] < forces[7] < forces[8]
    assert forces[0] / forces[3] > 100 and forces[8] / forces[6] > 10


def test_fig7_force_changes_sign_near_2_6():
    # Paper: for alpha 0.005, beta 1000, gamma 0.001 the force vanishes near d/sigma = 2.6.
    c = asperity.separation_curve(np.linspace(2.0, 3.2, 121), 0.005, 1000, 1e-3)
    crossing = c.d[np.flatnonzero(np.diff(np.sign(c.P)))[0]]
    assert 2.4 < crossing < 2.8


def test_pull_off_is_a_minimum_of_the_force():
    po = asperity.pull_off(0.004, 1000, 1e-3)
    d = po.d + np.array([-1e-3, 0.0, 1e-3])
    P = asperity.separation_curve(d, 0.004, 1000, 1e-3).P
    assert P[1] == pytest.approx(-po.force, rel=1e-12)
    assert P[1] < P[0] and P[1] < P[2]


def test_no_pull_off_without_adhesion():
    po = asperity.pull_off(0.01, 1000, 0.0)
    assert po.force == 0.0 and not po.exists and np.isnan(po.d)


@pytest.mark.parametrize("gamma", [0.0, 1e-3])
def test_load_curve_inverts_separation_curve(gamma):
    P = np.logspace(-2, 5, 200)
    lc = asperity.load_curve(P, 0.01, 1000, gamma)
    sc = asperity.separation_curve(lc.d, 0.01, 1000, gamma)
    np.testing.assert_allclose(sc.P, P, rtol=1e-10)
    for k in ("F", "area", "contacts", "mu", "pressure"):
        np.testing.assert_allclose(getattr(lc, k), getattr(sc, k), rtol=1e-10)
    assert np.all(np.diff(lc.d) < 0)  # more load, closer surfaces


def test_load_curve_tensile_loads_on_the_stable_branch():
    po = asperity.pull_off(0.003, 1000, 1e-3)
    P = np.array([-0.999 * po.force, -0.5 * po.force, 0.0, 10.0])
    lc = asperity.load_curve(P, 0.003, 1000, 1e-3)
    assert np.all(lc.d <= po.d + 1e-12)
    sc = asperity.separation_curve(lc.d, 0.003, 1000, 1e-3)
    np.testing.assert_allclose(sc.P, P, rtol=1e-9, atol=1e-9 * po.force)
    assert np.isnan(lc.mu[:3]).all() and lc.F[2] > 0  # finite friction at zero load
    with pytest.raises(ValueError, match="P"):
        asperity.load_curve([-1.01 * po.force], 0.003, 1000, 1e-3)


def test_large_loads():
    lc = asperity.load_curve([1e8], 0.01, 100, 0.0)
    assert lc.d[0] < -10
    assert asperity.separation_curve(lc.d, 0.01, 100).P[0] == pytest.approx(1e8, rel=1e-10)


def test_friction_coefficient_falls_with_load_and_rises_with_adhesion():
    P = np.logspace(0, 5, 20)
    dry = asperity.load_curve(P, 0.01, 1000, 0.0)
    wet = asperity.load_curve(P, 0.01, 1000, 1e-3)
    assert np.all(np.diff(dry.mu) < 0) and np.all(np.diff(wet.mu) < 0)
    assert np.all(wet.mu > dry.mu)


def test_result_object_conversions():
    c = asperity.separation_curve([0.0, 1.0], 0.01, 1000, 1e-3)
    frame = c.to_dataframe()
    assert list(frame.columns) == ["d", "P", "F", "mu", "area", "pressure", "contacts"]
    assert len(c) == 2 and frame.attrs["gamma"] == 1e-3
    text = c.to_csv()
    import pandas as pd
    back = pd.read_csv(io.StringIO(text))
    np.testing.assert_array_equal(back["P"].to_numpy(), c.P)
    buf = io.StringIO()
    c.to_csv(buf)
    assert buf.getvalue() == text


def test_model_reuses_its_tabulation():
    m = asperity.Model(0.01, 1000, 1e-3)
    a = m.load_curve([1.0, 2.0])
    tab = m._tab
    b = m.load_curve([1.0, 2.0])
    assert m._tab is tab
    np.testing.assert_array_equal(a.d, b.d)


BAD = [
    (dict(alpha=0.0), "alpha"), (dict(alpha=-1.0), "alpha"), (dict(beta=np.nan), "beta"),
    (dict(gamma=-1e-3), "gamma"), (dict(nu=0.5), "nu"), (dict(nu=-1.0), "nu"),
    (dict(h_over_b=0.0), "h_over_b"), (dict(beta=np.inf), "beta"),
    (dict(alpha=[0.1, 0.2]), "alpha"),
]


@pytest.mark.parametrize("kwargs, name", BAD)
def test_bad_parameters(kwargs, name):
    args = dict(alpha=0.01, beta=1000.0, gamma=1e-3)
    args.update(kwargs)
    for call in (lambda: asperity.separation_curve([0.0], **args),
                 lambda: asperity.load_curve([1.0], **args)):
        with pytest.raises(ValueError, match=name):
            call()


@pytest.mark.parametrize("d", [[], [np.nan], [np.inf], [100.0], "abc"])
def test_bad_separations(d):
    with pytest.raises(ValueError, match="d"):
        asperity.separation_curve(d, 0.01, 1000)


@pytest.mark.parametrize("P", [[], [np.nan], [0.0], [-1.0]])
def test_bad_loads_without_adhesion(P):
    with pytest.raises(ValueError, match="P"):
        asperity.load_curve(P, 0.01, 1000)


def test_bad_d_max():
    with pytest.raises(ValueError, match="d_max"):
        asperity.pull_off(0.01, 1000, 1e-3, d_max=-1)


@settings(max_examples=25)
@given(st.floats(1e-3, 0.3), st.floats(10.0, 1e6), st.one_of(st.just(0.0), st.floats(1e-6, 5e-2)),
       st.floats(-2.0, 6.0))
def test_load_curve_inverts_at_random_parameters(alpha, beta, gamma, log_load):
    P = 10.0**log_load * np.array([1.0, 3.0])
    # Hertz needs d ~ -(P / (3.8 alpha beta^2))^(2/3): stay well inside d >= D_MIN = -1e4.
    assume(P.max() <= 1e4 * alpha * beta**2)
    lc = asperity.load_curve(P, alpha, beta, gamma)
    sc = asperity.separation_curve(lc.d, alpha, beta, gamma)
    # With strong adhesion a small load is a difference of large compressive and tensile
    # parts: compare on the compressive (Hertz) scale at the same separation.
    scale = asperity.separation_curve(lc.d, alpha, beta, 0.0).P
    np.testing.assert_allclose(sc.P, P, rtol=1e-9, atol=1e-10 * scale.max())
    np.testing.assert_allclose(sc.F, lc.F, rtol=1e-9)
    assert lc.d[1] < lc.d[0]


def test_no_pull_off_zero_load_has_no_equilibrium():
    m = asperity.Model(0.1, 1000, 1e-3)
    assert not m.pull_off().exists
    with pytest.raises(ValueError, match="P"):
        m.load_curve([0.0, 1.0])
    lc = m.load_curve([1e-30, 1.0])  # tiny but positive: the flat far out
    np.testing.assert_allclose(m.separation_curve(lc.d).P, [1e-30, 1.0], rtol=1e-9)


def test_pull_off_beyond_ten_sigma_for_a_long_adhesive_range():
    # delta_hat ~ 38: asperities stay in adhesive contact ~34 sigma below their tops.
    po = asperity.pull_off(1e-3, 10, 1e-3)
    assert po.exists and po.d > 10
    d = np.linspace(-3, asperity.Model(1e-3, 10, 1e-3).d_search, 3001)
    scan = asperity.separation_curve(d, 1e-3, 10, 1e-3).P
    assert po.force == pytest.approx(-scan.min(), rel=1e-6)
    lc = asperity.load_curve([-0.98 * po.force], 1e-3, 10, 1e-3)
    assert 10 < lc.d[0] < po.d


def test_results_do_not_depend_on_call_history():
    m = asperity.Model(0.01, 1000, 1e-3)
    first = m.separation_curve([9.0])
    m.separation_curve([-3.0])
    again = m.separation_curve([9.0])
    for key in ("P", "F", "area", "contacts"):
        assert getattr(again, key)[0] == pytest.approx(getattr(first, key)[0], rel=1e-12)
    from scipy.special import ndtr
    assert asperity.separation_curve([9.0], 0.01, 1000).contacts[0] == pytest.approx(ndtr(-9.0), rel=1e-12)


@pytest.mark.parametrize("kwargs, needle", [
    (dict(alpha=True, beta=10.0), "boolean"),
    (dict(alpha=1e300, beta=10.0, gamma=1e-3), "alpha"),
    (dict(alpha=0.01, beta=1e-300, gamma=1e-3), "beta"),
    (dict(alpha=0.01, beta=1000.0, gamma=1e-200), "lambda"),
    (dict(alpha=0.01, beta=1000.0, gamma=1e-3, h_over_b=1e-300), "lambda"),
    (dict(alpha=1e-7, beta=10.0, gamma=0.05), "adhesive contact"),
])
def test_out_of_range_parameter_combinations(kwargs, needle):
    with pytest.raises(ValueError, match=needle):
        asperity.separation_curve([0.0], **kwargs)


def test_vanishing_load_gives_infinite_mu_without_warnings():
    c = asperity.load_curve([5e-324, 1.0], 0.01, 1000, 1e-3)
    assert np.isinf(c.mu[0]) and np.isfinite(c.mu[1])


def test_model_delegates_to_load_control(monkeypatch):
    # Model is a cache: the algorithms are asperity.load_control's, called with its tabulation.
    from asperity import curves, load_control

    calls = []

    def spy(name):
        real = getattr(load_control, name)

        def wrapper(*args, **kwargs):
            calls.append(name)
            return real(*args, **kwargs)
        monkeypatch.setattr(curves, name, wrapper)

    for name in ("start_separation", "bracket_low", "stable_branch", "invert_branch", "find_pull_off"):
        spy(name)
    m = asperity.Model(0.003, 1000, 1e-3)
    lc = m.load_curve([1.0, 10.0])
    assert calls == ["start_separation", "stable_branch", "invert_branch"]  # the Hertz estimate sufficed
    calls.clear()
    po = m.pull_off()  # found on the load curve's grid, cached
    assert calls == [] and po.exists
    tab = m.tabulation(-3.0, m.d_search)
    branch = load_control.stable_branch(tab, float(lc.d.min()) - 1.0, m.d_search)
    np.testing.assert_allclose(branch.tab.sums(lc.d)[0][:, 1], [1.0, 10.0], rtol=1e-10)
    assert m.pull_off(5.0).exists and calls == ["find_pull_off"]


def test_model_steps_down_when_the_start_separation_falls_short(monkeypatch):
    # A start separation carrying less than the largest load: bracket_low steps down, same curve.
    from asperity import curves

    loads = [1.0, 1e5]
    want = asperity.Model(0.003, 1000, 1e-3).load_curve(loads)
    calls = []
    real = curves.bracket_low

    def spy(*args):
        calls.append(args[2])
        return real(*args)
    monkeypatch.setattr(curves, "start_separation", lambda *args: -3.0)
    monkeypatch.setattr(curves, "bracket_low", spy)
    got = asperity.Model(0.003, 1000, 1e-3).load_curve(loads)
    assert calls == [-5.0]  # one step below -3, where the force at -3 fell short of 1e5
    np.testing.assert_allclose(got.d, want.d, rtol=1e-12)
    np.testing.assert_allclose(got.F, want.F, rtol=1e-10)


def test_pull_off_to_dict():
    d = asperity.pull_off(0.01, 1000, 0.0).to_dict()
    assert d == {"pull_off": 0.0, "d": None, "exists": False}
    po = asperity.pull_off(0.003, 1000, 1e-3)
    assert po.as_dict() == po.to_dict() and po.to_dict()["d"] == po.d


def test_more_points_than_max_points_are_refused_at_once():
    """A review: 1e7 loads ran for 146 s and 3.6 GB; the command line refused them already."""
    import time

    from asperity.curves import MAX_POINTS, Model

    m = Model(0.05, 1000.0, 1e-3)
    start = time.perf_counter()
    with pytest.raises(ValueError, match=r"P must hold at most 1000000 values \(MAX_POINTS\), got 1000001"):
        m.load_curve(np.linspace(1.0, 10.0, MAX_POINTS + 1))
    with pytest.raises(ValueError, match=r"d must hold at most 1000000 values"):
        m.separation_curve(np.linspace(0.0, 5.0, MAX_POINTS + 1))
    assert time.perf_counter() - start < 30.0  # refused, not computed
