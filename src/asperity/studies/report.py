"""One call reproduces the paper: figures, their data, Table 1 and a self-contained report.

>>> from asperity.studies import reproduce                    # doctest: +SKIP
>>> summary = reproduce("paper-out", progress=print)          # doctest: +SKIP

writes, in ``out_dir``: ``fig3.png`` ... ``fig9.png`` with ``.svg`` and ``.csv``
alongside, ``table1.csv`` and ``index.html`` (images embedded, no external resources).
"""

from __future__ import annotations

import base64
import html
import time
from collections.abc import Callable
from pathlib import Path

from .._atomic import atomic_write
from .._validation import check_callable
from .._validation_files import check_output_path
from .._version import __version__
from ._common import CSV_COLUMNS, DPI, FIGSIZE, H_OVER_B, NU, csv_rows, save_figure, write_csv
from .figures import FIGURES
from .table1 import TABLE1_COLUMNS, printed_load_scale_factor, write_table1_csv

__all__ = ["reproduce", "DECISIONS"]

PAPER = ('G. G. Adams, S. M\u00fcft\u00fc, N. Mohd Azhar, "A Scale-Dependent Model for Multi-Asperity Contact '
         'and Friction", Journal of Tribology 125(4), 700-708 (2003), doi:10.1115/1.1572515')

#: Choices the paper leaves open or states inconsistently (shown in index.html).
DECISIONS = (
    ("Eq 4: the missing pi",
     "The text gives F_f = pi a^2 tau_f, but Eq 4 drops the pi (F_f/G*b^2 = tau_f a^2). We use "
     "F_f = pi a^2 tau_f, which Eq 10 (prefactor 2 pi, with G* = 2G) confirms."),
    ("Eq 17: the load scale P-hat",
     "Eq 17 prints P-hat = (1 - nu) alpha^2 / (2 pi beta gamma). Only (1 - nu) alpha / (2 pi beta gamma) "
     "follows from the definitions and tends to Eq 6 as gamma -> 0, and only it reproduces the first rows "
     "of Table 1; the printed form would multiply every force by 1/alpha (100 to 500 here)."),
    ("Eq 18: the lower limit",
     "The lower limit of the integral in Eq 18 is garbled. We integrate each asperity from the end of the "
     "stable displacement-controlled Maugis-Dugdale branch (where it jumps out of contact), i.e. over all "
     "asperities still in adhesive contact."),
    ("Poisson's ratio",
     f"The paper does not state nu, which enters Eqs 6 and 17 through G = E/2(1 + nu). We use nu = {NU:g}."),
    ("Dugdale range",
     f"h = b (h/b = {H_OVER_B:g}), as the paper states for its adhesive results."),
    ("Unstated figure parameters",
     "The paper gives neither the parameter values of the curves in Figs 4-9 nor the axis ranges. Each "
     "figure below says what we chose and why; the checks test the paper's words, not its pixels."),
)

TABLE1_REASONS = (
    "Poisson's ratio: the paper does not state nu; we use 0.3. In Eqs 6 and 17 every force, hence every "
    "pull-off force, is proportional to 1/(1 - nu), so another nu scales all rows alike (by 0.875 for "
    "nu = 0.2, 1.17 for nu = 0.4): it cannot explain ratios that vary from row to row, and it would spoil "
    "the agreement of rows 1-2.",
    "Eq 17: P-hat is misprinted (alpha^2 for alpha). We cannot tell which form, or which mixture of "
    "forms, the original MATLAB code used; the column 'with printed P-hat' shows what the printed form "
    "would give (every force times 1/alpha), which is far from the paper in every row.",
    "Eq 18: its lower limit is garbled. We integrate down to the end of the stable displacement-controlled "
    "Maugis-Dugdale branch; a different cut-off (e.g. at zero penetration, or at the force-controlled "
    "pull-off of each asperity) changes the tensile contribution of the asperities near the edge of "
    "contact, which is what the pull-off force is made of.",
    "The search for the pull-off: we take the largest tensile force for d/sigma up to 10, scanned on a 0.02 "
    "grid and refined by Newton's method. The paper does not say how it searched; a coarse or short scan "
    "underestimates shallow minima such as row 6 (alpha = 0.01, beta = 300), whose tensile force is tiny.",
    "Quadrature: the paper's integrals were evaluated with MATLAB. The pull-off force is a small difference "
    "of large compressive and tensile contributions, so modest relative errors in either are amplified; "
    "ours are tested against an independent adaptive-quadrature, multiple-precision reference "
    "implementation (asperity.reference).",
)

_CSS = """
body { font-family: Georgia, 'Times New Roman', serif; max-width: 60em; margin: 2em auto; padding: 0 1em;
       line-height: 1.45; color: #222; }
h1 { font-size: 1.6em; } h2 { font-size: 1.3em; border-bottom: 1px solid #ccc; padding-bottom: .2em;
       margin-top: 2em; }
figure { margin: 1em 0; } figure img { max-width: 100%; height: auto; border: 1px solid #eee; }
figcaption { font-size: .95em; }
table { border-collapse: collapse; margin: .8em 0; font-size: .92em; }
th, td { border: 1px solid #ccc; padding: .25em .6em; text-align: right; }
th { background: #f4f4f4; } td.l, th.l { text-align: left; }
.pass { color: #fff; background: #2e7d32; padding: 0 .4em; border-radius: 3px; font-family: sans-serif;
        font-size: .85em; white-space: nowrap; }
.not { color: #fff; background: #b26a00; padding: 0 .4em; border-radius: 3px; font-family: sans-serif;
       font-size: .85em; white-space: nowrap; }
.detail { color: #555; font-size: .9em; }
.params { background: #f8f8f8; padding: .5em .8em; border-left: 3px solid #999; font-size: .93em; }
.small { font-size: .85em; color: #666; }
"""


def _badge(passed: bool) -> str:
    return '<span class="pass">PASS</span>' if passed else '<span class="not">NOT SHOWN</span>'


def _fmt(x: float) -> str:
    return f"{x:.4g}" if abs(x) >= 1e-3 or x == 0 else f"{x:.3g}"


def _figure_section(n: int, info: dict, png: bytes) -> str:
    e = html.escape
    data = info["data"]
    checks = "".join(f"<li>{_badge(c.passed)} {e(c.claim)}<br><span class=\"detail\">{e(c.detail)}</span></li>"
                     for c in info["checks"])
    b64 = base64.b64encode(png).decode("ascii")
    return f"""
<section id="fig{n}">
<h2>Fig. {n}. {e(data.title)}</h2>
<figure><img src="data:image/png;base64,{b64}" alt="Fig. {n}: {e(data.title)}">
<figcaption><b>Fig. {n}.</b> {e(data.caption)}</figcaption></figure>
<p class="params"><b>Parameters and why.</b> {e(data.parameters)}</p>
<p><b>What the paper says, and whether our curves show it</b></p>
<ul>{checks}</ul>
<p class="small">Data: <a href="fig{n}.csv">fig{n}.csv</a> (long format: one row per plotted point, column
<code>curve</code> names the curve, <code>x</code> and <code>y</code> are the plotted values);
vector image: <a href="fig{n}.svg">fig{n}.svg</a>. Computed in {info["seconds"]:.2f} s.</p>
</section>"""


def _table1_trends(rows: list[dict]) -> str:
    """The paper's reading of Table 1, checked on our numbers (row order as printed)."""
    f = [r["computed"] for r in rows]
    trends = [
        ("every row has a pull-off force", all(x > 0 for x in f)),
        ("it rises steeply as alpha falls (rows 4 to 1)", f[0] > f[1] > f[2] > f[3] and f[0] / f[3] > 100),
        ("it rises steeply as gamma rises (rows 7 to 9)", f[6] < f[7] < f[8] and f[8] / f[6] > 10),
        ("it falls as beta rises (rows 5 to 6)", f[4] > f[5]),
    ]
    shown = [t for t, ok in trends if ok]
    missed = [t for t, ok in trends if not ok]
    text = "Our values show the table's trends: " + "; ".join(shown) + "." if shown else ""
    if missed:
        text += " Not shown by our values: " + "; ".join(missed) + "."
    return text


def _table1_section(rows: list[dict]) -> str:
    e = html.escape
    body = []
    for i, r in enumerate(rows, 1):
        printed = r["computed"] * printed_load_scale_factor(r["alpha"], r["beta"], r["gamma"], NU)
        body.append(f"<tr><td>{i}</td><td>{r['alpha']:g}</td><td>{r['beta']:g}</td><td>{r['gamma']:g}</td>"
                    f"<td>{r['paper']:g}</td><td>{_fmt(r['computed'])}</td><td>{r['ratio']:.3f}</td>"
                    f"<td>{_fmt(printed)}</td></tr>")
    agree = [i for i, r in enumerate(rows, 1) if abs(r["ratio"] - 1.0) <= 0.05]
    others = [r["ratio"] for i, r in enumerate(rows, 1) if i not in agree]
    spread = max(max(others), 1.0 / min(others)) if others else 1.0
    agree_text = (f"Rows {', '.join(map(str, agree))} agree with the paper within "
                  f"{100 * max(abs(rows[i - 1]['ratio'] - 1) for i in agree):.1f} %." if agree
                  else "No row agrees with the paper within 5 %.")
    reasons = "".join(f"<li>{e(t)}</li>" for t in TABLE1_REASONS)
    return f"""
<section id="table1">
<h2>Table 1. Dimensionless pull-off force |P|/NGb<sup>2</sup></h2>
<table>
<tr><th>row</th><th>&alpha;</th><th>&beta;</th><th>&gamma;</th><th>paper</th><th>computed</th>
<th>ratio<br>computed/paper</th><th>with printed P&#770;<br>(Eq 17, for comparison)</th></tr>
{''.join(body)}
</table>
<p class="small">Computed: the largest tensile force over d/&sigma; &le; 10 (nu = {NU:g}, h = b);
also in <a href="table1.csv">table1.csv</a> (columns {', '.join(TABLE1_COLUMNS)}).</p>
<p><b>How well it agrees.</b> {e(agree_text)} The other {len(others)} rows differ by factors of up to
{spread:.1f} (ratios from {min(r['ratio'] for r in rows):.3g} to {max(r['ratio'] for r in rows):.3g}).
{e(_table1_trends(rows))} Nothing has been tuned to match. Possible reasons for the differences:</p>
<ul>{reasons}</ul>
</section>"""


def _html(figs: dict[int, dict], pngs: dict[int, bytes], rows: list[dict], seconds: float) -> str:
    e = html.escape
    summary = []
    for n, info in figs.items():
        for c in info["checks"]:
            summary.append(f'<tr><td><a href="#fig{n}">Fig. {n}</a></td><td class="l">{e(c.claim)}</td>'
                           f"<td>{_badge(c.passed)}</td></tr>")
    n_pass = sum(c.passed for info in figs.values() for c in info["checks"])
    n_all = sum(len(info["checks"]) for info in figs.values())
    sections = "".join(_figure_section(n, info, pngs[n]) for n, info in figs.items())
    decisions = "".join(f"<dt><b>{e(k)}</b></dt><dd>{e(v)}</dd>" for k, v in DECISIONS)
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<title>asperity: reproduction of the paper</title>
<style>{_CSS}</style></head>
<body>
<h1>Reproduction of {e(PAPER)}</h1>
<p>Figures 3-9 and Table 1 recomputed with <code>asperity</code> {e(__version__)} (Greenwood-Williamson
asperity statistics, Hurtado-Kim friction stress, Maugis-Dugdale adhesion; Gaussian heights,
&nu; = {NU:g}, h = b). Each figure lists the paper's claims about it and whether our curves show them
(<b>PASS</b>) or not (<b>NOT SHOWN</b>); a claim that is not shown is reported as such, never tuned away.
Generated in {seconds:.1f} s.</p>
<h2>Summary: {n_pass} of {n_all} claims shown</h2>
<table><tr><th>figure</th><th class="l">claim</th><th>result</th></tr>{''.join(summary)}</table>
<p><a href="#table1">Table 1</a> &middot; <a href="#decisions">Decisions</a></p>
{sections}
{_table1_section(rows)}
<section id="decisions">
<h2>Decisions</h2>
<dl>{decisions}</dl>
</section>
<p class="small">Regenerate with <code>asperity.studies.reproduce(out_dir)</code>. Figures are
{FIGSIZE[0]:g} &times; {FIGSIZE[1]:g} in at {DPI} dpi.</p>
</body></html>
"""


def reproduce(out_dir, progress: Callable[[str], object] | None = None) -> dict:
    """Write every figure, Table 1 and ``index.html`` into ``out_dir``; return a summary.

    Parameters
    ----------
    out_dir : str or path
        Output directory (created if missing, inside an existing one; existing files of the
        same names are replaced).
        Every file is written atomically (to a temporary file, then renamed), so an
        interrupted run leaves complete files only, never a truncated one.
    progress : callable, optional
        Called with one line of text per figure when it is done (``"Fig 3: ... done in
        0.4 s"``), then once for Table 1 and once for ``index.html``.

    Returns
    -------
    dict
        ``out_dir``; ``files`` (every path written, as str); ``figures``: for each
        ``"fig3"`` ... ``"fig9"`` its ``png``, ``svg``, ``csv`` paths, ``seconds`` and
        ``checks`` (list of ``{"claim", "passed", "detail"}``); ``table1``: ``csv`` path and
        ``rows`` (dicts with the columns of ``table1.csv``); ``index``: the HTML path;
        ``checks_passed``, ``checks_total``; ``seconds``: the wall time.
    """
    out = Path(check_output_path(out_dir, "out_dir", directory=True))  # its parent must exist, as for -o
    if progress is not None:
        check_callable(progress, "progress")
    t_start = time.perf_counter()
    out.mkdir(exist_ok=True)
    say = progress if progress is not None else (lambda message: None)
    files: list[str] = []
    figs: dict[int, dict] = {}
    pngs: dict[int, bytes] = {}
    summary_figs: dict[str, dict] = {}
    for n, spec in FIGURES.items():
        t0 = time.perf_counter()
        data = spec.data()
        fig = spec.draw(data)
        png, svg, csv_path = (out / f"{spec.name}.{ext}" for ext in ("png", "svg", "csv"))
        save_figure(fig, png, svg)
        write_csv(csv_path, csv_rows(data), CSV_COLUMNS)
        checks = spec.checks(data)
        seconds = time.perf_counter() - t0
        figs[n] = {"data": data, "checks": checks, "seconds": seconds}
        pngs[n] = png.read_bytes()
        files += [str(png), str(svg), str(csv_path)]
        summary_figs[spec.name] = {
            "png": str(png), "svg": str(svg), "csv": str(csv_path), "seconds": seconds,
            "checks": [{"claim": c.claim, "passed": bool(c.passed), "detail": c.detail} for c in checks]}
        n_pass = sum(c.passed for c in checks)
        say(f"Fig {n}: {spec.short} ... {n_pass}/{len(checks)} claims shown, done in {seconds:.1f} s")

    t0 = time.perf_counter()
    table_path = out / "table1.csv"
    rows = write_table1_csv(table_path)
    files.append(str(table_path))
    agree = sum(abs(r["ratio"] - 1.0) <= 0.05 for r in rows)
    say(f"Table 1: pull-off force for {len(rows)} rows ... {agree} within 5 % of the paper, "
        f"done in {time.perf_counter() - t0:.1f} s")

    t0 = time.perf_counter()
    index = out / "index.html"
    atomic_write(index, _html(figs, pngs, rows, time.perf_counter() - t_start))
    files.append(str(index))
    say(f"index.html ... done in {time.perf_counter() - t0:.1f} s")

    checks_all = [c for info in figs.values() for c in info["checks"]]
    return {
        "out_dir": str(out),
        "files": files,
        "figures": summary_figs,
        "table1": {"csv": str(table_path), "rows": rows},
        "index": str(index),
        "checks_passed": sum(bool(c.passed) for c in checks_all),
        "checks_total": len(checks_all),
        "seconds": time.perf_counter() - t_start,
    }
