"""``asperity materials``: the shipped materials table (SI units, with sources)."""

from __future__ import annotations

import argparse

from ._args import add_output_arguments

NAME = "materials"
HELP = "list the materials table (SI units, with sources)"
DESCRIPTION = ("The shipped materials table: E [Pa], nu, Burgers vector b [m], work of adhesion w [J/m^2], "
               "hardness H [Pa] and the Nix-Gao size-effect pair H0 [Pa], h* [m] (docs/plasticity.md); "
               "empty = missing, with sources.")

#: Columns listed, in order (``sources`` only with ``--sources``).
KEYS = ("name", "kind", "E_Pa", "nu", "b_m", "work_of_adhesion_J_m2", "hardness_Pa", "ise_H0_Pa", "ise_h_star_m")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--sources", action="store_true", help="include the source of every number")
    add_output_arguments(parser, plot=False)


def run(args) -> None:
    from ..materials import material_table
    from ._output import format_rows, output_format, write_outputs

    keys = [*KEYS, "sources"] if args.sources else list(KEYS)
    fmt = output_format(args)
    missing = None if fmt == "json" else ""  # JSON's null (a CLI check found "" among the numbers)
    rows = [{k: (missing if row.get(k) is None else row.get(k)) for k in keys} for row in material_table()]
    write_outputs(format_rows(rows, fmt), args)
