"""``asperity load``: quantities versus normal load (Figs 3-6, 9), dimensionless or physical."""

from __future__ import annotations

import argparse

from ._args import UNITS, add_contact_arguments, add_interaction_argument, add_model_arguments, add_output_arguments

NAME = "load"
HELP = "quantities versus normal load (Figs 3-6, 9)"
DESCRIPTION = "Quantities at the stable separation for each normal load."
EPILOG = f"Columns:\n{UNITS}"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_model_arguments(parser)
    add_contact_arguments(parser)
    add_interaction_argument(parser)
    parser.add_argument("--P", metavar="LIST",
                        help="loads P/(N G b^2): 'a,b,c' or 'start:stop:count' (spaced logarithmically)")
    parser.add_argument("--load", metavar="LIST",
                        help="physical loads with a force unit, e.g. 1mN:1N:50 (spaced logarithmically; "
                             "with a physical contact)")
    add_output_arguments(parser)


def run(args) -> None:
    from ._curve import run_curve

    run_curve(args, "load")
