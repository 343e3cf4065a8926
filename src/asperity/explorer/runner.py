"""Running a view's computations: the library's results or its message, now or in a worker thread.

:func:`attempt` computes a view (:func:`asperity.explorer.compute.compute`) and its optional
panels, turning the library's refusals into the page's messages and the panels' warnings into
notes shown on the page; :func:`immediate_runner` runs it at once (tests, scripts),
:func:`threaded_runner` in the explorer's single worker thread, handing the result back to the
page's document.
"""

from __future__ import annotations

import warnings
from concurrent.futures import ThreadPoolExecutor
from functools import partial

from . import compute as _compute
from .wording import page_wording

__all__ = ["attempt", "immediate_runner", "threaded_runner", "page_message"]


def page_message(err: Exception) -> str:
    """The page's sentence for an error: the library's message in the page's words, or a plea to report a bug."""
    if isinstance(err, ValueError | TypeError | ArithmeticError):
        return page_wording(str(err)) or type(err).__name__
    return f"unexpected error ({type(err).__name__}: {err}); please report it with the page's address"


def attempt(state, panels=()):
    """:func:`asperity.explorer.compute.compute` of ``state`` and the ``compute`` of each panel, or the
    library's message if it rejects the view.  A panel's own error becomes its entry in ``extras``."""
    try:
        result = _compute.compute(state)
    except Exception as err:  # noqa: BLE001 - a bug is shown too, rather than leave the page waiting
        return page_message(err)
    for panel in panels:
        try:
            with warnings.catch_warnings(record=True) as caught:  # to the page, not the server's log
                warnings.simplefilter("always")
                result.extras[panel] = panel.compute(result)
            label, seen = panel.toggle.label.split(":")[0], {_compute.number_free(n) for n in result.warnings}
            result.extra_warnings.extend(f"{label}: {note}" for note in _compute.caught_notes(caught)
                                         if _compute.number_free(note) not in seen)  # the curves' own: once
        except Exception as err:  # noqa: BLE001
            result.extras[panel] = page_message(err)
    return result


def immediate_runner(work, done) -> None:
    """Compute at once, in this thread (for tests and scripts)."""
    done(work())


_EXECUTOR: list = []


def threaded_runner(doc):
    """Compute in the explorer's worker thread (one for all pages, so computations never overlap);
    the result comes back to the document's thread through ``doc.add_next_tick_callback``."""
    def run(work, done):
        if not _EXECUTOR:
            _EXECUTOR.append(ThreadPoolExecutor(max_workers=1, thread_name_prefix="asperity-explore"))
        def back(future):
            try:
                doc.add_next_tick_callback(partial(done, future.result()))
            except Exception:  # noqa: BLE001 - the page was closed meanwhile: nothing to show
                pass

        _EXECUTOR[0].submit(work).add_done_callback(back)
    return run
