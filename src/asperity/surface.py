r"""A Greenwood-Williamson rough surface in SI units, and its link to the paper's groups.

The Greenwood-Williamson (GW) model describes a nominally flat rough surface by three
summit statistics and the nominal area it covers:

=================  ============================================  ==============
symbol             meaning                                       unit
=================  ============================================  ==============
``sigma_s``        standard deviation of summit heights          m
``R``              mean summit radius of curvature               m
``eta``            summit density (summits per nominal area)     1/m\ :sup:`2`
``area``           nominal contact area :math:`A_0`              m\ :sup:`2`
=================  ============================================  ==============

The names are those of :data:`asperity.quantities.PHYSICAL_PARAMETERS`;
:class:`asperity.topography.SummitParameters` uses the same three.  The surface holds
:math:`N = \eta A_0` asperities, and with the Burgers vector :math:`b` of the material it
gives the paper's roughness and friction-regime parameters (Eq 7),

.. math::
    \alpha = (\sigma_s/R)^{1/2},\qquad \beta = (R\sigma_s)^{1/2}/b,

which :func:`surface_from_groups` inverts (Eq 20):
:math:`\sigma_s = \alpha\beta b`, :math:`R = \beta b/\alpha`.

**Summits versus all heights.**  :math:`\sigma_s` is the deviation of the *summit*
heights, smaller than the rms roughness :math:`\sigma = \sqrt{m_0}` of all heights that
profilometers and AFMs report.  For an isotropic Gaussian surface Nayak (1971), as
summarised by McCool (1986), gives

.. math::
    \sigma_s = \Bigl(1 - \frac{0.8968}{\alpha_N}\Bigr)^{1/2}\sigma,\qquad
    \alpha_N = \frac{m_0 m_4}{m_2^2} \ge 1,

with :math:`m_0, m_2, m_4` the spectral moments (mean square height, slope, curvature of
a profile) and :math:`\alpha_N` the bandwidth parameter
(:func:`nayak_summit_sigma`, :meth:`Surface.from_rms`).  :math:`\sigma_s/\sigma` is 0.73
at :math:`\alpha_N = 1.9`, 0.91 at 5, 0.95 at 10 and 0.995 at 100: for a broadband
surface the two are close, for a narrow-band one they are not, and there is no default
for :math:`\alpha_N`.  :func:`asperity.topography.analyse_surface` measures it from a scan.

Every input accepts a float in SI units, a pint ``Quantity`` or a string with a unit
such as ``'2nm'`` (``pip install 'asperity[units]'``).

References
----------
.. [1] J. A. Greenwood, J. B. P. Williamson, "Contact of nominally flat surfaces",
   Proc. R. Soc. A 295 (1966) 300-319.
.. [2] Adams, Müftü, Mohd Azhar, "A nano-scale multi-asperity contact and friction model",
   Eqs (7), (20).
.. [3] P. R. Nayak, "Random process model of rough surfaces", J. Lubr. Technol. (ASME) 93
   (1971) 398-407.
.. [4] J. I. McCool, "Comparison of models for the contact of rough surfaces", Wear 107
   (1986) 37-60.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from ._validation import check_finite_result, check_scalar_positive, check_text
from .quantities import PHYSICAL_PARAMETERS
from .units import format_si

__all__ = ["Surface", "surface_from_groups", "nayak_summit_sigma", "NAYAK_SIGMA_S"]

#: Nayak's constant in the summit-height variance, :math:`\sigma_s^2 = (1 - 0.8968/\alpha_N)\,m_0`
#: (Nayak 1971, as collected by McCool 1986).
NAYAK_SIGMA_S = 0.8968

#: The fields of a :class:`Surface`, with their entries in the quantity registry.
SURFACE_PARAMETERS = {name: PHYSICAL_PARAMETERS[name] for name in ("sigma_s", "R", "eta", "area")}


@dataclass(frozen=True)
class Surface:
    r"""A Greenwood-Williamson rough surface in SI units.

    Parameters
    ----------
    sigma_s : float, pint.Quantity or str
        Standard deviation of summit heights :math:`\sigma_s` (m), > 0.
    R : float, pint.Quantity or str
        Mean summit radius of curvature :math:`R` (m), > 0.
    eta : float, pint.Quantity or str
        Summit density :math:`\eta` (1/m^2), > 0.
    area : float, pint.Quantity or str
        Nominal contact area :math:`A_0` (m^2), > 0.
    source : str, optional
        Where the numbers come from (e.g. ``'scan.x3p, spectral (Nayak/McCool)'``), for
        descriptions; not compared.

    Attributes
    ----------
    N : float
        Number of summits :math:`\eta A_0` in the nominal area.
    alpha : float
        Roughness parameter :math:`(\sigma_s/R)^{1/2}` (Eq 7).

    Raises
    ------
    ValueError
        For a value that is not one finite number > 0, or a quantity of the wrong
        dimension; the message names the field and its unit.

    Examples
    --------
    >>> Surface(sigma_s=2e-9, R=1e-6, eta=1e12, area=1e-6).N
    1000000.0
    """

    sigma_s: float
    R: float
    eta: float
    area: float
    source: str | None = field(default=None, compare=False)

    def __post_init__(self):
        for name, q in SURFACE_PARAMETERS.items():
            object.__setattr__(self, name, check_scalar_positive(getattr(self, name), name, q.si_unit))
        if not math.isfinite(self.eta * self.area):
            raise ValueError(f"eta * area (the number of summits N) must be finite, got eta = {self.eta:g} 1/m^2 and "
                             f"area = {self.area:g} m^2 (N overflows)")
        if self.source is not None:
            check_text(self.source, "source")

    @classmethod
    def from_rms(cls, rms, R, eta, area, *, alpha_n) -> Surface:
        r"""The surface of an rms roughness :math:`\sigma` and a bandwidth :math:`\alpha_N` (Nayak).

        .. math:: \sigma_s = \Bigl(1 - \frac{0.8968}{\alpha_N}\Bigr)^{1/2}\sigma

        Parameters
        ----------
        rms : float, pint.Quantity or str
            Rms roughness :math:`\sigma = \sqrt{m_0}` of all heights (m), > 0.
        R : float, pint.Quantity or str
            Mean summit radius of curvature (m), > 0.
        eta : float, pint.Quantity or str
            Summit density (1/m^2), > 0.
        area : float, pint.Quantity or str
            Nominal contact area (m^2), > 0.
        alpha_n : float
            Nayak's bandwidth parameter :math:`\alpha_N = m_0m_4/m_2^2 \ge 1`; required
            (no default: :math:`\sigma_s/\sigma` ranges from 0.32 at 1 to 1 at infinity).

        Returns
        -------
        Surface
            With :math:`\sigma_s` from :func:`nayak_summit_sigma`.

        References
        ----------
        Nayak (1971); McCool (1986).

        Examples
        --------
        >>> s = Surface.from_rms(5e-9, 1e-6, 1e12, 1e-6, alpha_n=10.0)
        >>> round(s.sigma_s * 1e9, 4)
        4.7705
        """
        rms, alpha_n = check_scalar_positive(rms, "rms", "m"), check_scalar_positive(alpha_n, "alpha_n", "")
        return cls(sigma_s=nayak_summit_sigma(rms, alpha_n), R=R, eta=eta, area=area,
                   source=f"rms {format_si(rms, 'm')} with alpha_N = {alpha_n:g} (Nayak)")

    @property
    def N(self) -> float:
        """Number of asperities (summits) :math:`\\eta A_0` in the nominal area."""
        return self.eta * self.area

    @property
    def alpha(self) -> float:
        """Surface roughness parameter :math:`(\\sigma_s/R)^{1/2}` (Eq 7)."""
        return math.sqrt(self.sigma_s / self.R)


def surface_from_groups(alpha, beta, b, eta, area) -> Surface:
    r"""The :class:`Surface` with given roughness and friction-regime parameters (Eq 20).

    .. math:: \sigma_s = \alpha\beta b,\qquad R = \beta b/\alpha

    Parameters
    ----------
    alpha : float
        Roughness parameter :math:`\alpha = (\sigma_s/R)^{1/2}` (Eq 7), > 0.
    beta : float
        Friction-regime parameter :math:`\beta = (R\sigma_s)^{1/2}/b` (Eq 7), > 0.
    b : float, pint.Quantity or str
        Burgers vector :math:`b` (m), > 0.
    eta : float, pint.Quantity or str
        Summit density :math:`\eta` (1/m^2), > 0.
    area : float, pint.Quantity or str
        Nominal area :math:`A_0` (m^2), > 0.

    Returns
    -------
    Surface
        With :math:`\sigma_s = \alpha\beta b` and :math:`R = \beta b/\alpha`.

    References
    ----------
    Adams et al., Eq (20).

    Examples
    --------
    >>> s = surface_from_groups(0.01, 100.0, 2.5e-10, 1e12, 1e-6)
    >>> round(s.sigma_s * 1e10, 12), round(s.R * 1e6, 12)
    (2.5, 2.5)
    """
    alpha = check_scalar_positive(alpha, "alpha", "")
    beta = check_scalar_positive(beta, "beta", "")
    b = check_scalar_positive(b, "b", "m")
    sigma_s, R = alpha * beta * b, beta * b / alpha
    check_finite_result([sigma_s, R], "sigma_s or R", alpha=alpha, beta=beta, b=b)
    if not (sigma_s > 0 and R > 0):
        raise ValueError(f"alpha = {alpha!r}, beta = {beta!r}, b = {b!r} give sigma_s = {sigma_s!r}, R = {R!r}: "
                         "below double precision")
    return Surface(sigma_s=sigma_s, R=R, eta=eta, area=area)


def nayak_summit_sigma(rms, alpha_n) -> float:
    r"""Summit-height deviation :math:`\sigma_s` of an isotropic Gaussian surface from its rms roughness.

    .. math:: \sigma_s = \Bigl(1 - \frac{0.8968}{\alpha_N}\Bigr)^{1/2}\sigma

    Parameters
    ----------
    rms : float, pint.Quantity or str
        Rms roughness :math:`\sigma = \sqrt{m_0}` of all surface heights (m), > 0.
    alpha_n : float
        Nayak's bandwidth parameter :math:`\alpha_N = m_0 m_4/m_2^2` of profile moments, >= 1
        (its least value for any profile; an isotropic surface has :math:`\alpha_N \ge 1.5`);
        the relation is reliable for :math:`\alpha_N \gtrsim 5`.

    Returns
    -------
    float
        :math:`\sigma_s` (m).

    Raises
    ------
    ValueError
        For ``rms`` not > 0 or ``alpha_n`` not >= 1 (the message names the parameter).

    References
    ----------
    Nayak (1971), J. Lubr. Technol. 93, 398-407; McCool (1986), Wear 107, 37-60 (Table 1).

    Examples
    --------
    >>> round(nayak_summit_sigma(1.0, 100.0), 6)
    0.995506
    """
    rms = check_scalar_positive(rms, "rms", "m")
    alpha_n = check_scalar_positive(alpha_n, "alpha_n", "")
    if alpha_n < 1.0:
        raise ValueError(f"alpha_n (Nayak's bandwidth parameter m0 m4/m2^2) must be >= 1 "
                         f"(valid range 1 <= alpha_n < inf), got {alpha_n!r}")
    return math.sqrt(1.0 - NAYAK_SIGMA_S / alpha_n) * rms
