r"""One registry of the model's quantities: names, symbols, meanings, units and valid ranges.

Every place that names a quantity derives it from here: the columns of a curve
(:data:`asperity.curves.COLUMNS`), the SI columns of a physical curve
(:data:`asperity.physical.PHYSICAL_COLUMNS`), the command line's help, the explorer's
sliders and axis labels, a sweep's xarray attributes and a fit's parameter bounds.

A :class:`Quantity` carries

* ``name``: the Python name, keyword argument and dimensionless column (``'alpha'``, ``'P'``);
* ``symbol``: LaTeX, without dollars (``r'\alpha'``);
* ``meaning``: one line, with the dimensionless unit where there is one;
* ``unit``: the dimensionless unit (``'1'``, ``'sigma'``, ``'N G b^2'``, ...);
* ``si_name``, ``si_unit``, ``si_meaning``: the SI column (``'P_N'``), unit (``'N'``) and
  meaning, for quantities that have a physical form;
* the valid range (``lo``, ``hi``, whether each end is included), ``log`` (spans decades:
  log axes, log sliders, fitted in log10), a ``typical`` range for sliders and sweeps,
  the ``default`` and the ``source`` (equation of the paper, or reference).

Six registries: :data:`MODEL_PARAMETERS` (the dimensionless inputs of
:class:`asperity.Model` and of its per-asperity laws), :data:`PHYSICAL_PARAMETERS` (inputs
of a physical contact, in SI units), :data:`CURVE_COLUMNS` (the columns of every curve),
:data:`PLASTIC_COLUMNS` (the column a curve gains when the per-asperity law or the material
has a critical interference), :data:`CYCLE_QUANTITIES` (the inputs and results of a
loading cycle, :mod:`asperity.cycle`) and :data:`FIT_PARAMETERS` (parameters only the fits
have: offsets, the COS and Amontons laws).  :func:`quantity` looks a name up in all six.
A fit names a physical parameter by its SI name (``w_J_m2``, ``R_m``, ``tau_Pa``), a
dimensionless one by its name (``alpha``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

__all__ = [
    "Quantity",
    "MODEL_PARAMETERS",
    "PHYSICAL_PARAMETERS",
    "CURVE_COLUMNS",
    "VALIDATION_COLUMNS",
    "PLASTIC_COLUMNS",
    "CYCLE_QUANTITIES",
    "FIT_PARAMETERS",
    "quantity",
]

_INF = math.inf


@dataclass(frozen=True)
class Quantity:
    """A named quantity of the model with its units and valid range (see the module docstring)."""

    name: str
    symbol: str
    meaning: str
    unit: str = "1"
    si_name: str | None = None
    si_unit: str | None = None
    si_meaning: str | None = None
    lo: float = -_INF
    hi: float = _INF
    lo_inclusive: bool = False
    hi_inclusive: bool = False
    log: bool = False
    typical: tuple[float, float] | None = None
    default: float | None = None
    source: str = ""

    def contains(self, value: float) -> bool:
        """True if the scalar ``value`` lies in the valid range."""
        above = value >= self.lo if self.lo_inclusive else value > self.lo
        below = value <= self.hi if self.hi_inclusive else value < self.hi
        return bool(above and below)

    def range_text(self) -> str:
        """The valid range as text, e.g. ``'0 < alpha < inf'`` or ``'-1 < nu < 0.5'``."""
        if self.lo == -_INF and self.hi == _INF:
            return f"{self.name} real"
        left = "" if self.lo == -_INF else f"{self.lo:g} {'<=' if self.lo_inclusive else '<'} "
        right = "" if self.hi == _INF else f" {'<=' if self.hi_inclusive else '<'} {self.hi:g}"
        if self.hi == _INF and self.lo != -_INF:
            right = " <= inf" if self.hi_inclusive else " < inf"
        return f"{left}{self.name}{right}"

    def help(self) -> str:
        """One line for ``--help``: meaning, valid range, default and source."""
        parts = [self.meaning, self.range_text()]
        if self.default is not None:
            parts.append(f"default {self.default:g}")
        if self.source:
            parts.append(self.source)
        return "; ".join(parts)

    def label(self, si: bool = False) -> str:
        """Axis label, e.g. ``'$\\alpha$'`` or ``'$P$ (N)'``."""
        if si and self.si_unit and self.si_unit != "1":
            return f"${self.symbol}$ ({self.si_unit})"
        return f"${self.symbol}$"


def _registry(*items: Quantity) -> dict[str, Quantity]:
    return {q.name: q for q in items}


#: Dimensionless inputs of :class:`asperity.Model` (and the Hurtado-Kim constants).
MODEL_PARAMETERS = _registry(
    Quantity("alpha", r"\alpha", "surface roughness parameter (sigma/R)^(1/2)", lo=0.0, log=True,
             typical=(1e-4, 0.3), source="Eq 7"),
    Quantity("beta", r"\beta", "friction regime parameter (R sigma)^(1/2)/b", lo=0.0, log=True,
             typical=(10.0, 1e6), source="Eq 7"),
    Quantity("gamma", r"\gamma", "adhesion parameter w/(E* b); 0 = no adhesion (Hertz)", lo=0.0,
             lo_inclusive=True, log=True, typical=(1e-6, 0.05), default=0.0, source="Eq 16"),
    Quantity("nu", r"\nu", "Poisson's ratio (the paper does not state it)", lo=-1.0, hi=0.5,
             typical=(0.0, 0.49), default=0.3, source="decisions.md 4"),
    Quantity("h_over_b", "h/b", "Dugdale range over Burgers vector (paper: 1)", lo=0.0, log=True,
             typical=(0.1, 10.0), default=1.0, source="Eq 15"),
    Quantity("tau_f1", r"\bar\tau_{f1}", "Hurtado-Kim friction stress tau_f/G* of small contacts (region 1)",
             lo=0.0, log=True, typical=(1e-4, 0.2), default=1.0 / 43.0, source="Eq 2, Hurtado & Kim 1999"),
    Quantity("tau_f2", r"\bar\tau_{f2}", "Hurtado-Kim friction stress tau_f/G* of large contacts (region 3)",
             lo=0.0, log=True, typical=(1e-6, 0.01), default=1.0 / 43.0 / 30.0, source="Eq 2, Hurtado & Kim 1999"),
    Quantity("a1", r"\bar a_1", "Hurtado-Kim contact radius a/b where region 2 starts", lo=0.0, log=True,
             typical=(1.0, 1e3), default=28.0, source="Eq 3, Hurtado & Kim 1999"),
    Quantity("a2", r"\bar a_2", "Hurtado-Kim contact radius a/b where region 2 ends (> a1)", lo=0.0, log=True,
             typical=(1e3, 1e7), default=8.0e4, source="Eq 3, Hurtado & Kim 1999"),
    Quantity("H_over_E", "H/E^*", "hardness over composite modulus H/E* of the elastic-plastic law "
             "(H0/E* with the size effect); plasticity index psi = alpha/(H/E*)", lo=0.0, hi=0.142,
             hi_inclusive=True, log=True, typical=(1e-4, 0.14),
             source="Jackson & Green 2005 (S_y = H/2.84); docs/plasticity.md"),
    Quantity("h_star_over_sigma", r"h^*/\sigma", "Nix-Gao size-effect length over sigma, h*/sigma; 0 = no "
             "size effect", lo=0.0, lo_inclusive=True, log=True, typical=(1e-2, 1e4), default=0.0,
             source="Nix & Gao 1998; docs/plasticity.md"),
)

#: Inputs of a physical contact (:class:`asperity.physical.PhysicalContact`), SI units.
PHYSICAL_PARAMETERS = _registry(
    Quantity("sigma_s", r"\sigma_s", "standard deviation of summit heights", unit="m", si_name="sigma_s_m",
             si_unit="m", lo=0.0, log=True, typical=(1e-10, 1e-5), source="Eq 7"),
    Quantity("R", "R", "mean summit radius of curvature", unit="m", si_name="R_m", si_unit="m", lo=0.0,
             log=True, typical=(1e-8, 1e-3), source="Eq 7"),
    Quantity("eta", r"\eta", "summit density (summits per area)", unit="1/m^2", si_name="eta_per_m2",
             si_unit="1/m^2", lo=0.0, log=True, typical=(1e8, 1e16)),
    Quantity("area", "A_0", "nominal contact area", unit="m^2", si_name="area_m2", si_unit="m^2", lo=0.0,
             log=True, typical=(1e-12, 1e-2)),
    Quantity("E", "E", "Young's modulus", unit="Pa", si_name="E_Pa", si_unit="Pa", lo=0.0, log=True,
             typical=(1e8, 1.2e12)),
    Quantity("E_star", "E^*", "composite Young's modulus", unit="Pa", si_name="E_star_Pa", si_unit="Pa",
             lo=0.0, log=True, typical=(1e8, 1.2e12)),
    Quantity("G_star", "G^*", "effective shear modulus 2G (unit of the friction stress)", unit="Pa",
             si_name="G_star_Pa", si_unit="Pa", lo=0.0, log=True, typical=(1e8, 1e12), source="Eq 2"),
    Quantity("b", "b", "Burgers vector", unit="m", si_name="b_m", si_unit="m", lo=0.0, log=True,
             typical=(1e-10, 1e-9), source="Eq 7"),
    Quantity("w", "w", "work of adhesion", unit="J/m^2", si_name="w_J_m2", si_unit="J/m^2", lo=0.0,
             lo_inclusive=True, log=True, typical=(1e-3, 5.0), source="Eq 16"),
    Quantity("h", "h", "Dugdale range of the adhesive stress", unit="m", si_name="h_m", si_unit="m", lo=0.0,
             log=True, typical=(1e-11, 1e-8), source="Eq 14"),
    Quantity("rms", r"\sigma", "rms roughness (standard deviation of all surface heights, sqrt(m0))", unit="m",
             si_name="rms_m", si_unit="m", lo=0.0, log=True, typical=(1e-10, 1e-5), source="Nayak 1971"),
    Quantity("alpha_n", r"\alpha_N", "Nayak's bandwidth parameter m0 m4/m2^2 of the surface heights", lo=1.0,
             lo_inclusive=True, log=True, typical=(1.5, 1e3), source="Nayak 1971; McCool 1986"),
    Quantity("tau", r"\tau", "interfacial shear strength", unit="Pa", si_name="tau_Pa", si_unit="Pa", lo=0.0,
             log=True, typical=(1e5, 1e10)),
    Quantity("hardness", "H", "hardness (mean pressure of a fully plastic contact; H0 with the size effect)",
             unit="Pa", si_name="H_Pa", si_unit="Pa", lo=0.0, log=True, typical=(1e7, 1.5e11),
             source="materials table; docs/plasticity.md"),
    Quantity("h_star", "h^*", "Nix-Gao size-effect length (indentation size effect)", unit="m",
             si_name="h_star_m", si_unit="m", lo=0.0, lo_inclusive=True, log=True, typical=(1e-8, 1e-5),
             source="Nix & Gao 1998"),
    Quantity("tau1", r"\tau_{f1}", "Hurtado-Kim shear strength of small contacts (region 1), tau_f1 G*", unit="Pa",
             si_name="tau1_Pa", si_unit="Pa", lo=0.0, log=True, typical=(1e6, 1e10), source="Eq 2"),
    Quantity("tau2", r"\tau_{f2}", "Hurtado-Kim shear strength of large contacts (region 3), tau_f2 G*", unit="Pa",
             si_name="tau2_Pa", si_unit="Pa", lo=0.0, log=True, typical=(1e4, 1e9), source="Eq 2"),
    Quantity("sigma0", r"\sigma_0", "Dugdale adhesive stress w/h", unit="Pa", si_name="sigma0_Pa", si_unit="Pa",
             lo=0.0, log=True, typical=(1e6, 1e11), source="Eq 14"),
)

#: Parameters of the fits only (:mod:`asperity.fit`): offsets and the empirical friction laws.
FIT_PARAMETERS = _registry(
    Quantity("d0", "d_0", "separation offset: the model sees d - d0 (sigma)", unit="sigma", si_name="d0_m",
             si_unit="m", default=0.0),
    Quantity("alpha_t", r"\alpha_t", "COS transition parameter, 0 (DMT) to 1 (JKR)", lo=0.0, hi=1.0,
             lo_inclusive=True, hi_inclusive=True, typical=(0.0, 1.0), source="Carpick et al. 1999, Eq 7"),
    Quantity("mu0", r"\mu_0", "Amontons friction coefficient of F = mu0 (P + P0)", lo=0.0, log=True,
             typical=(1e-3, 2.0)),
    Quantity("P0", "P_0", "Amontons adhesion offset of F = mu0 (P + P0), a load", unit="N G b^2", si_name="P0_N",
             si_unit="N"),
    Quantity("F0", "F_0", "COS friction at zero load, tau pi a0^2", unit="N G b^2", si_name="F0_N", si_unit="N",
             lo=0.0, log=True, source="Carpick et al. 1999"),
    Quantity("Pc", "P_c", "COS critical load (the pull-off load, negative)", unit="N G b^2", si_name="Pc_N",
             si_unit="N", hi=0.0, source="Carpick et al. 1999"),
)

#: Columns of every curve (dimensionless, and SI for a physical contact), in output order.
CURVE_COLUMNS = _registry(
    Quantity("d", r"d/\sigma", "separation d/sigma", unit="sigma", si_name="d_m", si_unit="m",
             si_meaning="separation of the flat from the mean summit height"),
    Quantity("P", r"P/NGb^2", "normal force P/(N G b^2), compressive > 0", unit="N G b^2", si_name="P_N",
             si_unit="N", si_meaning="total normal force, compressive > 0", log=True),
    Quantity("F", r"F/NGb^2", "friction force F/(N G b^2)", unit="N G b^2", si_name="F_N", si_unit="N",
             si_meaning="total friction force", log=True),
    Quantity("mu", r"\mu", "friction coefficient F/P (NaN where P <= 0)", si_name="mu", si_unit="1",
             si_meaning="friction coefficient F/P (NaN where P <= 0)", log=True),
    Quantity("area", r"A/N\pi b^2", "real contact area A/(N pi b^2)", unit="N pi b^2", si_name="area_m2",
             si_unit="m^2", si_meaning="real contact area", log=True),
    Quantity("pressure", r"P/E^*A", "mean contact pressure P/(E* A) (NaN without contact)", unit="E*",
             si_name="pressure_Pa", si_unit="Pa",
             si_meaning="mean pressure over the real contact area, P/area (NaN without contact)", log=True),
    Quantity("contacts", "n/N", "fraction of asperities in contact n/N", si_name="contacts", si_unit="1",
             si_meaning="number of asperities in contact"),
)

#: The column a curve gains when its per-asperity law (Jackson-Green) or, for a physical
#: contact, its material has a critical interference (asperities past it have yielded).
PLASTIC_COLUMNS = _registry(
    Quantity("plastic", "n_p/N", "fraction of asperities past the critical interference (yielded) n_p/N",
             si_name="plastic", si_unit="1", si_meaning="number of asperities past the critical interference "
             "(yielded)", source="Jackson & Green 2005; docs/plasticity.md"),
)


def _column(name: str, symbol: str, unit: str, meaning: str, log: bool = False) -> Quantity:
    """An SI-only column (its name is its SI name)."""
    return Quantity(name, symbol, meaning, unit=unit, si_name=name, si_unit=unit, si_meaning=meaning, log=log)


#: Columns of a side-by-side check against a boundary-element solution
#: (:class:`asperity.validation.SurfaceValidation`), SI units, in output order.  ``spectral``
#: and ``detected`` are the two estimates of the GW summit parameters (:mod:`asperity.topography`).
VALIDATION_COLUMNS = _registry(
    _column("P_N", "P", "N", "total normal force on the scanned area, compressive > 0", log=True),
    _column("p_Pa", r"\bar p", "Pa", "nominal pressure P/A0", log=True),
    _column("fraction_bem", "A/A_0", "1", "boundary-element real contact area over nominal area", log=True),
    _column("area_bem_m2", "A_{BEM}", "m^2", "boundary-element real contact area (contact pixels x pixel area)",
            log=True),
    _column("area_spectral_m2", "A_{GW}", "m^2", "statistical-model real contact area, spectral summit parameters",
            log=True),
    _column("area_detected_m2", "A_{GW}", "m^2", "statistical-model real contact area, detected summit parameters",
            log=True),
    _column("area_icha_m2", "A_{ICHA}", "m^2", "interacting and coalescing Hertzian asperities (on the detected "
            "summits): real contact area", log=True),
    _column("area_persson_m2", "A_{P}", "m^2", "Persson's theory: real contact area erf(sqrt(2) p/E* h')",
            log=True),
    _column("area_bgt_m2", "A_{BGT}", "m^2", "Bush-Gibson-Thomas light-load asymptote: real contact area "
            "sqrt(2 pi) p A0/E* h'", log=True),
    _column("dev_spectral", r"A_{GW}/A_{BEM}-1", "1", "deviation of the spectral model area from the BEM area"),
    _column("dev_detected", r"A_{GW}/A_{BEM}-1", "1", "deviation of the detected model area from the BEM area"),
    _column("dev_icha", r"A_{ICHA}/A_{BEM}-1", "1", "deviation of the ICHA area from the BEM area"),
    _column("dev_persson", r"A_{P}/A_{BEM}-1", "1", "deviation of Persson's area from the BEM area"),
    _column("dev_bgt", r"A_{BGT}/A_{BEM}-1", "1", "deviation of the BGT asymptote from the BEM area"),
    _column("gap_bem_m", r"\bar g", "m", "boundary-element mean gap between the flat and the deformed surface"),
    _column("gap_spectral_m", r"\bar g", "m", "statistical-model mean gap (local separation + mean summit "
            "height), spectral"),
    _column("gap_detected_m", r"\bar g", "m", "statistical-model mean gap (local separation + mean summit "
            "height), detected"),
    _column("gap_icha_m", r"\bar g", "m", "ICHA mean gap between the flat and the deformed surface"),
    _column("sep_bem_m", "s", "m", "approach: distance of the flat from the undeformed mean plane "
            "(non-periodic BEM only; NaN for periodic)"),
    _column("sep_spectral_m", "s", "m", "statistical-model distance of the flat from the undeformed mean plane, "
            "spectral"),
    _column("sep_detected_m", "s", "m", "statistical-model distance of the flat from the undeformed mean plane, "
            "detected"),
    _column("sep_icha_m", "s", "m", "ICHA distance of the flat from the undeformed mean plane (non-periodic only; "
            "NaN for periodic)"),
    _column("spots_bem", "n_{spots}", "1", "boundary-element number of contact spots (connected contact regions)"),
    _column("contacts_spectral", "n", "1", "statistical-model number of asperities in contact, spectral"),
    _column("contacts_detected", "n", "1", "statistical-model number of asperities in contact, detected"),
    _column("spots_icha", "n_{spots}", "1", "ICHA contact spots (asperities in contact, a coalesced group once)"),
    _column("iterations_bem", "it", "1", "constrained conjugate-gradient iterations of the BEM solve"),
)


#: Inputs and results of a loading cycle (:mod:`asperity.cycle`): dimensionless, and SI for a
#: physical contact (:mod:`asperity.physical_cycle`).
CYCLE_QUANTITIES = _registry(
    Quantity("d_min", r"d_{min}/\sigma", "closest approach of the cycle d_min/sigma", unit="sigma",
             si_name="d_min_m", si_unit="m", si_meaning="closest approach (separation at the turning point)",
             lo=-1.0e4, lo_inclusive=True),
    Quantity("d_max", r"d_{max}/\sigma", "start and end of the cycle d_max/sigma (default: 10 beyond the end of "
             "the asperities' stable branch)", unit="sigma", si_name="d_max_m", si_unit="m",
             si_meaning="separation where the cycle starts and ends"),
    Quantity("preload", r"P_{pre}/NGb^2", "preload: the largest compressive load P/(N G b^2), reached at the "
             "closest approach (as a result: the force there, negative when a cycle given by d_min never "
             "turns compressive)", unit="N G b^2", si_name="preload_N", si_unit="N",
             si_meaning="largest compressive load of the cycle (the force at the closest approach; negative "
             "when it is still tensile)", lo=0.0, log=True),
    Quantity("stiffness", r"k\sigma/NGb^2", "instrument spring stiffness k sigma/(N G b^2); inf: displacement "
             "control", unit="N G b^2/sigma", si_name="stiffness_N_m", si_unit="N/m",
             si_meaning="stiffness of the instrument's spring (cantilever)", lo=0.0, hi=_INF, hi_inclusive=True,
             log=True, default=_INF),
    Quantity("u_in", r"\bar u_{in}", "penetration (z - d)/sigma at which an approaching asperity jumps into "
             "contact, in [u_end, 0]", unit="sigma", si_name="u_in_m", si_unit="m",
             si_meaning="penetration at which an approaching asperity jumps into contact", lo=-1.0e4, hi=0.0,
             lo_inclusive=True, hi_inclusive=True, default=0.0, source="decisions.md 11"),
    Quantity("d_base", r"Z/\sigma", "displacement of the instrument spring's base Z/sigma = d - P/k", unit="sigma",
             si_name="d_base_m", si_unit="m", si_meaning="displacement of the instrument spring's base, d - P/k"),
    Quantity("pull_off", r"P_{off}/NGb^2", "pull-off force on retraction |P|/(N G b^2)", unit="N G b^2",
             si_name="pull_off_N", si_unit="N", si_meaning="pull-off force on retraction", lo=0.0,
             lo_inclusive=True, log=True),
    Quantity("d_pull_off", r"d_{off}/\sigma", "separation of the pull-off on retraction", unit="sigma",
             si_name="d_pull_off_m", si_unit="m", si_meaning="separation of the pull-off on retraction"),
    Quantity("energy", r"E/NGb^2\sigma", "energy dissipated per cycle E/(N G b^2 sigma)", unit="N G b^2 sigma",
             si_name="energy_J", si_unit="J", si_meaning="energy dissipated per cycle", lo=0.0,
             lo_inclusive=True, log=True),
    Quantity("energy_per_area", "E/A_0", "energy dissipated per cycle and nominal area", unit="J/m^2",
             si_name="energy_J_m2", si_unit="J/m^2", si_meaning="energy dissipated per cycle and nominal area",
             lo=0.0, lo_inclusive=True, log=True),
    Quantity("loop_energy", r"e/Gb^2\sigma", "energy one asperity dissipates through the whole loop "
             "e/(G b^2 sigma)", unit="G b^2 sigma", si_name="loop_energy_J", si_unit="J",
             si_meaning="energy one asperity dissipates through the whole loop", lo=0.0, lo_inclusive=True),
    Quantity("loop_fraction", "n_{loop}/N", "fraction of asperities through the whole loop", si_name="loop_count",
             si_unit="1", si_meaning="number of asperities through the whole loop", lo=0.0, hi=1.0,
             lo_inclusive=True, hi_inclusive=True),
    Quantity("jump_energy", r"E_{jump}/NGb^2\sigma", "energy lost in the instrument's jumps E/(N G b^2 sigma)",
             unit="N G b^2 sigma", si_name="jump_energy_J", si_unit="J",
             si_meaning="energy lost in the instrument's jumps", lo=0.0, lo_inclusive=True),
    Quantity("friction_hysteresis", r"\oint F/NGb^2\sigma", "friction hysteresis: integral of F_retract - "
             "F_approach over the separation, per N G b^2 sigma", unit="N G b^2 sigma",
             si_name="friction_hysteresis_N_m", si_unit="N m",
             si_meaning="integral of F_retract - F_approach over the separation", lo=0.0, lo_inclusive=True),
)


def quantity(name: str) -> Quantity:
    """The :class:`Quantity` called ``name`` in any registry (model parameters first).

    Raises
    ------
    ValueError
        For an unknown name; the message lists the known ones.
    """
    if not isinstance(name, str):
        raise TypeError(f"name must be a string, got {type(name).__name__} {name!r}")
    registries = (MODEL_PARAMETERS, PHYSICAL_PARAMETERS, CURVE_COLUMNS, PLASTIC_COLUMNS, CYCLE_QUANTITIES,
                  FIT_PARAMETERS)
    for registry in registries:
        if name in registry:
            return registry[name]
    known = sorted({name for registry in registries for name in registry})
    raise ValueError(f"unknown quantity {name!r}; known: {', '.join(known)}")
