"""``asperity explore``: the live view of the model in the browser (a local Bokeh server)."""

from __future__ import annotations

import argparse

NAME = "explore"
HELP = "live view of the model in the browser (local server, no internet needed)"
DESCRIPTION = ("Start the explorer: a page with sliders for the model's parameters (dimensionless groups, or a "
               "material, surface and loads in SI units) and plots that follow them, served from this machine. "
               "Prints the page's address and opens it in the browser; Ctrl-C stops the server. The page's "
               "address holds the view: bookmark or share it. Needs asperity[explore].")
EPILOG = ("examples:\n  asperity explore\n  asperity explore --port 8080 --no-browser\n"
          "  asperity explore --port 0          # any free port")


def port_number(text: str) -> int:
    """argparse type of ``--port``: a whole number from 0 (a free port) to 65535."""
    try:
        port = int(text)
    except ValueError:
        port = -1
    if not 0 <= port <= 65535:
        raise argparse.ArgumentTypeError(f"expected a port number from 0 (any free port) to 65535, got {text!r}")
    return port


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--port", type=port_number, default=5006,
                        help="TCP port (default 5006; 0 picks a free one)")
    parser.add_argument("--host", default="127.0.0.1",
                        help="address to listen on (default 127.0.0.1: this machine only; 0.0.0.0 opens the "
                             "explorer to the network)")
    parser.add_argument("--no-browser", action="store_true", help="do not open the page in a browser")


def run(args) -> None:
    from ..explorer.server import serve
    from ._args import UsageError

    try:
        serve(port=args.port, host=args.host, open_browser=not args.no_browser,
              announce=lambda line: print(line, flush=True))
    except OSError as err:
        raise UsageError(f"cannot listen on {args.host}:{args.port}: {err.strerror or err}; "
                         "choose another --port (0 picks a free one) or --host") from None
