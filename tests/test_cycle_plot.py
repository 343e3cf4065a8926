"""The cycle figure (asperity.cycle_plot): what it draws is the result's."""

import sys

import numpy as np
import pytest

from asperity._optional import MissingDependency
from asperity.cycle import cycle
from asperity.cycle_plot import plot_cycle
from asperity.physical import PhysicalContact, Surface

pytest.importorskip("matplotlib")

ABOVE = (0.02, 50.0, 0.02)


def shoelace(x, y):
    return 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def test_shaded_loop_is_the_energy_and_the_pull_off_is_marked():
    c = cycle(*ABOVE, preload=100.0, n=2000)
    ax = plot_cycle(c, title="t")
    (patch,) = ax.patches
    xy = patch.get_xy()
    assert shoelace(xy[:, 0], xy[:, 1]) == pytest.approx(c.energy, rel=1e-4)
    marker = [line for line in ax.lines if line.get_marker() == "^"]
    assert len(marker) == 1 and marker[0].get_ydata()[0] == pytest.approx(-c.pull_off.force)
    assert {t.get_text() for t in ax.get_legend().get_texts()} >= {"approach", "retract"}
    assert ax.get_title() == "t"


def test_jumps_are_dashed_and_measured_against_the_base():
    c = cycle(*ABOVE, preload=100.0, n=300, stiffness=100.0)
    ax = plot_cycle(c)
    dashed = [line for line in ax.lines if line.get_linestyle() == "--"]
    assert len(dashed) == len(c.jumps) == 2
    for line, j in zip(dashed, c.jumps, strict=True):
        np.testing.assert_allclose(line.get_xdata(), [j.d_base, j.d_base], rtol=1e-9)
        np.testing.assert_allclose(sorted(line.get_ydata()), sorted([j.P_from, j.P_to]), rtol=1e-9)


@pytest.mark.filterwarnings("ignore::asperity.plasticity.PlasticityWarning")
def test_physical_cycle_in_nanonewtons_and_nanometres():
    contact = PhysicalContact("Au", Surface(2e-9, 100e-9, 2e14, 1e-12))
    c = contact.cycle(preload="5uN", n=100)
    ax = plot_cycle(c)
    retract = [line for line in ax.lines if line.get_label() == "retract"][0]
    np.testing.assert_allclose(retract.get_ydata(), c.retract.P[:retract.get_ydata().size] * 1e9)
    assert "nm" in ax.get_xlabel() and "nN" in ax.get_ylabel()


def test_without_matplotlib(monkeypatch):
    monkeypatch.setitem(sys.modules, "matplotlib", None)
    with pytest.raises(MissingDependency, match=r"asperity\[plot\]"):
        plot_cycle(cycle(*ABOVE, d_min=0.0, n=5))
