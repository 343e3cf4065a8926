"""The paper-reproduction layer: asperity.studies.reproduce and what it writes."""

import csv
import re
import struct
import subprocess
import sys

import numpy as np
import pytest

import asperity

FIGS = range(3, 10)

# Printed Table 1 (alpha, beta, gamma, |P|/NGb^2), typed in independently of the package.
PAPER_TABLE1 = [
    (0.002, 1000, 0.001, 2158.1), (0.003, 1000, 0.001, 320.1), (0.004, 1000, 0.001, 26.7),
    (0.005, 1000, 0.001, 1.0), (0.01, 100, 0.001, 2.9), (0.01, 300, 0.001, 0.005),
    (0.01, 1000, 0.005, 9.5), (0.01, 1000, 0.007, 81.2), (0.01, 1000, 0.010, 2480.8),
]

# What each figure plots on x and y, as functions of a curve's columns.
PLOTTED = {
    3: (lambda r: r["P"] / r["alpha"], lambda r: r["alpha"] * r["mu"]),
    4: (lambda r: r["P"] / r["alpha"], lambda r: r["alpha"] * r["mu"]),
    5: (lambda r: r["P"] / r["alpha"], lambda r: r["alpha"] * r["mu"]),
    6: (lambda r: r["P"], lambda r: r["mu"]),
    7: (lambda r: r["d"], lambda r: np.abs(r["P"])),
    8: (lambda r: r["d"], lambda r: r["F"]),
    9: (lambda r: r["P"], lambda r: r["pressure"]),
}
BY_SEPARATION = {7, 8}


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    from asperity.studies import reproduce

    out = tmp_path_factory.mktemp("paper")
    messages = []
    summary = reproduce(out, progress=messages.append)
    return out, summary, messages


def read_csv(path):
    with open(path, newline="", encoding="utf-8") as fh:
        reader = csv.DictReader(fh)
        return reader.fieldnames, list(reader)


def curves_of(path):
    """Figure CSV -> {curve id: dict of column -> array (numbers) or list (text)}."""
    header, rows = read_csv(path)
    out = {}
    for row in rows:
        out.setdefault(row["curve"], []).append(row)
    result = {}
    for key, rs in out.items():
        cols = {}
        for name in header:
            values = [r[name] for r in rs]
            try:
                cols[name] = np.array([float(v) for v in values])
            except ValueError:
                cols[name] = values
        result[key] = cols
    return result


def png_size(path):
    with open(path, "rb") as fh:
        head = fh.read(24)
    assert head[:8] == b"\x89PNG\r\n\x1a\n"
    return struct.unpack(">II", head[16:24])


def test_writes_every_file(run):
    out, summary, _ = run
    expected = {f"fig{n}.{ext}" for n in FIGS for ext in ("png", "svg", "csv")} | {"table1.csv", "index.html"}
    written = {p.name for p in out.iterdir()}
    assert expected <= written
    assert {p.rsplit("/", 1)[-1] for p in summary["files"]} == expected
    for name in expected:
        assert (out / name).stat().st_size > 0, name
    for n in FIGS:
        assert png_size(out / f"fig{n}.png") == (900, 675)  # 6 x 4.5 in at 150 dpi
        assert (out / f"fig{n}.svg").read_text(encoding="utf-8").lstrip().startswith("<?xml")


def test_progress_once_per_figure(run):
    _, _, messages = run
    for n in FIGS:
        assert sum(m.startswith(f"Fig {n}:") for m in messages) == 1
    assert all(isinstance(m, str) and m for m in messages)


def test_summary_checks(run):
    _, summary, _ = run
    total = 0
    for n in FIGS:
        checks = summary["figures"][f"fig{n}"]["checks"]
        assert checks, n
        for c in checks:
            assert isinstance(c["claim"], str) and c["claim"]
            assert isinstance(c["passed"], bool)
            assert isinstance(c["detail"], str) and c["detail"]
        total += len(checks)
    assert summary["checks_total"] == total
    assert 0 <= summary["checks_passed"] <= total


def test_checks_are_claim_passed_detail_tuples():
    from asperity.studies import FIGURES

    spec = FIGURES[7]
    for claim, passed, detail in spec.checks(spec.data()):
        assert isinstance(claim, str) and isinstance(passed, bool) and isinstance(detail, str)


def test_table1_csv(run):
    out, _, _ = run
    header, rows = read_csv(out / "table1.csv")
    assert header == ["alpha", "beta", "gamma", "paper", "computed", "ratio"]
    assert len(rows) == 9
    for row, (alpha, beta, gamma, paper) in zip(rows, PAPER_TABLE1, strict=True):
        assert (float(row["alpha"]), float(row["beta"]), float(row["gamma"])) == (alpha, beta, gamma)
        assert float(row["paper"]) == paper
        expected = asperity.pull_off(alpha, beta, gamma).force
        assert float(row["computed"]) == pytest.approx(expected, rel=1e-9)
        assert float(row["ratio"]) == pytest.approx(expected / paper, rel=1e-9)


@pytest.mark.parametrize("n", FIGS)
def test_figure_csv_matches_library(run, n):
    out, _, _ = run
    curves = curves_of(out / f"fig{n}.csv")
    assert len(curves) >= 2
    fx, fy = PLOTTED[n]
    for key, c in curves.items():
        alpha, beta, gamma = c["alpha"][0], c["beta"][0], c["gamma"][0]
        assert np.all(c["alpha"] == alpha) and np.all(c["gamma"] == gamma)
        assert c["adhesion"][0] == str(gamma > 0)
        assert key == f"alpha={alpha:g} beta={beta:g} gamma={gamma:g}"
        if n in BY_SEPARATION:
            direct = asperity.separation_curve(c["d"], alpha, beta, gamma)
        else:
            direct = asperity.load_curve(c["P"], alpha, beta, gamma)
        for name in ("d", "P", "F", "mu", "area", "pressure", "contacts"):
            np.testing.assert_allclose(c[name], getattr(direct, name), rtol=1e-8, atol=0,
                                       err_msg=f"fig{n} {key} {name}")
        np.testing.assert_allclose(c["x"], fx(c), rtol=1e-12)
        np.testing.assert_allclose(c["y"], fy(c), rtol=1e-12)


def test_figure_7_has_exactly_one_tensile_curve(run):
    out, _, _ = run
    curves = curves_of(out / "fig7.csv")
    tensile = [k for k, c in curves.items() if np.any(c["P"] < 0)]
    assert tensile == ["alpha=0.005 beta=1000 gamma=0.001"]


def test_index_html_is_self_contained(run):
    out, summary, _ = run
    text = (out / "index.html").read_text(encoding="utf-8")
    assert summary["index"].endswith("index.html")
    for n in FIGS:
        assert f'id="fig{n}"' in text
        assert f"Fig. {n}." in text
    assert text.count("data:image/png;base64,") == len(FIGS)
    assert not re.search(r"https?:", text, flags=re.IGNORECASE)
    assert not re.search(r"""(src|href)\s*=\s*["']?//""", text)
    assert "@import" not in text
    assert 'id="table1"' in text and "2158.1" in text and 'id="decisions"' in text
    assert "PASS" in text


def test_studies_import_without_matplotlib():
    code = ("import sys, asperity, asperity.studies\n"
            "assert 'matplotlib' not in sys.modules, 'matplotlib imported'\n")
    subprocess.run([sys.executable, "-c", code], check=True)


# -- legends name only what can be seen; axes fit the data -------------------------------------------

def _legend_texts(fig):
    return [t.get_text() for t in fig.axes[0].get_legend().get_texts()]


def test_hidden_curves_share_the_visible_curves_entry():
    pytest.importorskip("matplotlib")
    from asperity.studies.figures import FIGURES

    spec = FIGURES[4]
    texts = _legend_texts(spec.draw(spec.data()))
    # alpha = 0.06 lies under alpha = 0.1 (within half a line width): one entry for both.
    assert "α = 0.1; also α = 0.06" in texts and "α = 0.06" not in texts


def test_visible_legend_entries():
    pytest.importorskip("matplotlib")
    import numpy as np

    from asperity.studies._common import new_figure, visible_legend_entries

    fig, ax = new_figure()
    x = np.geomspace(1, 100, 50)
    ax.loglog(x, x, color="C0", label="under")
    ax.loglog(x, x * 1.001, color="C1", label="over")          # hides "under"
    ax.loglog(x, 2 * x, color="C2", label="apart")
    ax.loglog(x, 2 * x, color="C3", ls="--", label="dashed")   # dashed: "apart" shows in its gaps
    ax.loglog([], [], color="C4", label="empty")                # nothing drawn: no entry
    ax.set_ylim(0.5, 300)
    _, labels = visible_legend_entries(ax)
    assert labels == ["over; also under", "apart", "dashed"]


@pytest.mark.parametrize("n, values", [(7, lambda s: abs(s.curve.P)), (8, lambda s: s.curve.F)])
def test_separation_figures_fit_their_data(n, values):
    pytest.importorskip("matplotlib")
    import numpy as np

    from asperity.studies.figures import FIGURES

    spec = FIGURES[n]
    data = spec.data()
    lo, hi = spec.draw(data).axes[0].get_ylim()
    v = np.concatenate([values(s) for s in data.series])
    v = v[v > 0]
    assert lo <= v.min() and hi >= v.max()
    assert np.log10(v.min() / lo) < 0.5 and np.log10(hi / v.max()) < 0.5  # within half a decade


def test_fig7_legend_entries_are_drawn():
    pytest.importorskip("matplotlib")
    from asperity.studies.figures import FIGURES

    texts = _legend_texts(FIGURES[7].draw(FIGURES[7].data()))
    assert texts[-2:] == [r"tensile part ($\bar P < 0$): $-\bar P$ plotted", "pull-off force"]
