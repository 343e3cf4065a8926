"""The names of the height distributions, and their command-line spelling.

:data:`DISTRIBUTIONS` maps each name to its class; :func:`distribution` builds one by
name, :func:`parse_heights` from the spelling the command line takes (``--heights``):

==========================================  ===========================================
spelling                                    distribution
==========================================  ===========================================
``gaussian``                                :class:`~asperity.heights.Gaussian` (Eq 19)
``exponential``                             :class:`~asperity.heights.Exponential`
``weibull:skew=S``                          :class:`~asperity.heights.Weibull`
``pearson3:skew=S``                         :class:`~asperity.heights.PearsonIII`
``johnson:skew=S,kurt=K``                   :class:`~asperity.heights.Johnson`
``mixture:w=W,m1=M1,s1=S1,m2=M2,s2=S2``     :class:`~asperity.heights.Mixture`
``empirical:FILE``                          :class:`~asperity.heights.Empirical` of the summit heights in FILE
``best:FILE``                               the best-ranked fit to them (:func:`~asperity.heights.fit_heights`)
==========================================  ===========================================

FILE holds one summit height per line, in any unit (:func:`~asperity.heights.samples.read_samples`).
Every error lists the valid names or parameters.
"""

from __future__ import annotations

from .._numbers import FloatUnderflow, strict_float
from .base import HeightDistribution
from .empirical import Empirical
from .exponential import Exponential
from .gaussian import Gaussian
from .johnson import Johnson
from .mixture import Mixture
from .pearson import PearsonIII
from .weibull import Weibull

__all__ = ["DISTRIBUTIONS", "SPELLINGS", "distribution", "parse_heights"]

#: Name -> class of every height distribution (CLI choices and menus read this).
DISTRIBUTIONS: dict[str, type[HeightDistribution]] = {
    cls.name: cls for cls in (Gaussian, Exponential, Weibull, PearsonIII, Johnson, Mixture, Empirical)}

#: Name -> command-line spelling (``best:FILE`` fits the others to summit heights).
SPELLINGS = {
    **{name: (name if name == "empirical" or not cls.parameters
              else f"{name}:" + ",".join(f"{p}={p.upper()}" for p in cls.parameters))
       for name, cls in DISTRIBUTIONS.items()},
    "empirical": "empirical:FILE",
    "best": "best:FILE",
}


def _names() -> str:
    return ", ".join(SPELLINGS.values())


def distribution(name: str, **params) -> HeightDistribution:
    """The distribution called ``name`` with ``params`` (an ``empirical`` one takes ``file=``).

    Parameters
    ----------
    name : str
        A key of :data:`DISTRIBUTIONS` (case-insensitive).
    **params : float
        Its parameters, all of them (e.g. ``skew=0.5``); ``file=`` for ``empirical``.

    Returns
    -------
    HeightDistribution

    Raises
    ------
    ValueError
        For an unknown name (the valid ones are listed), a missing or unknown parameter
        (the valid ones are listed), or a value out of range.

    Examples
    --------
    >>> distribution("pearson3", skew=-0.3)
    PearsonIII(skew=-0.3)

    References
    ----------
    docs/heights.md (the families, their parameters and ranges).
    """
    if not isinstance(name, str):
        raise ValueError(f"heights: the distribution name must be a string, got {name!r}")
    key = name.strip().lower()
    if key not in DISTRIBUTIONS:
        raise ValueError(f"name: unknown height distribution {name!r}; valid: {', '.join(DISTRIBUTIONS)}")
    cls = DISTRIBUTIONS[key]
    if cls is Empirical:
        if set(params) != {"file"}:
            raise ValueError("heights: empirical takes exactly one parameter, file (a one-column file of "
                             "summit heights): empirical:FILE")
        return Empirical.from_file(params["file"])
    unknown = sorted(set(params) - set(cls.parameters))
    missing = [p for p in cls.parameters if p not in params]
    if unknown or missing:
        what = (f"unknown parameter(s) {', '.join(unknown)}" if unknown else
                f"missing parameter(s) {', '.join(missing)}")
        valid = ", ".join(cls.parameters) if cls.parameters else "none"
        raise ValueError(f"heights: {key}: {what}; its parameters: {valid} (spelling {SPELLINGS[key]})")
    return cls(**params)


def parse_heights(spec) -> HeightDistribution:
    """The distribution of a command-line spelling, e.g. ``'weibull:skew=0.5'`` (module docstring).

    A :class:`HeightDistribution` is returned as it is.

    Parameters
    ----------
    spec : str or HeightDistribution
        ``name`` or ``name:key=value,key=value``; ``empirical:FILE``; ``best:FILE``.

    Returns
    -------
    HeightDistribution

    Raises
    ------
    ValueError
        For a malformed spelling, an unknown name or parameter (the valid ones are listed),
        a value that is not a number or out of range, or an unreadable file.

    Examples
    --------
    >>> parse_heights("johnson:skew=0.5,kurt=4")
    Johnson(skew=0.5, kurt=4.0)
    >>> parse_heights("gaussian")
    Gaussian()

    References
    ----------
    docs/heights.md (the spellings); Adams et al., Eq (19) for ``gaussian``.
    """
    if isinstance(spec, HeightDistribution):
        return spec
    if not isinstance(spec, str):
        raise ValueError(f"heights must be a spelling such as 'weibull:skew=0.5' or a HeightDistribution, "
                         f"got {spec!r}")
    name, colon, rest = spec.strip().partition(":")
    key = name.strip().lower()
    if not key:
        raise ValueError(f"heights: empty distribution name in {spec!r}; valid: {_names()}")
    if key in ("empirical", "best"):
        if not rest.strip():
            raise ValueError(f"heights: {key} needs a file of summit heights: {key}:FILE")
        if key == "empirical":
            return Empirical.from_file(rest.strip())
        from .fit import fit_heights  # the ranking needs the fits; only for best:FILE
        from .samples import read_samples

        return fit_heights(read_samples(rest.strip())).best
    if key not in DISTRIBUTIONS:
        raise ValueError(f"heights: unknown distribution {name.strip()!r}; valid: {_names()}")
    params = {}
    for item in (rest.split(",") if rest.strip() else []):
        k, eq, v = item.partition("=")
        k = k.strip().lower()
        if not eq or not k or not v.strip():
            raise ValueError(f"heights: expected key=value in {spec!r}, got {item.strip()!r} "
                             f"(spelling {SPELLINGS[key]})")
        if k in params:
            raise ValueError(f"heights: {k} given twice in {spec!r}")
        try:
            params[k] = strict_float(v.strip())
        except FloatUnderflow as err:
            raise ValueError(f"heights: {k} must be a number, got {v.strip()!r} in {spec!r}: {err}") from None
        except ValueError:
            raise ValueError(f"heights: {k} must be a number, got {v.strip()!r} in {spec!r}") from None
    if colon and not params:
        if DISTRIBUTIONS[key].parameters:
            raise ValueError(f"heights: {key} needs its parameters: {SPELLINGS[key]}")
        raise ValueError(f"heights: nothing after ':' in {spec!r}; {key} has no parameters (spelling "
                         f"{SPELLINGS[key]})")
    return distribution(key, **params)
