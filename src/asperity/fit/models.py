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

from .base import FitCurve, FitModel, ParameterSpec, parameter_spec
from .laws import AmontonsFit, COSFit, DMTFit, HertzFit, JKRFit, MDFit

__all__ = ["ParameterSpec", "FitCurve", "FitModel", "MODELS", "get_model", "parameter_spec"]


def _gw():
    from .gw import GWFit

    return GWFit


#: Model name -> class (``gw`` resolved on first use).
MODELS = {"gw": None, "hertz": HertzFit, "jkr": JKRFit, "dmt": DMTFit, "md": MDFit, "cos": COSFit,
          "amontons": AmontonsFit}


def model_class(key: str) -> type:
    """The :class:`FitModel` subclass registered as ``key`` (a lower-case name of :data:`MODELS`)."""
    return _gw() if key == "gw" else MODELS[key]


def _take(names) -> str:
    """The phrase naming ``names`` with its verb: model 'x' takes, or models 'x', 'y' take."""
    return f"model {names[0]!r} takes" if len(names) == 1 else f"models {', '.join(map(repr, names))} take"


def material_refusal(*names: str) -> str:
    """The message refusing ``material=`` for the models ``names``, which take none."""
    return (f"material: {_take(names)} no material; only the single-asperity laws (hertz, jkr, dmt, md) "
            "do (their E_star_Pa and starts); the physical gw model takes its material from its contact "
            "(contact=PhysicalContact(...); --material with --sigma-s, --R, --eta, --area or --surface)")


def contact_refusal(*names: str) -> str:
    """The message refusing ``contact=`` for the models ``names``, which take none."""
    return (f"contact: {_take(names)} no contact; only the rough-surface model gw does (a physical contact: "
            "--material with --sigma-s, --R, --eta, --area or --surface); the single-asperity laws take "
            "material= and the tip radius R_m")


def _given_model(model: FitModel, material, contact) -> FitModel:
    """A model object with ``material`` and ``contact``: itself, or a copy of a law given the
    material it lacks; a material or contact it takes none of, or other than its own, is refused."""
    if material is not None:
        if not model.uses_material:
            raise ValueError(material_refusal(model.name))
        from ..materials import as_material

        own = getattr(model, "material", None)
        if own is None:
            model = type(model)(material=material)
        elif own != as_material(material):
            raise ValueError(f"material: model {model.name!r} was built with material {own.name!r}; give "
                             "the material once (to the model or as material=)")
    if contact is not None:
        if not model.uses_contact:
            raise ValueError(contact_refusal(model.name))
        if model.contact is None and model.name == "gw":  # a plain GWFit(): the contact's fit
            return type(model)(contact=contact)
        if model.contact is None:
            raise ValueError(f"contact: model {model.name!r} has its own summit heights or law, but a physical fit "
                             "takes those of its contact: give them to the PhysicalContact (heights=..., "
                             "plasticity='jackson-green', adhesion=False) and fit 'gw' with contact=")
        if model.contact is not contact:
            raise ValueError(f"contact: model {model.name!r} was built with another contact; give the contact once "
                             "(GWFit(contact=...) or as contact=)")
    return model


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
        For an unknown name (the message lists the valid ones), a material for a model that
        takes none (``gw``, ``cos``, ``amontons``), a contact for a model other than ``gw``,
        or a model object given another material or contact than its own: refused, never
        ignored.
    """
    if isinstance(name, FitModel):
        return _given_model(name, material, contact)
    key = str(name).strip().lower()
    if key not in MODELS:
        raise ValueError(f"unknown model {name!r}; valid: {', '.join(MODELS)}")
    cls = model_class(key)
    if material is not None and not cls.uses_material:
        raise ValueError(material_refusal(key))
    if contact is not None and not cls.uses_contact:
        raise ValueError(contact_refusal(key))
    if key == "gw":
        return _gw()(contact=contact, material=material)
    return MODELS[key](material=material)
