"""FitResult and Comparison: the JSON object of the issue, tables, the curve, the figure."""

import json
import math

import numpy as np
import pytest

import asperity
from asperity.fit import FitResult, compare_models, fit_friction_load, friction_load_data
from asperity.fit.models import FitCurve

from ..cli.helpers import strict_json

P = np.linspace(0.5, 5.0, 12)
NOISY = friction_load_data(P, 0.3 * (P + 1.0) * (1 + 0.02 * np.random.default_rng(1).standard_normal(12)))


@pytest.fixture(scope="module")
def result():
    return fit_friction_load(NOISY, "amontons")


def test_to_dict_is_exactly_the_issue_object(result):
    d = result.to_dict()
    assert list(d) == ["model", "parameters", "chisqr", "aic", "bic", "n_points", "warnings"]
    assert d["model"] == "amontons" and d["n_points"] == 12 and d["warnings"] == []
    for name, p in d["parameters"].items():
        assert list(p) == ["value", "stderr", "ci95", "vary"], name
        assert len(p["ci95"]) == 2 and p["ci95"][0] < p["value"] < p["ci95"][1]
    assert strict_json(json.dumps(d)) == d


def test_non_finite_becomes_null():
    res = fit_friction_load(friction_load_data([1.0, 2.0], [0.6, 0.9]), "amontons", weights="none")
    assert res.n_free == res.n_points == 2
    assert any("no degrees of freedom" in w for w in res.warnings)
    text = json.dumps(res.to_dict(), allow_nan=False)  # would raise on NaN or inf
    assert strict_json(text)["parameters"]["mu0"]["value"] == pytest.approx(0.3)


def test_frozen_and_tables(result):
    assert isinstance(result, FitResult)
    with pytest.raises(AttributeError):
        result.chisqr = 0.0
    assert result.rows()[0]["name"] == "mu0" and set(result.columns()) >= {"value", "stderr", "ci95_lo", "method"}
    assert result.to_csv().splitlines()[0].startswith("name,value,stderr,ci95_lo,ci95_hi,vary")
    assert "mu0" in result.summary() and "AIC" in result.summary()
    assert result.redchi == pytest.approx(result.chisqr / (12 - 2))
    assert result.aic == pytest.approx(12 * math.log(result.chisqr / 12) + 2 * 2)
    assert result.bic == pytest.approx(12 * math.log(result.chisqr / 12) + math.log(12) * 2)
    assert result.residuals.shape == (12,) and result.nfev > 0 and result.model_evaluations > 0
    np.testing.assert_allclose(result.fitted[0], result.values["mu0"] * (P + result.values["P0"]), rtol=1e-12)
    # relative weights from the model at the fit (iteratively reweighted, to 1e-6)
    np.testing.assert_allclose(result.residuals, (result.fitted[0] - NOISY.y) / np.abs(result.fitted[0]), rtol=1e-5)


def test_curve_on_a_fine_grid(result):
    assert isinstance(result.curve, FitCurve) and len(result.curve) == 200
    cols = result.curve.columns()
    assert list(cols) == ["P", "F", "mu"] and cols["P"][0] == P[0] and cols["P"][-1] == P[-1]
    np.testing.assert_allclose(cols["F"], result.values["mu0"] * (cols["P"] + result.values["P0"]), rtol=1e-12)
    assert result.curve.to_csv().startswith("P,F,mu\n")
    Pg = np.geomspace(1.0, 1e4, 20)
    gw = fit_friction_load(friction_load_data(Pg, asperity.load_curve(Pg, 0.01, 1000.0, 1e-3).F), "gw",
                           vary=["gamma"], start={"gamma": 2e-3}, ci="wald")
    assert isinstance(gw.curve, asperity.CurveResult) and gw.curve.P[0] == pytest.approx(1.0)
    assert np.all(np.diff(np.log(gw.curve.P)) == pytest.approx(np.log(1e4) / 199))  # log-spaced


def test_plot(result, tmp_path):
    pytest.importorskip("matplotlib")
    fig = result.plot(tmp_path / "fit.png")
    assert (tmp_path / "fit.png").read_bytes()[:4] == b"\x89PNG"
    assert len(fig.axes) == 2 and fig.axes[1].get_ylabel() == "residual (relative)"
    result.plot(tmp_path / "fit.svg")
    assert (tmp_path / "fit.svg").read_text().lstrip().startswith("<?xml")


def test_comparison_table():
    table = compare_models(NOISY, ["cos", "amontons"])
    rows = table.rows()
    assert [r["model"] for r in rows] == [r.model for r in table.results]
    assert rows[0]["aic"] <= rows[1]["aic"] and rows[0]["delta_aic"] == 0.0
    assert sum(r["akaike_weight"] for r in rows) == pytest.approx(1.0)
    assert rows[1]["akaike_weight"] == pytest.approx(math.exp(-rows[1]["delta_aic"] / 2) /
                                                     (1 + math.exp(-rows[1]["delta_aic"] / 2)))
    assert [d["model"] for d in table.to_list()] == [r["model"] for r in rows]
    assert table.to_csv().startswith("model,n_free,chisqr")
    assert "dAIC" in table.summary() and len(table) == 2 and table.best is table.results[0]


def test_physical_axes_carry_the_si_prefix_of_the_data():
    """Found by a review: AFM data in nN were drawn as 'load (N)' with a 1e-8 offset; the
    axes now scale to the data's prefix, the points at their values in it."""
    pytest.importorskip("matplotlib")
    P = np.linspace(1e-9, 5e-8, 12)
    data = friction_load_data(P, 0.3 * P + 2e-9, physical=True)
    fig = fit_friction_load(data, "amontons", ci="wald").plot()
    top, bottom = fig.axes[0], fig.axes[1]
    assert top.get_ylabel() == "friction (nN)" and bottom.get_xlabel() == "load (nN)"
    points = np.asarray(top.containers[0].lines[0].get_xdata())  # the errorbar's markers
    np.testing.assert_allclose(points, P * 1e9, rtol=1e-12)
