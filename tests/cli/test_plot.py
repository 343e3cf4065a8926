"""``--plot``: the figure, and that a failing plot writes nothing."""

import numpy as np
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


# -- asperity plot: a heat map of a sweep ----------------------------------------------------------
@pytest.fixture(scope="module")
def sweep_file(tmp_path_factory):
    pytest.importorskip("xarray")
    pytest.importorskip("netCDF4")
    import numpy as np

    import asperity

    out = tmp_path_factory.mktemp("sweep") / "map.nc"
    asperity.sweep(alpha=np.geomspace(1e-3, 0.1, 4), beta=1000.0, gamma=np.array([0.0, 1e-4, 1e-3]),
                   P=np.array([1.0, 10.0]), out=str(out), scheduler="serial").close()
    return out


@pytest.mark.parametrize("extra", [["--z", "pull_off"], ["--z", "mu", "--at", "P=9"]])
def test_heat_map_of_a_sweep(capsys, tmp_path, sweep_file, extra):
    pytest.importorskip("matplotlib")
    path = tmp_path / "map.png"
    code, out, err = run(capsys, "plot", str(sweep_file), "--x", "alpha", "--y", "gamma", *extra, "-o", str(path))
    assert code == 0, err
    assert path.read_bytes()[:4] == b"\x89PNG" and out.strip() == f"wrote {path}"


def test_heat_map_axes_and_colour_bar(sweep_file, tmp_path):
    # Log axes where the registry says so, and the colour bar labelled with the units of the file.
    pytest.importorskip("matplotlib")
    import xarray as xr

    from asperity.cli import plot

    seen = {}
    from matplotlib.figure import Figure

    savefig = Figure.savefig

    def capture(fig, *args, **kwargs):
        ax, cax = fig.axes
        seen.update(x=ax.get_xscale(), y=ax.get_yscale(), label=cax.get_ylabel(), xlabel=ax.get_xlabel())
        return savefig(fig, *args, **kwargs)
    Figure.savefig = capture
    try:
        with xr.open_dataset(sweep_file) as ds:
            plot.heat_map(ds, "alpha", "gamma", "pull_off", {}, str(tmp_path / "a.png"), "png")
    finally:
        Figure.savefig = savefig
    # gamma holds 0: no log axis for it; alpha spans decades
    assert seen["x"] == "log" and seen["y"] == "linear"
    assert seen["label"] == "pull_off [N G b^2]" and seen["xlabel"] == r"$\alpha$"


@pytest.mark.parametrize("argv, needle", [
    (["--x", "alpha", "--y", "gamma", "--z", "nope"], "not a variable"),
    (["--x", "alpha", "--y", "beta", "--z", "pull_off"], "not a dimension"),
    (["--x", "alpha", "--y", "alpha", "--z", "pull_off"], "different"),
    (["--x", "alpha", "--y", "gamma", "--z", "mu"], "fix it with --at P=VALUE"),
    (["--x", "alpha", "--y", "gamma", "--z", "mu", "--at", "P"], "NAME=VALUE"),
    (["--x", "alpha", "--y", "gamma", "--z", "mu", "--at", "Q=1"], "not another dimension"),
    (["--x", "alpha", "--y", "gamma", "--z", "mu", "--at", "P=nan"], "P must be a finite number"),
    (["--x", "alpha", "--y", "gamma", "--z", "mu", "--at", "P=inf"], "P must be a finite number"),
    (["--x", "alpha", "--y", "gamma", "--z", "mu", "--at", "P=1", "--at", "P=10"], "P given twice"),
    (["--x", "alpha", "--y", "gamma", "--z", "mu", "--at", "P=1_0"], "NAME=VALUE with a number"),
])
def test_heat_map_errors(capsys, tmp_path, sweep_file, argv, needle):
    pytest.importorskip("matplotlib")
    path = tmp_path / "x.png"
    code, _, err = run(capsys, "plot", str(sweep_file), *argv, "-o", str(path))
    assert one_line_error(code, err, needle), err
    assert not path.exists()


def test_heat_map_of_a_missing_file(capsys, tmp_path):
    code, _, err = run(capsys, "plot", str(tmp_path / "none.nc"), "--x", "a", "--y", "b", "--z", "c")
    assert one_line_error(code, err, "no such sweep")


def test_heat_map_names_a_bad_z_before_it_names_the_default_file(capsys, tmp_path, sweep_file, monkeypatch):
    """Found by the random CLI fuzz: ``--z Au/Au`` without ``-o`` made the default output
    ``Au/Au.png`` in a directory that does not exist (a traceback instead of status 2)."""
    pytest.importorskip("matplotlib")
    monkeypatch.chdir(tmp_path)
    code, _, err = run(capsys, "plot", str(sweep_file), "--x", "alpha", "--y", "gamma", "--z", "Au/Au")
    assert one_line_error(code, err, "not a variable"), err
    assert not list(tmp_path.iterdir())


@pytest.mark.parametrize("command", [["plot", "{store}", "--x", "alpha", "--y", "gamma", "--z", "pull_off"],
                                     ["load", *MODEL, "--P", "1"]])
def test_output_into_a_missing_directory_is_refused(capsys, tmp_path, sweep_file, command):
    argv = [a.format(store=sweep_file) for a in command]
    code, _, err = run(capsys, *argv, "-o", str(tmp_path / "missing" / "out.png"))
    assert one_line_error(code, err, "does not exist"), err
    assert not (tmp_path / "missing").exists()


def test_heat_map_cells_are_centred_on_log_axes():
    """Found by a review: on a log axis the cells' edges are geometric midpoints (linear ones
    put the alpha = 1e-3 cell over 2.5e-4..1.75e-3 and gave gamma = 1e-5 a negative edge)."""
    import numpy as np

    from asperity.cli.plot import _edges

    edges = _edges(np.array([1e-3, 1e-2, 1e-1]), True)
    np.testing.assert_allclose(edges, [10 ** -3.5, 10 ** -2.5, 10 ** -1.5, 10 ** -0.5], rtol=1e-12)
    np.testing.assert_allclose(_edges(np.array([0.0, 1.0, 3.0]), False), [-0.5, 0.5, 2.0, 4.0])
    assert np.all(_edges(np.geomspace(1e-5, 1e-2, 5), True) > 0)


def test_heat_map_names_the_grid_value_it_draws(capsys, tmp_path, sweep_file):
    """Found by a review: ``--at P=9`` silently drew P = 10; now a note says so (and an exact
    grid value draws without one)."""
    pytest.importorskip("matplotlib")
    path = tmp_path / "x.png"
    code, _, err = run(capsys, "plot", str(sweep_file), "--x", "alpha", "--y", "gamma", "--z", "mu", "--at", "P=9",
                       "-o", str(path))
    assert code == 0 and err.strip() == ("asperity: note: --at P=9.0: the sweep has no P = 9.0; its nearest grid "
                                         "value (in decades), 10.0, is drawn")
    code, _, err = run(capsys, "plot", str(sweep_file), "--x", "alpha", "--y", "gamma", "--z", "mu", "--at", "P=10",
                       "-o", str(path))
    assert code == 0 and err == ""


def test_heat_map_never_replaces_its_sweep_nor_writes_a_file_named_dash(capsys, tmp_path, sweep_file, monkeypatch):
    pytest.importorskip("matplotlib")
    before = sweep_file.read_bytes()
    code, _, err = run(capsys, "plot", str(sweep_file), "--x", "alpha", "--y", "gamma", "--z", "pull_off",
                       "-o", str(sweep_file))
    assert one_line_error(code, err, "is the sweep being read") and sweep_file.read_bytes() == before
    monkeypatch.chdir(tmp_path)
    code, _, err = run(capsys, "plot", str(sweep_file), "--x", "alpha", "--y", "gamma", "--z", "pull_off", "-o", "-")
    assert one_line_error(code, err, "cannot go to standard output") and not list(tmp_path.iterdir())


def test_dash_output_is_standard_output_and_an_input_is_never_overwritten(capsys, tmp_path, monkeypatch):
    """``-o -`` writes to standard output (found by a review: it made a file named '-'); an
    output naming the command's input file is refused before anything is written."""
    monkeypatch.chdir(tmp_path)
    code, out, err = run(capsys, "load", *MODEL, "--P", "1", "--format", "csv", "-o", "-")
    code2, out2, _ = run(capsys, "load", *MODEL, "--P", "1", "--format", "csv")
    assert code == code2 == 0 and out == out2 and not list(tmp_path.iterdir())
    data = tmp_path / "fl.csv"
    data.write_text("P,F\n" + "".join(f"{p},{0.3 * p + 1}\n" for p in range(1, 9)))
    before = data.read_bytes()
    for option in ("-o", "--plot"):
        code, _, err = run(capsys, "fit", str(data), "--model", "amontons", option, str(data))
        assert one_line_error(code, err, "is the input file"), err
        assert data.read_bytes() == before


def test_dash_is_no_image_nor_sweep_and_summit_files_are_inputs(capsys, tmp_path, monkeypatch):
    """Found by a review: ``--plot -`` and ``sweep --out -`` wrote files named '-', and
    ``--heights empirical:z.txt -o z.txt`` replaced the summit heights; ``-o -`` on a
    terminal is the table, as without ``-o``."""
    import argparse

    from asperity.cli import _output

    monkeypatch.chdir(tmp_path)
    code, _, err = run(capsys, "load", *MODEL, "--P", "1", "--plot", "-")
    assert one_line_error(code, err, "--plot -: an image cannot go to standard output")
    code, _, err = run(capsys, "sweep", "--alpha", "0.01", "--beta", "1000", "--P", "1", "--out", "-",
                       "--scheduler", "serial")
    assert one_line_error(code, err, "not standard output")
    z = tmp_path / "z.txt"
    z.write_text("z\n" + "".join(f"{v}\n" for v in np.random.default_rng(0).standard_normal(40)))
    before = z.read_bytes()
    code, _, err = run(capsys, "load", *MODEL, "--P", "1", "--heights", f"empirical:{z}", "-o", str(z))
    assert one_line_error(code, err, "is the input file") and z.read_bytes() == before
    assert not (tmp_path / "-").exists()
    monkeypatch.setattr(_output.sys.stdout, "isatty", lambda: True, raising=False)
    for output in (None, "-"):
        assert _output.output_format(argparse.Namespace(format=None, output=output)) == "table"
    assert _output.output_format(argparse.Namespace(format=None, output="x.csv")) == "csv"


def test_heat_map_title_names_what_grey_means(sweep_file, tmp_path, monkeypatch):
    """Found by a newcomer: cells grey for a zero pull-off (gamma = 0, log colours) were titled
    'grey: <= 0 or not computed (see message)' though every set was computed.  The title now
    names what is there: '<= 0', 'not computed (see message)' (a NaN set), or both."""
    pytest.importorskip("matplotlib")
    import xarray as xr
    from matplotlib.figure import Figure

    from asperity.cli import plot

    titles = []
    savefig = Figure.savefig
    monkeypatch.setattr(Figure, "savefig", lambda fig, *a, **k: (titles.append(fig.axes[0].get_title()),
                                                                   savefig(fig, *a, **k)))
    with xr.open_dataset(sweep_file) as ds:
        ds = ds.load()
    assert float(ds["pull_off"].sel(gamma=0.0).max()) <= 0.0 < float(ds["pull_off"].max())  # zero at gamma = 0
    plot.heat_map(ds, "alpha", "gamma", "pull_off", {}, str(tmp_path / "a.png"), "png")
    failed = ds.copy(deep=True)
    failed["pull_off"][{"alpha": 1, "gamma": 2}] = np.nan
    plot.heat_map(failed, "alpha", "gamma", "pull_off", {}, str(tmp_path / "b.png"), "png")
    failed["mu"][{"alpha": 1, "gamma": 2, "P": 0}] = np.nan  # mu > 0 everywhere
    plot.heat_map(failed, "alpha", "gamma", "mu", {"P": 1.0}, str(tmp_path / "c.png"), "png")
    plot.heat_map(ds, "alpha", "gamma", "mu", {"P": 1.0}, str(tmp_path / "d.png"), "png")
    assert titles == ["grey: <= 0", "grey: <= 0 or not computed (see message)",
                      "P = 1, grey: not computed (see message)", "P = 1"]


@pytest.fixture(scope="module")
def material_sweep(tmp_path_factory):
    pytest.importorskip("xarray")
    pytest.importorskip("netCDF4")
    import asperity

    out = tmp_path_factory.mktemp("materials") / "phys.nc"
    asperity.sweep(material=["Au", "Si"], sigma_s=np.array([1e-9, 2e-9, 4e-9]), R=1e-6, eta=1e12, area=1e-6,
                   w=0.0, P=np.array([1e-3, 1e-2, 1e-1]), out=str(out), scheduler="serial").close()
    return out


def _drawn(monkeypatch):
    """The heat maps saved: (cell values, x tick labels, title) of each."""
    from matplotlib.figure import Figure

    seen = []
    savefig = Figure.savefig

    def capture(fig, *args, **kwargs):
        ax = fig.axes[0]
        seen.append((np.ma.filled(ax.collections[0].get_array(), np.nan).reshape(-1),
                     [t.get_text() for t in ax.get_xticklabels()], ax.get_title()))
        return savefig(fig, *args, **kwargs)
    monkeypatch.setattr(Figure, "savefig", capture)
    return seen


def test_a_sweep_over_materials_is_drawn_with_one_cell_per_material(capsys, tmp_path, material_sweep, monkeypatch):
    """Found by a user trial: a physical sweep over materials could not be drawn: '--x material'
    failed converting 'Au' to a number and '--at material=Au' was refused as no number."""
    pytest.importorskip("matplotlib")
    import xarray as xr

    seen = _drawn(monkeypatch)
    with xr.open_dataset(material_sweep) as ds:
        ds = ds.load()
    code, out, err = run(capsys, "plot", str(material_sweep), "--x", "material", "--y", "sigma_s", "--z", "mu",
                         "--at", "P_N=0.01", "-o", str(tmp_path / "a.png"))
    assert code == 0, err
    values, ticks, title = seen[-1]
    np.testing.assert_array_equal(values, ds.mu.sel(P_N=0.01).transpose("sigma_s", "material").values.ravel())
    assert ticks == ["Au", "Si"] and title == "P_N = 0.01"
    code, out, err = run(capsys, "plot", str(material_sweep), "--x", "P_N", "--y", "sigma_s", "--z", "area_m2",
                         "--at", "material=Si", "-o", str(tmp_path / "b.png"))
    assert code == 0, err
    values, _, title = seen[-1]
    np.testing.assert_array_equal(values, ds.area_m2.sel(material="Si").transpose("sigma_s", "P_N").values.ravel())
    assert title == "material = Si"


@pytest.mark.parametrize("at, needle", [("material=Cu", "--at: material=Cu: the sweep's material values are Au, Si"),
                                        ("sigma_s=Au", "--at: sigma_s takes a number"),
                                        ("material=", "NAME=VALUE")])
def test_a_wrong_name_for_a_dimension_of_names_is_one_line(capsys, tmp_path, material_sweep, at, needle):
    pytest.importorskip("matplotlib")
    axes = ["--x", "P_N", "--y", "material"] if at.startswith("sigma_s") else ["--x", "P_N", "--y", "sigma_s"]
    code, out, err = run(capsys, "plot", str(material_sweep), *axes, "--z", "area_m2", "--at", at,
                         "-o", str(tmp_path / "c.png"))
    assert one_line_error(code, err, needle) and not (tmp_path / "c.png").exists()


def test_at_picks_the_nearest_grid_value_in_decades_on_a_log_axis(capsys, tmp_path, sweep_file, monkeypatch):
    """A user trial: '--at P=5' on the grid P = 1, 10 drew P = 1 (nearer on a linear scale);
    on a log axis 5 is nearer 10 (0.30 decades against 0.70).  3 is nearer 1 (0.48 against 0.52)."""
    pytest.importorskip("matplotlib")
    seen = _drawn(monkeypatch)
    for wanted, drawn in (("5", "10"), ("3", "1")):
        code, out, err = run(capsys, "plot", str(sweep_file), "--x", "alpha", "--y", "gamma", "--z", "mu", "--at",
                             f"P={wanted}", "-o", str(tmp_path / "d.png"))
        assert code == 0 and seen[-1][2] == f"P = {drawn}"
        assert f"its nearest grid value (in decades), {float(drawn)!r}, is drawn" in err
