"""``asperity fit``: fit a model to measured data (friction-load, force-separation, pull-off).

Parses the options into the arguments of :mod:`asperity.fit` (``fit_friction_load``,
``fit_force_separation``, ``fit_pull_off``, ``fit_joint``, ``compare_models``), calls it
and prints the result: a table, or with ``--format json`` the object of
:meth:`asperity.fit.FitResult.to_dict` (a list ranked by AIC with ``--compare``).  The
library checks everything about the data and the options; errors are one line, exit 2.
"""

from __future__ import annotations

import argparse

from .._numbers import strict_float
from ._args import BODY_OPTIONS, SURFACE_OPTIONS, UsageError, add_contact_arguments, output_file, quantity
from ._build import contact_from_args, heights_from_args, law_from_args, material_from_args

#: The options that make a rough surface (--R alone is the tip radius of the single-asperity laws).
SURFACE_ONLY = tuple(name for name in SURFACE_OPTIONS if name != "R")
#: Options of the contact's per-asperity law and heights (argument names).
CONTACT_ONLY = ("law", "hardness", "h_star", "size_effect", "plastic_threshold", "interaction")
#: Of those, the ones the dimensionless gw fit takes too (its law, H/E*, h*/sigma).
DIMENSIONLESS_GW = ("law", "hardness", "h_star")


def _given(args, names) -> bool:
    return any(getattr(args, n, None) not in (None, False) for n in names)


#: Options that set a fit parameter, and its name: given both ways, the option is refused.
SETS_PARAMETER = {"R": "R_m", "w": "w_J_m2", "sigma0": "sigma0_Pa", "sigma_s": "sigma_s_m", "eta": "eta_per_m2",
                  "area": "area_m2", "b": "b_m", "h": "h_m"}


def _flag(name: str) -> str:
    return f"--{name.replace('_', '-')}"


def _refuse_unused(args, names, contact, fix, start) -> None:
    """Options the fit would ignore, or that name a parameter --fix/--start name too: refused (a review
    found --tau, --tau-f1, --nu, --b, --h and --no-adhesion accepted and ignored, and --R 2um with
    --fix R_m=20nm fitted with 20 nm)."""
    for option, param in SETS_PARAMETER.items():
        if getattr(args, option, None) is not None and (param in fix or param in start):
            where = "--fix" if param in fix else "--start"
            raise UsageError(f"{_flag(option)} and {where} {param}=... set the same parameter: give it once")
    if contact is not None:
        return
    unused = [_flag(n) for n in ("tau", "tau_f1", "tau_f2", "a1", "a2", "b", "h", "no_adhesion")
              if getattr(args, n, None) not in (None, False)]
    if unused:
        raise UsageError(f"{', '.join(unused)}: {'applies' if len(unused) == 1 else 'apply'} only to the rough-"
                         "surface model with a physical contact; without one, hold a dimensionless gw parameter "
                         "with --fix (tau_f1=0.03, a1=...), and a single-asperity law fits its own tau_Pa and "
                         "w_J_m2 (--fix w_J_m2=0 for no adhesion; md takes --sigma0)")
    if args.nu is not None and not _given(args, ("material", "E", "material2", "E2", "nu2")):
        raise UsageError("--nu: without a body (--material, --E) there is no Poisson's ratio to set; the "
                         "dimensionless gw fit holds its nu with --fix nu=0.2")

NAME = "fit"
HELP = "fit a model to measured friction-load, force-separation or pull-off data"
DESCRIPTION = ("Fit the multi-asperity model (gw) or a single-asperity friction law (hertz, jkr, dmt, md, cos, "
               "amontons) to a CSV file; report values, standard errors, 95% intervals, chi-square, AIC/BIC and "
               "what the data cannot determine.")
EPILOG = """Data columns (found by their header):
  dimensionless  P, F or mu, d, P_off; uncertainties F_err, mu_err, P_err, d_err
  physical       load [mN], friction [nN], separation [nm], pull_off [nN], friction_err [nN],
                 or P_N, F_N, d_m; units of unit-less physical columns from --load-unit etc.
  pull-off rows  a column named after a parameter (alpha, R [nm], sigma_s [nm]) sets it per row
Models and their parameters (names as in --vary/--fix):
  gw        alpha, beta, gamma, nu, h_over_b, tau_f1, tau_f2, a1, a2 (dimensionless data;
            with --law jackson-green --hardness H/E* [--h-star h*/sigma]: no gamma, and
            H_over_E, h_star_over_sigma, fixed unless in --vary);
            with a physical contact (--material/--sigma-s/--R/--eta/--area, or --surface FILE,
            and the other contact options): sigma_s_m, R_m, eta_per_m2, area_m2, w_J_m2, b_m,
            h_m, tau1_Pa, tau2_Pa, a1, a2, or with --tau the one tau_Pa (physical data; the
            contact gives their start values, its per-asperity law --law ... and its
            interaction stay as given)
  hertz     R_m, E_star_Pa, tau_Pa        jkr, dmt   + w_J_m2        md   + w_J_m2, sigma0_Pa
  cos       F0, Pc, alpha_t (F0_N, Pc_N)  amontons   mu0, P0 (P0_N)
  force-separation fits add the offset d0 (d0_m).  The bodies (--material, or --E --nu,
  --material2 ...) give E_star_Pa of the laws, --R (--radius) their tip radius R_m.
A fit with a physical contact starts with '#' lines describing the contact it starts from
(--no-comments: none); --format json then holds it as "contact".
Examples:
  asperity fit afm.csv --model jkr --material Si --R 20nm
  asperity fit afm.csv --compare jkr,dmt,md,cos,amontons --material Si --R 20nm --format json
  asperity fit mu.csv --model gw --vary alpha,gamma --fix beta=1000 --plot fit.png"""

MODELS = ("gw", "hertz", "jkr", "dmt", "md", "cos", "amontons")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("data", metavar="DATA", nargs="+",
                        help="CSV file(s); several files are fitted jointly (see --shared)")
    parser.add_argument("--model", choices=MODELS, default=None, help="model to fit (default gw)")
    parser.add_argument("--compare", metavar="LIST",
                        help="fit each of these models (comma list) to the data and rank them by AIC")
    g = parser.add_argument_group("parameters")
    g.add_argument("--vary", metavar="NAMES", help="parameters to fit, comma list (default: the model's)")
    g.add_argument("--fix", metavar="NAME=VALUE,...", help="hold parameters at values (SI numbers, or with a unit "
                                                          "for physical names: R_m=20nm)")
    g.add_argument("--start", metavar="NAME=VALUE,...", help="start values of fitted parameters")
    g.add_argument("--bounds", metavar="NAME=LO:HI,...", help="bounds (LO or HI may be empty: open)")
    g.add_argument("--shared", metavar="NAMES", help="with several DATA files: parameters common to all (default "
                                                      "all); the others get one copy per file, NAME_1, NAME_2, ...")
    f = parser.add_argument_group("fitting")
    f.add_argument("--weights", choices=("auto", "column", "relative", "none"), default="auto",
                   help="residual weights: column = 1/uncertainty column, relative = 1/|model| (default for "
                        "friction and pull-off data without uncertainties), none; auto picks")
    f.add_argument("--loss", choices=("linear", "soft_l1", "huber"), default="linear",
                   help="loss function (soft_l1, huber: robust to outliers)")
    f.add_argument("--ci", choices=("auto", "wald", "profile"), default="auto",
                   help="95%% intervals: profile likelihood where the covariance is unreliable (auto), always, "
                        "or never (wald)")
    f.add_argument("--profile-budget", metavar="SECONDS", type=_budget,
                   help="seconds the profile likelihoods of one fit may take in all (default 60; inf: no limit; "
                        "each model of --compare has its own); a profile not finished keeps its Wald interval, "
                        "with a warning")
    f.add_argument("--restarts", choices=("auto", "always", "never"), default="auto",
                   help="repeat the fit from other starts (each free parameter moved both ways) when it looks "
                        "stuck in a local minimum "
                        "(auto: points out of the model's reach, not converged, or an improbable chi-square), "
                        "for every fit (always), or never")
    d = parser.add_argument_group("data")
    d.add_argument("--kind", choices=("friction", "force", "pull_off"), help="the data kind (default: from the "
                                                                             "columns)")
    d.add_argument("--load-unit", metavar="UNIT", help="unit of load/force columns without one (e.g. nN)")
    d.add_argument("--friction-unit", metavar="UNIT", help="unit of friction columns without one")
    d.add_argument("--separation-unit", metavar="UNIT", help="unit of separation columns without one")
    d.add_argument("--drop-nan", action="store_true", help="drop rows holding NaN (empty cells), and count them")
    add_contact_arguments(parser, json_shape='the fit\'s object with a "contact" key ({"contact": {...}, '
                                             '"results": [...]} with --compare)')
    for action in parser._actions:  # the shared help speaks of the dimensionless model's default: not a fit's
        if "--nu" in action.option_strings:
            action.help = ("Poisson's ratio of the (first) body: with --E, a body of your own; with --material, "
                           "replacing the table's.  The dimensionless gw fit holds its nu with --fix nu=...")
    o = parser.add_argument_group("output")
    o.add_argument("--format", choices=("table", "json"), default="table", help="output format (default table)")
    o.add_argument("-o", "--output", metavar="FILE", type=output_file, help="write to FILE instead of standard "
                                                                           "output")
    o.add_argument("--plot", metavar="FILE.png", type=output_file, help="also draw data, fit and residuals")


def _budget(text):
    """--profile-budget: seconds > 0 or inf (an argparse type: a bad value is a one-line usage error)."""
    import argparse

    from ..fit.runner import check_budget

    try:
        return check_budget(strict_float(text))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected seconds > 0 or inf, got {text!r}") from None


def _model_names(args) -> list[str]:
    """The models named by --compare (a list) or --model (default gw)."""
    return _names(args.compare, "--compare") if args.compare is not None else [args.model or "gw"]


def _takes_material(names) -> bool:
    """Whether any of the models ``names`` takes a material (the single-asperity laws)."""
    from ..fit.models import MODELS, model_class

    keys = [n.strip().lower() for n in names]
    return any(k in MODELS and model_class(k).uses_material for k in keys)


def _profile_budget(args):
    from ..fit.profile import PROFILE_BUDGET

    if args.profile_budget is not None and args.ci == "wald":
        raise UsageError("--profile-budget limits the profile likelihoods, which --ci wald never computes")
    return PROFILE_BUDGET if args.profile_budget is None else args.profile_budget


def _names(text, option):
    if text is None:
        return None
    items = [x.strip() for x in text.split(",")]
    if any(not x for x in items):
        raise UsageError(f"{option}: empty name in {text!r}; give names separated by commas")
    return items


def _pairs(text, option):
    if text is None:
        return {}
    out = {}
    for item in _names(text, option):
        name, sep, value = item.partition("=")
        if not sep or not name.strip() or not value.strip():
            raise UsageError(f"{option}: expected NAME=VALUE, got {item!r}")
        if name.strip() in out:
            raise UsageError(f"{option}: {name.strip()} is given twice; give each name once")
        out[name.strip()] = value.strip()
    return out


def _value(name, text, option):
    """A number, or a quantity with a unit for a physical parameter name (R_m=20nm)."""
    try:
        return strict_float(text)
    except ValueError:
        pass
    from ..quantities import FIT_PARAMETERS, PHYSICAL_PARAMETERS

    units = {q.si_name: q.si_unit for reg in (PHYSICAL_PARAMETERS, FIT_PARAMETERS) for q in reg.values()
             if q.si_name}
    if name not in units:
        raise UsageError(f"{option}: {name}={text!r} is not a number")
    return quantity(text, units[name], f"{option} {name}")


def _bounds(text):
    out = {}
    for name, value in _pairs(text, "--bounds").items():
        lo, sep, hi = value.partition(":")
        if not sep:
            raise UsageError(f"--bounds: expected {name}=LO:HI, got {name}={value!r}")
        out[name] = tuple(None if not x.strip() else _value(name, x.strip(), "--bounds") for x in (lo, hi))
    return out


def _options(args):
    vary = _names(args.vary, "--vary")
    fix = {k: _value(k, v, "--fix") for k, v in _pairs(args.fix, "--fix").items()}
    start = {k: _value(k, v, "--start") for k, v in _pairs(args.start, "--start").items()}
    contact = material = None
    names = _model_names(args)
    _refuse_unused(args, names, _given(args, SURFACE_ONLY) or None, fix, start)
    if _given(args, SURFACE_ONLY):  # a rough surface: the multi-asperity contact of gw
        if "gw" not in [n.strip().lower() for n in names]:
            given = ", ".join(f"--{n.replace('_', '-')}" for n in SURFACE_ONLY
                              if getattr(args, n, None) not in (None, False))
            raise UsageError(f"{given}: surface options make a physical contact, which only the rough-surface "
                             f"model gw takes; {'model' if len(names) == 1 else 'models'} {', '.join(names)} "
                             f"{'takes' if len(names) == 1 else 'take'} none: drop them (a single-asperity law "
                             "takes --material and the tip radius --R)")
        contact = contact_from_args(args)
    else:  # options only a physical rough-surface contact uses: refused, never ignored
        unused = [f"--{n.replace('_', '-')}" for n in CONTACT_ONLY
                  if n not in DIMENSIONLESS_GW and getattr(args, n, None) not in (None, False)]
        if unused:
            verb = "applies" if len(unused) == 1 else "apply"
            raise UsageError(f"{', '.join(unused)} {verb} only to the rough-surface model with a physical contact "
                             "(--material/--E ... with --sigma-s, --R, --eta, --area or --surface FILE); "
                             "the single-asperity laws and the dimensionless gw fit take none of them "
                             "(the dimensionless gw fit takes --heights, --law, --hardness H/E*, --h-star h*/sigma)")
    if _given(args, BODY_OPTIONS) and (contact is None or _takes_material(names)):
        material = material_from_args(args)  # E* of the single-asperity laws (a contact holds its own)
    if args.R is not None:  # the tip radius of the single-asperity laws
        R = quantity(args.R, "m", "--R")
        (start if vary is not None and "R_m" in vary else fix).setdefault("R_m", R)
    return {"vary": vary, "fix": fix, "start": start, "bounds": _bounds(args.bounds), "contact": contact,
            "material": material, "weights": args.weights, "loss": args.loss, "ci": args.ci,
            "restarts": args.restarts, "profile_budget": _profile_budget(args)}


def _with_heights(names, args, contact):
    """The model names with 'gw' replaced by a GWFit of ``--heights`` and ``--law --hardness --h-star``
    (dimensionless: H/E*, h*/sigma); a physical contact has them already."""
    given = [f"--{n.replace('_', '-')}" for n in ("heights", *DIMENSIONLESS_GW) if getattr(args, n, None) is not None]
    if not given or contact is not None:
        return names
    if "gw" not in [str(n).strip().lower() for n in names]:
        verb = "applies" if len(given) == 1 else "apply"
        raise UsageError(f"{', '.join(given)} {verb} to the rough-surface model gw (the single-asperity laws have "
                         "one asperity: no summit heights, no plastic law)")
    from ..fit.gw import GWFit

    try:
        law = law_from_args(args)
    except ValueError as err:
        raise UsageError(f"--law {args.law or 'elastic'}: {err} (give --hardness H/E* and, for the size effect, "
                         "--h-star h*/sigma)") from None
    gw = GWFit(heights=heights_from_args(args) if args.heights is not None else None, law=law)
    return [gw if str(n).strip().lower() == "gw" else n for n in names]


def run(args) -> None:
    from ..fit import compare_models, fit_force_separation, fit_friction_load, fit_joint, fit_pull_off, read_data
    from ._output import comment_header, format_json, write_outputs

    units = {k: v for k, v in (("load", args.load_unit), ("friction", args.friction_unit),
                               ("separation", args.separation_unit)) if v is not None}
    opts = _options(args)
    contact = opts["contact"]
    if args.compare is not None and args.model is not None:
        raise UsageError("give --model or --compare, not both")
    datasets = [read_data(path, kind=args.kind, units=units, drop_nan=args.drop_nan) for path in args.data]
    if args.compare is not None:
        if len(datasets) > 1:
            raise UsageError("--compare fits one DATA file")
        result = compare_models(datasets[0], _with_heights(_model_names(args), args, contact), **opts)
        listed = result.to_list()
        text = format_json(listed if contact is None else {"contact": contact.to_dict(), "results": listed}) \
            if args.format == "json" else result.summary() + "\n" + "\n".join(r.summary() for r in result.results)
        best = result.best
    else:
        (model,) = _with_heights([args.model or "gw"], args, contact)
        if len(datasets) > 1:
            best = fit_joint(datasets, model, shared=_names(args.shared, "--shared"), **opts)
        else:
            if args.shared is not None:
                raise UsageError("--shared needs several DATA files")
            fit = {"friction": fit_friction_load, "force": fit_force_separation,
                   "pull_off": fit_pull_off}[datasets[0].kind]
            best = fit(datasets[0], model, **opts)
        fitted = best.to_dict() if contact is None else {"contact": contact.to_dict(), **best.to_dict()}
        text = format_json(fitted) if args.format == "json" else best.summary()
    if args.format != "json":
        text = comment_header(contact, comments=not args.no_comments) + text

    def plot(path, fmt):
        best.plot(path, fmt=fmt)

    write_outputs(text, args, plot=plot)
