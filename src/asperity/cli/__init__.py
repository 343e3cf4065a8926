"""The ``asperity`` command line.

``asperity reproduce`` recomputes the paper's figures and Table 1; ``separation``,
``load``, ``pulloff`` and ``md`` compute curves for one's own parameters; ``cycle`` an
approach-retract cycle (hysteresis, energy dissipated, pull-off); ``fit`` fits a model to
measured data; ``surface`` reads a measured surface, ``bem`` checks the model against a
boundary-element contact of it, ``materials`` lists the materials table, ``sweep`` runs
grids of parameter sets (NetCDF/Zarr, on Dask) and ``plot`` draws them as heat maps;
``explore`` serves a live view of the model to the browser.  Every error prints one line
and exits with status 2.

One module per command (:data:`COMMANDS`), each with ``NAME``, ``HELP``,
``DESCRIPTION`` (and optionally ``EPILOG``), ``add_arguments(parser)`` and ``run(args)``;
the shared parts are :mod:`~asperity.cli._args` (lists, quantities, argument groups),
:mod:`~asperity.cli._build` (the model or contact of the parsed options),
:mod:`~asperity.cli._output` (formats, atomic writing) and :mod:`~asperity.cli._plot`.
Command modules import NumPy, SciPy and the model inside ``run``, after parsing, so
``--help`` and ``--version`` answer without loading them.
"""

from __future__ import annotations

import argparse
import os
import signal
import sys
import threading
import warnings

from .._optional import MissingDependency
from .._version import __version__
from . import bem, cycle, explore, fit, load, materials, md, plot, pulloff, reproduce, separation, surface, sweep
from ._args import UNITS, UsageError, join_negative_lists, parse_list
from ._lists import OutputClosed

__all__ = ["main", "build_parser", "parse_list", "UsageError", "COMMANDS"]

#: Command name -> its module, in the order ``asperity --help`` lists them.
COMMANDS = {module.NAME: module for module in (reproduce, separation, load, pulloff, cycle, fit, surface, bem,
                                               materials, md, sweep, plot, explore)}


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # one line, no usage dump
        raise UsageError(message)


def build_parser() -> argparse.ArgumentParser:
    """The parser of every command in :data:`COMMANDS`."""
    parser = _Parser(
        prog="asperity",
        description="Multi-asperity contact, adhesion and friction (Greenwood-Williamson + "
                    "Hurtado-Kim + Maugis-Dugdale).",
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog=f"Output columns and units:\n{UNITS}",
    )
    parser.add_argument("--version", action="version", version=f"asperity {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    for module in COMMANDS.values():
        epilog = getattr(module, "EPILOG", None)
        kwargs = {"formatter_class": argparse.RawDescriptionHelpFormatter, "epilog": epilog} if epilog else {}
        module.add_arguments(sub.add_parser(module.NAME, help=module.HELP, description=module.DESCRIPTION,
                                            **kwargs))
    return parser


def run_with_notes(run, args) -> None:
    """Run a command; print each of the library's warnings (:class:`asperity.AsperityWarning`)
    as one ``asperity: note:`` line on standard error (once per distinct message, after the
    command succeeded: none after an error), and pass any other warning on as it came."""
    from .._warnings import AsperityWarning

    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", AsperityWarning)
        try:
            run(args)
        finally:
            notes = list(dict.fromkeys(" ".join(str(w.message).split()) for w in caught
                                       if issubclass(w.category, AsperityWarning)))
            others = [w for w in caught if not issubclass(w.category, AsperityWarning)]
    for w in others:  # re-issued, so that tests (which turn warnings into errors) see them
        warnings.warn_explicit(w.message, w.category, w.filename, w.lineno, source=w.source)
    for note in notes:
        print(f"asperity: note: {note}", file=sys.stderr)


class Terminated(KeyboardInterrupt):
    """SIGTERM, raised in the main thread so that it unwinds as Ctrl-C does (files closed, a
    sweep's cluster shut down, its partial store left to resume)."""


def _terminate(signum, frame):
    raise Terminated


def main(argv=None) -> int:
    """Run the command line on ``argv`` (default ``sys.argv[1:]``); return the exit status.

    Errors print one line ``asperity: error: ...`` and return 2.  asperity's warnings (e.g.
    :class:`asperity.AreaFractionWarning`) print one ``asperity: note: ...`` line each after
    a successful command, and none after an error.  Ctrl-C (status 130) and SIGTERM (143)
    print ``asperity: interrupted`` (a review found SIGTERM ending a sweep on a local cluster
    with Python's "leaked semaphore" warning and no line of ours).
    """
    parser = build_parser()
    # (not where SIGTERM is ignored by the parent, as Python keeps an ignored SIGINT)
    in_main = threading.current_thread() is threading.main_thread() and \
        signal.getsignal(signal.SIGTERM) is not signal.SIG_IGN
    previous = signal.signal(signal.SIGTERM, _terminate) if in_main else None  # (None: set outside Python)
    try:
        return _main(parser, argv, discard=argv is None)
    finally:
        if in_main and previous is not None:
            signal.signal(signal.SIGTERM, previous)


def _main(parser, argv, discard=False) -> int:
    try:
        args = parser.parse_args(join_negative_lists(sys.argv[1:] if argv is None else argv))
        if args.command is None:
            parser.print_help()
            return 2
        run_with_notes(COMMANDS[args.command].run, args)
    except (UsageError, ValueError, TypeError, MissingDependency) as exc:  # the library's own checks
        print(f"asperity: error: {' '.join(str(exc).split())}", file=sys.stderr)
        return 2
    except KeyboardInterrupt as exc:
        terminated = isinstance(exc, Terminated)
        print(f"asperity: interrupted{' (SIGTERM)' if terminated else ''}", file=sys.stderr)
        return 143 if terminated else 130
    except OutputClosed:  # the reader left ('asperity load ... | head -1'): quietly, as a shell tool does
        if discard:
            _discard_stdout()
        return 141
    return 0


def _discard_stdout() -> None:
    """Point standard output at the null device, so that Python's flush at exit does not
    report the closed pipe again (only for the command line itself: a caller's own output
    stays as it is)."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError, AttributeError):  # no file descriptor
        pass

