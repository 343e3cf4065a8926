"""The explorer's page on the server side, without a browser: controls, updates, messages, URL, CSV."""

import math

import numpy as np
import pytest

pytest.importorskip("bokeh")

from bokeh.document import Document  # noqa: E402

import asperity  # noqa: E402
from asperity.explorer.app import ExplorerSession, immediate_runner  # noqa: E402
from asperity.explorer.controls import SLIDER_STEPS  # noqa: E402
from asperity.explorer.labels import plain  # noqa: E402
from asperity.explorer.state import CUSTOM, START, default_state, number_text, state_from_query  # noqa: E402
from asperity.materials import material  # noqa: E402
from asperity.physical import PhysicalContact  # noqa: E402
from asperity.quantities import MODEL_PARAMETERS  # noqa: E402
from asperity.surface import Surface  # noqa: E402


def session(query=None, **kwargs):
    return ExplorerSession(Document(), query, runner=immediate_runner, **kwargs)


def model_of(state):
    """The library's model for a view, built here from the numbers alone."""
    return asperity.Model(state["alpha"], state["beta"], state["gamma"], nu=state["nu"], h_over_b=state["h_over_b"],
                          friction=asperity.HurtadoKim(state["tau_f1"], state["tau_f2"], state["a1"], state["a2"]))


def assert_shows(s, state):
    """The plots hold the library's curves for ``state`` (dimensionless)."""
    m = model_of(state)
    load = m.load_curve(np.geomspace(state["P_min"], state["P_max"], state["n"]))
    sep = m.separation_curve(np.linspace(state["d_min"], state["d_max"], state["n"]))
    for name in ("d", "P", "F", "mu", "area", "pressure", "contacts"):
        np.testing.assert_array_equal(s.plots.load.data[name], getattr(load, name), err_msg=name)
        np.testing.assert_array_equal(s.plots.separation.data[name], getattr(sep, name), err_msg=name)
    po = m.pull_off()
    assert list(s.plots.pull_off.data["force"]) == ([po.force] if po.exists else [])


def query_state(s):
    state, messages = state_from_query(s.page.query)
    assert messages == []
    return state


def test_first_view_is_the_librarys():
    s = session()
    assert s.good == default_state() and query_state(s) == default_state()
    assert_shows(s, default_state())
    assert "λ" in s.page.derived_html and "Maugis-Dugdale" in s.page.derived_html
    assert "no warnings" in s.page.messages_html and "error" not in s.page.messages_html


def test_controls_are_built_from_the_registry():
    s = session()
    for name in ("alpha", "beta", "gamma", "nu", "h_over_b", "tau_f1", "tau_f2", "a1", "a2"):
        q = MODEL_PARAMETERS[name]
        c = s.controls[name]
        lo, hi = q.typical
        start, end = (math.log10(lo), math.log10(hi)) if q.log else (lo, hi)
        assert (c.slider.start, c.slider.end) == (start, end), name
        assert c.slider.step == pytest.approx((end - start) / SLIDER_STEPS)
        assert c.log == q.log and c.text.description == q.help() and c.text.title.startswith(plain(q.symbol))
    assert s.controls["sigma_s_m"].text.title == "σₛ (m)"
    assert s.controls["P_min"].slider is None  # ranges are typed only


def test_slider_move_updates_plots_text_and_url():
    s = session()
    c = s.controls["alpha"]
    c.slider.value = c.slider.value + 7 * c.slider.step
    alpha = float(f"{10 ** c.slider.value:.3g}")
    assert alpha != START["alpha"] and c.text.value == number_text(alpha)
    assert query_state(s)["alpha"] == alpha
    assert_shows(s, default_state().replace(alpha=alpha))


def test_typed_value_beyond_the_slider_widens_it():
    s = session()
    c = s.controls["alpha"]
    c.text.value = "0.5"  # typical range ends at 0.3
    assert c.slider.end == pytest.approx(math.log10(0.5)) and c.slider.value == c.slider.end
    assert query_state(s)["alpha"] == 0.5
    assert_shows(s, default_state().replace(alpha=0.5))


def test_zero_gamma_is_typed_and_turns_adhesion_off():
    s = session()
    s.controls["gamma"].text.value = "0"
    assert s.controls["gamma"].slider.value == s.controls["gamma"].slider.start
    assert query_state(s)["gamma"] == 0.0 and list(s.plots.pull_off.data["d"]) == []
    assert "no adhesion" in s.page.derived_html


@pytest.mark.parametrize("key, text, needle", [
    ("alpha", "-1", "alpha must be &gt; 0"),
    ("alpha", "abc", "alpha: expected a number, got &#x27;abc&#x27;"),
    ("a1", "1e6", "a2"),
    ("n", "5", None),
])
def test_invalid_values_show_a_message_and_keep_the_last_view(key, text, needle):
    s = session()
    before = {k: np.array(v) for k, v in s.plots.load.data.items()}
    url = s.page.query
    s.controls[key].text.value = text
    if needle is None:  # valid: for contrast
        assert query_state(s)["n"] == 5 and len(s.plots.load.data["P"]) == 5
        return
    assert needle in s.page.messages_html and "class=\"error\"" in s.page.messages_html
    assert "last valid parameters" in s.page.messages_html
    assert s.page.query == url
    for k, v in before.items():
        np.testing.assert_array_equal(s.plots.load.data[k], v)
    s.controls[key].text.value = number_text(default_state()[key])  # back to valid: message gone
    assert "no warnings" in s.page.messages_html and "error" not in s.page.messages_html


def test_material_menu_and_custom_values():
    s = session("mode=physical")
    s.controls["material"].widget.value = "Si"
    si = material("Si")
    assert s.controls["E_Pa"].text.value == number_text(si.E) and query_state(s)["material"] == "Si"
    assert "E_Pa" not in s.page.query
    s.controls["E_Pa"].text.value = "100 GPa"
    assert s.controls["material"].widget.value == CUSTOM
    state = query_state(s)
    assert state["material"] == CUSTOM and state["E_Pa"] == pytest.approx(1e11, rel=1e-15)
    assert (state["material_nu"], state["b_m"], state["w_J_m2"]) == (si.nu, si.b, si.w)


@pytest.mark.filterwarnings("ignore::asperity.plasticity.PlasticityWarning")  # gold yields: shown in the page
def test_mode_switch_shows_the_physical_contact_in_si_units():
    s = session()
    assert s.sections["Model parameters"].visible and not s.sections["Physical contact"].visible
    s.mode.active = 1
    assert not s.sections["Model parameters"].visible and s.sections["Physical contact"].visible
    assert not s.controls["P_max"].layout.visible and s.controls["P_max_N"].layout.visible
    state = query_state(s)
    assert state.mode == "physical"
    contact = PhysicalContact("Au", Surface(state["sigma_s_m"], state["R_m"], state["eta_per_m2"], state["area_m2"]),
                              friction=asperity.HurtadoKim())
    load = contact.load_curve(np.geomspace(state["P_min_N"], state["P_max_N"], state["n"]))
    np.testing.assert_array_equal(s.plots.load.data["P"], load.P)
    np.testing.assert_array_equal(s.plots.load.data["area"], load.area)
    assert s.plots.figures["mu"].xaxis.axis_label == "P (N)"
    assert s.plots.area_fraction.visible


def test_warning_of_the_library_is_shown():
    s = session("mode=physical&P_max_N=3000")
    assert "above 10 %" in s.page.messages_html and 'class="warning"' in s.page.messages_html


def test_rejected_link_falls_back_to_the_defaults():
    s = session("alpha=-2&foo=1")
    assert s.good == default_state()
    assert "unknown parameter" in s.page.messages_html and "rejected" in s.page.messages_html
    assert s.controls["alpha"].text.value == number_text(START["alpha"])
    assert_shows(s, default_state())


def test_link_sets_every_control():
    s = session("alpha=0.02&beta=300&nu=0.2&tau_f1=0.05&n=30")
    assert s.controls["alpha"].text.value == "0.02" and s.controls["tau_f1"].text.value == "0.05"
    assert s.controls["alpha"].slider.value == pytest.approx(math.log10(0.02))
    assert_shows(s, default_state().replace(alpha=0.02, beta=300.0, nu=0.2, tau_f1=0.05, n=30))


def test_csv_download_is_the_librarys_csv():
    s = session("n=25")
    s.download("load")
    assert s.page.download_name == "asperity-load-curve.csv" and s.page.download_count == 1
    m = model_of(s.good)
    assert s.page.download_text == m.load_curve(np.geomspace(START["P_min"], START["P_max"], 25)).to_csv()
    s.download("separation")
    assert s.page.download_count == 2
    assert s.page.download_text == m.separation_curve(np.linspace(START["d_min"], START["d_max"], 25)).to_csv()


def test_changes_during_a_computation_merge_into_one_update():
    jobs = []
    s = ExplorerSession(Document(), None, runner=lambda work, done: jobs.append((work, done)))
    assert jobs == []  # the first view is computed at once
    c = s.controls["beta"]
    for text in ("300", "400", "500"):
        c.text.value = text
    assert len(jobs) == 1 and s.attempted["beta"] == 300.0  # one computation at a time
    work, done = jobs.pop()
    done(work())
    assert len(jobs) == 1 and s.attempted["beta"] == 500.0  # then only the latest
    work, done = jobs.pop()
    done(work())
    assert jobs == [] and query_state(s)["beta"] == 500.0
    assert_shows(s, default_state().replace(beta=500.0))


def test_unexpected_errors_are_messages_too(monkeypatch):
    from asperity.explorer import compute as compute_module

    s = session()

    def broken(state):
        raise IndexError("boom")

    monkeypatch.setattr(compute_module, "compute", broken)
    s.controls["beta"].text.value = "300"
    assert "unexpected error (IndexError: boom)" in s.page.messages_html


def test_law_plasticity_and_interaction_controls():
    """The law's parameters appear with the Jackson-Green law; the physical controls reach the
    contact; the material menu fills the hardness; the URL holds them."""
    s = session("gamma=0")
    assert not s.controls["H_over_E"].layout.visible
    s.controls["law"].widget.value = "jackson-green"
    assert s.controls["H_over_E"].layout.visible and s.controls["h_star_over_sigma"].layout.visible
    assert "law=jackson-green" in s.page.query and "H_over_E=" in s.page.query
    from asperity.elastic_plastic import JacksonGreen

    v = query_state(s)
    model = asperity.Model(v["alpha"], v["beta"], 0.0, law=JacksonGreen(v["H_over_E"], v["h_star_over_sigma"]))
    np.testing.assert_array_equal(s.plots.load.data["area"],
                                  model.load_curve(np.geomspace(v["P_min"], v["P_max"], v["n"])).area)
    s.controls["law"].widget.value = "elastic"
    assert not s.controls["H_over_E"].layout.visible and "H_over_E" not in s.page.query
    s.mode.active = 1
    s.controls["adhesion"].widget.active = False
    s.controls["plasticity"].widget.value = "jackson-green"
    s.controls["interaction"].widget.value = "cgp2008"
    assert s.failure is None and s.result.subject.law == "jackson-green"
    assert s.result.subject.interaction.name == "cgp2008"
    assert "plasticity index ψ" in s.page.derived_html
    s.controls["material"].widget.value = "Si"
    assert s.controls["H_Pa"].text.value == number_text(material("Si").H)


@pytest.mark.parametrize("query", ["mode=physical&material=Au/mica&plasticity=jackson-green",
                                   "mode=physical&interaction=cgp2008",
                                   "mode=physical&adhesion=0&size_effect=1"])
def test_a_rejected_physical_link_says_so(query):
    """Found by a review: the mode reset of the fallback cleared the note (physical links only);
    a later review: the fallback threw the mode away too, now it is the link's mode's default."""
    s = session(query)
    assert "the link&#x27;s parameters were rejected" in s.page.messages_html or \
        "the link's parameters were rejected" in s.page.messages_html
    assert "default view of its mode (physical)" in s.page.messages_html
    assert s.failure is None and query_state(s).mode == "physical"
    assert query_state(s) == default_state().replace(mode="physical")


def test_a_linked_table_material_shows_its_own_values():
    """Found by a review: a link naming Cu showed gold's E, nu, b, w, H in the custom fields, and
    editing one of them switched to a custom material with gold's other values."""
    cu = material("Cu")
    s = session("mode=physical&material=Cu&adhesion=0&plasticity=jackson-green&size_effect=1")
    assert s.failure is None, s.failure
    assert s.controls["E_Pa"].text.value == number_text(cu.E) and s.controls["w_J_m2"].text.value == number_text(cu.w)
    before = s.result.load.F.copy()
    psi = s.result.subject.plasticity_index
    s.controls["E_Pa"].text.value = f"{cu.E / 1e9:.17g} GPa"  # the same E, typed: now a custom copy of Cu
    assert s.controls["material"].widget.value == CUSTOM and s.failure is None, s.failure
    np.testing.assert_allclose(s.result.load.F, before, rtol=1e-12)
    assert s.result.subject.plasticity_index == pytest.approx(psi, rel=1e-12)


def test_the_jackson_green_law_has_no_gamma():
    """Choosing the elastic-plastic law hides gamma (it has no adhesion) instead of failing on it;
    the derived numbers say which law has no adhesion, and give the plasticity index."""
    s = session("gamma=0.001&alpha=0.02")
    s.controls["law"].widget.value = "jackson-green"
    assert s.failure is None and not s.controls["gamma"].layout.visible and "gamma=" not in s.page.query
    assert "no adhesion: Jackson-Green" in s.page.derived_html
    assert f"<td>{0.02 / query_state(s)['H_over_E']:.4g}</td>" in s.page.derived_html   # psi = alpha/(H/E*)
    s.controls["law"].widget.value = "elastic"
    assert s.controls["gamma"].layout.visible and "gamma=0.001" in s.page.query


def test_editing_a_table_materials_value_shows_the_custom_fields_and_says_what_it_kept():
    """Found by a review: after a switch to custom by editing, H, H0, h* stayed hidden though
    used; values the table material lacks are kept from the fields, and the page says so."""
    s = session("mode=physical&material=Cu&adhesion=0&plasticity=jackson-green")
    s.controls["material"].widget.value = "Si"
    assert not s.controls["H0_Pa"].layout.visible
    s.controls["E_Pa"].text.value = "170 GPa"
    assert s.controls["material"].widget.value == CUSTOM
    assert all(s.controls[k].layout.visible for k in ("H_Pa", "H0_Pa", "h_star_m"))
    assert "custom material from Si, which has no H0 (size effect), h* in the table" in s.page.messages_html
    assert s.result.subject.material.H == material("Si").H


def test_choosing_custom_in_the_menu_says_what_the_fields_hold_that_the_table_lacks():
    """Found by a review: custom chosen from the menu kept Au's H for H0 and a default h*, and
    the size effect ran on them without a note (editing a value did give one)."""
    s = session("mode=physical&adhesion=0&plasticity=jackson-green")
    s.controls["material"].widget.value = CUSTOM
    assert "custom material from Au, which has no H0 (size effect), h* in the table" in s.page.messages_html
    s = session("mode=physical&material=Cu&adhesion=0&plasticity=jackson-green")
    s.controls["material"].widget.value = CUSTOM  # copper has every value: nothing to say
    assert "custom material from" not in s.page.messages_html


def test_the_physical_jackson_green_law_has_no_adhesion_control():
    """As gamma in dimensionless mode: with the Jackson-Green law the adhesion flag is hidden
    and not used (the law has none), so choosing the law never fails on it."""
    s = session("mode=physical")
    assert s.controls["adhesion"].layout.visible
    s.controls["plasticity"].widget.value = "jackson-green"
    assert s.failure is None, s.failure
    assert not s.controls["adhesion"].layout.visible and "adhesion=" not in s.page.query
    assert s.result.subject.gamma == 0.0 and s.result.subject.law == "jackson-green"
    assert "no adhesion: Jackson-Green" in s.page.derived_html
    s.controls["plasticity"].widget.value = "elastic"
    assert s.controls["adhesion"].layout.visible and s.result.subject.gamma > 0


@pytest.mark.filterwarnings("ignore::asperity.plasticity.PlasticityWarning")
def test_messages_box_grows_with_its_messages_up_to_a_limit():
    # found by a review: three messages in a 62 px box, two of them out of sight
    from asperity.explorer.app import MESSAGES_HEIGHT, MESSAGES_MAX_HEIGHT

    assert session().messages.height == MESSAGES_HEIGHT
    s = session("mode=physical&P_max_N=3000&alpha=-2&foo=1")
    items = s.page.messages_html.count("<div class=")
    assert items >= 3, s.page.messages_html
    assert MESSAGES_HEIGHT < s.messages.height <= MESSAGES_MAX_HEIGHT
