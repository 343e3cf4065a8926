"""Write the explorer's screenshot for the docs: ``python -m tests.explorer.screenshot [docs/img/explorer.png]``.

Starts ``asperity explore`` on a free port, opens the default view in headless Chromium
(the same tooling as the end-to-end tests), and saves the page.
"""

import sys
from pathlib import Path

from .browser import ROOT, ExplorerProcess, open_browser, wait_ready

#: The view shown in the docs: the defaults (Table 1's second row, with adhesion).
VIEW = ""


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    out = Path(argv[0]) if argv else ROOT / "docs" / "img" / "explorer.png"
    server = ExplorerProcess()
    try:
        with open_browser(viewport={"width": 1400, "height": 900}) as context:
            page = context.new_page()
            page.goto(server.url + VIEW)
            wait_ready(page)
            page.wait_for_timeout(1000)  # let every plot paint
            page.screenshot(path=str(out), full_page=False)
    finally:
        server.stop()
    print(f"wrote {out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
