"""``asperity cycle``: an approach-retract cycle (hysteresis, energy dissipated, pull-off), dimensionless
or physical, under displacement control or through the instrument's spring."""

from __future__ import annotations

import argparse

from .._numbers import strict_float
from ..quantities import CURVE_COLUMNS, CYCLE_QUANTITIES
from ._args import (
    UsageError,
    add_contact_arguments,
    add_model_arguments,
    add_output_arguments,
    integer,
    parse_list,
    quantity,
    quantity_list,
)
from ._build import contact_from_args, is_physical, model_from_args, title

NAME = "cycle"
HELP = "approach-retract cycle: hysteresis, energy dissipated, pull-off on retraction"
DESCRIPTION = ("Approach from --dmax to the closest approach (--dmin, or the separation carrying --preload), then "
               "retract: both branches with every column of a curve and a 'branch' column, the pull-off force "
               "on retraction and the energy dissipated per cycle (Fuller-Tabor with Maugis-Dugdale asperities). "
               "With --stiffness, the curve an instrument measures through its spring, with whole-surface jumps.")

#: option -> (cycle quantity, SI unit of its physical form)
OPTIONS = {"dmin": ("d_min", "m"), "preload": ("preload", "N"), "dmax": ("d_max", "m"),
           "stiffness": ("stiffness", "N/m"), "u_in": ("u_in", "m")}

EPILOG = ("Rows: branch (approach, retract), d_base and jump with --stiffness, then:\n"
          + "\n".join(f"  {name:9s} {q.meaning}" for name, q in CURVE_COLUMNS.items())
          + "\n  d_base    " + CYCLE_QUANTITIES["d_base"].meaning
          + "\n  jump      True where the step from the previous row is a whole-surface jump"
          + "\n--format json: one object with rows, pull_off (force, d), energy (energy dissipated per cycle,"
          + "\none asperity's loop energy, fraction of asperities through the loop, jumps' share), friction."
          + "\nWith a physical contact (--material ...) the same in SI units (d_m, P_N, ..., energy_J, energy_J_m2),"
          + "\nafter '#' lines describing the contact (--no-comments: none); JSON then holds it as \"contact\".")


def _help(option: str) -> str:
    name, unit = OPTIONS[option]
    q = CYCLE_QUANTITIES[name]
    return f"{q.meaning}; with --material a quantity in {unit} (e.g. " + \
        {"m": "2nm", "N": "1mN", "N/m": "0.1N/m"}[unit] + ")"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_model_arguments(parser, gamma_required=True)
    add_contact_arguments(parser)
    g = parser.add_argument_group("cycle (give --dmin or --preload)")
    g.add_argument("--dmin", "--d-min", dest="dmin", metavar="D", help=_help("dmin"))
    g.add_argument("--preload", metavar="P", help=_help("preload"))
    g.add_argument("--dmax", "--d-max", dest="dmax", metavar="D", help=_help("dmax"))
    g.add_argument("--stiffness", metavar="K", help=_help("stiffness") + "; default inf (displacement control)")
    g.add_argument("--u-in", dest="u_in", metavar="U", help=_help("u_in") + "; default 0 (first touch)")
    g.add_argument("--d", metavar="LIST", help="evaluate both branches at these separations instead of the path: "
                                               "'a,b,c' or 'start:stop:count' (lengths with --material, e.g. "
                                               "0nm:10nm:21); displacement control only")
    g.add_argument("--points", metavar="N", type=integer, default=200,
                   help="points per branch on the path (default 200)")
    add_output_arguments(parser)


def _number(text: str | None, option: str, physical: bool):
    """The option's value: a quantity in its SI unit with a physical contact, else a plain number."""
    if text is None:
        return None
    if physical and option == "stiffness":
        from ..physical_cycle_inputs import infinite_stiffness

        if infinite_stiffness(text, "--stiffness"):
            return float("inf")
    if physical:
        return quantity(text, OPTIONS[option][1], f"--{option.replace('_', '-')}")
    try:
        return strict_float(text)
    except ValueError:
        raise UsageError(f"--{option.replace('_', '-')}: expected a number, got {text!r} (quantities with units "
                         "need a physical contact: --material ...)") from None


def _rows(result) -> list[dict]:
    """One dict per row of ``result.columns()``: text, booleans and floats as they are."""
    cols = result.columns()
    conv = {k: (str if v.dtype.kind in "US" else bool if v.dtype.kind == "b" else float) for k, v in cols.items()}
    return [{k: conv[k](v[i]) for k, v in cols.items()} for i in range(len(result))]


def run(args) -> None:
    from ._output import comment_header, format_json, format_rows, output_format, write_outputs

    physical = is_physical(args)
    values = {opt: _number(getattr(args, opt), opt, physical) for opt in OPTIONS}
    if (values["dmin"] is None) == (values["preload"] is None):  # in the options' words (a CLI check)
        raise UsageError("give exactly one of --dmin (the closest approach) and --preload (the largest compressive "
                         "load)")
    if args.d is not None and values["stiffness"] is not None and values["stiffness"] != float("inf"):
        raise UsageError("with --stiffness the measured path is computed: give --points instead of --d")
    kwargs = {"d_min": values["dmin"], "preload": values["preload"], "d_max": values["dmax"], "n": args.points,
              "u_in": 0.0 if values["u_in"] is None else values["u_in"]}
    if args.d is not None:
        kwargs["d"] = quantity_list(args.d, "m", log=False, name="--d") if physical else \
            parse_list(args.d, log=False, name="--d")
    contact = None
    if physical:
        contact = contact_from_args(args)
        result = contact.cycle(stiffness=values["stiffness"], **kwargs)
    else:
        if args.gamma is None:
            raise UsageError("cycle needs --gamma (the adhesion parameter; 0 for Hertz)")
        from ..cycle import compute_cycle
        from ..cycle_integrals import CycleIntegrals

        stiffness = float("inf") if values["stiffness"] is None else values["stiffness"]
        result = compute_cycle(CycleIntegrals(model_from_args(args), kwargs.pop("u_in")), stiffness=stiffness,
                               **kwargs)
    fmt = output_format(args)
    rows = _rows(result)
    if fmt == "json":
        head = {} if contact is None else {"contact": contact.to_dict()}
        text = format_json({**head, "rows": rows, **result.to_dict()}, indent=1)
    else:
        text = comment_header(contact, comments=not args.no_comments) + format_rows(rows, fmt)
        if fmt == "table":
            text += _summary(result)

    def plot(path, fmt_):
        from ..cycle_plot import plot_cycle

        ax = plot_cycle(result, title=title(args, contact))
        ax.figure.savefig(path, dpi=150, format=fmt_)

    write_outputs(text, args, plot=plot)


def _summary(result) -> str:
    """Two lines under the table: the pull-off and the energy dissipated."""
    d = result.to_dict()
    po, en = d["pull_off"], d["energy"]
    return "\n" + "\n".join(f"{key}: " + ", ".join(f"{k}={v:.6g}" if isinstance(v, float) else f"{k}={v}"
                                                  for k, v in part.items())
                            for key, part in (("pull_off", po), ("energy", en))) + "\n"
