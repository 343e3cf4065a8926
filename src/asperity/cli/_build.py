"""From parsed command-line arguments to the library's objects.

:func:`is_physical` tells a physical contact (``--material``, ``--sigma-s``, ...) from the
dimensionless model (``--alpha``, ``--beta``); :func:`model_from_args` builds the
:class:`asperity.Model`, :func:`contact_from_args` the :class:`asperity.PhysicalContact` (with
:func:`material_from_args`, :func:`surface_from_args`, :func:`friction_from_args`,
:func:`heights_from_args` and :func:`interaction_from_args`); :func:`title` names either in
one line.  The library checks every value (its ValueError names the parameter, which is the
option's name without dashes); only the combination of options is checked here.  The options themselves are defined in
:mod:`asperity.cli._args`.

Nothing here imports NumPy, SciPy or the model at module level.
"""

from __future__ import annotations

from .._numbers import FloatUnderflow, strict_float
from .._warnings import AsperityWarning
from ._args import CONTACT_OPTIONS
from ._lists import UsageError, optional_quantity, quantity, quantity_items

__all__ = ["is_physical", "model_from_args", "law_from_args", "contact_from_args", "surface_from_args",
           "friction_from_args", "interaction_from_args",
           "material_from_args", "heights_from_args", "title", "SurfaceNote"]


def _given(args, names) -> list[str]:
    """The options among ``names`` (dest names) that were given, as ``--flags``."""
    return [f"--{n.replace('_', '-')}" for n in names if getattr(args, n, None) not in (None, False)]


def is_physical(args) -> bool:
    """True for a physical contact (``--material``, ``--E``, ``--sigma-s``, ...), False for ``--alpha``/``--beta``.

    Raises
    ------
    UsageError
        For a mixture of the two, or a missing alpha/beta.
    """
    physical = _given(args, (*CONTACT_OPTIONS, "no_adhesion"))
    if physical:
        dimensionless = _given(args, ("alpha", "beta", "gamma", "h_over_b"))
        if dimensionless:
            raise UsageError(f"give either the dimensionless model ({', '.join(dimensionless)}) or a physical "
                             f"contact ({', '.join(physical)}), not both")
        return True
    if getattr(args, "alpha", None) is None or getattr(args, "beta", None) is None:
        raise UsageError("the model needs --alpha and --beta (or a physical contact: --material with --sigma-s, "
                         "--R, --eta and --area)")
    return False


def heights_from_args(args):
    """The height distribution of ``--heights`` (the Gaussian without it), read by
    :func:`asperity.heights.parse_heights`."""
    from ..heights import GAUSSIAN, parse_heights

    spec = getattr(args, "heights", None)
    return GAUSSIAN if spec is None else parse_heights(spec)


def _number(text, name: str):
    """A dimensionless option's text as a float (None stays None)."""
    if text is None:
        return None
    try:
        return strict_float(text)
    except ValueError as err:
        shown = repr(text) if len(text) <= 60 else repr(text[:60]) + "..."
        why = f" ({err})" if isinstance(err, FloatUnderflow) else ""
        raise UsageError(f"{name}: expected a number (dimensionless, without a physical contact), "
                         f"got {shown}{why}") from None


def model_from_args(args):
    """The :class:`asperity.Model` of ``--alpha --beta --gamma --nu --h-over-b``, the friction
    constants and ``--law --hardness --h-star``."""
    from ..curves import Model

    for option, value in (("--size-effect", args.size_effect or None), ("--plastic-threshold", args.plastic_threshold)):
        if value is not None:
            raise UsageError(f"{option} applies to a physical contact (--material ...); without it give "
                             "--hardness H/E* and --h-star h*/sigma")
    law = law_from_args(args)
    nu = 0.3 if args.nu is None else args.nu
    h_over_b = 1.0 if args.h_over_b is None else args.h_over_b
    friction = friction_from_args(args, physical=False)
    kwargs = {} if friction is None else {"friction": friction}
    interaction = interaction_from_args(args, physical=False)
    if interaction is not None:
        kwargs["interaction"] = interaction
    return Model(args.alpha, args.beta, args.gamma or 0.0, nu=nu, h_over_b=h_over_b, law=law,
                 heights=heights_from_args(args), **kwargs)


def interaction_from_args(args, *, physical: bool):
    """The asperity interaction of ``--interaction SPEC`` (None without it or for ``none``).

    ``none`` or ``cgp2008`` (Ciavarella, Greenwood & Paggi 2008, :mod:`asperity.interaction`).
    A physical contact takes the name (its compliance follows from eta, A0, b and sigma_s);
    the dimensionless model takes ``cgp2008:k=K``, a
    :class:`~asperity.interaction.MeanFieldInteraction` of compliance K.  The correction is
    non-adhesive: with adhesion (no ``--no-adhesion``, or ``--gamma`` > 0) it is refused here
    with the option to add, before the library's refusal in its own words.
    """
    spec = getattr(args, "interaction", None)
    if spec is None:
        return None
    name, _, rest = spec.strip().partition(":")
    name = name.strip().lower()
    from ..interaction import INTERACTIONS

    if name not in INTERACTIONS:
        raise UsageError(f"--interaction: expected one of {', '.join(INTERACTIONS)} (cgp2008:k=K without a "
                         f"physical contact), got {spec!r}")
    if name == "none":
        if rest:
            raise UsageError(f"--interaction none takes no parameter, got {spec!r}")
        return None
    if physical:
        if rest:
            raise UsageError(f"--interaction {name}: with a physical contact the compliance follows from eta, "
                             f"A0, b and sigma_s; give --interaction {name} without ':k=...'")
        if not args.no_adhesion:
            raise UsageError(f"--interaction {name} (Ciavarella, Greenwood & Paggi 2008) is derived for "
                             "non-adhesive contact: add --no-adhesion")
        return name
    key, eq, value = rest.partition("=")
    if key.strip().lower() != "k" or not eq:
        raise UsageError(f"--interaction {name}: the dimensionless model needs its compliance, e.g. "
                         f"{name}:k=0.05 (or a physical contact, --material ...), got {spec!r}")
    k = _number(value.strip(), f"--interaction {name}:k")
    if not k >= 0.0 or k == float("inf"):
        raise UsageError(f"--interaction {name}:k must be a finite number >= 0, got {value.strip()!r}")
    if args.gamma:
        raise UsageError(f"--interaction {name} (Ciavarella, Greenwood & Paggi 2008) is derived for "
                         "non-adhesive contact: leave out --gamma (or give --gamma 0)")
    from ..interaction import MeanFieldInteraction

    return MeanFieldInteraction(k)


def law_from_args(args):
    """The dimensionless per-asperity law of ``--law --hardness --h-star`` (H/E*, h*/sigma as
    numbers): :func:`asperity.elastic_plastic.make_law`'s spec; its ValueError names the option."""
    from ..elastic_plastic import make_law

    return make_law(args.law or "elastic", H_over_E=_number(args.hardness, "--hardness"),
                    h_star_over_sigma=_number(args.h_star, "--h-star"))


def friction_from_args(args, *, physical: bool):
    """``--tau`` (Pa, physical only), a :class:`~asperity.HurtadoKim` of the constants given, or None."""
    constants = {n: getattr(args, n) for n in ("tau_f1", "tau_f2", "a1", "a2") if getattr(args, n, None) is not None}
    tau = getattr(args, "tau", None)
    if tau is not None:
        if constants:
            raise UsageError("give --tau (a constant shear strength) or the Hurtado-Kim constants "
                             f"({', '.join(_given(args, constants))}), not both")
        if not physical:
            raise UsageError("--tau is a stress in Pa: it needs a physical contact (--material ...)")
        return quantity(tau, "Pa", "--tau")
    if constants:
        from ..friction_stress import HurtadoKim

        return HurtadoKim(**constants)
    return None


def _check_surface_options(args) -> None:
    """One way to give the surface, and --area (the combination only; the library checks values)."""
    if args.surface is not None:
        clash = _given(args, ("sigma_s", "rms", "alpha_n", "R", "eta"))
        if clash:
            raise UsageError(f"--surface gives sigma_s, R and eta: not with {', '.join(clash)}")
    else:
        stray = _given(args, ("size", "unit", "method"))
        if stray:
            raise UsageError(f"{', '.join(stray)} {'applies' if len(stray) == 1 else 'apply'} only with --surface FILE")
        if args.sigma_s is not None and args.rms is not None:
            raise UsageError("give --sigma-s (summit heights) or --rms (all heights, with --bandwidth), not both")
        if args.rms is not None and args.alpha_n is None:
            raise UsageError("--rms needs --bandwidth ALPHA_N (Nayak's m0 m4/m2^2; 'asperity surface' measures "
                             "it) to give sigma_s = (1 - 0.8968/alpha_N)^(1/2) rms; or give --sigma-s")
        if args.alpha_n is not None and args.rms is None:
            raise UsageError("--bandwidth only applies with --rms")
        missing = [flag for flag, v in (("--sigma-s (or --rms)", args.sigma_s or args.rms), ("--R", args.R),
                                        ("--eta", args.eta)) if v is None]
        if missing:
            raise UsageError(f"a physical contact needs the surface: {', '.join(missing)} (or --surface FILE)")
    if args.area is None:
        raise UsageError("a physical contact needs --area (the nominal contact area, e.g. 1mm^2)")


def surface_from_args(args):
    """The :class:`asperity.surface.Surface` of the surface options (a scan's through the library)."""
    from ..surface import Surface

    _check_surface_options(args)
    area = quantity(args.area, "m^2", "--area")
    if args.surface is not None:
        import warnings

        from .._optional import require

        require("SurfaceTopography", purpose="--surface", extra="topography")
        from ..topography import analyse_surface

        kwargs = {} if args.size is None else {"physical_sizes": tuple(quantity_items(args.size, "m", "--size"))}
        if args.unit is not None:
            kwargs["unit"] = args.unit
        analysis = analyse_surface(args.surface, **kwargs)
        for message in analysis.warnings:  # printed as notes once the command succeeds
            warnings.warn(f"surface {args.surface}: {message}", SurfaceNote, stacklevel=1)
        return analysis.surface(area, method=args.method or "spectral")
    R, eta = quantity(args.R, "m", "--R"), quantity(args.eta, "1/m^2", "--eta")
    if args.rms is not None:
        return Surface.from_rms(quantity(args.rms, "m", "--rms"), R, eta, area, alpha_n=args.alpha_n)
    return Surface(quantity(args.sigma_s, "m", "--sigma-s"), R, eta, area)


class SurfaceNote(AsperityWarning):
    """A scan's reason for doubt (:attr:`asperity.topography.SurfaceAnalysis.warnings`): an
    :class:`asperity.AsperityWarning`, so :func:`asperity.cli.run_with_notes` prints it as a note."""


def material_from_args(args):
    """The :class:`asperity.materials.Material` of the bodies' options (``--material --E --nu
    --material2 --E2 --nu2 --b --w --h --sigma0``) through :func:`asperity.bodies.contact_material`;
    the library checks every value."""
    from ..bodies import contact_material

    return contact_material(args.material, E=optional_quantity(args.E, "Pa", "--E"), nu=getattr(args, "nu", None),
                            material2=args.material2, E2=optional_quantity(args.E2, "Pa", "--E2"), nu2=args.nu2,
                            b=optional_quantity(args.b, "m", "--b"),
                            w=optional_quantity(getattr(args, "w", None), "J/m^2", "--w"),
                            h=optional_quantity(getattr(args, "h", None), "m", "--h"),
                            sigma0=optional_quantity(getattr(args, "sigma0", None), "Pa", "--sigma0"))


def contact_from_args(args):
    """The :class:`asperity.physical.PhysicalContact` of the physical-contact and plasticity options.

    The bodies go through :func:`material_from_args`, the surface through
    :func:`surface_from_args`, the friction law through :func:`friction_from_args`, the
    per-asperity law from ``--law --hardness --h-star --size-effect --plastic-threshold``;
    the library checks every value.
    """
    from ..physical import PhysicalContact

    threshold = args.plastic_threshold
    kwargs = {} if threshold is None else {"plastic_threshold": threshold}
    if args.no_adhesion:  # options that would be silently ignored
        given = [f"--{n.replace('_', '-')}" for n in ("w", "h", "sigma0") if getattr(args, n, None) is not None]
        if given:
            raise UsageError(f"{', '.join(given)} describe the adhesion, which --no-adhesion turns off: give one "
                             "or the other")
    if threshold is not None and args.law is not None and args.law.strip().lower() != "elastic":
        raise UsageError(f"--plastic-threshold applies to the elastic law (the note when asperities pass yield); "
                         f"--law {args.law} models the yield itself")
    return PhysicalContact(material_from_args(args), surface_from_args(args),
                           friction=friction_from_args(args, physical=True), adhesion=not args.no_adhesion,
                           plasticity=args.law, hardness=optional_quantity(args.hardness, "Pa", "--hardness"),
                           h_star=optional_quantity(args.h_star, "m", "--h-star"),
                           size_effect=True if args.size_effect else None, heights=heights_from_args(args),
                           interaction=interaction_from_args(args, physical=True), **kwargs)


def title(args, contact=None) -> str:
    """One line naming the contact (its first description line, and a plastic law) or the model
    parameters (plot titles)."""
    law = "" if getattr(args, "law", None) in (None, "elastic") else f", {args.law}"
    law += f", heights {args.heights}" if getattr(args, "heights", None) else ""
    if contact is not None:
        return contact.describe().splitlines()[0].removeprefix("contact: ") + law
    return (f"alpha={args.alpha:g}, beta={args.beta:g}, gamma={args.gamma or 0:g}, "
            f"nu={0.3 if args.nu is None else args.nu:g}, h/b={1.0 if args.h_over_b is None else args.h_over_b:g}"
            f"{law}")
