"""docs/cli.md, the command-line reference, is every command's --help as the parser prints it.

Regenerate it after changing an option: ``python -m tests.cli.test_reference`` (from the
repository's root).  The test fails when the page and the parser disagree, so no option can
go undocumented.
"""

import contextlib
import io
import os
import re
import sys
from pathlib import Path
from unittest import mock

from asperity.cli import COMMANDS, build_parser

PAGE = Path(__file__).resolve().parents[2] / "docs" / "cli.md"

#: argparse's layout changes between Python versions; the page holds this version's.
PYTHON = f"{sys.version_info[0]}.{sys.version_info[1]}"

HEAD = f"""# Command-line reference

Every command's `--help`, as `asperity COMMAND --help` prints it (generated from the parser
by `python -m tests.cli.test_reference` under Python {PYTHON}; a test keeps it current).  The guides explain the
options in context: [physical.md](physical.md) (units, materials, surfaces),
[cycle.md](cycle.md), [fitting.md](fitting.md), [heights.md](heights.md),
[plasticity.md](plasticity.md), [sweeps.md](sweeps.md), [validation.md](validation.md)
(`bem`), [explorer.md](explorer.md).
"""


def _help(argv) -> str:
    out = io.StringIO()
    with mock.patch.dict(os.environ, {"COLUMNS": "100"}), contextlib.redirect_stdout(out):
        try:
            build_parser().parse_args(argv)
        except SystemExit:
            pass
    return out.getvalue().replace("usage: pytest", "usage: asperity").replace("usage: __main__.py", "usage: asperity")


def reference() -> str:
    parts = [HEAD, "## asperity\n", "```text", _help(["--help"]).rstrip(), "```\n"]
    for name in COMMANDS:
        parts += [f"## asperity {name}\n", "```text", _help([name, "--help"]).rstrip(), "```\n"]
    return "\n".join(parts)


def _options(text: str) -> dict[str, list[str]]:
    """Each section's (command's) options, whatever argparse's layout."""
    sections = re.split(r"^## ", text, flags=re.M)[1:]
    return {s.split("\n", 1)[0]: sorted(set(re.findall(r"(?<![\w-])--[a-z][a-z0-9-]*", s))) for s in sections}


def test_the_reference_page_is_every_commands_help():
    page, fresh = PAGE.read_text(), reference()
    # every option of every command is in that command's section
    assert _options(page) == _options(fresh), "docs/cli.md is stale: python -m tests.cli.test_reference"
    if f"under Python {PYTHON};" in page:  # the version that wrote it: the very text
        assert page == fresh, "docs/cli.md is stale: python -m tests.cli.test_reference"


if __name__ == "__main__":
    PAGE.write_text(reference())
    print(f"wrote {PAGE}")
