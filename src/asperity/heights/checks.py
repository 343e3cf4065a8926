"""Checks shared by the height distributions: moment orders, derivative orders, and the
wrapper that keeps every family's density finite and quiet (:func:`checked_density`)."""

from __future__ import annotations

import functools
import math

import numpy as np

from .._validation import as_float_array, ufunc_result
from .._validation_files import short_repr

__all__ = ["MAX_ORDER", "check_order", "check_derivative_order", "checked_density"]


#: Highest order of a GW moment the closed forms and the quadrature serve (:func:`check_order`):
#: the laws need 0, 1, 3/2 and a few more.  Far below the summits F_n grows like |d|^n: at
#: order 20 it leaves double precision only beyond |d| ~ 1e15, at order 124 already at 300.
MAX_ORDER = 20.0


def check_order(order) -> float:
    """The order n of a GW moment as a float, -1 < n <= :data:`MAX_ORDER` (a 0-d array is a number)."""
    if isinstance(order, np.ndarray) and order.ndim == 0 and order.dtype.kind in "fiu":
        order = order[()]
    if isinstance(order, bool) or not isinstance(order, int | float | np.integer | np.floating):
        raise ValueError(f"order must be one real number in (-1, {MAX_ORDER:g}], got {short_repr(order)}")
    k = float(order)
    if not -1.0 < k <= MAX_ORDER:
        raise ValueError(f"order must lie in (-1, {MAX_ORDER:g}], got {short_repr(order)}")
    return k


def check_derivative_order(order) -> int:
    """The order of a density derivative: 1 or 2 (a ValueError naming ``order`` otherwise)."""
    if isinstance(order, bool) or not isinstance(order, int | np.integer) or order not in (1, 2):
        raise ValueError(f"order (of the density's derivative) must be 1 or 2, got {short_repr(order)}")
    return int(order)


#: Beyond this height every standardised density, its derivatives and its survival function
#: have their limits (0, or 1 for the survival function below); a family's formula may
#: overflow there (z^2 = inf) and give NaN, which :func:`checked_density` replaces by them.
_FAR = 1e150


def checked_density(method, name: str):
    """``method`` (a family's pdf, sf or pdf_derivative) on finite heights, without warnings.

    :class:`~asperity.heights.base.HeightDistribution` wraps every family's three methods
    with it.  Heights must be real and finite (a ValueError naming ``z``); far out
    (:math:`|z| \\ge 10^{150}`, or above the family's ``z_end``, where its survival function
    is below 1e-280), where a formula may overflow to NaN, the result is its limit (0, or 1
    for the survival function below); a NaN anywhere else is a defect of the family
    (ArithmeticError).  Float arrays, as the integrals pass, are checked by one sum.
    """

    @functools.wraps(method)
    def checked(self, z, *args, **kwargs):
        # the integrals call this with float arrays: one sum decides (a NaN or an inf makes it
        # non-finite, and finite heights of physical size never overflow it)
        with np.errstate(all="ignore"):  # the sums too: 1e308 + 1e308 overflows quietly
            if not (type(z) is np.ndarray and z.dtype == np.float64 and math.isfinite(z.sum())):
                z = as_float_array(z, "z", allow_empty=True)
            out = method(self, z, *args, **kwargs)
            total = np.sum(out)
        if math.isfinite(total):
            return ufunc_result(out)
        z_b = np.broadcast_to(z, np.shape(out))
        bad = ~np.isfinite(out)
        # far out, or above the highest summit the family resolves (sf < 1e-280 there)
        far = bad & ((np.abs(z_b) >= _FAR) | (z_b > self.z_end))
        limit = np.where(z_b < 0, 1.0, 0.0) if name == "sf" else 0.0
        out = np.where(far, limit, out)
        if not np.isfinite(out).all():
            raise ArithmeticError(f"{type(self).__name__}.{name} lost precision at z = "
                                  f"{short_repr(z_b[~np.isfinite(out)])}")  # a defect: report it
        return ufunc_result(out)

    checked._checked = True
    return checked
