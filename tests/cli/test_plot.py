"""``--plot``: the figure, and that a failing plot writes nothing."""

import pytest

from .helpers import AU, MODEL, one_line_error, run


@pytest.mark.parametrize("suffix, magic", [(".png", b"\x89PNG"), (".svg", b"<?xml"), (".pdf", b"%PDF")])
def test_plot_formats(capsys, tmp_path, suffix, magic):
    pytest.importorskip("matplotlib")
    path = tmp_path / f"fig{suffix}"
    code, _, _ = run(capsys, "load", *MODEL, "--P", "1:1e3:9", "--plot", str(path))
    assert code == 0 and path.read_bytes().startswith(magic)


def test_physical_plot(capsys, tmp_path):
    pytest.importorskip("matplotlib")
    path = tmp_path / "sep.png"
    code, _, _ = run(capsys, "separation", *AU, "--separation", "-2nm:6nm:9", "--plot", str(path))
    assert code == 0 and path.read_bytes()[:4] == b"\x89PNG"


def test_failing_plot_writes_nothing(capsys, tmp_path):
    # An unknown image format fails while saving the figure: neither -o nor --plot is touched,
    # and nothing is printed on standard output.
    pytest.importorskip("matplotlib")
    out, fig = tmp_path / "c.csv", tmp_path / "c.nosuchformat"
    out.write_text("previous\n")
    code, stdout, err = run(capsys, "load", *MODEL, "--P", "1:1e3:5", "-o", str(out), "--plot", str(fig))
    assert one_line_error(code, err, "nosuchformat")
    assert out.read_text() == "previous\n" and not fig.exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["c.csv"]
    code, stdout, err = run(capsys, "load", *MODEL, "--P", "1:1e3:5", "--plot", str(fig))
    assert code == 2 and stdout == ""


def test_failing_plot_keeps_an_existing_figure(capsys, tmp_path, monkeypatch):
    pytest.importorskip("matplotlib")
    from matplotlib.figure import Figure

    fig = tmp_path / "c.png"
    fig.write_bytes(b"old figure")

    def broken_savefig(self, fname, **kwargs):
        with open(fname, "wb") as fh:
            fh.write(b"\x89PNG half")
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(Figure, "savefig", broken_savefig)
    code, stdout, err = run(capsys, "load", *MODEL, "--P", "1:1e3:5", "--plot", str(fig))
    assert one_line_error(code, err, "cannot write plot") and stdout == ""
    assert fig.read_bytes() == b"old figure" and [p.name for p in tmp_path.iterdir()] == ["c.png"]


@pytest.fixture
def drawn(monkeypatch):
    """The figures ``--plot`` saves, captured as matplotlib objects."""
    pytest.importorskip("matplotlib")
    from matplotlib.figure import Figure

    figures = []
    save = Figure.savefig

    def capture(self, *args, **kwargs):
        figures.append(self)
        return save(self, *args, **kwargs)

    monkeypatch.setattr(Figure, "savefig", capture)
    return figures


def _legend(ax):
    legend = ax.get_legend()
    return [] if legend is None else [t.get_text() for t in legend.get_texts()]


def test_no_legend_without_a_tensile_part(capsys, tmp_path, drawn):
    code, _, _ = run(capsys, "separation", "--alpha", "0.01", "--beta", "1000", "--d", "0:4:9", "--plot",
                     str(tmp_path / "f.png"))
    assert code == 0 and _legend(drawn[0].axes[0]) == []


def test_legend_names_only_the_parts_drawn(capsys, tmp_path, drawn):
    # Adhesive: compressive then tensile.  Only tensile (far out): one entry.
    run(capsys, "separation", "--alpha", "0.005", "--beta", "1000", "--gamma", "1e-3", "--d", "-1:4:11",
        "--plot", str(tmp_path / "a.png"))
    run(capsys, "separation", "--alpha", "0.005", "--beta", "1000", "--gamma", "1e-3", "--d", "3:4:5",
        "--plot", str(tmp_path / "b.png"))
    assert _legend(drawn[0].axes[0]) == ["compressive $P$", "tensile $-P$"]
    assert _legend(drawn[1].axes[0]) == ["tensile $-P$"]


def test_physical_axes_fit_the_data(capsys, tmp_path, drawn):
    code, _, _ = run(capsys, "separation", *AU, "--separation", "-2nm:6nm:9", "--plot", str(tmp_path / "s.png"))
    ax = drawn[0].axes[0]
    assert code == 0 and ax.get_xlabel() == "separation $d$ (nm)"
    lo, hi = ax.get_xlim()
    assert lo <= -2 and hi >= 6 and hi - lo < 10  # in nm, around the data


def test_tensile_loads_plot_on_a_linear_axis(capsys, tmp_path, drawn):
    code, _, _ = run(capsys, "load", *AU, "--load=-1N,0N,1mN,1N", "--plot", str(tmp_path / "l.png"))
    mu_ax, area_ax = drawn[0].axes
    assert code == 0 and area_ax.get_xscale() == "linear" and mu_ax.get_xscale() == "log"
    assert mu_ax.get_lines()[0].get_xdata().min() > 0  # mu only where it is defined
