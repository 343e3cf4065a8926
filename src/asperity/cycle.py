r"""Approach and retract: loading-unloading hysteresis, energy dissipated, pull-off against preload.

The paper's force (Eq 18) counts every asperity down to the end of its stable branch: the
surface pulled away after full contact.  An experiment (AFM colloidal probe, SFA, MEMS
stiction test) is a cycle :math:`\bar d_{max} \to \bar d_{min} \to \bar d_{max}`.  On approach an
asperity carries nothing until it touches (penetration :math:`\bar u_{in}`, default 0); on
retraction it stays stuck, tensile, until its branch ends at :math:`\bar u_{end} < 0`.  The
two curves differ (Fuller & Tabor 1975, here with Maugis-Dugdale asperities), the loop between
them is energy dissipated, and the pull-off force on retraction grows with the preload until
it reaches the paper's (Table 1).  The integrals are in :mod:`asperity.cycle_integrals`, the
searches in :mod:`asperity.cycle_search`, the instrument's spring in :mod:`asperity.instrument`,
the algorithms on cached integrals in :mod:`asperity.cycle_run` and the results in
:mod:`asperity.cycle_result`.

* :func:`cycle`: one cycle (from a closest approach ``d_min`` or a ``preload``), with the
  approach and retract curves, the pull-off on retraction, the energy dissipated, the friction
  hysteresis and, with a finite ``stiffness``, the measured curve with its jumps.
* :func:`preload_curve`: pull-off force and energy dissipated against preload, in one call.

The module itself is callable: ``asperity.cycle(alpha, beta, gamma, d_min=...)`` is
:func:`cycle` (``from asperity.cycle import cycle`` works as well).

Everything is per asperity and dimensionless as in :mod:`asperity.curves`: forces in
:math:`NGb^2`, separations in :math:`\sigma`, energies in :math:`NGb^2\sigma`.

References
----------
.. [1] K. N. G. Fuller, D. Tabor, Proc. R. Soc. A 345 (1975) 327.
.. [2] D. Maugis, J. Colloid Interface Sci. 150 (1992) 243; D. Maugis, Contact, Adhesion and
   Rupture of Elastic Solids, Springer (2000).
.. [3] K. L. Johnson, J. A. Greenwood, J. Colloid Interface Sci. 192 (1997) 326.
.. [4] J. A. Greenwood, Tribol. Lett. 65 (2017) 159.
.. [5] Adams et al., Eqs (6), (10), (18), (21), Table 1.
"""

from __future__ import annotations

import math
import sys
import types

from .asperity_law import ContactLaw
from .curves import Model
from .cycle_integrals import CycleIntegrals
from .cycle_result import BranchCurve, CycleResult, PreloadCurve
from .cycle_run import MAX_POINTS, compute_cycle, compute_preload_curve
from .heights import GAUSSIAN

__all__ = ["BranchCurve", "CycleResult", "PreloadCurve", "cycle", "preload_curve", "compute_cycle",
           "compute_preload_curve", "CycleIntegrals", "MAX_POINTS"]


def cycle(alpha, beta, gamma=0.0, *, d_min=None, preload=None, d_max=None, d=None, n=200, stiffness=math.inf,
          u_in=0.0, nu=0.3, h_over_b=1.0, friction=None, heights=GAUSSIAN,
          law: ContactLaw | None = None) -> CycleResult:
    r"""One approach-retract cycle :math:`\bar d_{max} \to \bar d_{min} \to \bar d_{max}`: curves, pull-off, energy.

    With :math:`\bar u = \bar z - \bar d` (:mod:`asperity.cycle_integrals`): on approach the
    asperities with :math:`\bar u \ge \bar u_{in}` touch; on retraction those that touched
    (:math:`\bar z \ge \bar d_{min} + \bar u_{in}`) and have :math:`\bar u \ge \bar u_{end}`.

    .. math::
        \bar P^{app}(\bar d) = \int_{\bar u_{in}}^\infty\bar P(\bar u)\phi\,d\bar u,\quad
        \bar P^{ret}(\bar d) = \int_{\max(\bar u_{end},\,\bar u_{in}+\bar d_{min}-\bar d)}^\infty
            \bar P(\bar u)\phi\,d\bar u,\quad
        E = \int_{\bar d_{min}}^{\bar d_{max}}(\bar P^{app} - \bar P^{ret})\,d\bar d

    (and the same for F, area, contacts).  With a spring of stiffness :math:`\bar k` the measured
    curve is the force against the base displacement :math:`\bar Z = \bar d - \bar P/\bar k`, with
    whole-surface jumps where :math:`d\bar P/d\bar d > \bar k` (:mod:`asperity.instrument`).

    Parameters
    ----------
    alpha, beta : float
        Roughness :math:`\alpha = (\sigma/R)^{1/2} > 0` and friction regime parameter
        :math:`\beta = (R\sigma)^{1/2}/b > 0` (Eq 7).
    gamma : float
        Adhesion parameter :math:`\gamma = w/(E^*b) \ge 0` (Eq 16); 0 (Hertz): no hysteresis.
    d_min : float, optional
        Closest approach :math:`d/\sigma`, in :math:`[-10^4, \bar d_{max})`.
    preload : float, optional
        Largest compressive load :math:`P/(NGb^2) > 0`, reached at the closest approach (on the
        approach branch).  Give exactly one of ``d_min`` and ``preload``.
    d_max : float, optional
        Start and end of the cycle, :math:`d/\sigma` (default: 10 beyond the end of the stable
        branch, :math:`10 - \bar u_{end}`, where every asperity's loop is closed), at most
        :math:`30 - \bar u_{end}`.
    d : array_like, optional
        Separations in :math:`[\bar d_{min}, \bar d_{max}]` at which to evaluate both branches
        instead of the path (displacement control only).
    n : int
        Points per branch on the path (default 200, at least a quarter of them in the transition
        zone :math:`[\bar d_{min}, \bar d_{min} + \bar u_{in} - \bar u_{end}]`).
    stiffness : float
        Instrument spring :math:`\bar k = k\sigma/(NGb^2) > 0`; ``inf`` (default): displacement control.
    u_in : float
        Penetration :math:`\bar u_{in}` in :math:`[\bar u_{end}, 0]` at which an approaching asperity
        jumps into contact (default 0: first touch; :math:`\bar u_{end}` gives the paper's
        hysteresis-free reading).
    nu : float
        Poisson's ratio, -1 < nu < 0.5 (default 0.3; the paper does not state it).
    h_over_b : float
        Dugdale range over Burgers vector :math:`h/b > 0` (Eq 15; default 1).
    friction : FrictionLaw, optional
        Single-asperity friction law (default: Hurtado-Kim with the paper's constants).
    heights : HeightDistribution or str
        Asperity heights (default: ``Gaussian()``, Eq 19); or a spec string (``'weibull:skew=0.5'``,
        :func:`asperity.heights.parse_heights`).
    law : ContactLaw, optional
        Per-asperity law built for these parameters (default: ``AsperityLaw``).

    Returns
    -------
    CycleResult
        ``approach`` and ``retract`` curves (all the columns of a curve, ``d_base``, ``jump``),
        ``pull_off`` on retraction, ``energy`` (:math:`NGb^2\sigma`), ``loop_energy``,
        ``loop_fraction``, ``jump_energy``, ``friction_hysteresis``, ``friction_zero_load``, ``jumps``.

    Raises
    ------
    ValueError
        If a parameter is out of its range: ``d_min`` not below ``d_max``, a non-positive or
        non-numeric ``stiffness``, a ``preload`` that is not compressive or needs a separation
        beyond the model's domain, ``u_in`` outside :math:`[\bar u_{end}, 0]`, both or neither
        of ``d_min`` and ``preload``, ``d`` outside :math:`[\bar d_{min}, \bar d_{max}]` or with a
        finite stiffness, or a ``d_min`` inside a jump of the spring.

    Examples
    --------
    >>> c = cycle(0.01, 1000.0, 1e-3, d_min=0.0, n=50)
    >>> bool(c.energy > 0), bool(c.retract.P[-1] <= c.approach.P[0] + 1e-12), c.pull_off.exists
    (True, True, True)

    References
    ----------
    Fuller & Tabor (1975); Maugis (1992); Johnson & Greenwood (1997); Greenwood (2017);
    Adams et al., Eqs (6), (10), (18), (21).
    """
    model = Model(alpha, beta, gamma, nu=nu, h_over_b=h_over_b, friction=friction, heights=heights, law=law)
    return compute_cycle(CycleIntegrals(model, u_in), d_min=d_min, preload=preload, d_max=d_max, d=d, n=n,
                         stiffness=stiffness)


def preload_curve(preload, alpha, beta, gamma=0.0, *, d_max=None, u_in=0.0, nu=0.3, h_over_b=1.0, friction=None,
                  heights=GAUSSIAN, law: ContactLaw | None = None) -> PreloadCurve:
    r"""Pull-off force and energy dissipated against preload (displacement control), vectorised.

    For each preload :math:`P_{pre}` the closest approach :math:`\bar d_{min}` solves
    :math:`\bar P^{app}(\bar d_{min}) = P_{pre}`; then

    .. math::
        P_{off} = \max\Big(0, -\min_{\bar d_{min}\le\bar d\le\bar d_{max}}\bar P^{ret}(\bar d)\Big),\qquad
        E = -\int_{\bar u_c}^{\bar u_{in}}\bar P(\bar u)\big[\bar\Phi(\bar d_{min}+\bar u_{in})
            - \bar\Phi(\bar d_{max}+\bar u)\big]d\bar u,

    :math:`\bar u_c = \max(\bar u_{end}, \bar u_{in} - \bar d_{max} + \bar d_{min})`.  The pull-off
    rises from 0 and saturates at the paper's (:func:`asperity.pull_off`) once the preload pushes
    the whole transition zone below the paper's pull-off separation.

    Parameters
    ----------
    preload : array_like
        Preloads :math:`P/(NGb^2)`, finite and > 0; at most 10^6 of them.
    alpha, beta, gamma : float
        Model parameters (Eqs 7, 16).
    d_max : float, optional
        Start and end of each cycle, :math:`d/\sigma` (default :math:`10 - \bar u_{end}`).
    u_in : float
        Jump-in penetration in :math:`[\bar u_{end}, 0]` (default 0).
    nu : float
        Poisson's ratio, -1 < nu < 0.5 (default 0.3; the paper does not state it).
    h_over_b : float
        Dugdale range over Burgers vector :math:`h/b > 0` (Eq 15; default 1).
    friction : FrictionLaw, optional
        Single-asperity friction law (default: Hurtado-Kim with the paper's constants).
    heights : HeightDistribution or str
        Asperity heights (default: ``Gaussian()``, Eq 19); or a spec string (``'weibull:skew=0.5'``,
        :func:`asperity.heights.parse_heights`).
    law : ContactLaw, optional
        Per-asperity law built for these parameters (default: ``AsperityLaw``).

    Returns
    -------
    PreloadCurve
        ``preload``, ``d_min``, ``pull_off``, ``d_pull_off``, ``energy``, ``loop_fraction``,
        ``friction_hysteresis``, one per preload.

    Raises
    ------
    ValueError
        If a preload is not positive, is reached only beyond ``d_max``, or needs a separation
        below :math:`-10^4`; or a parameter is out of its range.

    Examples
    --------
    >>> pc = preload_curve([1.0, 1e3, 1e6], 0.003, 1000.0, 1e-3)
    >>> bool(pc.pull_off[0] <= pc.pull_off[1] <= pc.pull_off[2]), round(float(pc.pull_off[-1]), 1)
    (True, 320.1)

    References
    ----------
    Fuller & Tabor (1975); Greenwood (2017); Adams et al., Eq (18), Table 1.
    """
    model = Model(alpha, beta, gamma, nu=nu, h_over_b=h_over_b, friction=friction, heights=heights, law=law)
    return compute_preload_curve(CycleIntegrals(model, u_in), preload, d_max=d_max)


class _CallableModule(types.ModuleType):
    """This module, callable: ``asperity.cycle(...)`` is :func:`cycle` (the issue's spelling)."""

    def __call__(self, *args, **kwargs) -> CycleResult:
        return cycle(*args, **kwargs)


sys.modules[__name__].__class__ = _CallableModule
