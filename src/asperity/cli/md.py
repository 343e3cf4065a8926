"""``asperity md``: one Maugis-Dugdale asperity in Maugis' units, or its pull-off.

The library (:func:`asperity.md_solve`, :func:`asperity.md_pull_off`) checks lambda and
the penetrations; its ValueError becomes the one-line error.
"""

from __future__ import annotations

import argparse

from ._args import add_output_arguments, decimal, parse_list

NAME = "md"
HELP = "one Maugis-Dugdale asperity"
DESCRIPTION = ("One Maugis-Dugdale sphere in Maugis' units: radius A, load P/(pi w R), m = c/a at "
               "penetrations Delta; or its pull-off.")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--lam", type=decimal, required=True, help="Maugis parameter lambda > 0 (Eq 14)")
    what = parser.add_mutually_exclusive_group(required=True)
    what.add_argument("--delta", metavar="LIST",
                      help="penetrations Delta: 'a,b,c' or 'start:stop:count' (linearly spaced)")
    what.add_argument("--pulloff", action="store_true",
                      help="load- and displacement-controlled pull-off")
    add_output_arguments(parser, plot=False)


def run(args) -> None:
    import numpy as np

    from ..maugis_dugdale import md_pull_off, md_solve
    from ._output import format_rows, output_format, write_outputs

    if args.pulloff:
        rows = []
        for control in ("load", "displacement"):
            p = md_pull_off(args.lam, control)
            rows.append({"control": control, "P": p.P, "A": p.A, "delta": p.delta})
    else:
        delta = parse_list(args.delta, log=False, name="--delta")
        A, P, t = md_solve(delta, args.lam)
        m = np.sqrt(1.0 + t * t)
        rows = [{"delta": float(x), "A": float(a), "P": float(p), "m": float(mm)}
                for x, a, p, mm in zip(delta, A, P, m, strict=True)]
    write_outputs(format_rows(rows, output_format(args)), args)
