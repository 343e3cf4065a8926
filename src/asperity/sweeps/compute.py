"""One chunk of a sweep: a Model per parameter set, its curve and its pull-off.

:func:`compute_chunk` is what a task runs, on a worker or in the driving process.  It
takes only plain data (the chunk's parameter sets, the loads) and returns plain arrays,
so it pickles cheaply.  A set outside the model's domain (the library raises
:class:`ValueError`) gives NaN in every variable and its message; the chunk goes on.  Loads
below a set's least load (minus its pull-off force; none without adhesion) give NaN at those
loads only, the others and the pull-off are computed, and the message notes it.  A set
computed under one of the library's validity warnings (:class:`asperity.AsperityWarning`,
e.g. asperities past yield with the elastic law) keeps its numbers and its message holds the
warning, prefixed ``note:``.
"""

from __future__ import annotations

import warnings

import numpy as np

from .._warnings import AsperityWarning
from ..bodies import contact_material
from ..curves import Model
from ..friction_stress import HurtadoKim
from ..load_control import LoadOutOfRange
from ..physical import PhysicalContact
from ..surface import Surface

__all__ = ["compute_chunk", "compute_set", "LOADS_NAN_NOTE"]

#: Words of a set's note when some of its loads lie below its least load (NaN there).
LOADS_NAN_NOTE = "load(s) below it, the others computed"

_HK = ("tau_f1", "tau_f2", "a1", "a2")


def compute_set(kind: str, params: dict, axis: str, values: np.ndarray) -> dict:
    """Curve and pull-off of one parameter set, as a dict of output variables.

    Parameters
    ----------
    kind : {'model', 'physical'}
        Dimensionless parameters (alpha, beta, gamma, nu, h_over_b, tau_f1, tau_f2, a1, a2)
        or a physical contact (material, sigma_s, R, eta, area, and optionally w and b, in SI
        units).
    params : dict
        The set's parameters.
    axis : {'P', 'd', 'P_N', 'd_m'}
        Whether ``values`` are loads or separations (dimensionless or SI).
    values : ndarray
        The loads or separations.

    Returns
    -------
    dict
        Curve columns (one value per load or separation) and ``pull_off``, ``pull_off_d``
        (``pull_off_N``, ``pull_off_d_m``, alpha, beta, gamma for a physical contact).

    Raises
    ------
    ValueError
        If the set lies outside the model's domain (e.g. lambda out of range, or every load
        below minus the pull-off; loads below it beside others it carries are NaN, with an
        :class:`~asperity.AsperityWarning`).
    """
    if kind == "physical":
        p = params
        body = p["material"]
        if p.get("w") is not None or p.get("b") is not None:  # the material's, replaced
            body = contact_material(body, w=p.get("w"), b=p.get("b"))
        contact = PhysicalContact(body, Surface(p["sigma_s"], p["R"], p["eta"], p["area"]))
        # SI names: d_m, P_N, F_N, mu, area_m2, pressure_Pa, contacts
        out = _load_columns(contact, values) if axis == "P_N" else contact.separation_curve(values).columns()
        po = contact.pull_off()
        out.update(pull_off_N=po.force, pull_off_d_m=po.d, alpha=contact.alpha, beta=contact.beta,
                   gamma=contact.gamma)
        return out
    p = params
    model = Model(p["alpha"], p["beta"], p["gamma"], nu=p["nu"], h_over_b=p["h_over_b"],
                  friction=HurtadoKim(*(p[k] for k in _HK)))
    out = _load_columns(model, values) if axis == "P" else model.separation_curve(values).columns()
    po = model.pull_off()
    out.update(pull_off=po.force, pull_off_d=po.d)
    return out


def _load_columns(model, P: np.ndarray) -> dict:
    """``model.load_curve(P).columns()``, or where some loads lie below its least load, the
    columns at the others with NaN at those and an :class:`AsperityWarning` saying so (a user
    trial: one load below the pull-off blanked the whole set, the loads it could carry and its
    pull-off too)."""
    try:
        return model.load_curve(P).columns()
    except LoadOutOfRange as err:
        first = err
        inside = P > err.floor if err.exclusive else P >= err.floor
    for _ in range(3):  # a load at the floor in newtons can round below it in the model's units: drop it
        if not np.any(inside):
            raise first
        try:
            part = model.load_curve(P[inside]).columns()
            break
        except LoadOutOfRange as again:
            inside &= P > again.got
    else:
        raise first
    columns = {}
    for name, column in part.items():
        full = np.full(P.shape, np.nan)
        full[inside] = column
        columns[name] = full
    axis = "P_N" if "P_N" in columns else "P"
    columns[axis] = np.asarray(P, dtype=float).copy()
    warnings.warn(AsperityWarning(f"{first}: NaN at the {int(np.sum(~inside))} {LOADS_NAN_NOTE}"), stacklevel=2)
    return columns


def compute_chunk(kind: str, sets: list[dict], axis: str, values: np.ndarray, variables: dict) -> dict:
    """Every output variable for the parameter sets ``sets`` of one chunk.

    Parameters
    ----------
    kind, axis, values :
        As in :func:`compute_set`.
    sets : list of dict
        The chunk's parameter sets, in C order.
    variables : dict
        Output variable -> (meaning, unit, 'curve' or 'set') (:meth:`SweepSpec.variables`).

    Returns
    -------
    dict
        Each variable as an array of shape ``(len(sets), len(values))`` ('curve') or
        ``(len(sets),)`` ('set'), and ``message``: '' for a set computed, ``'note: ...'``
        for a set computed under a validity warning of the library, else the reason it was
        not computed (its variables are NaN).
    """
    n, m = len(sets), values.size
    out = {k: np.full((n, m) if where == "curve" else n, np.nan) for k, (_, _, where) in variables.items()}
    messages = []
    for i, params in enumerate(sets):
        try:
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always", AsperityWarning)
                result = compute_set(kind, params, axis, values)
        except ValueError as err:
            messages.append(str(err) or type(err).__name__)
            continue
        for w in caught:  # warnings of other libraries go on as they came
            if not issubclass(w.category, AsperityWarning):
                warnings.warn_explicit(w.message, w.category, w.filename, w.lineno)
        notes = dict.fromkeys(str(w.message) for w in caught if issubclass(w.category, AsperityWarning))
        messages.append("; ".join(f"note: {note}" for note in notes))
        for k in out:
            out[k][i] = result[k]
    out["message"] = np.array(messages, dtype=object)
    return out
