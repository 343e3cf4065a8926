r"""Results of a physical contact in SI units, and the warning of a too large contact area.

:class:`PhysicalCurve` (columns in :data:`PHYSICAL_COLUMNS`, from the quantity registry)
and :class:`PhysicalPullOff` are what :class:`asperity.physical.PhysicalContact`
returns; :mod:`asperity.physical` re-exports everything here.

**The GW assumption.**  Greenwood-Williamson asperities are independent, which needs a
real contact area :math:`A` well below the nominal area :math:`A_0`.  Every curve carries
``area_fraction`` :math:`= A/A_0` and the flags ``area_fraction_high`` (above
:data:`AREA_FRACTION_CAUTION`, 10 %: neighbouring contacts interact, the results degrade)
and ``exceeds_nominal_area`` (above :data:`AREA_FRACTION_LIMIT`, 100 %: more contact than
surface, not physical).  A call whose result passes 10 % issues one
:class:`AreaFractionWarning` (:func:`warn_area_fraction`), an
:class:`asperity.AsperityWarning` like every validity warning of the library (the command
line prints it as one ``asperity: note:`` line); :meth:`PhysicalCurve.validity_warnings`
gives the same sentence as text.

References
----------
.. [1] J. A. Greenwood, J. B. P. Williamson, Proc. R. Soc. A 295 (1966) 300.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field

import numpy as np

from ._csv import columns_to_csv, columns_to_dataframe
from ._validation import check_scalar_positive, check_text
from ._warnings import AsperityWarning
from .curves import CurveResult, PullOff
from .quantities import CURVE_COLUMNS, PLASTIC_COLUMNS

__all__ = [
    "PHYSICAL_COLUMNS",
    "PHYSICAL_PLASTIC_COLUMNS",
    "AREA_FRACTION_CAUTION",
    "AREA_FRACTION_LIMIT",
    "AreaFractionWarning",
    "warn_area_fraction",
    "PhysicalCurve",
    "PhysicalPullOff",
]


#: Columns of a :class:`PhysicalCurve`: attribute -> (CSV/DataFrame column, SI unit, meaning),
#: derived from :data:`asperity.quantities.CURVE_COLUMNS`.
PHYSICAL_COLUMNS = {name: (q.si_name, q.si_unit, q.si_meaning) for name, q in CURVE_COLUMNS.items()}
#: The optional column ``plastic`` (number of asperities past the critical interference), as above.
PHYSICAL_PLASTIC_COLUMNS = {name: (q.si_name, q.si_unit, q.si_meaning) for name, q in PLASTIC_COLUMNS.items()}


#: Real over nominal contact area above which a curve warns: neighbouring contacts interact.
AREA_FRACTION_CAUTION = 0.1
#: Real over nominal contact area above which the GW model is broken (more contact than surface).
AREA_FRACTION_LIMIT = 1.0


class AreaFractionWarning(AsperityWarning):
    """The real contact area of a result passes 10 % (or 100 %) of the nominal area.

    The Greenwood-Williamson model treats asperities as independent; this needs the real
    contact area well below the nominal one.  An :class:`asperity.AsperityWarning` (a
    :class:`UserWarning`): filter it like any warning, e.g.
    ``warnings.simplefilter("ignore", asperity.AreaFractionWarning)``.
    """


def _area_fraction_message(fraction: float, caution: float = AREA_FRACTION_CAUTION, where: str = "") -> str | None:
    """The warning for a largest real/nominal area ``fraction``, or None up to ``caution``;
    ``where`` (e.g. ``" from P = 10 N"``) says from which load on it is passed."""
    if not fraction > caution:  # also False for NaN
        return None
    if fraction > AREA_FRACTION_LIMIT:
        return (f"the real contact area reaches {fraction:.3g} times the nominal area (above "
                f"{100 * max(caution, AREA_FRACTION_LIMIT):g} %{where}): the GW model's assumption is broken and "
                "these numbers are not physical")
    return (f"the real contact area reaches {100 * fraction:.3g} % of the nominal area (above {100 * caution:g} %"
            f"{where}): neighbouring asperities interact and the GW model (independent asperities) is unreliable "
            "there")


def warn_area_fraction(fraction, *, stacklevel: int = 1, where: str = "") -> None:
    """Issue one :class:`AreaFractionWarning` if ``fraction`` passes :data:`AREA_FRACTION_CAUTION`.

    Parameters
    ----------
    fraction : float
        Largest real over nominal contact area of a result, >= 0 (NaN: no warning).
    stacklevel : int
        As for :func:`warnings.warn`, counted from the caller of this function (1: the caller).
    where : str
        Where the fraction is reached, appended to the limit in the message (e.g.
        ``" at pull-off"``); default none.

    Returns
    -------
    None

    Raises
    ------
    TypeError
        If ``fraction`` is not a real number, ``stacklevel`` not an integer or ``where`` not a string.
    """
    if isinstance(fraction, bool) or not isinstance(fraction, int | float | np.integer | np.floating):
        raise TypeError(f"fraction must be a real number, got {type(fraction).__name__} {fraction!r}")
    if not (fraction >= 0 or math.isnan(fraction)) or math.isinf(fraction):
        raise ValueError(f"fraction must be finite and >= 0 (or NaN), got {fraction!r}")
    if isinstance(stacklevel, bool) or not isinstance(stacklevel, int):
        raise TypeError(f"stacklevel must be an integer, got {type(stacklevel).__name__} {stacklevel!r}")
    where = check_text(where, "where")
    message = _area_fraction_message(float(fraction), where=where)
    if message is not None:
        warnings.warn(message, AreaFractionWarning, stacklevel=stacklevel + 1)


@dataclass(frozen=True)
class PhysicalCurve:
    """A curve in SI units; columns and units in :data:`PHYSICAL_COLUMNS`.

    ``d`` [m], ``P`` [N], ``F`` [N], ``mu`` [-], ``area`` [m^2], ``pressure`` [Pa] (= P/area),
    ``contacts`` [number of asperities].  ``dimensionless`` is the model's own
    :class:`~asperity.CurveResult`; ``parameters`` the inputs and groups.  ``plastic``
    [number of asperities past the critical interference] is None unless the per-asperity
    law is elastic-plastic (``plasticity='jackson-green'``); then it is the last column.
    """

    d: np.ndarray
    P: np.ndarray
    F: np.ndarray
    mu: np.ndarray
    area: np.ndarray
    pressure: np.ndarray
    contacts: np.ndarray
    dimensionless: CurveResult = field(repr=False, compare=False)
    parameters: dict = field(default_factory=dict, compare=False)
    nominal_area: float = math.nan
    plastic: np.ndarray | None = None

    @property
    def area_fraction(self) -> np.ndarray:
        """Real over nominal contact area.  The GW model (independent asperities) needs it
        well below 1; above ~0.1 neighbouring contacts interact and the results degrade."""
        return self.area / self.nominal_area

    @property
    def max_area_fraction(self) -> float:
        """Largest real over nominal contact area of the curve (0 without contact)."""
        fraction = np.asarray(self.area_fraction, dtype=float)
        return float(np.max(fraction)) if fraction.size else 0.0

    @property
    def area_fraction_high(self) -> bool:
        """True if the real contact area passes :data:`AREA_FRACTION_CAUTION` (10 %) of the
        nominal area somewhere: the results degrade there (an :class:`AreaFractionWarning`)."""
        return self.max_area_fraction > AREA_FRACTION_CAUTION

    @property
    def exceeds_nominal_area(self) -> bool:
        """True if the real contact area passes the nominal area (:data:`AREA_FRACTION_LIMIT`)
        somewhere: the GW assumption is broken there."""
        return self.max_area_fraction > AREA_FRACTION_LIMIT

    def validity_warnings(self, limit: float = AREA_FRACTION_CAUTION) -> list[str]:
        """Reasons to distrust the curve, as sentences: the real contact area above ``limit``
        (default :data:`AREA_FRACTION_CAUTION`, 10 %) of the nominal area, from the smallest
        load where it is; the text of the :class:`AreaFractionWarning` the curve issued.  Empty
        when there are none."""
        limit = check_scalar_positive(limit, "limit")
        fraction = np.asarray(self.area_fraction, dtype=float)
        with np.errstate(invalid="ignore"):
            if not (fraction > limit).any():
                return []
            # the message names the limit passed: 100 % once the nominal area is exceeded
            passed = max(limit, AREA_FRACTION_LIMIT) if np.nanmax(fraction) > AREA_FRACTION_LIMIT else limit
            over = fraction > passed
        where = f" from P = {float(np.min(np.asarray(self.P)[over])):.4g} N"
        return [_area_fraction_message(float(np.nanmax(fraction)), limit, where)]

    def __len__(self) -> int:
        return int(np.size(self.d))

    def _column_table(self) -> dict:
        if self.plastic is None:
            return PHYSICAL_COLUMNS
        return {**PHYSICAL_COLUMNS, **PHYSICAL_PLASTIC_COLUMNS}

    def columns(self) -> dict[str, np.ndarray]:
        """Column name (with unit, e.g. ``'P_N'``) -> array, in the order of :data:`PHYSICAL_COLUMNS`
        (then ``plastic``, if present)."""
        return {col: np.asarray(getattr(self, attr)) for attr, (col, _, _) in self._column_table().items()}

    def to_dataframe(self):
        """The curve as a :class:`pandas.DataFrame` (needs pandas); units in ``attrs['units']``."""
        units = {col: unit for col, unit, _ in self._column_table().values()}
        return columns_to_dataframe(self.columns(), {**self.parameters, "units": units})

    def to_csv(self, path_or_buffer=None) -> str | None:
        """Write CSV (header of column names with units, e.g. ``d_m,P_N,...``); return it if no path."""
        return columns_to_csv(self.columns(), path_or_buffer)


@dataclass(frozen=True)
class PhysicalPullOff:
    """Pull-off force in newtons (>= 0) and the separation in metres where it occurs.

    ``d`` is NaN when ``exists`` is False.  ``dimensionless`` is the model's
    :class:`~asperity.PullOff`.  ``area`` is the real contact area (m^2) at the pull-off
    separation (0 when no force is tensile) and ``nominal_area`` the surface's (m^2).
    """

    force: float
    d: float
    exists: bool
    dimensionless: PullOff = field(repr=False, compare=False)
    area: float = 0.0
    nominal_area: float = math.nan

    @property
    def area_fraction(self) -> float:
        """Real over nominal contact area at the pull-off separation."""
        return self.area / self.nominal_area

    def to_dict(self) -> dict:
        """``{'pull_off_N', 'd_m', 'exists', 'area_m2', 'area_fraction'}``; NaN becomes None (strict JSON)."""
        def finite(x):
            return x if math.isfinite(x) else None
        return {"pull_off_N": self.force, "d_m": finite(self.d), "exists": self.exists,
                "area_m2": self.area, "area_fraction": finite(self.area_fraction)}
