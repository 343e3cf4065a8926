r"""The multi-asperity model as a fit model: dimensionless, or physical through :class:`PhysicalContact`.

*Dimensionless* data (the paper's units: :math:`P/NGb^2`, :math:`F/NGb^2`, :math:`d/\sigma`)
are fitted with :class:`asperity.Model` and the parameters ``alpha``, ``beta``, ``gamma``
(varied by default), ``nu``, ``h_over_b`` and the Hurtado-Kim constants ``tau_f1``,
``tau_f2``, ``a1``, ``a2`` (fixed at the paper's values unless varied), with Gaussian
summit heights or those given (``GWFit(heights=...)``, passed as the ``model``).  With the
Jackson-Green elastic-plastic law (``GWFit(law=JacksonGreen(H_over_E, h_star_over_sigma))``,
non-adhesive) the model has no ``gamma`` and gains ``H_over_E`` and ``h_star_over_sigma``,
fixed at the law's values unless varied (``vary=["alpha", "beta", "H_over_E"]`` fits the
hardness).

*Physical* data (newtons, metres) need a :class:`~asperity.physical.PhysicalContact`, which
gives the material (:math:`E`, :math:`\nu`, hence :math:`E^*` and :math:`G^*`, fixed) and the
start values of ``sigma_s_m``, ``R_m``, ``eta_per_m2``, ``area_m2`` (the surface),
``w_J_m2``, ``b_m``, ``h_m`` and the friction law's: the Hurtado-Kim shear strengths
``tau1_Pa`` :math:`= \bar\tau_{f1}G^*` and ``tau2_Pa`` :math:`= \bar\tau_{f2}G^*` with ``a1``,
``a2``, or, for a contact with a constant shear strength (``friction=ConstantShear(...)``,
command line ``--tau``), the one ``tau_Pa`` :math:`= \bar\tau_f G^*`.  ``w_J_m2`` (unless the
contact has no adhesion) and ``tau1_Pa``, ``tau2_Pa`` (or ``tau_Pa``) vary by default.  Each
evaluation builds the contact for the current values and uses its dimensionless model and scales, exactly as
:meth:`PhysicalContact.load_curve` does.  ``eta_per_m2`` and ``area_m2`` enter only
through :math:`N = \eta A_0`: vary at most one of them.

Loads more tensile than the model's pull-off force (or, without adhesion, loads <= 0) have
no equilibrium; they are compared with the friction at the pull-off (0 without adhesion)
and counted.  Evaluated models are cached by their parameter values, so a Jacobian column
that leaves a data set's parameters unchanged costs nothing.
"""

from __future__ import annotations

from collections import OrderedDict
from dataclasses import replace

import numpy as np

from ..curves import Model
from ..elastic_plastic import Elastic, JacksonGreen
from ..friction_stress import ConstantShear, HurtadoKim
from ..groups import maugis_lambda
from ..heights import GAUSSIAN, check_heights
from ..physical import PhysicalContact
from ..surface import Surface
from ..tabulation import D_MIN
from .base import FitCurve, FitModel, parameter_spec

__all__ = ["GWFit", "HK_NAMES"]

#: The Hurtado-Kim constants, dimensionless names.
HK_NAMES = ("tau_f1", "tau_f2", "a1", "a2")
_CACHE_SIZE = 32


class GWFit(FitModel):
    """The multi-asperity model of the paper (see the module docstring).

    Parameters
    ----------
    contact : PhysicalContact, optional
        Needed for physical data: the material and the start values.
    material : None
        Refused if given (the contact holds the material); accepted so all models are built alike.
    heights : HeightDistribution, optional
        Summit heights of the dimensionless model (default the Gaussian, Eq 19), e.g.
        ``asperity.heights.Weibull(skew=0.5)``; a physical fit takes the contact's.
    law : Elastic or JacksonGreen, optional
        Per-asperity law of the dimensionless model (:mod:`asperity.elastic_plastic`; default
        elastic); a physical fit takes the contact's.

    Examples
    --------
    >>> from asperity.heights import Weibull
    >>> GWFit(heights=Weibull(skew=0.5)).heights
    Weibull(skew=0.5)
    """

    name = "gw"
    uses_contact = True
    title = "multi-asperity (Greenwood-Williamson + Hurtado-Kim + Maugis-Dugdale)"
    kinds = ("friction", "force", "pull_off")

    def __init__(self, contact=None, material=None, heights=None, law=None):
        if contact is not None and not isinstance(contact, PhysicalContact):
            raise ValueError(f"contact must be an asperity.physical.PhysicalContact, got {type(contact).__name__}")
        if heights is not None and contact is not None:
            raise ValueError("heights: a physical fit takes the contact's summit heights; give them to the "
                             "PhysicalContact (heights=...) instead")
        if material is not None:
            from .models import material_refusal

            raise ValueError(material_refusal(self.name))
        if law is not None and contact is not None:
            raise ValueError("law: a physical fit takes the contact's per-asperity law; give it to the "
                             "PhysicalContact (plasticity=..., hardness=...) instead")
        if law is not None and not isinstance(law, Elastic | JacksonGreen):
            raise ValueError("law must be asperity.elastic_plastic.Elastic() or JacksonGreen(H_over_E, "
                             f"h_star_over_sigma) (e.g. make_law('jackson-green', H_over_E=0.01)), got {law!r:.80}")
        self.contact = contact
        self.heights = GAUSSIAN if heights is None else check_heights(heights)
        self.law = law if isinstance(law, JacksonGreen) else None
        named = [] if self.law is None else [_law_label(self.law)]
        if self.heights != GAUSSIAN:
            named.append(f"heights {self.heights.spec or repr(self.heights)}")
        if named:  # the result names the model it fitted
            self.name = f"gw ({'; '.join(named)})"
        self._cache: OrderedDict = OrderedDict()

    def check(self, data):
        super().check(data)
        if data.physical and self.contact is None:
            raise ValueError("model 'gw' on physical data needs a contact (PhysicalContact: material and surface; "
                             "--material, --sigma-s, --R, --eta, --area)")
        if self.law is not None and data.kind == "pull_off":
            raise ValueError(f"model {self.name!r}: the Jackson-Green law has no adhesion, hence no pull-off force; "
                             "pull-off data need the elastic law (with gamma)")
        if not data.physical and self.contact is not None:
            raise ValueError("a contact was given but the data are dimensionless (P, F, d): drop the contact, or "
                             "give the data in physical units")

    # -- parameters ---------------------------------------------------------------------
    def specs(self, data):
        force = data.kind == "force"
        if not data.physical:
            from ..quantities import MODEL_PARAMETERS as M

            adhesive = [parameter_spec("gamma", 1e-3, physical=False, vary=True)] if self.law is None else [
                parameter_spec("H_over_E", self.law.H_over_E, physical=False),
                parameter_spec("h_star_over_sigma", self.law.h_star_over_sigma, physical=False)]
            specs = [parameter_spec("alpha", 0.01, physical=False, vary=True),
                     parameter_spec("beta", 1000.0, physical=False, vary=True), *adhesive,
                     parameter_spec("nu", M["nu"].default, physical=False),
                     parameter_spec("h_over_b", M["h_over_b"].default, physical=False),
                     *(parameter_spec(n, M[n].default, physical=False) for n in HK_NAMES)]
            if force:
                specs.append(parameter_spec("d0", 0.0, physical=False))
            return {s.name: s for s in specs}
        c = self.contact
        s = c.surface
        specs = [parameter_spec("sigma_s", s.sigma_s, physical=True), parameter_spec("R", s.R, physical=True),
                 parameter_spec("eta", s.eta, physical=True), parameter_spec("area", s.area, physical=True),
                 parameter_spec("w", c.w, physical=True, vary=c.w > 0), parameter_spec("b", c.b, physical=True),
                 parameter_spec("h", c.h, physical=True), *_friction_specs(c)]
        if force:
            specs.append(parameter_spec("d0", 0.0, physical=True))
        return {p.name: p for p in specs}

    def start(self, data, values):
        return dict(values)

    # -- the model for given values -------------------------------------------------------
    def _build(self, v: dict):
        """(dimensionless Model, force scale, separation scale, contact or None), cached."""
        key = tuple(sorted((k, float(x)) for k, x in v.items()))
        hit = self._cache.get(key)
        if hit is not None:
            self._cache.move_to_end(key)
            return hit
        if self.contact is None:
            law = None if self.law is None else JacksonGreen(v["H_over_E"], v["h_star_over_sigma"])
            model = Model(v["alpha"], v["beta"], v.get("gamma", 0.0), nu=v["nu"], h_over_b=v["h_over_b"],
                          friction=HurtadoKim(*(v[n] for n in HK_NAMES)), heights=self.heights, law=law)
            built = (model, 1.0, 1.0, None)
        else:
            c = self.contact
            G_star = c.G_star
            material = replace(c.material, w=v["w_J_m2"], b=v["b_m"], h=None, sigma0=None)
            surface = Surface(v["sigma_s_m"], v["R_m"], v["eta_per_m2"], v["area_m2"])
            friction = ConstantShear(v["tau_Pa"] / G_star) if "tau_Pa" in v else \
                HurtadoKim(v["tau1_Pa"] / G_star, v["tau2_Pa"] / G_star, v["a1"], v["a2"])
            # everything else as the given contact: adhesion, heights, plasticity, interaction
            contact = PhysicalContact(material, surface, h=v["h_m"], friction=friction, adhesion=c.adhesion,
                                      heights=c.heights, **_law_of(c))
            built = (contact.model, contact.force_scale, surface.sigma_s, contact)
        self._cache[key] = built
        if len(self._cache) > _CACHE_SIZE:
            self._cache.popitem(last=False)
        return built

    def friction(self, P, v):
        model, fs, _, _ = self._build(v)
        F, clamped = _friction(model, np.asarray(P, dtype=float) / fs)
        return F * fs, clamped

    def force(self, d, v):
        model, fs, ds, _ = self._build(v)
        d0 = v["d0_m"] if "d0_m" in v else v["d0"]
        d_bar = (np.asarray(d, dtype=float) - d0) / ds
        inside = np.clip(d_bar, D_MIN, model.d_top)
        return model.separation_curve(inside).P * fs, int(np.count_nonzero(inside != d_bar))

    def pull_off(self, data, v):
        rows = data.conditions
        out = np.empty(len(data))
        for i in range(len(data)):
            row = {**v, **{k: float(c[i]) for k, c in rows.items()}}
            model, fs, _, _ = self._build(row)
            out[i] = model.pull_off().force * fs
        return out

    # -- results --------------------------------------------------------------------------
    def curve(self, data, v, x):
        if data.kind == "pull_off":
            return FitCurve({"row": data.x, "pull_off_N" if data.physical else "pull_off": self.pull_off(data, v),
                             **data.conditions}, dict(v))
        model, fs, ds, contact = self._build(v)
        if data.kind == "friction":
            grid = np.asarray(x, dtype=float) / fs
            if np.min(grid) <= 0:
                floor = _pull_off_load(model)
                grid = np.unique(np.maximum(grid, floor)) if floor is not None else grid[grid > 0]
            if contact is not None:
                return contact.load_curve(grid * fs)
            return model.load_curve(grid)
        if data.kind == "force":
            d0 = v["d0_m"] if "d0_m" in v else v["d0"]
            d_bar = np.clip((np.asarray(x, dtype=float) - d0) / ds, D_MIN, model.d_top)
            if contact is not None:
                return replace(contact.separation_curve(d_bar * ds), d=d_bar * ds + d0)
            return replace(model.separation_curve(d_bar), d=d_bar + d0)

    def derived(self, v):
        needed = (("alpha", "beta", "h_over_b") if self.contact is None else
                  ("sigma_s_m", "R_m", "eta_per_m2", "area_m2", "w_J_m2", "b_m", "h_m"))
        if any(name not in v for name in needed):
            return {}  # some are given per row (pull-off conditions)
        if self.contact is None:
            if self.law is not None:
                return {}  # no adhesion, no lambda
            if v.get("gamma", 0.0) <= 0:
                return {"lam": 0.0}
            return {"lam": float(maugis_lambda(v["alpha"], v["beta"], v["gamma"], v["h_over_b"]))}
        contact = self._build(v)[3]
        return {"alpha": contact.alpha, "beta": contact.beta, "gamma": contact.gamma, "lam": contact.lam}


def _law_of(contact) -> dict:
    """The per-asperity law, hardness, size effect, yield threshold and interaction of
    ``contact``, as keyword arguments of :class:`PhysicalContact`, for the contacts a fit builds."""
    size = contact.h_star > 0.0
    return {"plasticity": contact.law, "hardness": contact.hardness, "size_effect": size,
            "h_star": contact.h_star if size else None, "plastic_threshold": contact.plastic_threshold,
            "interaction": contact.interaction.name}


def _friction_specs(contact) -> list:
    """The friction law's parameters of a physical fit: ``tau_Pa`` (varied) for a constant
    shear strength (the contact's ``friction=ConstantShear``, command line ``--tau``), else
    the Hurtado-Kim ``tau1_Pa``, ``tau2_Pa`` (varied), ``a1``, ``a2``."""
    law = contact.model.params.friction
    if isinstance(law, ConstantShear):
        return [parameter_spec("tau", law.tau * contact.G_star, physical=True, vary=True,
                               meaning="constant friction stress (Bowden-Tabor), tau_f G*")]
    if isinstance(law, HurtadoKim):
        return [parameter_spec("tau1", law.tau_f1 * contact.G_star, physical=True, vary=True),
                parameter_spec("tau2", law.tau_f2 * contact.G_star, physical=True, vary=True),
                parameter_spec("a1", law.a1, physical=False), parameter_spec("a2", law.a2, physical=False)]
    raise ValueError("model 'gw' fits the Hurtado-Kim or a constant friction stress; the contact has "
                     f"{type(law).__name__}")


def _pull_off_load(model: Model) -> float | None:
    """Minus the model's pull-off force (its most tensile load), or None if it has none."""
    if not model.params.adhesive:
        return None
    po = model.pull_off()
    return -po.force * (1.0 - 1e-12) if po.exists and po.force > 0 else None


def _friction(model: Model, P):
    """Friction at loads P (dimensionless) with infeasible loads clamped; (F, number clamped).

    Loads below the pull-off load are evaluated at it; without a tensile branch (no
    adhesion, or a negligible one) loads <= 0 get F = 0, the limit of a vanishing contact.
    """
    if np.min(P) > 0:
        return model.load_curve(P).F, 0
    floor = _pull_off_load(model)
    if floor is not None:
        return model.load_curve(np.maximum(P, floor)).F, int(np.count_nonzero(P < floor))
    ok = P > 0
    F = np.zeros_like(P)
    if np.any(ok):
        F[ok] = model.load_curve(P[ok]).F
    return F, int(np.count_nonzero(~ok))


def _law_label(law) -> str:
    """The Jackson-Green law as the fit's model name shows it, its start values included.

    So that two plastic models with different hardness are told apart (in a ranking, say).
    """
    label = f"{law.name} H/E*={law.H_over_E:g}"
    return label + (f" h*/sigma={law.h_star_over_sigma:g}" if law.h_star_over_sigma else "")
