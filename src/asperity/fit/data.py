r"""Measured data for the fits: friction against load, normal force against separation, pull-off forces.

A :class:`Dataset` holds one data set of one *kind*:

=============  ==========================  =================================  ===========================
kind           x (independent)             y (measured)                       uncertainty columns
=============  ==========================  =================================  ===========================
``friction``   load :math:`P`              friction :math:`F`, or :math:`\mu`   ``F_err``/``mu_err``, ``P_err``
``force``      separation :math:`d`        normal force :math:`P`             ``P_err``, ``d_err``
``pull_off``   the row (one condition)     pull-off force :math:`|P_{po}|`    ``pull_off_err``
=============  ==========================  =================================  ===========================

Values are either dimensionless (the paper's units: :math:`P/NGb^2`, :math:`d/\sigma`) or
physical, in SI units (newtons, metres); a physical data set can only be fitted by a
physical model.  A pull-off data set may carry *condition* columns, one value per row,
named after a model parameter (``alpha``, ``R_m``, ``R [nm]``, ``sigma_s [nm]``): each
row is then one surface or condition, and the parameter takes that row's value.

:func:`~asperity.fit.read.read_data` reads them from CSV files (columns found by their
header names and units); :func:`friction_load_data`, :func:`force_separation_data` and
:func:`pull_off_data` build them from arrays.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .._validation import as_float_array, check_bool, check_text
from ..units import is_quantity, to_si
from .headers import condition_names

__all__ = ["KINDS", "MAX_ROWS", "Dataset", "friction_load_data", "force_separation_data", "pull_off_data"]

#: Data kinds: name -> (meaning of x, meaning of y).
KINDS = {
    "friction": ("load P", "friction force F or coefficient mu"),
    "force": ("separation d", "normal force P"),
    "pull_off": ("condition (row)", "pull-off force |P|"),
}
#: Largest number of data rows read.
MAX_ROWS = 10**6

@dataclass(frozen=True)
class Dataset:
    r"""One measured data set (see the module docstring for the kinds and units).

    Parameters
    ----------
    kind : {'friction', 'force', 'pull_off'}
        What was measured.
    x : array_like
        Loads (``friction``), separations (``force``) or row numbers (``pull_off``).
    y : array_like
        Friction force or coefficient, normal force, or pull-off force (> 0).
    quantity : {'F', 'mu', 'P', 'pull_off'}
        What ``y`` is.
    physical : bool
        SI units (N, m) rather than the paper's dimensionless units.
    y_err, x_err : array_like, optional
        Standard uncertainties of ``y`` and ``x`` (> 0), in their units.
    conditions : dict, optional
        Per-row parameter values (``pull_off``), ``{name: array}`` with fit names (``alpha``,
        ``R_m``).
    name : str
        Label (the file name when read).
    n_dropped : int
        Rows dropped because they held NaN (``drop_nan``).
    notes : tuple of str
        What the reader did that the user should know (ignored columns, dropped rows).

    Raises
    ------
    ValueError
        For arrays that are not 1-D, real and finite, of unequal length or out of range.
    """

    kind: str
    x: np.ndarray
    y: np.ndarray
    quantity: str
    physical: bool = False
    y_err: np.ndarray | None = None
    x_err: np.ndarray | None = None
    conditions: dict = field(default_factory=dict)
    name: str = ""
    n_dropped: int = 0
    notes: tuple[str, ...] = ()

    def __post_init__(self):
        if self.kind not in KINDS:
            raise ValueError(f"kind must be one of {', '.join(KINDS)}, got {self.kind!r}")
        allowed = {"friction": ("F", "mu"), "force": ("P",), "pull_off": ("pull_off",)}[self.kind]
        if self.quantity not in allowed:
            raise ValueError(f"quantity of {self.kind!r} data must be one of {allowed}, got {self.quantity!r}")
        set_ = object.__setattr__
        x, y = _vector(self.x, "x"), _vector(self.y, "y")
        if x.size != y.size:
            raise ValueError(f"x and y must have the same length, got {x.size} and {y.size}")
        set_(self, "x", x)
        set_(self, "y", y)
        for name in ("y_err", "x_err"):
            err = getattr(self, name)
            if err is not None:
                err = _vector(err, name)
                if err.size != x.size:
                    raise ValueError(f"{name} must have the length of x ({x.size}), got {err.size}")
                if np.any(err <= 0):
                    raise ValueError(f"{name} (uncertainty) must be > 0 in every row, got min {err.min():g}")
                set_(self, name, err)
        known = {fit: si for fit, si in condition_names().values()}
        conditions = {}
        for k, v in dict(self.conditions).items():
            if k not in known:  # a user trial: a typo ('R' for 'R_m') was ignored without a word
                raise ValueError(f"conditions: unknown name {k!r}; the names are {', '.join(sorted(known))}")
            conditions[k] = _vector(v, f"conditions[{k!r}]", self.physical, known[k])
        for k, v in conditions.items():
            if v.size != x.size:
                raise ValueError(f"conditions[{k!r}] must have one value per row ({x.size}), got {v.size}")
        set_(self, "conditions", conditions)
        set_(self, "physical", bool(self.physical))
        set_(self, "notes", tuple(str(n) for n in self.notes))
        self._check_values()

    def _check_values(self):
        x, y = self.x, self.y
        if self.quantity == "mu" and np.any(x <= 0):  # first: mu = F/P < 0 there says nothing of the sign
            i = int(np.flatnonzero(x <= 0)[0])
            raise ValueError(f"a friction coefficient needs a load > 0, got P = {x[i]:g} at row {i + 1} (give the "
                             "friction force F instead)")
        if self.quantity in ("F", "mu") and np.any(y < 0):
            i = int(np.flatnonzero(y < 0)[0])
            raise ValueError(f"negative friction: {self.quantity} = {y[i]:g} at row {i + 1} (friction is >= 0; "
                             "flip the sign of the lateral signal, or drop the row)")
        if self.quantity == "pull_off" and np.any(y <= 0):
            i = int(np.flatnonzero(y <= 0)[0])
            raise ValueError(f"pull-off forces must be > 0 (magnitudes), got {y[i]:g} at row {i + 1}")

    def __len__(self) -> int:
        return int(self.x.size)

    @property
    def x_name(self) -> str:
        """Name of x: ``'P'``/``'P_N'``, ``'d'``/``'d_m'`` or ``'row'``."""
        base = {"friction": "P", "force": "d", "pull_off": "row"}[self.kind]
        return base if not self.physical or base == "row" else {"P": "P_N", "d": "d_m"}[base]

    @property
    def y_name(self) -> str:
        """Name of y: ``'F'``/``'F_N'``, ``'mu'``, ``'P'``/``'P_N'`` or ``'pull_off'``/``'pull_off_N'``."""
        if not self.physical or self.quantity == "mu":
            return self.quantity
        return f"{self.quantity}_N"


#: The SI unit of each column a quantity (pint) may be given for, with physical=True.
_SI_UNITS = {"P": "N", "F": "N", "force": "N", "d": "m", "mu": ""}


def _vector(value, name, physical=False, si=None) -> np.ndarray:
    listed = isinstance(value, list | tuple) and any(is_quantity(v) or isinstance(v, str) for v in value)
    if is_quantity(value) or listed:  # a review: nN quantities lost their unit (values 1e9 too large)
        base = name[:-4] if name.endswith("_err") else name
        if physical is not True:
            raise ValueError(f"{name} is a quantity ({value!r}) but the data are dimensionless: pass "
                             "physical=True for SI data, or plain numbers in the model's units")
        value = to_si(value, _SI_UNITS[base] if si is None else si, name)
    arr = as_float_array(value, name)
    if arr.ndim != 1:
        raise ValueError(f"{name} must be 1-D, got shape {arr.shape}")
    if arr.size > MAX_ROWS:
        raise ValueError(f"{name} has {arr.size} points, more than MAX_ROWS = {MAX_ROWS}")
    return arr


def _columns(physical, name, required=1, **columns) -> tuple:
    """The columns (None stays None) as 1-D float arrays of one length, ``physical`` and ``name``
    checked: errors name the user's arguments (``P``, ``F``, ``force_err``, ...); the first
    ``required`` columns may not be None."""
    out = {k: None if v is None and i >= required else _vector(v, k, physical)
           for i, (k, v) in enumerate(columns.items())}
    given = {k: v for k, v in out.items() if v is not None}  # the first (x, or the forces) is required
    first = next(iter(given))
    for k, v in given.items():
        if v.size != given[first].size:
            raise ValueError(f"{k} must have the length of {first} ({given[first].size}), got {v.size}")
        if k.endswith("_err") and np.any(v <= 0):
            raise ValueError(f"{k} (uncertainty) must be > 0 in every row, got min {v.min():g}")
    return (*out.values(), check_bool(physical, "physical"), check_text(name, "name"))


def friction_load_data(P, F=None, *, mu=None, F_err=None, mu_err=None, P_err=None, physical=False,
                       name="friction") -> Dataset:
    r"""A friction-versus-load data set from arrays: :math:`F` (or :math:`\mu`) at loads :math:`P`.

    Parameters
    ----------
    P : array_like
        Loads: :math:`P/NGb^2` (dimensionless) or newtons (``physical``); > 0 with ``mu``.
    F : array_like, optional
        Friction forces (>= 0), in the unit of ``P``.  Give ``F`` or ``mu``.
    mu : array_like, optional
        Friction coefficients :math:`F/P` (>= 0).
    F_err, mu_err, P_err : array_like, optional
        Standard uncertainties (> 0) of ``F``, ``mu`` and ``P``.
    physical : bool
        SI units (N) instead of the paper's dimensionless ones.
    name : str
        Label.

    Returns
    -------
    Dataset
        Kind ``'friction'``.

    Raises
    ------
    ValueError
        If neither or both of ``F`` and ``mu`` are given, or an array is invalid (see
        :class:`Dataset`).
    """
    if (F is None) == (mu is None):
        raise ValueError("give the friction force F or the coefficient mu (one of them)")
    if F is None and F_err is not None or mu is None and mu_err is not None:
        raise ValueError("F_err goes with F and mu_err with mu")
    P, F, mu, F_err, mu_err, P_err, physical, name = _columns(physical, name, P=P, F=F, mu=mu, F_err=F_err,
                                                              mu_err=mu_err, P_err=P_err)
    y, quantity, err = (F, "F", F_err) if mu is None else (mu, "mu", mu_err)
    return Dataset("friction", P, y, quantity, physical, y_err=err, x_err=P_err, name=name)


def force_separation_data(d, P, *, P_err=None, d_err=None, physical=False, name="force") -> Dataset:
    r"""A normal-force-versus-separation data set from arrays.

    Parameters
    ----------
    d : array_like
        Separations: :math:`d/\sigma` (dimensionless) or metres (``physical``).
    P : array_like
        Normal forces (compressive > 0): :math:`P/NGb^2` or newtons.
    P_err, d_err : array_like, optional
        Standard uncertainties (> 0).
    physical : bool
        SI units.
    name : str
        Label.

    Returns
    -------
    Dataset
        Kind ``'force'``.

    Raises
    ------
    ValueError
        If an array is invalid (see :class:`Dataset`).
    """
    d, P, P_err, d_err, physical, name = _columns(physical, name, 2, d=d, P=P, P_err=P_err, d_err=d_err)
    return Dataset("force", d, P, "P", physical, y_err=P_err, x_err=d_err, name=name)


def pull_off_data(force, *, force_err=None, conditions=None, physical=False, name="pull_off") -> Dataset:
    r"""A data set of pull-off forces, one per surface or condition.

    Parameters
    ----------
    force : array_like
        Pull-off forces (magnitudes, > 0): :math:`|P|/NGb^2` or newtons.
    force_err : array_like, optional
        Standard uncertainties (> 0).
    conditions : dict, optional
        ``{parameter name: one value per row}``, e.g. ``{"alpha": [0.002, 0.003]}`` or
        ``{"R_m": [...]}``: the parameter takes the row's value, as for one surface each.
    physical : bool
        SI units.
    name : str
        Label.

    Returns
    -------
    Dataset
        Kind ``'pull_off'``; ``x`` holds the row numbers 0, 1, ...

    Raises
    ------
    ValueError
        If an array is invalid (see :class:`Dataset`).
    """
    force, force_err, physical, name = _columns(physical, name, force=force, force_err=force_err)
    if np.any(force <= 0):
        raise ValueError(f"force (pull-off forces) must be > 0 (magnitudes), got min {force.min():g}")
    if conditions is not None and not isinstance(conditions, dict):
        raise TypeError(f"conditions must be a dict of name -> one value per force, got {type(conditions).__name__}")
    return Dataset("pull_off", np.arange(force.size, dtype=float), force, "pull_off", physical, y_err=force_err,
                   conditions=conditions or {}, name=name)
