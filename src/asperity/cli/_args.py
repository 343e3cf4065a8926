"""Command-line arguments shared by the commands: the argument groups.

* The shared argument groups, with help texts from :mod:`asperity.quantities`:
  :func:`add_model_arguments` (alpha, beta, gamma, nu, h/b), :func:`add_contact_arguments`
  (a physical contact: the bodies, the rough surface, the friction law),
  :func:`add_plasticity_arguments` (the per-asperity law: ``--law``, ``--hardness``,
  ``--h-star``, ``--size-effect``, ``--plastic-threshold``; added by both groups before,
  once), :func:`add_heights_argument` (the summit-height distribution ``--heights``, spelt
  as :data:`HEIGHTS_HELP` lists and read by :func:`asperity.heights.parse_heights`; added by
  both groups too, once), :func:`add_interaction_argument` (``--interaction``, the curve
  commands only), :func:`add_surface_arguments` (a scan file for ``surface`` and ``bem``) and
  :func:`add_output_arguments` (``--format``, ``-o``, ``--plot``).
* What builds the library's objects from them is in :mod:`asperity.cli._build`.
* Lists and quantities (``a,b,c``, ``start:stop:count``, ``2nm``) come from
  :mod:`~asperity.cli._lists` and are re-exported.

Every command that calls :func:`add_contact_arguments` gets every physical option and
:func:`asperity.cli._build.contact_from_args` reads them all, so a new physical command needs
nothing else.

Nothing here imports NumPy, SciPy or the model at module level: the parser is built
(and ``--help`` answered) before any of them is loaded.
"""

from __future__ import annotations

import argparse
import os
import re

from .._numbers import strict_float
from ..quantities import CURVE_COLUMNS, MODEL_PARAMETERS, PHYSICAL_PARAMETERS, PLASTIC_COLUMNS
from ._lists import (
    MAX_POINTS,
    UsageError,
    join_negative_lists,
    parse_list,
    quantity,
    quantity_items,
    quantity_list,
)

__all__ = [
    "decimal",
    "integer",
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
    "add_body_arguments",
    "add_output_arguments",
    "add_plasticity_arguments",
    "add_interaction_argument",
    "add_surface_arguments",
    "read_kwargs_from_args",
    "LAW_NAMES",
    "UNITS",
    "MODEL_HELP",
    "MATERIAL_FORMS",
    "CONTACT_OPTIONS",
    "HEIGHTS_HELP",
    "add_heights_argument",
]

#: Output columns and units, for the epilog of ``--help`` (from :data:`asperity.quantities.CURVE_COLUMNS`).
UNITS = ("\n".join(f"  {name:9s} {q.meaning}" for name, q in CURVE_COLUMNS.items())
         + "".join(f"\n  {name:9s} {q.meaning} (with --law jackson-green)" for name, q in PLASTIC_COLUMNS.items())
         + "\nWith a physical contact (SI):\n"
         + "\n".join(f"  {q.si_name:11s} [{q.si_unit}] {q.si_meaning}" for q in CURVE_COLUMNS.values())
         + "".join(f"\n  {q.si_name:11s} [{q.si_unit}] {q.si_meaning} (with --law jackson-green)"
                   for q in PLASTIC_COLUMNS.values())
         + "\nA physical result starts with '#' lines stating the contact computed (both bodies, E*, G*, "
           "w, h, b,\nthe surface, alpha, beta, gamma, lambda and the adhesion regime, N, the friction law, "
           "the\nper-asperity law with the hardness and plasticity index, the interaction); "
           "read the CSV\nwith pandas.read_csv(path, comment='#'), or drop them with --no-comments. "
           "JSON: one object\n{\"contact\": {...}, \"rows\": [...]}.")

#: ``--help`` text of ``--heights``: the spellings of :data:`asperity.heights.SPELLINGS` (a test
#: checks they agree; the registry itself would load SciPy before ``--help`` is answered).
HEIGHTS_HELP = ("summit-height distribution, standardised to mean 0 and deviation sigma_s: gaussian (default, "
                "Eq 19), exponential, weibull:skew=S (-1..2), pearson3:skew=S (-2..2), johnson:skew=S,kurt=K, "
                "mixture:w=W,m1=M1,s1=S1,m2=M2,s2=S2 (two Gaussians, any unit), empirical:FILE (a one-column "
                "file of measured summit heights, any unit), best:FILE (the best-ranked fit to them; see "
                "'asperity surface --summits')")

#: Names of the per-asperity laws, as :data:`asperity.elastic_plastic.LAWS` lists them (that
#: module loads SciPy, which ``--help`` must not; a test keeps the two equal).
LAW_NAMES = ("elastic", "jackson-green")

#: ``--help`` text of each model parameter (from :data:`asperity.quantities.MODEL_PARAMETERS`).
MODEL_HELP = {name: MODEL_PARAMETERS[name].help() for name in ("alpha", "beta", "gamma", "nu", "h_over_b")}

#: How ``--material`` names a contact (the description of the bodies' group in ``--help``).
MATERIAL_FORMS = ("--material Au is ONE gold body on a rigid flat (the paper's set-up); --material Au/Au is TWO "
                  "gold bodies (E* and G* halve and the answers change: the pull-off force of a surface with "
                  "sigma_s = 2nm, R = 1um is 1.6x larger); --material A/B pairs any two table names, as does "
                  "--material A --material2 B (two bodies of different Burgers vectors, or with no tabulated "
                  "work of adhesion between them, need --b and --w). "
                  "Without --material, --E and --nu describe a body of your own. --E/--nu (first body), "
                  "--E2/--nu2 (second body), --b, --w, --h or --sigma0 replace the table's values; "
                  "'asperity materials' lists the table.")

#: Options of the bodies, the surface and the friction law: ``dest`` names (None when not given).
BODY_OPTIONS = ("material", "E", "material2", "E2", "nu2", "b", "w", "h", "sigma0")
SURFACE_OPTIONS = ("sigma_s", "rms", "alpha_n", "R", "eta", "area", "surface", "size", "unit", "method")
FRICTION_OPTIONS = ("tau", "tau_f1", "tau_f2", "a1", "a2")
#: Every option that makes a command physical (``--nu`` and the Hurtado-Kim constants serve both forms;
#: ``--tau`` needs a physical contact and says so).
CONTACT_OPTIONS = (*BODY_OPTIONS, *SURFACE_OPTIONS)


# -- paths ---------------------------------------------------------------------------------
def decimal(text: str) -> float:
    """An argparse type: a plain decimal number (:func:`asperity.units.strict_float`: not '1_0',
    not other scripts' digits, not a number that underflows to 0); named ``float`` so argparse
    says "invalid float value"."""
    return strict_float(text)


decimal.__name__ = "float"


def integer(text: str) -> int:
    """An argparse type: an integer written with the ASCII digits (``int`` also reads '1_0' and
    other scripts' digits); named ``int`` so argparse says "invalid int value"."""
    stripped = text.strip()
    if not re.fullmatch(r"[+-]?[0-9]+", stripped):
        raise ValueError(f"invalid integer {text!r}")
    return int(stripped)


integer.__name__ = "int"


def output_file(text: str) -> str:
    """argparse type of ``-o FILE`` and ``--plot FILE``: not empty, not a directory, in a directory that exists."""
    if text == "":
        raise argparse.ArgumentTypeError("expected a file name, got ''")
    if os.path.isdir(text):
        raise argparse.ArgumentTypeError(f"{text!r} is a directory; give a file name")
    parent = os.path.dirname(text)
    if parent and not os.path.isdir(parent):
        raise argparse.ArgumentTypeError(f"{text!r}: the directory {parent!r} does not exist")
    return text


def output_dir(text: str) -> str:
    """argparse type of ``--out DIR``: not empty, and its parent directory exists (DIR itself is made)."""
    import os

    if text == "":
        raise argparse.ArgumentTypeError("expected a directory name, got ''")
    parent = os.path.dirname(os.path.abspath(text))
    if not os.path.isdir(parent):
        what = "is a file, not a directory" if os.path.exists(parent) else "does not exist"
        raise argparse.ArgumentTypeError(f"{os.path.dirname(text) or parent!r} {what} (the directory "
                                         f"{os.path.basename(text)!r} is made inside an existing one)")
    return text


# -- argument groups -------------------------------------------------------------------------
def add_model_arguments(parser: argparse.ArgumentParser, *, gamma_required: bool = False) -> None:
    """The dimensionless model parameters: ``--alpha --beta --gamma --nu --h-over-b``
    (``gamma_required``: the command refuses to run without ``--gamma``, and its help says so
    instead of the model's default 0)."""
    g = parser.add_argument_group("model parameters (dimensionless), or a physical contact below")
    g.add_argument("--alpha", type=decimal, help=MODEL_HELP["alpha"])
    g.add_argument("--beta", type=decimal, help=MODEL_HELP["beta"])
    gamma_help = MODEL_HELP["gamma"]
    if gamma_required:
        gamma_help = gamma_help.replace("; default 0", "; required here (no default)")
    g.add_argument("--gamma", type=decimal, default=None, help=gamma_help)
    g.add_argument("--nu", type=decimal, default=None, help=_NU_HELP)
    g.add_argument("--h-over-b", dest="h_over_b", type=decimal, default=None, help=MODEL_HELP["h_over_b"])
    add_heights_argument(parser, g)
    add_plasticity_arguments(parser)


def add_heights_argument(parser: argparse.ArgumentParser, group=None) -> None:
    """``--heights SPEC``, the summit-height distribution (in ``group``, else a group of its own).

    Both :func:`add_model_arguments` and :func:`add_contact_arguments` add it; the second
    call leaves the parser as it is.
    """
    if any("--heights" in action.option_strings for action in parser._actions):
        return  # added by the other group already
    group = group if group is not None else parser.add_argument_group("summit heights (docs/heights.md)")
    group.add_argument("--heights", metavar="SPEC", default=None, help=HEIGHTS_HELP)


def add_plasticity_arguments(parser: argparse.ArgumentParser) -> None:
    """The per-asperity law: ``--law --hardness --h-star --size-effect --plastic-threshold``.

    Both :func:`add_model_arguments` and :func:`add_contact_arguments` add it; the second
    call leaves the parser as it is.  ``--hardness`` and ``--h-star`` are numbers (H/E*,
    h*/sigma) for the dimensionless model and quantities with units for a physical contact.
    """
    if any("--law" in action.option_strings for action in parser._actions):
        return  # added by the other group already
    hardness, h_star = MODEL_PARAMETERS["H_over_E"], MODEL_PARAMETERS["h_star_over_sigma"]
    p = parser.add_argument_group("per-asperity law and plasticity (docs/plasticity.md)")
    p.add_argument("--law", metavar="NAME", default=None,
                   help=f"per-asperity law: {' or '.join(LAW_NAMES)} (default elastic: Hertz, or Maugis-Dugdale "
                        "with adhesion; jackson-green: elastic-plastic, no adhesion)")
    p.add_argument("--hardness", metavar="H", default=None,
                   help=f"hardness of the asperities: {hardness.meaning} ({hardness.range_text()}); with a physical "
                        f"contact the {PHYSICAL_PARAMETERS['hardness'].meaning} as a pressure with a unit, e.g. "
                        "188MPa (default: the materials table)")
    p.add_argument("--h-star", dest="h_star", metavar="H_STAR", default=None,
                   help=f"{h_star.meaning} ({h_star.range_text()}); with a physical contact a length, e.g. 1.6um; "
                        "turns the size effect on, --hardness then being H0")
    p.add_argument("--size-effect", dest="size_effect", action="store_true",
                   help="with a physical contact: the Nix-Gao size effect with H0 and h* from the materials table")
    p.add_argument("--plastic-threshold", dest="plastic_threshold", type=decimal, default=None,
                   help="with a physical contact and the elastic law: note when more than this share of the "
                        "asperities in contact is past the critical interference (default 0.01)")


def add_interaction_argument(parser: argparse.ArgumentParser) -> None:
    """``--interaction SPEC``: the asperity interaction of the curve commands (``load``,
    ``separation``), read by :func:`asperity.cli._build.interaction_from_args`."""
    parser.add_argument("--interaction", metavar="SPEC", default=None,
                        help="asperity interaction (docs/validation.md): none (plain GW, the default) or "
                             "cgp2008, the mean-field correction of Ciavarella, Greenwood & Paggi (2008), "
                             "non-adhesive (--no-adhesion, or --gamma 0); with a physical contact its compliance "
                             "follows from eta, A0, b and sigma_s, the dimensionless model needs it: "
                             "cgp2008:k=0.05 (k = Delta/sigma_s per unit load P/(N G b^2))")


_NU_BODY = "Poisson's ratio of the (first) body, replacing the table's, no default (a body of your own, --E, needs it)"
_NU_HELP = f"{MODEL_HELP['nu']} (the default of the dimensionless model); with a physical contact: {_NU_BODY}"


def _help(name: str, extra: str = "", symbol: str | None = None) -> str:
    """``--help`` text of a physical quantity from the registry, with its SI unit."""
    q = PHYSICAL_PARAMETERS[name]
    return f"{q.meaning} {symbol or name} [{q.si_unit}]{extra}"


def _paragraph(text: str) -> str:
    """A group description wrapped for ``--help`` (commands with an epilog print descriptions raw)."""
    import textwrap

    return textwrap.fill(text, 78)


def add_contact_arguments(parser: argparse.ArgumentParser, *,
                          json_shape: str = '{"contact": {...}, "rows": [...]}') -> None:
    """A physical contact: the bodies, the rough surface and the friction law (see :data:`MATERIAL_FORMS`).

    Bodies: ``--material --E --nu --material2 --E2 --nu2 --b --w --h --sigma0 --no-adhesion``;
    surface: ``--sigma-s`` (alias ``--sigma``) or ``--rms`` with ``--bandwidth``, ``--R``
    (``--radius``), ``--eta`` (``--density``), ``--area``, or ``--surface FILE`` with
    ``--size --unit --method``; friction: ``--tau`` or ``--tau-f1 --tau-f2 --a1 --a2``;
    ``--no-comments``; the per-asperity law (:func:`add_plasticity_arguments`).  ``--nu`` is
    the model group's option where that group exists.
    """
    add_body_arguments(parser)
    s = parser.add_argument_group(
        "physical contact: the rough surface (Greenwood-Williamson summits)", _paragraph(
        "Either --sigma-s (or --rms with --bandwidth), --R and --eta, or --surface FILE; always --area. "
        "sigma_s is the deviation of the SUMMIT heights, below the rms roughness sigma of all heights: "
        "sigma_s = (1 - 0.8968/alpha_N)^(1/2) sigma (Nayak 1971, McCool 1986), alpha_N = m0 m4/m2^2 the "
        "bandwidth parameter (sigma_s/sigma = 0.91 at alpha_N = 5, 0.95 at 10, 0.995 at 100; "
        "'asperity surface' measures it)."))
    s.add_argument("--sigma-s", "--sigma", dest="sigma_s", metavar="LENGTH", help=_help("sigma_s", ", e.g. 2nm"))
    s.add_argument("--rms", metavar="LENGTH", help=_help("rms", ", converted to sigma_s with --bandwidth",
                                                         symbol="sigma"))
    s.add_argument("--bandwidth", "--alpha-n", dest="alpha_n", type=decimal, metavar="ALPHA_N",
                   help=f"{PHYSICAL_PARAMETERS['alpha_n'].help()}; needed with --rms")
    s.add_argument("--R", "--radius", dest="R", metavar="LENGTH", help=_help("R", ", e.g. 1um"))
    s.add_argument("--eta", "--density", dest="eta", metavar="DENSITY", help=_help("eta", ", e.g. 1e12/m^2 "
                                                                                           "or 1/um^2"))
    s.add_argument("--area", metavar="AREA", help=_help("area", ", e.g. 1mm^2", symbol="A0"))
    s.add_argument("--surface", metavar="FILE", help="a measured scan (AFM map or profile, any format "
                   "SurfaceTopography reads): its summits give sigma_s, R, eta (needs asperity[topography])")
    s.add_argument("--size", help="with --surface: scan size when the file stores none, Lx,Ly or L with units "
                                  "(e.g. 10um,10um)")
    s.add_argument("--unit", help="with --surface: unit of the stored heights when the file stores none "
                                  "(m, mm, um, nm, Å, pm)")
    s.add_argument("--method", choices=("spectral", "detected"), default=None,
                   help="with --surface: summits from the spectral moments (Nayak/McCool, default) or detected")
    f = parser.add_argument_group("friction law (default: Hurtado-Kim with the paper's constants)")
    f.add_argument("--tau", metavar="STRESS", help=_help("tau", ", constant (e.g. 50MPa), instead of "
                                                                "Hurtado-Kim; physical contacts only"))
    for name in ("tau_f1", "tau_f2", "a1", "a2"):
        f.add_argument(f"--{name.replace('_', '-')}", dest=name, type=decimal, help=MODEL_PARAMETERS[name].help())
    parser.add_argument("--no-comments", action="store_true",
                        help="a physical result starts with '#' lines stating the contact computed (read the CSV "
                             "with pandas.read_csv(path, comment='#')); this leaves them out. JSON output is "
                             f"{json_shape} either way")
    add_heights_argument(parser)
    add_plasticity_arguments(parser)


def add_body_arguments(parser: argparse.ArgumentParser, *, adhesion: bool = True) -> None:
    """The bodies of a physical contact: ``--material --E --nu --material2 --E2 --nu2 --b`` and,
    with ``adhesion``, ``--w --h --sigma0 --no-adhesion`` (see :data:`MATERIAL_FORMS`).

    :func:`add_contact_arguments` adds them with the surface; a command whose surface is its
    own (``asperity bem``, a non-adhesive comparison) adds them alone, without adhesion.
    """
    forms = MATERIAL_FORMS if adhesion else MATERIAL_FORMS.replace("--b, --w, --h or --sigma0", "--b").replace(
        " (two bodies of different Burgers vectors, or with no tabulated work of adhesion between them, need --b and "
        "--w)", "")
    b = parser.add_argument_group("physical contact: the bodies (quantities with units, e.g. 70GPa, 0.25nm, "
                                  "0.1J/m^2)", _paragraph(forms))
    b.add_argument("--material", metavar="NAME",
                   help="table name: 'Au' (on a rigid flat), 'Au/Au' (two bodies), 'A/B'")
    b.add_argument("--E", metavar="STRESS", help=_help("E", " of the (first) body, e.g. 70GPa"))
    try:  # without the model's group (asperity bem) there is no dimensionless default to name
        b.add_argument("--nu", type=decimal, default=None, help=_NU_HELP if adhesion else _NU_BODY)
    except argparse.ArgumentError:  # already there: the model group's --nu serves both
        pass
    b.add_argument("--material2", metavar="NAME", help="second elastic body from the table, instead of the "
                                                       "rigid flat (one body, e.g. Si)")
    b.add_argument("--E2", metavar="STRESS", help="Young's modulus E2 [Pa] of the second body (with --nu2: a body of "
                                                  "your own; with --material2: replaces the table's)")
    b.add_argument("--nu2", type=decimal, help="Poisson's ratio nu2 of the second body, -1 < nu2 < 0.5")
    b.add_argument("--b", metavar="LENGTH", help=_help("b", ", e.g. 0.25nm"))
    if not adhesion:
        return
    b.add_argument("--w", metavar="ENERGY", help=_help("w", " of the interface, e.g. 0.1J/m^2 or 50mJ/m^2 "
                                                            "(the table's are clean surfaces in vacuum)"))
    b.add_argument("--h", metavar="LENGTH", help=_help("h", "; default b (the paper)"))
    b.add_argument("--sigma0", metavar="STRESS", help=_help("sigma0", ", instead of --h (h = w/sigma0)"))
    b.add_argument("--no-adhesion", action="store_true",
                   help="ignore the work of adhesion (Hertz contacts, gamma = 0)")


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
                   help="write to FILE instead of standard output ('-': standard output)")
    if plot:
        g.add_argument("--plot", metavar="FILE.png", type=output_file,
                       help="also draw the curve to a PNG (needs matplotlib)")
