r"""Curves the paper reports: quantities versus separation, versus load, and pull-off.

:func:`separation_curve`, :func:`load_curve` and :func:`pull_off` compute them for one
parameter set.  :class:`Model` holds a parameter set and caches its tabulated
per-asperity law and pull-off force, so a user sweeping thousands of loads pays the
set-up once; its methods delegate to :mod:`asperity.load_control`.

*Load control.*  With adhesion :math:`\bar P(\bar d)` is not monotone: it falls from
large compressive values, may turn tensile, reaches its most tensile value (the
pull-off force) and returns to zero as :math:`\bar d\to\infty`.  The equilibrium under
a given load is the first separation, coming from full contact, at which
:math:`\bar P(\bar d)` equals the load: the stable branch, :math:`d\bar P/d\bar d < 0`.
"""

from __future__ import annotations

from dataclasses import fields

import numpy as np

from ._validation import check_1d, check_scalar_real
from .asperity_law import ContactLaw, ModelParameters, check_law
from .curve_result import COLUMNS, CurveResult
from .heights import GAUSSIAN, HeightDistribution, check_heights
from .interaction import as_interaction
from .load_control import (
    LoadOutOfRange,
    PullOff,
    bracket_low,
    find_pull_off,
    invert_branch,
    stable_branch,
    start_separation,
)
from .multi_asperity import friction_coefficient, mean_pressure
from .tabulation import D_MAX, D_MIN, Tabulation, check_separation

__all__ = ["CurveResult", "COLUMNS", "PullOff", "Model", "separation_curve", "load_curve", "pull_off", "MAX_POINTS"]

#: Most loads or separations one curve takes (as on the command line): beyond, a curve costs
#: minutes and gigabytes (1e7 loads: 146 s, 3.6 GB), so it is refused at once.
MAX_POINTS = 10**6
#: Loads this far (relative) below minus the pull-off force are taken as it (a fresh pull_off() differs by rounding).
PULL_OFF_RTOL = 1e-12


class Model:
    """The multi-asperity contact and friction model for one parameter set, cached.

    Builds the per-asperity law once and keeps its tabulation (widened as needed) and the
    pull-off force, so repeated curves cost only the sums; the algorithms are the functions
    of :mod:`asperity.load_control`.  A Model's caches are mutable: use one per thread.

    Parameters
    ----------
    alpha : float
        Roughness :math:`\\alpha = (\\sigma/R)^{1/2} > 0` (Eq 7).
    beta : float
        Friction regime parameter :math:`\\beta = (R\\sigma)^{1/2}/b > 0` (Eq 7).
    gamma : float
        Adhesion parameter :math:`\\gamma = w/(E^*b) \\ge 0` (Eq 16); 0 (default) is Hertz.
    nu : float
        Poisson's ratio, -1 < nu < 0.5 (default 0.3; the paper does not state it).
    h_over_b : float
        Dugdale range over Burgers vector :math:`h/b > 0` (Eq 15; default 1, as in the paper).
    friction : FrictionLaw, optional
        Single-asperity friction law (default: Hurtado-Kim with the paper's constants).
    heights : HeightDistribution or str
        Asperity heights (default: ``Gaussian()``, Eq 19); or a spec string (``'weibull:skew=0.5'``,
        :func:`asperity.heights.parse_heights`).
    interaction : None, 'none' or an interaction object, optional
        Asperity interaction (:mod:`asperity.interaction`): None (default) is plain GW;
        a :class:`~asperity.interaction.MeanFieldInteraction` (Ciavarella, Greenwood &
        Paggi 2008) makes ``d`` the apparent separation from the undeformed surface
        (non-adhesive models only).
    law : ContactLaw or law spec, optional
        Per-asperity law: a :class:`~asperity.asperity_law.ContactLaw` built for these
        parameters, or a law spec of :data:`asperity.elastic_plastic.LAWS` (anything with a
        ``contact_law(params)`` method, e.g. ``JacksonGreen(H_over_E=0.01)``), built here.
        Default: ``AsperityLaw`` (Hertz or Maugis-Dugdale).  A law with a critical
        interference (``plastic_fraction``) adds the column ``plastic`` to every curve.

    Raises
    ------
    ValueError
        If a parameter is out of its range, ``heights`` is not a HeightDistribution,
        ``law`` not a ContactLaw for these parameters, or ``interaction`` unknown.

    Examples
    --------
    >>> m = Model(alpha=0.01, beta=1000, gamma=1e-3)
    >>> curve = m.load_curve([1.0, 10.0, 100.0])
    >>> bool(curve.mu[0] > curve.mu[-1])
    True
    """

    def __init__(self, alpha, beta, gamma=0.0, *, nu=0.3, h_over_b=1.0, friction=None,
                 heights: HeightDistribution = GAUSSIAN, law: ContactLaw | None = None, interaction=None):
        kwargs = {} if friction is None else {"friction": friction}
        self.params = ModelParameters(alpha, beta, gamma, nu, h_over_b, **kwargs)
        self.heights = check_heights(heights)
        if law is not None and not isinstance(law, ContactLaw) and callable(getattr(law, "contact_law", None)):
            law = law.contact_law(self.params)  # a law spec (asperity.elastic_plastic.LAWS)
        self.law = check_law(law, self.params)
        #: Asperity interaction (:mod:`asperity.interaction`); plain GW by default.
        self.interaction = as_interaction(interaction, adhesive=self.params.adhesive)
        #: Largest valid separation: beyond it every quantity underflows.
        self.d_top = D_MAX - self.law.u_end
        #: Default reach of the pull-off search: 10 sigma past the end of the stable branch.
        self.d_search = 10.0 - self.law.u_end
        self._tab: Tabulation | None = None
        self._pull_off: dict[float, PullOff] = {}
        self._parameters_dict: dict | None = None

    # -- cache ----------------------------------------------------------------------
    def tabulation(self, d_min: float, d_max: float) -> Tabulation:
        """A tabulation serving [d_min, d_max], reusing (and widening) the cached one."""
        if self._tab is None:
            self._tab = Tabulation(self.params, d_min, d_max, self.heights, law=self.law)
        else:
            self._tab = self._tab.extended(d_min, d_max)
        return self._tab

    def _parameters(self):
        if self._parameters_dict is None:
            p = {f.name: getattr(self.params, f.name) for f in fields(self.params)}
            p["friction"] = repr(self.params.friction)
            p["heights"] = self.heights.spec or repr(self.heights)
            if self.interaction.active:
                p["interaction"] = repr(self.interaction)
            if callable(getattr(self.law, "parameters", None)):  # e.g. the Jackson-Green law and its hardness
                p.update(self.law.parameters())
            self._parameters_dict = p
        return dict(self._parameters_dict)

    def _result(self, d, sums, d_local=None) -> CurveResult:
        """The curve at (apparent) separations ``d``; ``d_local``: the separations the asperities feel."""
        contacts, P, F, area = (sums[:, i] for i in range(4))
        d_local = d if d_local is None else d_local
        plastic = (self.law.plastic_fraction(d_local, self.heights) if hasattr(self.law, "plastic_fraction")
                   else None)
        return CurveResult(d=d, P=P, F=F, mu=friction_coefficient(F, P), area=area,
                           pressure=mean_pressure(P, area, self.params.nu), contacts=contacts,
                           parameters=self._parameters(), plastic=plastic,
                           d_local=None if d_local is d else d_local)

    # -- curves ---------------------------------------------------------------------
    def separation_curve(self, d) -> CurveResult:
        """All quantities at separations ``d``: :func:`separation_curve` for this model."""
        d = check_separation(_check_size(check_1d(d, "d"), "d"), d_max=self.d_top)
        tab = self.tabulation(float(d.min()), max(float(d.max()), 10.0))
        if not self.interaction.active:
            return self._result(d, tab.sums(d)[0])
        # Interaction hook: the asperities feel the local separation d_loc = d + Delta(P(d_loc)) <= d + Delta(P(d)).
        reach = min(float(np.max(d + self.interaction.shift(tab.sums(d)[0][:, 1]))), self.d_top)
        tab = self.tabulation(float(d.min()), max(reach, 10.0))
        d_loc = np.minimum(self.interaction.local_separation(
            d, lambda x: tuple(s[:, 1] for s in tab.sums(np.minimum(x, reach), order=1))), reach)
        return self._result(d, tab.sums(d_loc)[0], d_loc)

    def pull_off(self, d_max: float | None = None) -> PullOff:
        """Largest tensile force for -3 <= d/sigma <= ``d_max``: :func:`pull_off` for this model (cached).

        ``d_max`` defaults to :attr:`d_search`, 10 sigma beyond the end of the asperities'
        stable branch.  After :meth:`load_curve` the search made on its grid (which spans
        ``[d_lo <= -3, d_search]``) is reused.
        """
        if d_max is None:
            d_max = self.d_search
        d_max = check_scalar_real(d_max, "d_max")
        if not 0.0 < d_max <= self.d_top:
            raise ValueError(f"d_max must lie in (0, {self.d_top:.6g}], got {d_max!r}")
        if d_max not in self._pull_off:
            if self.params.adhesive:
                self._pull_off[d_max] = find_pull_off(self.tabulation(-3.0, d_max), -3.0, d_max)
            else:  # no adhesion, no tensile force: no tabulation needed
                self._pull_off[d_max] = PullOff(0.0, float("nan"), False)
        return self._pull_off[d_max]

    def load_curve(self, P) -> CurveResult:
        """All quantities at the stable separation for each load ``P``: :func:`load_curve` for this model."""
        P = _check_size(check_1d(P, "P"), "P")
        if not self.params.adhesive and np.any(P <= 0):
            raise LoadOutOfRange(0.0, P.min(), "without adhesion, gamma = 0", exclusive=True)
        d_hi, P_max = self.d_search, float(P.max())
        d_lo = start_separation(self.params, P_max, d_hi)
        branch = stable_branch(self.tabulation(d_lo, d_hi), d_lo, d_hi, d_top=self.d_top, P_min=float(P.min()),
                               pull_off=self._pull_off.get(d_hi))
        if not branch.P[0] > P_max:  # the Hertz estimate fell short: step down (bracket_low) and redo
            d_lo, self._tab = bracket_low(branch.tab, P_max, max(d_lo - max(2.0, 0.5 * abs(d_lo)), D_MIN), d_hi)
            branch = stable_branch(self._tab, d_lo, d_hi, d_top=self.d_top, P_min=float(P.min()),
                                   pull_off=branch.pull_off)
        self._tab = branch.tab
        # the branch's pull-off search over [d_lo <= -3, d_hi] (or its finding of none) serves pull_off() too
        self._pull_off.setdefault(d_hi, branch.pull_off or PullOff(0.0, float("nan"), False))
        floor = branch.P[-1]
        if P.min() < floor - PULL_OFF_RTOL * abs(floor):
            d_end = None if floor < 0 else float(branch.grid[-1])
            what = "minus the pull-off force" if d_end is None else f"the force at d/sigma = {d_end:.4g}"
            raise LoadOutOfRange(floor, P.min(), what, d_end=d_end)
        d, sums = invert_branch(branch.tab, np.maximum(P, floor), branch.grid, branch.P, branch.dP)
        sums[:, 1] = P  # solved for to rounding; report the load asked for
        # Interaction hook: the apparent separation is the local one less the uniform sinking.
        return self._result(d - self.interaction.shift(P), sums, d)


def _check_size(values, name):
    if values.size > MAX_POINTS:
        raise ValueError(f"{name} must hold at most {MAX_POINTS} values (MAX_POINTS), got {values.size}: split "
                         "the curve, or sample it more coarsely")
    return values


def separation_curve(d, alpha, beta, gamma=0.0, *, nu=0.3, h_over_b=1.0, friction=None,
                     heights=GAUSSIAN, interaction=None) -> CurveResult:
    r"""Normal and friction force, :math:`\mu`, area, pressure and contacts versus separation (Figs 7-8).

    .. math::
        \frac nN = \int\phi,\quad \bar P = \int\bar P(\bar u)\phi,\quad
        \bar F = \int 2\pi\bar\tau_f\bar a^2\phi,\quad \frac{A}{N\pi b^2} = \int\bar a^2\phi,\quad
        \mu = \frac{\bar F}{\bar P},\quad \frac{P}{E^*A} = \frac{(1-\nu)\bar P}{2\pi A/(N\pi b^2)}

    integrals over :math:`\bar z \ge \bar d + \bar u_{end}` with :math:`\bar u = \bar z - \bar d`
    (:mod:`asperity.multi_asperity`).

    Parameters
    ----------
    d : array_like
        Separations :math:`\bar d = d/\sigma` of the mean summit plane from the flat, in
        :math:`[-10^4, 30 - \bar u_{end}]` (:math:`\bar u_{end} = 0` without adhesion).
    alpha : float
        Roughness :math:`\alpha = (\sigma/R)^{1/2} > 0` (Eq 7).
    beta : float
        Friction regime parameter :math:`\beta = (R\sigma)^{1/2}/b > 0` (Eq 7).
    gamma : float
        Adhesion parameter :math:`\gamma = w/(E^*b) \ge 0` (Eq 16); 0 (default) is Hertz.
    nu : float
        Poisson's ratio, -1 < nu < 0.5 (default 0.3; the paper does not state it).
    h_over_b : float
        Dugdale range over Burgers vector :math:`h/b > 0` (Eq 15; default 1, as in the paper).
    friction : FrictionLaw, optional
        Single-asperity friction law (default: Hurtado-Kim with the paper's constants).
    heights : HeightDistribution or str
        Asperity heights (default: ``Gaussian()``, Eq 19); or a spec string (``'weibull:skew=0.5'``,
        :func:`asperity.heights.parse_heights`).
    interaction : None, 'none' or an interaction object, optional
        Asperity interaction (:mod:`asperity.interaction`; default None, plain GW): with a
        :class:`~asperity.interaction.MeanFieldInteraction` (Ciavarella, Greenwood & Paggi
        2008, non-adhesive only) ``d`` is the apparent separation from the undeformed
        surface, the asperities sitting at :math:`d_{loc} = d + k\bar P`.

    Returns
    -------
    CurveResult
        Arrays ``d`` (:math:`d/\sigma`), ``P`` (:math:`P/(NGb^2)`, positive compressive),
        ``F`` (:math:`F/(NGb^2)`), ``mu`` (:math:`F/P`, NaN where :math:`P \le 0`), ``area``
        (:math:`A/(N\pi b^2)`), ``pressure`` (:math:`P/(E^*A)`, NaN without contact) and
        ``contacts`` (:math:`n/N`), one value per separation; ``parameters`` holds the inputs.

    Raises
    ------
    ValueError
        If a parameter is out of its range or a separation outside :math:`[-10^4, 30 - \bar u_{end}]`.

    Examples
    --------
    >>> c = separation_curve([0.0, 1.0], 0.01, 1000.0)
    >>> round(float(c.contacts[0]), 12), bool(c.P[0] > c.P[1] > 0)
    (0.5, True)

    References
    ----------
    Adams et al., Eqs (1), (5), (6), (10), (18), (21); Figs 7-8.
    """
    return Model(alpha, beta, gamma, nu=nu, h_over_b=h_over_b, friction=friction,
                 heights=heights, interaction=interaction).separation_curve(d)


def load_curve(P, alpha, beta, gamma=0.0, *, nu=0.3, h_over_b=1.0, friction=None,
               heights=GAUSSIAN, interaction=None) -> CurveResult:
    r"""All quantities at the stable separation for each normal load (Figs 3-6, 9).

    The separation under a load :math:`P` is the first one, coming from full contact, where
    :math:`\bar P(\bar d) = P`: on the stable branch, which ends at the pull-off force
    (:func:`asperity.load_control.stable_branch`, :func:`~asperity.load_control.invert_branch`).

    .. math::
        \bar P(\bar d) = P,\quad d\bar P/d\bar d < 0;\qquad \mu = \bar F(\bar d)/P

    Parameters
    ----------
    P : array_like
        Loads :math:`P/(NGb^2)` per asperity, positive compressive: > 0 without adhesion;
        with adhesion down to minus the pull-off force (:func:`pull_off`; up to 1e-12 of it
        below, its rounding, is taken as it).
    alpha : float
        Roughness :math:`\alpha = (\sigma/R)^{1/2} > 0` (Eq 7).
    beta : float
        Friction regime parameter :math:`\beta = (R\sigma)^{1/2}/b > 0` (Eq 7).
    gamma : float
        Adhesion parameter :math:`\gamma = w/(E^*b) \ge 0` (Eq 16); 0 (default) is Hertz.
    nu : float
        Poisson's ratio, -1 < nu < 0.5 (default 0.3; the paper does not state it).
    h_over_b : float
        Dugdale range over Burgers vector :math:`h/b > 0` (Eq 15; default 1, as in the paper).
    friction : FrictionLaw, optional
        Single-asperity friction law (default: Hurtado-Kim with the paper's constants).
    heights : HeightDistribution or str
        Asperity heights (default: ``Gaussian()``, Eq 19); or a spec string (``'weibull:skew=0.5'``,
        :func:`asperity.heights.parse_heights`).
    interaction : None, 'none' or an interaction object, optional
        Asperity interaction (:mod:`asperity.interaction`; default None, plain GW): with a
        :class:`~asperity.interaction.MeanFieldInteraction` (Ciavarella, Greenwood & Paggi
        2008, non-adhesive only) ``d`` is the apparent separation from the undeformed
        surface, the asperities sitting at :math:`d_{loc} = d + k\bar P`.

    Returns
    -------
    CurveResult
        Arrays ``d`` (:math:`d/\sigma`), ``P`` (the loads, :math:`P/(NGb^2)`), ``F``
        (:math:`F/(NGb^2)`), ``mu`` (:math:`F/P`, NaN where :math:`P \le 0`), ``area``
        (:math:`A/(N\pi b^2)`), ``pressure`` (:math:`P/(E^*A)`) and ``contacts`` (:math:`n/N`),
        one value per load; ``parameters`` holds the inputs.

    Raises
    ------
    ValueError
        If a parameter is out of its range, a load is not positive without adhesion or more
        tensile than the pull-off force with it (no equilibrium), or a load needs a
        separation below :math:`-10^4`.

    Examples
    --------
    >>> c = load_curve([1.0, 100.0], 0.01, 1000.0, 1e-3)
    >>> [round(float(x), 9) for x in c.P], bool(c.d[0] > c.d[1]), bool(c.mu[0] > c.mu[1])
    ([1.0, 100.0], True, True)

    References
    ----------
    Adams et al., Eqs (1), (6), (10), (18), (21); Figs 3-6, 9.
    """
    return Model(alpha, beta, gamma, nu=nu, h_over_b=h_over_b, friction=friction,
                 heights=heights, interaction=interaction).load_curve(P)


def pull_off(alpha, beta, gamma, *, nu=0.3, h_over_b=1.0, friction=None, heights=GAUSSIAN,
             d_max=None) -> PullOff:
    r"""Pull-off force :math:`|P|/(NGb^2)`: the largest tensile force for -3 <= d/sigma <= d_max (Table 1).

    .. math::
        P_{off} = \max\Big(0,\ -\min_{-3 \le \bar d \le \bar d_{max}} \bar P(\bar d)\Big)

    found on a grid and refined by Newton's method on :math:`d\bar P/d\bar d = 0`
    (:func:`asperity.load_control.find_pull_off`).

    Parameters
    ----------
    alpha : float
        Roughness :math:`\alpha = (\sigma/R)^{1/2} > 0` (Eq 7).
    beta : float
        Friction regime parameter :math:`\beta = (R\sigma)^{1/2}/b > 0` (Eq 7).
    gamma : float
        Adhesion parameter :math:`\gamma = w/(E^*b) \ge 0` (Eq 16); 0 gives no pull-off.
    nu : float
        Poisson's ratio, -1 < nu < 0.5 (default 0.3; the paper does not state it).
    h_over_b : float
        Dugdale range over Burgers vector :math:`h/b > 0` (Eq 15; default 1, as in the paper).
    friction : FrictionLaw, optional
        Single-asperity friction law (default: Hurtado-Kim; it does not change the force).
    heights : HeightDistribution or str
        Asperity heights (default: ``Gaussian()``, Eq 19); or a spec string (``'weibull:skew=0.5'``,
        :func:`asperity.heights.parse_heights`).
    d_max : float, optional
        Upper end of the search, :math:`0 < \bar d_{max} \le 30 - \bar u_{end}` (default:
        :math:`10 - \bar u_{end}`, 10 sigma beyond the end of the asperities' stable branch,
        where the force is a negligible remnant whatever the adhesion range).

    Returns
    -------
    PullOff
        ``force`` (:math:`|P|/(NGb^2) \ge 0`), ``d`` (:math:`d/\sigma` of the most tensile
        force, NaN if none) and ``exists`` (False when the force stays compressive).

    Raises
    ------
    ValueError
        If a parameter or ``d_max`` is out of its range.

    Examples
    --------
    >>> po = pull_off(0.003, 1000.0, 1e-3)
    >>> po.exists, round(po.force, 1)  # Table 1 prints 320.1
    (True, 320.1)

    References
    ----------
    Adams et al., Eq (18), Table 1, Fig 7.
    """
    return Model(alpha, beta, gamma, nu=nu, h_over_b=h_over_b, friction=friction,
                 heights=heights).pull_off(d_max)
