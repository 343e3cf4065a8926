"""``asperity surface``: Greenwood-Williamson summit parameters of a measured surface."""

from __future__ import annotations

import argparse

from ._args import add_surface_arguments, output_file

NAME = "surface"
HELP = "GW summit parameters of a measured surface (AFM map, profile)"
DESCRIPTION = ("Read a height map or line scan (any format SurfaceTopography reads) and compute the summit "
               "parameters sigma_s, R, eta two ways: from the spectral moments m0, m2, m4 (Nayak/McCool) and "
               "by summit detection. With --material, also alpha and beta (Eq 7). Reports the skewness and "
               "kurtosis of the detected summit heights and ranks the height distributions fitted to them by "
               "AIC; pass the best one's spelling to --heights of the other commands, or write the summits "
               "with --summits FILE and use --heights best:FILE or empirical:FILE. Needs asperity[topography].")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_surface_arguments(parser)
    parser.add_argument("--material", help="material name for alpha, beta (its Burgers vector b)")
    parser.add_argument("--b", help="Burgers vector, a length (e.g. 0.2885nm), instead of --material")
    parser.add_argument("--summits", metavar="FILE", type=output_file,
                        help="also write the detected summit heights (metres, one per line after the header "
                             "line z_m) to FILE, for --heights empirical:FILE or best:FILE")
    parser.add_argument("--format", choices=("table", "json"), default=None,
                        help="output format (default: a readable summary on a terminal, JSON otherwise)")
    parser.add_argument("-o", "--output", metavar="FILE", type=output_file,
                        help="write to FILE instead of standard output")


def run(args) -> None:
    from .._optional import require
    from ._args import UsageError, quantity, read_kwargs_from_args
    from ._output import check_targets, format_json, output_format, output_targets, write_outputs

    require("SurfaceTopography", purpose="surface", extra="topography")
    from ..topography import analyse_surface

    kwargs = read_kwargs_from_args(args)
    b = quantity(args.b, "m", "--b") if args.b else None
    if args.material and b is not None:
        raise UsageError("give --material or --b, not both")
    mat = None
    if args.material:
        from ..materials import material

        mat = material(args.material)
    check_targets(args, output_targets(args))  # before anything is written
    result = analyse_surface(args.file, material=mat, b=b, **kwargs)
    fmt = output_format(args, piped="json")
    text = result.summary() + "\n" if fmt == "table" else format_json(result.to_dict(), indent=1)
    also = [(args.summits, result.write_summits, "summits file")] if args.summits else []
    write_outputs(text, args, also=also)  # all the files or none
