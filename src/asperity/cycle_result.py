"""Results of a loading cycle (:mod:`asperity.cycle`): the branches, one cycle, and pull-off and
energy against preload, as frozen dataclasses with ``columns()``, ``to_csv()``,
``to_dataframe()`` (and ``to_dict()`` for the scalars, strict JSON).

Units are the model's, per asperity: separations in :math:`\\sigma`, forces in :math:`NGb^2`,
energies in :math:`NGb^2\\sigma`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ._csv import columns_to_csv, columns_to_dataframe
from ._json import json_safe
from .curves import CurveResult
from .instrument import Jump
from .load_control import PullOff

__all__ = ["BranchCurve", "CycleResult", "PreloadCurve"]


@dataclass(frozen=True)
class BranchCurve(CurveResult):
    """One branch of a cycle, in path order: the columns of a curve, the spring's base displacement
    ``d_base`` (:math:`\\bar d - \\bar P/\\bar k`; equal to ``d`` without a spring), ``jump``
    (True where the step from the previous point is a whole-surface jump), ``branch``
    (``'approach'`` or ``'retract'``) and ``spring`` (measured through a finite spring).

    :meth:`columns` gives ``branch``, (``d_base``,) the columns of a curve (, ``jump``): ``d_base``
    and ``jump`` only with a spring; ``to_csv()`` and ``to_dataframe()`` write them.
    """

    d_base: np.ndarray = None
    jump: np.ndarray = None
    branch: str = ""
    spring: bool = False

    def columns(self) -> dict[str, np.ndarray]:
        """``branch``, (``d_base``,) the columns of a curve (, ``jump``), in that order."""
        out = {"branch": np.full(len(self), self.branch)}
        if self.spring:
            out["d_base"] = np.asarray(self.d_base)
        out.update(super().columns())
        if self.spring:
            out["jump"] = np.asarray(self.jump, dtype=bool)
        return out


@dataclass(frozen=True)
class CycleResult:
    r"""One approach-retract cycle (per asperity, model units).

    Attributes
    ----------
    approach, retract : BranchCurve
        The two branches in path order (``d`` from ``d_max`` down to ``d_min``, then back).
    pull_off : PullOff
        Most tensile force on retraction, :math:`|P|/(NGb^2)`, and its separation (on the
        measured path with a spring).
    energy : float
        Energy dissipated per cycle, :math:`E/(NGb^2\sigma) \ge 0`: the asperities' loops
        (the area between the curves) plus the jumps' losses.
    loop_energy : float
        What one asperity dissipates through the whole loop, :math:`-\int_{u_{end}}^{u_{in}}\bar P\,d\bar u`
        in :math:`Gb^2\sigma`.
    loop_fraction : float
        Fraction of the asperities that went through the whole loop.
    jump_energy : float
        Part of ``energy`` lost in the instrument's jumps (0 under displacement control).
    friction_hysteresis : float
        :math:`\int_{d_{min}}^{d_{max}}(\bar F^{ret} - \bar F^{app})\,d\bar d` in :math:`NGb^2\sigma`.
    friction_zero_load : tuple of float
        Friction force :math:`F/(NGb^2)` where the force first changes sign on approach and on
        retraction (NaN where it keeps its sign).
    d_min, d_max, preload, stiffness, u_in, u_end : float
        The cycle: closest approach, start and end, the force at the closest approach, the
        spring's stiffness :math:`k\sigma/(NGb^2)` (inf: displacement control), the jump-in
        penetration and the end of the stable branch.
    jumps : tuple of Jump
        The whole-surface jumps of the measured curve (none without a spring).
    parameters : dict
        The model's inputs.
    """

    approach: BranchCurve
    retract: BranchCurve
    pull_off: PullOff
    energy: float
    loop_energy: float
    loop_fraction: float
    jump_energy: float
    friction_hysteresis: float
    friction_zero_load: tuple[float, float]
    d_min: float
    d_max: float
    preload: float
    stiffness: float
    u_in: float
    u_end: float
    jumps: tuple[Jump, ...] = ()
    parameters: dict = field(default_factory=dict, compare=False)

    @property
    def spring(self) -> bool:
        """Whether the cycle is measured through a finite spring."""
        return not math.isinf(self.stiffness)

    def __len__(self) -> int:
        return len(self.approach) + len(self.retract)

    def columns(self) -> dict[str, np.ndarray]:
        """``branch``, (``d_base``,) the columns of a curve (, ``jump``): approach rows, then retract rows.

        ``d_base`` and ``jump`` are there only with a finite spring stiffness.
        """
        parts = [b.columns() for b in (self.approach, self.retract)]
        return {name: np.concatenate([p[name] for p in parts]) for name in parts[0]}

    def to_dataframe(self):
        """The rows as a :class:`pandas.DataFrame` (needs pandas: ``asperity[frame]``)."""
        return columns_to_dataframe(self.columns(), {**self.parameters, **self.to_dict()})

    def to_csv(self, path_or_buffer=None) -> str | None:
        """Write the rows as CSV (header, then approach and retract rows); return it if no path."""
        return columns_to_csv(self.columns(), path_or_buffer)

    def to_dict(self) -> dict:
        """The cycle's scalars as strict JSON values (NaN and inf become None)."""
        po = self.pull_off
        return json_safe({
            "d_min": self.d_min, "d_max": self.d_max, "preload": self.preload, "stiffness": self.stiffness,
            "u_in": self.u_in, "u_end": self.u_end,
            "pull_off": {"force": po.force, "d": po.d, "exists": po.exists},
            "energy": {"energy": self.energy, "loop_energy": self.loop_energy, "loop_fraction": self.loop_fraction,
                       "jump_energy": self.jump_energy},
            "friction": {"hysteresis": self.friction_hysteresis, "zero_load_approach": self.friction_zero_load[0],
                         "zero_load_retract": self.friction_zero_load[1]},
            "jumps": [j.to_dict() for j in self.jumps],
        })


@dataclass(frozen=True)
class PreloadCurve:
    """Pull-off force and energy dissipated against preload (displacement control), one row per preload.

    Columns: ``preload`` and ``pull_off`` (:math:`P/(NGb^2)`), ``d_min`` and ``d_pull_off``
    (:math:`d/\\sigma`, NaN where there is no pull-off), ``energy`` and ``friction_hysteresis``
    (:math:`NGb^2\\sigma`), ``loop_fraction``; ``d_max`` and ``u_in`` of the cycles.
    """

    preload: np.ndarray
    d_min: np.ndarray
    pull_off: np.ndarray
    d_pull_off: np.ndarray
    energy: np.ndarray
    loop_fraction: np.ndarray
    friction_hysteresis: np.ndarray
    d_max: float = math.nan
    u_in: float = 0.0
    parameters: dict = field(default_factory=dict, compare=False)

    def __len__(self) -> int:
        return int(np.size(self.preload))

    def columns(self) -> dict[str, np.ndarray]:
        """Column name -> array, in the order of the fields."""
        names = ("preload", "d_min", "pull_off", "d_pull_off", "energy", "loop_fraction", "friction_hysteresis")
        return {name: np.asarray(getattr(self, name)) for name in names}

    def to_dataframe(self):
        """The table as a :class:`pandas.DataFrame` (needs pandas)."""
        return columns_to_dataframe(self.columns(), {**self.parameters, "d_max": self.d_max, "u_in": self.u_in})

    def to_csv(self, path_or_buffer=None) -> str | None:
        """Write CSV (header, then one row per preload); return it if no path."""
        return columns_to_csv(self.columns(), path_or_buffer)
