"""examples/explorer_link.py: a link's view, recomputed in a script, is the library's."""

import importlib.util
import pathlib

import numpy as np

import asperity
from asperity.physical import PhysicalContact
from asperity.surface import Surface

EXAMPLE = pathlib.Path(__file__).parents[2] / "examples" / "explorer_link.py"


def load_example():
    spec = importlib.util.spec_from_file_location("explorer_link", EXAMPLE)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_link_to_csv(tmp_path, capsys):
    link = "http://127.0.0.1:5006/?mode=physical&material=Si&sigma_s_m=3e-9&P_max_N=5&n=40&foo=1"
    load_example().main([link, "--out", str(tmp_path)])
    out = capsys.readouterr().out
    assert "unknown parameter 'foo'" in out and "pull-off force" in out and "mode: physical, 40 loads" in out
    contact = PhysicalContact("Si", Surface(3e-9, 1e-6, 1e12, 1e-6), friction=asperity.HurtadoKim())
    assert (tmp_path / "load-curve.csv").read_text() == contact.load_curve(np.geomspace(1e-4, 5.0, 40)).to_csv()
    sep = contact.separation_curve(np.linspace(-1.0, 5.0, 40) * 3e-9)
    assert (tmp_path / "separation-curve.csv").read_text() == sep.to_csv()


def test_default_view(tmp_path, capsys):
    load_example().main(["--out", str(tmp_path)])
    model = asperity.Model(0.003, 1000.0, 1e-3)
    expected = model.load_curve(np.geomspace(1e-2, 1e5, 200)).to_csv()
    assert (tmp_path / "load-curve.csv").read_text() == expected
    po = model.pull_off()
    assert f"{po.force:.4g} at d/σ = {po.d:.4g}" in capsys.readouterr().out
