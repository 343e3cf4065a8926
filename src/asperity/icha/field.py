r"""The elastic displacement field of Hertzian contact spots, free and periodic.

A Hertzian contact spot of radius :math:`a` carrying the force :math:`F` on an elastic
half-space of contact modulus :math:`E^*` presses the surface in by (Johnson 1985, Eq 3.42)

.. math::
    u(r) = \frac{3F}{8a^3E^*}\,(2a^2 - r^2)\quad(r\le a),\qquad
    u(r) = \frac{3F}{4\pi a^3E^*}\Big[(2a^2 - r^2)\sin^{-1}\frac ar + a\sqrt{r^2-a^2}\Big]\quad(r>a),

which tends to Boussinesq's point-force field :math:`F/\pi E^* r` far away (the excess
decays as :math:`a^2/10r^3` and integrates to zero over the plane).  This is the field
through which the contacts of the interacting asperity model feel each other
(:mod:`asperity.icha`).

**Periodic cell.**  A periodic boundary-element cell repeats the surface; a point force
then presses the surface by the periodic Green's function with its mean removed (the
uniform part is a rigid shift),

.. math::
    G(\mathbf r) = \frac{1}{A_0}\sum_{\mathbf q\ne 0}\frac{2}{E^* q}\,e^{i\mathbf q\cdot\mathbf r},

the same kernel as the periodic half-space of the boundary elements (Stanley & Kato 1997).
It is summed by Ewald's splitting :math:`1/r = \mathrm{erfc}(r/\xi)/r + \mathrm{erf}(r/\xi)/r`,
whose long-range part has the plane transform :math:`(2\pi/q)\,\mathrm{erfc}(q\xi/2)`:

.. math::
    \pi E^* G(\mathbf r) = \frac{\mathrm{erfc}(r/\xi)}{r} + L(\mathbf r) - \frac{2\sqrt\pi\,\xi}{A_0},\qquad
    L(\mathbf r) = \frac{1}{A_0}\sum_{\mathbf q\ne0}\frac{2\pi}{q}\,\mathrm{erfc}\frac{q\xi}{2}\,
    e^{i\mathbf q\cdot\mathbf r},

with :math:`r` the distance to the nearest image and :math:`\xi` an eighth of the shorter
side (the other images' short-range terms are below :math:`\mathrm{erfc}(4) = 1.5\times10^{-8}`
of the nearest one's).  A Hertzian spot adds its excess over the point force
(:func:`hertz_excess`) at its nearest image only: at the farther ones the excess is below
:math:`a^2/10r^2` of their field.  :math:`L` is smooth and periodic: it is tabulated once per cell by
an inverse FFT and interpolated by cubic splines (:class:`PeriodicKernel`).

References
----------
.. [1] K. L. Johnson, *Contact Mechanics*, Cambridge University Press (1985), §3.4, Eq (3.42).
.. [2] J. Boussinesq (1885); Johnson (1985), §3.2, Eq (3.19).
.. [3] H. M. Stanley, T. Kato, J. Tribol. 119 (1997) 481-485.
.. [4] P. P. Ewald, Ann. Phys. 369 (1921) 253-287.
"""

from __future__ import annotations

import math

import numpy as np
from scipy import ndimage, special

from .._validation import as_float_array, check_scalar_positive

__all__ = ["hertz_displacement", "hertz_excess", "FreeKernel", "PeriodicKernel", "EWALD_FRACTION"]

#: Ewald splitting length :math:`\xi` as a fraction of the shorter side of the cell.
EWALD_FRACTION = 1.0 / 8.0
#: erfc(q xi / 2) below this is dropped from the reciprocal sum.
_ERFC_CUT = 1e-12
#: Table points per Ewald length along each axis (cubic-spline interpolation of L).
_TABLE_PER_XI = 16


def hertz_displacement(r, a, F, E_star):
    r"""Surface displacement around a Hertzian contact spot (Johnson 1985, Eq 3.42).

    .. math::
        u = \frac{3F}{8a^3E^*}(2a^2 - r^2)\ (r\le a),\qquad
        u = \frac{3F}{4\pi a^3E^*}\Big[(2a^2 - r^2)\sin^{-1}\frac ar + a\sqrt{r^2-a^2}\Big]\ (r>a);
        \qquad u = \frac{F}{\pi E^* r}\ \text{if}\ a = 0

    Parameters
    ----------
    r : array_like
        Distance from the centre of the spot :math:`r` [m], >= 0 (> 0 where ``a`` is 0).
    a : array_like
        Contact radius :math:`a` [m], >= 0 (0: Boussinesq's point force).
    F : array_like
        Force carried by the spot :math:`F` [N], >= 0.
    E_star : float
        Contact modulus :math:`E^*` [Pa], > 0.

    Returns
    -------
    ndarray
        Displacement into the half-space :math:`u` [m], the broadcast shape of ``r``, ``a``, ``F``.

    Raises
    ------
    ValueError
        For negative or non-finite input, or ``r = 0`` with ``a = 0``.

    Examples
    --------
    >>> R, a, E = 1e-6, 1e-8, 1e11                 # at the centre: the Hertz interference a^2/R
    >>> F = 4 * E * a**3 / (3 * R)
    >>> round(float(hertz_displacement(0.0, a, F, E)) / (a**2 / R), 12)
    1.0

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), §3.4, Eq (3.42a, b); §3.2, Eq (3.19).
    """
    r, a, F = (as_float_array(v, n, allow_empty=True) for v, n in ((r, "r"), (a, "a"), (F, "F")))
    E_star = check_scalar_positive(E_star, "E_star", "Pa")
    for v, n in ((r, "r"), (a, "a"), (F, "F")):
        if np.any(v < 0):
            raise ValueError(f"{n} must be >= 0, got min {v.min():g}")
    r, a, F = np.broadcast_arrays(r, a, F)
    if np.any((r == 0) & (a == 0)):
        raise ValueError("r must be > 0 where a = 0 (a point force has no finite displacement under itself)")
    return F * _unit_field(r, a) / (math.pi * E_star)


def _unit_field(r, a):
    """:math:`\\pi E^* u/F` of a Hertzian spot (1/m), no checks; a = 0 gives 1/r."""
    r, a = np.broadcast_arrays(np.asarray(r, float), np.asarray(a, float))
    out = np.empty(r.shape)
    point = a == 0
    inside = ~point & (r <= a)
    outside = ~point & ~inside
    out[point] = 1.0 / r[point]
    ai = a[inside]
    out[inside] = 3 * math.pi * (2 * ai**2 - r[inside] ** 2) / (8 * ai**3)
    ro, ao = r[outside], a[outside]
    s = ao / ro
    out[outside] = 3 / (4 * ao**3) * ((2 * ao**2 - ro**2) * np.arcsin(s) + ao * ro * np.sqrt(1 - s * s))
    return out


#: Series of :math:`r\,e(r, a)` in :math:`s = a/r`: :math:`s^2/10 + 9s^4/280 + 5s^6/336 + 35s^8/4224`
#: (used for :math:`s < 0.1`, where the closed form loses digits to cancellation).
_EXCESS_SERIES = (1 / 10, 9 / 280, 5 / 336, 35 / 4224)


def _excess(r, a):
    r""":math:`\pi E^* u/F - 1/r` [1/m] for r > 0 (0 for infinite r), no checks; series for a < r/10."""
    r, a = np.broadcast_arrays(np.asarray(r, float), np.asarray(a, float))
    s2 = (a / r) ** 2
    c1, c2, c3, c4 = _EXCESS_SERIES
    out = np.asarray(s2 * (c1 + s2 * (c2 + s2 * (c3 + s2 * c4))) / r, dtype=float).reshape(r.shape)
    near = s2 >= 0.01
    if near.any():
        out[near] = _unit_field(r[near], a[near]) - 1.0 / r[near]
    return out


def _excess_da(r, a):
    """Derivative of :func:`_excess` with respect to the contact radius a [1/m^2] (0 for infinite r)."""
    r, a = np.broadcast_arrays(np.asarray(r, float), np.asarray(a, float))
    s = a / r
    s2 = s * s
    c1, c2, c3, c4 = _EXCESS_SERIES
    out = np.asarray(s * (2 * c1 + s2 * (4 * c2 + s2 * (6 * c3 + s2 * 8 * c4))) / (r * r), float).reshape(r.shape)
    near = s2 >= 0.01
    if near.any():
        rn, an = r[near], a[near]
        inside = rn <= an
        val = np.empty(rn.shape)
        ri, ai = rn[inside], an[inside]
        val[inside] = -3 * math.pi / (4 * ai**2) + 9 * math.pi * ri**2 / (8 * ai**4)
        ro, ao = rn[~inside], an[~inside]
        val[~inside] = -3 / ao * _unit_field(ro, ao) + 3 / ao**2 * np.arcsin(ao / ro)
        out[near] = val
    return out


def hertz_excess(r, a):
    r"""Hertzian field minus Boussinesq's, in units of :math:`F/\pi E^*`: :math:`\pi E^* u/F - 1/r`.

    .. math::
        e(r, a) = \frac{\pi E^*}{F}\,u_{Hertz}(r; a) - \frac1r ,\qquad
        e \to \frac{a^2}{10\,r^3}\ (r\gg a),\qquad \int_{\mathbb R^2} e\,\mathrm dA = 0

    Parameters
    ----------
    r : array_like
        Distance from the centre of the spot [m], > 0.
    a : array_like
        Contact radius [m], >= 0.

    Returns
    -------
    ndarray
        :math:`e` [1/m], the broadcast shape.

    Raises
    ------
    ValueError
        For r <= 0, a < 0 or non-finite input.

    Examples
    --------
    >>> float(hertz_excess(1.0, 0.0))
    0.0

    References
    ----------
    K. L. Johnson, Contact Mechanics (1985), Eqs (3.19), (3.42).
    """
    r, a = as_float_array(r, "r", allow_empty=True), as_float_array(a, "a", allow_empty=True)
    if np.any(r <= 0) or np.any(a < 0):
        raise ValueError("r must be > 0 and a >= 0")
    return _excess(r, a)


def _point_matrix(r, field, diagonal):
    """``field(r)`` off the diagonal of the square matrix ``r``, ``diagonal`` on it."""
    out = np.full(r.shape, float(diagonal))
    off = ~np.eye(r.shape[0], dtype=bool)
    out[off] = field(r[off])
    return out


class FreeKernel:
    r"""Hertzian spots on a free (non-periodic) half-space: :math:`\pi E^* u/F` of Johnson's Eq (3.42).

    The counterpart of :class:`PeriodicKernel` for a map that does not repeat: no images,
    plain distances.
    """

    #: No images: nothing is added under a spot.
    self_images = 0.0
    size = None

    def nearest(self, dx, dy):
        """The separation itself and its length [m]."""
        dx, dy = np.asarray(dx, float), np.asarray(dy, float)
        return dx, dy, np.hypot(dx, dy)

    def unit_field(self, dx, dy, a):
        r""":math:`\pi E^* u/F` [1/m] of Hertzian spots of radius ``a`` (>= 0) at separations ``dx, dy``."""
        return _unit_field(np.hypot(dx, dy), a)

    def point_matrix(self, x, y):
        r"""Distances and :math:`\pi E^* G = 1/r` [1/m] between all points ``x, y``; 0 on the diagonal."""
        _, _, r = self.nearest(x[:, None] - x[None, :], y[:, None] - y[None, :])
        return r, _point_matrix(r, lambda r: 1.0 / r, self.self_images)

    def point_row(self, x0, y0, x, y):
        r"""Distances and :math:`\pi E^* G = 1/r` [1/m] from the point ``x0, y0`` to the points ``x, y`` (not it)."""
        _, _, r = self.nearest(x0 - x, y0 - y)
        return r, 1.0 / r

    @staticmethod
    def spot_excess(r, a):
        """:func:`hertz_excess` without input checks (the solver's inner loop), r > 0."""
        return _excess(r, a)

    @staticmethod
    def spot_excess_da(r, a):
        """Derivative of :meth:`spot_excess` with respect to ``a`` [1/m^2] (the solver's Jacobian)."""
        return _excess_da(r, a)


class PeriodicKernel:
    r"""Periodic point-force Green's function of a rectangular cell, split by Ewald.

    ``PeriodicKernel(size_x, size_y)`` tabulates the smooth long-range part :math:`L` (module
    docstring) once; :meth:`unit_field` then gives :math:`\pi E^* u/F` of Hertzian spots in
    the periodic cell (nearest-image Hertz field, plus all images by Ewald's sum, mean removed).

    Parameters
    ----------
    size_x, size_y : float
        Sides of the periodic cell [m], > 0.

    Attributes
    ----------
    xi : float
        Ewald length [m], :data:`EWALD_FRACTION` of the shorter side.
    constant : float
        :math:`2\sqrt\pi\,\xi/A_0` [1/m], the mean of the short-range part.
    self_images : float
        :math:`\lim_{r\to0}(\pi E^*G - 1/r) = L(0) - 2/\sqrt\pi\xi - 2\sqrt\pi\xi/A_0` [1/m]:
        what the images of a spot add under the spot itself.
    """

    def __init__(self, size_x, size_y):
        self.size = (check_scalar_positive(size_x, "size_x", "m"), check_scalar_positive(size_y, "size_y", "m"))
        lx, ly = self.size
        self.xi = EWALD_FRACTION * min(lx, ly)
        area = lx * ly
        self.constant = 2 * math.sqrt(math.pi) * self.xi / area
        qmax = 2 * special.erfcinv(_ERFC_CUT) / self.xi
        self._n = tuple(max(2 * int(math.ceil(qmax * s / (2 * math.pi))) + 2, int(_TABLE_PER_XI * s / self.xi))
                        for s in self.size)
        nx, ny = self._n
        qx = 2 * math.pi * np.fft.fftfreq(nx, d=lx / nx)
        qy = 2 * math.pi * np.fft.fftfreq(ny, d=ly / ny)
        q = np.hypot(qx[:, None], qy[None, :])
        coeff = np.zeros_like(q)
        nz = q > 0
        coeff[nz] = 2 * math.pi / q[nz] * special.erfc(q[nz] * self.xi / 2) / area
        table = np.real(np.fft.ifft2(coeff)) * nx * ny
        self._spline = ndimage.spline_filter(table, order=3, mode="grid-wrap")
        self.self_images = float(table[0, 0]) - 2 / (math.sqrt(math.pi) * self.xi) - self.constant

    def nearest(self, dx, dy):
        """Nearest-image separation (dx, dy) wrapped into the cell, and its length [m]."""
        lx, ly = self.size
        dx = dx - lx * np.round(dx / lx)
        dy = dy - ly * np.round(dy / ly)
        return dx, dy, np.hypot(dx, dy)

    def long_range(self, dx, dy):
        """The smooth periodic part :math:`L` [1/m] at separations ``dx, dy`` (cubic splines)."""
        lx, ly = self.size
        nx, ny = self._n
        coords = np.array([np.ravel(dx) / lx * nx, np.ravel(dy) / ly * ny])
        values = ndimage.map_coordinates(self._spline, coords, order=3, mode="grid-wrap", prefilter=False)
        return values.reshape(np.shape(dx))

    def point_field(self, dx, dy):
        r""":math:`\pi E^* G` [1/m] of a point force at separations ``dx, dy`` (nonzero), mean removed."""
        dx, dy, r = self.nearest(np.asarray(dx, float), np.asarray(dy, float))
        return special.erfc(r / self.xi) / r + self.long_range(dx, dy) - self.constant

    def point_matrix(self, x, y):
        r"""Nearest-image distances and :math:`\pi E^* G` [1/m] between all points ``x, y``.

        The diagonal holds :attr:`self_images`.
        """
        dx, dy, r = self.nearest(x[:, None] - x[None, :], y[:, None] - y[None, :])
        values = self.long_range(dx, dy) - self.constant
        short = _point_matrix(r, lambda r: special.erfc(r / self.xi) / r, -2 / (math.sqrt(math.pi) * self.xi))
        return r, values + short

    spot_excess = staticmethod(FreeKernel.spot_excess)
    spot_excess_da = staticmethod(FreeKernel.spot_excess_da)

    def point_row(self, x0, y0, x, y):
        r"""Nearest-image distances and :math:`\pi E^* G` [1/m] from ``x0, y0`` to the points ``x, y`` (not it)."""
        dx, dy, r = self.nearest(x0 - np.asarray(x, float), y0 - np.asarray(y, float))
        return r, self.long_range(dx, dy) - self.constant + special.erfc(r / self.xi) / r

    def unit_field(self, dx, dy, a):
        r""":math:`\pi E^* u/F` [1/m] of Hertzian spots of radius ``a`` at separations ``dx, dy``.

        The nearest image contributes its Hertz field (:func:`hertz_displacement`), the
        others Ewald's sum; at zero separation the value is the spot's own Hertz field at
        its centre plus :attr:`self_images`.
        """
        dx, dy, r = self.nearest(np.asarray(dx, float), np.asarray(dy, float))
        r, a = np.broadcast_arrays(r, np.asarray(a, float))
        out = self.long_range(dx, dy) - self.constant + np.zeros(r.shape)
        zero = r == 0
        near = ~zero
        out[near] += _unit_field(r[near], a[near]) - special.erf(r[near] / self.xi) / r[near]
        out[zero] += _unit_field(r[zero], a[zero]) - 2 / (math.sqrt(math.pi) * self.xi)
        return out
