"""Fixed composite Gauss-Legendre quadrature on panels split at breakpoints.

The multi-asperity integrals are integrals over penetration ``u`` of a per-asperity
law times the height density.  The law has a square-root endpoint (Hertz at u = 0,
Maugis-Dugdale at the end of its stable branch) and kinks (Hurtado-Kim breakpoints);
the density must be resolved wherever it is centred.  So: a first panel with the
substitution ``u = u0 + s^4`` (which makes the square-root and fourth-root endpoints analytic), panels
growing geometrically away from the endpoint (which keeps every panel at least half
its width away from the endpoint singularity), the law's breakpoints as panel
boundaries, and unit-width panels on integer edges further out.  Sixteen nodes per panel give errors
far below 1e-12 for every integrand met here (see the tests against adaptive
quadrature and closed forms).

The tabulations in separation (:mod:`asperity.height_sums`) interpolate on Chebyshev points
of the first kind: :func:`chebyshev_basis` gives the points, the values-to-coefficients
matrix and the derivative matrix of the Chebyshev series, :func:`legendre_to_chebyshev` the
coefficients of a polynomial known at the Gauss-Legendre nodes of a panel.

References
----------
.. [1] J. C. Mason, D. C. Handscomb, *Chebyshev Polynomials*, Chapman & Hall/CRC (2003),
   ch. 4 (discrete orthogonality at the zeros of :math:`T_n`), ch. 2 (derivatives of a
   Chebyshev series).
"""

from __future__ import annotations

import functools
import math

import numpy as np

from ._validation import check_1d, check_integer, check_scalar_real

__all__ = ["gauss_legendre", "panel_edges", "composite_nodes", "chebyshev_basis", "legendre_to_chebyshev"]

NODES_PER_PANEL = 16
GROWTH = 3.0


#: Most nodes per panel, panels and nodes in total that the helpers accept (memory bounds).
MAX_NODES_PER_PANEL, MAX_PANELS = 1000, 10**6


def gauss_legendre(n: int):
    """Gauss-Legendre nodes and weights on [0, 1] (``n`` nodes, 1 <= n <= 1000); cached, read-only."""
    return _gauss_legendre(check_integer(n, "n", 1, MAX_NODES_PER_PANEL))


def _frozen(*arrays):
    """The arrays made read-only: they are cached and shared by every caller (a review changed
    later results by scaling one in place)."""
    for a in arrays:
        a.flags.writeable = False
    return arrays


@functools.lru_cache(maxsize=8)
def _gauss_legendre(n: int):
    x, w = np.polynomial.legendre.leggauss(n)
    return _frozen(0.5 * (x + 1.0), 0.5 * w)


def chebyshev_basis(n: int):
    """First-kind Chebyshev points on [-1, 1] and the matrices of their series; cached, read-only.

    Parameters
    ----------
    n : int
        Number of points, 2 <= n <= 1000.

    Returns
    -------
    x : ndarray, shape (n,)
        :math:`x_m = \\cos((2m+1)\\pi/2n)`, the zeros of :math:`T_n`.
    T : ndarray, shape (n, n)
        Values at ``x`` to the coefficients :math:`c_k` of :math:`\\sum_k c_kT_k` (discrete
        orthogonality of :math:`T_k` at the zeros of :math:`T_n`).
    D : ndarray, shape (n, n)
        Coefficients of a series to those of its derivative (the recurrence
        :math:`c'_{k-1} = c'_{k+1} + 2kc_k`, :math:`c'_0` halved).
    """
    return _chebyshev_basis(check_integer(n, "n", 2, MAX_NODES_PER_PANEL))


@functools.lru_cache(maxsize=4)
def _chebyshev_basis(n: int):
    m = np.arange(n)
    theta = (2 * m + 1) * np.pi / (2 * n)
    x = np.cos(theta)
    T = 2.0 / n * np.cos(np.outer(m, theta))
    T[0] *= 0.5
    D = np.zeros((n, n))
    for j in range(n):  # derivative of T_j in the T basis
        c = np.zeros(n)
        c[j] = 1.0
        d = np.zeros(n + 1)
        for k in range(n - 1, 0, -1):
            d[k - 1] = d[k + 1] + 2 * k * c[k]
        d[0] *= 0.5
        D[:, j] = d[:n]
    return _frozen(x, T, D)


def legendre_to_chebyshev(n: int):
    """Matrix taking values at the ``n`` Gauss-Legendre nodes of [0, 1] to the Chebyshev
    coefficients in :math:`2x - 1` of the polynomial of degree ``n - 1`` through them; cached,
    read-only.

    Parameters
    ----------
    n : int
        Number of nodes, 1 <= n <= 1000.

    Returns
    -------
    ndarray, shape (n, n)
    """
    return _legendre_to_chebyshev(check_integer(n, "n", 1, MAX_NODES_PER_PANEL))


@functools.lru_cache(maxsize=4)
def _legendre_to_chebyshev(n: int):
    x, _ = _gauss_legendre(n)
    return _frozen(np.linalg.inv(np.cos(np.outer(np.arccos(2.0 * x - 1.0), np.arange(n)))))[0]


def panel_edges(start, stop, first, breakpoints=(), lo_clip=None, growth=GROWTH):
    """Panel boundaries from ``start`` (a singular endpoint) to ``stop``.

    Widths grow from ``first`` by ``growth`` until they reach 1; unit panels follow on
    integer edges (so all of them have width exactly 1 and share their nodes' offsets).
    Each breakpoint inside becomes a boundary.  With ``lo_clip`` above ``start``, the
    edges below it are dropped and ``lo_clip`` becomes the first edge, without ever
    building the panels in between.

    ``start < stop`` and ``0 < first``, finite, with ``stop - start`` at most
    :data:`MAX_PANELS`; ``growth > 1``; ``breakpoints`` finite; ``lo_clip`` None or finite.
    """
    start, stop, first = (check_scalar_real(x, n) for x, n in ((start, "start"), (stop, "stop"), (first, "first")))
    if not start < stop:
        raise ValueError(f"start must be < stop, got {start!r} and {stop!r}")
    if not stop - start <= MAX_PANELS:
        raise ValueError(f"stop - start must be <= {MAX_PANELS} (unit panels), got {stop - start:g}")
    if not first > 0:
        raise ValueError(f"first (width of the first panel) must be > 0, got {first!r}")
    growth = check_scalar_real(growth, "growth")
    if not growth > 1:
        raise ValueError(f"growth must be > 1, got {growth!r}")
    breakpoints = check_1d(breakpoints, "breakpoints", allow_empty=True)
    lo_clip = None if lo_clip is None else check_scalar_real(lo_clip, "lo_clip")
    if lo_clip is not None and not lo_clip < stop:
        raise ValueError(f"lo_clip must be < stop, got {lo_clip!r} and {stop!r}")
    graded = [start]
    width, x = first, start
    while width < 1.0 and x < stop:
        x = x + width
        graded.append(x)
        width *= growth
    first_unit = math.ceil(graded[-1] + 0.25)  # leave no sliver before the unit grid
    if lo_clip is not None and lo_clip > start:
        first_unit = max(first_unit, math.floor(lo_clip))
    unit = np.arange(first_unit, math.ceil(stop) + 1, dtype=float)
    end = unit[-1] if unit.size else graded[-1]
    edges = np.concatenate([graded, unit, [p for p in breakpoints if start < p < end]])
    edges = np.unique(edges)
    if lo_clip is not None and lo_clip > start:
        edges = np.concatenate([[lo_clip], edges[edges > lo_clip]])
    # Drop slivers created by breakpoints sitting almost on an edge.
    keep = np.concatenate([[True], np.diff(edges) > 1e-14 * max(1.0, abs(edges[-1]))])
    return edges[keep]


def composite_nodes(edges, n=NODES_PER_PANEL):
    """Nodes and weights on the panels; the first panel uses u = edges[0] + s^4.

    The quartic substitution makes the endpoint behaviours met here analytic in s:
    u^(3/2) (Hertz), a square root (Maugis-Dugdale branch end) and the fourth root at
    lambda = lambda_c, where the branch end changes kind.

    ``edges`` is increasing and finite (at least 2), ``n`` nodes per panel (1..1000), at
    most :data:`MAX_PANELS` panels.
    """
    edges = check_1d(edges, "edges")
    if not (edges.size >= 2 and np.all(np.diff(edges) > 0)):
        raise ValueError(f"edges must be increasing, with at least 2 values, got {edges.size} values")
    if edges.size - 1 > MAX_PANELS:
        raise ValueError(f"edges must hold at most {MAX_PANELS} panels, got {edges.size - 1}")
    x, w = gauss_legendre(n)
    a, b = edges[:-1], edges[1:]
    nodes = (a[:, None] + (b - a)[:, None] * x[None, :])
    weights = (b - a)[:, None] * w[None, :]
    # First panel: u = a + s^4, s in [0, (b - a)^(1/4)], du = 4 s^3 ds.
    h = (b[0] - a[0]) ** 0.25
    s = h * x
    nodes[0] = a[0] + s**4
    weights[0] = 4.0 * s**3 * h * w
    return nodes.ravel(), weights.ravel()
