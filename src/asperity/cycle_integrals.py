r"""Multi-asperity integrals on the approach and retraction branches of a loading cycle.

The paper's integrals (Eqs 5, 6, 10, 18, 21) count every asperity down to the end of its
stable Maugis-Dugdale branch, :math:`\bar u \ge \bar u_{end}`: that is the surface pulled
away after full contact.  An experiment is a cycle (Fuller & Tabor 1975).  With
:math:`\bar u = \bar z - \bar d` the penetration of an asperity of height :math:`\bar z`,
:math:`\bar u_{end} < 0` the end of its stable branch and :math:`\bar u_{in}`
(:math:`\bar u_{end} \le \bar u_{in} \le 0`, default 0: first touch) the penetration at
which an approaching asperity jumps into contact:

* **approach** to :math:`\bar d`: the asperities with :math:`\bar u \ge \bar u_{in}` touch,

  .. math:: S^{app}(\bar d) = \int_{\bar u_{in}}^\infty q(\bar u)\,\phi(\bar d + \bar u)\,d\bar u;

* **retraction** to :math:`\bar d \ge \bar d_{min}` after the closest approach
  :math:`\bar d_{min}`: the asperities that touched (:math:`\bar z \ge \bar d_{min} + \bar u_{in}`)
  and have not snapped off (:math:`\bar u \ge \bar u_{end}`),

  .. math::
      S^{ret}(\bar d; \bar d_{min}) = \int_{\bar u_c}^\infty q\,\phi(\bar d + \bar u)\,d\bar u,
      \qquad \bar u_c = \max(\bar u_{end},\ \bar u_{in} + \bar d_{min} - \bar d),

  which is :math:`S^{app}(\bar d) + \int_{\bar u_c}^{\bar u_{in}} q\,\phi\,d\bar u` in the
  *transition zone* :math:`\bar d < \bar d_{min} + \bar u_{in} - \bar u_{end}` and the paper's
  curve beyond it;
* **loop integrals** over a cycle :math:`\bar d_{max} \to \bar d_{min} \to \bar d_{max}`
  (exchanging the order of integration, :math:`\bar\Phi` the survival function of the heights):

  .. math::
      L = \int_{\bar d_{min}}^{\bar d_{max}} (S^{ret} - S^{app})\,d\bar d
        = \int_{\bar u_c(\bar d_{max})}^{\bar u_{in}} q(\bar u)\,
          \big[\bar\Phi(\bar d_{min} + \bar u_{in}) - \bar\Phi(\bar d_{max} + \bar u)\big]\,d\bar u,

  the bracket counting the asperities that touched and pass through penetration
  :math:`\bar u` while stuck on retraction.  For the force column, :math:`-L` is the energy
  dissipated per cycle.

:math:`q` is each of the columns (1, :math:`\bar P`, :math:`\bar F`, :math:`\bar a^2`) of the
per-asperity law (a :class:`~asperity.asperity_law.ContactLaw`).  The approach integrals are a
:class:`~asperity.tabulation.Tabulation` of the law cut off at :math:`\bar u_{in}`
(:class:`ApproachLaw`: the fast path and :mod:`asperity.load_control` apply unchanged); the
paper's integrals come from the :class:`~asperity.curves.Model`; the band
:math:`[\bar u_c, \bar u_{in}]` is integrated on fixed Gauss-Legendre panels over
:math:`[\bar u_{end}, \bar u_{in}]` (:class:`LoopBand`, first panel in :math:`s` with
:math:`\bar u = \bar u_{end} + s^4`, which makes the branch end's square or fourth root
analytic), the panel cut by the moving limit on fresh nodes.

References
----------
.. [1] K. N. G. Fuller, D. Tabor, Proc. R. Soc. A 345 (1975) 327.
.. [2] Adams et al., Eqs (5), (6), (10), (18), (21).
.. [3] J. A. Greenwood, Tribol. Lett. 65 (2017) 159 (review of Fuller-Tabor hysteresis).
"""

from __future__ import annotations

import math

import numpy as np

from .curves import Model
from .cycle_band import ApproachLaw, LoopBand, check_u_in, law_columns
from .tabulation import D_MAX, Tabulation

__all__ = ["ApproachLaw", "LoopBand", "CycleIntegrals", "law_columns", "check_u_in"]


class CycleIntegrals:
    r"""The approach, retraction and loop integrals of one parameter set, with cached tables.

    Parameters
    ----------
    model : Model
        The parameter set (its law, heights and cached tabulation of the paper's integrals).
    u_in : float
        Jump-in penetration :math:`\bar u_{in}` in :math:`\sigma`, in ``[u_end, 0]`` (default 0,
        first touch; ``u_end`` gives the paper's hysteresis-free reading).

    Attributes
    ----------
    u_end, u_in : float
        End of the stable branch and jump-in penetration (:math:`\sigma`).
    reach : float
        :math:`\bar u_{in} - \bar u_{end} \ge 0`: width of the transition zone of retraction.
    band : LoopBand
        The law on :math:`[\bar u_{end}, \bar u_{in}]`.

    Raises
    ------
    ValueError
        If ``model`` is not a :class:`~asperity.curves.Model` or ``u_in`` is out of range.
    """

    def __init__(self, model: Model, u_in=0.0):
        if not isinstance(model, Model):
            raise ValueError(f"model must be an asperity.Model, got {type(model).__name__}")
        self.model = model
        self.params = model.params
        self.heights = model.heights
        self.law = model.law
        self.u_end = float(self.law.u_end)
        self.u_in = check_u_in(u_in, self.u_end)
        self.reach = self.u_in - self.u_end
        self.band = LoopBand(self.law, self.u_in, self.heights)
        self.approach_law = ApproachLaw(self.law, self.u_in) if self.reach > 0 else self.law
        self._tab_app: Tabulation | None = None

    # -- tables ---------------------------------------------------------------------------
    def paper_tab(self, d_lo: float, d_hi: float) -> Tabulation:
        """The model's tabulation of the paper's integrals, serving [d_lo, d_hi]."""
        return self.model.tabulation(d_lo, d_hi)

    @property
    def approach_top(self) -> float:
        """Largest separation of the approach tabulation, :data:`~asperity.tabulation.D_MAX` minus
        the approach law's end.  Beyond it the approach sums are taken as 0: only summits
        higher than :data:`~asperity.tabulation.D_MAX` standard deviations touch there, a
        share below :math:`e^{-31}` even for the exponential's heavy tail (the Gaussian's is
        :math:`10^{-198}`), as every curve of the model neglects them."""
        return D_MAX - float(self.approach_law.u_end)

    def approach_tab(self, d_lo: float, d_hi: float) -> Tabulation:
        """A tabulation of :class:`ApproachLaw` serving [d_lo, d_hi] (cached, widened as needed),
        cut at :attr:`approach_top`."""
        d_hi = min(d_hi, self.approach_top)
        d_lo = min(d_lo, d_hi)
        if self.reach == 0.0:
            return self.paper_tab(d_lo, d_hi)
        if self._tab_app is None:
            self._tab_app = Tabulation(self.params, d_lo, d_hi, self.heights, law=self.approach_law)
        else:
            self._tab_app = self._tab_app.extended(d_lo, d_hi)
        return self._tab_app

    def set_approach_tab(self, tab: Tabulation) -> None:
        """Keep ``tab`` (a widened approach tabulation returned by :mod:`asperity.load_control`)."""
        if self.reach == 0.0:
            self.model.tabulation(tab.d_min, tab.d_max)
        else:
            self._tab_app = tab

    # -- sums -----------------------------------------------------------------------------
    def approach_sums(self, d, order: int = 0):
        """``[S_0, .., S_order]`` on approach at separations ``d`` (1-D): shape (n, 4) each (0
        beyond :attr:`approach_top`, which a cycle's start may pass when the asperities' branch
        ends deep in tension)."""
        d = np.asarray(d, dtype=float).ravel()
        inside = d <= self.approach_top
        if inside.all():
            if d.size == 0:
                return [np.zeros((0, 4)) for _ in range(order + 1)]
            return self.approach_tab(float(d.min()), float(d.max())).sums(d, order)
        out = [np.zeros((d.size, 4)) for _ in range(order + 1)]
        if inside.any():
            for o, part in zip(out, self.approach_sums(d[inside], order), strict=True):
                o[inside] = part
        return out

    def paper_sums(self, d, order: int = 0):
        """``[S_0, .., S_order]`` of the paper's integrals (Eq 18's lower limit) at ``d``."""
        d = np.asarray(d, dtype=float).ravel()
        if d.size == 0:
            return [np.zeros((0, 4)) for _ in range(order + 1)]
        return self.paper_tab(float(d.min()), float(d.max())).sums(d, order)

    def zone_sums(self, d, d_min, order: int = 0):
        r"""Retraction sums by the transition-zone formula, valid for :math:`0 \le d - d_{min} \le` reach.

        :math:`S^{app} + \int_{u_c}^{u_{in}} q\phi`, and for ``order`` 1 the derivative
        :math:`\int_{u_c}^\infty q\phi' + q(u_c)\phi(\bar d_{min} + \bar u_{in})` (the lower limit
        moves with :math:`\bar d`).  At ``d - d_min = reach`` this is the left-hand derivative at
        the kink where the transition zone ends.
        """
        if order > 1:
            raise ValueError(f"order must be 0 or 1, got {order}")
        d, d_min = (np.asarray(x, dtype=float).ravel() for x in np.broadcast_arrays(d, d_min))
        u_c = np.clip(self.u_in - (d - d_min), self.u_end, self.u_in)
        app = self.approach_sums(d, order)
        *band, q_c = self.band.sums(d, u_c, order, edge=True) if order else (*self.band.sums(d, u_c), None)
        out = [a + b for a, b in zip(app, band, strict=True)]
        if order == 1 and self.reach > 0:
            # where d_min + u_in is at or below the lowest summit, the band starts at the edge,
            # whose motion the band's slope holds (the density's value there is no limit)
            z = d_min + self.u_in
            rho = np.where(z > float(self.heights.support[0]), self.heights.pdf(z), 0.0)
            out[1] = out[1] + q_c * rho[:, None]
        return out

    def retract_sums(self, d, d_min, order: int = 0):
        r"""``[S_0, .., S_order]`` on retraction to ``d`` after the closest approach ``d_min``.

        ``d`` and ``d_min`` broadcast (1-D after), ``d >= d_min``; the paper's integrals beyond
        the transition zone, :meth:`zone_sums` inside it.  ``order`` 0 or 1.
        """
        d, d_min = (np.asarray(x, dtype=float).ravel() for x in np.broadcast_arrays(d, d_min))
        out = [np.zeros((d.size, 4)) for _ in range(order + 1)]
        zone = (d - d_min) < self.reach
        for rows, parts in ((~zone, lambda r: self.paper_sums(d[r], order)),
                            (zone, lambda r: self.zone_sums(d[r], d_min[r], order))):
            if np.any(rows):
                for o, part in zip(out, parts(rows), strict=True):
                    o[rows] = part
        return out

    def loop(self, d_min, d_max: float):
        """Loop integrals of the cycle ``d_max -> d_min -> d_max``: :meth:`LoopBand.loop`."""
        return self.band.loop(d_min, d_max)

    def loop_energy(self) -> float:
        """Energy one asperity dissipates through the whole loop (:meth:`LoopBand.loop_energy`)."""
        return self.band.loop_energy()

    def loop_fraction(self, d_min, d_max: float):
        r"""Fraction of asperities through the whole loop: touched on approach
        (:math:`\bar z \ge \bar d_{min} + \bar u_{in}`) and snapped off on retraction
        (:math:`\bar z \le \bar d_{max} + \bar u_{end}`); 0 without hysteresis."""
        d_min = np.asarray(d_min, dtype=float)
        if self.reach == 0.0:
            return np.zeros_like(d_min)
        sf = self.heights.sf
        return np.maximum(sf(d_min + self.u_in) - sf(d_max + self.u_end), 0.0)


def chebyshev_points(m: int):
    """``m`` points on [0, 1] clustered at both ends (Chebyshev-Lobatto), from 0 to 1."""
    k = np.arange(m)
    return 0.5 * (1.0 - np.cos(math.pi * k / (m - 1)))
