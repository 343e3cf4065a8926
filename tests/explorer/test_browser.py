"""End to end in real headless Chromium (Debian's /usr/bin/chromium, driven by Playwright).

One ``asperity explore --port 0 --no-browser`` and one browser serve the module.  The
plotted data are read from the page's Bokeh data sources and compared with the library,
called here with the parameters the page's address holds.  Every request and websocket
the page opens is recorded; any that leaves 127.0.0.1/localhost fails the test.  Without
a browser (or Playwright) the tests skip, unless ASPERITY_REQUIRE_BROWSER=1.
"""

import importlib.util
from urllib.parse import parse_qs

import numpy as np
import pytest

from .browser import (
    ExplorerProcess,
    Network,
    changes,
    need_browser,
    open_browser,
    query_of,
    slider_handle,
    source_data,
    type_into,
    wait_changes,
    wait_ready,
    watch_source,
)

COLUMNS = ("d", "P", "F", "mu", "area", "pressure", "contacts")


@pytest.fixture(scope="module")
def server():
    need_browser()
    process = ExplorerProcess()
    yield process
    code, _, err = process.stop()
    assert code == 0, err


@pytest.fixture(scope="module")
def context(server):
    with open_browser() as ctx:
        yield ctx


@pytest.fixture()
def page(context, server):
    page = context.new_page()
    network = Network(page)
    page.network = network
    yield page
    page.close()
    assert network.urls, "the page made no request"
    assert any(u.startswith("ws://127.0.0.1") for u in network.urls), network.urls
    assert network.foreign() == [], f"requests leaving this machine: {network.foreign()}"


def load(page, url):
    page.goto(url)
    wait_ready(page)
    watch_source(page)


def params(page) -> dict:
    """The view's numbers, read from the page's address (the URL holds every parameter)."""
    return {k: v[-1] for k, v in parse_qs(query_of(page)).items()}


def library_curves(p: dict):
    """The library's load and separation curves for a dimensionless view, built from the numbers alone."""
    import asperity

    n = int(p["n"])
    model = asperity.Model(float(p["alpha"]), float(p["beta"]), float(p["gamma"]), nu=float(p["nu"]),
                           h_over_b=float(p["h_over_b"]),
                           friction=asperity.HurtadoKim(float(p["tau_f1"]), float(p["tau_f2"]), float(p["a1"]),
                                                        float(p["a2"])))
    return (model.load_curve(np.geomspace(float(p["P_min"]), float(p["P_max"]), n)),
            model.separation_curve(np.linspace(float(p["d_min"]), float(p["d_max"]), n)), model.pull_off())


def assert_plotted(page, load, separation):
    shown_load, shown_sep = source_data(page, "load"), source_data(page, "separation")
    for name in COLUMNS:
        np.testing.assert_allclose(shown_load[name], getattr(load, name), rtol=1e-12, equal_nan=True, err_msg=name)
        np.testing.assert_allclose(shown_sep[name], getattr(separation, name), rtol=1e-12, equal_nan=True,
                                   err_msg=name)


def test_page_shows_the_library_and_its_state_in_the_url(page, server):
    load(page, server.url)
    p = params(page)
    assert p["mode"] == "dimensionless" and p["alpha"] == "0.003" and int(p["n"]) == 200
    curve, sep, po = library_curves(p)
    assert_plotted(page, curve, sep)
    assert source_data(page, "pull_off")["force"] == pytest.approx([po.force], rel=1e-12)
    page.locator(".asp-derived table").get_by_text("Maugis-Dugdale").wait_for()


def test_slider_move_and_typed_value(page, server):
    load(page, server.url)
    before = params(page)["alpha"]
    handle = slider_handle(page, "alpha")
    handle.focus()
    page.keyboard.press("ArrowRight")
    wait_changes(page, 1)
    page.wait_for_function(f"() => !window.location.search.includes('alpha={before}&')")
    p = params(page)
    assert float(p["alpha"]) > float(before)
    assert page.locator(".asp-input-alpha input").input_value() == p["alpha"]
    assert_plotted(page, *library_curves(p)[:2])
    type_into(page, "beta", "2500")
    wait_changes(page, 2)
    page.wait_for_function("() => window.location.search.includes('beta=2500&')")
    p = params(page)
    assert p["beta"] == "2500"
    assert_plotted(page, *library_curves(p)[:2])


def test_link_sets_the_view(page, server):
    import asperity
    from asperity.physical import PhysicalContact
    from asperity.surface import Surface

    load(page, server.url + "?mode=physical&material=Si&sigma_s_m=3e-9&R_m=2e-6&P_max_N=5&n=50&d_max=3")
    assert page.locator(".asp-input-mode .bk-active").inner_text() == "physical"
    assert page.locator(".asp-input-material select").input_value() == "Si"
    assert page.locator(".asp-input-sigma_s_m input").input_value() == "3e-9"
    p = params(page)
    assert (p["mode"], p["material"], p["sigma_s_m"], p["n"]) == ("physical", "Si", "3e-9", "50")
    contact = PhysicalContact("Si", Surface(3e-9, 2e-6, float(p["eta_per_m2"]), float(p["area_m2"])),
                              friction=asperity.HurtadoKim())
    curve = contact.load_curve(np.geomspace(float(p["P_min_N"]), 5.0, 50))
    sep = contact.separation_curve(np.linspace(float(p["d_min"]), 3.0, 50) * 3e-9)
    assert_plotted(page, curve, sep)
    assert " N at d = " in page.locator(".asp-derived table").inner_text()


def test_elastic_plastic_link_and_law_menu(page, server):
    """A link with the Jackson-Green law draws the library's curves with that law; choosing the
    elastic law in the page hides the law's parameters and drops them from the address."""
    import asperity
    from asperity.elastic_plastic import JacksonGreen

    load(page, server.url + "?gamma=0&law=jackson-green&H_over_E=0.005&h_star_over_sigma=2&n=40")
    assert page.locator(".asp-input-law select").input_value() == "jackson-green"
    assert page.locator(".asp-input-H_over_E input").is_visible()
    p = params(page)
    model = asperity.Model(float(p["alpha"]), float(p["beta"]), 0.0, nu=float(p["nu"]),
                           h_over_b=float(p["h_over_b"]),
                           friction=asperity.HurtadoKim(float(p["tau_f1"]), float(p["tau_f2"]), float(p["a1"]),
                                                        float(p["a2"])),
                           law=JacksonGreen(float(p["H_over_E"]), float(p["h_star_over_sigma"])))
    n = int(p["n"])
    assert_plotted(page, model.load_curve(np.geomspace(float(p["P_min"]), float(p["P_max"]), n)),
                   model.separation_curve(np.linspace(float(p["d_min"]), float(p["d_max"]), n)))
    page.locator(".asp-input-law select").select_option("elastic")
    wait_changes(page, 1)
    page.wait_for_function("() => window.location.search.includes('law=elastic')")
    assert "H_over_E" not in params(page) and not page.locator(".asp-input-H_over_E input").is_visible()
    assert_plotted(page, *library_curves(params(page))[:2])


def test_invalid_value_shows_the_message_and_keeps_the_view(page, server):
    load(page, server.url)
    url, before = page.url, source_data(page, "load")
    type_into(page, "alpha", "-1")
    messages = page.locator(".asp-messages")  # the text shown (in the Div's shadow DOM)
    messages.locator(".error").get_by_text("alpha must be > 0").wait_for()
    assert "last valid parameters" in messages.locator(".note").inner_text()
    type_into(page, "beta", "many")
    messages.locator(".error").get_by_text("beta: expected a number, got 'many'").wait_for()
    page.wait_for_timeout(300)
    assert page.url == url and changes(page) == 0
    assert source_data(page, "load") == before


def test_messages_box_grows_and_keeps_its_text(page, server):
    # the box's height follows its messages; BokehJS renders a Div whose height changed again
    # with its own (empty) text, so the messages must be written again after that
    load(page, server.url + "?mode=physical&P_max_N=3000&foo=1")
    messages = page.locator(".asp-messages")
    messages.locator(".note").get_by_text("unknown parameter 'foo' ignored").wait_for()
    messages.locator(".warning").get_by_text("AreaFractionWarning", exact=False).first.wait_for()
    assert messages.bounding_box()["height"] > 62
    type_into(page, "sigma_s_m", "-1")
    messages.locator(".error").get_by_text("must be > 0", exact=False).first.wait_for()
    assert "last valid parameters" in messages.locator(".note").all_inner_texts()[-1]


def test_csv_download_is_the_librarys(page, server, tmp_path):
    load(page, server.url + "?n=30&gamma=0.002")
    with page.expect_download() as info:
        page.locator(".asp-button-csv-load button").click()
    download = info.value
    assert download.suggested_filename == "asperity-load-curve.csv"
    path = tmp_path / "load.csv"
    download.save_as(path)
    curve, _, _ = library_curves(params(page))
    assert path.read_text() == curve.to_csv()


def test_png_download(page, server, tmp_path):
    load(page, server.url)
    with page.expect_download() as info:
        page.locator(".asp-button-png button").click()
    path = tmp_path / "figure.png"
    info.value.save_as(path)
    data = path.read_bytes()
    assert info.value.suggested_filename == "asperity-explorer.png"
    assert data[:8] == b"\x89PNG\r\n\x1a\n" and len(data) > 20_000


def test_missing_browser_skips_or_fails_as_ci_wants(monkeypatch):
    from . import browser

    monkeypatch.setattr(browser, "CHROMIUM", "/nonexistent/chromium")
    monkeypatch.delenv(browser.REQUIRE, raising=False)
    with pytest.raises(pytest.skip.Exception, match="no browser at /nonexistent/chromium"):
        browser.need_browser()
    monkeypatch.setenv(browser.REQUIRE, "1")
    with pytest.raises(pytest.fail.Exception, match="ASPERITY_REQUIRE_BROWSER=1"):
        browser.need_browser()


@pytest.mark.skipif(importlib.util.find_spec("asperity.cycle") is None,
                    reason="asperity.cycle is not installed (the approach/retract panel is optional)")
def test_cycle_panel_in_the_browser(page, server):
    from asperity.cycle import cycle

    load(page, server.url + "?n=40")
    page.locator(".asp-toggle-cycle input").check()
    page.wait_for_function("() => { const m = Bokeh.documents[0].get_model_by_name('cycle:retract'); "
                           "return m && m.data.P.length > 0; }")
    p = params(page)
    ref = cycle(float(p["alpha"]), float(p["beta"]), float(p["gamma"]), preload=float(p["P_max"]), n=40)
    shown = source_data(page, "cycle:retract")
    np.testing.assert_allclose(shown["P"], ref.retract.P, rtol=1e-12)
    np.testing.assert_allclose(source_data(page, "cycle:approach")["d"], ref.approach.d, rtol=1e-12)
    assert_plotted(page, *library_curves(p)[:2])  # the other plots are untouched


def test_fit_panel_in_the_browser(page, server, tmp_path):
    """A friction-load file uploaded through the page and fitted: the plotted fit is asperity.fit's."""
    pytest.importorskip("lmfit")
    import asperity
    from asperity.fit import fit_friction_load

    P = np.geomspace(1.0, 1e4, 20)
    F = asperity.Model(0.01, 1000.0, 1e-3).load_curve(P).F * (1 + 0.02 * np.random.default_rng(1).standard_normal(20))
    path = tmp_path / "afm.csv"
    path.write_text("P,F,F_err\n" + "".join(f"{p!r},{f!r},{0.02 * f!r}\n" for p, f in zip(P.tolist(), F.tolist(),
                                                                                          strict=True)))
    load(page, server.url + "?n=40&alpha=0.02&beta=800&gamma=0.002")
    page.locator(".asp-toggle-fit input").check()
    page.locator(".asp-fit-file input").set_input_files(str(path))
    page.wait_for_function("() => { const m = Bokeh.documents[0].get_model_by_name('fit:data'); "
                           "return m && m.data.P.length === 20; }")
    page.locator(".asp-fit-run button").click()
    page.wait_for_function("() => { const m = Bokeh.documents[0].get_model_by_name('fit:curve'); "
                           "return m && m.data.F.length > 0; }", timeout=60_000)
    p = params(page)
    fixed = {k: float(p[k]) for k in ("nu", "h_over_b", "tau_f1", "tau_f2", "a1", "a2")}
    ref = fit_friction_load(str(path), "gw", start={k: float(p[k]) for k in ("alpha", "beta", "gamma")}, fix=fixed,
                            vary=("alpha", "beta", "gamma"))
    np.testing.assert_allclose(source_data(page, "fit:curve")["F"], ref.curve.F, rtol=1e-9)
    np.testing.assert_allclose(source_data(page, "fit:data")["P"], P, rtol=1e-15)
