"""The library's warning categories share one base class, so users and front ends can filter them.

:class:`AsperityWarning` is a :class:`UserWarning`; every warning asperity raises about its
own results (a plastic share the elastic model ignores, a real area beyond what
Greenwood-Williamson allows, ...) derives from it.  ``warnings.simplefilter("ignore",
asperity.AsperityWarning)`` silences them all; the command line prints each as one
``asperity: note: ...`` line.
"""

from __future__ import annotations

import os
import sys

__all__ = ["AsperityWarning", "frames_to_user"]

_PACKAGE = os.path.dirname(os.path.abspath(__file__))


class AsperityWarning(UserWarning):
    """Base class of the warnings asperity raises about the validity of its results."""


def frames_to_user() -> int:
    """How many frames up from the caller of this function the first one outside asperity is
    (1: the caller was called by the user), for a warning's ``stacklevel`` that points at the
    user's line whichever of asperity's routes led there."""
    frame, count = sys._getframe(1), 0
    while frame is not None and os.path.abspath(frame.f_code.co_filename).startswith(_PACKAGE + os.sep):
        frame, count = frame.f_back, count + 1
    return max(count, 1)
