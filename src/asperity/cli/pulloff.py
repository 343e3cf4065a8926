"""``asperity pulloff``: the pull-off force (Table 1), dimensionless or physical."""

from __future__ import annotations

import argparse

from .._numbers import strict_float
from ._args import UsageError, add_contact_arguments, add_model_arguments, add_output_arguments
from ._build import contact_from_args, is_physical, model_from_args

NAME = "pulloff"
HELP = "pull-off force (Table 1)"
DESCRIPTION = ("Largest tensile force |P|/(N G b^2) over separations up to d_max, and where it occurs; with a "
               "physical contact in newtons and metres, with the real contact area there.")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_model_arguments(parser, gamma_required=True)
    add_contact_arguments(parser)
    parser.add_argument("--d-max", "--dmax", dest="d_max", default=None,
                        help="largest separation d/sigma searched, in units of sigma (sigma_s with a physical "
                             "contact, which also takes a length, e.g. 20nm); default: 10 beyond the end of the "
                             "asperities' stable branch, i.e. 10 without adhesion range")
    add_output_arguments(parser, plot=False)


def run(args) -> None:
    from ._output import format_json, format_physical, format_rows, output_format, write_outputs

    fmt = output_format(args)
    if is_physical(args):
        contact = contact_from_args(args)
        row = contact.pull_off(_d_max(args.d_max, physical=True)).to_dict()
        write_outputs(format_physical([row], fmt, contact, comments=not args.no_comments), args)
        return
    if args.gamma is None:
        raise UsageError("pulloff needs --gamma (the adhesion parameter)")
    po = model_from_args(args).pull_off(_d_max(args.d_max, physical=False))
    row = po.to_dict()  # the API's keys: pull_off, d, exists
    write_outputs(format_json(row) if fmt == "json" else format_rows([row], fmt), args)


def _d_max(text, physical: bool):
    """--d-max: a number (units of sigma), or with a physical contact a length with its unit."""
    if text is None:
        return None
    try:
        return strict_float(text)
    except ValueError:
        if physical:
            return text  # a length: PhysicalContact.pull_off converts it and names a bad one
        raise UsageError(f"--d-max: expected a number (d/sigma), got {text!r}") from None
