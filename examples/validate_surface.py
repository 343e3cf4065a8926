"""Is the statistical model good enough for my surface?  Check it against boundary elements.

    python examples/validate_surface.py                      # a synthetic 4 um self-affine scan
    python examples/validate_surface.py scan.npy 4um nm      # your scan: file, size, height unit
    python examples/validate_surface.py --grid 128 --out out # smaller, faster

It solves the full elastic contact of the surface (boundary elements, ContactMechanics:
``pip install 'asperity[bem]'``) at loads giving about 0.5 % to 30 % real contact area,
puts the models beside it -- Greenwood-Williamson (summit parameters from the spectral
moments and from detected summits), the interacting and coalescing Hertzian asperities on the
scan's own summits (ICHA), Persson's area and the Bush-Gibson-Thomas light-load asymptote --
prints the table, the largest deviation up to 20 % real area and the costs, and writes
``validation.csv`` and ``validation.png`` to ``--out`` (and, for the synthetic surface, its
heights in nm as ``scan.npy``, a file to try ``asperity bem`` on: ``asperity bem
validation/scan.npy --size 4um,4um --unit nm --material Au --load 1mN:100mN:8``).
"""

from __future__ import annotations

import argparse
import pathlib
import sys
import warnings

import numpy as np

from asperity import AsperityWarning
from asperity.materials import material
from asperity.validation import validate_surface
from asperity.validation.models import MODELS
from asperity.validation.surfaces import synthetic_surface


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scan", nargs="?", help="height map (default: a synthetic self-affine surface)")
    parser.add_argument("size", nargs="?", help="scan size with a unit, e.g. 4um (files that store none)")
    parser.add_argument("unit", nargs="?", help="unit of the stored heights, e.g. nm (files that store none)")
    parser.add_argument("--grid", type=int, default=256, help="points per side (synthetic) or subsampling")
    parser.add_argument("--loads", type=int, default=8)
    parser.add_argument("--out", default="validation", help="folder for validation.csv and validation.png")
    args = parser.parse_args(argv)
    gold = material("Au")
    if args.scan is None:
        surface = synthetic_surface("self-affine", 4e-6, args.grid, short_cutoff=4e-6 / 32, hurst=0.8,
                                    long_cutoff=2e-6, seed=0) if args.grid >= 128 else \
            synthetic_surface("self-affine", 4e-6, args.grid, short_cutoff=4e-6 * 4 / args.grid, hurst=0.8, seed=0)
        kwargs, area = {}, 16e-12
    else:
        kwargs = {k: v for k, v in (("physical_sizes", args.size), ("unit", args.unit)) if v}
        kwargs["grid"] = args.grid
        surface = args.scan
        area = None
    if area is None:  # nominal pressure range from the scan's own size, once read
        from asperity.topography import read_topography

        topo = read_topography(surface, **{k: v for k, v in kwargs.items() if k != "grid"})
        area = float(np.prod(topo.physical_sizes))
    # A/A0 ~ 2 p / (E* h'), h' ~ 0.1: these loads span about 0.5 % to 30 % real area
    loads = area * gold.E_star * np.geomspace(2.5e-4, 1.6e-2, args.loads)
    result = validate_surface(surface, loads, material=gold, models=MODELS, **kwargs)
    t = result.columns()
    print(f"{result.bem.nb_grid_pts[0]} x {result.bem.nb_grid_pts[1]} grid, "
          f"{'periodic' if result.bem.periodic else 'free'} boundaries, {result.analysis.detected.n_summits} "
          f"summits, alpha_N = {result.analysis.spectral.alpha_n:.3g}")
    print("A_model/A_BEM:")
    print(f"{'P [N]':>10} {'A/A0 BEM':>9} " + " ".join(f"{m:>9}" for m in result.methods) +
          f" {'gap BEM [nm]':>13} {'gap GW':>7} {'gap ICHA':>8} {'spots':>6} {'GW':>6} {'ICHA':>5}")
    for i in range(len(result)):
        print(f"{t['P_N'][i]:10.4g} {t['fraction_bem'][i]:9.4f} " +
              " ".join(f"{1 + t[f'dev_{m}'][i]:9.3f}" for m in result.methods) +
              f" {t['gap_bem_m'][i] * 1e9:13.3f} {t['gap_spectral_m'][i] * 1e9:7.2f} {t['gap_icha_m'][i] * 1e9:8.2f}"
              f" {t['spots_bem'][i]:6d} {t['contacts_spectral'][i]:6.1f} {t['spots_icha'][i]:5d}")
    if np.min(t["fraction_bem"]) <= 0.2:
        print("largest |A_model/A_BEM - 1| up to 20 % real area: " +
              ", ".join(f"{m} {result.deviation(m):.1%}" for m in result.methods))
    c = result.costs
    print(f"cost: boundary elements {c['bem']:.2f} s; model / BEM (each with its own analysis of the scan): " +
          ", ".join(f"{m} {v:.1e}" for m, v in result.cost_ratios.items()))
    for note in result.parameters["warnings"]:
        print(f"note: {note}")
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    result.to_csv(out / "validation.csv")
    result.plot(out / "validation.png")
    if args.scan is None:  # a file for the command line's examples (docs/validation.md)
        np.save(out / "scan.npy", surface.heights() * 1e9)
    return result


if __name__ == "__main__":
    with warnings.catch_warnings(record=True) as caught:  # the library's notes, one line each
        warnings.simplefilter("always", AsperityWarning)
        try:
            main()
        except (ValueError, TypeError) as err:  # a file without size, a bad unit, ...: one line
            print(f"validate_surface.py: error: {' '.join(str(err).split())}", file=sys.stderr)
            sys.exit(2)
        finally:
            for w in caught:
                print(f"note: {w.message}", file=sys.stderr)
