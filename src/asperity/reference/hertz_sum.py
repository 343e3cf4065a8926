"""Slow path for the deterministic asperity model: summits by loops, Hertz sums by bisection.

Written from the definitions only (imports nothing from asperity):

* a summit is a regional maximum: a plateau (the grid points of one height connected
  through their 8 neighbours, often one point) none of whose neighbours is higher, taken at
  its first point in row order; on a periodic map the neighbours wrap, on a free map a
  plateau that reaches the border is no summit, nor is a point whose mean curvature is not
  positive (a plateau wrapping round a periodic map);
* its height is measured from the mean of the map, its curvatures from central
  differences; radius ``'mean'``: ``1/(-(hxx + hyy)/2)``, ``'geometric'``:
  ``(hxx*hyy - hxy**2)**-0.5`` (the mean radius where that is not positive);
* independent Hertz caps: ``F = 4/3 E sqrt(R) w**1.5``, ``A = pi R w`` for ``w = z - d > 0``;
  the flat's position ``d`` carrying a load is found by bisection;
* interacting caps on a free half-space (no coalescence): each contact presses the surface
  by Johnson's Eq (3.42) field of its Hertz pressure; solved by damped fixed-point
  iteration on the displacements, with ``d`` by bisection at each step.
"""

import math

import numpy as np

__all__ = ["summits", "hertz_sum", "interacting_free"]


def summits(h, dx, dy, periodic, radius="geometric"):
    """List of (x, y, z, R) of the summits of the map ``h`` (pure-Python loops)."""
    h = [[float(v) for v in row] for row in np.asarray(h, float)]
    nx, ny = len(h), len(h[0])
    mean = sum(sum(row) for row in h) / (nx * ny)
    out = []

    def at(i, j):
        if periodic:
            return h[i % nx][j % ny]
        return h[i][j]

    seen = [[False] * ny for _ in range(nx)]
    for i0 in range(nx):
        for j0 in range(ny):
            if seen[i0][j0]:
                continue
            seen[i0][j0] = True
            stack, plateau, ok = [(i0, j0)], [], True
            while stack:  # flood the plateau of (i0, j0)
                a, b = stack.pop()
                plateau.append((a, b))
                for da in (-1, 0, 1):
                    for db in (-1, 0, 1):
                        x, y = a + da, b + db
                        if (da, db) == (0, 0):
                            continue
                        if not periodic and not (0 <= x < nx and 0 <= y < ny):
                            ok = False  # a point of the plateau on the border
                            continue
                        x, y = x % nx, y % ny
                        if h[x][y] > h[a][b]:
                            ok = False
                        elif h[x][y] == h[a][b] and not seen[x][y]:
                            seen[x][y] = True
                            stack.append((x, y))
            if not ok or len(plateau) == nx * ny:  # the whole map one plateau: nothing stands out
                continue
            i, j = min(plateau)
            c = h[i][j]
            hxx = (at(i + 1, j) - 2 * c + at(i - 1, j)) / dx**2
            hyy = (at(i, j + 1) - 2 * c + at(i, j - 1)) / dy**2
            hxy = (at(i + 1, j + 1) - at(i + 1, j - 1) - at(i - 1, j + 1) + at(i - 1, j - 1)) / (4 * dx * dy)
            kappa = -(hxx + hyy) / 2
            if not kappa > 0:  # a plateau's point flat both ways is no cap
                continue
            gauss = hxx * hyy - hxy * hxy
            R = 1 / math.sqrt(gauss) if radius == "geometric" and gauss > 0 else 1 / kappa
            out.append((i * dx, j * dy, c - mean, R))
    return out


def _bisect(f, lo, hi, n=200):
    """Root of the decreasing function f on [lo, hi] (f(lo) > 0 > f(hi))."""
    for _ in range(n):
        mid = (lo + hi) / 2
        if f(mid) > 0:
            lo = mid
        else:
            hi = mid
    return (lo + hi) / 2


def hertz_sum(caps, P, E):
    """Independent Hertz caps carrying the load P: (area, contacts, d)."""
    def load(d):
        return sum(4 / 3 * E * math.sqrt(R) * max(z - d, 0.0) ** 1.5 for _, _, z, R in caps)

    top = max(z for _, _, z, _ in caps)
    lo = min(z for _, _, z, _ in caps) - 1.0
    while load(lo) < P:
        lo -= 2 * (top - lo)
    d = _bisect(lambda d: load(d) - P, lo, top)
    area = sum(math.pi * R * (z - d) for _, _, z, R in caps if z > d)
    return area, sum(1 for _, _, z, _ in caps if z > d), d


def _field(r, a, F, E):
    """Johnson Eq (3.42): displacement at r from a Hertz spot (radius a, force F)."""
    if F == 0.0:
        return 0.0
    if r <= a:
        return 3 * F * (2 * a * a - r * r) / (8 * a**3 * E)
    return 3 * F / (4 * math.pi * a**3 * E) * ((2 * a * a - r * r) * math.asin(a / r) + a * math.sqrt(r * r - a * a))


def interacting_free(caps, P, E, iterations=400, relax=0.5):
    """Interacting Hertz caps on a free half-space (no coalescence): (area, contacts, d, forces)."""
    n = len(caps)
    u = [0.0] * n
    forces = [0.0] * n
    d = 0.0
    for _ in range(iterations):
        def load(d, u=u):
            return sum(4 / 3 * E * math.sqrt(caps[i][3]) * max(caps[i][2] - d - u[i], 0.0) ** 1.5 for i in range(n))

        top = max(caps[i][2] - u[i] for i in range(n))
        lo = top - 1.0
        while load(lo) < P:
            lo -= 2 * (top - lo)
        d = _bisect(lambda d: load(d) - P, lo, top)
        w = [max(caps[i][2] - d - u[i], 0.0) for i in range(n)]
        forces = [4 / 3 * E * math.sqrt(caps[i][3]) * w[i] ** 1.5 for i in range(n)]
        radii = [math.sqrt(caps[i][3] * w[i]) for i in range(n)]
        new = []
        for i in range(n):
            s = 0.0
            for j in range(n):
                if j != i and forces[j] > 0:
                    s += _field(math.hypot(caps[i][0] - caps[j][0], caps[i][1] - caps[j][1]), radii[j], forces[j], E)
            new.append(s)
        u = [(1 - relax) * u[i] + relax * new[i] for i in range(n)]
    area = sum(math.pi * caps[i][3] * w[i] for i in range(n))
    return area, sum(1 for x in w if x > 0), d, forces
