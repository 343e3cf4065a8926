"""The ``asperity`` command line.

``asperity reproduce`` recomputes the paper's figures and Table 1; ``separation``,
``load``, ``pulloff`` and ``md`` compute curves for one's own parameters.  Every error
prints one line and exits with status 2.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time

import numpy as np

from ._version import __version__
from .curves import COLUMNS, Model
from .maugis_dugdale import md_branch_end, md_pull_off, md_solve
from .physical import PHYSICAL_COLUMNS
from .quantities import MODEL_PARAMETERS

__all__ = ["main"]

UNITS = ("\n".join(f"  {name:9s} {meaning}" for name, meaning in COLUMNS.items())
         + "\nWith --material (SI):\n"
         + "\n".join(f"  {col:11s} [{unit}] {meaning}" for col, unit, meaning in PHYSICAL_COLUMNS.values()))

MODEL_HELP = {name: MODEL_PARAMETERS[name].help() for name in ("alpha", "beta", "gamma", "nu", "h_over_b")}


class UsageError(Exception):
    """A problem with the command line or its values: one line, exit status 2."""


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # one line, no usage dump
        raise UsageError(message)


def parse_list(text: str, *, log: bool, name: str) -> np.ndarray:
    """``a,b,c`` or ``start:stop:count`` (log-spaced if ``log``, else linear)."""
    try:
        if ":" in text:
            parts = text.split(":")
            if len(parts) != 3:
                raise ValueError
            start, stop = float(parts[0]), float(parts[1])
            count = int(parts[2])
            if count < 1:
                raise UsageError(f"{name}: count in start:stop:count must be >= 1, got {count}")
            if log:
                if start <= 0 or stop <= 0:
                    raise UsageError(f"{name}: a log-spaced range start:stop:count needs start, "
                                     f"stop > 0 (use a comma list for zero or negative loads)")
                return np.geomspace(start, stop, count)
            return np.linspace(start, stop, count)
        values = np.array([float(v) for v in text.split(",") if v.strip() != ""])
    except ValueError:
        raise UsageError(f"{name}: expected numbers 'a,b,c' or 'start:stop:count', got {text!r}") from None
    if values.size == 0:
        raise UsageError(f"{name}: no values given")
    if not np.all(np.isfinite(values)):
        raise UsageError(f"{name}: values must be finite, got {text!r}")
    return values


def _model_args(p: argparse.ArgumentParser):
    g = p.add_argument_group("model parameters (dimensionless), or a physical contact below")
    g.add_argument("--alpha", type=float, help=MODEL_HELP["alpha"])
    g.add_argument("--beta", type=float, help=MODEL_HELP["beta"])
    g.add_argument("--gamma", type=float, default=None, help=MODEL_HELP["gamma"])
    g.add_argument("--nu", type=float, default=None, help=MODEL_HELP["nu"])
    g.add_argument("--h-over-b", dest="h_over_b", type=float, default=1.0, help=MODEL_HELP["h_over_b"])
    ph = p.add_argument_group(
        "physical contact (SI results; quantities with units, e.g. 2nm, 1um, 1e12/m^2, 1mm^2)")
    ph.add_argument("--material", help="material name from the table (asperity materials lists them), "
                                       "e.g. Au, Si, Au/Au")
    ph.add_argument("--sigma", help="standard deviation of summit heights sigma_s, a length (e.g. 2nm)")
    ph.add_argument("--radius", help="mean summit radius R, a length (e.g. 1um)")
    ph.add_argument("--density", help="summit density eta, per area (e.g. 1e12/m^2)")
    ph.add_argument("--area", help="nominal contact area, an area (e.g. 1mm^2)")
    ph.add_argument("--no-adhesion", action="store_true",
                    help="ignore the material's work of adhesion (Hertz contacts, gamma = 0)")


def _output_args(p: argparse.ArgumentParser, plot: bool = True):
    g = p.add_argument_group("output")
    g.add_argument("--format", choices=("table", "csv", "json"), default=None,
                   help="output format (default: table on a terminal, csv otherwise)")
    g.add_argument("-o", "--output", metavar="FILE", help="write to FILE instead of standard output")
    if plot:
        g.add_argument("--plot", metavar="FILE.png", help="also draw the curve to a PNG (needs matplotlib)")


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(
        prog="asperity",
        description="Multi-asperity contact, adhesion and friction (Greenwood-Williamson + "
                    "Hurtado-Kim + Maugis-Dugdale).",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog=f"Output columns and units:\n{UNITS}",
    )
    parser.add_argument("--version", action="version", version=f"asperity {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)

    rep = sub.add_parser("reproduce", help="recompute the paper's Figs 3-9 and Table 1",
                         description="Recompute Figs 3-9 and Table 1 of the paper: PNG, SVG and "
                                     "CSV per figure, table1.csv and an index.html report.")
    rep.add_argument("--out", default="asperity-paper", metavar="DIR",
                     help="output directory (default: ./asperity-paper)")

    fmt = argparse.RawDescriptionHelpFormatter
    sep = sub.add_parser("separation", help="quantities versus separation d/sigma (Figs 7-8)",
                         formatter_class=fmt, epilog=f"Columns:\n{UNITS}",
                         description="Normal and friction force, mu, area, pressure and contacts "
                                     "at given separations.")
    _model_args(sep)
    sep.add_argument("--d", metavar="LIST",
                     help="separations d/sigma: 'a,b,c' or 'start:stop:count' (linearly spaced)")
    sep.add_argument("--separation", metavar="LIST",
                     help="physical separations with a length unit, e.g. 0nm:10nm:21 (with --material)")
    _output_args(sep)

    load = sub.add_parser("load", help="quantities versus normal load (Figs 3-6, 9)",
                          formatter_class=fmt, epilog=f"Columns:\n{UNITS}",
                          description="Quantities at the stable separation for each normal load.")
    _model_args(load)
    load.add_argument("--P", metavar="LIST",
                      help="loads P/(N G b^2): 'a,b,c' or 'start:stop:count' (spaced logarithmically)")
    load.add_argument("--load", metavar="LIST",
                      help="physical loads with a force unit, e.g. 1mN:1N:50 (spaced logarithmically; "
                           "with --material)")
    _output_args(load)

    po = sub.add_parser("pulloff", help="pull-off force (Table 1)",
                        description="Largest tensile force |P|/(N G b^2) over separations up to "
                                    "d_max, and where it occurs.")
    _model_args(po)
    po.add_argument("--d-max", dest="d_max", type=float, default=None,
                    help="largest separation d/sigma searched (default: 10 beyond the end of the asperities' "
                         "stable branch, i.e. 10 without adhesion range)")
    _output_args(po, plot=False)

    srf = sub.add_parser("surface", help="GW summit parameters of a measured surface (AFM map, profile)",
                         description="Read a height map or line scan (any format SurfaceTopography reads) "
                                     "and compute the summit parameters sigma_s, R, eta two ways: from the "
                                     "spectral moments m0, m2, m4 (Nayak/McCool) and by summit detection. "
                                     "With --material, also alpha and beta (Eq 7). Needs asperity[topography].")
    srf.add_argument("file", help="height map or profile file")
    srf.add_argument("--material", help="material name for alpha, beta (its Burgers vector b)")
    srf.add_argument("--b", help="Burgers vector, a length (e.g. 0.2885nm), instead of --material")
    srf.add_argument("--size", help="scan size when the file stores none: Lx,Ly or L with units (e.g. 10um,10um)")
    srf.add_argument("--unit", help="height/length unit when the file stores none (e.g. nm)")
    srf.add_argument("--fill-undefined", action="store_true", help="fill missing (NaN) pixels by interpolation")
    srf.add_argument("--format", choices=("table", "json"), default=None,
                     help="output format (default: a readable summary on a terminal, JSON otherwise)")
    srf.add_argument("-o", "--output", metavar="FILE", help="write to FILE instead of standard output")

    mat = sub.add_parser("materials", help="list the materials table (SI units, with sources)",
                         description="The shipped materials table: E [Pa], nu, Burgers vector b [m], "
                                     "work of adhesion w [J/m^2]; empty = missing, with sources.")
    mat.add_argument("--sources", action="store_true", help="include the source of every number")
    _output_args(mat, plot=False)

    md = sub.add_parser("md", help="one Maugis-Dugdale asperity",
                        description="One Maugis-Dugdale sphere in Maugis' units: radius A, load "
                                    "P/(pi w R), m = c/a at penetrations Delta; or its pull-off.")
    md.add_argument("--lam", type=float, required=True, help="Maugis parameter lambda > 0 (Eq 14)")
    what = md.add_mutually_exclusive_group(required=True)
    what.add_argument("--delta", metavar="LIST",
                      help="penetrations Delta: 'a,b,c' or 'start:stop:count' (linearly spaced)")
    what.add_argument("--pulloff", action="store_true",
                      help="load- and displacement-controlled pull-off")
    _output_args(md, plot=False)
    return parser


# -- output ------------------------------------------------------------------------------
def _json_value(v):
    """JSON has no NaN or infinity: they become null."""
    if isinstance(v, float | np.floating) and not math.isfinite(v):
        return None
    return v


def _format_rows(rows: list[dict], fmt: str) -> str:
    if fmt == "json":
        clean = [{k: _json_value(v) for k, v in row.items()} for row in rows]
        return json.dumps(clean, indent=1, allow_nan=False) + "\n"
    names = list(rows[0]) if rows else []
    if fmt == "csv":
        lines = [",".join(names)] + [",".join(_csv(r[n]) for n in names) for r in rows]
        return "\n".join(lines) + "\n"
    cells = [[_short(r[n]) for n in names] for r in rows]
    widths = [max(len(n), *(len(c[i]) for c in cells)) if cells else len(n) for i, n in enumerate(names)]
    out = ["  ".join(n.rjust(w) for n, w in zip(names, widths, strict=True))]
    out += ["  ".join(c.rjust(w) for c, w in zip(row, widths, strict=True)) for row in cells]
    return "\n".join(out) + "\n"


def _csv(v) -> str:
    return repr(float(v)) if isinstance(v, float | np.floating) else str(v)


def _short(v) -> str:
    if isinstance(v, bool | np.bool_):
        return str(bool(v))
    if isinstance(v, float | np.floating):
        return f"{float(v):.6g}"
    return str(v)


def _emit(text: str, args):
    if args.output:
        try:
            with open(args.output, "w", encoding="utf-8") as fh:
                fh.write(text)
        except OSError as exc:
            raise UsageError(f"cannot write output file {args.output!r}: {exc.strerror}") from None
    else:
        sys.stdout.write(text)


def _fmt(args) -> str:
    if args.format:
        return args.format
    return "table" if (args.output is None and sys.stdout.isatty()) else "csv"


def _curve_rows(curve) -> list[dict]:
    cols = curve.columns()  # dimensionless names, or physical names with units (P_N, d_m, ...)
    return [{k: float(v[i]) for k, v in cols.items()} for i in range(len(curve))]


def _plot(curve, path: str, x: str, title: str, physical: bool = False):
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        raise UsageError("--plot needs matplotlib: pip install 'asperity[plot]'") from None
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9, 3.6), layout="constrained")
    xs = getattr(curve, x)
    if x == "P":
        xlabel = r"$P$ (N)" if physical else r"$\bar P = P/NGb^2$"
        ax1.loglog(xs, curve.mu, "k-")
        ax1.set_xlabel(xlabel)
        ax1.set_ylabel(r"$\mu$")
        ax2.loglog(xs, curve.area, "k-")
        ax2.set_xlabel(xlabel)
        ax2.set_ylabel(r"real contact area $A$ (m$^2$)" if physical else r"$A/N\pi b^2$")
    else:
        pos = curve.P > 0
        ax1.semilogy(xs[pos], curve.P[pos], "k-", label="compressive $P$")
        if np.any(~pos):
            ax1.semilogy(xs[~pos], -curve.P[~pos], "r--", label="tensile $-P$")
        ax1.legend()
        xlabel = r"separation $d$ (m)" if physical else r"$d/\sigma$"
        ax1.set_xlabel(xlabel)
        ax1.set_ylabel(r"$|P|$ (N)" if physical else r"$|P|/NGb^2$")
        ax2.semilogy(xs, curve.F, "k-")
        ax2.set_xlabel(xlabel)
        ax2.set_ylabel(r"$F$ (N)" if physical else r"$F/NGb^2$")
    fig.suptitle(title)
    try:
        fig.savefig(path, dpi=150)
    except OSError as exc:
        raise UsageError(f"cannot write plot {path!r}: {exc.strerror}") from None
    finally:
        plt.close(fig)


# -- commands ------------------------------------------------------------------------------
def _is_physical(args) -> bool:
    physical = [args.material, args.sigma, args.radius, args.density, args.area]
    if any(v is not None for v in physical):
        if args.alpha is not None or args.beta is not None or args.gamma is not None:
            raise UsageError("give either --alpha/--beta/--gamma or a physical contact "
                             "(--material, --sigma, --radius, --density, --area), not both")
        missing = [f"--{n}" for n, v in zip(("material", "sigma", "radius", "density", "area"),
                                             physical, strict=True) if v is None]
        if missing:
            raise UsageError(f"a physical contact also needs {', '.join(missing)}")
        if args.nu is not None:
            raise UsageError("--nu comes from the material with --material")
        return True
    if args.alpha is None or args.beta is None:
        raise UsageError("the model needs --alpha and --beta (or --material with --sigma, --radius, "
                         "--density and --area)")
    return False


def _model(args) -> Model:
    nu = 0.3 if args.nu is None else args.nu
    return Model(args.alpha, args.beta, args.gamma or 0.0, nu=nu, h_over_b=args.h_over_b)


def _contact(args):
    from .physical import PhysicalContact, Surface
    from .units import parse_quantity

    surface = Surface(parse_quantity(args.sigma, "m", "--sigma"), parse_quantity(args.radius, "m", "--radius"),
                      parse_quantity(args.density, "1/m^2", "--density"),
                      parse_quantity(args.area, "m^2", "--area"))
    return PhysicalContact(args.material, surface, adhesion=not args.no_adhesion)


def _quantity_list(text: str, unit: str, *, log: bool, name: str) -> np.ndarray:
    """``a,b,c`` or ``start:stop:count`` of quantities with units, in ``unit``."""
    from .units import parse_quantity

    if ":" in text:
        parts = text.split(":")
        if len(parts) != 3:
            raise UsageError(f"{name}: expected 'start:stop:count', got {text!r}")
        start, stop = (parse_quantity(x, unit, name) for x in parts[:2])
        return parse_list(f"{start!r}:{stop!r}:{parts[2]}", log=log, name=name)
    return np.array([parse_quantity(x, unit, name) for x in text.split(",") if x.strip()])


def _title(args) -> str:
    if args.material:
        return (f"{args.material}: sigma_s={args.sigma}, R={args.radius}, eta={args.density}, "
                f"area={args.area}{', no adhesion' if args.no_adhesion else ''}")
    return (f"alpha={args.alpha:g}, beta={args.beta:g}, gamma={args.gamma or 0:g}, "
            f"nu={0.3 if args.nu is None else args.nu:g}, h/b={args.h_over_b:g}")


def _run_curve(args, kind: str):
    """separation or load: dimensionless or physical, then output and plot."""
    physical = _is_physical(args)
    if kind == "separation":
        dimless, phys, unit, log = args.d, args.separation, "m", False
        names = ("--d", "--separation")
    else:
        dimless, phys, unit, log = args.P, args.load, "N", True
        names = ("--P", "--load")
    text = phys if physical else dimless
    if text is None or (phys if not physical else dimless) is not None:
        want, other = (names[1], names[0]) if physical else names
        raise UsageError(f"give {want} LIST" + (f" (not {other}) with --material" if physical
                                               else f" (or --material ... with {names[1]})"))
    if physical:
        values = _quantity_list(text, unit, log=log, name=names[1])
        contact = _contact(args)
        curve = getattr(contact, f"{kind}_curve")(values)
    else:
        values = parse_list(text, log=log, name=names[0])
        curve = getattr(_model(args), f"{kind}_curve")(values)
    _emit(_format_rows(_curve_rows(curve), _fmt(args)), args)
    if physical and np.nanmax(curve.area_fraction) > 0.1:
        print(f"asperity: note: the real contact area reaches {np.nanmax(curve.area_fraction):.0%} of the nominal "
              "area; the GW model (independent asperities) is unreliable there", file=sys.stderr)
    if args.plot:
        _plot(curve, args.plot, "d" if kind == "separation" else "P", _title(args), physical)


def cmd_separation(args):
    _run_curve(args, "separation")


def cmd_load(args):
    _run_curve(args, "load")


def cmd_pulloff(args):
    if _is_physical(args):
        po = _contact(args).pull_off(args.d_max)
        row = {"pull_off_N": po.force, "d_m": po.d}
    else:
        if args.gamma is None:
            raise UsageError("pulloff needs --gamma (the adhesion parameter)")
        po = _model(args).pull_off(args.d_max)
        row = {"pull_off": po.force, "d": po.d}
    fmt = _fmt(args)
    if fmt == "json":
        text = json.dumps({k: _json_value(v) for k, v in row.items()}, allow_nan=False) + "\n"
    else:
        text = _format_rows([row], fmt)
    _emit(text, args)


def cmd_md(args):
    lam = args.lam
    if not (math.isfinite(lam) and lam > 0):
        raise UsageError(f"--lam must be > 0 and finite, got {lam!r}")
    if args.pulloff:
        rows = []
        for control in ("load", "displacement"):
            p = md_pull_off(lam, control)
            rows.append({"control": control, "P": p.P, "A": p.A, "delta": p.delta})
    else:
        delta = parse_list(args.delta, log=False, name="--delta")
        end = md_branch_end(lam)
        if np.any(delta < end.delta):
            raise UsageError(f"--delta must be >= {end.delta:.6g}, the end of the stable branch "
                             f"for lam={lam:g}")
        A, P, t = md_solve(delta, lam)
        m = np.sqrt(1.0 + t * t)
        rows = [{"delta": float(x), "A": float(a), "P": float(p), "m": float(mm)}
                for x, a, p, mm in zip(delta, A, P, m, strict=True)]
    _emit(_format_rows(rows, _fmt(args)), args)


def cmd_surface(args):
    from .units import parse_quantity

    try:
        import SurfaceTopography  # noqa: F401

        from .topography import analyse_surface
    except ImportError:
        raise UsageError("surface needs SurfaceTopography: pip install 'asperity[topography]'") from None
    kwargs = {"fill_undefined": args.fill_undefined}
    if args.size:
        kwargs["physical_sizes"] = tuple(parse_quantity(x, "m", "--size") for x in args.size.split(","))
    if args.unit:
        kwargs["unit"] = args.unit
    b = parse_quantity(args.b, "m", "--b") if args.b else None
    if args.material and b is not None:
        raise UsageError("give --material or --b, not both")
    mat = None
    if args.material:
        from .materials import material

        mat = material(args.material)
    result = analyse_surface(args.file, material=mat, b=b, **kwargs)
    fmt = args.format or ("table" if (args.output is None and sys.stdout.isatty()) else "json")
    text = result.summary() + "\n" if fmt == "table" else json.dumps(result.to_dict(), indent=1) + "\n"
    _emit(text, args)


def cmd_materials(args):
    from .materials import material_table

    keys = ["name", "kind", "E_Pa", "nu", "b_m", "work_of_adhesion_J_m2"] + (["sources"] if args.sources else [])
    rows = [{k: ("" if row.get(k) is None else row.get(k)) for k in keys} for row in material_table()]
    _emit(_format_rows(rows, _fmt(args)), args)


def cmd_reproduce(args):
    try:
        from .studies.report import reproduce
    except ImportError as exc:  # matplotlib missing
        raise UsageError(f"reproduce needs matplotlib: pip install 'asperity[plot]' ({exc})") from None
    start = time.perf_counter()

    def progress(message):
        print(message, flush=True)

    try:
        reproduce(args.out, progress=progress)
    except OSError as exc:
        raise UsageError(f"cannot write to {args.out!r}: {exc.strerror or exc}") from None
    print(f"done in {time.perf_counter() - start:.1f} s: open {args.out}/index.html", flush=True)


COMMANDS = {"separation": cmd_separation, "load": cmd_load, "pulloff": cmd_pulloff, "md": cmd_md,
            "reproduce": cmd_reproduce, "materials": cmd_materials, "surface": cmd_surface}


def _join_negative_lists(argv):
    """``--d -1,0,2`` -> ``--d=-1,0,2``: argparse would take ``-1,0,2`` for an option."""
    out = list(argv)
    i = 0
    while i < len(out) - 1:
        nxt = out[i + 1]
        if out[i].startswith("--") and "=" not in out[i] and nxt[:1] == "-" and nxt[1:2] in tuple("0123456789."):
            out[i:i + 2] = [f"{out[i]}={nxt}"]
        i += 1
    return out


def main(argv=None) -> int:
    parser = build_parser()
    argv = sys.argv[1:] if argv is None else argv
    try:
        args = parser.parse_args(_join_negative_lists(argv))
        if args.command is None:
            parser.print_help()
            return 2
        COMMANDS[args.command](args)
    except UsageError as exc:
        print(f"asperity: error: {exc}", file=sys.stderr)
        return 2
    except ValueError as exc:  # the library's own parameter checks
        print(f"asperity: error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("asperity: interrupted", file=sys.stderr)
        return 130
    return 0


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
