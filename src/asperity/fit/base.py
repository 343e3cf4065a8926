r"""What a fit model is: parameters (:class:`ParameterSpec`), curve (:class:`FitCurve`), interface (:class:`FitModel`).

A model names its parameters with :mod:`asperity.quantities` (the SI name of a physical
quantity, ``w_J_m2``; the symbol of a dimensionless one, ``alpha``), takes their bounds and
log scale from the registry, and predicts, for a data set of each kind it supports, the
values at the data's points (:meth:`FitModel.predict`) and the curve on a grid
(:meth:`FitModel.curve`).  The models themselves are in :mod:`asperity.fit.laws` and
:mod:`asperity.fit.gw`; the registry in :mod:`asperity.fit.models`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..quantities import quantity
from .data import Dataset

__all__ = ["ParameterSpec", "FitCurve", "FitModel", "parameter_spec"]


@dataclass(frozen=True)
class ParameterSpec:
    """One parameter of a model: its start value, whether it varies by default, bounds, scale.

    Attributes
    ----------
    name : str
        Fit name: the SI name of a physical quantity (``w_J_m2``), else the symbol (``alpha``).
    value : float or None
        Start (or fixed) value; None if the user must give one.
    vary : bool
        Varied by default.
    lo, hi : float
        Bounds (from :mod:`asperity.quantities`).
    log : bool
        Fitted in log10 (the quantity spans decades).
    unit : str
        Unit (SI for physical parameters).
    meaning : str
        One line, from the registry.
    lo_inclusive, hi_inclusive : bool
        Whether the bounds themselves are valid values (the registry's; 0 is a valid work
        of adhesion, not a valid radius).
    typical : tuple of float or None
        The registry's typical range in ``unit`` (None where it has none in that unit): a
        fitted value far outside it gets a note (a unit mistake in the data).
    """

    name: str
    value: float | None
    vary: bool = False
    lo: float = -math.inf
    hi: float = math.inf
    log: bool = False
    unit: str = "1"
    meaning: str = ""
    lo_inclusive: bool = True
    hi_inclusive: bool = True
    typical: tuple | None = None

    def valid(self, value: float) -> bool:
        """True if ``value`` lies in the parameter's valid range (bounds included where valid)."""
        above = value >= self.lo if self.lo_inclusive else value > self.lo
        below = value <= self.hi if self.hi_inclusive else value < self.hi
        return bool(above and below)

    def range_text(self) -> str:
        """The valid range as text, e.g. ``'0 < R_m < inf'``."""
        left = "" if self.lo == -math.inf else f"{self.lo:g} {'<=' if self.lo_inclusive else '<'} "
        right = "" if self.hi == math.inf else f" {'<=' if self.hi_inclusive else '<'} {self.hi:g}"
        if self.hi == math.inf and self.lo != -math.inf:
            right = " < inf"
        return f"{left}{self.name}{right}" if left or right else f"{self.name} real"


def parameter_spec(qname: str, value, *, physical: bool, vary: bool = False, meaning=None) -> ParameterSpec:
    """The :class:`ParameterSpec` of registry quantity ``qname`` (SI name if ``physical``)."""
    q = quantity(qname)
    si = physical and q.si_name is not None
    return ParameterSpec(name=q.si_name if si else q.name, value=None if value is None else float(value), vary=vary,
                         lo=q.lo, hi=q.hi, log=q.log, unit=(q.si_unit if si else q.unit) or "1",
                         meaning=q.meaning if meaning is None else meaning,
                         lo_inclusive=q.lo_inclusive or q.lo == -math.inf,
                         hi_inclusive=q.hi_inclusive or q.hi == math.inf,
                         typical=q.typical if q.log and (not si or q.unit == q.si_unit) else None)


@dataclass(frozen=True)
class FitCurve:
    """A fitted curve of a single-asperity or empirical law on a grid: named columns with units.

    ``columns()`` gives name -> array (SI names, e.g. ``P_N``, ``F_N``, ``area_m2``, for
    physical data); ``to_csv()`` and ``to_dataframe()`` write them.
    """

    data: dict = field(default_factory=dict)
    parameters: dict = field(default_factory=dict, compare=False)

    def __len__(self) -> int:
        return int(np.size(next(iter(self.data.values())))) if self.data else 0

    def __getattr__(self, name):
        data = self.__dict__.get("data", {})
        if name in data:
            return data[name]
        raise AttributeError(name)

    def columns(self) -> dict:
        """Column name -> array."""
        return {k: np.asarray(v, dtype=float) for k, v in self.data.items()}

    def to_csv(self, path_or_buffer=None):
        """CSV text of the columns (written atomically to a path if given)."""
        from .._csv import columns_to_csv

        return columns_to_csv(self.columns(), path_or_buffer)

    def to_dataframe(self):
        """The curve as a pandas DataFrame (needs ``asperity[frame]``)."""
        from .._csv import columns_to_dataframe

        return columns_to_dataframe(self.columns(), self.parameters)


class FitModel:
    """Base of the fit models (see the module docstring); subclasses set the class attributes.

    Attributes
    ----------
    name : str
        Registry name.
    kinds : tuple of str
        Data kinds it predicts (``friction``, ``force``, ``pull_off``).
    physical : bool or None
        True: SI data only; False: dimensionless data only; None: either.
    uses_material : bool
        Whether ``material=`` means anything to it (the single-asperity laws' :math:`E^*` and
        starts); :func:`~asperity.fit.models.get_model` refuses a material for the others.
    uses_contact : bool
        Whether ``contact=`` means anything to it (the rough-surface model on physical data).
    """

    name = ""
    kinds: tuple[str, ...] = ()
    physical: bool | None = None
    uses_material = False
    uses_contact = False
    title = ""

    def check(self, data: Dataset) -> None:
        """Raise ValueError unless this model can fit ``data``."""
        if data.kind not in self.kinds:
            raise ValueError(f"model {self.name!r} cannot fit {data.kind} data; it fits {', '.join(self.kinds)} data")
        if self.physical is True and not data.physical:
            raise ValueError(f"model {self.name!r} works in SI units: give physical data (units in the header, "
                             "e.g. 'load [nN]', 'friction [nN]')")
        if self.physical is False and data.physical:
            raise ValueError(f"model {self.name!r} is dimensionless here; for physical data give a contact")

    def specs(self, data: Dataset) -> dict[str, ParameterSpec]:
        """Parameters (name -> :class:`ParameterSpec`) for fitting ``data``."""
        raise NotImplementedError

    def predict(self, data: Dataset, v: dict) -> tuple[np.ndarray, int]:
        """Model values at the data's points and the number of points outside its domain."""
        if data.kind == "friction":
            F, clamped = self.friction(data.x, v)
            return (F / data.x if data.quantity == "mu" else F), clamped
        if data.kind == "force":
            return self.force(data.x, v)
        return self.pull_off(data, v), 0

    def friction(self, P, v):  # pragma: no cover - every model overrides what it supports
        raise NotImplementedError

    def force(self, d, v):  # pragma: no cover
        raise NotImplementedError

    def pull_off(self, data, v):  # pragma: no cover
        raise NotImplementedError

    def curve(self, data: Dataset, v: dict, x: np.ndarray):
        """The fitted curve at ``x`` (a grid over the data's range): a :class:`FitCurve`."""
        unit = "_N" if data.physical else ""
        if data.kind == "friction":
            F, _ = self.friction(x, v)
            with np.errstate(divide="ignore", invalid="ignore"):
                mu = np.where(x > 0, F / np.where(x > 0, x, 1.0), np.nan)
            return FitCurve({f"P{unit}": x, f"F{unit}": F, "mu": mu}, dict(v))
        if data.kind == "force":
            return FitCurve({"d_m" if data.physical else "d": x, f"P{unit}": self.force(x, v)[0]}, dict(v))
        return FitCurve({"row": data.x, f"pull_off{unit}": self.pull_off(data, v)}, dict(v))

    def derived(self, v: dict) -> dict:
        """Quantities that follow from the fitted parameters (e.g. the Maugis parameter)."""
        return {}
