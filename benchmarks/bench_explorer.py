"""Update latency of ``asperity explore`` in headless Chromium (run: .venv/bin/python benchmarks/bench_explorer.py).

Target (issue #11): the plots show a slider move within 200 ms, for 200-point curves.

How it is measured: the explorer runs as ``asperity explore --port 0 --no-browser`` (a
subprocess, OPENBLAS_NUM_THREADS=1); Playwright drives Debian's Chromium.  In the page, a
capture-phase listener stamps ``performance.now()`` at the input event (the key press on
the slider's handle, or Enter in a typed entry); a listener on the load curve's Bokeh
data source stamps the moment the new data arrive (after the round trip: websocket to
the server, the library's computation of both 200-point curves and the pull-off,
websocket back); two ``requestAnimationFrame`` callbacks later the frame with the new
curves has been painted.  Reported: median and maximum over the moves, per case.
"""

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse  # noqa: E402
import statistics  # noqa: E402
import sys  # noqa: E402
from pathlib import Path  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from tests.explorer.browser import ExplorerProcess, open_browser, slider_handle, wait_ready  # noqa: E402

TARGET_MS = 200.0

_PROBE = """() => {
    window.__lat = {t0: null, samples: []};
    const s = Bokeh.documents[0].get_model_by_name('load');
    for (const type of ['keydown', 'pointerdown']) {
        document.addEventListener(type, () => { window.__lat.t0 = performance.now(); }, true);
    }
    s.properties.data.change.connect(() => {
        const t0 = window.__lat.t0, t1 = performance.now();
        requestAnimationFrame(() => requestAnimationFrame(() => {
            window.__lat.samples.push([t1 - t0, performance.now() - t0]);
        }));
    });
}"""


def _samples(page):
    return page.evaluate("() => window.__lat.samples")


def _wait(page, count):
    page.wait_for_function(f"() => window.__lat.samples.length >= {count}", timeout=15_000)


def measure_slider(page, key: str, moves: int):
    handle = slider_handle(page, key)
    handle.focus()
    start = len(_samples(page))
    for i in range(moves):
        page.keyboard.press("ArrowRight" if i % 2 == 0 else "ArrowLeft")
        _wait(page, start + i + 1)
    return _samples(page)[start:]


def measure_typed(page, key: str, values):
    start = len(_samples(page))
    box = page.locator(f".asp-input-{key} input")
    for i, value in enumerate(values):
        box.fill(value)
        box.press("Enter")
        _wait(page, start + i + 1)
    return _samples(page)[start:]


def cpu_seconds(pids) -> float:
    """CPU time (user + system) used so far by the processes ``pids`` (Linux /proc)."""
    total = 0.0
    for pid in pids:
        try:
            fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        total += (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")
    return total


def chromium_pids(profile: str) -> list[int]:
    """The Chromium processes using the user-data directory ``profile``."""
    out = []
    for proc in Path("/proc").iterdir():
        if proc.name.isdigit():
            try:
                if profile.encode() in (proc / "cmdline").read_bytes():
                    out.append(int(proc.name))
            except OSError:
                pass
    return out


def report(name: str, samples, cpu) -> bool:
    data = [s[0] for s in samples]
    painted = [s[1] for s in samples]
    ok = statistics.median(painted) <= TARGET_MS
    print(f"  {name:40s} data {statistics.median(data):6.1f} ms (max {max(data):6.1f})   "
          f"painted {statistics.median(painted):6.1f} ms (max {max(painted):6.1f})   "
          f"CPU/update: server {cpu[0]:5.1f} ms, browser {cpu[1]:5.1f} ms   "
          f"{'ok' if ok else 'SLOW'}  [{len(samples)} moves]")
    return ok


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--moves", type=int, default=20, help="slider moves per case")
    args = parser.parse_args()
    server = ExplorerProcess()
    ok = True
    print(f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
    try:
        with open_browser() as context:
            page = context.new_page()
            page.goto(server.url)
            wait_ready(page)
            page.evaluate(_PROBE)
            browser = chromium_pids(context.profile_dir)
            print(f"update latency, 200-point curves (target: median painted <= {TARGET_MS:g} ms), {server.url}")

            def run(name, measure, *a):
                pids = ([server.proc.pid], browser)
                before = [cpu_seconds(p) for p in pids]
                samples = measure(page, *a)
                cpu = [(cpu_seconds(p) - b) * 1e3 / len(samples) for p, b in zip(pids, before, strict=True)]
                return report(name, samples, cpu)

            ok &= run("dimensionless, slider alpha (adhesion)", measure_slider, "alpha", args.moves)
            ok &= run("dimensionless, slider gamma", measure_slider, "gamma", args.moves)
            ok &= run("dimensionless, typed beta", measure_typed, "beta", ["300", "3000"] * 5)
            page.goto(server.url + "?mode=physical")
            wait_ready(page)
            page.evaluate(_PROBE)
            ok &= run("physical (Au), slider sigma_s", measure_slider, "sigma_s_m", args.moves)
            ok &= run("physical (Au), slider w", measure_slider, "w_J_m2", args.moves)
    finally:
        server.stop()
    return 0 if ok else 1


if __name__ == "__main__":
    raise SystemExit(main())
