"""Input checks shared by every public function (file names: :mod:`asperity._validation_files`,
re-exported here).

Each check raises :class:`ValueError` naming the parameter and its valid range, so a
user never meets a silent NaN or a traceback from deep inside SciPy.

The array checks (``check_*``) take plain numbers or arrays.  The scalar checks
(``check_scalar_*``, ``check_optional_positive``) serve physical inputs: given a
``unit``, they first convert a pint ``Quantity`` or a string such as ``'2nm'`` to that SI
unit with :func:`asperity.units.to_si`, then return one Python ``float``.
"""

from __future__ import annotations

import numpy as np

from ._results import check_finite_result, check_mean_pressure, check_overflow, ufunc_result
from ._validation_files import IMAGE_FORMATS, check_image, check_output_path, check_path
from ._validation_files import short_repr as _short_repr
from .units import to_si

__all__ = [
    "as_float_array",
    "check_nonnegative",
    "check_overflow",
    "check_poisson",
    "check_positive",
    "check_radius",
    "check_range",
    "check_interval",
    "check_scalar_range",
    "check_scalar_poisson",
    "check_scalar_positive",
    "check_optional_positive",
    "check_text",
    "check_bool",
    "check_callable",
    "check_integer",
    "check_1d",
    "check_path",
    "check_output_path",
    "check_image",
    "IMAGE_FORMATS",
    "check_finite_result",
    "check_mean_pressure",
    "check_scalar_real",
    "check_broadcast",
    "scalar",
    "ufunc_result",
]


def as_float_array(value, name: str, *, allow_empty: bool = False) -> np.ndarray:
    """Convert ``value`` to a float array; reject NaN, infinity and (by default) emptiness.

    None, booleans (also inside lists), complex numbers, masked values, strings, dates,
    dicts and ragged lists raise :class:`ValueError` naming ``name``.
    """
    # Fast paths for what the library passes itself (a float, a float64 array): a copy, as below.
    if type(value) is float or type(value) is np.float64:
        if value - value == 0.0:  # finite
            return np.array(value)
    elif type(value) is np.ndarray and value.dtype == np.float64 and (value.size or allow_empty):
        if np.isfinite(value).all():
            return value.copy()
    if hasattr(value, "magnitude") and hasattr(value, "units") and hasattr(value, "dimensionless"):  # pint
        if not value.dimensionless:  # NumPy would drop the unit (with pint's UnitStrippedWarning)
            raise ValueError(f"{name} is a number in the model's own units, got the quantity {value!r}: give "
                             "a plain number (the physical API, asperity.physical, takes SI quantities)")
        value = value.to("dimensionless").magnitude
    _reject_non_real(value, name)
    if isinstance(value, bool | np.bool_) or _holds_bool(value):
        raise ValueError(f"{name} must be a real number, got a boolean {_short_repr(value)}")
    if np.ma.is_masked(value):
        raise ValueError(f"{name} must not have masked (missing) values, got {_short_repr(value)}")
    try:
        raw = np.asarray(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a real number or an array of real numbers, "
                         f"got {_short_repr(value)}") from None
    if raw.dtype == np.bool_:
        raise ValueError(f"{name} must be a real number, got a boolean {_short_repr(value)}")
    if np.iscomplexobj(raw):
        raise ValueError(f"{name} must be a real number, got a complex value {_short_repr(value)}")
    try:
        with np.errstate(over="ignore"):  # a long double or an int beyond the doubles: refused as infinite below
            arr = raw.astype(float)
    except OverflowError:  # a Python int beyond the doubles (10**400): a user trial got OverflowError
        raise ValueError(f"{name} must be finite (no NaN or infinity), got {_short_repr(value)}") from None
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a real number or an array of real numbers, "
                         f"got {_short_repr(value)}") from None
    if arr.size == 0 and not allow_empty:
        raise ValueError(f"{name} must not be empty")
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"{name} must be finite (no NaN or infinity), got {_short_repr(value)}")
    return arr


def _holds_bool(value) -> bool:
    """True if a (nested) list or tuple, or an object array, holds a boolean, which NumPy would
    silently make 0 or 1."""
    if isinstance(value, np.ndarray) and value.dtype == object:  # a user trial: [True, 1.0] as objects
        return any(isinstance(v, bool | np.bool_) for v in value.flat)
    if not isinstance(value, list | tuple):
        return False
    types = set(map(type, value))
    if bool in types or np.bool_ in types:
        return True
    return any(_holds_bool(v) for v in value) if types & {list, tuple} else False


def check_positive(value, name: str) -> np.ndarray:
    """``value`` as a float array; every element must satisfy 0 < value < inf."""
    arr = as_float_array(value, name)
    if (arr <= 0).any():
        raise ValueError(f"{name} must be > 0 (valid range 0 < {name} < inf), got {_short_repr(value)}")
    return arr


def check_nonnegative(value, name: str) -> np.ndarray:
    """``value`` as a float array; every element must satisfy 0 <= value < inf."""
    arr = as_float_array(value, name)
    if (arr < 0).any():
        raise ValueError(f"{name} must be >= 0 (valid range 0 <= {name} < inf), got {_short_repr(value)}")
    return arr


def check_range(value, name: str, lo: float, hi: float) -> np.ndarray:
    """``value`` as a float array; every element must satisfy lo <= value <= hi."""
    arr = as_float_array(value, name)
    if ((arr < lo) | (arr > hi)).any():
        raise ValueError(f"{name} must lie in [{lo:g}, {hi:g}], got {_short_repr(value)}")
    return arr


def check_interval(value, name: str, lo: float, hi: float, *, lo_open: bool = False, hi_open: bool = False,
                   context: str = "") -> np.ndarray:
    """``value`` as a float array; every element in the interval from ``lo`` to ``hi``.

    The ends are included unless ``lo_open``/``hi_open``; the message reads
    ``"{name} must lie in [lo, hi){context}, got ..."``.
    """
    arr = as_float_array(value, name)
    below = arr <= lo if lo_open else arr < lo
    above = arr >= hi if hi_open else arr > hi
    if np.any(below | above):
        left, right = "(" if lo_open else "[", ")" if hi_open else "]"
        raise ValueError(f"{name} must lie in {left}{lo:g}, {hi:g}{right}{context}, got {_short_repr(value)}")
    return arr
def check_scalar_range(value, name: str, lo: float, hi: float, *, what: str = "") -> float:
    """One finite real number with lo <= value <= hi, as a float (shape parameters, weights).

    ``what`` (e.g. ``"Weibull skewness"``) is named in the message beside ``name``.

    Raises
    ------
    ValueError
        For a boolean, complex, non-numeric, NaN, infinite, non-scalar or out-of-range value.
    """
    label = f"{name} ({what})" if what else name
    arr = as_float_array(value, label)
    if arr.ndim != 0:
        raise ValueError(f"{label} must be a scalar, got an array of shape {arr.shape}")
    x = float(arr)
    if not lo <= x <= hi:
        raise ValueError(f"{label} must lie in [{lo:g}, {hi:g}], got {_short_repr(value)}")
    return x


def check_poisson(nu) -> np.ndarray:
    """Poisson's ratio of an isotropic elastic solid: -1 < nu < 0.5."""
    arr = as_float_array(nu, "nu")
    if ((arr <= -1.0) | (arr >= 0.5)).any():
        raise ValueError(f"nu (Poisson's ratio) must lie in (-1, 0.5), got {_short_repr(nu)}")
    return arr


def check_radius(A, name: str = "A") -> np.ndarray:
    """A contact radius (array, may be empty): finite and >= 0."""
    arr = as_float_array(A, name, allow_empty=True)
    if (arr < 0).any():
        raise ValueError(f"{name} (contact radius) must be >= 0")
    return arr


def scalar(value, name: str) -> float:
    """A scalar parameter (0-d); arrays are rejected with a clear message."""
    arr = np.asarray(value)
    if arr.ndim != 0:
        raise ValueError(f"{name} must be a scalar here, got an array of shape {arr.shape}")
    return float(arr)


def _unit_text(unit: str | None) -> str:
    return f" {unit}" if unit else ""


def _as_scalar(value, name: str, unit: str | None) -> float:
    """``value`` converted to ``unit`` (if given) as one finite real float."""
    converted = value if unit is None else to_si(value, unit, name)
    arr = as_float_array(converted, name)
    if arr.ndim != 0:
        raise ValueError(f"{name} must be a scalar, got an array of shape {arr.shape}")
    return float(arr)


def check_scalar_sign(value, name: str, *, positive: bool) -> float:
    """A real scalar, > 0 (``positive``) or >= 0, as a float; the errors name ``name``
    (those of :func:`check_positive` / :func:`check_nonnegative`, then :func:`scalar`)."""
    check = check_positive if positive else check_nonnegative
    return float(scalar(check(value, name), name))


def check_scalar_positive(value, name: str, unit: str | None = None, *, allow_zero: bool = False) -> float:
    """One finite real number > 0 (>= 0 with ``allow_zero``), converted to ``unit`` if given.

    Parameters
    ----------
    value : float, pint.Quantity or str
        A number (taken to be in ``unit`` already), a pint ``Quantity`` or, when ``unit``
        is given, a string with a unit such as ``'2nm'``.
    name : str
        Parameter name for the error message.
    unit : str, optional
        SI unit in pint syntax (``'m'``, ``'Pa'``, ``'1/m^2'``, ``''`` for dimensionless);
        None: no unit conversion.
    allow_zero : bool
        Accept 0.

    Returns
    -------
    float

    Raises
    ------
    ValueError
        For a boolean, complex, non-numeric, NaN, infinite, non-scalar or out-of-range
        value, or a quantity of the wrong dimension; the message names ``name``, the unit
        and the valid range.
    """
    x = _as_scalar(value, name, unit)
    if x < 0 or (x == 0 and not allow_zero):
        bound = f">= 0{_unit_text(unit)} (valid range 0 <= {name} < inf)" if allow_zero else \
            f"> 0{_unit_text(unit)} (valid range 0 < {name} < inf)"
        raise ValueError(f"{name} must be {bound}, got {_short_repr(value)}")
    return x


def check_optional_positive(value, name: str, unit: str | None = None, *, allow_zero: bool = False) -> float | None:
    """None (a missing value) or :func:`check_scalar_positive` of ``value``."""
    if value is None:
        return None
    x = _as_scalar(value, name, unit)
    if x < 0 or (x == 0 and not allow_zero):
        bound = ">= 0" if allow_zero else "> 0"
        raise ValueError(f"{name} must be {bound}{_unit_text(unit)} or None (missing), got {_short_repr(value)}")
    return x


def check_broadcast(**arrays) -> tuple[int, ...]:
    """The common shape of arrays that must broadcast together; a ValueError naming them if they do not."""
    shapes = {name: np.shape(a) for name, a in arrays.items()}
    try:
        return np.broadcast_shapes(*shapes.values())
    except ValueError:
        listed = ", ".join(f"{name} {shape}" for name, shape in shapes.items())
        raise ValueError(f"{', '.join(shapes)} must have shapes that broadcast together, got {listed}") from None


def check_scalar_real(value, name: str) -> float:
    """One finite real number (any sign) as a float; arrays, booleans, None, strings are errors."""
    return _as_scalar(value, name, None)


def check_scalar_poisson(value, name: str = "nu") -> float:
    """One Poisson's ratio of an isotropic elastic solid, -1 < nu < 0.5, as a float."""
    x = _as_scalar(value, name, "")
    if not -1.0 < x < 0.5:
        raise ValueError(f"{name} (Poisson's ratio) must lie in (-1, 0.5), got {_short_repr(value)}")
    return x


def check_text(value, name: str) -> str:
    """``value`` if it is a string; otherwise a :class:`TypeError` naming ``name``."""
    if not isinstance(value, str):
        raise TypeError(f"{name} must be a string, got {type(value).__name__} {_short_repr(value)}")
    return value


def check_bool(value, name: str) -> bool:
    """``value`` if it is a boolean (Python or NumPy); otherwise a :class:`TypeError` naming ``name``."""
    if not isinstance(value, bool | np.bool_):
        raise TypeError(f"{name} must be True or False, got {type(value).__name__} {_short_repr(value)}")
    return bool(value)


def check_callable(value, name: str):
    """``value`` if it is callable; otherwise a :class:`TypeError` naming ``name``."""
    if not callable(value):
        raise TypeError(f"{name} must be callable, got {type(value).__name__} {_short_repr(value)}")
    return value


def check_integer(value, name: str, lo: int, hi: int) -> int:
    """One integer (Python or NumPy, not a boolean) with lo <= value <= hi, as an ``int``."""
    if isinstance(value, bool | np.bool_) or not isinstance(value, int | np.integer):
        raise TypeError(f"{name} must be an integer, got {type(value).__name__} {_short_repr(value)}")
    if not lo <= value <= hi:
        raise ValueError(f"{name} must lie in [{lo}, {hi}], got {_short_repr(value)}")
    return int(value)


def check_1d(value, name: str, *, allow_empty: bool = False) -> np.ndarray:
    """A scalar or 1-D list/array of finite reals as a 1-D float array; 2-D input is an error, not flattened."""
    arr = as_float_array(value, name, allow_empty=allow_empty)
    if arr.ndim > 1:
        raise ValueError(f"{name} must be a number or a 1-D list or array, got an array of shape {arr.shape}")
    return arr.reshape(-1)


def check_positive_scaled(value, name: str, factor: float):
    """``factor * value`` for a positive ``value`` (:func:`check_positive`), refusing by name a product
    that overflows (e.g. :math:`K = \\tfrac43E^*` of an E* near the largest double)."""
    value = check_positive(value, name)
    with np.errstate(all="ignore"):
        out = factor * value
    return check_finite_result(out, f"{factor:g} {name}", **{name: value})


def _reject_non_real(value, name: str) -> None:
    """Refuse what NumPy would silently turn into floats: None, strings, complex numbers,
    dates, dicts and masked arrays (whose mask ``np.asarray`` drops)."""
    if type(value) is float or (type(value) is np.ndarray and value.dtype.kind in "fiu"):
        return  # the common case, decided at once
    import reprlib  # short reprs of huge inputs; local to keep this helper self-contained

    what = None
    if isinstance(value, np.ma.MaskedArray):
        what = "a masked array (fill or drop the masked values first)"
    elif value is None or isinstance(value, str | bytes | dict):
        what = "a dict" if isinstance(value, dict) else reprlib.repr(value)
    else:
        try:
            raw = np.asarray(value)
        except (TypeError, ValueError):  # ragged nesting, unconvertible objects
            raw = None
            what = f"{reprlib.repr(value)}, which does not convert to an array"
        if raw is None:
            pass
        elif raw.dtype.kind == "c":
            what = f"a complex value {reprlib.repr(value)}"
        elif raw.dtype.kind in "USVMm":
            what = f"an array of dtype {raw.dtype}" if raw.ndim else reprlib.repr(value)
        elif raw.dtype == object:
            bad = next((x for x in raw.flat if x is None or isinstance(x, str | bytes | dict | complex)), False)
            if bad is not False:
                what = f"an element {reprlib.repr(bad)}"
    if what is not None:
        raise ValueError(f"{name} must be a real number or an array of real numbers, got {what}")
