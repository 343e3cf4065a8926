"""Driving the explorer in real headless Chromium (Debian's /usr/bin/chromium) with Playwright.

Shared by the end-to-end tests, ``benchmarks/bench_explorer.py`` (update latency) and
``tests/explorer/screenshot.py`` (docs/img/explorer.png).  Never downloads a browser.

* :func:`browser_missing` says why no browser test can run here (None if one can);
  :func:`need_browser` skips a test for that reason, or fails it when the environment
  sets ``ASPERITY_REQUIRE_BROWSER=1`` (CI).
* :class:`ExplorerProcess` runs ``asperity explore --port 0 --no-browser`` in a
  subprocess, reads the address it prints, and stops it with SIGINT.
* :func:`open_browser` launches Chromium with a fresh user-data directory;
  :class:`Network` records every request and websocket of a page.
* The page helpers read Bokeh's data sources and models (``Bokeh.documents[0]``).
"""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from contextlib import contextmanager
from pathlib import Path
from urllib.parse import urlparse

CHROMIUM = "/usr/bin/chromium"
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                 "--disable-component-update", "--no-first-run"]
REQUIRE = "ASPERITY_REQUIRE_BROWSER"
LOCAL_HOSTS = ("127.0.0.1", "localhost")
ROOT = Path(__file__).resolve().parents[2]


def browser_missing() -> str | None:
    """Why the browser tests cannot run here, or None if they can."""
    try:
        import playwright.sync_api  # noqa: F401
    except ImportError:
        return "playwright is not installed (pip install -e '.[test]')"
    try:
        import bokeh  # noqa: F401
    except ImportError:
        return "bokeh is not installed (pip install -e '.[explore]')"
    if not os.access(CHROMIUM, os.X_OK):
        return f"no browser at {CHROMIUM} (apt-get install chromium)"
    return None


def need_browser() -> None:
    """Skip the calling test (or fixture) without a browser; fail instead if CI requires one."""
    import pytest

    reason = browser_missing()
    if reason is None:
        return
    if os.environ.get(REQUIRE) == "1":
        pytest.fail(f"{REQUIRE}=1 but the browser tests cannot run: {reason}")
    pytest.skip(reason)


class ExplorerProcess:
    """``asperity explore --port 0 --no-browser`` in a subprocess; ``url`` is the page's address."""

    def __init__(self, *extra: str, timeout: float = 60.0):
        env = {**os.environ, "OPENBLAS_NUM_THREADS": "1", "PYTHONUNBUFFERED": "1"}
        self.proc = subprocess.Popen([sys.executable, "-m", "asperity.cli", "explore", "--port", "0", "--no-browser",
                                      *extra], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                     env=env, cwd=ROOT)
        self.url = self._read_url(timeout)

    def _read_url(self, timeout: float) -> str:
        import selectors

        sel = selectors.DefaultSelector()
        sel.register(self.proc.stdout, selectors.EVENT_READ)
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            if sel.select(timeout=0.5):
                line = self.proc.stdout.readline()
                if "serving http" in line:
                    return line.split("serving ", 1)[1].split()[0]
                if line == "" and self.proc.poll() is not None:
                    break
        self.proc.kill()
        raise RuntimeError(f"asperity explore did not start: {self.proc.stderr.read()}")

    def stop(self, timeout: float = 20.0) -> tuple[int, str, str]:
        """Send SIGINT (Ctrl-C); return (exit status, rest of stdout, stderr)."""
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGINT)
        try:
            out, err = self.proc.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            out, err = self.proc.communicate()
        return self.proc.returncode, out, err


@contextmanager
def open_browser(**context_options):
    """A Playwright browser context of Debian's Chromium with a fresh user-data directory
    (its path in the context's ``profile_dir``)."""
    from playwright.sync_api import sync_playwright

    profile = tempfile.mkdtemp(prefix="asperity-chromium-")
    try:
        with sync_playwright() as p:
            context = p.chromium.launch_persistent_context(
                profile, executable_path=CHROMIUM, args=CHROMIUM_ARGS, headless=True, accept_downloads=True,
                **{"viewport": {"width": 1440, "height": 1000}, **context_options})
            context.profile_dir = profile
            try:
                yield context
            finally:
                context.close()
    finally:
        shutil.rmtree(profile, ignore_errors=True)


class Network:
    """Every request and websocket a page opens (URLs), and those not to this machine."""

    def __init__(self, page):
        self.urls: list[str] = []
        page.on("request", lambda request: self.urls.append(request.url))
        page.on("websocket", lambda ws: self.urls.append(ws.url))

    def foreign(self) -> list[str]:
        out = []
        for url in self.urls:
            parsed = urlparse(url)
            if parsed.scheme in ("data", "blob", "about"):
                continue
            if parsed.hostname not in LOCAL_HOSTS:
                out.append(url)
        return out


# -- the page ---------------------------------------------------------------------------------
_DOC = "Bokeh.documents[0]"


def wait_ready(page, timeout: float = 30_000) -> None:
    """Wait until the page's document is connected and its load curve is plotted."""
    page.wait_for_function(f"() => window.Bokeh && Bokeh.documents.length > 0 && "
                           f"{_DOC}.get_model_by_name('load') && {_DOC}.get_model_by_name('load').data.P.length > 0",
                           timeout=timeout)


def source_data(page, name: str) -> dict:
    """The columns of the data source called ``name`` (lists of floats; NaN kept)."""
    return page.evaluate(f"""(name) => {{
        const data = {_DOC}.get_model_by_name(name).data;
        const out = {{}};
        for (const [k, v] of (data instanceof Map ? data.entries() : Object.entries(data))) out[k] = Array.from(v);
        return out;
    }}""", name)


def model_property(page, name: str, prop: str):
    """A property of the model called ``name`` (e.g. a Div's text)."""
    return page.evaluate(f"([n, p]) => {_DOC}.get_model_by_name(n)[p]", [name, prop])


def query_of(page) -> str:
    """The query string of the page's address, without '?'."""
    return urlparse(page.url).query


def watch_source(page, name: str = "load") -> None:
    """Start counting changes of a data source (``window.__changes``); see :func:`changes`."""
    page.evaluate(f"""(name) => {{
        window.__changes = 0;
        const s = {_DOC}.get_model_by_name(name);
        s.properties.data.change.connect(() => {{ window.__changes += 1; }});
    }}""", name)


def changes(page) -> int:
    return page.evaluate("() => window.__changes")


def wait_changes(page, count: int, timeout: float = 15_000) -> None:
    page.wait_for_function(f"() => window.__changes >= {count}", timeout=timeout)


def type_into(page, key: str, text: str) -> None:
    """Type ``text`` into the entry of field ``key`` and press Enter."""
    box = page.locator(f".asp-input-{key} input")
    box.fill(text)
    box.press("Enter")


def slider_handle(page, key: str):
    return page.locator(f".asp-slider-{key} .noUi-handle").first
