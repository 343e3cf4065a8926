"""Measured summit heights: reading a one-column file, checking, standardising, sample moments.

A summit-height file holds one number per line (text or one-column CSV), in any unit:
blank lines and lines starting with ``#`` are skipped, and a first line that is not a
number is taken as a header (e.g. ``z_m``).  Anything else (two columns, a word in the
data, NaN, infinity) is an error naming the file and the line; nothing is repaired.
"""

from __future__ import annotations

import math
import re

import numpy as np

from .._numbers import is_number
from .._validation import as_float_array, check_output_path, check_path, check_text
from ..units import strict_float

__all__ = ["MIN_SAMPLES", "read_samples", "write_samples", "check_samples", "sample_moments", "standardise"]

#: Fewest summit heights a distribution is built from or fitted to.
MIN_SAMPLES = 20


def check_samples(samples, name: str = "samples") -> np.ndarray:
    """Summit heights as a 1-D float array: finite, at least :data:`MIN_SAMPLES`, not all equal.

    Raises
    ------
    ValueError
        For non-real or non-finite values, a 2-D array, too few values or zero spread.
    """
    z = as_float_array(samples, name, allow_empty=True)
    if z.ndim != 1:
        raise ValueError(f"{name} must be a 1-D array of summit heights, got shape {z.shape}")
    if z.size < MIN_SAMPLES:
        raise ValueError(f"{name} must hold at least {MIN_SAMPLES} summit heights, got {z.size}")
    if not np.std(_scaled(z)) > 1e-12:  # relative to the largest |z|: heights of any magnitude
        raise ValueError(f"{name}: all {z.size} summit heights are equal (to rounding); no distribution to fit")
    return z


def read_samples(path) -> np.ndarray:
    """The summit heights of a one-column text/CSV file (module docstring), checked.

    Parameters
    ----------
    path : str or os.PathLike
        The file.

    Returns
    -------
    ndarray
        1-D float array (in the file's unit).

    Raises
    ------
    ValueError
        If the file cannot be read, is not one number per line, or holds too few or
        degenerate values; the message starts with the file name.
    """
    name = check_path(path, "path")
    try:
        with open(name, encoding="utf-8") as fh:
            lines = fh.read().splitlines()
    except (OSError, UnicodeDecodeError) as err:
        raise ValueError(f"{name}: cannot read summit heights ({err.__class__.__name__}: {err})") from None
    values = []
    first = True
    for number, line in enumerate(lines, 1):
        text = line.strip().rstrip(",").strip()
        if not text or text.startswith("#"):
            continue
        try:
            x = strict_float(text)
        except ValueError:
            numeric = all(is_number(cell) for cell in text.replace(";", ",").split(",")) or \
                all(is_number(cell) for cell in text.split())
            # text made of number characters ('1_0e-9', '5e-400') is a bad number, not a header
            looks_numeric = re.fullmatch(r"[\d\s.eE+\-_,;]+", text) is not None
            if first and not numeric and not looks_numeric:  # a header (a row of numbers is not one)
                first = False
                continue
            raise ValueError(f"{name}: line {number}: expected one number per line, "
                             f"got {line.strip()[:40]!r}") from None
        first = False
        if not math.isfinite(x):
            raise ValueError(f"{name}: line {number}: summit heights must be finite, got {line.strip()[:40]!r}")
        values.append(x)
    try:
        return check_samples(np.array(values, dtype=float), "summit heights")
    except ValueError as err:
        raise ValueError(f"{name}: {err}") from None


def write_samples(path, samples, header: str = "z") -> None:
    """Write summit heights one per line under a header, atomically (:func:`read_samples` reads them back exactly).

    Parameters
    ----------
    path : str or os.PathLike
        The file to create or replace.
    samples : array_like
        Summit heights (see :func:`check_samples`).
    header : str
        First line, e.g. ``'z_m'`` for heights in metres.

    Raises
    ------
    ValueError
        For bad samples.
    OSError
        If the file cannot be written (nothing is then left behind).
    """
    from .._atomic import atomic_write

    path, header = check_output_path(path, "path"), check_text(header, "header")
    z = check_samples(samples)
    atomic_write(path, header + "\n" + "".join(f"{x!r}\n" for x in z.tolist()))


def _scaled(z) -> np.ndarray:
    """``z`` over its largest magnitude (a power of 2: exact), so that sums of squares neither
    overflow (heights of 1e160) nor underflow (1e-200); zeros stay zeros."""
    top = float(np.max(np.abs(z))) if z.size else 0.0
    return z if top == 0.0 else np.ldexp(z, -math.frexp(top)[1])


def standardise(z) -> np.ndarray:
    """``(z - mean) / std`` with the population standard deviation (as sigma_s is measured),
    computed on the heights scaled to order 1 (any magnitude a float can hold)."""
    z = _scaled(np.asarray(z, dtype=float))
    return (z - z.mean()) / z.std()


def sample_moments(samples) -> tuple[float, float]:
    r"""Sample skewness and kurtosis, :math:`m_3/m_2^{3/2}` and :math:`m_4/m_2^2` (moment estimators, biased).

    Parameters
    ----------
    samples : array_like
        Summit heights (see :func:`check_samples`).

    Returns
    -------
    skew, kurt : float
        Kurtosis is 3 for a Gaussian (not the excess).
    """
    z = standardise(check_samples(samples))
    return float(np.mean(z**3)), float(np.mean(z**4))
