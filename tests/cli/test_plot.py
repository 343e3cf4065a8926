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
