"""Command-line arguments shared by the commands: lists, quantities, argument groups.

* :func:`parse_list`: ``a,b,c`` or ``start:stop:count`` -> a float array; malformed
  lists (an empty item, a wrong number of ``:`` fields, a count that is not a positive
  integer, a non-finite value) are errors, never repaired, and no list may hold more than
  :data:`MAX_POINTS` points (checked before anything is allocated).
* :func:`quantity` and :func:`quantity_list`: the same with units (``2nm``, ``1mN:1N:50``).
* The shared argument groups: :func:`add_model_arguments` (alpha, beta, gamma, nu, h/b, and
  the per-asperity law: ``--law``, ``--hardness``, ``--h-star``, ``--size-effect``,
  ``--plastic-threshold``; the summit-height distribution ``--heights``, spelt as :data:`HEIGHTS_HELP` lists and read by
  :func:`asperity.heights.parse_heights`),
  :func:`add_contact_arguments` (a physical contact: material and surface),
  :func:`add_output_arguments` (``--format``, ``-o``, ``--plot``), with help texts from
  :mod:`asperity.quantities`; and what builds the model from them:
  :func:`is_physical`, :func:`model_from_args`, :func:`contact_from_args`.

Nothing here imports NumPy, SciPy or the model at module level: the parser is built
(and ``--help`` answered) before any of them is loaded.
"""

from __future__ import annotations

import argparse
import os

from ..quantities import CURVE_COLUMNS, MODEL_PARAMETERS, PHYSICAL_PARAMETERS, PLASTIC_COLUMNS

__all__ = [
    "MAX_POINTS",
    "UsageError",
    "parse_list",
    "quantity",
    "quantity_items",
    "quantity_list",
    "join_negative_lists",
    "output_file",
    "output_dir",
    "add_model_arguments",
    "add_contact_arguments",
    "add_output_arguments",
    "add_surface_arguments",
    "read_kwargs_from_args",
    "is_physical",
    "model_from_args",
    "contact_from_args",
    "title",
    "LAW_NAMES",
    "UNITS",
    "MODEL_HELP",
    "HEIGHTS_HELP",
    "heights_from_args",
]

#: Largest number of points a list or a ``start:stop:count`` range may hold.
MAX_POINTS = 10**6

#: Output columns and units, for the epilog of ``--help`` (from :data:`asperity.quantities.CURVE_COLUMNS`).
UNITS = ("\n".join(f"  {name:9s} {q.meaning}" for name, q in CURVE_COLUMNS.items())
         + "".join(f"\n  {name:9s} {q.meaning} (with --law jackson-green)" for name, q in PLASTIC_COLUMNS.items())
         + "\nWith --material (SI):\n"
         + "\n".join(f"  {q.si_name:11s} [{q.si_unit}] {q.si_meaning}" for q in CURVE_COLUMNS.values())
         + "".join(f"\n  {q.si_name:11s} [{q.si_unit}] {q.si_meaning} (with --law jackson-green)"
                   for q in PLASTIC_COLUMNS.values()))

#: ``--help`` text of each model parameter (from :data:`asperity.quantities.MODEL_PARAMETERS`).
MODEL_HELP = {name: MODEL_PARAMETERS[name].help() for name in ("alpha", "beta", "gamma", "nu", "h_over_b")}

#: ``--help`` text of ``--heights``: the spellings of :data:`asperity.heights.SPELLINGS` (a test
#: checks they agree; the registry itself would load SciPy before ``--help`` is answered).
HEIGHTS_HELP = ("summit-height distribution, standardised to mean 0 and deviation sigma_s: gaussian (default, "
                "Eq 19), exponential, weibull:skew=S (-1..2), pearson3:skew=S (-2..2), johnson:skew=S,kurt=K, "
                "mixture:w=W,m1=M1,s1=S1,m2=M2,s2=S2 (two Gaussians, any unit), empirical:FILE (a one-column "
                "file of measured summit heights, any unit), best:FILE (the best-ranked fit to them; see "
                "'asperity surface --summits')")

#: The physical-contact options, in the order they are listed in messages.
CONTACT_OPTIONS = ("material", "sigma", "radius", "density", "area")

#: Names of the per-asperity laws, as :data:`asperity.elastic_plastic.LAWS` lists them (that
#: module loads SciPy, which ``--help`` must not; a test keeps the two equal).
LAW_NAMES = ("elastic", "jackson-green")


class UsageError(Exception):
    """A problem with the command line or its values: one line, exit status 2."""


def _show(text: str, limit: int = 60) -> str:
    """``repr`` of a user's text, shortened (a list may hold a million items)."""
    return repr(text) if len(text) <= limit else repr(text[:limit]) + "..."


def _too_many(name: str, count: int) -> UsageError:
    return UsageError(f"{name}: {count} points is more than the limit of {MAX_POINTS} (MAX_POINTS)")


def _items(text: str, name: str) -> list[str]:
    """The comma-separated items of ``text``; an empty item or too many items is an error."""
    if text.count(",") + 1 > MAX_POINTS:
        raise _too_many(name, text.count(",") + 1)
    items = text.split(",")
    if any(not item.strip() for item in items):
        raise UsageError(f"{name}: empty item in {_show(text)}; give numbers separated by single commas "
                         "'a,b,c' or a range 'start:stop:count'")
    return items


def _range_parts(text: str, name: str) -> tuple[str, str, int]:
    """``start``, ``stop`` (texts) and ``count`` of ``start:stop:count``, count checked."""
    parts = text.split(":")
    if len(parts) != 3:
        raise UsageError(f"{name}: expected a range 'start:stop:count' (three fields), got {_show(text)}")
    try:
        count = int(parts[2])
    except ValueError:
        count = None
    if count is None or count < 1:
        raise UsageError(f"{name}: count in start:stop:count must be a positive integer, got {parts[2]!r}")
    if count > MAX_POINTS:
        raise _too_many(name, count)
    return parts[0], parts[1], count


def _spaced(start: float, stop: float, count: int, *, log: bool, name: str, text: str):
    """``count`` points from ``start`` to ``stop``, log-spaced if ``log``, else linear."""
    import math

    import numpy as np

    if not (math.isfinite(start) and math.isfinite(stop)):
        raise UsageError(f"{name}: values must be finite, got {_show(text)}")
    if log:
        if start <= 0 or stop <= 0:
            raise UsageError(f"{name}: a log-spaced range start:stop:count needs start, "
                             f"stop > 0 (use a comma list for zero or negative loads)")
        return np.geomspace(start, stop, count)
    with np.errstate(over="ignore", invalid="ignore"):
        values = np.linspace(start, stop, count)
        if not np.all(np.isfinite(values)):  # stop - start beyond the float range: weigh the ends
            t = np.linspace(0.0, 1.0, count)
            values = start * (1.0 - t) + stop * t
    return values


def parse_list(text: str, *, log: bool, name: str):
    """``a,b,c`` or ``start:stop:count`` (log-spaced if ``log``, else linear) as a float array.

    Parameters
    ----------
    text : str
        Finite numbers separated by single commas, or ``start:stop:count`` with a
        positive integer count.  At most :data:`MAX_POINTS` points.
    log : bool
        Space a range logarithmically (start and stop must then be > 0).
    name : str
        The option, for messages (``'--P'``).

    Returns
    -------
    numpy.ndarray
        1-D float array.

    Raises
    ------
    UsageError
        For an empty item (``0,,1``, ``1,``), a range without exactly three fields, a count
        that is not a positive integer, a non-finite value, or more than
        :data:`MAX_POINTS` points.
    """
    import numpy as np

    bad = UsageError(f"{name}: expected numbers 'a,b,c' or 'start:stop:count', got {_show(text)}")
    if ":" in text:
        start, stop, count = _range_parts(text, name)
        try:
            lo, hi = float(start), float(stop)
        except ValueError:
            raise bad from None
        return _spaced(lo, hi, count, log=log, name=name, text=text)
    items = _items(text, name)
    try:
        values = np.array([float(v) for v in items])
    except ValueError:
        raise bad from None
    if not np.all(np.isfinite(values)):
        raise UsageError(f"{name}: values must be finite, got {_show(text)}")
    return values


def quantity(text: str, unit: str, name: str) -> float:
    """One quantity with a unit (``'2nm'``) in the SI unit ``unit`` (needs pint)."""
    from .._optional import require

    require("pint", purpose="quantities with units", extra="units")
    from ..units import parse_quantity

    return parse_quantity(text, unit, name)


def quantity_items(text: str, unit: str, name: str) -> list[float]:
    """A comma list of quantities (``'10um,5um'``) in ``unit``; empty items are errors."""
    return [quantity(x, unit, name) for x in _items(text, name)]


def quantity_list(text: str, unit: str, *, log: bool, name: str):
    """``a,b,c`` or ``start:stop:count`` of quantities with units (``1mN:1N:50``), in ``unit``.

    The same rules as :func:`parse_list`.
    """
    import numpy as np

    if ":" in text:
        start, stop, count = _range_parts(text, name)
        lo, hi = quantity(start, unit, name), quantity(stop, unit, name)
        return _spaced(lo, hi, count, log=log, name=name, text=text)
    return np.array(quantity_items(text, unit, name), dtype=float)


def join_negative_lists(argv):
    """``--d -1,0,2`` -> ``--d=-1,0,2``: argparse would take ``-1,0,2`` for an option."""
    out = list(argv)
    i = 0
    while i < len(out) - 1:
        nxt = out[i + 1]
        if out[i].startswith("--") and "=" not in out[i] and nxt[:1] == "-" and nxt[1:2] in tuple("0123456789."):
            out[i:i + 2] = [f"{out[i]}={nxt}"]
        i += 1
    return out


# -- paths ---------------------------------------------------------------------------------
def output_file(text: str) -> str:
    """argparse type of ``-o FILE`` and ``--plot FILE``: not empty, not a directory."""
    if text == "":
        raise argparse.ArgumentTypeError("expected a file name, got ''")
    if os.path.isdir(text):
        raise argparse.ArgumentTypeError(f"{text!r} is a directory; give a file name")
    return text


def output_dir(text: str) -> str:
    """argparse type of ``--out DIR``: not empty."""
    if text == "":
        raise argparse.ArgumentTypeError("expected a directory name, got ''")
    return text


# -- argument groups -------------------------------------------------------------------------
def _meaning(name: str) -> str:
    return PHYSICAL_PARAMETERS[name].meaning


def add_model_arguments(parser: argparse.ArgumentParser) -> None:
    """The dimensionless model parameters: ``--alpha --beta --gamma --nu --h-over-b``."""
    g = parser.add_argument_group("model parameters (dimensionless), or a physical contact below")
    g.add_argument("--alpha", type=float, help=MODEL_HELP["alpha"])
    g.add_argument("--beta", type=float, help=MODEL_HELP["beta"])
    g.add_argument("--gamma", type=float, default=None, help=MODEL_HELP["gamma"])
    g.add_argument("--nu", type=float, default=None, help=MODEL_HELP["nu"])
    g.add_argument("--h-over-b", dest="h_over_b", type=float, default=1.0, help=MODEL_HELP["h_over_b"])
    g.add_argument("--heights", metavar="SPEC", default=None, help=HEIGHTS_HELP)
    p = parser.add_argument_group("per-asperity law and plasticity (docs/plasticity.md)")
    p.add_argument("--law", metavar="NAME", default=None,
                   help=f"per-asperity law: {' or '.join(LAW_NAMES)} (default elastic: Hertz, or Maugis-Dugdale "
                        "with adhesion; jackson-green: elastic-plastic, no adhesion)")
    hardness, h_star = MODEL_PARAMETERS["H_over_E"], MODEL_PARAMETERS["h_star_over_sigma"]
    p.add_argument("--hardness", metavar="H", default=None,
                   help=f"hardness of the asperities: {hardness.meaning} ({hardness.range_text()}); with --material "
                        f"the {_meaning('hardness')} as a pressure with a unit, e.g. 188MPa (default: the materials "
                        "table)")
    p.add_argument("--h-star", dest="h_star", metavar="H_STAR", default=None,
                   help=f"{h_star.meaning} ({h_star.range_text()}); with --material a length, e.g. 1.6um; turns "
                        "the size effect on, --hardness then being H0")
    p.add_argument("--size-effect", dest="size_effect", action="store_true",
                   help="with --material: the Nix-Gao size effect with H0 and h* from the materials table")
    p.add_argument("--plastic-threshold", dest="plastic_threshold", type=float, default=None,
                   help="with --material and the elastic law: note when more than this share of the asperities in "
                        "contact is past the critical interference (default 0.01)")


def add_contact_arguments(parser: argparse.ArgumentParser) -> None:
    """A physical contact: ``--material --sigma --radius --density --area --no-adhesion``."""
    ph = parser.add_argument_group(
        "physical contact (SI results; quantities with units, e.g. 2nm, 1um, 1e12/m^2, 1mm^2)")
    ph.add_argument("--material", help="material name from the table (asperity materials lists them), "
                                       "e.g. Au, Si, Au/Au")
    ph.add_argument("--sigma", help=f"{_meaning('sigma_s')} sigma_s, a length (e.g. 2nm)")
    ph.add_argument("--radius", help=f"{_meaning('R')} R, a length (e.g. 1um)")
    ph.add_argument("--density", help=f"{_meaning('eta')} eta, e.g. 1e12/m^2")
    ph.add_argument("--area", help=f"{_meaning('area')}, an area (e.g. 1mm^2)")
    ph.add_argument("--no-adhesion", action="store_true",
                    help="ignore the material's work of adhesion (Hertz contacts, gamma = 0)")


def add_surface_arguments(parser: argparse.ArgumentParser) -> None:
    """A measured surface: ``FILE --size --unit --fill-undefined`` (as ``asperity surface``)."""
    parser.add_argument("file", help="height map or profile file")
    parser.add_argument("--size", help="scan size when the file stores none: Lx,Ly or L with units "
                                       "(e.g. 10um,10um)")
    parser.add_argument("--unit", help="height/length unit when the file stores none (e.g. nm)")
    parser.add_argument("--fill-undefined", action="store_true",
                        help="fill missing (NaN) pixels by interpolation")


def read_kwargs_from_args(args) -> dict:
    """Keyword arguments of :func:`asperity.topography.read_topography` from :func:`add_surface_arguments`."""
    kwargs = {"fill_undefined": args.fill_undefined}
    if args.size:
        kwargs["physical_sizes"] = tuple(quantity_items(args.size, "m", "--size"))
    if args.unit:
        kwargs["unit"] = args.unit
    return kwargs


def add_output_arguments(parser: argparse.ArgumentParser, plot: bool = True) -> None:
    """``--format {table,csv,json}``, ``-o FILE`` and (if ``plot``) ``--plot FILE.png``."""
    g = parser.add_argument_group("output")
    g.add_argument("--format", choices=("table", "csv", "json"), default=None,
                   help="output format (default: table on a terminal, csv otherwise)")
    g.add_argument("-o", "--output", metavar="FILE", type=output_file,
                   help="write to FILE instead of standard output")
    if plot:
        g.add_argument("--plot", metavar="FILE.png", type=output_file,
                       help="also draw the curve to a PNG (needs matplotlib)")


# -- from arguments to the model ---------------------------------------------------------------
def is_physical(args) -> bool:
    """True for a physical contact (``--material`` ...), False for ``--alpha``/``--beta``.

    Raises
    ------
    UsageError
        For a mixture of the two, an incomplete physical contact or a missing alpha/beta.
    """
    physical = [getattr(args, name) for name in CONTACT_OPTIONS]
    if any(v is not None for v in physical):
        if args.alpha is not None or args.beta is not None or args.gamma is not None:
            raise UsageError("give either --alpha/--beta/--gamma or a physical contact "
                             "(--material, --sigma, --radius, --density, --area), not both")
        missing = [f"--{n}" for n, v in zip(CONTACT_OPTIONS, physical, strict=True) if v is None]
        if missing:
            raise UsageError(f"a physical contact also needs {', '.join(missing)}")
        if args.nu is not None:
            raise UsageError("--nu comes from the material with --material")
        return True
    if args.alpha is None or args.beta is None:
        raise UsageError("the model needs --alpha and --beta (or --material with --sigma, --radius, "
                         "--density and --area)")
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
        return float(text)
    except ValueError:
        raise UsageError(f"{name}: expected a number (dimensionless, without --material), got {_show(text)}") from None


def model_from_args(args):
    """The :class:`asperity.Model` of ``--alpha --beta --gamma --nu --h-over-b`` and ``--law --hardness --h-star``."""
    from ..curves import Model
    from ..elastic_plastic import make_law

    for option, value in (("--size-effect", args.size_effect or None), ("--plastic-threshold", args.plastic_threshold)):
        if value is not None:
            raise UsageError(f"{option} applies to a physical contact (--material ...); without it give "
                             "--hardness H/E* and --h-star h*/sigma")
    law = make_law(args.law or "elastic", H_over_E=_number(args.hardness, "--hardness"),
                   h_star_over_sigma=_number(args.h_star, "--h-star"))
    nu = 0.3 if args.nu is None else args.nu
    return Model(args.alpha, args.beta, args.gamma or 0.0, nu=nu, h_over_b=args.h_over_b, law=law,
                 heights=heights_from_args(args))


def contact_from_args(args):
    """The :class:`asperity.physical.PhysicalContact` of the physical-contact, plasticity and ``--heights`` options."""
    from ..physical import PhysicalContact, Surface

    surface = Surface(quantity(args.sigma, "m", "--sigma"), quantity(args.radius, "m", "--radius"),
                      quantity(args.density, "1/m^2", "--density"), quantity(args.area, "m^2", "--area"))
    # Commands without the plasticity options (e.g. fit) get the defaults.
    law, hardness, h_star, size_effect, threshold = (getattr(args, name, None) for name in (
        "law", "hardness", "h_star", "size_effect", "plastic_threshold"))
    kwargs = {} if threshold is None else {"plastic_threshold": threshold}
    return PhysicalContact(args.material, surface, adhesion=not args.no_adhesion, plasticity=law,
                           hardness=None if hardness is None else quantity(hardness, "Pa", "--hardness"),
                           h_star=None if h_star is None else quantity(h_star, "m", "--h-star"),
                           size_effect=True if size_effect else None,
                           heights=heights_from_args(args), **kwargs)


def title(args) -> str:
    """One line naming the contact or the model parameters (plot titles)."""
    law = "" if args.law in (None, "elastic") else f", {args.law}"
    heights = f", heights {args.heights}" if getattr(args, "heights", None) else ""
    if args.material:
        return (f"{args.material}: sigma_s={args.sigma}, R={args.radius}, eta={args.density}, "
                f"area={args.area}{', no adhesion' if args.no_adhesion else ''}{law}{heights}")
    return (f"alpha={args.alpha:g}, beta={args.beta:g}, gamma={args.gamma or 0:g}, "
            f"nu={0.3 if args.nu is None else args.nu:g}, h/b={args.h_over_b:g}{law}{heights}")
