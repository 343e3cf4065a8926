r"""Figs 3-6: the friction coefficient versus the normal load.

Fig 3 has no adhesion and plots :math:`\alpha\mu` against :math:`\bar P/\alpha`, which
depends on :math:`\beta` only.  Figs 4 and 5 keep those scaled coordinates (Fig 4 so that
one no-adhesion curve serves every :math:`\alpha`); Fig 6 plots :math:`\mu` against
:math:`\bar P` as the paper's text describes it.
"""

from __future__ import annotations

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
    ratio_text,
    visible_legend_entries,
)

__all__ = ["fig3_data", "fig3_draw", "fig3_checks", "fig4_data", "fig4_draw", "fig4_checks",
           "fig5_data", "fig5_draw", "fig5_checks", "fig6_data", "fig6_draw", "fig6_checks"]

#: The paper's defaults for Figs 4-6 ("unless otherwise specified").
ALPHA0, BETA0, GAMMA0 = 1e-2, 1e3, 1e-3

# -- Fig 3 ---------------------------------------------------------------------------------
FIG3_BETAS = (1e2, 1e3, 1e4, 1e5, 1e6)
FIG3_X = np.logspace(-2, 6, 81)  # P/alpha; the curves are smooth, 10 points a decade suffice

FIG3_PARAMETERS = (
    "gamma = 0 (no adhesion); beta = 1e2, 1e3, 1e4, 1e5, 1e6, the range the paper states; "
    "P/alpha from 1e-2 to 1e6 (81 log-spaced loads), eight decades over which the smallest-beta "
    "curve falls through the Hurtado-Kim transition. Without adhesion alpha*mu versus P/alpha "
    "does not depend on alpha (P scales with alpha, F not at all), so alpha = 0.01, the paper's "
    "default, is used for the computation (loads P = 0.01 * P/alpha).")


def fig3_data() -> FigureData:
    series = tuple(load_series(ALPHA0, b, 0.0, ALPHA0 * FIG3_X, label=params_text(beta=b))
                   for b in FIG3_BETAS)
    return FigureData(
        3, r"Scaled friction coefficient alpha*mu vs scaled load P/alpha, no adhesion", "P_over_alpha",
        "alpha_mu", series,
        caption=("Scaled friction coefficient against scaled normal load without adhesion "
                 "(gamma = 0) for friction regime parameters beta = 1e2 to 1e6."),
        parameters=FIG3_PARAMETERS)


@drawing
def fig3_draw(data: FigureData):
    """Fig 3: log-log alpha*mu against P/alpha, one curve per beta."""
    fig, ax = new_figure()
    for s, c in zip(data.series, COLOURS, strict=False):
        ax.loglog(s.column("P_over_alpha"), s.column("alpha_mu"), color=c, label=s.label)
    ax.set_xlabel(r"scaled normal load  $\bar P/\alpha$,  $\bar P = P/NGb^2$")
    ax.set_ylabel(r"scaled friction coefficient  $\alpha\mu$")
    ax.set_xlim(FIG3_X[0], FIG3_X[-1])
    ax.set_ylim(*log_decades_limits([s.column("alpha_mu") for s in data.series], 0.1))
    ax.legend(*visible_legend_entries(ax), title="γ = 0 (no adhesion)", loc="lower left")
    return fig


def fig3_checks(data: FigureData) -> list[Check]:
    data = check_data(data, 3)
    amu = np.array([s.column("alpha_mu") for s in data.series])  # rows: beta ascending
    x = data.series[0].column("P_over_alpha")
    low, high = amu[:, 0], amu[:, -1]
    ordered_low = bool(np.all(np.diff(low) < 0))
    # First load at which the ordering by beta fails, if any.
    ok = np.all(np.diff(amu, axis=0) < 0, axis=0)
    first_bad = x[np.argmin(ok)] if not ok.all() else None
    spread_low, spread_high = low.max() / low.min(), high.max() / high.min()
    drop = amu[:, 0] / amu[:, -1]  # how much each curve falls over the load range
    decreasing = bool(np.all(np.diff(amu, axis=1) < 0))
    checks = [
        Check("mu is higher for smaller beta", bool(ok.all()),
              f"at P/alpha = {x[0]:g}, alpha*mu = {ratio_text(low)} for beta = 1e2..1e6 (ordered: {ordered_low}). "
              + (f"The ordering holds for P/alpha below {first_bad:g} only; above it the beta = 1e2 curve falls "
                 f"below the beta = 1e3 curve (at P/alpha = {x[-1]:g}: {ratio_text(high)}). The paper does not "
                 "give its load range, so its curves may simply stop before they cross."
                 if first_bad is not None else "The ordering holds at every plotted load.")),
        Check("the difference between the betas is especially significant at low load",
              ordered_low and spread_low > spread_high,
              f"largest over smallest alpha*mu across beta: {spread_low:.3g} at P/alpha = {x[0]:g}, "
              f"{spread_high:.3g} at P/alpha = {x[-1]:g}"),
        Check("for high beta the friction coefficient depends less on the normal load",
              bool(np.all(np.diff(drop) < 0)),
              f"alpha*mu(lowest load)/alpha*mu(highest load) = {ratio_text(drop)} for beta = 1e2..1e6"),
        Check("the friction coefficient decreases with load (every curve)", decreasing,
              "alpha*mu is strictly decreasing along every curve" if decreasing
              else "some curve increases with load somewhere"),
    ]
    return checks


# -- Fig 4 ---------------------------------------------------------------------------------
FIG4_ALPHAS = (0.005, 0.01, 0.02, 0.06, 0.1)
FIG4_X = np.logspace(-2, 8, 101)  # P/alpha

FIG4_PARAMETERS = (
    "beta = 1e3, gamma = 1e-3, h = b (the paper's defaults for Figs 4-6); alpha = 0.005, 0.01, 0.02, "
    "0.06, 0.1, bracketing the two thresholds the text names (adhesion matters below about 0.06, "
    "strongly below 0.01); alpha = 0.002-0.004 (Table 1) would add curves 4-9 decades above the "
    "rest. Plotted in the scaled coordinates of Fig 3, alpha*mu vs P/alpha, because the paper "
    "compares every alpha with a single no-adhesion case and speaks of the curves approaching the "
    "same scaled coefficient of friction at high load: only in these coordinates is the "
    "no-adhesion curve (dashed, beta = 1e3) the same for all alpha. P/alpha from 1e-2 to 1e8 "
    "(101 loads), so that P reaches about 1e6 where the text says the curves converge.")


def fig4_data() -> FigureData:
    base = load_series(ALPHA0, BETA0, 0.0, ALPHA0 * FIG4_X,
                       label="no adhesion (γ = 0, any α)")
    series = [load_series(a, BETA0, GAMMA0, a * FIG4_X, label=params_text(alpha=a))
              for a in FIG4_ALPHAS]
    return FigureData(
        4, "Effect of the roughness parameter alpha with adhesion", "P_over_alpha", "alpha_mu",
        (*series, base),
        caption=("Scaled friction coefficient against scaled normal load with adhesion "
                 "(beta = 1e3, gamma = 1e-3, h = b) for several roughness parameters alpha (solid), and "
                 "without adhesion (dashed), which in these coordinates is one curve for every alpha. The "
                 "curves for alpha = 0.06 and 0.1 lie within a few per cent of the no-adhesion curve and are "
                 "hidden beneath it."),
        parameters=FIG4_PARAMETERS)


@drawing
def fig4_draw(data: FigureData):
    """Fig 4: alpha*mu against P/alpha for several alpha, with the no-adhesion curve dashed."""
    return _draw_family(data, "P_over_alpha", "alpha_mu", r"scaled normal load  $\bar P/\alpha$,  $\bar P = P/NGb^2$",
                        r"scaled friction coefficient  $\alpha\mu$", FIG4_X, params_text(beta=BETA0, gamma=GAMMA0))


def _draw_family(data: FigureData, x: str, y: str, xlabel: str, ylabel: str, xs, legend_title: str):
    """A log-log family of adhesive curves in colour and the no-adhesion baseline dashed."""
    fig, ax = new_figure()
    colours = iter(COLOURS)
    for s in data.series:
        style = {"color": next(colours)} if s.adhesion else {"color": "0.25", "ls": "--", "lw": 1.8}
        ax.loglog(s.column(x), s.column(y), label=s.label, **style)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.set_xlim(xs[0], xs[-1])
    ax.set_ylim(*log_decades_limits([s.column(y) for s in data.series], 0.15))
    ax.legend(*visible_legend_entries(ax), title=legend_title, loc="upper right")
    return fig


def _ratio_to(series, base) -> np.ndarray:
    """alpha*mu of an adhesive curve over the no-adhesion one, at the same plotted x."""
    return series.column("alpha_mu") / base.column("alpha_mu")


def fig4_checks(data: FigureData) -> list[Check]:
    data = check_data(data, 4)
    base = [s for s in data.series if not s.adhesion][0]
    adh = [s for s in data.series if s.adhesion]
    dev = {s.alpha: float(np.max(np.abs(_ratio_to(s, base) - 1.0))) for s in adh}
    at_low = {s.alpha: float(_ratio_to(s, base)[0]) for s in adh}
    at_high = {s.alpha: float(_ratio_to(s, base)[-1]) for s in adh}
    threshold = 0.10
    small = [a for a in dev if a >= 0.06]
    large = [a for a in dev if a < 0.06]
    c1 = all(dev[a] < threshold for a in small) and all(dev[a] >= threshold for a in large)
    dev_text = "; ".join(f"alpha = {a:g}: {100 * v:.3g} %" for a, v in dev.items())
    a_lo, a_mid = min(at_low), 0.01
    growth = at_low[a_lo] / at_low[a_mid]
    highest = data.series[0].column("P_over_alpha")[-1]
    conv = max(abs(v - 1) for v in at_high.values())
    decreasing = all(bool(np.all(np.diff(s.column("alpha_mu")) < 0)) for s in data.series)
    return [
        Check("only for alpha below about 0.06 do the results differ from the case without adhesion",
              c1,
              f"largest change of alpha*mu by adhesion over the plotted loads (counted as a difference when "
              f"above {100 * threshold:g} %): {dev_text}"),
        Check("as alpha decreases below 0.01 the effect of adhesion increases significantly",
              growth > 10.0,
              f"at the lowest plotted load P/alpha = {FIG4_X[0]:g}, adhesion multiplies alpha*mu by "
              f"{at_low[a_mid]:.3g} for alpha = 0.01 and by {at_low[a_lo]:.3g} for alpha = {a_lo:g} "
              f"(counted as significant when more than 10 times larger)"),
        Check("at high load (P near 1e6) the curves approach the same scaled coefficient of friction",
              conv < 0.05,
              f"at P/alpha = {highest:g} (P = {highest * min(FIG4_ALPHAS):g} to {highest * max(FIG4_ALPHAS):g}) the "
              f"adhesive alpha*mu exceeds the no-adhesion value by at most {100 * conv:.2g} % "
              f"(threshold 5 %)"),
        Check("the friction coefficient decreases with the applied load (every curve)", decreasing,
              "alpha*mu is strictly decreasing along every curve" if decreasing
              else "some curve increases with load somewhere"),
    ]


# -- Fig 5 ---------------------------------------------------------------------------------
FIG5_BETAS = (1e2, 1e3, 1e4, 1e5)
FIG5_X = np.logspace(-2, 6, 81)  # P/alpha, as Fig 3

FIG5_PARAMETERS = (
    "alpha = 0.01, gamma = 1e-3 (solid) and gamma = 0 (dashed, same colour), h = b; beta = 1e2, 1e3, "
    "1e4, 1e5: one curve a decade across the range of Fig 3 (1e6 is left out: its adhesive and "
    "non-adhesive curves already coincide at 1e5, and eight curves are enough). Same scaled "
    "coordinates and loads as Fig 3 (P/alpha from 1e-2 to 1e6), since the paper says Figs 3-5 "
    "use the same scalings; with alpha fixed at 0.01 they differ from mu vs P only by a factor "
    "of 100 on each axis.")


def fig5_data() -> FigureData:
    series = []
    for b in FIG5_BETAS:
        series.append(load_series(ALPHA0, b, GAMMA0, ALPHA0 * FIG5_X, label=params_text(beta=b)))
        series.append(load_series(ALPHA0, b, 0.0, ALPHA0 * FIG5_X, label=params_text(beta=b, gamma=0.0)))
    return FigureData(
        5, "Effect of the friction regime parameter beta, with and without adhesion", "P_over_alpha",
        "alpha_mu", tuple(series),
        caption=("Scaled friction coefficient against scaled normal load for several beta "
                 "(alpha = 0.01): with adhesion (gamma = 1e-3, solid) and without (gamma = 0, dashed)."),
        parameters=FIG5_PARAMETERS)


@drawing
def fig5_draw(data: FigureData):
    """Fig 5: alpha*mu against P/alpha for several beta; solid with adhesion, dashed without."""
    fig, ax = new_figure()
    colour = dict(zip(FIG5_BETAS, COLOURS, strict=False))
    paired_curves(ax, data, "P_over_alpha", "alpha_mu", lambda s: colour[s.beta])
    ax.set_xlabel(r"scaled normal load  $\bar P/\alpha$,  $\bar P = P/NGb^2$")
    ax.set_ylabel(r"scaled friction coefficient  $\alpha\mu$")
    ax.set_xlim(FIG5_X[0], FIG5_X[-1])
    ax.set_ylim(*log_decades_limits([s.column("alpha_mu") for s in data.series], 0.15))
    adhesion_legend(ax, GAMMA0, title=params_text(alpha=ALPHA0), loc="upper right")
    return fig


def fig5_checks(data: FigureData) -> list[Check]:
    data = check_data(data, 5)
    adh = {s.beta: s for s in data.series if s.adhesion}
    dry = {s.beta: s for s in data.series if not s.adhesion}
    betas = sorted(adh)
    x = adh[betas[0]].column("P_over_alpha")
    amu = np.array([adh[b].column("alpha_mu") for b in betas])
    ratio = np.array([adh[b].column("alpha_mu") / dry[b].column("alpha_mu") for b in betas])
    ok = np.all(np.diff(amu, axis=0) < 0, axis=0)
    first_bad = x[np.argmin(ok)] if not ok.all() else None
    c_order = bool(ok[0])
    c_increase = bool(np.all(ratio >= 1.0))
    c_beta = bool(np.all(np.diff(ratio[:, 0]) < 0))
    c_load = bool(np.all(np.diff(ratio, axis=1) <= 0))
    hi_b = betas[-1]
    c_high_beta = float(ratio[-1].max()) < 1.10
    spread_hi = amu[:, -1].max() / amu[:, -1].min()
    spread_lo = amu[:, 0].max() / amu[:, 0].min()
    adh_hi = float(ratio[:, -1].max())
    decreasing = all(bool(np.all(np.diff(s.column("alpha_mu")) < 0)) for s in data.series)
    return [
        Check("lower beta gives a higher coefficient of friction", first_bad is None,
              f"at P/alpha = {x[0]:g}: alpha*mu = {ratio_text(amu[:, 0])} for beta = "
              f"{', '.join(f'{b:g}' for b in betas)} (ordered: {c_order}). "
              + (f"The ordering holds only for P/alpha below {first_bad:g}; above it beta = 1e2 falls below "
                 f"beta = 1e3 (at P/alpha = {x[-1]:g}: {ratio_text(amu[:, -1])}), as in Fig 3."
                 if first_bad is not None else "The ordering holds at every plotted load.")),
        Check("adhesion increases the friction coefficient, most for low beta and low load",
              c_increase and c_beta and c_load,
              f"mu(with)/mu(without) at the lowest load = {ratio_text(ratio[:, 0])} and at the highest load = "
              f"{ratio_text(ratio[:, -1])} for beta = {', '.join(f'{b:g}' for b in betas)}; ratio >= 1 "
              f"everywhere: {c_increase}; falls with beta: {c_beta}; falls with load: {c_load}"),
        Check("for high beta mu is nearly independent of adhesion and less sensitive to load",
              c_high_beta and bool((amu[-1, 0] / amu[-1, -1]) < (amu[0, 0] / amu[0, -1])),
              f"beta = {hi_b:g}: adhesion changes alpha*mu by at most {100 * (ratio[-1].max() - 1):.2g} % "
              f"(threshold 10 %); alpha*mu falls by a factor {amu[-1, 0] / amu[-1, -1]:.3g} over the loads, "
              f"against {amu[0, 0] / amu[0, -1]:.3g} for beta = {betas[0]:g}"),
        Check("a large normal force makes mu nearly independent of both adhesion and beta",
              adh_hi < 1.25 and spread_hi < 1.5,
              f"at P/alpha = {x[-1]:g}: adhesion raises alpha*mu by at most {100 * (adh_hi - 1):.3g} % "
              f"(threshold 25 %); alpha*mu across beta spans a factor {spread_hi:.3g} "
              f"(threshold 1.5; at the lowest load {spread_lo:.3g})"),
        Check("the friction coefficient decreases with the applied load (every curve)", decreasing,
              "alpha*mu is strictly decreasing along every curve" if decreasing
              else "some curve increases with load somewhere"),
    ]


# -- Fig 6 ---------------------------------------------------------------------------------
FIG6_GAMMAS = (1e-4, 1e-3, 3e-3, 1e-2)
FIG6_P = np.logspace(-2, 6, 81)

FIG6_PARAMETERS = (
    "alpha = 0.01, beta = 1e3, h = b (the paper's defaults); gamma = 1e-4, 1e-3 (the default), 3e-3 and "
    "1e-2 (the largest value of Table 1), about one curve per half decade, plus gamma = 0 (dashed) "
    "as the no-adhesion baseline. Plotted as mu vs P, as the text describes Fig 6 (alpha is fixed, so "
    "the scaled plot would only shift the axes). P from 1e-2 to 1e6 (81 loads).")


def fig6_data() -> FigureData:
    series = [load_series(ALPHA0, BETA0, g, FIG6_P, label=params_text(gamma=g))
              for g in FIG6_GAMMAS]
    series.append(load_series(ALPHA0, BETA0, 0.0, FIG6_P, label="no adhesion, γ = 0"))
    return FigureData(
        6, "Effect of the adhesion parameter gamma", "P", "mu", tuple(series),
        caption=("Friction coefficient against normal load for several adhesion parameters gamma "
                 "(alpha = 0.01, beta = 1e3, h = b), and without adhesion (dashed); the gamma = 1e-4 curve "
                 "lies within 8 % of the dashed one."),
        parameters=FIG6_PARAMETERS)


@drawing
def fig6_draw(data: FigureData):
    """Fig 6: mu against P for several gamma, with the no-adhesion baseline dashed."""
    return _draw_family(data, "P", "mu", r"normal load  $\bar P = P/NGb^2$", r"friction coefficient  $\mu$",
                        FIG6_P, params_text(alpha=ALPHA0, beta=BETA0))


def fig6_checks(data: FigureData) -> list[Check]:
    data = check_data(data, 6)
    adh = sorted((s for s in data.series if s.adhesion), key=lambda s: s.gamma)
    base = [s for s in data.series if not s.adhesion][0]
    mu = np.array([base.column("mu")] + [s.column("mu") for s in adh])  # gamma ascending, 0 first
    ordered = np.all(np.diff(mu, axis=0) > 0, axis=0)
    rel = mu[1:] / mu[0]
    low_vs_high = rel[:, 0] / rel[:, -1]
    decreasing = all(bool(np.all(np.diff(s.column("mu")) < 0)) for s in data.series)
    gammas = ", ".join(f"{s.gamma:g}" for s in adh)
    return [
        Check("higher gamma gives a higher coefficient of friction, especially at low load",
              bool(ordered.all()) and bool(np.all(low_vs_high > 1.0)),
              f"mu increases with gamma at {int(ordered.sum())} of {ordered.size} loads; mu/mu(gamma = 0) = "
              f"{ratio_text(rel[:, 0])} at P = {FIG6_P[0]:g} and {ratio_text(rel[:, -1])} at P = {FIG6_P[-1]:g} "
              f"for gamma = {gammas}"),
        Check("the friction coefficient decreases with the applied load (every curve)", decreasing,
              "mu is strictly decreasing along every curve" if decreasing
              else "some curve increases with load somewhere"),
    ]
