"""The models against boundary elements on synthetic surfaces (the tables of docs/validation.md).

Run on one core: ``OPENBLAS_NUM_THREADS=1 .venv/bin/python benchmarks/bench_validation.py``
(about 40 minutes on a shared two-core machine; ``--quick`` for a smaller run).  For each surface type (self-affine with
Hurst 0.5, 0.8 and 0.9; Gaussian-correlated), several seeds and two grids of the *same*
band-limited surface (``asperity.validation.surfaces``), it solves the boundary-element
contact at loads spanning about 0.5 % to 30 % real area and puts the models beside it:
GW (spectral and detected summit parameters), ICHA (interacting and coalescing Hertzian
asperities on the detected summits), Persson's area and the BGT light-load asymptote.  It
writes every row to ``--out`` (CSV) and prints:

* per surface type and grid: the ratio A_model/A_BEM at each load band (mean over seeds,
  and the seed-to-seed standard deviation), and the same against the grid-extrapolated BEM
  area A_ext = 2 A_512 - A_256 (first order in the pixel size; bench_fairness.py measures
  the order);
* the largest |A_model/A_BEM - 1| up to 20 % real area (worst seed);
* the costs, best of N on one surface per grid: BEM (all loads), and each model with its
  own input analysis, and their ratios (with the load average of the machine).

A non-periodic (free-boundary) run of one surface shows the approach (separation of the
flat from the undeformed surface): BEM, GW, GW with the mean-field interaction, ICHA.
"""

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse  # noqa: E402
import csv  # noqa: E402
import time  # noqa: E402
import warnings  # noqa: E402

import numpy as np  # noqa: E402

from asperity.icha import icha_contact  # noqa: E402
from asperity.materials import material  # noqa: E402
from asperity.persson import persson_area_fraction, rms_slope  # noqa: E402
from asperity.physical import PhysicalContact  # noqa: E402
from asperity.plasticity import PlasticityWarning  # noqa: E402
from asperity.topography import analyse_surface  # noqa: E402
from asperity.validation import bem_contact, validate_surface  # noqa: E402
from asperity.validation.models import MODELS  # noqa: E402
from asperity.validation.surfaces import synthetic_surface  # noqa: E402

SIZE = 4e-6            # 4 um x 4 um, as in issue #13
LAMBDA_S = SIZE / 32   # shortest wavelength: 8 px on 256^2, 16 px on 512^2
SURFACES = [("self-affine", 0.5), ("self-affine", 0.8), ("self-affine", 0.9), ("gaussian", None)]
BANDS = [(0.0, 0.02), (0.02, 0.05), (0.05, 0.1), (0.1, 0.2), (0.2, 0.35)]
METHODS = ("spectral", "detected", "icha", "persson", "bgt")


def loads(mat, n):
    """Loads giving about 0.5 % to 30 % real area (A/A0 ~ 2 p/(E* h'), h' = 0.1)."""
    return SIZE**2 * mat.E_star * np.geomspace(2.5e-4, 1.6e-2, n)


def surface(kind, hurst, seed, grid, periodic=True):
    topo = synthetic_surface(kind, SIZE, grid, short_cutoff=LAMBDA_S, hurst=hurst or 0.8, long_cutoff=SIZE / 2,
                             seed=seed)
    if not periodic:
        from SurfaceTopography import Topography

        topo = Topography(topo.heights(), topo.physical_sizes, periodic=False, unit="m")
    return topo


def name_of(kind, hurst):
    return kind if hurst is None else f"{kind} H={hurst}"


def main():
    warnings.simplefilter("ignore", PlasticityWarning)   # gold yields at these loads: an elastic comparison
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--seeds", type=int, default=3)
    parser.add_argument("--grids", default="256,512")
    parser.add_argument("--loads", type=int, default=8)
    parser.add_argument("--quick", action="store_true", help="one seed, grids 128,256, 6 loads")
    parser.add_argument("--out", default="bench_validation.csv")
    parser.add_argument("--no-free", action="store_true", help="skip the non-periodic run")
    parser.add_argument("--no-costs", action="store_true", help="skip the best-of-N cost measurement")
    args = parser.parse_args()
    if args.quick:
        args.seeds, args.grids, args.loads = 1, "128,256", 6
    grids = [int(g) for g in args.grids.split(",")]
    mat = material("Au")
    rows = []
    print(f"{SIZE * 1e6:g} um square, shortest wavelength {LAMBDA_S * 1e9:g} nm, Au (E* = {mat.E_star / 1e9:.4g} GPa)")
    for kind, hurst in SURFACES:
        for grid in grids:
            for seed in range(args.seeds):
                start = time.perf_counter()
                r = validate_surface(surface(kind, hurst, seed, grid), loads(mat, args.loads), material=mat,
                                     models=MODELS)
                t = r.columns()
                for i in range(len(r)):
                    rows.append({"surface": name_of(kind, hurst), "grid": grid, "seed": seed,
                                 **{k: float(v[i]) for k, v in t.items()},
                                 "alpha_n": r.analysis.spectral.alpha_n, "n_summits": r.icha.n_summits,
                                 **{f"cost_{k}_s": r.costs[k] for k in ("bem", "analysis", "model", *MODELS[1:])}})
                print(f"  {name_of(kind, hurst):18s} grid {grid:4d} seed {seed}: alpha_N "
                      f"{r.analysis.spectral.alpha_n:5.1f}, {r.icha.n_summits:4d} summits, max |dev| <= 20 %: " +
                      ", ".join(f"{m} {r.deviation(m):.3f}" for m in METHODS) +
                      f"; BEM {r.costs['bem']:.1f} s, ICHA {r.costs['icha'] * 1e3:.0f} ms "
                      f"({time.perf_counter() - start:.0f} s)", flush=True)
    with open(args.out, "w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    summarise(rows, grids)
    if len(grids) >= 2:
        extrapolated(rows, grids)
    if not args.no_costs:
        costs(mat, grids, args.loads)
    if not args.no_free:
        free_run(mat, grids[0], args.loads)


def band_cells(sel, key, methods):
    out = []
    for lo, hi in BANDS:
        band = [r for r in sel if lo < r[key] <= hi]
        if not band:
            out.append(f"{'-':^11s}")
            continue
        vals = {m: np.array([r[f"ratio_{m}"] for r in band]) for m in methods}
        out.append(" ".join(f"{vals[m].mean():.2f}" + (f"±{vals[m].std():.2f}" if m == methods[0] else "")
                            for m in methods))
    return out


def summarise(rows, grids):
    for r in rows:
        for m in METHODS:
            r[f"ratio_{m}"] = 1 + r[f"dev_{m}"]
    print("\nA_model/A_BEM by BEM area band: mean over seeds (± seed-to-seed std for the first), models "
          + " | ".join(METHODS))
    print("surface            grid  " + "  ".join(f"{lo:>4.0%}-{hi:<4.0%}" for lo, hi in BANDS))
    for name in dict.fromkeys(r["surface"] for r in rows):
        for grid in grids:
            sel = [r for r in rows if r["surface"] == name and r["grid"] == grid]
            for m in METHODS:
                cells = band_cells(sel, "fraction_bem", (m,))
                print(f"{name:18s} {grid:4d} {m:9s} " + "  ".join(f"{c:11s}" for c in cells))
    print("\nlargest |A_model/A_BEM - 1| up to 20 % real area (worst seed):")
    for name in dict.fromkeys(r["surface"] for r in rows):
        for grid in grids:
            sel = [r for r in rows if r["surface"] == name and r["grid"] == grid and r["fraction_bem"] <= 0.2]
            print(f"{name:18s} {grid:4d}  " + "  ".join(f"{m} {max(abs(r[f'dev_{m}']) for r in sel):.3f}"
                                                      for m in METHODS))


def extrapolated(rows, grids):
    """Ratios on the finest grid against A_ext = 2 A_fine - A_coarse of the same surface, seed and load."""
    coarse, fine = grids[-2], grids[-1]
    key = {(r["surface"], r["seed"], round(r["P_N"], 15)): r for r in rows if r["grid"] == coarse}
    ext_rows = []
    for r in rows:
        if r["grid"] != fine:
            continue
        c = key[(r["surface"], r["seed"], round(r["P_N"], 15))]
        a_ext = 2 * r["area_bem_m2"] - c["area_bem_m2"]
        e = {"surface": r["surface"], "fraction_ext": a_ext / SIZE**2, "bias_fine": r["area_bem_m2"] / a_ext - 1,
             "bias_coarse": c["area_bem_m2"] / a_ext - 1}
        for m in METHODS:
            e[f"ratio_{m}"] = r[f"area_{m}_m2"] / a_ext
        ext_rows.append(e)
    print(f"\nagainst the extrapolated BEM area A_ext = 2 A_{fine} - A_{coarse} (models on the {fine} grid); "
          f"BEM bias A_{fine}/A_ext - 1 and A_{coarse}/A_ext - 1 per band:")
    for name in dict.fromkeys(r["surface"] for r in ext_rows):
        sel = [r for r in ext_rows if r["surface"] == name]
        for lo, hi in BANDS:
            band = [r for r in sel if lo < r["fraction_ext"] <= hi]
            if band:
                print(f"{name:18s} {lo:>4.0%}-{hi:<4.0%} bias {np.mean([r['bias_fine'] for r in band]):+.3f} "
                      f"{np.mean([r['bias_coarse'] for r in band]):+.3f}  " +
                      "  ".join(f"{m} {np.mean([r[f'ratio_{m}'] for r in band]):.2f}" for m in METHODS))
        up = [r for r in sel if r["fraction_ext"] <= 0.2]
        print(f"{name:18s} worst |A/A_ext - 1| up to 20 %: " +
              "  ".join(f"{m} {max(abs(r[f'ratio_{m}'] - 1) for r in up):.3f}" for m in METHODS))


def best(fn, n):
    times = []
    for _ in range(n):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return min(times)


def costs(mat, grids, n_loads):
    print(f"\ncosts, self-affine H=0.8 seed 0, {n_loads} loads, wall time best of N on one core "
          f"(load average before: {os.getloadavg()[0]:.1f}):")
    P = loads(mat, n_loads)
    for grid in grids:
        cost_line(mat, grid, P)


def cost_line(mat, grid, P):
    topo = surface("self-affine", 0.8, 0, grid)
    bem = best(lambda: bem_contact(topo, P, E_star=mat.E_star), 3 if grid <= 256 else 2)

    def gw():
        analysis = analyse_surface(topo)
        for method in ("spectral", "detected"):
            s = getattr(analysis, method)
            PhysicalContact(mat, s.surface(SIZE**2), adhesion=False).load_curve(P)

    t_gw = best(gw, 5)
    t_icha = best(lambda: icha_contact(topo, P, E_star=mat.E_star), 5)
    t_persson = best(lambda: persson_area_fraction(P / SIZE**2, mat.E_star, rms_slope(topo)), 5)
    print(f"  {grid:4d}^2: BEM {bem:7.2f} s | GW (analysis + curves) {t_gw * 1e3:7.1f} ms = {t_gw / bem:.1e} | "
          f"ICHA {t_icha * 1e3:7.1f} ms = {t_icha / bem:.1e} | Persson {t_persson * 1e3:5.2f} ms = "
          f"{t_persson / bem:.1e}  (load average after: {os.getloadavg()[0]:.1f})", flush=True)


def free_run(mat, grid, n_loads):
    print(f"\nnon-periodic (free boundaries), self-affine H=0.8, seed 0, grid {grid}: approach s (nm) of the flat "
          "from the undeformed mean plane")
    r = validate_surface(surface("self-affine", 0.8, 0, grid, periodic=False), loads(mat, n_loads), material=mat,
                         interaction="cgp2008", models="gw,icha")
    t = r.columns()
    plain = PhysicalContact(mat, r.analysis.spectral.surface(r.bem.nominal_area), adhesion=False).load_curve(t["P_N"])
    plain_sep = plain.d + r.analysis.spectral.mean_summit_height
    print("  A/A0(BEM)  A_GW/A_BEM  A_ICHA/A_BEM   s_BEM   s_GW  s_GW+cgp2008  s_ICHA   gap_BEM  gap_GW  gap_ICHA")
    for i in range(len(r)):
        print(f"  {t['fraction_bem'][i]:9.4f}  {1 + t['dev_spectral'][i]:9.3f}  {1 + t['dev_icha'][i]:11.3f}  "
              f"{t['sep_bem_m'][i] * 1e9:7.2f} {plain_sep[i] * 1e9:6.2f}  {t['sep_spectral_m'][i] * 1e9:11.2f}  "
              f"{t['sep_icha_m'][i] * 1e9:6.2f}  {t['gap_bem_m'][i] * 1e9:8.2f} {t['gap_spectral_m'][i] * 1e9:7.2f} "
              f"{t['gap_icha_m'][i] * 1e9:8.2f}")
    print(f"  BEM {r.costs['bem']:.1f} s, GW {r.costs['model'] * 1e3:.2f} ms, ICHA {r.costs['icha'] * 1e3:.0f} ms")


if __name__ == "__main__":
    main()
