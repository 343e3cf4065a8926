r"""The models a fit can use, by name: their parameters and what they predict for each kind of data.

=============  ===============================================================  ==========================
name           friction :math:`F(P)`                                            also fits
=============  ===============================================================  ==========================
``gw``         the multi-asperity model (:mod:`asperity.fit.gw`)                force-separation, pull-off
``hertz``      :math:`\tau\pi a^2`, :func:`~asperity.hertz.hertz_contact_radius`  force-separation
``jkr``        :math:`\tau\pi a^2`, :func:`~asperity.jkr.jkr_contact_radius`      force-separation, pull-off
``dmt``        :math:`\tau\pi a^2`, :func:`~asperity.dmt.dmt_contact_radius`      force-separation, pull-off
``md``         :math:`\tau\pi a^2`, exact :mod:`~asperity.maugis_dugdale_load`    force-separation, pull-off
``cos``        :func:`~asperity.cos.cos_friction`, :math:`(F_0, P_c, \alpha_t)`
``amontons``   :func:`~asperity.amontons.amontons_friction`, :math:`\mu_0(P + P_0)`
=============  ===============================================================  ==========================

The single-asperity laws (``hertz``, ``jkr``, ``dmt``, ``md``) work in SI units, on physical
data: parameters ``w_J_m2``, ``R_m``, ``E_star_Pa``, ``tau_Pa`` (and ``sigma0_Pa`` for
Maugis-Dugdale); by default ``w_J_m2``, ``tau_Pa`` (and ``sigma0_Pa``) vary while the tip
radius ``R_m`` and the modulus ``E_star_Pa`` are fixed, since a friction-load curve
determines only :math:`\tau(R/K)^{2/3}` and :math:`wR` of JKR and DMT (see docs/fitting.md).
The empirical forms ``cos`` and ``amontons`` take either units.  A normal-force curve of a
single asperity is the force at penetration :math:`\delta = d_0 - d` (displacement
control, the stable branch), with the offset ``d0_m`` fixed at 0 unless varied.

Each model is a :class:`FitModel`: :meth:`~FitModel.specs` gives its parameters
(:class:`ParameterSpec`: start value, bounds and log scale from
:mod:`asperity.quantities`, starts estimated from the data where possible),
:meth:`~FitModel.predict` the model's values at the data's points, :meth:`~FitModel.curve`
the fitted curve on a grid.  Loads the model cannot carry (below its pull-off load) are
compared with the value at its pull-off, and counted, so that the fit stays continuous;
the result warns when any remain at the best fit.  :data:`MODELS` is the registry;
:func:`get_model` looks a name up.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..amontons import amontons_friction
from ..cos import cos_friction
from ..dmt import dmt_contact_radius, dmt_normal_force, dmt_pull_off_force
from ..hertz import hertz_contact_radius, hertz_normal_force
from ..jkr import jkr_contact_radius, jkr_normal_force, jkr_pull_off_force
from ..materials import as_material
from ..maugis_dugdale import LAMBDA_RANGE, md_branch_end, md_lambda
from ..maugis_dugdale_load import md_contact_radius, md_normal_force, md_pull_off_force
from ..quantities import quantity
from .data import Dataset

__all__ = ["ParameterSpec", "FitCurve", "FitModel", "MODELS", "get_model", "parameter_spec"]


@dataclass(frozen=True)
class ParameterSpec:
    """One parameter of a model: its start value, whether it varies by default, bounds, scale.

    Attributes
    ----------
    name : str
        Fit name: the SI name of a physical quantity (``w_J_m2``), else the symbol (``alpha``).
    value : float or None
        Start (or fixed) value; None if the user must give one.
    vary : bool
        Varied by default.
    lo, hi : float
        Bounds (from :mod:`asperity.quantities`).
    log : bool
        Fitted in log10 (the quantity spans decades).
    unit : str
        Unit (SI for physical parameters).
    meaning : str
        One line, from the registry.
    """

    name: str
    value: float | None
    vary: bool = False
    lo: float = -math.inf
    hi: float = math.inf
    log: bool = False
    unit: str = "1"
    meaning: str = ""


def parameter_spec(qname: str, value, *, physical: bool, vary: bool = False, meaning=None) -> ParameterSpec:
    """The :class:`ParameterSpec` of registry quantity ``qname`` (SI name if ``physical``)."""
    q = quantity(qname)
    si = physical and q.si_name is not None
    return ParameterSpec(name=q.si_name if si else q.name, value=None if value is None else float(value), vary=vary,
                         lo=q.lo, hi=q.hi, log=q.log, unit=(q.si_unit if si else q.unit) or "1",
                         meaning=q.meaning if meaning is None else meaning)


@dataclass(frozen=True)
class FitCurve:
    """A fitted curve of a single-asperity or empirical law on a grid: named columns with units.

    ``columns()`` gives name -> array (SI names, e.g. ``P_N``, ``F_N``, ``area_m2``, for
    physical data); ``to_csv()`` and ``to_dataframe()`` write them.
    """

    data: dict = field(default_factory=dict)
    parameters: dict = field(default_factory=dict, compare=False)

    def __len__(self) -> int:
        return int(np.size(next(iter(self.data.values())))) if self.data else 0

    def __getattr__(self, name):
        data = self.__dict__.get("data", {})
        if name in data:
            return data[name]
        raise AttributeError(name)

    def columns(self) -> dict:
        """Column name -> array."""
        return {k: np.asarray(v, dtype=float) for k, v in self.data.items()}

    def to_csv(self, path_or_buffer=None):
        """CSV text of the columns (written atomically to a path if given)."""
        from .._csv import columns_to_csv

        return columns_to_csv(self.columns(), path_or_buffer)

    def to_dataframe(self):
        """The curve as a pandas DataFrame (needs ``asperity[frame]``)."""
        from .._csv import columns_to_dataframe

        return columns_to_dataframe(self.columns(), self.parameters)


class FitModel:
    """Base of the fit models (see the module docstring); subclasses set the class attributes.

    Attributes
    ----------
    name : str
        Registry name.
    kinds : tuple of str
        Data kinds it predicts (``friction``, ``force``, ``pull_off``).
    physical : bool or None
        True: SI data only; False: dimensionless data only; None: either.
    """

    name = ""
    kinds: tuple[str, ...] = ()
    physical: bool | None = None
    title = ""

    def check(self, data: Dataset) -> None:
        """Raise ValueError unless this model can fit ``data``."""
        if data.kind not in self.kinds:
            raise ValueError(f"model {self.name!r} cannot fit {data.kind} data; it fits {', '.join(self.kinds)} data")
        if self.physical is True and not data.physical:
            raise ValueError(f"model {self.name!r} works in SI units: give physical data (units in the header, "
                             "e.g. 'load [nN]', 'friction [nN]')")
        if self.physical is False and data.physical:
            raise ValueError(f"model {self.name!r} is dimensionless here; for physical data give a contact")

    def specs(self, data: Dataset) -> dict[str, ParameterSpec]:
        """Parameters (name -> :class:`ParameterSpec`) for fitting ``data``."""
        raise NotImplementedError

    def predict(self, data: Dataset, v: dict) -> tuple[np.ndarray, int]:
        """Model values at the data's points and the number of points outside its domain."""
        if data.kind == "friction":
            F, clamped = self.friction(data.x, v)
            return (F / data.x if data.quantity == "mu" else F), clamped
        if data.kind == "force":
            return self.force(data.x, v)
        return self.pull_off(data, v), 0

    def friction(self, P, v):  # pragma: no cover - every model overrides what it supports
        raise NotImplementedError

    def force(self, d, v):  # pragma: no cover
        raise NotImplementedError

    def pull_off(self, data, v):  # pragma: no cover
        raise NotImplementedError

    def curve(self, data: Dataset, v: dict, x: np.ndarray):
        """The fitted curve at ``x`` (a grid over the data's range): a :class:`FitCurve`."""
        unit = "_N" if data.physical else ""
        if data.kind == "friction":
            F, _ = self.friction(x, v)
            with np.errstate(divide="ignore", invalid="ignore"):
                mu = np.where(x > 0, F / np.where(x > 0, x, 1.0), np.nan)
            return FitCurve({f"P{unit}": x, f"F{unit}": F, "mu": mu}, dict(v))
        if data.kind == "force":
            return FitCurve({"d_m" if data.physical else "d": x, f"P{unit}": self.force(x, v)[0]}, dict(v))
        return FitCurve({"row": data.x, f"pull_off{unit}": self.pull_off(data, v)}, dict(v))

    def derived(self, v: dict) -> dict:
        """Quantities that follow from the fitted parameters (e.g. the Maugis parameter)."""
        return {}


# -- single-asperity laws -------------------------------------------------------------------
def _estimate_pull_off(data: Dataset) -> float:
    """A start for the pull-off force from friction-load data: past the most tensile load."""
    if data.kind == "pull_off":
        return float(np.median(data.y))
    P_min = float(np.min(data.x))
    span = float(np.max(data.x) - P_min)
    return 1.2 * -P_min if P_min < 0 else max(0.05 * span, 1e-300)


class _Law(FitModel):
    """F = tau pi a(P)^2 for one asperity (SI units)."""

    physical = True
    adhesive = True
    has_sigma0 = False

    def __init__(self, material=None):
        self.material = None if material is None else as_material(material)

    def specs(self, data):
        E = self.material.E_star if self.material is not None else None
        w0 = self.material.w if self.material is not None and self.material.w else None
        out = {"R_m": parameter_spec("R", None, physical=True, meaning="tip (sphere) radius"),
               "E_star_Pa": parameter_spec("E_star", E, physical=True)}
        if self.adhesive:
            out["w_J_m2"] = parameter_spec("w", w0, physical=True, vary=True)
        if self.has_sigma0:
            s0 = self.material.sigma0 if self.material is not None else None
            out["sigma0_Pa"] = parameter_spec("sigma0", s0, physical=True, vary=True)
        if data.kind == "friction":
            out["tau_Pa"] = parameter_spec("tau", None, physical=True, vary=True)
        if data.kind == "force":
            out["d0_m"] = parameter_spec("d0", 0.0, physical=True)
        return out

    def start(self, data, values: dict) -> dict:
        """Data-driven starts for the parameters still without a value, given the others."""
        v = dict(values)
        R, E = v.get("R_m"), v.get("E_star_Pa")
        if R is None or E is None:
            return v
        if self.adhesive and v.get("w_J_m2") is None:
            v["w_J_m2"] = _estimate_pull_off(data) / (self.pull_off_factor * math.pi * R)
        if self.has_sigma0 and v.get("sigma0_Pa") is None:  # lambda = 1
            v["sigma0_Pa"] = 0.5 * np.cbrt(math.pi * v["w_J_m2"] * (4.0 / 3.0 * E) ** 2 / R)
        if "tau_Pa" in v and v["tau_Pa"] is None:
            v["tau_Pa"] = 1.0
            P = data.x[np.argmax(data.y * (data.x if data.quantity == "mu" else 1.0))]
            F = float(np.max(data.y * (data.x if data.quantity == "mu" else 1.0)))
            a = self.radius(np.array([P]), v)[0][0]
            v["tau_Pa"] = F / (math.pi * a * a) if a > 0 and F > 0 else 1e8
        return v

    pull_off_factor = 1.5

    def radius(self, P, v):
        """Contact radius at loads P (clamped to the pull-off load) and the number clamped."""
        floor = -self.pull_off_value(v)
        clamped = int(np.count_nonzero(P < floor))
        return self.contact_radius(np.maximum(P, floor), v), clamped

    def friction(self, P, v):
        a, clamped = self.radius(P, v)
        return v["tau_Pa"] * math.pi * a * a, clamped

    def curve(self, data, v, x):
        out = super().curve(data, v, x)
        if data.kind == "friction":
            a = self.radius(x, v)[0]
            out = FitCurve({**out.data, "radius_m": a, "area_m2": math.pi * a * a}, dict(v))
        return out

    def pull_off(self, data, v):
        rows = {k: c for k, c in data.conditions.items()}
        return self.pull_off_value({**v, **rows}) * np.ones(len(data))


class HertzFit(_Law):
    name = "hertz"
    title = "Hertz, F = tau pi a^2, a^3 = PR/K"
    kinds = ("friction", "force")
    adhesive = False

    def pull_off_value(self, v):
        return 0.0

    def contact_radius(self, P, v):
        return hertz_contact_radius(P, R=v["R_m"], E_star=v["E_star_Pa"])

    def force(self, d, v):
        delta = v["d0_m"] - d
        return hertz_normal_force(np.maximum(delta, 0.0), R=v["R_m"], E_star=v["E_star_Pa"]), 0


class JKRFit(_Law):
    name = "jkr"
    title = "JKR, F = tau pi a^2"
    kinds = ("friction", "force", "pull_off")

    def pull_off_value(self, v):
        return jkr_pull_off_force(R=v["R_m"], w=v["w_J_m2"])

    def contact_radius(self, P, v):
        return jkr_contact_radius(P, R=v["R_m"], w=v["w_J_m2"], E_star=v["E_star_Pa"])

    def force(self, d, v):
        R, w, K = v["R_m"], v["w_J_m2"], 4.0 / 3.0 * v["E_star_Pa"]
        end = (6.0 ** (-2.0 / 3.0) - math.sqrt(8.0 / 3.0 * 6.0 ** (-1.0 / 3.0))) * np.cbrt(
            math.pi**2 * w * w * R / (K * K)) * (1.0 - 1e-12)
        delta = v["d0_m"] - d
        return jkr_normal_force(np.maximum(delta, end), R=R, w=w, E_star=v["E_star_Pa"]), int(np.sum(delta < end))


class DMTFit(_Law):
    name = "dmt"
    title = "DMT, F = tau pi a^2"
    kinds = ("friction", "force", "pull_off")
    pull_off_factor = 2.0

    def pull_off_value(self, v):
        return dmt_pull_off_force(R=v["R_m"], w=v["w_J_m2"])

    def contact_radius(self, P, v):
        return dmt_contact_radius(P, R=v["R_m"], w=v["w_J_m2"], E_star=v["E_star_Pa"])

    def force(self, d, v):
        delta = v["d0_m"] - d
        return (dmt_normal_force(np.maximum(delta, 0.0), R=v["R_m"], w=v["w_J_m2"], E_star=v["E_star_Pa"]),
                int(np.sum(delta < 0)))


class MDFit(_Law):
    name = "md"
    title = "Maugis-Dugdale (exact), F = tau pi a^2"
    kinds = ("friction", "force", "pull_off")
    has_sigma0 = True
    pull_off_factor = 1.75

    def lam(self, v):
        """The Maugis parameter, clipped to the range the solution handles."""
        lam = float(md_lambda(v["R_m"], v["w_J_m2"], v["E_star_Pa"], v["sigma0_Pa"]))
        return min(max(lam, LAMBDA_RANGE[0]), LAMBDA_RANGE[1])

    def pull_off_value(self, v):
        if np.ndim(v["R_m"]) or np.ndim(v["w_J_m2"]):  # one condition per row
            R, w = np.broadcast_arrays(v["R_m"], v["w_J_m2"])
            return np.array([self.pull_off_value({**v, "R_m": r, "w_J_m2": x}) for r, x in zip(R, w, strict=True)])
        return md_pull_off_force(R=v["R_m"], w=v["w_J_m2"], E_star=v["E_star_Pa"], lam=self.lam(v))

    def contact_radius(self, P, v):
        return md_contact_radius(P, R=v["R_m"], w=v["w_J_m2"], E_star=v["E_star_Pa"], lam=self.lam(v))

    def force(self, d, v):
        R, w, K, lam = v["R_m"], v["w_J_m2"], 4.0 / 3.0 * v["E_star_Pa"], self.lam(v)
        end = md_branch_end(lam).delta * np.cbrt(math.pi**2 * w * w * R / (K * K)) * (1.0 - 1e-12)
        delta = v["d0_m"] - d
        return (md_normal_force(np.maximum(delta, end), R=R, w=w, E_star=v["E_star_Pa"], lam=lam),
                int(np.sum(delta < end)))

    def derived(self, v):
        return {"lam": float(md_lambda(v["R_m"], v["w_J_m2"], v["E_star_Pa"], v["sigma0_Pa"]))}


# -- empirical forms --------------------------------------------------------------------------
class COSFit(FitModel):
    name = "cos"
    title = "Carpick-Ogletree-Salmeron, F = F0 ((alpha_t + sqrt(1 - P/Pc))/(1 + alpha_t))^(4/3)"
    kinds = ("friction",)

    def __init__(self, material=None):
        pass

    def specs(self, data):
        phys = data.physical
        return {s.name: s for s in (parameter_spec("F0", None, physical=phys, vary=True),
                                    parameter_spec("Pc", None, physical=phys, vary=True),
                                    parameter_spec("alpha_t", 0.5, physical=phys, vary=True))}

    def start(self, data, values):
        v = dict(values)
        F = data.y * (data.x if data.quantity == "mu" else 1.0)
        Pc_name, F0_name = ("Pc_N", "F0_N") if data.physical else ("Pc", "F0")
        if v.get(Pc_name) is None:
            v[Pc_name] = -_estimate_pull_off(data)
        if v.get(F0_name) is None:
            i = int(np.argmin(np.abs(data.x)))
            v[F0_name] = max(float(F[i]), float(np.max(F)) * 1e-3, 1e-300)
        return v

    def friction(self, P, v):
        Pc, F0 = (v["Pc_N"], v["F0_N"]) if "Pc_N" in v else (v["Pc"], v["F0"])
        clamped = int(np.count_nonzero(P < Pc))
        return cos_friction(np.maximum(P, Pc), F0=F0, Pc=Pc, alpha_t=v["alpha_t"]), clamped


class AmontonsFit(FitModel):
    name = "amontons"
    title = "Amontons with an adhesion offset, F = mu0 (P + P0)"
    kinds = ("friction",)

    def __init__(self, material=None):
        pass

    def specs(self, data):
        phys = data.physical
        return {s.name: s for s in (parameter_spec("mu0", None, physical=phys, vary=True),
                                    parameter_spec("P0", None, physical=phys, vary=True))}

    def start(self, data, values):
        v = dict(values)
        P0_name = "P0_N" if data.physical else "P0"
        F = data.y * (data.x if data.quantity == "mu" else 1.0)
        slope, intercept = np.polyfit(data.x, F, 1) if len(data) > 1 else (F[0] / data.x[0], 0.0)
        slope = slope if slope > 0 else float(np.max(F) / max(np.max(np.abs(data.x)), 1e-300))
        if v.get("mu0") is None:
            v["mu0"] = slope
        if v.get(P0_name) is None:
            v[P0_name] = max(intercept / slope, -float(np.min(data.x)))
        return v

    def friction(self, P, v):
        P0 = v["P0_N"] if "P0_N" in v else v["P0"]
        clamped = int(np.count_nonzero(P < -P0))
        return amontons_friction(np.maximum(P, -P0), mu0=v["mu0"], P0=P0), clamped


def _gw():
    from .gw import GWFit

    return GWFit


#: Model name -> class (``gw`` resolved on first use).
MODELS = {"gw": None, "hertz": HertzFit, "jkr": JKRFit, "dmt": DMTFit, "md": MDFit, "cos": COSFit,
          "amontons": AmontonsFit}


def get_model(name, *, material=None, contact=None) -> FitModel:
    """The :class:`FitModel` called ``name`` (a name of :data:`MODELS`, case-insensitive).

    Parameters
    ----------
    name : str or FitModel
        Model name, or a model (returned as is).
    material : Material or str, optional
        Material of the single-asperity laws (their ``E_star_Pa``, and ``w_J_m2`` and
        ``sigma0_Pa`` starts).
    contact : PhysicalContact, optional
        The physical multi-asperity contact (``gw`` on physical data).

    Raises
    ------
    ValueError
        For an unknown name (the message lists the valid ones).
    """
    if isinstance(name, FitModel):
        return name
    key = str(name).strip().lower()
    if key not in MODELS:
        raise ValueError(f"unknown model {name!r}; valid: {', '.join(MODELS)}")
    if key == "gw":
        return _gw()(contact=contact, material=material)
    return MODELS[key](material=material)
