"""``asperity sweep``: curves and pull-off over a grid or list of parameter sets, to NetCDF or Zarr.

Each option takes one value (a constant) or a list, ``a,b,c`` or ``start:stop:count``
(log-spaced for the quantities :mod:`asperity.quantities` marks ``log``): every list is a
dimension of the grid.  ``--points FILE.csv`` lists the sets instead.  The results go to
``--out`` (NetCDF, or Zarr for a name ending in ``.zarr``) through
:func:`asperity.sweeps.sweep`, which this module only calls.
"""

from __future__ import annotations

import argparse
import os

from ..quantities import MODEL_PARAMETERS, PHYSICAL_PARAMETERS
from ._args import UsageError, integer, output_file, parse_list, quantity_list

NAME = "sweep"
HELP = "curves and pull-off over a grid of parameter sets (NetCDF/Zarr; Dask)"
DESCRIPTION = ("Curves at given loads (or separations) and the pull-off force for every parameter set of a grid "
               "(each list is a dimension) or of a list of points, serially or on a Dask cluster. "
               "Needs the sweep extra: pip install 'asperity[sweep]'.")
EPILOG = """Lists: 'a,b,c' or 'start:stop:count' (log-spaced where the quantity spans decades).
Examples:
  asperity sweep --alpha 1e-3:0.1:20 --beta 1000 --gamma 1e-5:1e-2:20 --P 1e-2:1e5:8 --out map.nc
  asperity sweep --points sets.csv --P 1,10,100 --out map.zarr --scheduler tcp://10.0.0.1:8786
  asperity sweep --material Au,Si --sigma-s 1nm,2nm,4nm --R 1um --eta 1e12/m^2 --area 1mm^2 \\
      --load 1mN:1N:30 --out metals.nc
A physical sweep takes table materials, with their work of adhesion and Burgers vector or
--w and --b in their place (--w 0J/m^2: no adhesion; a material without them in the table, such as
diamond or mica, needs them), and the elastic law: the dimensions of a sweep are those of
asperity.sweep, whose parameter sets have no --E, --law or --hardness (compute such contacts
one by one with load/pulloff/cycle).
Each set's contact is in the file's coordinates; there is no single contact to describe.
Then: asperity plot map.nc --x alpha --y gamma --z pull_off"""

#: Model options: (option, parameter name).
MODEL_OPTIONS = (("--alpha", "alpha"), ("--beta", "beta"), ("--gamma", "gamma"), ("--nu", "nu"),
                 ("--h-over-b", "h_over_b"), ("--tau-f1", "tau_f1"), ("--tau-f2", "tau_f2"), ("--a1", "a1"),
                 ("--a2", "a2"))
#: Physical options: (option, parameter name, SI unit); the old spellings --sigma, --radius and
#: --density are aliases, as for every physical command.
PHYSICAL_OPTIONS = (("--sigma-s", "sigma_s", "m"), ("--R", "R", "m"), ("--eta", "eta", "1/m^2"),
                    ("--area", "area", "m^2"), ("--w", "w", "J/m^2"), ("--b", "b", "m"))
ALIASES = {"--sigma-s": ("--sigma",), "--R": ("--radius",), "--eta": ("--density",), "--area": (), "--w": (),
           "--b": ()}


def _store_path(text: str) -> str:
    """argparse type of ``--out``: a file name, or a ``.zarr`` directory (trailing slashes
    dropped; the library then says whether an existing one holds this sweep); not ``-``."""
    if text == "-":
        raise argparse.ArgumentTypeError("a sweep is a file or a directory, not standard output ('-')")
    name = text.rstrip("/") if text.rstrip("/").endswith(".zarr") else text
    if not name.endswith(".zarr"):
        return output_file(name)
    parent = os.path.dirname(name)
    if parent and not os.path.isdir(parent):
        raise argparse.ArgumentTypeError(f"{text!r}: the directory {parent!r} does not exist")
    return name


def add_arguments(parser: argparse.ArgumentParser) -> None:
    g = parser.add_argument_group("model parameters (dimensionless): a value or a list each")
    for option, name in MODEL_OPTIONS:
        g.add_argument(option, dest=name, metavar="LIST", help=MODEL_PARAMETERS[name].help())
    ph = parser.add_argument_group("physical contact (SI results; quantities with units, e.g. 2nm, 1um)")
    ph.add_argument("--material", metavar="NAMES", help="material name(s), e.g. Au or Au,Si (asperity materials)")
    for option, name, _ in PHYSICAL_OPTIONS:
        ph.add_argument(option, *ALIASES[option], dest=name, metavar="LIST", help=PHYSICAL_PARAMETERS[name].meaning)
    s = parser.add_argument_group("sets, loads and output")
    s.add_argument("--points", metavar="FILE.csv",
                   help="CSV of parameter sets (a header of parameter names, one row per set)")
    s.add_argument("--P", metavar="LIST", help="loads P/(N G b^2) of every set")
    s.add_argument("--d", metavar="LIST", help="separations d/sigma of every set (instead of loads)")
    s.add_argument("--load", metavar="LIST", help="physical loads with a force unit, e.g. 1mN:1N:30")
    s.add_argument("--separation", metavar="LIST", help="physical separations with a length unit, e.g. -2nm:10nm:50")
    s.add_argument("--out", metavar="PATH", type=_store_path, default="sweep.nc",
                   help="NetCDF file, or Zarr directory if it ends in .zarr (default: sweep.nc)")
    s.add_argument("--resume", action="store_true",
                   help="complete an interrupted sweep of the same arguments at --out (only its missing chunks)")
    s.add_argument("--scheduler", metavar="ADDRESS", default=None,
                   help="Dask scheduler address of an existing cluster, or 'local' (one worker per core; the "
                        "default when Dask is installed) or 'serial'")
    s.add_argument("--chunk-sets", dest="chunk_sets", metavar="N", type=integer, default=None,
                   help="parameter sets per task (default: a 32nd of the sets, within 32..256)")
    s.add_argument("--progress", action=argparse.BooleanOptionalAction, default=None,
                   help="progress bar with ETA on standard error (default: when it is a terminal)")


def _single(text: str) -> bool:
    """A single value (a constant), not a list or range (a dimension, even of length 1)."""
    return "," not in text and ":" not in text


def _values(args):
    """Keyword arguments of :func:`asperity.sweeps.sweep` from the options (lists parsed)."""
    kwargs = {}
    for option, name in MODEL_OPTIONS:
        text = getattr(args, name)
        if text is not None:
            v = parse_list(text, log=MODEL_PARAMETERS[name].log, name=option)
            kwargs[name] = float(v[0]) if _single(text) else v
    for option, name, unit in PHYSICAL_OPTIONS:
        text = getattr(args, name)
        if text is not None:
            v = quantity_list(text, unit, log=True, name=option)
            kwargs[name] = float(v[0]) if _single(text) else v
    if args.material is not None:
        names = [n.strip() for n in args.material.split(",")]
        if any(not n for n in names):
            raise UsageError(f"--material: empty name in {args.material!r}")
        kwargs["material"] = names[0] if len(names) == 1 else names
    return kwargs


def _axis(args, physical: bool):
    given = [o for o, v in (("--P", args.P), ("--d", args.d), ("--load", args.load),
                            ("--separation", args.separation)) if v is not None]
    wanted = ("--load", "--separation") if physical else ("--P", "--d")
    if len(given) != 1 or given[0] not in wanted:
        raise UsageError(f"give one of {' or '.join(wanted)}" + (" (a physical sweep)" if physical else "")
                         + (f", not {', '.join(given)}" if given else ""))
    option = given[0]
    if option == "--P":
        return {"P": parse_list(args.P, log=True, name="--P")}
    if option == "--d":
        return {"d": parse_list(args.d, log=False, name="--d")}
    if option == "--load":
        return {"P": quantity_list(args.load, "N", log=True, name="--load")}
    return {"d": quantity_list(args.separation, "m", log=False, name="--separation")}


def sweep_arguments(args) -> dict:
    """Every keyword argument of :func:`asperity.sweeps.sweep` the command line gives (for tests too)."""
    kwargs = _values(args)
    physical = args.material is not None or any(getattr(args, n) is not None for _, n, _ in PHYSICAL_OPTIONS)
    if args.points is not None:
        kwargs["points"] = args.points
        import os

        if not os.path.isfile(args.points):
            what = "is a directory, not a CSV file" if os.path.isdir(args.points) else "no such file"
            raise UsageError(f"--points {args.points!r}: {what}")
        try:
            with open(args.points, encoding="utf-8") as fh:
                header = fh.readline()
        except (OSError, UnicodeDecodeError) as err:
            raise UsageError(f"--points {args.points!r}: cannot read it as text ({err})") from None
        physical = physical or "material" in header.split(",")
    kwargs.update(_axis(args, physical))
    kwargs.update(out=args.out, resume=args.resume, scheduler=args.scheduler)
    if args.chunk_sets is not None:
        kwargs["chunk_sets"] = args.chunk_sets
    return kwargs


def run(args) -> None:
    import sys

    import numpy as np

    from ..sweeps import sweep
    from ..sweeps.compute import LOADS_NAN_NOTE
    from ._output import say

    kwargs = sweep_arguments(args)
    progress = sys.stderr.isatty() if args.progress is None else args.progress
    ds = sweep(progress=progress, **kwargs)
    messages = ds["message"].values.astype(str)
    noted = int(np.char.startswith(messages, "note:").sum())
    failed = int((messages != "").sum()) - noted
    partly = int((np.char.find(messages, LOADS_NAN_NOTE) >= 0).sum())  # computed, NaN at some loads
    total = int(messages.size)
    ds.close()
    say(f"wrote {args.out}: {total} parameter sets"
        + (f", {failed} outside the model's domain (NaN; see the message variable)" if failed else "")
        + (f", {noted} with a validity note of the library (see the message variable)" if noted else "")
        + (f", of which {partly} with NaN at the loads below their least load" if partly else "") + "\n")
