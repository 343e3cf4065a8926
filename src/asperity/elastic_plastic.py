r"""Per-asperity laws selectable by name: the paper's elastic law and the Jackson-Green elastic-plastic law.

:data:`LAWS` maps a name to a *law spec*, a small frozen dataclass holding the material's
plasticity in dimensionless form; ``spec.contact_law(params)`` builds the
:class:`~asperity.asperity_law.ContactLaw` that :class:`~asperity.curves.Model` integrates:

=================  ============================  =============================================
name               spec                          per-asperity law
=================  ============================  =============================================
``elastic``        :class:`Elastic`              Hertz or Maugis-Dugdale (the paper's, default)
``jackson-green``  :class:`JacksonGreen`         :class:`JacksonGreenLaw`, no adhesion
=================  ============================  =============================================

**Jackson-Green in the model's units.**  With :math:`\bar u = \omega/\sigma`,
:math:`\alpha = (\sigma/R)^{1/2}`, the hardness :math:`H/E^*` and :math:`e_y = S_y/E^* =
(H/E^*)/2.84` (:func:`~asperity.jackson_green.jg_yield_from_hardness`):

.. math::
    \bar u_{c0} = \frac{\omega_{c0}}{\sigma} = \frac{(\pi C e_y/2)^2}{\alpha^2},\qquad
    \bar a_c^2 = \beta^2\bar u_c,\qquad
    \frac{P_c}{Gb^2} = \frac43\frac{2}{1-\nu}\alpha\beta^2\bar u_c^{3/2},

(the Hertz radius and force at :math:`\bar u_c`), so :math:`\bar a = \beta(\bar u_c\,A/A_c)^{1/2}`
and :math:`P/(Gb^2) = (P_c/Gb^2)(P/P_c)` with :math:`A/A_c` and :math:`P/P_c` of
:func:`~asperity.jackson_green_fits.jg_area` and :func:`~asperity.jackson_green_fits.jg_load` at
:math:`\omega^* = \bar u/\bar u_c`.  The plasticity index of Greenwood and Williamson,
:math:`\psi = (E^*/H)(\sigma/R)^{1/2} = \alpha/(H/E^*)`, gives
:math:`\bar u_{c0} = (\pi C/(2\cdot2.84))^2/\psi^2`.

**Size effect** (:mod:`asperity.nix_gao`): with the Nix-Gao length :math:`h^*/\sigma > 0` the
hardness at penetration :math:`\bar u` is :math:`H\sqrt{1 + h^*/(\sigma\bar u)}`, so
:math:`\bar u_c(\bar u) = \bar u_{c0}(1 + h^*/\sigma\bar u)`, :math:`e_y(\bar u) = e_{y0}
\sqrt{1 + h^*/\sigma\bar u}` and :math:`\omega^* = \bar u/\bar u_c(\bar u)`; with
:math:`h^* = 0` the law is the plain one.

**Regime boundaries** (:attr:`JacksonGreenLaw.breakpoints`): the critical interference
:math:`\bar u_c` (:math:`\omega^* = 1`, yield starts; the *plastic fraction* counts
asperities beyond it), the load's switch :math:`\bar u_x` (:math:`\omega^*_x`,
:func:`~asperity.jackson_green_fits.jg_load_transition`), the area's switch :math:`\bar u_t`
(:math:`\omega^* = 1.9`), and the Hurtado-Kim radii mapped through the law's radius.

**Adhesion.**  The Jackson-Green law has none: it needs :math:`\gamma = 0`.  The model's
adhesion is Maugis-Dugdale, whose contact radius and adhesive zone come from the elastic
half-space solution; with a plastic core they have no consistent counterpart, so the
combination raises :class:`ValueError` instead of guessing (docs/plasticity.md).

References
----------
.. [1] R. L. Jackson, I. Green, J. Tribol. 127 (2005) 343-354.
.. [2] J. A. Greenwood, J. B. P. Williamson, Proc. R. Soc. A 295 (1966) 300-319
   (plasticity index).
.. [3] W. D. Nix, H. Gao, J. Mech. Phys. Solids 46 (1998) 411-425.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ._validation import (
    as_float_array,
    check_broadcast,
    check_finite_result,
    check_nonnegative,
    check_positive,
    ufunc_result,
)
from .asperity_law import AsperityLaw, ModelParameters
from .heights import GAUSSIAN, HeightDistribution, check_heights
from .jackson_green import jg_yield_coefficient
from .jackson_green_law import JacksonGreen, JacksonGreenLaw
from .nix_gao import ng_interference

__all__ = [
    "Elastic",
    "JacksonGreen",
    "JacksonGreenLaw",
    "LAWS",
    "make_law",
    "critical_penetration",
    "plastic_fraction",
]


def critical_penetration(alpha, nu, H_over_E, h_star_over_sigma=0.0):
    r"""Penetration at which an asperity starts to yield, :math:`\bar u_c = \omega_c/\sigma`.

    .. math::
        \bar u_{c0} = \frac{(\pi C e_y/2)^2}{\alpha^2},\quad e_y = \frac{H/E^*}{2.84},\quad
        C = 1.295\,e^{0.736\nu};\qquad
        \bar u_c = \bar u_{c0}\,\frac{1 + \sqrt{1 + 4(h^*/\sigma)/\bar u_{c0}}}{2}

    Jackson & Green's critical interference in units of :math:`\sigma`, with the
    self-consistent Nix-Gao size effect (:func:`~asperity.nix_gao.ng_critical_interference`).
    Broadcasts like a ufunc over its four inputs.

    Parameters
    ----------
    alpha : array_like
        Roughness :math:`\alpha = (\sigma/R)^{1/2} > 0` (Eq 7).
    nu : array_like
        Poisson's ratio, :math:`0 \le \nu < 0.5` (the range of JG's :math:`C(\nu)`).
    H_over_E : array_like
        Hardness over composite modulus :math:`H/E^* > 0` (:math:`H_0/E^*` with the size effect).
    h_star_over_sigma : array_like
        Nix-Gao length over :math:`\sigma`, :math:`h^*/\sigma \ge 0` (0: no size effect).

    Returns
    -------
    ndarray or numpy.float64
        :math:`\bar u_c > 0`, the broadcast shape of the inputs (a NumPy scalar for scalars).

    Raises
    ------
    ValueError
        If an input is not real and finite or out of its range, the shapes do not broadcast,
        or :math:`\bar u_c` leaves double precision.

    Examples
    --------
    >>> psi = 0.01 / 0.002  # plasticity index alpha / (H/E*)
    >>> u_c = critical_penetration(0.01, 0.3, 0.002)
    >>> C = 1.295 * 2.718281828459045 ** (0.736 * 0.3)
    >>> round(float(u_c) * psi**2 / (3.141592653589793 * C / (2 * 2.84)) ** 2, 12)
    1.0

    References
    ----------
    Jackson & Green (2005), critical interference; Greenwood & Williamson (1966); Nix & Gao (1998).
    """
    alpha = check_positive(alpha, "alpha")
    H = check_positive(H_over_E, "H_over_E")
    h = check_nonnegative(h_star_over_sigma, "h_star_over_sigma")
    C = jg_yield_coefficient(nu)
    check_broadcast(alpha=alpha, nu=C, H_over_E=H, h_star_over_sigma=h)
    with np.errstate(all="ignore"):
        u_c0 = (0.5 * np.pi * C * H / 2.84) ** 2 / alpha**2
        bad = ~((u_c0 > 0.0) & (u_c0 < math.inf))  # under- or overflow
        if bad.any():
            i = np.flatnonzero(bad.ravel())[0]
            a, e = (float(np.broadcast_to(x, bad.shape).ravel()[i]) for x in (alpha, H))
            raise ValueError(f"the critical penetration leaves double precision for alpha = {a!r}, "
                             f"H_over_E = {e!r}: give values of physical size")
        u_c = ng_interference(1.0, u_c0, h)
    return ufunc_result(check_finite_result(u_c, "the critical penetration", alpha=alpha, H_over_E=H,
                                            h_star_over_sigma=h))


def plastic_fraction(d, u_c, heights: HeightDistribution = GAUSSIAN):
    r"""Fraction of all asperities past the critical interference, :math:`n_p/N = \int_{\bar d + \bar u_c}^\infty\phi`.

    .. math::
        \frac{n_p}{N} = \int_{\bar d + \bar u_c}^\infty \phi(\bar z)\,d\bar z

    Parameters
    ----------
    d : array_like
        Separations :math:`d/\sigma`, finite.
    u_c : array_like
        Critical penetration :math:`\bar u_c = \omega_c/\sigma > 0` (:func:`critical_penetration`),
        broadcast with ``d``.
    heights : HeightDistribution or str
        Asperity heights (default Gaussian, Eq 19); or a spec string (``'weibull:skew=0.5'``,
        :func:`asperity.heights.parse_heights`).

    Returns
    -------
    ndarray or numpy.float64
        :math:`n_p/N` in [0, 1], the broadcast shape of ``d`` and ``u_c``.

    Raises
    ------
    ValueError
        If ``d`` or ``u_c`` is not real and finite, ``u_c <= 0``, or their shapes do not
        broadcast.

    Examples
    --------
    >>> round(float(plastic_fraction(-1.0, 1.0)), 12)  # asperities above the mean height
    0.5

    References
    ----------
    Greenwood & Williamson (1966); Adams et al., Eq (5).
    """
    d = as_float_array(d, "d", allow_empty=True)
    u_c = check_positive(u_c, "u_c")
    check_broadcast(d=d, u_c=u_c)
    heights = check_heights(heights)
    with np.errstate(over="ignore"):
        z = d + u_c  # d + u_c past 1e308 is above every height: sf = 0
    return ufunc_result(np.asarray(heights.sf(np.where(np.isfinite(z), z, np.finfo(float).max)), dtype=float))


@dataclass(frozen=True)
class Elastic:
    """The paper's per-asperity law: Hertz, or Maugis-Dugdale with adhesion (a law spec)."""

    name: ClassVar[str] = "elastic"
    plastic: ClassVar[bool] = False

    def contact_law(self, params: ModelParameters) -> AsperityLaw:
        """The :class:`~asperity.asperity_law.AsperityLaw` for ``params``."""
        return AsperityLaw(params)


#: Law name -> law spec class (command-line choices read it).
LAWS = {"elastic": Elastic, "jackson-green": JacksonGreen}


def make_law(name: str, *, H_over_E=None, h_star_over_sigma=None):
    r"""The law spec called ``name`` in :data:`LAWS`, with its options.

    Parameters
    ----------
    name : str
        ``'elastic'`` or ``'jackson-green'`` (case-insensitive).
    H_over_E : float, optional
        Hardness :math:`H/E^*` (needed by, and only by, ``'jackson-green'``).
    h_star_over_sigma : float, optional
        Nix-Gao length :math:`h^*/\sigma` (``'jackson-green'`` only; default 0).

    Returns
    -------
    Elastic or JacksonGreen

    Raises
    ------
    ValueError
        For an unknown name (the message lists the known ones), a missing hardness, or
        options the law does not take.

    Examples
    --------
    >>> make_law("jackson-green", H_over_E=0.01)
    JacksonGreen(H_over_E=0.01, h_star_over_sigma=0.0)

    References
    ----------
    Jackson & Green (2005); Nix & Gao (1998); docs/plasticity.md.
    """
    if not isinstance(name, str):
        raise TypeError(f"name (the per-asperity law) must be a string, one of {', '.join(LAWS)}; got {name!r}")
    key = name.strip().lower().replace("_", "-")  # 'Jackson_Green' too
    if key not in LAWS:
        raise ValueError(f"name: unknown law {name!r}; known: {', '.join(LAWS)}")
    if key == "elastic":
        if H_over_E is not None or h_star_over_sigma is not None:
            raise ValueError("the elastic law takes no hardness (H_over_E) or size effect (h_star_over_sigma); "
                             "use the law 'jackson-green'")
        return Elastic()
    if H_over_E is None:
        raise ValueError("the law 'jackson-green' needs the hardness H_over_E = H/E*")
    return JacksonGreen(H_over_E, 0.0 if h_star_over_sigma is None else h_star_over_sigma)
