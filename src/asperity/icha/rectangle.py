r"""The mean displacement of a free rectangular scan under a point force (Boussinesq).

A point force :math:`F` on an elastic half-space presses the surface in by
:math:`u = F/\pi E^* r` (Boussinesq; Johnson 1985, §3.2, Eq 3.19).  Over a rectangular scan
of sides :math:`L_x, L_y` the mean of that displacement is :math:`F/\pi E^*` times the mean
of :math:`1/r` over the rectangle, in closed form (:func:`boussinesq_rectangle_mean`).  The
interacting asperity model (:mod:`asperity.icha`) uses it for the approach of the flat on a
map that does not repeat, as the boundary elements' free boundaries do.

References
----------
.. [1] J. Boussinesq, *Application des potentiels à l'étude de l'équilibre et du mouvement
   des solides élastiques*, Gauthier-Villars, Paris (1885).
.. [2] K. L. Johnson, *Contact Mechanics*, Cambridge University Press (1985), §3.2, Eq (3.19).
"""

from __future__ import annotations

import numpy as np

from .._validation import as_float_array, check_scalar_positive

__all__ = ["boussinesq_rectangle_mean"]


def boussinesq_rectangle_mean(x, y, size_x, size_y):
    r"""Mean over the rectangle :math:`[0, L_x]\times[0, L_y]` of :math:`1/r` from a point inside it.

    .. math::
        \frac{1}{L_xL_y}\iint\frac{\mathrm dA}{\sqrt{(x'-x)^2+(y'-y)^2}},\qquad
        \int_0^X\!\!\int_0^Y\frac{\mathrm dy\,\mathrm dx}{\sqrt{x^2+y^2}}
        = X\sinh^{-1}\frac YX + Y\sinh^{-1}\frac XY

    summed over the four quadrants around the point.  Times :math:`F/\pi E^*`, the mean
    displacement of a free (non-periodic) scan under a point force.

    Parameters
    ----------
    x, y : array_like
        Position of the point [m], within :math:`[0, L_x]\times[0, L_y]`.
    size_x, size_y : float
        Sides :math:`L_x, L_y` [m], > 0.

    Returns
    -------
    ndarray
        The mean [1/m], the broadcast shape of ``x`` and ``y``.

    Raises
    ------
    ValueError
        For a point outside the rectangle or a non-positive side.

    Examples
    --------
    >>> round(float(boussinesq_rectangle_mean(0.5, 0.5, 1.0, 1.0)), 6)   # the centre of a unit square: 4 asinh(1)
    3.525494

    References
    ----------
    Johnson (1985), §3.2, Eq (3.19), integrated over a rectangle.
    """
    x, y = as_float_array(x, "x", allow_empty=True), as_float_array(y, "y", allow_empty=True)
    lx, ly = check_scalar_positive(size_x, "size_x", "m"), check_scalar_positive(size_y, "size_y", "m")
    if np.any((x < 0) | (x > lx) | (y < 0) | (y > ly)):
        raise ValueError("the point must lie within the rectangle")

    def corner(X, Y):
        X, Y = np.broadcast_arrays(X, Y)
        out = np.zeros(X.shape)
        ok = (X > 0) & (Y > 0)
        out[ok] = X[ok] * np.arcsinh(Y[ok] / X[ok]) + Y[ok] * np.arcsinh(X[ok] / Y[ok])
        return out

    total = corner(x, y) + corner(lx - x, y) + corner(x, ly - y) + corner(lx - x, ly - y)
    return total / (lx * ly)
