"""Optional panels appear only with their capability; the approach/retract panel plots each branch."""

import importlib.util
import sys
import types
from dataclasses import dataclass

import numpy as np
import pytest

pytest.importorskip("bokeh")

from bokeh.document import Document  # noqa: E402

from asperity.explorer import panels  # noqa: E402
from asperity.explorer.app import ExplorerSession, immediate_runner  # noqa: E402

HAS_CYCLE = importlib.util.find_spec("asperity.cycle") is not None


@dataclass(frozen=True)
class FakeCycle:
    """A stand-in cycle result: the columns a CycleResult has (``branch``, ``d``, ``P``)."""

    d: np.ndarray
    P: np.ndarray
    branch: np.ndarray

    def columns(self):
        return {"d": self.d, "P": self.P, "branch": self.branch}


def fake_cycle_module(calls):
    module = types.ModuleType("asperity.cycle")

    def cycle_curve(subject, P_max):
        calls.append((subject, P_max))
        d = np.linspace(0.0, 2.0, 5)
        return FakeCycle(np.r_[d, d[::-1]], np.r_[P_max - d, -d[::-1]], np.array(["approach"] * 5 + ["retract"] * 5))

    module.cycle_curve = cycle_curve
    return module


@pytest.mark.skipif(HAS_CYCLE, reason="asperity.cycle is installed: the real panel is tested below")
def test_no_cycle_no_panel():
    assert panels.cycle_panel() is None
    s = ExplorerSession(Document(), None, runner=immediate_runner)
    assert s.panels == []


def test_cycle_panel_plots_each_branch(monkeypatch):
    calls = []
    monkeypatch.setitem(sys.modules, "asperity.cycle", fake_cycle_module(calls))
    monkeypatch.setattr(importlib.util, "find_spec", lambda name, *a: object() if name == "asperity.cycle" else None)
    s = ExplorerSession(Document(), "n=20", runner=immediate_runner)
    assert len(s.panels) == 1 and isinstance(s.panels[0], panels.CyclePanel)
    subject, P_max = calls[-1]
    assert subject is s.result.subject and P_max == s.result.load.P.max()
    approach, retract = (s.panels[0].sources[b].data for b in ("approach", "retract"))
    np.testing.assert_array_equal(approach["P"], P_max - np.linspace(0, 2, 5))
    np.testing.assert_array_equal(retract["d"], np.linspace(0, 2, 5)[::-1])


def test_a_failing_panel_is_a_message_not_a_crash(monkeypatch):
    calls = []
    module = fake_cycle_module(calls)

    def broken(subject, P_max):
        raise ValueError("no retract branch for these loads")

    module.cycle_curve = broken
    monkeypatch.setitem(sys.modules, "asperity.cycle", module)
    monkeypatch.setattr(importlib.util, "find_spec", lambda name, *a: object() if name == "asperity.cycle" else None)
    s = ExplorerSession(Document(), "n=20", runner=immediate_runner)
    assert s.result is not None and "no retract branch" in s.messages.text


@pytest.mark.skipif(not HAS_CYCLE, reason="asperity.cycle is not installed (the panel is optional)")
def test_real_cycle_panel():
    panel = panels.cycle_panel()
    assert panel is not None, "asperity.cycle exists but has no cycle_curve: update explorer/panels.py"
    s = ExplorerSession(Document(), "n=20", runner=immediate_runner)
    assert s.panels and all(len(src.data["d"]) for src in s.panels[0].sources.values())
