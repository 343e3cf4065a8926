r"""Table 1: the dimensionless pull-off force :math:`|P|/NGb^2` for nine parameter sets."""

from __future__ import annotations

import numpy as np

from .._validation import check_finite_result, check_output_path, check_scalar_poisson, check_scalar_positive
from ..groups import load_scale
from ._common import model, write_csv

__all__ = ["TABLE1", "TABLE1_COLUMNS", "table1_rows", "write_table1_csv", "printed_load_scale_factor"]

#: The paper's Table 1: (alpha, beta, gamma, printed |P|/(N G b^2)).
TABLE1 = (
    (0.002, 1000.0, 0.001, 2158.1),
    (0.003, 1000.0, 0.001, 320.1),
    (0.004, 1000.0, 0.001, 26.7),
    (0.005, 1000.0, 0.001, 1.0),
    (0.01, 100.0, 0.001, 2.9),
    (0.01, 300.0, 0.001, 0.005),
    (0.01, 1000.0, 0.005, 9.5),
    (0.01, 1000.0, 0.007, 81.2),
    (0.01, 1000.0, 0.010, 2480.8),
)

#: Columns of ``table1.csv``; ``ratio`` is computed / paper.
TABLE1_COLUMNS = ("alpha", "beta", "gamma", "paper", "computed", "ratio")


def table1_rows() -> list[dict]:
    """The nine rows with our pull-off force (:meth:`asperity.Model.pull_off`, d/sigma up to 10)."""
    rows = []
    for alpha, beta, gamma, paper in TABLE1:
        computed = float(model(alpha, beta, gamma).pull_off().force)
        rows.append({"alpha": alpha, "beta": beta, "gamma": gamma, "paper": paper,
                     "computed": computed, "ratio": computed / paper})
    return rows


def write_table1_csv(path, rows=None) -> list[dict]:
    """Write ``table1.csv`` (columns :data:`TABLE1_COLUMNS`); return the rows written.

    ``path`` is a file name; ``rows`` (default: :func:`table1_rows`) a list of dicts with
    the keys :data:`TABLE1_COLUMNS`.
    """
    path = check_output_path(path, "path")
    if rows is not None and not (isinstance(rows, list | tuple) and all(
            isinstance(r, dict) and set(TABLE1_COLUMNS) <= set(r) for r in rows)):
        raise TypeError(f"rows must be a list of dicts with the keys {', '.join(TABLE1_COLUMNS)}, got "
                        f"{type(rows).__name__}")
    rows = table1_rows() if rows is None else rows
    write_csv(path, rows, TABLE1_COLUMNS)
    return rows


def printed_load_scale_factor(alpha, beta, gamma, nu=0.3) -> float:
    r"""Factor every force (so every pull-off) would gain with Eq 17's printed :math:`\hat P`.

    :math:`\bar P = P_M/\hat P` for every asperity, so the printed
    :math:`\hat P = (1-\nu)\alpha^2/(2\pi\beta\gamma)` instead of the derived
    :math:`(1-\nu)\alpha/(2\pi\beta\gamma)` multiplies the whole force curve by their ratio,
    :math:`1/\alpha`, leaving the separation of the pull-off unchanged.
    """
    alpha, beta, gamma = (check_scalar_positive(x, n) for x, n in ((alpha, "alpha"), (beta, "beta"), (gamma, "gamma")))
    nu = check_scalar_poisson(nu)
    derived = load_scale(alpha, beta, gamma, nu, form="derived")
    printed = load_scale(alpha, beta, gamma, nu, form="printed")
    with np.errstate(all="ignore"):
        return float(check_finite_result(derived / printed, "the factor", alpha=alpha, beta=beta, gamma=gamma))
