"""The library's messages in the words of the page.

The library's errors and warnings name its keywords (``pass adhesion=False``, ``give
hardness= (Pa)``) and, in parentheses, the command line's options.  The explorer shows them
with the names of its own controls instead: each rule below rewrites one such advice, and
the command-line parentheses are dropped.  A message no rule matches is shown as it is.
"""

from __future__ import annotations

import re

__all__ = ["RULES", "page_wording"]

#: (pattern, replacement) pairs, applied in order: the library's advice -> the page's controls.
RULES = (
    (r" \(command line: [^()]*\)", ""),
    (r"pass adhesion=False or interaction='none'", "untick adhesion or choose the interaction none"),
    (r"pass adhesion=False for the Hertz model", "untick adhesion for the Hertz model"),
    (r"pass adhesion=False", "untick adhesion"),
    (r"give it one \(dataclasses\.replace\(material, w=\.\.\.\)\) or",
     "choose the material custom and give its w, or"),
    (r"give one, e\.g\. asperity\.bodies\.contact_material\(material, b=[^)]*\)",
     "choose the material custom and give its b"),
    (r"give hardness= \(H0, Pa\) and h_star= \(m\)", "choose the material custom and give its H0 (size effect) "
                                                      "and h*, or untick the size effect"),
    (r"give hardness= \(H0, Pa\)", "choose the material custom and give its H0 (size effect), or untick the size "
                                   "effect"),
    (r"give h_star= \(m\)", "choose the material custom and give its h*, or untick the size effect"),
    (r"give hardness= \(Pa\)", "choose the material custom and give its hardness H"),
    (r"size_effect=True \(the size effect\)", "the size effect"),
    (r"use plasticity='jackson-green' without adhesion",
     "choose the asperity law jackson-green (it has no adhesion)"),
    (r"plasticity='jackson-green'", "the asperity law jackson-green"),
    (r", or filter asperity\.PlasticityWarning \(threshold [^)]*\)", ""),
    (r" or None \(missing\)", ""),
    (r"drop such rows with drop_nan=True[^)]*", "remove such rows from the file"),
    (r"give an uncertainty column or use weights='none'", "give an uncertainty column"),
    (r": fix one of them", ": the data do not determine them (the fit panel varies them all)"),
    (r": fix it, or give data that depend on it", ": the data do not determine it"),
)
_COMPILED = tuple((re.compile(p), r) for p, r in RULES)


def page_wording(text: str) -> str:
    """``text`` (a library message) with its advice in the explorer's words (see :data:`RULES`).

    Parameters
    ----------
    text : str
        An error or warning message of the library.

    Returns
    -------
    str
        The message as the page shows it.

    Examples
    --------
    >>> page_wording("material 'X' has no hardness: give hardness= (Pa)")
    "material 'X' has no hardness: choose the material custom and give its hardness H"
    """
    for pattern, replacement in _COMPILED:
        text = pattern.sub(replacement, text)
    return text
