"""Optional panels appear only with their capability; the approach/retract panel plots each branch."""

import importlib.util
import sys
import types
from types import SimpleNamespace

import numpy as np
import pytest

pytest.importorskip("bokeh")

from bokeh.document import Document  # noqa: E402

import asperity  # noqa: E402
from asperity.explorer import panels  # noqa: E402
from asperity.explorer.app import ExplorerSession, immediate_runner  # noqa: E402

HAS_CYCLE = importlib.util.find_spec("asperity.cycle") is not None


def fake_cycle_module(calls, fail=None):
    """A stand-in asperity.cycle with the real module's call and result shape."""
    module = types.ModuleType("asperity.cycle")

    def cycle(alpha, beta, gamma=0.0, *, preload=None, n=200, nu=0.3, h_over_b=1.0, friction=None, heights=None,
              law=None):
        calls.append({"alpha": alpha, "beta": beta, "gamma": gamma, "preload": preload, "n": n, "nu": nu,
                      "h_over_b": h_over_b, "friction": friction, "heights": heights, "law": law})
        if fail:
            raise ValueError(fail)
        d = np.linspace(0.0, 2.0, 5)
        return SimpleNamespace(approach=SimpleNamespace(d=d[::-1], P=preload - d[::-1]),
                               retract=SimpleNamespace(d=d, P=-d), pull_off=SimpleNamespace(force=1.5, d=1.2,
                                                                                            exists=True))

    module.cycle = cycle
    return module


def cycle_of(session):
    """The session's approach/retract panel (the fit panel may stand beside it)."""
    return next(p for p in session.panels if isinstance(p, panels.CyclePanel))


@pytest.fixture()
def with_cycle(monkeypatch):
    def install(module):
        monkeypatch.setitem(sys.modules, "asperity.cycle", module)
        real = importlib.util.find_spec
        monkeypatch.setattr(importlib.util, "find_spec",
                            lambda name, *a: object() if name == "asperity.cycle" else real(name, *a))
    return install


@pytest.mark.skipif(HAS_CYCLE, reason="asperity.cycle is installed: the real panel is tested below")
def test_no_cycle_no_panel():
    assert panels.cycle_panel() is None
    s = ExplorerSession(Document(), None, runner=immediate_runner)
    assert not [p for p in s.panels if isinstance(p, panels.CyclePanel)]


def test_cycle_panel_is_off_until_asked_then_plots_each_branch(with_cycle):
    calls = []
    with_cycle(fake_cycle_module(calls))
    s = ExplorerSession(Document(), "n=20&alpha=0.004&nu=0.25", runner=immediate_runner)
    panel = cycle_of(s)
    assert isinstance(panel, panels.CyclePanel) and calls == [] and panel.figure not in panel.layout.children
    panel.toggle.active = True  # the user asks for it: the same view, with the cycle
    assert panel.figure in panel.layout.children and len(calls) == 1
    call = calls[0]
    assert (call["alpha"], call["nu"], call["n"], call["preload"]) == (0.004, 0.25, 20, s.result.load.P.max())
    assert call["friction"] == asperity.HurtadoKim() and isinstance(call["heights"], asperity.heights.Gaussian)
    assert call["law"] is None  # the elastic law
    np.testing.assert_array_equal(panel.sources["retract"].data["P"], -np.linspace(0, 2, 5))
    assert list(panel.marker.data["P"]) == [-1.5]
    s.controls["beta"].text.value = "300"  # every update now computes the cycle too
    assert len(calls) == 2 and calls[-1]["beta"] == 300.0
    panel.toggle.active = False
    s.controls["beta"].text.value = "400"
    assert len(calls) == 2 and panel.figure not in panel.layout.children


def test_a_failing_panel_is_a_message_not_a_crash(with_cycle):
    with_cycle(fake_cycle_module([], fail="no retract branch for these loads"))
    s = ExplorerSession(Document(), "n=20", runner=immediate_runner)
    cycle_of(s).toggle.active = True
    assert s.failure is None and "no retract branch" in s.page.messages_html
    assert 'class="warning"' in s.page.messages_html


@pytest.mark.skipif(not HAS_CYCLE, reason="asperity.cycle is not installed (the panel is optional)")
def test_real_cycle_panel():
    from asperity.cycle import cycle

    panel = panels.cycle_panel()
    assert panel is not None, "asperity.cycle exists but has no cycle(): update explorer/panels.py"
    s = ExplorerSession(Document(), "n=30", runner=immediate_runner)
    cycle_of(s).toggle.active = True
    assert s.failure is None, s.failure
    ref = cycle(0.003, 1000.0, 1e-3, preload=1e5, n=30)
    np.testing.assert_allclose(cycle_of(s).sources["retract"].data["P"], ref.retract.P, rtol=1e-12)
    # with the Jackson-Green law (no adhesion) the cycle is the library's with that law
    from asperity.elastic_plastic import JacksonGreen

    s = ExplorerSession(Document(), "n=30&gamma=0&law=jackson-green&H_over_E=0.003&h_star_over_sigma=2",
                        runner=immediate_runner)
    cycle_of(s).toggle.active = True
    assert s.failure is None, s.failure
    with pytest.warns(asperity.AsperityWarning, match="no unloading"):
        ref = cycle(0.003, 1000.0, 0.0, preload=1e5, n=30, law=JacksonGreen(0.003, 2.0))
    np.testing.assert_allclose(cycle_of(s).sources["approach"].data["P"], ref.approach.P, rtol=1e-12)
    # the cycle's warning reaches the page (it went to the server's log), once
    assert s.page.messages_html.count("approach and retract: AsperityWarning: the jackson-green law has no "
                                      "unloading") == 1, s.page.messages_html


@pytest.mark.skipif(not HAS_CYCLE, reason="asperity.cycle is not installed (the panel is optional)")
def test_cycle_axes_use_si_prefixes_in_physical_mode():
    # found by a review: the cycle's d axis read 2e-9 (m) where the other plots read '2 n'
    from bokeh.models import BasicTickFormatter, CustomJSTickFormatter

    s = ExplorerSession(Document(), "mode=physical&n=30", runner=immediate_runner)
    panel = cycle_of(s)
    assert panel.figure.xaxis.axis_label == "d (m)"
    assert all(isinstance(a.formatter, CustomJSTickFormatter) for a in (panel.figure.xaxis, panel.figure.yaxis))
    s.mode.active = 0
    assert all(isinstance(a.formatter, BasicTickFormatter) for a in (panel.figure.xaxis, panel.figure.yaxis))
