"""The library's warning categories share one base class, so users and front ends can filter them.

:class:`AsperityWarning` is a :class:`UserWarning`; every warning asperity raises about its
own results (a plastic share the elastic model ignores, a real area beyond what
Greenwood-Williamson allows, ...) derives from it.  ``warnings.simplefilter("ignore",
asperity.AsperityWarning)`` silences them all; the command line prints each as one
``asperity: note: ...`` line.
"""

from __future__ import annotations

__all__ = ["AsperityWarning"]


class AsperityWarning(UserWarning):
    """Base class of the warnings asperity raises about the validity of its results."""
