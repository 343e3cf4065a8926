"""The explorer's state: the mode and every parameter, to and from a URL query string.

A view of the explorer is one :class:`State`: the mode (``dimensionless`` or
``physical``) and the value of every :class:`Field`.  The fields come from the quantity
registry (:mod:`asperity.quantities`: names, meanings, valid and typical ranges, log
scale, defaults), the materials table (:func:`asperity.materials.material_names`) and the
registry of height distributions (``asperity.heights.DISTRIBUTIONS`` where it exists;
Gaussian heights otherwise).  Only the starting values of the three groups without a
registry default, and the load and separation ranges, are chosen here (:data:`START`).

The query string holds every field of the view (``?mode=dimensionless&alpha=0.003&...``),
numbers written with :func:`repr` so that they read back exactly; a link or a bookmark
therefore reproduces the view.  :func:`state_from_query` never fails: an unknown key or
an unreadable value becomes a message and the field keeps its default.  Whether values
are *valid* is the library's to say, when the explorer computes the curves
(:mod:`asperity.explorer.compute`).

Nothing here imports Bokeh.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from urllib.parse import parse_qs, urlencode

from ..quantities import CURVE_COLUMNS, MODEL_PARAMETERS, PHYSICAL_PARAMETERS, Quantity
from ..units import strict_float

__all__ = ["MODES", "START", "MAX_POINTS", "Field", "State", "fields", "distributions", "parse_value", "number_text",
           "state_from_query", "default_state", "used", "material_values", "CUSTOM", "ELASTIC"]

MODES = ("dimensionless", "physical")
#: Choice of the material menu meaning "the moduli, b and w typed below".
CUSTOM = "custom"
#: Points per curve are between 2 and this (a front-end limit: every update stays quick).
MAX_POINTS = 2000

#: Starting values not in the registry: alpha, beta, gamma of Table 1's second row (a visible
#: pull-off force), the loads of the paper's figures, the separations of Fig 7, and the gold
#: contact of the README (2 nm, 1 um, 1e12 /m^2 over 1 mm^2, loads 0.1 mN to 10 N).
START = {
    "alpha": 0.003, "beta": 1000.0, "gamma": 1e-3,
    "P_min": 1e-2, "P_max": 1e5, "d_min": -1.0, "d_max": 5.0, "n": 200,
    "material": "Au", "sigma_s": 2e-9, "R": 1e-6, "eta": 1e12, "area": 1e-6, "P_min_N": 1e-4, "P_max_N": 10.0,
    "H_over_E": 0.01, "h_star": 1e-6,
}
#: The per-asperity law a view starts with (a name of ``asperity.elastic_plastic.LAWS``).
ELASTIC = "elastic"


@dataclass(frozen=True)
class Field:
    """One parameter of the view.

    ``key`` is its query-string name; ``kind`` one of ``number``, ``integer``, ``choice``,
    ``flag``; ``quantity`` the registry entry (meaning, ranges, log scale) where there is
    one; ``unit`` the SI unit a typed value may carry (pint syntax, ``''`` for none);
    ``mode`` the mode that uses it (None: both); ``choices`` for a menu; ``group`` the
    distribution whose parameter it is, if any; ``when`` a ``(key, value)`` pair: the field
    is used (shown, written to the query string) only while field ``key`` has that value.
    """

    key: str
    kind: str
    default: object
    quantity: Quantity | None = None
    unit: str = ""
    label: str = ""
    mode: str | None = None
    choices: tuple[str, ...] = ()
    group: str | None = None
    help: str = ""
    when: tuple[str, str] | None = None

    def text(self, value) -> str:
        """``value`` as written in a query string (numbers in the shortest form that reads back exactly)."""
        if self.kind == "number":
            return number_text(value)
        if self.kind == "flag":
            return "1" if value else "0"
        return str(value)


def number_text(value: float) -> str:
    """The shortest text that reads back as exactly ``value`` (``1e12``, ``0.003``, ``2e-9``).

    >>> number_text(1e12), number_text(10.0), number_text(1 / 43), number_text(-1.0)
    ('1e12', '10', '0.023255813953488372', '-1')
    """
    value = float(value)
    if not math.isfinite(value):
        return repr(value)
    for digits in range(1, 18):
        text = f"{value:.{digits}g}"
        if float(text) == value:
            break
    mantissa, _, exponent = text.partition("e")
    short = f"{mantissa}e{int(exponent)}" if exponent else mantissa
    plain = repr(value).removesuffix(".0")
    return plain if "e" not in plain and len(plain) <= len(short) else short


def distributions() -> dict:
    """Height distributions by name: ``asperity.heights.DISTRIBUTIONS`` if it exists, else Gaussian only.

    Values are what the registry holds (classes or instances); :func:`asperity.explorer.compute.height_distribution`
    builds one.
    """
    from .. import heights

    registry = getattr(heights, "DISTRIBUTIONS", None)
    if not registry:
        return {"gaussian": heights.Gaussian}
    # a distribution built from data (the empirical one: measured summit heights) has no place in a menu
    return {name: entry for name, entry in registry.items() if _buildable(entry)}


def _buildable(entry) -> bool:
    """True if ``entry`` is an instance, or a class that builds with its defaults (not from data)."""
    if not isinstance(entry, type):
        return True
    try:
        entry()
    except (TypeError, ValueError):
        return False
    return True


def _distribution_fields(name: str, entry) -> list[Field]:
    """Numeric constructor fields (with defaults) of a dataclass distribution, as fields ``<name>_<field>``."""
    cls = entry if isinstance(entry, type) else type(entry)
    if not dataclasses.is_dataclass(cls):
        return []
    out = []
    for f in dataclasses.fields(cls):
        value = getattr(entry, f.name) if not isinstance(entry, type) else f.default
        if f.init and isinstance(value, int | float) and not isinstance(value, bool):
            out.append(Field(f"{name}_{f.name}", "number", float(value), label=f"{name} {f.name}", group=name,
                             help=f"parameter {f.name!r} of the {name} height distribution"))
    return out


def _registry_field(key: str, q: Quantity, default, *, mode=None, unit="", label="") -> Field:
    return Field(key, "number", default, quantity=q, unit=unit, label=label, mode=mode, help=q.help())


def fields() -> dict[str, Field]:
    """Every field of the view, by query key, in the order of the page (built on each call)."""
    from ..elastic_plastic import LAWS
    from ..interaction import INTERACTIONS
    from ..materials import material, material_names

    M, S, C = MODEL_PARAMETERS, PHYSICAL_PARAMETERS, CURVE_COLUMNS
    menu = distributions()
    au = material(START["material"])
    out = [Field("mode", "choice", MODES[0], choices=MODES, help="dimensionless groups or a physical contact")]
    out += [_registry_field(k, M[k], START[k] if M[k].default in (None, 0.0) else M[k].default, mode=MODES[0])
            for k in ("alpha", "beta", "gamma", "nu", "h_over_b")]
    # gamma (adhesion) belongs to the elastic law: the Jackson-Green law has none
    out = [dataclasses.replace(f, when=("law", ELASTIC)) if f.key == "gamma" else f for f in out]
    laws = tuple(LAWS)
    jg = ("law", laws[1])
    out += [Field("law", "choice", ELASTIC, mode=MODES[0], choices=laws, label="asperity law",
                  help="per-asperity law: elastic (Hertz or Maugis-Dugdale, with gamma) or Jackson-Green "
                       "elastic-plastic (no adhesion: no gamma)"),
            dataclasses.replace(_registry_field("H_over_E", M["H_over_E"], START["H_over_E"], mode=MODES[0]),
                                when=jg),
            dataclasses.replace(_registry_field("h_star_over_sigma", M["h_star_over_sigma"],
                                                M["h_star_over_sigma"].default, mode=MODES[0]), when=jg)]
    out += [_registry_field(k, M[k], M[k].default) for k in ("tau_f1", "tau_f2", "a1", "a2")]
    out.append(Field("heights", "choice", next(iter(menu)), choices=tuple(menu),
                     help="distribution of summit heights (in units of sigma)"))
    for name, entry in menu.items():
        out += _distribution_fields(name, entry)
    out += [_registry_field("P_min", C["P"], START["P_min"], mode=MODES[0], label="P min"),
            _registry_field("P_max", C["P"], START["P_max"], mode=MODES[0], label="P max"),
            _registry_field("d_min", C["d"], START["d_min"], label="d/σ min"),
            _registry_field("d_max", C["d"], START["d_max"], label="d/σ max"),
            Field("n", "integer", START["n"], label="points", help=f"points per curve, 2 to {MAX_POINTS}")]
    out += [Field("material", "choice", START["material"], mode=MODES[1], choices=(*material_names(), CUSTOM),
                  help="material from the table (asperity materials), or custom: the values typed below"),
            _registry_field("E_Pa", S["E"], au.E, mode=MODES[1], unit="Pa", label="E"),
            _registry_field("material_nu", M["nu"], au.nu, mode=MODES[1], label="ν"),
            _registry_field("b_m", S["b"], au.b, mode=MODES[1], unit="m", label="b"),
            _registry_field("w_J_m2", S["w"], au.w, mode=MODES[1], unit="J/m^2", label="w"),
            dataclasses.replace(_registry_field("H_Pa", S["hardness"], au.H, mode=MODES[1], unit="Pa", label="H"),
                                when=("material", CUSTOM)),
            dataclasses.replace(_registry_field("H0_Pa", S["hardness"], au.H, mode=MODES[1], unit="Pa",
                                                label="H0 (size effect)"), when=("material", CUSTOM)),
            dataclasses.replace(_registry_field("h_star_m", S["h_star"], START["h_star"], mode=MODES[1], unit="m",
                                                label="h*"), when=("material", CUSTOM)),
            Field("adhesion", "flag", True, mode=MODES[1], when=("plasticity", ELASTIC),
                  help="Maugis-Dugdale, with the material's w (off: Hertz); the Jackson-Green law has none"),
            Field("plasticity", "choice", ELASTIC, mode=MODES[1], choices=laws, label="asperity law",
                  help="per-asperity law: elastic, or Jackson-Green elastic-plastic with the material's "
                       "hardness H (no adhesion)"),
            Field("size_effect", "flag", False, mode=MODES[1], label="size effect",
                  help="Nix-Gao size effect: H = H0 (1 + h*/omega)^1/2, with the material's H0 and h*"),
            Field("interaction", "choice", next(iter(INTERACTIONS)), mode=MODES[1], choices=tuple(INTERACTIONS),
                  help="asperity interaction: none, or the mean field of Ciavarella, Greenwood & Paggi 2008 "
                       "(no adhesion)")]
    out += [_registry_field(S[k].si_name, S[k], START[k], mode=MODES[1], unit=S[k].si_unit)
            for k in ("sigma_s", "R", "eta", "area")]
    out += [_registry_field("P_min_N", C["P"], START["P_min_N"], mode=MODES[1], unit="N", label="P min"),
            _registry_field("P_max_N", C["P"], START["P_max_N"], mode=MODES[1], unit="N", label="P max")]
    return {f.key: f for f in out}


#: Fields written to the query string only with the custom material (H_Pa its hardness; H0_Pa
#: and h_star_m its Nix-Gao pair, used with the size effect).
MATERIAL_KEYS = ("E_Pa", "material_nu", "b_m", "w_J_m2", "H_Pa", "H0_Pa", "h_star_m")


@dataclass(frozen=True)
class State:
    """The mode and every parameter of one view (a mapping from field key to value)."""

    values: Mapping[str, object] = field(default_factory=dict)

    def __getitem__(self, key: str):
        return self.values[key]

    @property
    def mode(self) -> str:
        return self.values["mode"]

    def replace(self, **changes) -> State:
        """A copy with some values changed (unknown keys raise KeyError)."""
        unknown = set(changes) - set(self.values)
        if unknown:
            raise KeyError(f"unknown explorer field(s): {', '.join(sorted(unknown))}")
        return State({**self.values, **changes})

    def shown(self, spec: Mapping[str, Field] | None = None) -> list[str]:
        """Keys written to the query string: all, but the custom material's values only with it
        and a distribution's parameters only when it is chosen (``spec``: :func:`fields`, if known)."""
        spec = fields() if spec is None else spec
        out = []
        for key, f in spec.items():
            if key not in self.values or (key in MATERIAL_KEYS and self.values["material"] != CUSTOM):
                continue
            if not used(f, self.values):
                continue
            out.append(key)
        return out

    def to_query(self, spec: Mapping[str, Field] | None = None) -> str:
        """The query string (without ``?``) of this view; :func:`state_from_query` reads it back."""
        spec = fields() if spec is None else spec
        return urlencode([(k, spec[k].text(self.values[k])) for k in self.shown(spec)], safe=":/")


def material_values(name: str) -> dict:
    """The custom-material fields (E_Pa, material_nu, b_m, w_J_m2, H_Pa, H0_Pa, h_star_m) of table
    material ``name``, those it has; {} for a name the table does not know (the library says
    so when computing)."""
    from ..materials import material

    try:
        m = material(name)
    except ValueError:
        return {}
    values = {"E_Pa": m.E, "material_nu": m.nu, "b_m": m.b, "w_J_m2": m.w, "H_Pa": m.H, "H0_Pa": m.H0,
              "h_star_m": m.h_star}
    return {k: v for k, v in values.items() if v is not None}


def used(f: Field, values: Mapping[str, object]) -> bool:
    """Whether field ``f`` counts in a view of ``values``: its distribution is the chosen one and
    its ``when`` condition holds (the mode is not considered)."""
    if f.group is not None and f.group != values.get("heights"):
        return False
    return f.when is None or values.get(f.when[0]) == f.when[1]


def default_state() -> State:
    """The view the explorer opens with."""
    return State({k: f.default for k, f in fields().items()})


#: An example of a quantity in each SI unit of the page, for messages.
_EXAMPLES = {"Pa": "79GPa", "m": "2nm", "J/m^2": "0.5J/m^2", "1/m^2": "1e12/m^2", "m^2": "1mm^2", "N": "10mN"}


def _example(unit: str) -> str:
    return _EXAMPLES.get(unit, f"1 {unit}")


def parse_value(f: Field, text: str):
    """The value of field ``f`` typed (or linked) as ``text``.

    Numbers may carry a unit compatible with the field's (``2nm``, ``79GPa``; needs pint);
    a bare number is in SI units.  Whether the value is in range is left to the library.

    Raises
    ------
    ValueError
        Naming the field, for text that is not a number (or a known choice, or 0/1 for a flag).
    """
    text = str(text).strip()
    name = f.label or f.key
    if f.kind == "choice":
        if text not in f.choices:
            raise ValueError(f"{f.key}: unknown choice {text!r}; valid: {', '.join(f.choices)}")
        return text
    if f.kind == "flag":
        if text.lower() not in ("1", "0", "true", "false"):
            raise ValueError(f"{f.key}: expected 1 or 0, got {text!r}")
        return text.lower() in ("1", "true")
    if f.kind == "integer":
        try:
            value = int(text)
        except ValueError:
            value = None
        if value is None or not 2 <= value <= MAX_POINTS:
            raise ValueError(f"{name}: expected a whole number from 2 to {MAX_POINTS}, got {text!r}")
        return value
    if f.unit:
        from ..units import parse_quantity

        try:
            value = parse_quantity(text, f.unit, name, require_unit=False) if text else math.nan
        except ValueError:  # pint's exception text is no sentence for the page
            value = None
        if value is None or not math.isfinite(value):
            raise ValueError(f"{name}: expected a number in {f.unit} or a quantity with a unit such as "
                             f"{_example(f.unit)}, got {text!r}") from None
        return value
    try:
        value = strict_float(text)
    except ValueError:
        raise ValueError(f"{name}: expected a number, got {text!r}") from None
    if not math.isfinite(value):
        raise ValueError(f"{name}: expected a finite number, got {text!r}")
    return value


def state_from_query(query) -> tuple[State, list[str]]:
    """The state a query string (or parsed query, key -> list of values) describes, and messages.

    Unknown keys and unreadable values are reported (the field keeps its default); a
    repeated key takes its last value, and says so.  Never raises for what a link may contain.
    """
    if isinstance(query, str):
        query = parse_qs(query.lstrip("?"), keep_blank_values=True)
    spec = fields()
    values = {k: f.default for k, f in spec.items()}
    messages, given = [], []
    for key, raw in query.items():
        key = key.decode() if isinstance(key, bytes) else str(key)
        texts = [v.decode("utf-8", "replace") if isinstance(v, bytes) else str(v) for v in raw]
        if key not in spec:
            messages.append(f"link: unknown parameter {key!r} ignored")
            continue
        if not texts:
            continue
        if len(texts) > 1:  # (taken silently before: found by a review)
            messages.append(f"link: {key} given {len(texts)} times; the last, {texts[-1]!r}, is used")
        try:
            values[key] = parse_value(spec[key], texts[-1])
            given.append(key)
        except ValueError as err:
            messages.append(f"link: {err}; using {spec[key].text(spec[key].default)}")
    for key in dict.fromkeys(given):  # a value the view does not use is said to be ignored, not dropped silently
        f = spec[key]
        if f.group is not None and f.group != values.get("heights"):  # (the other mode's values are kept)
            why = f"it belongs to the heights {f.group}"
        elif f.when is not None and values.get(f.when[0]) != f.when[1]:
            why = f"it applies with {f.when[0]} = {f.when[1]}, not {values.get(f.when[0])}"
        elif key in MATERIAL_KEYS and values["material"] != CUSTOM:
            why = f"it applies to the custom material; the link's material is {values['material']}"
        else:
            continue
        name = key if (f.label or key) == key else f"{f.label} ({key})"
        messages.append(f"link: {name} is not used in this view ({why}); ignored")
    return State(values), messages
