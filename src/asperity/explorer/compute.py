r"""From a view's :class:`~asperity.explorer.state.State` to the library's curves and numbers.

Everything the explorer shows comes from the public API, called as a user would:

* dimensionless mode: :class:`asperity.Model` (``alpha, beta, gamma, nu, h_over_b``, the
  Hurtado-Kim law :class:`asperity.HurtadoKim` and the height distribution), its
  :meth:`~asperity.Model.load_curve` at log-spaced loads :math:`P/(NGb^2)`,
  :meth:`~asperity.Model.separation_curve` at evenly spaced :math:`d/\sigma` and
  :meth:`~asperity.Model.pull_off`;
* physical mode: :class:`asperity.physical.PhysicalContact` of a material from the table
  (:func:`asperity.materials.material`) or typed (:class:`asperity.materials.Material`)
  on a :class:`asperity.surface.Surface`, with loads in newtons and separations
  :math:`d = \bar d\,\sigma_s` in metres;
* the derived numbers: :func:`asperity.groups.maugis_lambda` (Eq 15) or
  :attr:`PhysicalContact.lam`, :func:`asperity.regimes.adhesion_regime`,
  :func:`~asperity.regimes.tabor_parameter` (with :math:`z_0 = h`, the Dugdale range) and
  :func:`~asperity.regimes.fuller_tabor_parameter`.  In dimensionless mode these two take
  lengths in units of :math:`b` and stresses in units of :math:`E^*` (the surface of
  :func:`asperity.surface.surface_from_groups` with :math:`b = 1`), which leaves the
  dimensionless results unchanged.

:func:`compute` raises the library's :class:`ValueError` (or :class:`TypeError`) for an
invalid view, and returns every warning the library issues (among them
:class:`asperity.physical.AreaFractionWarning`: a real contact area above 10 % of the
nominal area), as text in :attr:`Result.warnings`.
The only checks made here are those of the explorer's own inputs: a load range of
positive loads for the log axes, increasing ranges.

Nothing here imports Bokeh.
"""

from __future__ import annotations

import math
import re
import warnings
from dataclasses import dataclass, field

import numpy as np

from .state import CUSTOM, ELASTIC, MODES, State, distributions
from .wording import page_wording

__all__ = ["Result", "compute", "caught_notes", "number_free",
           "height_distribution", "friction_law", "asperity_law", "model_gamma", "loads",
           "separations", "build_subject", "load_columns", "separation_columns", "pull_off_columns"]


@dataclass(frozen=True)
class Result:
    """Everything one view shows: its state, the two curves, the pull-off, derived numbers, warnings.

    ``load`` and ``separation`` are :class:`asperity.CurveResult` (dimensionless) or
    :class:`asperity.physical.PhysicalCurve` (physical); ``pull_off`` a
    :class:`asperity.PullOff` or :class:`asperity.physical.PhysicalPullOff`; ``derived``
    rows ``(name, value, meaning)``; ``warnings`` sentences; ``subject`` the
    :class:`asperity.Model` or :class:`asperity.physical.PhysicalContact` computed.
    """

    state: State
    subject: object
    load: object
    separation: object
    pull_off: object
    derived: tuple[tuple[str, str, str], ...]
    warnings: tuple[str, ...] = ()
    extras: dict = field(default_factory=dict, compare=False)
    #: The panels' warnings (``'label: Category: message'``), shown with the view's own.
    extra_warnings: list = field(default_factory=list, compare=False)

    @property
    def physical(self) -> bool:
        return self.state.mode == MODES[1]


def height_distribution(state: State):
    """The :class:`asperity.HeightDistribution` chosen: the registry's entry, built with the
    view's values of its parameters (a class) or as it is (an instance)."""
    from ..heights import HeightDistribution

    name = state["heights"]
    entry = distributions()[name]
    if isinstance(entry, HeightDistribution):
        return entry
    prefix = f"{name}_"
    kwargs = {k[len(prefix):]: v for k, v in state.values.items() if k.startswith(prefix)}
    return entry(**kwargs)


def friction_law(state: State):
    """The Hurtado-Kim law of the view's ``tau_f1, tau_f2, a1, a2`` (:class:`asperity.HurtadoKim`)."""
    from .. import HurtadoKim

    return HurtadoKim(tau_f1=state["tau_f1"], tau_f2=state["tau_f2"], a1=state["a1"], a2=state["a2"])


#: Widest load range of a view, in decades (the paper's figures span seven).
MAX_DECADES = 24


def _increasing(lo: float, hi: float, what: str):
    if not lo < hi:
        raise ValueError(f"{what}: the minimum must be below the maximum, got {lo:g} and {hi:g}")


def loads(state: State) -> np.ndarray:
    """The ``n`` log-spaced loads of the view (:math:`P/(NGb^2)`, or newtons in physical mode)."""
    lo, hi = (state["P_min"], state["P_max"]) if state.mode == MODES[0] else (state["P_min_N"], state["P_max_N"])
    if not lo > 0:
        raise ValueError(f"load range: loads are log-spaced and must be > 0, got a minimum of {lo:g}")
    _increasing(lo, hi, "load range")
    if hi / lo > 10.0**MAX_DECADES:  # a log axis over hundreds of decades shows nothing
        raise ValueError(f"load range: at most {MAX_DECADES} decades on the plots' log axes, got {lo:g} to {hi:g} "
                         f"({math.log10(hi / lo):.0f} decades): raise the minimum")
    return np.geomspace(lo, hi, state["n"])


def separations(state: State) -> np.ndarray:
    r"""The ``n`` evenly spaced separations :math:`d/\sigma` of the view."""
    _increasing(state["d_min"], state["d_max"], "separation range")
    return np.linspace(state["d_min"], state["d_max"], state["n"])


def _material(state: State):
    from ..materials import Material, material

    if state["material"] != CUSTOM:
        return material(state["material"])
    return Material(CUSTOM, E=state["E_Pa"], nu=state["material_nu"], b=state["b_m"], w=state["w_J_m2"],
                    H=state["H_Pa"], H0=state["H0_Pa"], h_star=state["h_star_m"])


def model_gamma(state: State) -> float:
    """The view's gamma: its value with the elastic law, 0 with the Jackson-Green law (no adhesion)."""
    return state["gamma"] if state["law"] == ELASTIC else 0.0


def asperity_law(state: State):
    """The per-asperity law of a dimensionless view: None (elastic) or
    :class:`asperity.elastic_plastic.JacksonGreen` of its ``H_over_E``, ``h_star_over_sigma``."""
    if state["law"] == ELASTIC:
        return None
    from ..elastic_plastic import LAWS

    return LAWS[state["law"]](H_over_E=state["H_over_E"], h_star_over_sigma=state["h_star_over_sigma"])


def build_subject(state: State):
    """The :class:`asperity.Model` (dimensionless) or :class:`~asperity.physical.PhysicalContact` of a view."""
    heights, friction = height_distribution(state), friction_law(state)
    if state.mode == MODES[0]:
        from .. import Model

        return Model(state["alpha"], state["beta"], model_gamma(state), nu=state["nu"], h_over_b=state["h_over_b"],
                     friction=friction, heights=heights, law=asperity_law(state))
    from ..physical import PhysicalContact
    from ..surface import Surface

    surface = Surface(sigma_s=state["sigma_s_m"], R=state["R_m"], eta=state["eta_per_m2"], area=state["area_m2"])
    adhesion = state["adhesion"] and state["plasticity"] == ELASTIC  # the Jackson-Green law has none
    return PhysicalContact(_material(state), surface, friction=friction, adhesion=adhesion,
                           heights=heights, plasticity=state["plasticity"], size_effect=state["size_effect"],
                           interaction=state["interaction"])


def _fmt(x: float) -> str:
    return "—" if x is None or not math.isfinite(x) else f"{x:.4g}"


def _adhesion_numbers(lam: float, R: float, w: float, E_star: float, h: float, sigma: float, law: str):
    from ..regimes import adhesion_regime, fuller_tabor_parameter, tabor_parameter

    if w == 0:
        which = "Hertz" if law == ELASTIC else "Jackson-Green, elastic-plastic"
        none = f"— (no adhesion: {which})"
        return [("λ", none, "Maugis parameter (Eq 15)"), ("adhesion regime", f"none ({which})", ""),
                ("Tabor μ_T", none, ""), ("Fuller-Tabor θ", none, "")]
    return [("λ", _fmt(lam), "Maugis parameter (Eq 15)"),
            ("adhesion regime", adhesion_regime(lam), "Johnson-Greenwood: DMT below λ = 0.1, JKR above 5"),
            ("Tabor μ_T", _fmt(tabor_parameter(R, w, E_star, h)), "(R w²/E*² z0³)^1/3 with z0 = h"),
            ("Fuller-Tabor θ", _fmt(fuller_tabor_parameter(sigma, R, w, E_star)),
             "E* σ^3/2 / (R^1/2 w): roughness defeats adhesion when large")]


def _off_plot(state: State, d_bar: float) -> str:
    """' (beyond the plotted separations)' when the pull-off lies outside the view's d range."""
    return "" if state["d_min"] <= d_bar <= state["d_max"] else " (beyond the plotted separations)"


def _derived(state: State, subject, pull_off) -> list[tuple[str, str, str]]:
    if state.mode == MODES[0]:
        from ..groups import maugis_lambda
        from ..surface import surface_from_groups

        a, b, g, hb = state["alpha"], state["beta"], model_gamma(state), state["h_over_b"]
        lam = maugis_lambda(a, b, g, hb) if g > 0 else math.nan
        s = surface_from_groups(a, b, 1.0, 1.0, 1.0)  # lengths in units of b, stresses in units of E*
        rows = _adhesion_numbers(float(lam), s.R, g, 1.0, hb, s.sigma_s, state["law"])
        where = f" at d/σ = {pull_off.d:.4g}{_off_plot(state, pull_off.d)}" if pull_off.exists else ""
        rows.insert(2, ("pull-off force", f"{_fmt(pull_off.force)}{where}", "|P|/(N G b²), most tensile force"))
        if state["law"] != ELASTIC:
            from ..plasticity import plasticity_index

            psi = plasticity_index(1.0, state["H_over_E"], a * a, 1.0)  # (E*/H)(sigma/R)^1/2 = alpha/(H/E*)
            rows.append(("plasticity index ψ", _fmt(float(psi)), "α/(H/E*): plastic asperities above about 1"))
        return rows
    c = subject
    rows = [("α, β, γ", f"{_fmt(c.alpha)}, {_fmt(c.beta)}, {_fmt(c.gamma)}", "groups of Eqs 7 and 16"),
            ("N", _fmt(c.N), "asperities (η A0)"), ("force unit", f"{_fmt(c.force_scale)} N", "N G b²")]
    rows += _adhesion_numbers(c.lam, c.surface.R, c.w if c.gamma > 0 else 0.0, c.E_star, c.h, c.surface.sigma_s,
                              c.law)
    where = f" at d = {pull_off.d:.4g} m{_off_plot(state, pull_off.d / c.surface.sigma_s)}" if pull_off.exists else ""
    rows.insert(5, ("pull-off force", f"{_fmt(pull_off.force)} N{where}", "most tensile force"))
    if c.hardness is not None:
        rows.append(("plasticity index ψ", _fmt(c.plasticity_index),
                     f"(E*/H)(σs/R)^1/2 with H = {_fmt(c.hardness)} Pa: plastic asperities above about 1"))
    return rows


def number_free(note: str) -> str:
    """A note with its numbers replaced by '#': two notes that differ only in them are one
    (their signs too: a review saw '-5.452e+11' and '1e+11' kept as two notes)."""
    return re.sub(r"[-+]?\.?\d[\d.e+-]*", "#", note)


def caught_notes(caught) -> list[str]:
    """Recorded warnings as the page shows them: ``'Category: message'`` in the page's words."""
    return [f"{w.category.__name__}: {page_wording(str(w.message))}" for w in caught]


def compute(state: State) -> Result:
    """The curves, pull-off, derived numbers and warnings of a view, from the library.

    Raises
    ------
    ValueError, TypeError
        The library's message for parameters it rejects (or an empty range of the view).
    """
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        P, d_bar = loads(state), separations(state)
        subject = build_subject(state)
        if state.mode == MODES[0]:
            load, separation = subject.load_curve(P), subject.separation_curve(d_bar)
        else:
            load, separation = subject.load_curve(P), subject.separation_curve(d_bar * subject.surface.sigma_s)
        pull_off = subject.pull_off()
        derived = _derived(state, subject, pull_off)
    notes = caught_notes(caught)
    # one of each: the two curves' notes differ only in their numbers (a share, a load), the first kept
    unique = {number_free(n): n for n in reversed(notes)}
    return Result(state, subject, load, separation, pull_off, tuple(derived), tuple(reversed(unique.values())))


# -- what the plots show ------------------------------------------------------------------
def _fraction(result: Result, curve):
    """Contacts as a fraction n/N, and real over nominal area (NaN in dimensionless mode)."""
    if result.physical:
        return curve.contacts / result.subject.N, curve.area_fraction
    return np.asarray(curve.contacts), np.full(len(curve), np.nan)


def load_columns(result: Result) -> dict[str, np.ndarray]:
    """Columns of the load plots: the library's (``d, P, F, mu, area, pressure, contacts``, SI in
    physical mode), ``fraction`` (n/N) and ``area_fraction`` (A/A0; NaN in dimensionless mode)."""
    c = result.load
    fraction, area_fraction = _fraction(result, c)
    return {**{k: np.asarray(getattr(c, k)) for k in ("d", "P", "F", "mu", "area", "pressure", "contacts")},
            "fraction": fraction, "area_fraction": area_fraction}


def separation_columns(result: Result) -> dict[str, np.ndarray]:
    """Columns of the separation plots: the library's, and the force split by sign for a log axis
    (``P_compressive`` = P where P > 0, ``P_tensile`` = -P where P < 0, NaN elsewhere)."""
    c = result.separation
    P = np.asarray(c.P)
    out = {k: np.asarray(getattr(c, k)) for k in ("d", "P", "F", "mu", "area", "pressure", "contacts")}
    out["P_compressive"] = np.where(P > 0, P, np.nan)
    out["P_tensile"] = np.where(P < 0, -P, np.nan)
    return out


def pull_off_columns(result: Result) -> dict[str, list[float]]:
    """The pull-off point (``d``, ``force``) for the P(d) plot; empty without a tensile force."""
    po = result.pull_off
    return {"d": [po.d], "force": [po.force]} if po.exists else {"d": [], "force": []}
