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

__all__ = ["main"]

UNITS = "\n".join(f"  {name:9s} {meaning}" for name, meaning in COLUMNS.items())

MODEL_HELP = {
    "alpha": "surface roughness parameter (sigma/R)^(1/2) > 0 (Eq 7)",
    "beta": "friction regime parameter (R sigma)^(1/2)/b > 0 (Eq 7)",
    "gamma": "adhesion parameter w/(E* b) >= 0 (Eq 16); 0 = no adhesion (Hertz)",
    "nu": "Poisson's ratio, -1 < nu < 0.5 (default 0.3; the paper does not state it)",
    "h_over_b": "Dugdale range over Burgers vector h/b > 0 (Eq 15; default 1 as in the paper)",
}


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


def _model_args(p: argparse.ArgumentParser, gamma_required: bool = False):
    g = p.add_argument_group("model parameters (dimensionless)")
    g.add_argument("--alpha", type=float, required=True, help=MODEL_HELP["alpha"])
    g.add_argument("--beta", type=float, required=True, help=MODEL_HELP["beta"])
    g.add_argument("--gamma", type=float, required=gamma_required, default=0.0, help=MODEL_HELP["gamma"])
    g.add_argument("--nu", type=float, default=0.3, help=MODEL_HELP["nu"])
    g.add_argument("--h-over-b", dest="h_over_b", type=float, default=1.0, help=MODEL_HELP["h_over_b"])


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
    sep.add_argument("--d", required=True, metavar="LIST",
                     help="separations d/sigma: 'a,b,c' or 'start:stop:count' (linearly spaced)")
    _output_args(sep)

    load = sub.add_parser("load", help="quantities versus normal load (Figs 3-6, 9)",
                          formatter_class=fmt, epilog=f"Columns:\n{UNITS}",
                          description="Quantities at the stable separation for each normal load.")
    _model_args(load)
    load.add_argument("--P", required=True, metavar="LIST",
                      help="loads P/(N G b^2): 'a,b,c' or 'start:stop:count' (spaced logarithmically)")
    _output_args(load)

    po = sub.add_parser("pulloff", help="pull-off force (Table 1)",
                        description="Largest tensile force |P|/(N G b^2) over separations up to "
                                    "d_max, and where it occurs.")
    _model_args(po, gamma_required=True)
    po.add_argument("--d-max", dest="d_max", type=float, default=10.0,
                    help="largest separation d/sigma searched (default 10)")
    _output_args(po, plot=False)

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
def _format_rows(rows: list[dict], fmt: str) -> str:
    if fmt == "json":
        return json.dumps(rows, indent=1, allow_nan=True).replace("NaN", "null") + "\n"
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
    cols = curve.columns()
    return [{k: float(v[i]) for k, v in cols.items()} for i in range(len(curve))]


def _plot(curve, path: str, x: str, title: str):
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        raise UsageError("--plot needs matplotlib: pip install 'asperity[plot]'") from None
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9, 3.6), layout="constrained")
    xs = getattr(curve, x)
    if x == "P":
        ax1.loglog(xs, curve.mu, "k-")
        ax1.set_xlabel(r"$\bar P = P/NGb^2$")
        ax1.set_ylabel(r"$\mu$")
        ax2.loglog(xs, curve.area, "k-")
        ax2.set_xlabel(r"$\bar P = P/NGb^2$")
        ax2.set_ylabel(r"$A/N\pi b^2$")
    else:
        pos = curve.P > 0
        ax1.semilogy(xs[pos], curve.P[pos], "k-", label="compressive $P$")
        if np.any(~pos):
            ax1.semilogy(xs[~pos], -curve.P[~pos], "r--", label="tensile $-P$")
        ax1.legend()
        ax1.set_xlabel(r"$d/\sigma$")
        ax1.set_ylabel(r"$|P|/NGb^2$")
        ax2.semilogy(xs, curve.F, "k-")
        ax2.set_xlabel(r"$d/\sigma$")
        ax2.set_ylabel(r"$F/NGb^2$")
    fig.suptitle(title)
    try:
        fig.savefig(path, dpi=150)
    except OSError as exc:
        raise UsageError(f"cannot write plot {path!r}: {exc.strerror}") from None
    finally:
        plt.close(fig)


# -- commands ------------------------------------------------------------------------------
def _model(args) -> Model:
    return Model(args.alpha, args.beta, args.gamma, nu=args.nu, h_over_b=args.h_over_b)


def _title(args) -> str:
    return (f"alpha={args.alpha:g}, beta={args.beta:g}, gamma={args.gamma:g}, nu={args.nu:g}, "
            f"h/b={args.h_over_b:g}")


def cmd_separation(args):
    d = parse_list(args.d, log=False, name="--d")
    curve = _model(args).separation_curve(d)
    _emit(_format_rows(_curve_rows(curve), _fmt(args)), args)
    if args.plot:
        _plot(curve, args.plot, "d", _title(args))


def cmd_load(args):
    P = parse_list(args.P, log=True, name="--P")
    curve = _model(args).load_curve(P)
    _emit(_format_rows(_curve_rows(curve), _fmt(args)), args)
    if args.plot:
        _plot(curve, args.plot, "P", _title(args))


def cmd_pulloff(args):
    po = _model(args).pull_off(args.d_max)
    row = {"pull_off": po.force, "d": po.d}
    fmt = _fmt(args)
    if fmt == "json":
        text = json.dumps({"pull_off": po.force, "d": None if math.isnan(po.d) else po.d}) + "\n"
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
            "reproduce": cmd_reproduce}


_LIST_OPTIONS = ("--d", "--P", "--delta")


def _join_negative_lists(argv):
    """``--d -1,0,2`` -> ``--d=-1,0,2``: argparse would take ``-1,0,2`` for an option."""
    out = list(argv)
    i = 0
    while i < len(out) - 1:
        nxt = out[i + 1]
        if out[i] in _LIST_OPTIONS and nxt[:1] == "-" and nxt[1:2] in tuple("0123456789."):
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
