"""The fit panel: a friction-load file fitted from the view's parameters, as asperity.fit does it."""

import base64

import numpy as np
import pytest

pytest.importorskip("bokeh")
pytest.importorskip("lmfit")

from bokeh.document import Document  # noqa: E402

import asperity  # noqa: E402
from asperity.explorer.app import ExplorerSession, immediate_runner  # noqa: E402
from asperity.explorer.fit_panel import FIT_VARY, PLASTIC_VARY, FitPanel  # noqa: E402
from asperity.fit import fit_friction_load, read_data  # noqa: E402

TRUTH = {"alpha": 0.01, "beta": 1000.0, "gamma": 1e-3}


def friction_csv(tmp_path, noise=0.02, seed=0):
    """Friction F against load P (dimensionless) from the model at TRUTH, with stated 2 % errors."""
    P = np.geomspace(1.0, 1e4, 25)
    F = asperity.Model(**TRUTH).load_curve(P).F
    F_noisy = F * (1 + noise * np.random.default_rng(seed).standard_normal(P.size))
    path = tmp_path / "friction.csv"
    rows = (f"{p!r},{f!r},{noise * f!r}\n" for p, f in zip(P.tolist(), F_noisy.tolist(), strict=True))
    path.write_text("P,F,F_err\n" + "".join(rows))
    return path


def fit_of(session) -> FitPanel:
    return next(p for p in session.panels if isinstance(p, FitPanel))


def upload(panel, path):
    panel.read_upload(base64.b64encode(path.read_bytes()).decode(), path.name)


def panel_with(query, path):
    """A page for ``query`` with the fit panel on and the file at ``path`` uploaded: (session, panel)."""
    s = ExplorerSession(Document(), query, runner=immediate_runner)
    panel = fit_of(s)
    panel.toggle.active = True
    upload(panel, path)
    return s, panel


def test_the_panel_fits_what_asperity_fit_fits_from_the_view(tmp_path):
    path = friction_csv(tmp_path)
    s = ExplorerSession(Document(), "n=30&alpha=0.02&beta=800&gamma=0.002&nu=0.25", runner=immediate_runner)
    panel = fit_of(s)
    assert panel.figure not in panel.layout.children and panel.run_button.disabled
    panel.toggle.active = True
    upload(panel, path)
    assert "25 points read" in panel.info.text and not panel.run_button.disabled
    np.testing.assert_array_equal(panel.points.data["P"], read_data(str(path), kind="friction").x)
    # the view's curve at the data's loads, beside the data
    np.testing.assert_allclose(panel.view_curve.data["F"], s.result.subject.load_curve(panel.points.data["P"]).F)
    r = panel.run_fit()
    ref = fit_friction_load(str(path), "gw", start={"alpha": 0.02, "beta": 800.0, "gamma": 0.002},
                            fix={"nu": 0.25, "h_over_b": 1.0, "tau_f1": asperity.HurtadoKim().tau_f1,
                                 "tau_f2": asperity.HurtadoKim().tau_f2, "a1": 28.0, "a2": 8e4}, vary=FIT_VARY)
    for name in FIT_VARY:
        assert r.values[name] == pytest.approx(ref.values[name], rel=1e-9)
    assert r.values["nu"] == 0.25  # the view's other parameters stay fixed
    np.testing.assert_allclose(panel.curve.data["F"], ref.curve.F, rtol=1e-9)
    assert "alpha" in panel.info.text and "95 % interval" in panel.info.text
    # a good fit of data with stated 2 % errors: chi-square near the degrees of freedom (22), and
    # far below that of the view it started from
    assert r.chisqr < 2.0 * (r.n_points - 3)
    start = asperity.Model(0.02, 800.0, 0.002, nu=0.25).load_curve(panel.points.data["P"]).F
    F, err = panel.points.data["F"], panel.points.data["F_err"]
    assert r.chisqr < 0.01 * float(np.sum(((start - F) / err) ** 2))
    panel.use_fitted()  # the view takes the fitted values
    for name in FIT_VARY:
        assert s.good[name] == pytest.approx(r.values[name], rel=1e-12)
    assert f"alpha={r.values['alpha']:.6g}"[:12] in s.page.query


@pytest.mark.parametrize("content, needle", [
    (b"P,F\n1,2\n", "at least"),                       # too few points for a fit
    (b"\xff\xfe\x00garbage", "not a text file"),
    (b"load [nN],friction [nN]\n1,2\n2,3\n3,4\n4,5\n5,6\n", "physical data"),
])
def test_bad_files_are_messages(tmp_path, content, needle):
    path = tmp_path / "bad.csv"
    path.write_bytes(content)
    _, panel = panel_with("n=20", path)
    assert needle in panel.info.text and panel.data is None and panel.run_button.disabled
    assert "/tmp" not in panel.info.text and "bad.csv" in panel.info.text  # the user's file, no server paths


def test_the_views_summit_heights_are_fitted_with(tmp_path):
    from asperity.fit.gw import GWFit
    from asperity.heights import Exponential

    path = friction_csv(tmp_path)
    _, panel = panel_with("n=20&heights=exponential&alpha=0.02", path)
    r = panel.run_fit()
    ref = fit_friction_load(str(path), GWFit(heights=Exponential()), start={"alpha": 0.02, "beta": 1000.0,
                                                                           "gamma": 1e-3}, vary=FIT_VARY)
    assert r.model == ref.model == "gw (heights exponential)"
    for name in FIT_VARY:
        assert r.values[name] == pytest.approx(ref.values[name], rel=1e-9)


def test_physical_mode_does_not_fit(tmp_path):
    s, panel = panel_with("n=20", friction_csv(tmp_path))
    s.on_value("mode", "physical")
    assert panel.run_button.disabled and "dimensionless" in panel.info.text


def test_messages_name_the_users_file_escaped(tmp_path):
    """Found by a review: names with HTML or backslashes were mangled to their last characters."""
    path = friction_csv(tmp_path)
    s = ExplorerSession(Document(), "n=20", runner=immediate_runner)
    panel = fit_of(s)
    panel.toggle.active = True
    panel.read_upload(base64.b64encode(path.read_bytes()).decode(), "<b>run 2</b>.csv")
    assert panel.info.text.startswith("&lt;b&gt;run 2&lt;/b&gt;.csv: 25 points read")
    panel.read_upload(base64.b64encode(b"P,F\n1,2\n").decode(), r"C:\Users\me\data.csv")
    assert panel.info.text.startswith(r"C:\Users\me\data.csv: 1 points")


def test_a_plastic_view_fits_alpha_beta_and_the_hardness(tmp_path):
    """With the Jackson-Green law the panel fits alpha, beta and H/E* of GWFit(law=the view's law)
    (no gamma), h*/sigma and the rest held, exactly as fit_friction_load; the fitted values go
    back into the view."""
    from asperity.elastic_plastic import JacksonGreen
    from asperity.fit.gw import GWFit

    P = np.geomspace(1.0, 1e4, 25)
    F = asperity.Model(0.05, 1000.0, law=JacksonGreen(0.004, 1.0)).load_curve(P).F
    F = F * (1 + 0.02 * np.random.default_rng(4).standard_normal(P.size))
    path = tmp_path / "plastic.csv"
    rows = zip(P.tolist(), F.tolist(), strict=True)
    path.write_text("P,F,F_err\n" + "".join(f"{p!r},{f!r},{0.02 * f!r}\n" for p, f in rows))
    s, panel = panel_with("n=20&gamma=0&law=jackson-green&alpha=0.04&H_over_E=0.006&h_star_over_sigma=1", path)
    r = panel.run_fit()
    ref = fit_friction_load(str(path), GWFit(law=JacksonGreen(0.006, 1.0)), vary=PLASTIC_VARY,
                            start={"alpha": 0.04, "beta": 1000.0, "H_over_E": 0.006},
                            fix={"h_star_over_sigma": 1.0, "nu": 0.3, "h_over_b": 1.0}, ci="wald")
    assert r.model == ref.model == "gw (jackson-green H/E*=0.006 h*/sigma=1)" and "gamma" not in r.values
    for name in PLASTIC_VARY:
        assert r.values[name] == pytest.approx(ref.values[name], rel=1e-9)
        assert name in panel.info.text
    panel.use_fitted()
    assert s.pending["H_over_E"] == r.values["H_over_E"] and s.pending["alpha"] == r.values["alpha"]
