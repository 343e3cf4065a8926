r"""Greenwood-Williamson multi-asperity integrals at a separation (Eqs 5, 6, 9, 10, 18, 21).

All quantities are per asperity (divided by :math:`N`):

===============  ==========================================================  =========
quantity         integral over in-contact asperities                         equation
===============  ==========================================================  =========
contacts         :math:`n/N = \int\phi\,d\bar z`                              Eq 5
P                :math:`P/(NGb^2) = \int\bar P(\bar u)\phi\,d\bar z`          Eqs 6, 18
F                :math:`F/(NGb^2) = \int 2\pi\bar\tau_f\bar a^2\phi\,d\bar z`  Eqs 9, 10
area             :math:`A/(N\pi b^2) = \int\bar a^2\phi\,d\bar z`             Eq 21
===============  ==========================================================  =========

with :math:`\bar u = \bar z - \bar d`, from the end of the asperity's stable branch
(:math:`\bar u = 0` for Hertz) to infinity.

They broadcast over the separation and the model's parameters like ufuncs.  They are fast
because the per-asperity law is tabulated once on fixed quadrature nodes in penetration
(:class:`~asperity.tabulation.Tabulation`, re-exported here with :data:`D_MIN`,
:data:`D_MAX` and :func:`check_separation`).
"""

from __future__ import annotations

import numpy as np

from ._validation import as_float_array, check_broadcast, check_poisson, ufunc_result
from .asperity_law import ModelParameters, check_law
from .heights import GAUSSIAN, check_heights
from .tabulation import D_MAX, D_MIN, Tabulation, check_separation

__all__ = [
    "D_MIN",
    "D_MAX",
    "Tabulation",
    "contact_fraction",
    "normal_force",
    "friction_force",
    "real_contact_area",
    "mean_pressure",
    "friction_coefficient",
    "check_separation",
]

#: The model's parameters over which the integrals broadcast (with the separation).
_PARAMETERS = ("alpha", "beta", "gamma", "nu", "h_over_b")


def _one_set(d, alpha, beta, gamma, nu, h_over_b, friction, heights):
    """The four integrals at separations ``d`` for one parameter set (checked by ModelParameters)."""
    kwargs = {} if friction is None else {"friction": friction}
    params = ModelParameters(alpha, beta, gamma, nu, h_over_b, **kwargs)
    heights = check_heights(heights)
    law = check_law(None, params)
    d = check_separation(d, d_max=D_MAX - law.u_end)
    tab = Tabulation(params, float(d.min()), float(d.max()), heights, law=law)
    return tab.evaluate(d)


def _is_array(value) -> bool:
    """Whether a parameter is array-like (a list, a pandas Series, a range, ...), not one value."""
    if isinstance(value, list | tuple | range):
        return True
    try:
        return np.ndim(value) > 0
    except (ValueError, TypeError):  # ragged: an array (as_float_array names it)
        return True


def _integrals(d, alpha, beta, gamma, nu, h_over_b, friction, heights, column):
    """One column of the integrals, broadcast over ``d`` and the parameters like a ufunc: one
    tabulation per distinct parameter set; a NumPy scalar for scalar inputs."""
    heights = check_heights(heights)  # a spec string read once, not once per parameter set (a review)
    values = dict(zip(_PARAMETERS, (alpha, beta, gamma, nu, h_over_b), strict=True))
    if not any(_is_array(v) for v in values.values()):
        out = _one_set(d, alpha, beta, gamma, nu, h_over_b, friction, heights)[column]
        return ufunc_result(out)
    arrays = {name: as_float_array(v, name) for name, v in values.items()}
    d = as_float_array(d, "d")
    shape = check_broadcast(d=d, **arrays)
    flat = [np.broadcast_to(a, shape).ravel() for a in (d, *arrays.values())]
    sets, inverse = np.unique(np.stack(flat[1:], axis=1), axis=0, return_inverse=True)
    inverse = inverse.ravel()
    out = np.empty(flat[0].size)
    for k, row in enumerate(sets):
        rows = inverse == k
        out[rows] = _one_set(flat[0][rows], *map(float, row), friction, heights)[column]
    return out.reshape(shape)


def contact_fraction(d, alpha, beta, gamma=0.0, *, nu=0.3, h_over_b=1.0, friction=None,
                     heights=GAUSSIAN):
    r"""Fraction of asperities in contact, :math:`n/N = \int\phi(\bar z)\,d\bar z` (Eq 5).

    .. math::
        \frac nN = \int_{\bar d + \bar u_{end}}^\infty \phi(\bar z)\,d\bar z

    With adhesion the lower limit is the end of the stable branch (negative penetration
    :math:`\bar u_{end}`), so adhesive contacts outnumber Hertzian ones at the same separation.
    Like the other integrals of this module it broadcasts over ``d`` and the five parameters
    as a ufunc does (one tabulation per distinct parameter set): a sweep over
    :math:`\alpha` and :math:`\gamma` is one call.

    Parameters
    ----------
    d : array_like
        Separation :math:`\bar d = d/\sigma` of the mean summit plane from the flat, in
        :math:`[-10^4, 30 - \bar u_{end}]` (beyond, every integral underflows; :math:`\bar u_{end} = 0`
        without adhesion).
    alpha : array_like
        Roughness :math:`\alpha = (\sigma/R)^{1/2} > 0` (Eq 7).
    beta : array_like
        Friction regime parameter :math:`\beta = (R\sigma)^{1/2}/b > 0` (Eq 7).
    gamma : array_like
        Adhesion parameter :math:`\gamma = w/(E^*b) \ge 0` (Eq 16); 0 (default) is Hertz.
    nu : array_like
        Poisson's ratio :math:`\nu`, -1 < nu < 0.5 (default 0.3; the paper does not state it).
    h_over_b : array_like
        Dugdale range over Burgers vector :math:`h/b > 0` (Eq 15; default 1, as in the paper).
    friction : FrictionLaw, optional
        Single-asperity friction stress law (default: Hurtado-Kim with the paper's constants).
    heights : HeightDistribution or str
        Asperity height statistics :math:`\phi` (default: ``Gaussian()``, Eq 19); or a spec
        string (``'weibull:skew=0.5'``, :func:`asperity.heights.parse_heights`).

    Returns
    -------
    ndarray
        :math:`n/N` (dimensionless, in [0, 1]), the broadcast shape of ``d``
        and the parameters (a NumPy scalar for scalars).

    Raises
    ------
    ValueError
        If a parameter is not real and finite or out of its range, the shapes do not
        broadcast, the parameters give a
        Maugis parameter outside :data:`~asperity.maugis_dugdale.LAMBDA_RANGE` or overflow,
        or a separation lies outside its range.

    Examples
    --------
    >>> round(float(contact_fraction(0.0, 0.01, 1000.0)), 12)  # Hertz: the upper half of phi
    0.5
    >>> n = contact_fraction(0.0, [[0.01], [0.05]], 1000.0, [0.0, 1e-3])  # alpha (2, 1) by gamma (2,)
    >>> n.shape, bool(n[1, 1] > n[1, 0])  # adhesion draws more asperities into contact
    ((2, 2), True)

    References
    ----------
    Adams et al., Eqs (5), (18) (lower limit), (19); Greenwood & Williamson (1966).
    """
    return _integrals(d, alpha, beta, gamma, nu, h_over_b, friction, heights, "contacts")


def normal_force(d, alpha, beta, gamma=0.0, *, nu=0.3, h_over_b=1.0, friction=None,
                 heights=GAUSSIAN):
    r"""Normal force per asperity :math:`\bar P = P/(NGb^2)` (Eq 6 for gamma = 0, Eq 18 otherwise).

    .. math::
        \gamma = 0:\ \bar P = \frac43\frac{2}{1-\nu}\alpha\beta^2
            \int_{\bar d}^\infty(\bar z-\bar d)^{3/2}\phi\,d\bar z,\qquad
        \gamma > 0:\ \bar P = \frac1{\hat P}\int_{\bar d+\bar u_{end}}^\infty
            P_M\big((\bar z-\bar d)/\hat\delta\big)\phi\,d\bar z

    with :math:`P_M` the stable-branch Maugis-Dugdale load (:func:`~asperity.maugis_dugdale.md_solve`)
    and the corrected :math:`\hat P = (1-\nu)\alpha/(2\pi\beta\gamma)` (docs/decisions.md).

    Parameters
    ----------
    d : array_like
        Separation :math:`\bar d = d/\sigma` of the mean summit plane from the flat, in
        :math:`[-10^4, 30 - \bar u_{end}]` (beyond, every integral underflows; :math:`\bar u_{end} = 0`
        without adhesion).
    alpha : array_like
        Roughness :math:`\alpha = (\sigma/R)^{1/2} > 0` (Eq 7).
    beta : array_like
        Friction regime parameter :math:`\beta = (R\sigma)^{1/2}/b > 0` (Eq 7).
    gamma : array_like
        Adhesion parameter :math:`\gamma = w/(E^*b) \ge 0` (Eq 16); 0 (default) is Hertz.
    nu : array_like
        Poisson's ratio :math:`\nu`, -1 < nu < 0.5 (default 0.3; the paper does not state it).
    h_over_b : array_like
        Dugdale range over Burgers vector :math:`h/b > 0` (Eq 15; default 1, as in the paper).
    friction : FrictionLaw, optional
        Single-asperity friction stress law (default: Hurtado-Kim with the paper's constants).
    heights : HeightDistribution or str
        Asperity height statistics :math:`\phi` (default: ``Gaussian()``, Eq 19); or a spec
        string (``'weibull:skew=0.5'``, :func:`asperity.heights.parse_heights`).

    Returns
    -------
    ndarray
        :math:`P/(NGb^2)`, positive compressive, negative tensile; the broadcast shape of ``d``
        and the parameters (a NumPy scalar for scalars).

    Raises
    ------
    ValueError
        If a parameter is not real and finite or out of its range, the shapes do not
        broadcast, the parameters give a
        Maugis parameter outside :data:`~asperity.maugis_dugdale.LAMBDA_RANGE` or overflow,
        or a separation lies outside its range.

    Examples
    --------
    >>> P = normal_force([0.0, 1.0], 0.01, 1000.0)  # Hertz: decreasing with separation
    >>> bool(P[0] > P[1] > 0)
    True

    References
    ----------
    Adams et al., Eqs (6), (17) (with the corrected :math:`\hat P`) and (18).
    """
    return _integrals(d, alpha, beta, gamma, nu, h_over_b, friction, heights, "P")


def friction_force(d, alpha, beta, gamma=0.0, *, nu=0.3, h_over_b=1.0, friction=None,
                   heights=GAUSSIAN):
    r"""Friction force per asperity :math:`\bar F = F/(NGb^2)` (Eqs 9-10).

    .. math::
        \bar F = 2\pi\int_{\bar d + \bar u_{end}}^\infty\bar\tau_f(\bar a)\,\bar a^2\,\phi(\bar z)\,d\bar z

    with the friction stress :math:`\bar\tau_f = \tau_f/G^*` (Hurtado-Kim, Eq 2, by default)
    at the contact radius :math:`\bar a = a/b` (Hertz, Eq 8, or Maugis-Dugdale through Eq 17);
    the integral is split where the radius crosses :math:`\bar a_1`, :math:`\bar a_2`.

    Parameters
    ----------
    d : array_like
        Separation :math:`\bar d = d/\sigma` of the mean summit plane from the flat, in
        :math:`[-10^4, 30 - \bar u_{end}]` (beyond, every integral underflows; :math:`\bar u_{end} = 0`
        without adhesion).
    alpha : array_like
        Roughness :math:`\alpha = (\sigma/R)^{1/2} > 0` (Eq 7).
    beta : array_like
        Friction regime parameter :math:`\beta = (R\sigma)^{1/2}/b > 0` (Eq 7).
    gamma : array_like
        Adhesion parameter :math:`\gamma = w/(E^*b) \ge 0` (Eq 16); 0 (default) is Hertz.
    nu : array_like
        Poisson's ratio :math:`\nu`, -1 < nu < 0.5 (default 0.3; the paper does not state it).
    h_over_b : array_like
        Dugdale range over Burgers vector :math:`h/b > 0` (Eq 15; default 1, as in the paper).
    friction : FrictionLaw, optional
        Single-asperity friction stress law (default: Hurtado-Kim with the paper's constants).
    heights : HeightDistribution or str
        Asperity height statistics :math:`\phi` (default: ``Gaussian()``, Eq 19); or a spec
        string (``'weibull:skew=0.5'``, :func:`asperity.heights.parse_heights`).

    Returns
    -------
    ndarray
        :math:`F/(NGb^2)` (>= 0), the broadcast shape of ``d``
        and the parameters (a NumPy scalar for scalars).

    Raises
    ------
    ValueError
        If a parameter is not real and finite or out of its range, the shapes do not
        broadcast, the parameters give a
        Maugis parameter outside :data:`~asperity.maugis_dugdale.LAMBDA_RANGE` or overflow,
        or a separation lies outside its range.

    Examples
    --------
    >>> from asperity.friction_stress import ConstantShear
    >>> F = friction_force(0.5, 0.01, 1000.0, friction=ConstantShear(0.01))
    >>> A = real_contact_area(0.5, 0.01, 1000.0)
    >>> round(float(F / (2 * 3.141592653589793 * 0.01 * A)), 12)  # constant stress: F = 2 pi tau A
    1.0

    References
    ----------
    Adams et al., Eqs (2), (9), (10); Hurtado & Kim (1999).
    """
    return _integrals(d, alpha, beta, gamma, nu, h_over_b, friction, heights, "F")


def real_contact_area(d, alpha, beta, gamma=0.0, *, nu=0.3, h_over_b=1.0, friction=None,
                      heights=GAUSSIAN):
    r"""Real contact area per asperity :math:`A/(N\pi b^2) = \int\bar a^2\phi\,d\bar z` (Eq 21).

    .. math::
        \frac{A}{N\pi b^2} = \int_{\bar d + \bar u_{end}}^\infty \bar a^2\,\phi(\bar z)\,d\bar z

    Without adhesion :math:`\bar a^2 = \beta^2(\bar z - \bar d)` (Eq 8), so this is
    :math:`\beta^2\int_{\bar d}^\infty(\bar z-\bar d)\phi\,d\bar z`.

    Parameters
    ----------
    d : array_like
        Separation :math:`\bar d = d/\sigma` of the mean summit plane from the flat, in
        :math:`[-10^4, 30 - \bar u_{end}]` (beyond, every integral underflows; :math:`\bar u_{end} = 0`
        without adhesion).
    alpha : array_like
        Roughness :math:`\alpha = (\sigma/R)^{1/2} > 0` (Eq 7).
    beta : array_like
        Friction regime parameter :math:`\beta = (R\sigma)^{1/2}/b > 0` (Eq 7).
    gamma : array_like
        Adhesion parameter :math:`\gamma = w/(E^*b) \ge 0` (Eq 16); 0 (default) is Hertz.
    nu : array_like
        Poisson's ratio :math:`\nu`, -1 < nu < 0.5 (default 0.3; the paper does not state it).
    h_over_b : array_like
        Dugdale range over Burgers vector :math:`h/b > 0` (Eq 15; default 1, as in the paper).
    friction : FrictionLaw, optional
        Single-asperity friction stress law (default: Hurtado-Kim with the paper's constants).
    heights : HeightDistribution or str
        Asperity height statistics :math:`\phi` (default: ``Gaussian()``, Eq 19); or a spec
        string (``'weibull:skew=0.5'``, :func:`asperity.heights.parse_heights`).

    Returns
    -------
    ndarray
        :math:`A/(N\pi b^2)` (>= 0), the broadcast shape of ``d``
        and the parameters (a NumPy scalar for scalars).

    Raises
    ------
    ValueError
        If a parameter is not real and finite or out of its range, the shapes do not
        broadcast, the parameters give a
        Maugis parameter outside :data:`~asperity.maugis_dugdale.LAMBDA_RANGE` or overflow,
        or a separation lies outside its range.

    Examples
    --------
    >>> import math
    >>> area = float(real_contact_area(0.0, 0.01, 1000.0))  # Hertz at d = 0: beta^2 / sqrt(2 pi)
    >>> round(area / (1e6 / math.sqrt(2 * math.pi)), 12)
    1.0

    References
    ----------
    Adams et al., Eqs (8), (21).
    """
    return _integrals(d, alpha, beta, gamma, nu, h_over_b, friction, heights, "area")


def mean_pressure(P, area, nu=0.3):
    r"""Mean contact pressure :math:`P/(E^*A) = \bar P(1-\nu)/(2\pi\bar A)` (Fig 9).

    Parameters
    ----------
    P : array_like
        :math:`P/(NGb^2)`.
    area : array_like
        :math:`A/(N\pi b^2)`; where it is 0 (no contact) the result is NaN.
    nu : array_like
        Poisson's ratio (:math:`E^*/G = 2/(1-\nu)`).
    """
    P, area = _pair(P, "P", area, "area")
    if np.any(area < 0):
        raise ValueError("area (real contact area) must be >= 0")
    nu = check_poisson(nu)
    check_broadcast(P=P, area=area, nu=nu)
    with np.errstate(all="ignore"):  # a finite load over a vanishing area: infinite pressure
        return ufunc_result(np.where(area > 0, P * (1.0 - nu) / (2.0 * np.pi * np.where(area > 0, area, 1.0)), np.nan))


def friction_coefficient(F, P):
    r"""Friction coefficient :math:`\mu = F/P` (Eq 1); NaN where :math:`P \le 0` (undefined).

    Under zero or tensile load an adhesive contact still has a finite friction force, so
    :math:`\mu` is infinite or meaningless there; NaN marks it.  Under a vanishing positive
    load :math:`F/P` overflows to infinity, its true value.
    """
    F, P = _pair(F, "F", P, "P")
    with np.errstate(all="ignore"):  # a finite friction over a vanishing load: mu = inf
        return ufunc_result(np.where(P > 0, F / np.where(P > 0, P, 1.0), np.nan))


def _pair(x, x_name, y, y_name):
    """Two real finite arrays (may be empty) of shapes that broadcast together."""
    x, y = as_float_array(x, x_name, allow_empty=True), as_float_array(y, y_name, allow_empty=True)
    try:
        np.broadcast_shapes(x.shape, y.shape)
    except ValueError:
        raise ValueError(f"{x_name} and {y_name} must have shapes that broadcast together, got {x.shape} and "
                         f"{y.shape}") from None
    return x, y
