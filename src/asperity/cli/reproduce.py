"""``asperity reproduce``: recompute the paper's Figs 3-9 and Table 1 into a directory.

Every file is written atomically by :func:`asperity.studies.reproduce`, so an
interrupted run leaves complete files (from this run or an earlier one), never a
truncated one.
"""

from __future__ import annotations

import argparse

from ._args import output_dir

NAME = "reproduce"
HELP = "recompute the paper's Figs 3-9 and Table 1"
DESCRIPTION = ("Recompute Figs 3-9 and Table 1 of the paper: PNG, SVG and CSV per figure, table1.csv and an "
               "index.html report.")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--out", default="asperity-paper", metavar="DIR", type=output_dir,
                        help="output directory (default: ./asperity-paper)")


def run(args) -> None:
    import time

    from .._optional import require
    from ._args import UsageError
    from ._output import say

    require("matplotlib", purpose="reproduce", extra="plot")
    from ..studies.report import reproduce

    start = time.perf_counter()

    def progress(message):
        say(f"{message}\n")

    try:
        reproduce(args.out, progress=progress)
    except OSError as exc:
        raise UsageError(f"cannot write to {args.out!r}: {exc.strerror or exc}") from None
    say(f"done in {time.perf_counter() - start:.1f} s: open {args.out}/index.html\n")
