r"""The single-asperity friction laws and the empirical forms as fit models (SI units for the laws).

``hertz``, ``jkr``, ``dmt`` and ``md``: :math:`F = \tau\pi a(P)^2` with the contact radius of
:func:`~asperity.hertz.hertz_contact_radius`, :func:`~asperity.jkr.jkr_contact_radius`,
:func:`~asperity.dmt.dmt_contact_radius` and the exact Maugis-Dugdale
:func:`~asperity.maugis_dugdale_load.md_contact_radius`; the normal force at penetration
:math:`\delta = d_0 - d` (displacement control) and the pull-off force.  ``cos`` and
``amontons``: :func:`~asperity.cos.cos_friction` and
:func:`~asperity.amontons.amontons_friction`, in either units.  Loads below a model's
pull-off load are compared with its value at the pull-off, and counted.
"""

from __future__ import annotations

import math

import numpy as np

from ..amontons import amontons_friction
from ..cos import cos_friction
from ..dmt import dmt_contact_radius, dmt_normal_force, dmt_pull_off_force
from ..hertz import hertz_contact_radius, hertz_normal_force
from ..jkr import jkr_contact_radius, jkr_normal_force, jkr_pull_off_force
from ..materials import as_material
from ..maugis_dugdale import LAMBDA_RANGE, md_branch_end, md_lambda
from ..maugis_dugdale_load import md_contact_radius, md_normal_force, md_pull_off_force
from .base import FitCurve, FitModel, parameter_spec
from .data import Dataset

__all__ = ["HertzFit", "JKRFit", "DMTFit", "MDFit", "COSFit", "AmontonsFit"]


def _estimate_pull_off(data: Dataset) -> float:
    """A start for the pull-off force from friction-load data: past the most tensile load."""
    if data.kind == "pull_off":
        return float(np.median(data.y))
    P_min = float(np.min(data.x))
    span = float(np.max(data.x) - P_min)
    return max(1.2 * -P_min, 0.05 * span, 1e-300)


class _Law(FitModel):
    """F = tau pi a(P)^2 for one asperity (SI units)."""

    physical = True
    adhesive = True
    has_sigma0 = False
    uses_material = True

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
        """Data-driven starts for the parameters still without a value, given the others.

        A varied offset ``d0_m`` without a start (the engine leaves it empty, :data:`DATA_STARTS`)
        starts at the largest separation where the force is still 2 % of its largest
        compressive value: the contact edge, near which the model carries force (from 0, data
        at positive separations carry none and the offset would be undetermined)."""
        v = dict(values)
        if "d0_m" in v and v["d0_m"] is None and data.kind == "force":
            pressed = data.y > 0.02 * float(np.max(data.y)) if np.max(data.y) > 0 else np.zeros(len(data), bool)
            v["d0_m"] = float(np.max(data.x[pressed])) if pressed.any() else float(np.max(data.x))
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

    def pull_off_value(self, v):  # broadcasts over a radius or work of adhesion per row
        lam = np.clip(md_lambda(v["R_m"], v["w_J_m2"], v["E_star_Pa"], v["sigma0_Pa"]), *LAMBDA_RANGE)
        return md_pull_off_force(R=v["R_m"], w=v["w_J_m2"], E_star=v["E_star_Pa"], lam=lam)

    def contact_radius(self, P, v):
        return md_contact_radius(P, R=v["R_m"], w=v["w_J_m2"], E_star=v["E_star_Pa"], lam=self.lam(v))

    def force(self, d, v):
        R, w, K, lam = v["R_m"], v["w_J_m2"], 4.0 / 3.0 * v["E_star_Pa"], self.lam(v)
        end = md_branch_end(lam).delta * np.cbrt(math.pi**2 * w * w * R / (K * K)) * (1.0 - 1e-12)
        delta = v["d0_m"] - d
        return (md_normal_force(np.maximum(delta, end), R=R, w=w, E_star=v["E_star_Pa"], lam=lam),
                int(np.sum(delta < end)))

    def derived(self, v):
        if "R_m" not in v:  # pull-off data with a radius per row: no single lambda
            return {}
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
        if len(np.unique(data.x)) > 1:
            slope, intercept = np.polyfit(data.x, F, 1)
        else:  # one load (repeated): no line through the points, the ratio is the start
            slope, intercept = float(np.mean(F) / data.x[0]) if data.x[0] else 0.0, 0.0
        slope = slope if slope > 0 else float(np.max(F) / max(np.max(np.abs(data.x)), 1e-300))
        if v.get("mu0") is None:
            v["mu0"] = slope
        if v.get(P0_name) is None:
            v[P0_name] = max(intercept / slope, -float(np.min(data.x))) if slope > 0 else 0.0
        return v

    def friction(self, P, v):
        P0 = v["P0_N"] if "P0_N" in v else v["P0"]
        clamped = int(np.count_nonzero(P < -P0))
        return amontons_friction(np.maximum(P, -P0), mu0=v["mu0"], P0=P0), clamped
