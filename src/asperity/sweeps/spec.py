r"""What a sweep computes: its parameter sets, loads, chunks, output variables and fingerprint.

A :class:`SweepSpec` is built once, in the process that drives the sweep, from a grid (the
outer product of the parameters given as 1-D arrays, each one a named dimension) or from a
list of points (one dimension ``point``, a coordinate per parameter).  Parameters given as
scalars are constant; the rest take their defaults from :mod:`asperity.quantities`.

The parameter sets are numbered in C order and cut into *chunks*: hyperslabs of
consecutive sets (fixed leading indices, a slice of one dimension, whole trailing
dimensions), so a chunk is one contiguous region of every output array.  A task computes
one chunk with one :class:`~asperity.Model` per set (a Model's caches are mutable; the
loads of a set share its Model), never a part of a set's loads.

Two kinds of sweep:

* ``"model"``: the dimensionless parameters alpha, beta, gamma, nu, h_over_b and the
  Hurtado-Kim constants tau_f1, tau_f2, a1, a2; loads ``P`` (:math:`P/NGb^2`) or
  separations ``d`` (:math:`d/\sigma`).
* ``"physical"``: a material (by name, a dimension of strings), the surface sigma_s, R,
  eta, area (SI units) through :class:`~asperity.physical.PhysicalContact`; loads ``P_N``
  (N) or separations ``d_m`` (m); results in SI (``F_N``, ``area_m2``, ...).
"""

from __future__ import annotations

import hashlib
import json
import math
import os
from dataclasses import dataclass

import numpy as np

from .._validation import as_float_array, check_path
from .._validation_files import short_repr
from .._version import __version__
from ..materials import material
from ..quantities import CURVE_COLUMNS, MODEL_PARAMETERS, PHYSICAL_PARAMETERS
from ..units import strict_float

__all__ = ["MODEL_NAMES", "PHYSICAL_NAMES", "CHUNK_SETS", "SweepSpec", "default_chunk_sets", "make_spec", "read_points"]

#: Parameters of a dimensionless sweep, in dimension order.
MODEL_NAMES = ("alpha", "beta", "gamma", "nu", "h_over_b", "tau_f1", "tau_f2", "a1", "a2")
#: Parameters of a physical sweep, in dimension order (material is a name).
PHYSICAL_NAMES = ("material", "sigma_s", "R", "eta", "area", "w", "b")
#: Most sets per chunk: ~0.5 s of work per task keeps the scheduler's share (ms per task) small.
CHUNK_SETS = 256
#: Loads (or separations) per curve at most, as on the command line.
MAX_CURVE_POINTS = 10**6


def default_chunk_sets(n_sets: int) -> int:
    """Sets per chunk by default: n_sets/32 within [32, CHUNK_SETS], so a small sweep still
    makes enough tasks to keep every worker busy.  It depends on the grid only (a resumed
    sweep must cut the same chunks, whatever the cluster)."""
    return int(min(CHUNK_SETS, max(32, n_sets // 32)))


def _model_defaults() -> dict:
    return {name: MODEL_PARAMETERS[name].default for name in MODEL_NAMES}


@dataclass(frozen=True)
class SweepSpec:
    """A sweep, fully determined (see the module docstring).

    Attributes
    ----------
    kind : {'model', 'physical'}
    dims : tuple of str
        Names of the parameter dimensions (grid order), or ``('point',)``.
    coords : dict
        Coordinate arrays: one per dimension of a grid; one per varying parameter (along
        ``point``) for a list of points.
    constants : dict
        The parameters that do not vary.
    axis : str
        Name of the per-set dimension: ``'P'``/``'d'`` (model) or ``'P_N'``/``'d_m'`` (physical).
    values : ndarray
        The loads or separations of every set.
    chunk_sets : int
        Sets per chunk aimed at (:func:`default_chunk_sets` by default).
    """

    kind: str
    dims: tuple
    coords: dict
    constants: dict
    axis: str
    values: np.ndarray
    chunk_sets: int = CHUNK_SETS

    @property
    def shape(self) -> tuple[int, ...]:
        """Shape of the parameter grid (``(n_points,)`` for a list of points)."""
        if self.dims == ("point",):
            return (len(next(iter(self.coords.values()))),)
        return tuple(len(self.coords[d]) for d in self.dims)

    @property
    def n_sets(self) -> int:
        return math.prod(self.shape)

    @property
    def varying(self) -> tuple[str, ...]:
        """Names of the parameters that vary (the grid's dimensions, or the points' columns)."""
        return tuple(self.coords)

    # -- chunks ------------------------------------------------------------------------
    def _split(self):
        """(dimension j that is sliced, its slice length, sets per unit of dimension j)."""
        shape = self.shape
        for j in range(len(shape)):
            trailing = math.prod(shape[j + 1:])
            if trailing <= self.chunk_sets:
                return j, max(1, min(shape[j], self.chunk_sets // trailing)), trailing
        return len(shape) - 1, self.chunk_sets, 1  # pragma: no cover - j = last always matches

    @property
    def n_chunks(self) -> int:
        j, step, _ = self._split()
        return math.prod(self.shape[:j]) * math.ceil(self.shape[j] / step)

    def chunk_region(self, k: int) -> tuple[slice, ...]:
        """The hyperslab of chunk ``k`` (0 <= k < n_chunks), one slice per parameter dimension."""
        shape = self.shape
        j, step, _ = self._split()
        per = math.ceil(shape[j] / step)
        lead, part = divmod(k, per)
        index = np.unravel_index(lead, shape[:j]) if j else ()
        region = [slice(int(i), int(i) + 1) for i in index]
        region.append(slice(part * step, min(shape[j], (part + 1) * step)))
        region.extend(slice(0, n) for n in shape[j + 1:])
        return tuple(region)

    def chunk_parameters(self, k: int) -> list[dict]:
        """The parameter sets of chunk ``k``, in C order, each a dict of every parameter."""
        region = self.chunk_region(k)
        if self.dims == ("point",):
            sl = region[0]
            columns = {n: self.coords[n][sl] for n in self.coords}
            return [dict(self.constants, **{n: _item(c[i]) for n, c in columns.items()})
                    for i in range(sl.stop - sl.start)]
        axes = [self.coords[d][sl] for d, sl in zip(self.dims, region, strict=True)]
        return [dict(self.constants, **{d: _item(v) for d, v in zip(self.dims, combo, strict=True)})
                for combo in _product(axes)]

    # -- identity ----------------------------------------------------------------------
    def describe(self) -> dict:
        """Everything that determines the results, as plain JSON-able data."""
        return {"kind": self.kind, "dims": list(self.dims), "axis": self.axis,
                "coords": {k: [_item(x) for x in v] for k, v in self.coords.items()},
                "constants": {k: _item(v) for k, v in self.constants.items()},
                "values": [float(x) for x in self.values], "chunk_sets": self.chunk_sets,
                "asperity": __version__}

    def fingerprint(self) -> str:
        """SHA-256 of :meth:`describe`: two sweeps share a store only if this matches."""
        text = json.dumps(self.describe(), sort_keys=True, allow_nan=True)
        return hashlib.sha256(text.encode()).hexdigest()

    # -- outputs -----------------------------------------------------------------------
    def variables(self) -> dict[str, tuple[str, str, str]]:
        """Output variable -> (meaning, unit, 'curve' or 'set'), from :mod:`asperity.quantities`."""
        physical = self.kind == "physical"
        out = {}
        for name, q in CURVE_COLUMNS.items():
            key = q.si_name if physical else name
            if key == self.axis:
                continue
            out[key] = ((q.si_meaning if physical else q.meaning), (q.si_unit if physical else q.unit), "curve")
        out["pull_off_N" if physical else "pull_off"] = (
            "pull-off force, the most tensile force (0 if none)", "N" if physical else "N G b^2", "set")
        out["pull_off_d_m" if physical else "pull_off_d"] = (
            "separation of the pull-off force (NaN if none)", "m" if physical else "sigma", "set")
        if physical:
            for name in ("alpha", "beta", "gamma"):
                q = MODEL_PARAMETERS[name]
                out[name] = (q.meaning, q.unit, "set")
        return out


def _item(x):
    """A NumPy scalar as a Python one (str stays str)."""
    return x.item() if isinstance(x, np.generic) else x


def _product(axes):
    """Cartesian product in C order (the last axis fastest)."""
    import itertools

    return itertools.product(*axes)


def _axis_values(kind, P, d):
    if (P is None) == (d is None):
        names = ("P_N", "d_m") if kind == "physical" else ("P", "d")
        raise ValueError(f"give loads {names[0]} or separations {names[1]} (one of them)")
    name = ("P_N" if P is not None else "d_m") if kind == "physical" else ("P" if P is not None else "d")
    values = as_float_array(P if P is not None else d, name)
    if values.ndim != 1:
        raise ValueError(f"{name} must be 1-D (one value per point of each curve), got shape {values.shape}")
    if values.size > MAX_CURVE_POINTS:
        raise ValueError(f"{name} must hold at most {MAX_CURVE_POINTS} values (points of each curve), got "
                         f"{values.size}")
    _distinct(name, values)
    return name, np.sort(values)  # increasing, as the grid's dimensions


def _distinct(name, values) -> None:
    """Refuse a repeated value along a dimension of the grid (``.sel`` would be ambiguous)."""
    seen = np.unique(values, return_counts=True)
    if np.any(seen[1] > 1):
        raise ValueError(f"{name} must hold distinct values (a dimension of the sweep's grid), got "
                         f"{_item(seen[0][seen[1] > 1][0])!r} more than once")


def _parameter(name, value, kind):
    """A parameter as a Python scalar (constant) or a 1-D array (a dimension)."""
    if name == "material":
        names = [value] if isinstance(value, str) else list(value) if isinstance(value, list | tuple | np.ndarray) \
            else None
        if not names or not all(isinstance(v, str) for v in names):
            raise ValueError(f"material must be a material name or a list of names, got {value!r}")
        for one in names:  # a misspelt name is refused before the sweep, not stored as a failed set
            try:
                material(one)
            except ValueError as err:
                raise ValueError(f"material: {err}") from None
        return names[0] if isinstance(value, str) else np.array(names, dtype=object)
    q = PHYSICAL_PARAMETERS[name] if kind == "physical" else MODEL_PARAMETERS[name]
    arr = as_float_array(value, name)
    if arr.ndim > 1:
        raise ValueError(f"{name} must be a number or a 1-D array, got shape {arr.shape}")
    bad = [x for x in arr.ravel() if not q.contains(float(x))]
    if bad:
        raise ValueError(f"{name} must satisfy {q.range_text()}, got {short_repr(bad[0])}")
    return float(arr) if arr.ndim == 0 else arr


def make_spec(parameters: dict, *, points=None, P=None, d=None, chunk_sets=None) -> SweepSpec:
    """A :class:`SweepSpec` from keyword parameters (scalars or 1-D arrays) or a list of points.

    Raises
    ------
    ValueError
        For an unknown parameter, a value outside its range (from :mod:`asperity.quantities`),
        model and physical parameters mixed, neither or both of loads and separations, points
        of unequal lengths, or a parameter both in ``points`` and given separately.
    """
    given = {k: v for k, v in parameters.items() if v is not None}
    if points is None or isinstance(points, dict):
        point_cols = dict(points or {})
    elif isinstance(points, str | os.PathLike):
        try:
            point_cols = read_points(points)
        except (TypeError, ValueError) as err:
            raise type(err)(str(err) if str(err).startswith("points") else f"points: {err}") from None
    else:
        raise TypeError(f"points must be a dict of parameter -> values or the path of a CSV file, got "
                        f"{type(points).__name__}")
    names = set(given) | set(point_cols)
    unknown = names - set(MODEL_NAMES) - set(PHYSICAL_NAMES)
    if unknown:
        raise ValueError(f"unknown sweep parameter(s) {sorted(unknown)}"
                         f"{' in points' if set(point_cols) & unknown else ''}; known: {', '.join(MODEL_NAMES)} "
                         f"(dimensionless) or {', '.join(PHYSICAL_NAMES)} (physical)")
    kind = "physical" if names & set(PHYSICAL_NAMES) else "model"
    allowed = PHYSICAL_NAMES if kind == "physical" else MODEL_NAMES
    if names - set(allowed):
        raise ValueError(f"give dimensionless parameters ({', '.join(MODEL_NAMES)}) or a physical contact "
                         f"({', '.join(PHYSICAL_NAMES)}), not both: got {sorted(names)}")
    both = set(given) & set(point_cols)
    if both:
        raise ValueError(f"{sorted(both)} given both in points and as a parameter")
    required = ("material", "sigma_s", "R", "eta", "area") if kind == "physical" else ("alpha", "beta")
    missing = [n for n in required if n not in names]
    if missing:
        raise ValueError(f"a sweep needs {', '.join(missing)}")
    values = {n: _parameter(n, v, kind) for n, v in given.items()}
    constants = {} if kind == "physical" else {k: v for k, v in _model_defaults().items() if v is not None}
    constants.update({n: v for n, v in values.items() if not isinstance(v, np.ndarray)})
    if point_cols:
        cols = {n: np.atleast_1d(_parameter(n, v, kind)) for n, v in point_cols.items()}
        lengths = {len(c) for c in cols.values()}
        if len(lengths) != 1:
            raise ValueError(f"points must all have the same length, got {sorted(lengths)}")
        if any(isinstance(v, np.ndarray) for v in values.values()):
            raise ValueError("with points, the other parameters must be single values")
        coords, dims = {n: cols[n] for n in allowed if n in cols}, ("point",)
    else:
        coords = {n: values[n] for n in allowed if isinstance(values.get(n), np.ndarray)}
        for n, v in coords.items():  # a grid's dimensions (a list of points may repeat values)
            _distinct(n, v)
        # in increasing order, whatever the order given: xarray's nearest selection and the
        # plots' cell edges need monotonic coordinates (a review: an unsorted grid drew a wrong map)
        coords = {n: v if v.dtype == object else np.sort(v) for n, v in coords.items()}
        dims = tuple(coords) or ("point",)
        if not coords:  # a single set
            coords = {required[0]: np.atleast_1d(constants.pop(required[0]))}
            dims = ("point",)
    for n in coords:
        constants.pop(n, None)
    axis, arr = _axis_values(kind, P, d)
    spec = SweepSpec(kind, dims, coords, constants, axis, arr)
    if chunk_sets is None:
        chunk_sets = default_chunk_sets(spec.n_sets)
    if isinstance(chunk_sets, bool) or not isinstance(chunk_sets, int | np.integer) or chunk_sets < 1:
        raise ValueError(f"chunk_sets must be an integer >= 1, got {chunk_sets!r}")
    return SweepSpec(kind, dims, coords, constants, axis, arr, int(chunk_sets))


def read_points(path: str) -> dict[str, np.ndarray]:
    """Columns of a CSV file of points: a header of parameter names, then one row per set.

    ``material`` holds names; every other column numbers.

    Raises
    ------
    ValueError
        If the file cannot be read, is empty, or a row has the wrong number of fields or a
        value that is not a number.
    """
    import csv

    path = check_path(path, "path")
    try:
        with open(path, newline="", encoding="utf-8") as fh:
            rows = [r for r in csv.reader(fh) if r and not r[0].lstrip().startswith("#")]
    except (OSError, UnicodeDecodeError) as err:
        raise ValueError(f"points: cannot read {path!r}: {err}") from None
    if len(rows) < 2:
        raise ValueError(f"points: {path!r} needs a header of parameter names and at least one row")
    header = [h.strip() for h in rows[0]]
    twice = sorted({h for h in header if header.count(h) > 1})
    if twice:
        raise ValueError(f"points: {path!r} names {', '.join(twice)} twice in its header")
    cols: dict[str, list] = {h: [] for h in header}
    for i, row in enumerate(rows[1:], start=2):
        if len(row) != len(header):
            raise ValueError(f"points: line {i} of {path!r} has {len(row)} fields, the header {len(header)}")
        for h, v in zip(header, row, strict=True):
            if h == "material":
                cols[h].append(v.strip())
                continue
            try:
                cols[h].append(strict_float(v))
            except ValueError:
                raise ValueError(f"points: line {i} of {path!r}: {h} = {v!r} is not a number") from None
    return {h: (np.array(v, dtype=object) if h == "material" else np.array(v)) for h, v in cols.items()}
