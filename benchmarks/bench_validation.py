"""The statistical model against boundary elements on synthetic surfaces (the tables of docs/validation.md).

Run on one core: ``OPENBLAS_NUM_THREADS=1 .venv/bin/python benchmarks/bench_validation.py``
(about 10 minutes; ``--quick`` for a smaller run).  For each surface type (self-affine with
Hurst 0.5, 0.8 and 0.9; Gaussian-correlated), several seeds and two grids of the *same*
band-limited surface (``asperity.validation.surfaces``), it solves the boundary-element
contact at loads spanning about 0.5 % to 30 % real area and puts GW beside it (spectral
and detected summit parameters).  It writes every row to ``--out`` (CSV) and prints:

* per surface type and grid: the ratio A_GW/A_BEM at each load band (mean over seeds,
  and the seed-to-seed standard deviation);
* the largest |A_GW/A_BEM - 1| up to 20 % real area;
* the costs: BEM (all loads), summit analysis, model curves, and the ratio.

A non-periodic (free-boundary) run of one surface shows the approach (separation of the
flat from the undeformed surface) with and without the mean-field interaction (cgp2008).
"""

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import argparse  # noqa: E402
import csv  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402

from asperity.materials import material  # noqa: E402
from asperity.physical import PhysicalContact  # noqa: E402
from asperity.validation import validate_surface  # noqa: E402
from asperity.validation.surfaces import synthetic_surface  # noqa: E402

SIZE = 4e-6            # 4 um x 4 um, as in issue #13
LAMBDA_S = SIZE / 32   # shortest wavelength: 8 px on 256^2, 16 px on 512^2
SURFACES = [("self-affine", 0.5), ("self-affine", 0.8), ("self-affine", 0.9), ("gaussian", None)]
BANDS = [(0.0, 0.02), (0.02, 0.05), (0.05, 0.1), (0.1, 0.2), (0.2, 0.35)]


def loads(mat, n):
    """Loads giving about 0.5 % to 30 % real area (A/A0 ~ 2 p/(E* h'), h' = 0.1)."""
    return SIZE**2 * mat.E_star * np.geomspace(2.5e-4, 1.6e-2, n)


def run(kind, hurst, seed, grid, mat, n_loads, periodic=True, interaction="none"):
    topo = synthetic_surface(kind, SIZE, grid, short_cutoff=LAMBDA_S, hurst=hurst or 0.8,
                             long_cutoff=SIZE / 2, seed=seed)
    if not periodic:
        from SurfaceTopography import Topography

        topo = Topography(topo.heights(), topo.physical_sizes, periodic=False, unit="m")
    return validate_surface(topo, loads(mat, n_loads), material=mat, interaction=interaction)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--seeds", type=int, default=3)
    parser.add_argument("--grids", default="256,512")
    parser.add_argument("--loads", type=int, default=8)
    parser.add_argument("--quick", action="store_true", help="one seed, grids 128,256, 6 loads")
    parser.add_argument("--out", default="bench_validation.csv")
    parser.add_argument("--no-free", action="store_true", help="skip the non-periodic run")
    args = parser.parse_args()
    if args.quick:
        args.seeds, args.grids, args.loads = 1, "128,256", 6
    grids = [int(g) for g in args.grids.split(",")]
    mat = material("Au")
    rows = []
    print(f"{SIZE * 1e6:g} um square, shortest wavelength {LAMBDA_S * 1e9:g} nm, Au (E* = {mat.E_star / 1e9:.4g} GPa)")
    for kind, hurst in SURFACES:
        name = kind if hurst is None else f"{kind} H={hurst}"
        for grid in grids:
            for seed in range(args.seeds):
                start = time.perf_counter()
                r = run(kind, hurst, seed, grid, mat, args.loads)
                t = r.columns()
                for i in range(len(r)):
                    rows.append({"surface": name, "grid": grid, "seed": seed,
                                 **{k: float(v[i]) for k, v in t.items()},
                                 "alpha_n": r.analysis.spectral.alpha_n,
                                 "n_summits": r.analysis.detected.n_summits,
                                 "cost_bem_s": r.costs["bem"], "cost_analysis_s": r.costs["analysis"],
                                 "cost_model_s": r.costs["model"]})
                print(f"  {name:18s} grid {grid:4d} seed {seed}: alpha_N {r.analysis.spectral.alpha_n:5.1f}, "
                      f"{r.analysis.detected.n_summits:4d} summits, max |dev| <= 20 %: spectral "
                      f"{r.deviation('spectral'):.3f}, detected {r.deviation('detected'):.3f}; BEM "
                      f"{r.costs['bem']:.2f} s, analysis {r.costs['analysis'] * 1e3:.1f} ms, model "
                      f"{r.costs['model'] * 1e3:.2f} ms ({time.perf_counter() - start:.1f} s)", flush=True)
    with open(args.out, "w", newline="") as fh:
        writer = csv.DictWriter(fh, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    summarise(rows, grids)
    if not args.no_free:
        free_run(mat, grids[0], args.loads)


def summarise(rows, grids):
    print("\nA_GW/A_BEM (spectral | detected), mean +- seed-to-seed std, by BEM area band:")
    header = "surface            grid  " + "  ".join(f"{lo:>4.0%}-{hi:<4.0%}      " for lo, hi in BANDS)
    print(header)
    for name in dict.fromkeys(r["surface"] for r in rows):
        for grid in grids:
            sel = [r for r in rows if r["surface"] == name and r["grid"] == grid]
            cells = []
            for lo, hi in BANDS:
                band = [r for r in sel if lo < r["fraction_bem"] <= hi]
                if not band:
                    cells.append(f"{'-':^17s}")
                    continue
                s = np.array([1 + r["dev_spectral"] for r in band])
                d = np.array([1 + r["dev_detected"] for r in band])
                cells.append(f"{s.mean():.2f}+-{s.std():.2f}|{d.mean():.2f}   ")
            print(f"{name:18s} {grid:4d}  " + "  ".join(cells))
    print("\nlargest |A_GW/A_BEM - 1| up to 20 % real area, and costs (per run, mean over seeds):")
    for name in dict.fromkeys(r["surface"] for r in rows):
        for grid in grids:
            sel = [r for r in rows if r["surface"] == name and r["grid"] == grid and r["fraction_bem"] <= 0.2]
            runs = {r["seed"]: r for r in rows if r["surface"] == name and r["grid"] == grid}
            bem = np.mean([r["cost_bem_s"] for r in runs.values()])
            ana = np.mean([r["cost_analysis_s"] for r in runs.values()])
            mod = np.mean([r["cost_model_s"] for r in runs.values()])
            area = np.mean([r["area_bem_m2"] for r in sel if r["fraction_bem"] > 0.1] or [np.nan])
            print(f"{name:18s} {grid:4d}  spectral {max(abs(r['dev_spectral']) for r in sel):.3f}  detected "
                  f"{max(abs(r['dev_detected']) for r in sel):.3f}  BEM {bem:7.2f} s  analysis {ana * 1e3:6.1f} ms "
                  f" model {mod * 1e3:5.2f} ms  model/BEM {mod / bem:.1e}  (model+analysis)/BEM "
                  f"{(mod + ana) / bem:.1e}  [mean BEM area 10-20 %: {area:.4g} m^2]")


def free_run(mat, grid, n_loads):
    print(f"\nnon-periodic (free boundaries), self-affine H=0.8, seed 0, grid {grid}: approach s (nm) of the flat "
          "from the undeformed mean plane")
    r = run("self-affine", 0.8, 0, grid, mat, n_loads, periodic=False, interaction="cgp2008")
    t = r.columns()
    plain = PhysicalContact(mat, r.analysis.spectral.surface(r.bem.nominal_area), adhesion=False).load_curve(t["P_N"])
    plain_sep = plain.d + r.analysis.spectral.mean_summit_height
    print("  A/A0(BEM)  A_GW/A_BEM   s_BEM   s_GW   s_GW+cgp2008   gap_BEM  gap_GW")
    for i in range(len(r)):
        print(f"  {t['fraction_bem'][i]:9.4f}  {1 + t['dev_spectral'][i]:9.3f}  {t['sep_bem_m'][i] * 1e9:7.2f} "
              f"{plain_sep[i] * 1e9:7.2f}  {t['sep_spectral_m'][i] * 1e9:9.2f}  {t['gap_bem_m'][i] * 1e9:9.2f} "
              f"{t['gap_spectral_m'][i] * 1e9:7.2f}")
    print(f"  BEM {r.costs['bem']:.1f} s, model {r.costs['model'] * 1e3:.2f} ms")


if __name__ == "__main__":
    main()
