"""Is the comparison with the boundary elements fair?  The checks behind docs/validation.md, "Fairness".

Run on one core: ``OPENBLAS_NUM_THREADS=1 .venv/bin/python benchmarks/bench_fairness.py`` (about 40 min
with the 1024^2 grids; ``--no-fine`` skips them).  On the synthetic 4 um surfaces of
``bench_validation.py`` (same band-limited surface on every grid) it measures:

1. the boundary-element area against the grid (256^2, 512^2 and 1024^2: observed order of
   convergence and Richardson-extrapolated area) and against the solver tolerance;
2. the summit heights: skewness, excess kurtosis and the Shapiro-Wilk test of normality
   (is GW's Gaussian summit-height distribution right for these surfaces?);
3. a deterministic Hertz sum over the detected summits (their own heights and radii, no
   statistics, no interaction), with the mean-curvature and the equivalent-sphere radius;
4. each isolated boundary-element contact spot holding one summit: its area over the Hertz
   area of that summit under the spot's own force (is Hertz right for one asperity?);
5. the light-load slope kappa in A/A0 = kappa p/(E* h'), against Persson sqrt(8/pi), BGT
   sqrt(2 pi) and the published boundary-element values near 2;
6. a diagnostic, not a model: each summit given its own shape below the tip (the azimuthal
   mean of the map around it) instead of a paraboloid, through Sneddon's solution for an
   axisymmetric punch; the sum over the summits and the isolated single-summit spots again
   (how much of the shortfall is the shape of one asperity?).
"""

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse  # noqa: E402
import math  # noqa: E402

import numpy as np  # noqa: E402
from scipy import ndimage, special, stats  # noqa: E402

from asperity.icha import icha_curve, map_summits  # noqa: E402
from asperity.materials import material  # noqa: E402
from asperity.persson import KAPPA_BGT, KAPPA_PERSSON, rms_slope  # noqa: E402
from asperity.validation.spots import label_spots  # noqa: E402
from asperity.validation.surfaces import synthetic_surface  # noqa: E402

SIZE = 4e-6
LAMBDA_S = SIZE / 32
SURFACES = [("self-affine", 0.5), ("self-affine", 0.8), ("self-affine", 0.9), ("gaussian", None)]
MAT = material("Au")
RATIOS = np.geomspace(2.5e-4, 1.6e-2, 8)   # p/E*, as bench_validation.py


def surface(kind, hurst, seed, grid):
    return synthetic_surface(kind, SIZE, grid, short_cutoff=LAMBDA_S, hurst=hurst or 0.8, long_cutoff=SIZE / 2,
                             seed=seed)


def solve(topo, P, tol=1e-4):
    """BEM at increasing loads: contact masks, pixel forces."""
    import ContactMechanics as cm
    from ContactMechanics.Systems import NonSmoothContactSystem

    n = topo.nb_grid_pts
    system = NonSmoothContactSystem(cm.PeriodicFFTElasticHalfSpace(n, MAT.E_star, topo.physical_sizes), topo)
    h = np.asarray(topo.heights())
    disp, out = None, []
    for p in P:
        res = system.minimize_proxy(external_force=p, initial_displacements=disp, pentol=tol * h.std(),
                                    forcetol=tol * p / h.size, maxiter=20000)
        assert res.success, res.message
        disp = res.x
        out.append(np.asarray(res.jac))
    return out


def name_of(kind, hurst):
    return kind if hurst is None else f"{kind} H={hurst}"


def grid_study(grids, seeds):
    print("\n1. BEM area against the grid (same surface), A/A0 per load; observed order p and extrapolated A:")
    for kind, hurst in SURFACES:
        for seed in seeds:
            P = SIZE**2 * MAT.E_star * RATIOS
            frac = np.array([[float(np.mean(f > 0)) for f in solve(surface(kind, hurst, seed, g), P)] for g in grids])
            print(f"  {name_of(kind, hurst)}, seed {seed}: grids {grids}")
            for i, r in enumerate(RATIOS):
                row = "  ".join(f"{frac[k, i]:.5f}" for k in range(len(grids)))
                extra = ""
                if len(grids) >= 3:
                    e1, e2 = frac[-3, i] - frac[-2, i], frac[-2, i] - frac[-1, i]
                    order = math.log2(e1 / e2) if e1 > 0 and e2 > 0 else float("nan")
                    ext = frac[-1, i] - e2 / (2**order - 1) if order == order and order > 0 else float("nan")
                    extra = (f"  p = {order:4.2f}  A_ext/A0 = {ext:.5f}  bias " +
                             " ".join(f"{frac[k, i] / ext - 1:+.3f}" for k in range(len(grids))))
                print(f"    p/E* = {r:.2e}: {row}{extra}")


def tolerance_check():
    print("\n1b. BEM tolerance (self-affine H=0.8, seed 0, 256^2): A(1e-4)/A(1e-7) - 1 per load")
    topo = surface("self-affine", 0.8, 0, 256)
    P = SIZE**2 * MAT.E_star * RATIOS
    a = np.array([np.mean(f > 0) for f in solve(topo, P, 1e-4)])
    b = np.array([np.mean(f > 0) for f in solve(topo, P, 1e-7)])
    print("   ", " ".join(f"{x:+.1e}" for x in a / b - 1))


def summit_statistics(seeds, grid):
    print(f"\n2. Summit heights ({grid}^2, all summits of the periodic map): normal?")
    print("  surface              seed  summits  sigma_s/sigma  skewness  excess kurtosis  Shapiro-Wilk p  "
          "R_geo/R_mean (median)")
    for kind, hurst in SURFACES:
        for seed in seeds:
            topo = surface(kind, hurst, seed, grid)
            h = np.asarray(topo.heights())
            s = map_summits(h, topo.pixel_size, periodic=True)
            m = map_summits(h, topo.pixel_size, periodic=True, radius="mean")
            print(f"  {name_of(kind, hurst):20s} {seed:4d}  {len(s):7d}  {s.z.std() / h.std():13.3f}  "
                  f"{stats.skew(s.z):8.3f}  {stats.kurtosis(s.z):15.3f}  {stats.shapiro(s.z).pvalue:14.2g}  "
                  f"{np.median(s.R / m.R):8.3f}")


def single_summit_spots(force, s, dx, grid):
    """(area, force, summit index) of each boundary-element contact spot (pixel forces ``force``)
    that holds exactly one of the summits ``s``."""
    ii, jj = np.round(s.x / dx).astype(int) % grid, np.round(s.y / dx).astype(int) % grid
    lab, n = label_spots(force > 0, periodic=True)
    Fs = ndimage.sum(force, lab, index=np.arange(1, n + 1))
    As = ndimage.sum(force > 0, lab, index=np.arange(1, n + 1)) * dx * dx
    count = np.bincount(lab[ii, jj], minlength=n + 1)[1:]
    which = {int(lab[ii[k], jj[k]]) - 1: k for k in range(len(s)) if lab[ii[k], jj[k]] > 0}
    return [(As[q], Fs[q], which[q]) for q in np.flatnonzero(count == 1)]


def hertz_sum_and_spots(seeds, grid):
    print(f"\n3-5. Deterministic Hertz sum over the detected summits, single-summit spots, kappa ({grid}^2)")
    for kind, hurst in SURFACES:
        for seed in seeds:
            topo = surface(kind, hurst, seed, grid)
            h = np.asarray(topo.heights())
            dx = SIZE / grid
            P = SIZE**2 * MAT.E_star * RATIOS
            forces = solve(topo, P)
            area = np.array([np.mean(f > 0) for f in forces]) * SIZE**2
            hs = {}
            for radius in ("mean", "geometric"):
                s = map_summits(h, topo.pixel_size, periodic=True, radius=radius)
                c = icha_curve(s, P, E_star=MAT.E_star, interaction=False, coalescence=False)
                hs[radius] = (s, c.area / area)
            slope = rms_slope(topo)
            kappa = area / SIZE**2 / (RATIOS / slope)
            print(f"  {name_of(kind, hurst)}, seed {seed}: h' = {slope:.4f}")
            print("    A_BEM/A0           " + " ".join(f"{x:6.4f}" for x in area / SIZE**2))
            print("    Hertz sum / BEM, mean radius      " + " ".join(f"{x:5.3f}" for x in hs["mean"][1]))
            print("    Hertz sum / BEM, geometric radius " + " ".join(f"{x:5.3f}" for x in hs["geometric"][1]))
            print("    kappa_BEM = A/A0 / (p/E* h')      " + " ".join(f"{x:5.3f}" for x in kappa) +
                  f"   (Persson {KAPPA_PERSSON:.3f}, BGT {KAPPA_BGT:.3f})")
            s = hs["geometric"][0]
            line = []
            for f in forces[:5]:
                ratio = [A / (math.pi * (3 * F * s.R[k] / (4 * MAT.E_star)) ** (2 / 3))
                         for A, F, k in single_summit_spots(f, s, dx, grid)]
                line.append(f"{np.median(ratio):5.3f} ({len(ratio)})" if ratio else "  -  ")
            print("    single-summit spots: median A_BEM/A_Hertz(F_spot), geometric radius (spots): " + " ".join(line))


def summit_profiles(h, dx, s, reach, nr=48, nth=32):
    """Height drop below each summit's tip, f(r) >= 0, the azimuthal mean of the map (cubic
    interpolation, periodic) on nr radii up to ``reach`` [m]; made non-decreasing (a punch)."""
    r = np.linspace(0.0, reach, nr)
    th = np.linspace(0.0, 2 * np.pi, nth, endpoint=False)
    X = (s.x / dx)[:, None, None] + (r / dx)[None, :, None] * np.cos(th)
    Y = (s.y / dx)[:, None, None] + (r / dx)[None, :, None] * np.sin(th)
    ring = ndimage.map_coordinates(h, [X.ravel(), Y.ravel()], order=3, mode="grid-wrap").reshape(X.shape).mean(2)
    return r, np.maximum.accumulate(ring[:, :1] - ring, axis=1)


def sneddon_tables(r, f, E_star, nodes=48):
    """Sneddon (1965) for an axisymmetric punch of profile f(r) (f(0) = 0): at contact radius a,
    delta = a int_0^{pi/2} f'(a sin t) dt and P = 2 E* a^2 int_0^{pi/2} sin^2 t f'(a sin t) dt
    (Gauss-Legendre in t; f' piecewise constant between the radii).  Returns a = r[1:], delta, P
    per profile.  Checked against Hertz on a paraboloid before use (check_sneddon)."""
    x, w = special.roots_legendre(nodes)
    t, w = (x + 1) * np.pi / 4, w * np.pi / 4
    a = r[1:]
    slope = np.diff(f, axis=1) / np.diff(r)                       # on (r_k, r_k+1)
    k = np.clip(np.searchsorted(r, a[:, None] * np.sin(t), side="right") - 1, 0, len(r) - 2)
    fp = slope[:, k]                                              # (summits, a, nodes)
    delta = a * (fp @ w)
    P = 2 * E_star * a**2 * (fp @ (w * np.sin(t) ** 2))
    return a, delta, P


def check_sneddon():
    R, E = 1.0, 1.0
    r = np.linspace(0.0, 1.0, 4001)
    a, delta, P = sneddon_tables(r, (r**2 / (2 * R))[None, :], E, nodes=200)
    assert np.allclose(delta[0, 100:], a[100:] ** 2 / R, rtol=2e-3), "Sneddon delta != Hertz"
    assert np.allclose(P[0, 100:], 4 * E * a[100:] ** 3 / (3 * R), rtol=2e-3), "Sneddon P != Hertz"


def shape_sum(z, a, delta, P, loads):
    """Sum over summits at one flat height (bisection per load): total area of the shape law."""
    def at(d, table):
        pen = z - d
        return np.array([np.interp(p, dl, tb, left=0.0, right=np.nan) for p, dl, tb in zip(pen, delta, table,
                                                                                              strict=True)])
    area = np.pi * np.broadcast_to(a**2, P.shape)
    out = []
    for load in loads:
        lo, hi = z.min() - 1.0, z.max()
        for _ in range(100):
            mid = 0.5 * (lo + hi)
            F = at(mid, P)
            lo, hi = (mid, hi) if not np.all(np.isfinite(F)) or F.sum() > load else (lo, mid)
        beyond = not np.all(np.isfinite(at(lo, P)))   # the load needs a summit pressed beyond its profile
        out.append(np.nan if beyond else float(np.sum(at(hi, area))))
    return np.array(out)


def shape_law(seeds, grid, reaches=(0.5, 0.75, 1.0)):
    print(f"\n6. Diagnostic: each summit's own shape below the tip (Sneddon), {grid}^2; sum over the summits / BEM,"
          " profile followed to reach x lambda_s ('-': a summit pressed beyond its profile)")
    check_sneddon()
    for kind, hurst in SURFACES:
        for seed in seeds:
            topo = surface(kind, hurst, seed, grid)
            h = np.asarray(topo.heights())
            h = h - h.mean()
            dx = SIZE / grid
            P = SIZE**2 * MAT.E_star * RATIOS
            forces = solve(topo, P)
            area = np.array([np.mean(f > 0) for f in forces]) * SIZE**2
            s = map_summits(h, topo.pixel_size, periodic=True, radius="geometric")
            hertz = icha_curve(s, P, E_star=MAT.E_star, interaction=False, coalescence=False).area / area
            print(f"  {name_of(kind, hurst)}, seed {seed}: A_BEM/A0 " + " ".join(f"{x:6.4f}" for x in area / SIZE**2))
            print("    Hertz sum / BEM                  " + " ".join(f"{x:5.3f}" for x in hertz))
            tables = {}
            for reach in reaches:
                r, f = summit_profiles(h, dx, s, reach * LAMBDA_S)
                tables[reach] = sneddon_tables(r, f, MAT.E_star)
                ratio = shape_sum(s.z, *tables[reach], P) / area
                print(f"    shape sum / BEM, reach {reach:4.2f}     " +
                      " ".join("  -  " if not np.isfinite(x) else f"{x:5.3f}" for x in ratio))
            a, delta, Ptab = tables[max(reaches)]
            line = []
            for f in forces[:5]:
                ratio = [A / (np.pi * np.interp(F, Ptab[k], a, right=np.nan) ** 2)
                         for A, F, k in single_summit_spots(f, s, dx, grid)]
                ratio = [x for x in ratio if np.isfinite(x)]
                line.append(f"{np.median(ratio):5.3f} ({len(ratio)})" if ratio else "  -  ")
            print("    single-summit spots: median A_BEM/A_shape(F_spot): " + " ".join(line))


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--seeds", type=int, default=3)
    parser.add_argument("--no-fine", action="store_true", help="grid study on 256 and 512 only")
    parser.add_argument("--only-shape", action="store_true", help="check 6 only (about 2 min)")
    args = parser.parse_args()
    seeds = list(range(args.seeds))
    if args.only_shape:
        shape_law(seeds[:1], 512)
        return
    summit_statistics(seeds, 512)
    hertz_sum_and_spots(seeds[:1], 512)
    shape_law(seeds[:1], 512)
    tolerance_check()
    grid_study([256, 512] if args.no_fine else [256, 512, 1024], [0])


if __name__ == "__main__":
    main()
