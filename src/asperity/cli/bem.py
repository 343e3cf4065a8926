"""``asperity bem``: the statistical model beside a full boundary-element contact of a measured surface."""

from __future__ import annotations

import argparse

from ._args import add_body_arguments, add_output_arguments, add_surface_arguments, decimal, integer

NAME = "bem"
#: The library's interaction names and boundary-element tolerance (asperity.interaction.INTERACTIONS,
#: asperity.validation.bem.DEFAULT_TOLERANCE), written out so that ``--help`` imports no numpy
#: (tests/cli/test_bem.py checks they are the library's).
INTERACTIONS = ("none", "cgp2008")
DEFAULT_TOLERANCE = 1e-4
HELP = "check the GW and other models against a boundary-element contact of a surface"
DESCRIPTION = ("Solve the full elastic (hard-wall, non-adhesive) contact of a measured surface pressed on a "
               "half-space with boundary elements (ContactMechanics), and put the models beside it for the same "
               "surface, material and loads: Greenwood-Williamson (summit parameters spectral and detected), and "
               "with --model the interacting and coalescing Hertzian asperities on the surface's own summits "
               "(icha), Persson's area (persson) and the Bush-Gibson-Thomas light-load asymptote (bgt): real "
               "area, mean gap, contact spots, and the deviation. Loads are total forces on the scanned area. "
               "Needs asperity[bem].")
EPILOG = ("Columns (SI units): P_N load, p_Pa nominal pressure, fraction_bem real/nominal area, area_*_m2 real "
          "areas, dev_* = A_model/A_BEM - 1, gap_*_m mean gaps, sep_*_m approach (non-periodic only), spots_bem "
          "contact spots, contacts_* GW asperities in contact, spots_icha ICHA contact spots, iterations_bem.\n"
          "The table and CSV start with '#' lines describing the GW model's contact for each summit method "
          "(--no-comments: none); JSON holds them as \"contacts\". The comparison is elastic and non-adhesive "
          "(the boundary-element solution is), so the adhesion and plasticity options do not apply.\n"
          "Example: asperity bem scan.npy --size 4um,4um --unit nm --material Au --load 1mN:100mN:8 --grid 256 "
          "--model gw,icha,persson")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_surface_arguments(parser)
    add_body_arguments(parser, adhesion=False)  # its E* drives both solutions
    parser.add_argument("--load", required=True, metavar="LIST",
                        help="total forces on the scanned area with a force unit, e.g. 1mN:1N:8 (spaced "
                             "logarithmically) or 1mN,5mN")
    parser.add_argument("--grid", type=integer, metavar="N",
                        help="average the scan down to at most N points per axis first (e.g. 512)")
    parser.add_argument("--periodic", action=argparse.BooleanOptionalAction, default=None,
                        help="periodic or free boundaries (default: as the file says; measured scans are free)")
    parser.add_argument("--interaction", default="none", choices=INTERACTIONS,
                        help="asperity-interaction correction of the GW model: none (plain GW) or cgp2008")
    parser.add_argument("--model", action="append", metavar="LIST",
                        help="models beside the boundary elements, comma-separated (or the option repeated): gw "
                             "(default), icha, persson, bgt")
    parser.add_argument("--tolerance", type=decimal, default=DEFAULT_TOLERANCE,
                        help="boundary-element convergence: penetration below this fraction of the rms height "
                             "and tensile pixel forces below it times the mean pixel force "
                             f"(default {DEFAULT_TOLERANCE:g})")
    parser.add_argument("--maxiter", type=integer, default=10000,
                        help="boundary-element iterations per load at most (default 10000)")
    parser.add_argument("--quiet", action="store_true", help="no progress report on standard error")
    parser.add_argument("--no-comments", action="store_true",
                        help="leave out the '#' lines describing the model's contacts")
    add_output_arguments(parser)


def run(args) -> None:
    import warnings

    from .._optional import require
    from ._args import quantity_list, read_kwargs_from_args
    from ._build import SurfaceNote, material_from_args
    from ._output import comment_header, format_json, format_rows, output_format, write_outputs

    require("ContactMechanics", purpose="asperity bem", extra="bem")
    from ..validation import validate_surface

    loads = quantity_list(args.load, "N", log=True, name="--load")
    result = validate_surface(args.file, loads, material=_material(args, material_from_args), grid=args.grid,
                              periodic=args.periodic, interaction=args.interaction,
                              models=",".join(args.model or ["gw"]), progress=not args.quiet,
                              tolerance=args.tolerance, maxiter=args.maxiter, **read_kwargs_from_args(args))
    fmt = output_format(args)
    if fmt == "json":
        text = format_json({"contacts": {m: c.to_dict() for m, c in result.contacts.items()}, **result.to_dict()},
                           indent=1)
    else:
        cols = result.columns()
        header = "".join(f"# summits {m}:\n" + comment_header(c) for m, c in result.contacts.items()) \
            if not args.no_comments else ""
        text = header + format_rows([{k: v[i] for k, v in cols.items()} for i in range(len(result))], fmt)
    write_outputs(text, args, plot=lambda path, image: result.plot(path, image))
    for message in result.parameters["warnings"]:  # notes, as every command prints the scan's doubts
        warnings.warn(f"surface {args.file}: {message}", SurfaceNote, stacklevel=1)


def _material(args, material_from_args):
    """The bodies; two bodies with different Burgers vectors and no ``--b`` get the nominal one
    of :func:`asperity.validation.validate_surface` (it only scales the groups of this
    non-adhesive comparison), with a note, rather than a refusal."""
    import argparse as _argparse
    import warnings

    from ..validation.compare import NOMINAL_B
    from ._build import SurfaceNote

    try:
        return material_from_args(args)
    except ValueError:
        if args.b is not None:
            raise
        material_from_args(_argparse.Namespace(**{**vars(args), "b": "1m"}))  # any other fault is raised here
    warnings.warn(f"the bodies have different Burgers vectors: the GW model uses b = {NOMINAL_B:g} m, on which this "
                  "comparison (no adhesion, no friction) does not depend (--b sets it)", SurfaceNote, stacklevel=2)
    return material_from_args(_argparse.Namespace(**{**vars(args), "b": f"{NOMINAL_B!r}m"}))
