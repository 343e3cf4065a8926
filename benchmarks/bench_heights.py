"""Speed of the model with non-Gaussian summit heights (run: .venv/bin/python benchmarks/bench_heights.py).

Target (issue #10): a 1000-load mu-P curve with a non-Gaussian height distribution within
3x of the Gaussian's time.  Each curve is a fresh ``asperity.load_curve`` (a new Model:
the tabulation, the law on its nodes, the separation panels), on one core
(OPENBLAS_NUM_THREADS=1), best of N wall-clock runs; the CPU time of the same best run is
printed too (the machine may be shared).  With ``--accuracy`` it also compares a few loads
against the reference path (asperity.reference, a density rebuilt from its definition and
adaptive quadrature), which takes a few seconds per distribution.
"""

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # one core, no BLAS thread noise

import argparse  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402

import asperity  # noqa: E402
from asperity.heights import (  # noqa: E402
    GAUSSIAN,
    Empirical,
    Exponential,
    Johnson,
    Mixture,
    PearsonIII,
    Weibull,
)

ALPHA, BETA = 0.01, 1000.0
LOADS = np.geomspace(1e-2, 1e5, 1000)


def distributions():
    summits = np.random.default_rng(20240613).gamma(3.0, size=900)
    return {
        "gaussian": GAUSSIAN,
        "exponential": Exponential(),
        "weibull:skew=0.5": Weibull(0.5),
        "weibull:skew=-0.8": Weibull(-0.8),
        "pearson3:skew=1": PearsonIII(1.0),
        "pearson3:skew=-0.3": PearsonIII(-0.3),
        "johnson:skew=0.5,kurt=4 (S_U)": Johnson(0.5, 4.0),
        "johnson:skew=-0.5,kurt=3.2 (S_B)": Johnson(-0.5, 3.2),
        "mixture (plateau, s1=0.41)": Mixture(0.8, 0.5, 0.5, -2.0, 1.2),
        "mixture (narrow, s1=0.33)": Mixture(0.7, 0.5, 0.3, -1.0, 1.0),
        "empirical (900 summits)": Empirical.from_samples(summits),
    }


def best_of(fn, repeat):
    best = (float("inf"), float("inf"))
    for _ in range(repeat):
        t, c = time.perf_counter(), time.process_time()
        fn()
        best = min(best, (time.perf_counter() - t, time.process_time() - c))
    return best


def accuracy(heights, gamma):
    """Largest relative difference of d, F, area against the reference path at three loads."""
    from asperity import reference
    from asperity.reference.heights import reference_density

    spec = getattr(heights, "spec", None) or "gaussian"
    name, _, rest = spec.partition(":")
    if isinstance(heights, Empirical):
        w, m, s = heights.translates()
        ref = reference_density("gauss_mixture", weights=w, means=m, sds=(s,) * len(w))
    elif heights is GAUSSIAN:
        ref = None
    else:
        params = {k: float(v) for k, v in (item.split("=") for item in rest.split(",") if item)}
        ref = reference_density(name, **params)
    loads = np.array([0.1, 10.0, 1e3])
    curve = asperity.load_curve(loads, ALPHA, BETA, gamma, heights=heights)
    err = 0.0
    for i, P in enumerate(loads):
        r = reference.load_point(P, ALPHA, BETA, gamma, heights=ref)
        err = max(err, abs(curve.d[i] - r["d"]) / max(1.0, abs(r["d"])), abs(curve.F[i] / r["F"] - 1),
                  abs(curve.area[i] / r["area"] - 1))
    return err


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--repeat", type=int, default=7, help="runs per curve (the best counts)")
    parser.add_argument("--accuracy", action="store_true", help="also compare three loads with the reference path")
    args = parser.parse_args()
    dists = distributions()
    for gamma, label in ((1e-3, "with adhesion (gamma = 1e-3), as benchmarks/bench_core.py"),
                         (0.0, "without adhesion (Hertz)")):
        print(f"1000-load mu-P curve, alpha={ALPHA}, beta={BETA:g}, {label}:")
        base = None
        for name, heights in dists.items():
            asperity.load_curve(LOADS[:5], ALPHA, BETA, gamma, heights=heights)  # warm-up
            wall, cpu = best_of(lambda h=heights, g=gamma: asperity.load_curve(LOADS, ALPHA, BETA, g, heights=h),
                                args.repeat)
            base = wall if base is None else base
            line = f"  {name:34s} {wall * 1e3:7.2f} ms (cpu {cpu * 1e3:6.2f})  x{wall / base:4.2f}"
            if args.accuracy:
                line += f"   vs reference {accuracy(heights, gamma):.1e}"
            print(line + ("" if wall <= 3 * base else "   (above the 3x target)"))


if __name__ == "__main__":
    main()
