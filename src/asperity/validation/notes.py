"""Notes on a comparison: where a model's numbers stop meaning anything, and doubts about the map.

:func:`comparison_notes` reads the table of :func:`~asperity.validation.compare.validate_surface`
and says, with the first load where it happens,

* when a model's real area exceeds the nominal area (ICHA's Hertz caps and the BGT
  asymptote have no bound; GW issues its own :class:`~asperity.physical.AreaFractionWarning`);
* when a model's mean gap is negative (the flat below the mean plane of the map: past
  the model's validity);
* when many of ICHA's summits are elongated (ridges), whose equivalent-sphere caps
  overstate their area;
* when the map's rms slope is not small, which the theories and the half-space boundary
  elements assume (a wrong height unit gives that).

:func:`model_warning_notes` turns the warnings of the GW curves into notes naming the
summit method, and the plasticity warning into what it means here (the comparison is
elastic, as the boundary elements are).
"""

from __future__ import annotations

import numpy as np

__all__ = ["comparison_notes", "model_warning_notes", "SLOPE_LIMIT", "ELONGATED_SHARE"]

#: An rms slope above this is not small: the theories compared assume slopes well below 1.
SLOPE_LIMIT = 1.0
#: ICHA is noted as unreliable when more than this share of the summits is elongated.
ELONGATED_SHARE = 0.1
_LABELS = {"spectral": "GW (spectral summits)", "detected": "GW (detected summits)", "icha": "ICHA",
           "persson": "Persson", "bgt": "BGT"}


def _first(P, mask) -> str:
    return f"P = {float(np.min(P[mask])):.4g} N"


def comparison_notes(table, methods, nominal_area, *, elongated=None, rms_slope=None) -> list[str]:
    """Notes on a comparison's table (see the module docstring).

    Parameters
    ----------
    table : dict of str -> ndarray
        The columns of the comparison (``P_N``, ``area_<method>_m2``, ``gap_<method>_m``).
    methods : sequence of str
        The area estimates compared (``spectral``, ``detected``, ``icha``, ``persson``, ``bgt``).
    nominal_area : float
        Scanned area [m^2].
    elongated : float, optional
        ICHA's share of elongated summits (:attr:`asperity.icha.IchaCurve.elongated`).
    rms_slope : float, optional
        The map's rms slope.

    Returns
    -------
    list of str
        One sentence per note, in the order above; empty if there is nothing to say.
    """
    P, notes = np.asarray(table["P_N"], dtype=float), []
    if rms_slope is not None and rms_slope > SLOPE_LIMIT:
        notes.append(f"the map's rms slope is {rms_slope:.3g}: the models and the boundary elements (a half-space "
                     "under small slopes) assume slopes well below 1; check the height unit and the scan size")
    for method in methods:
        if method in ("spectral", "detected"):
            continue  # GW says so itself (AreaFractionWarning)
        fraction = np.asarray(table[f"area_{method}_m2"], dtype=float) / nominal_area
        over = fraction > 1.0
        if over.any():
            why = " (a light-load asymptote, linear in the load)" if method == "bgt" else ""
            notes.append(f"the real area of {_LABELS[method]} exceeds the nominal area from {_first(P, over)} "
                         f"(up to {float(np.max(fraction)):.3g} times it, at P = {P[np.argmax(fraction)]:.4g} N){why}: "
                         "not physical there")
    for method in methods:
        gap = table.get(f"gap_{method}_m")
        if gap is None:
            continue
        below = np.asarray(gap, dtype=float) < 0
        if below.any():
            low = int(np.nanargmin(np.asarray(gap, dtype=float)))  # a CLI check: the least gap was shown
            notes.append(f"the mean gap of {_LABELS[method]} is negative from {_first(P, below)} (down to "
                         f"{float(gap[low]):.3g} m, at P = {P[low]:.4g} N): the model is past its validity there")
    if elongated is not None and elongated > ELONGATED_SHARE:
        notes.append(f"{100 * elongated:.3g} % of the map's summits are elongated (principal curvatures more than "
                     "10 times apart: ridges, a lay): ICHA's Hertz caps of the equivalent sphere overstate their "
                     "contact areas")
    return notes


def model_warning_notes(method: str, caught) -> list[str]:
    """The warnings of one GW curve (``caught``: :class:`warnings.WarningMessage` objects) as notes
    naming the summit ``method``; the plasticity warning says the comparison is elastic.

    Parameters
    ----------
    method : str
        ``'spectral'`` or ``'detected'``.
    caught : sequence of warnings.WarningMessage
        What the curve issued.

    Returns
    -------
    list of str
        One note per distinct warning.
    """
    from ..plasticity import PlasticityWarning

    out = []
    for w in caught:
        text = str(w.message)
        if issubclass(w.category, PlasticityWarning):
            text = (text.split(" but the model is elastic")[0] + ": the comparison is elastic, as the boundary "
                    "elements are; a real contact would yield there")
        out.append(f"{_LABELS[method]}: {text}")
    return list(dict.fromkeys(out))
