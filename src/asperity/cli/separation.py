"""``asperity separation``: quantities versus separation d/sigma (Figs 7-8), dimensionless or physical."""

from __future__ import annotations

import argparse

from ._args import UNITS, add_contact_arguments, add_interaction_argument, add_model_arguments, add_output_arguments

NAME = "separation"
HELP = "quantities versus separation d/sigma (Figs 7-8)"
DESCRIPTION = "Normal and friction force, mu, area, pressure and contacts at given separations."
EPILOG = f"Columns:\n{UNITS}"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_model_arguments(parser)
    add_contact_arguments(parser)
    add_interaction_argument(parser)
    parser.add_argument("--d", metavar="LIST",
                        help="separations d/sigma: 'a,b,c' or 'start:stop:count' (linearly spaced)")
    parser.add_argument("--separation", metavar="LIST",
                        help="physical separations with a length unit, e.g. 0nm:10nm:21 (with a physical contact)")
    add_output_arguments(parser)


def run(args) -> None:
    from ._curve import run_curve

    run_curve(args, "separation")
