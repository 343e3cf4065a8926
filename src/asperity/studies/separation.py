r"""Figs 7-8: the normal and the friction force versus the separation :math:`d/\sigma`.

Both figures show the same five :math:`(\alpha, \beta)` cases with :math:`\gamma = 10^{-3}`;
the Models are shared (see :func:`~asperity.studies._common.model`), so Fig 8 costs
almost nothing once Fig 7 is computed.
"""

from __future__ import annotations

import math

import numpy as np

from ._common import (
    COLOURS,
    Check,
    FigureData,
    check_data,
    drawing,
    log_decades_limits,
    model,
    new_figure,
    params_text,
    separation_series,
    visible_legend_entries,
)

__all__ = ["CASES", "fig7_data", "fig7_draw", "fig7_checks", "fig8_data", "fig8_draw", "fig8_checks"]

#: (alpha, beta) of the five curves of Figs 7-9; gamma = 1e-3 for all.
CASES = ((0.005, 1e3), (0.01, 1e3), (0.02, 1e3), (0.01, 1e4), (0.01, 1e5))
GAMMA = 1e-3
#: Separations d/sigma: a uniform grid, fine enough (0.01) to show the sign change of Fig 7.
D = np.linspace(0.0, 5.0, 501)

CASES_PARAMETERS = (
    "gamma = 1e-3, h = b; (alpha, beta) = (0.005, 1e3), (0.01, 1e3), (0.02, 1e3), (0.01, 1e4), (0.01, 1e5). "
    "The text names only alpha = 0.005, beta = 1e3 (the curve that turns tensile near d/sigma = 2.6) and "
    "says the other four stay compressive, that alpha changes the force nearly linearly and that a decade "
    "of beta changes it by about two decades. So alpha is doubled twice at beta = 1e3 and beta is raised "
    "by two decades at alpha = 0.01. beta = 1e2 and 3e2 were not used because Table 1 gives both a "
    "pull-off force at alpha = 0.01, gamma = 1e-3, which contradicts 'only alpha = 0.005, beta = 1000 "
    "gives a tensile force'. ")


def _label(alpha, beta):
    return params_text(alpha=alpha, beta=beta)


def _series():
    return tuple(separation_series(a, b, GAMMA, D, label=_label(a, b)) for a, b in CASES)


def _pull_offs():
    return {(a, b): model(a, b, GAMMA).pull_off() for a, b in CASES}


# -- Fig 7 ---------------------------------------------------------------------------------
FIG7_PARAMETERS = CASES_PARAMETERS + (
    "d/sigma from 0 to 5 in steps of 0.01, wide enough to show the pull-off peak of the tensile curve and "
    "its decay. As in the paper, where the force is tensile (P < 0) its negative is plotted (dashed, same "
    "colour); the dot marks the pull-off force.")


def fig7_data() -> FigureData:
    return FigureData(
        7, "Normal force vs separation", "d", "abs_P", _series(),
        caption=("Normal force against separation for several alpha and beta, with adhesion "
                 "(gamma = 1e-3, h = b). Where the force is tensile its magnitude -P is plotted, dashed; "
                 "the dot marks the pull-off force."),
        parameters=FIG7_PARAMETERS, extra={"pull_off": _pull_offs()})


def _split_by_sign(d, P):
    """Runs of equal sign of P: a list of (d, |P|, tensile) pieces."""
    pieces, start = [], 0
    sign = P < 0
    for i in range(1, P.size + 1):
        if i == P.size or sign[i] != sign[start]:
            pieces.append((d[start:i], np.abs(P[start:i]), bool(sign[start])))
            start = i
    return pieces


@drawing
def fig7_draw(data: FigureData):
    """Fig 7: |P| against d/sigma on a log axis; tensile parts dashed, pull-off marked."""
    from matplotlib.lines import Line2D

    fig, ax = new_figure()
    any_tensile = any_marker = False
    for s, c in zip(data.series, COLOURS, strict=False):
        for d, absP, tensile in _split_by_sign(s.curve.d, s.curve.P):
            any_tensile |= tensile
            ax.semilogy(d, absP, color=c, ls="--" if tensile else "-",
                        label=s.label if not tensile and d[0] == s.curve.d[0] else None)
        po = data.extra["pull_off"][(s.alpha, s.beta)]
        if po.exists and D[0] <= po.d <= D[-1]:
            ax.plot([po.d], [po.force], "o", color=c, ms=4.5)
            any_marker = True
    ax.set_xlabel(r"separation  $d/\sigma$")
    ax.set_ylabel(r"normal force  $\bar P = P/NGb^2$  (tensile: $-\bar P$)")
    ax.set_xlim(D[0], D[-1])
    ax.set_ylim(*log_decades_limits([np.abs(s.curve.P) for s in data.series], 0.3))
    handles, labels = visible_legend_entries(ax)
    if any_tensile:  # legend entries only for what is drawn
        handles.append(Line2D([], [], color="0.3", ls="--"))
        labels.append(r"tensile part ($\bar P < 0$): $-\bar P$ plotted")
    if any_marker:
        handles.append(Line2D([], [], color="0.3", ls="none", marker="o", ms=4.5))
        labels.append("pull-off force")
    ax.legend(handles, labels, title=params_text(gamma=GAMMA), loc="upper right")
    return fig


def _crossing(d, P):
    """Separations where P changes sign (linear interpolation)."""
    idx = np.flatnonzero(np.diff(np.sign(P)) != 0)
    return [float(d[i] - P[i] * (d[i + 1] - d[i]) / (P[i + 1] - P[i])) for i in idx]


def _index(d):
    """Index of the grid separation closest to ``d``."""
    return int(np.argmin(np.abs(D - d)))


def _exponent_text(e) -> str:
    return f"{e:.2f}" if np.isfinite(e) else "undefined (the force changes sign)"


def _decades(num, den):
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.log10(num / den)


def fig7_checks(data: FigureData) -> list[Check]:
    data = check_data(data, 7)
    po = data.extra["pull_off"]
    tensile = [(s.alpha, s.beta) for s in data.series if np.any(s.curve.P < 0)]
    only = tensile == [(0.005, 1e3)]
    po_text = "; ".join(
        f"({a:g}, {b:g}): " + (f"{p.force:.3g} at d/sigma = {p.d:.3g}" if p.exists else "none")
        for (a, b), p in po.items())
    others = [(a, b, p) for (a, b), p in po.items() if p.exists and (a, b) not in tensile and p.d > D[-1]]
    tail = "".join(
        f" ({a:g}, {b:g}) turns tensile only beyond the plotted range, and negligibly: at most {p.force:.2g} "
        f"at d/sigma = {p.d:.3g}."
        for a, b, p in others)
    s0 = data.find("alpha=0.005 beta=1000 gamma=0.001")
    cross = _crossing(s0.curve.d, s0.curve.P)
    near = len(cross) == 1 and abs(cross[0] - 2.6) <= 0.2
    # beta: a decade of beta at alpha = 0.01, over the compressive range d/sigma <= 3.
    sel = D <= 3.0
    b3, b4, b5 = (data.find(f"alpha=0.01 beta={b:g} gamma=0.001").curve.P for b in (1e3, 1e4, 1e5))
    r43, r54 = _decades(b4, b3)[sel], _decades(b5, b4)[sel]
    c_beta = bool(np.all((np.r_[r43, r54] >= 1.5) & (np.r_[r43, r54] <= 2.5)))
    # alpha: local exponent d log P / d log alpha at small separations (d/sigma <= 1).
    small = D <= 1.0
    a1, a2, a3 = (data.find(f"alpha={a:g} beta=1000 gamma=0.001").curve.P for a in (0.005, 0.01, 0.02))
    e12 = _decades(a2, a1)[small] / math.log10(2.0)
    e23 = _decades(a3, a2)[small] / math.log10(2.0)
    c_alpha = bool(np.all((np.r_[e12, e23] >= 0.8) & (np.r_[e12, e23] <= 1.25)))
    i3 = _index(3.0)
    e12_3, e23_3 = (_decades(a2, a1) / math.log10(2.0))[i3], (_decades(a3, a2) / math.log10(2.0))[i3]
    return [
        Check("of the five cases only alpha = 0.005, beta = 1000 gives a tensile force on separation",
              only,
              f"cases with P < 0 for d/sigma in [{D[0]:g}, {D[-1]:g}]: "
              f"{', '.join(f'({a:g}, {b:g})' for a, b in tensile) or 'none'}. Pull-off (largest tensile "
              f"force for d/sigma up to 10): {po_text}." + tail),
        Check("for alpha = 0.005, beta = 1000 the force changes sign at d/sigma of approximately 2.6",
              near,
              f"sign change(s) at d/sigma = {', '.join(f'{c:.3f}' for c in cross) or 'none'} "
              f"(accepted: 2.6 +- 0.2)"),
        Check("an order of magnitude increase in beta gives roughly two orders of magnitude more normal force",
              c_beta,
              f"at alpha = 0.01, for d/sigma in [0, 3]: log10 P(beta = 1e4)/P(1e3) = {r43.min():.2f} to "
              f"{r43.max():.2f}, log10 P(1e5)/P(1e4) = {r54.min():.2f} to {r54.max():.2f} "
              f"(accepted: 1.5 to 2.5 decades)"),
        Check("increasing alpha increases the normal force in a nearly linear manner",
              c_alpha,
              f"at beta = 1e3, for d/sigma in [0, 1]: exponent dlogP/dlog(alpha) = {e12.min():.2f} to "
              f"{e12.max():.2f} (alpha 0.005 -> 0.01) and {e23.min():.2f} to {e23.max():.2f} (0.01 -> 0.02), "
              f"accepted 0.8 to 1.25; at d/sigma = 3, where adhesion matters more: {_exponent_text(e12_3)} and "
              f"{_exponent_text(e23_3)}. Without adhesion the exponent is exactly 1 (P proportional to "
              "alpha beta^2); adhesion lowers the force most for the smallest alpha."),
    ]


# -- Fig 8 ---------------------------------------------------------------------------------
FIG8_PARAMETERS = CASES_PARAMETERS + "The same cases and separations as Fig 7 (d/sigma from 0 to 5)."


def fig8_data() -> FigureData:
    return FigureData(
        8, "Friction force vs separation", "d", "F", _series(),
        caption=("Friction force against separation for several alpha and beta, with adhesion "
                 "(gamma = 1e-3, h = b)."),
        parameters=FIG8_PARAMETERS)


@drawing
def fig8_draw(data: FigureData):
    """Fig 8: F against d/sigma on a log axis."""
    fig, ax = new_figure()
    for s, c in zip(data.series, COLOURS, strict=False):
        ax.semilogy(s.curve.d, s.curve.F, color=c, label=s.label)
    ax.set_xlabel(r"separation  $d/\sigma$")
    ax.set_ylabel(r"friction force  $\bar F = F/NGb^2$")
    ax.set_xlim(D[0], D[-1])
    ax.set_ylim(*log_decades_limits([s.curve.F for s in data.series], 0.3))
    ax.legend(*visible_legend_entries(ax), title=params_text(gamma=GAMMA), loc="upper right")
    return fig


def fig8_checks(data: FigureData) -> list[Check]:
    data = check_data(data, 8)
    sel = D <= 3.0
    b3, b4, b5 = (data.find(f"alpha=0.01 beta={b:g} gamma=0.001").curve.F for b in (1e3, 1e4, 1e5))
    r = np.r_[_decades(b4, b3)[sel], _decades(b5, b4)[sel]]
    c_beta = bool(np.all((r >= 1.7) & (r <= 2.3)))
    s1, s2 = (data.find(f"alpha={a:g} beta=1000 gamma=0.001") for a in (0.01, 0.02))
    fa = np.abs(_decades(s2.curve.F, s1.curve.F))
    pa = np.abs(_decades(s2.curve.P, s1.curve.P))
    i0, i3 = 0, _index(3.0)
    c_alpha = bool(np.all(fa[sel] < pa[sel])) and fa[i0] < fa[i3]
    return [
        Check("an order of magnitude increase in beta gives nearly two orders of magnitude more friction force",
              c_beta,
              f"at alpha = 0.01, for d/sigma in [0, 3]: log10 F ratio per decade of beta = {r.min():.2f} to "
              f"{r.max():.2f} (accepted: 1.7 to 2.3). Without adhesion, contacts in the Hurtado-Kim "
              "transition give F proportional to beta^(M+2) = beta^1.57 (M = -0.43), i.e. about 1.6 decades "
              "per decade of beta; 2 decades would need all contacts in the constant-stress regimes."),
        Check("alpha affects the friction force less than the normal force, especially at small separations",
              c_alpha,
              f"|log10 of the ratio alpha = 0.02 over 0.01| at beta = 1e3: for F {fa[i0]:.3f} at d/sigma = 0 "
              f"and {fa[i3]:.3f} at 3; for P {pa[i0]:.3f} and {pa[i3]:.3f}"),
    ]
