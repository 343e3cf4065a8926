"""Reproduce a view of ``asperity explore`` in a script, from its link.

Every view of the explorer lives in its address (``http://127.0.0.1:5006/?mode=...``).
Paste one here and this script computes the same curves with the library, prints the
derived numbers and writes the two CSV files the page's buttons download::

    python examples/explorer_link.py 'http://127.0.0.1:5006/?mode=physical&material=Si&P_max_N=5'
    python examples/explorer_link.py          # the explorer's default view

Needs no browser and no Bokeh: :mod:`asperity.explorer.state` reads the link and
:mod:`asperity.explorer.compute` makes the library calls the page makes.
"""

import argparse
from pathlib import Path
from urllib.parse import urlparse

from asperity.explorer.compute import compute
from asperity.explorer.state import state_from_query


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("link", nargs="?", default="", help="the page's address, or just its query string")
    parser.add_argument("--out", default="explorer-view", help="directory for the two CSV files")
    args = parser.parse_args(argv)
    query = urlparse(args.link).query if "?" in args.link else args.link
    state, messages = state_from_query(query)
    for message in messages:
        print(f"note: {message}")
    result = compute(state)  # the library's ValueError if the link's parameters are invalid
    print(f"mode: {state.mode}, {len(result.load)} loads, {len(result.separation)} separations")
    for name, value, meaning in result.derived:
        print(f"  {name:16s} {value:28s} {meaning}")
    for warning in result.warnings:
        print(f"warning: {warning}")
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    result.load.to_csv(out / "load-curve.csv")
    result.separation.to_csv(out / "separation-curve.csv")
    print(f"wrote {out / 'load-curve.csv'} and {out / 'separation-curve.csv'}")
    return result


if __name__ == "__main__":
    main()
