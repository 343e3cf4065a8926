r"""Approach-retract cycles of a physical contact, in SI units.

:func:`physical_cycle` and :func:`physical_preload_curve` run :func:`asperity.cycle.compute_cycle`
and :func:`asperity.cycle.compute_preload_curve` on the dimensionless model of a
:class:`~asperity.physical.PhysicalContact` and scale the results back (:math:`N` asperities,
summit height deviation :math:`\sigma_s`, nominal area :math:`A_0`):

==========================  ==========================================  ===============
quantity                    scale                                       SI name
==========================  ==========================================  ===============
separation, base position   :math:`\sigma_s`                            ``d_m``, ``d_base_m``
force, preload, pull-off    :math:`NGb^2`                               ``P_N``, ``preload_N``
spring stiffness            :math:`\bar k = k\sigma_s/(NGb^2)`          ``stiffness_N_m``
energy per cycle            :math:`NGb^2\sigma_s` (J); per :math:`A_0`  ``energy_J``, ``energy_J_m2``
one asperity's loop energy  :math:`Gb^2\sigma_s`                        ``loop_energy_J``
asperities through the loop :math:`N`                                   ``loop_count``
==========================  ==========================================  ===============

References
----------
.. [1] Adams et al., Eqs (7), (16), (17), (20).
.. [2] K. N. G. Fuller, D. Tabor, Proc. R. Soc. A 345 (1975) 327.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from ._csv import columns_to_csv, columns_to_dataframe
from ._json import json_safe
from ._validation import check_1d, check_finite_result, check_scalar_positive
from ._warnings import frames_to_user
from .cycle import CycleResult, PreloadCurve, compute_cycle, compute_preload_curve
from .cycle_integrals import CycleIntegrals
from .cycle_run import MAX_POINTS
from .physical import PhysicalContact, PhysicalCurve, PhysicalPullOff, warn_area_fraction
from .physical_cycle_inputs import check_cycle_separations, cycle_stiffness, cycle_u_in, length_input, scaled_error
from .quantities import CYCLE_QUANTITIES
from .units import to_si

__all__ = ["PhysicalBranch", "PhysicalCycle", "PhysicalPreloadCurve", "physical_cycle", "physical_preload_curve"]


def _si(name: str) -> str:
    return CYCLE_QUANTITIES[name].si_name


@dataclass(frozen=True)
class PhysicalBranch(PhysicalCurve):
    """One branch of a physical cycle in SI units (columns of :data:`~asperity.physical.PHYSICAL_COLUMNS`),
    with the spring's base displacement ``d_base`` (m), the ``jump`` marks, the ``branch`` name and
    ``spring`` (measured through a finite spring).  :meth:`columns`: ``branch``, (``d_base_m``,) the
    SI columns of a curve (, ``jump``)."""

    d_base: np.ndarray = None
    jump: np.ndarray = None
    branch: str = ""
    spring: bool = False

    def columns(self) -> dict[str, np.ndarray]:
        """``branch``, (``d_base_m``,) the SI columns of a curve (, ``jump``), in that order."""
        out = {"branch": np.full(len(self), self.branch)}
        if self.spring:
            out[_si("d_base")] = np.asarray(self.d_base)
        out.update(super().columns())
        if self.spring:
            out["jump"] = np.asarray(self.jump, dtype=bool)
        return out


@dataclass(frozen=True)
class PhysicalCycle:
    """An approach-retract cycle in SI units; ``dimensionless`` is the model's :class:`~asperity.cycle.CycleResult`.

    Attributes: ``approach``, ``retract`` (:class:`PhysicalBranch`), ``pull_off``
    (:class:`~asperity.physical.PhysicalPullOff`), ``energy_J``, ``energy_J_m2`` (per nominal
    area), ``loop_energy_J`` (one asperity's whole loop), ``loop_count``, ``jump_energy_J``,
    ``friction_hysteresis_N_m``, ``friction_zero_load_N``, ``d_min_m``, ``d_max_m``,
    ``preload_N``, ``stiffness_N_m`` (inf: displacement control), ``u_in_m``, ``jumps`` (dicts
    with SI names), ``parameters``.
    """

    approach: PhysicalBranch
    retract: PhysicalBranch
    pull_off: PhysicalPullOff
    energy_J: float
    energy_J_m2: float
    loop_energy_J: float
    loop_count: float
    jump_energy_J: float
    friction_hysteresis_N_m: float
    friction_zero_load_N: tuple[float, float]
    d_min_m: float
    d_max_m: float
    preload_N: float
    stiffness_N_m: float
    u_in_m: float
    jumps: tuple[dict, ...]
    dimensionless: CycleResult = field(repr=False, compare=False)
    parameters: dict = field(default_factory=dict, compare=False)

    def __len__(self) -> int:
        return len(self.approach) + len(self.retract)

    def columns(self) -> dict[str, np.ndarray]:
        """``branch``, (``d_base_m``,) the SI columns of a curve (, ``jump``): approach rows, then retract rows."""
        parts = [b.columns() for b in (self.approach, self.retract)]
        return {name: np.concatenate([p[name] for p in parts]) for name in parts[0]}

    def to_dataframe(self):
        """The rows as a :class:`pandas.DataFrame` (needs pandas); scalars in ``attrs``."""
        return columns_to_dataframe(self.columns(), {**self.parameters, **self.to_dict()})

    def to_csv(self, path_or_buffer=None) -> str | None:
        """Write the rows as CSV (SI column names); return it if no path."""
        return columns_to_csv(self.columns(), path_or_buffer)

    def to_dict(self) -> dict:
        """The cycle's scalars in SI units as strict JSON values (NaN and inf become None)."""
        po = self.pull_off
        return json_safe({
            "d_min_m": self.d_min_m, "d_max_m": self.d_max_m, "preload_N": self.preload_N,
            "stiffness_N_m": self.stiffness_N_m, "u_in_m": self.u_in_m,
            "pull_off": {"force_N": po.force, "d_m": po.d, "exists": po.exists},
            "energy": {"energy_J": self.energy_J, "energy_J_m2": self.energy_J_m2, "loop_energy_J": self.loop_energy_J,
                       "loop_count": self.loop_count, "jump_energy_J": self.jump_energy_J},
            "friction": {"hysteresis_N_m": self.friction_hysteresis_N_m,
                         "zero_load_approach_N": self.friction_zero_load_N[0],
                         "zero_load_retract_N": self.friction_zero_load_N[1]},
            "jumps": list(self.jumps),
        })


@dataclass(frozen=True)
class PhysicalPreloadCurve:
    """Pull-off force and energy dissipated against preload, in SI units, one row per preload.

    ``dimensionless`` is the model's :class:`~asperity.cycle.PreloadCurve`.
    """

    preload_N: np.ndarray
    d_min_m: np.ndarray
    pull_off_N: np.ndarray
    d_pull_off_m: np.ndarray
    energy_J: np.ndarray
    energy_J_m2: np.ndarray
    loop_count: np.ndarray
    friction_hysteresis_N_m: np.ndarray
    dimensionless: PreloadCurve = field(repr=False, compare=False)
    parameters: dict = field(default_factory=dict, compare=False)

    def __len__(self) -> int:
        return int(np.size(self.preload_N))

    def columns(self) -> dict[str, np.ndarray]:
        """Column name (with unit) -> array, in the order of the fields."""
        names = ("preload_N", "d_min_m", "pull_off_N", "d_pull_off_m", "energy_J", "energy_J_m2", "loop_count",
                 "friction_hysteresis_N_m")
        return {name: np.asarray(getattr(self, name)) for name in names}

    def to_dataframe(self):
        """The table as a :class:`pandas.DataFrame` (needs pandas)."""
        return columns_to_dataframe(self.columns(), self.parameters)

    def to_csv(self, path_or_buffer=None) -> str | None:
        """Write CSV (header of column names with units); return it if no path."""
        return columns_to_csv(self.columns(), path_or_buffer)


def _branch(contact: PhysicalContact, b) -> PhysicalBranch:
    sigma, fs = contact.surface.sigma_s, contact.force_scale
    P, area = b.P * fs, b.area * contact.area_scale
    with np.errstate(divide="ignore", invalid="ignore"):
        pressure = np.where(area > 0, P / np.where(area > 0, area, 1.0), np.nan)
    return PhysicalBranch(d=b.d * sigma, P=P, F=b.F * fs, mu=b.mu, area=area, pressure=pressure,
                          contacts=b.contacts * contact.N, dimensionless=b, parameters=contact.parameters(),
                          plastic=None if b.plastic is None else b.plastic * contact.N,
                          nominal_area=contact.surface.area, d_base=b.d_base * sigma, jump=b.jump, branch=b.branch,
                          spring=b.spring)


def physical_cycle(contact: PhysicalContact, *, d_min=None, preload=None, d_max=None, d=None, n=200,
                   stiffness=None, u_in=0.0) -> PhysicalCycle:
    r"""One approach-retract cycle of a physical contact, in SI units (:func:`asperity.cycle.cycle`).

    .. math::
        \bar d = d/\sigma_s,\quad \bar P = P/(NGb^2),\quad \bar k = k\sigma_s/(NGb^2),\quad
        E = \bar E\,NGb^2\sigma_s,\quad E/A_0

    Parameters
    ----------
    contact : PhysicalContact
        The material and surface.
    d_min : float, str or pint.Quantity, optional
        Closest approach (m, e.g. ``'2nm'``).
    preload : float, str or pint.Quantity, optional
        Largest compressive load (N, > 0, e.g. ``'1mN'``).  Give exactly one of ``d_min`` and ``preload``.
    d_max : float, str or pint.Quantity, optional
        Start and end of the cycle (m; default :math:`(10 - \bar u_{end})\sigma_s`).
    d : array_like or pint.Quantity, optional
        Separations (m) at which to evaluate both branches instead of the path (no spring).
    n : int
        Points per branch on the path (default 200).
    stiffness : float, str or pint.Quantity, optional
        Spring stiffness (N/m, > 0, e.g. ``'0.1N/m'``); None or inf: displacement control.
    u_in : float, str or pint.Quantity
        Penetration (m, in :math:`[\bar u_{end}\sigma_s, 0]`) at which an approaching asperity jumps
        into contact (default 0: first touch).

    Returns
    -------
    PhysicalCycle
        Curves in SI units (``d_m``, ``P_N``, ...; ``d_base_m`` and ``jump`` with a spring), the
        pull-off (N, m), ``energy_J``, ``energy_J_m2``, ``loop_energy_J``, ``loop_count``,
        ``jump_energy_J``, ``friction_hysteresis_N_m``, ``friction_zero_load_N``.

    Raises
    ------
    ValueError
        For an input out of its range (messages as :func:`asperity.cycle.cycle`, with the scales).

    Warns
    -----
    AreaFractionWarning
        If the real contact area passes 10 % of the nominal area on either branch
        (:func:`asperity.physical.warn_area_fraction`).
    PlasticityWarning
        If, with the elastic law, more than the contact's ``plastic_threshold`` of the
        asperities in contact are past the critical interference at the closest approach.
    AsperityWarning
        With an elastic-plastic law (no unloading: the retraction retraces the approach).

    Examples
    --------
    >>> from asperity.physical import PhysicalContact, Surface
    >>> contact = PhysicalContact("Au", Surface(2e-9, 100e-9, 2e14, 1e-12), plastic_threshold=1.0)  # (they yield)
    >>> c = physical_cycle(contact, preload="5uN", n=50)
    >>> c.pull_off.exists, bool(c.energy_J > 0), round(c.energy_J_m2 / c.energy_J * 1e-12, 12)
    (True, True, 1.0)

    References
    ----------
    Fuller & Tabor (1975); Adams et al., Eqs (7), (16), (17), (20).
    """
    if not isinstance(contact, PhysicalContact):
        raise ValueError(f"contact must be an asperity.physical.PhysicalContact, got {type(contact).__name__}")
    sigma, fs = contact.surface.sigma_s, contact.force_scale
    d_min = length_input(d_min, "d_min")
    d_max = length_input(d_max, "d_max")
    u_in_m = cycle_u_in(contact, length_input(u_in, "u_in", required=True))
    check_cycle_separations(contact, d_min, preload is not None, d_max)
    if preload is not None:
        preload = check_scalar_positive(preload, "preload", "N")
        with np.errstate(all="ignore"):
            preload = float(check_finite_result(np.float64(preload) / fs, "preload/(N G b^2)", preload=preload))
    k = cycle_stiffness(contact, stiffness)
    if d is not None:
        d = check_1d(to_si(d, "m", "d"), "d")
        check_cycle_separations(contact, d_min, preload is not None, d_max, d)
        with np.errstate(all="ignore"):
            d = check_finite_result(d / sigma, "d/sigma_s", d=d, sigma_s=sigma)
    try:
        ci = CycleIntegrals(contact.model, u_in_m / sigma)
        res = compute_cycle(ci, d_min=None if d_min is None else d_min / sigma, preload=preload,
                            d_max=None if d_max is None else d_max / sigma, d=d, n=n, stiffness=k)
    except ValueError as err:
        raise scaled_error(contact, err) from None
    po = res.pull_off
    energy = fs * sigma
    approach, retract = _branch(contact, res.approach), _branch(contact, res.retract)
    if res.approach.plastic is None:  # the elastic law: checked as every curve (the closest approach decides)
        contact.warn_if_yielding(res.approach.d, res.approach.contacts, stacklevel=2 + frames_to_user())
    warn_area_fraction(max(approach.max_area_fraction, retract.max_area_fraction), stacklevel=1 + frames_to_user(),
                       where=" during the cycle")
    jumps = tuple({"branch": j.branch, "d_base_m": j.d_base * sigma, "d_from_m": j.d_from * sigma,
                   "d_to_m": j.d_to * sigma, "P_from_N": j.P_from * fs, "P_to_N": j.P_to * fs,
                   "energy_J": j.energy * energy} for j in res.jumps)
    return PhysicalCycle(
        approach=approach, retract=retract,
        pull_off=PhysicalPullOff(force=po.force * fs, d=po.d * sigma, exists=po.exists, dimensionless=po),
        energy_J=res.energy * energy, energy_J_m2=res.energy * energy / contact.surface.area,
        loop_energy_J=res.loop_energy * energy / contact.N, loop_count=res.loop_fraction * contact.N,
        jump_energy_J=res.jump_energy * energy, friction_hysteresis_N_m=res.friction_hysteresis * energy,
        friction_zero_load_N=tuple(x * fs for x in res.friction_zero_load), d_min_m=res.d_min * sigma,
        d_max_m=res.d_max * sigma, preload_N=res.preload * fs, stiffness_N_m=res.stiffness * fs / sigma,
        u_in_m=res.u_in * sigma, jumps=jumps, dimensionless=res,
        parameters={**contact.parameters(), "u_in_m": res.u_in * sigma})


def physical_preload_curve(contact: PhysicalContact, preload, *, d_max=None, u_in=0.0) -> PhysicalPreloadCurve:
    r"""Pull-off force and energy dissipated against preload (N), in SI units (:func:`asperity.cycle.preload_curve`).

    Parameters
    ----------
    contact : PhysicalContact
        The material and surface.
    preload : array_like or pint.Quantity
        Preloads (N, > 0).
    d_max : float, str or pint.Quantity, optional
        Start and end of each cycle (m; default :math:`(10 - \bar u_{end})\sigma_s`).
    u_in : float, str or pint.Quantity
        Jump-in penetration (m, default 0).

    Returns
    -------
    PhysicalPreloadCurve
        ``preload_N``, ``d_min_m``, ``pull_off_N``, ``d_pull_off_m``, ``energy_J``, ``energy_J_m2``,
        ``loop_count``, ``friction_hysteresis_N_m``, one per preload.

    Raises
    ------
    ValueError
        For a preload that is not positive or out of the model's domain, or another input out of range.

    Examples
    --------
    >>> from asperity.physical import PhysicalContact, Surface
    >>> contact = PhysicalContact("Au", Surface(2e-9, 100e-9, 2e14, 1e-12), plastic_threshold=1.0)  # (they yield)
    >>> pc = physical_preload_curve(contact, [1e-9, 1e-6, 1e-4])
    >>> bool(pc.pull_off_N[0] <= pc.pull_off_N[1] <= pc.pull_off_N[2])
    True

    References
    ----------
    Fuller & Tabor (1975); Adams et al., Eq (18), Table 1.
    """
    if not isinstance(contact, PhysicalContact):
        raise ValueError(f"contact must be an asperity.physical.PhysicalContact, got {type(contact).__name__}")
    sigma, fs = contact.surface.sigma_s, contact.force_scale
    P = check_1d(to_si(preload, "N", "preload"), "preload")
    if P.size > MAX_POINTS:
        raise ValueError(f"preload must hold at most {MAX_POINTS} values, got {P.size}")
    if np.any(P <= 0):
        raise ValueError(f"preload (largest compressive loads) must be > 0 N, got min {P.min():g} N")
    d_max = length_input(d_max, "d_max")
    u_in_m = cycle_u_in(contact, length_input(u_in, "u_in", required=True))
    try:
        ci = CycleIntegrals(contact.model, u_in_m / sigma)
        with np.errstate(all="ignore"):
            P_bar = check_finite_result(P / fs, "preload/(N G b^2)", preload=P)
        res = compute_preload_curve(ci, P_bar, d_max=None if d_max is None else d_max / sigma)
    except ValueError as err:
        raise scaled_error(contact, err) from None
    energy = fs * sigma
    return PhysicalPreloadCurve(
        preload_N=P, d_min_m=res.d_min * sigma, pull_off_N=res.pull_off * fs, d_pull_off_m=res.d_pull_off * sigma,
        energy_J=res.energy * energy, energy_J_m2=res.energy * energy / contact.surface.area,
        loop_count=res.loop_fraction * contact.N, friction_hysteresis_N_m=res.friction_hysteresis * energy,
        dimensionless=res, parameters={**contact.parameters(), "d_max_m": res.d_max * sigma,
                                       "u_in_m": res.u_in * sigma})
