"""A progress report over the loads of a boundary-element run.

:func:`progress_bar` wraps an iterable: with tqdm installed it is a tqdm bar on standard
error; without tqdm each step prints one plain line ``bem: load 3/8 (P = 0.001 N)`` on
standard error; with ``enabled=False`` nothing is printed.  :func:`stage` reports the steps
before the loads (reading and analysing a large map can take minutes).
"""

from __future__ import annotations

import importlib
import sys

__all__ = ["progress_bar", "stage"]


#: Points of a map above which the stage report suggests averaging it first (--grid).
LARGE_MAP = 1024 * 1024


def stage(message: str, *, enabled: bool, points: int = 0, stream=None) -> None:
    """One line ``bem: message`` on ``stream`` (standard error) if ``enabled``; for a map of more
    than :data:`LARGE_MAP` ``points``, with the hint to average it first (``grid=``, ``--grid``)."""
    if enabled:
        hint = (" (slow for this many points: grid=512, command line --grid 512, averages the map first)"
                if points > LARGE_MAP else "")
        print(f"bem: {message}{hint}", file=sys.stderr if stream is None else stream, flush=True)


def _tqdm():
    try:
        return importlib.import_module("tqdm").tqdm
    except ImportError:
        return None


def progress_bar(loads, *, enabled: bool, label: str = "bem", stream=None):
    """Iterate over ``loads`` (forces in N), reporting progress on ``stream`` (standard error).

    Parameters
    ----------
    loads : sequence of float
        The loads, in the order they are solved.
    enabled : bool
        Report progress (tqdm bar if tqdm is installed, else one line per load).
    label : str
        Prefix of the report.
    stream : file-like, optional
        Where to write (default ``sys.stderr``).

    Yields
    ------
    float
        Each load in turn.
    """
    stream = sys.stderr if stream is None else stream
    if not enabled:
        yield from loads
        return
    tqdm = _tqdm()
    if tqdm is not None:
        with tqdm(total=len(loads), desc=label, unit="load", file=stream, leave=False) as bar:
            for load in loads:
                bar.set_postfix_str(f"P = {load:.4g} N")
                yield load
                bar.update(1)
        return
    for i, load in enumerate(loads, 1):
        print(f"{label}: load {i}/{len(loads)} (P = {load:.4g} N)", file=stream, flush=True)
        yield load
