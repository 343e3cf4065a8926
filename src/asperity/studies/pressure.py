r"""Fig 9: the mean contact pressure :math:`P/E^*A` versus the normal load.

Same five :math:`(\alpha, \beta)` cases as Figs 7-8 (:data:`~asperity.studies.separation.CASES`),
with (:math:`\gamma = 10^{-3}`, solid) and without (dashed) adhesion.
"""

from __future__ import annotations

import math

import numpy as np

from ._common import (
    COLOURS,
    Check,
    FigureData,
    adhesion_legend,
    check_data,
    drawing,
    load_series,
    log_decades_limits,
    new_figure,
    paired_curves,
    params_text,
)
from .separation import CASES, CASES_PARAMETERS, GAMMA

__all__ = ["fig9_data", "fig9_draw", "fig9_checks"]

FIG9_P = np.logspace(-2, 6, 81)

FIG9_PARAMETERS = CASES_PARAMETERS + (
    "The same cases as Figs 7-8, since the paper describes all three with the same words ('various "
    "values of alpha and beta, with gamma = 1e-3'); each with adhesion (solid) and without (dashed, same "
    "colour). P from 1e-2 to 1e6 (81 loads), the load range of Figs 4-6.")


def fig9_data() -> FigureData:
    series = []
    for a, b in CASES:
        label = params_text(alpha=a, beta=b)
        series.append(load_series(a, b, GAMMA, FIG9_P, label=label))
        series.append(load_series(a, b, 0.0, FIG9_P, label=label + ", γ = 0"))
    return FigureData(
        9, "Mean contact pressure vs normal load", "P", "pressure", tuple(series),
        caption=("Mean contact pressure P/(E* A) against normal load for several alpha and beta, with "
                 "adhesion (gamma = 1e-3, h = b, solid) and without (dashed)."),
        parameters=FIG9_PARAMETERS)


@drawing
def fig9_draw(data: FigureData):
    """Fig 9: P/(E* A) against P, log-log; solid with adhesion, dashed without."""
    fig, ax = new_figure()
    colour = dict(zip(CASES, COLOURS, strict=False))
    paired_curves(ax, data, "P", "pressure", lambda s: colour[(s.alpha, s.beta)])
    ax.set_xlabel(r"normal load  $\bar P = P/NGb^2$")
    ax.set_ylabel(r"mean contact pressure  $P/E^*A$")
    ax.set_xlim(FIG9_P[0], FIG9_P[-1])
    ax.set_ylim(*log_decades_limits([s.column("pressure") for s in data.series], 0.1))
    adhesion_legend(ax, GAMMA, loc="lower right")
    return fig


def fig9_checks(data: FigureData) -> list[Check]:
    data = check_data(data, 9)
    adh = {(s.alpha, s.beta): s.column("pressure") for s in data.series if s.adhesion}
    dry = {(s.alpha, s.beta): s.column("pressure") for s in data.series if not s.adhesion}
    lowers = {case: bool(np.all(adh[case] < dry[case])) for case in CASES}
    red = {case: float(np.min(adh[case] / dry[case])) for case in CASES}
    c_adh = all(lowers.values())
    # alpha ordering at beta = 1e3
    alphas = sorted(a for a, b in CASES if b == 1e3)
    ordered = {name: bool(np.all(np.diff(np.array([p[(a, 1e3)] for a in alphas]), axis=0) > 0))
               for name, p in (("with adhesion", adh), ("without", dry))}
    # sensitivity: d log p / d log alpha versus d log p / d log beta
    def exponents(p):
        ea = np.log10(p[(0.02, 1e3)] / p[(0.01, 1e3)]) / math.log10(2.0)
        eb = np.log10(p[(0.01, 1e4)] / p[(0.01, 1e3)])
        return ea, eb
    ea, eb = exponents(adh)
    ea0, eb0 = exponents(dry)
    c_sens = bool(np.all(np.abs(ea) > np.abs(eb)) and np.all(np.abs(ea0) > np.abs(eb0)))
    # how much the pressure changes over the loads: decades of pressure per decade of load
    span = math.log10(FIG9_P[-1] / FIG9_P[0])
    slope = {(case, kind): float(np.log10(p[case].max() / p[case].min()) / span)
             for kind, p in (("adhesive", adh), ("no adhesion", dry)) for case in CASES}
    worst = max(slope, key=slope.get)
    c_small = max(slope.values()) <= 0.25
    slope_text = "; ".join(f"({a:g}, {b:g}) {kind}: {v:.2f}" for ((a, b), kind), v in slope.items())
    return [
        Check("adhesion reduces the mean contact pressure (larger real area for a given load)", c_adh,
              "with/without adhesion pressure ratio, smallest over the loads: "
              + "; ".join(f"({a:g}, {b:g}): {red[(a, b)]:.3g}" for a, b in CASES)
              + f"; lower at every load for every case: {c_adh}"),
        Check("lower alpha (smoother surfaces) gives lower contact pressure", all(ordered.values()),
              f"at beta = 1e3, pressure increases with alpha = {', '.join(f'{a:g}' for a in alphas)} at every "
              f"load: with adhesion {ordered['with adhesion']}, without {ordered['without']}"),
        Check("the pressure is more sensitive to alpha than to beta", c_sens,
              f"d log p / d log alpha (alpha 0.01 -> 0.02, beta = 1e3) = {ea.min():.2f} to {ea.max():.2f} with "
              f"adhesion, {ea0.min():.2f} to {ea0.max():.2f} without; d log p / d log beta (1e3 -> 1e4, alpha = "
              f"0.01) = {eb.min():.2f} to {eb.max():.2f} with adhesion, {eb0.min():.2f} to {eb0.max():.2f} "
              "without"),
        Check("the pressure changes relatively little while the load varies over several orders of magnitude",
              c_small,
              f"decades of pressure per decade of load over P = {FIG9_P[0]:g} to {FIG9_P[-1]:g} (accepted: at "
              f"most 0.25 for every curve): {slope_text}. Largest: ({worst[0][0]:g}, {worst[0][1]:g}) "
              f"{worst[1]}; with adhesion the real area stays finite as the load goes to zero, so P/(E*A) falls "
              "towards zero at low loads wherever adhesion is strong."),
    ]
