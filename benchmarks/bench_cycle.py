"""Speed of loading-unloading cycles, on one core (run: .venv/bin/python benchmarks/bench_cycle.py).

Targets (issue #9): a 500-point cycle in <= 50 ms; pull-off (and energy) against 100 preloads
in <= 1 s.  Each call starts from the parameters (a new Model: tabulations built inside the
timing).  Best of N, wall time and CPU time of the process (on a machine shared with other jobs
the CPU time is the one-core cost); also the agreement with the independent reference path on
a few points (--reference).
"""

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # one core, no BLAS thread noise

import argparse  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402

from asperity import reference  # noqa: E402
from asperity.cycle import cycle, preload_curve  # noqa: E402

CASES = {"lambda 0.52 (alpha 0.01, beta 1000, gamma 1e-3)": (0.01, 1000.0, 1e-3),
         "lambda 0.78 (Table 1 row 2)": (0.003, 1000.0, 1e-3),
         "lambda 1.13 (alpha 0.02, beta 50, gamma 0.02)": (0.02, 50.0, 0.02)}


def best_of(fn, repeat):
    """Best wall time and best CPU time of this process (the latter is robust on a shared machine)."""
    wall, cpu = [], []
    for _ in range(repeat):
        t, c = time.perf_counter(), time.process_time()
        out = fn()
        cpu.append(time.process_time() - c)
        wall.append(time.perf_counter() - t)
    return (min(wall), min(cpu)), out


def ms(t):
    return f"{t[0] * 1e3:8.2f} ms wall, {t[1] * 1e3:7.2f} ms CPU"


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--repeat", type=int, default=7, help="best of this many runs")
    parser.add_argument("--reference", action="store_true", help="also compare a few points with the reference")
    args = parser.parse_args()
    preloads = np.geomspace(1e-2, 1e6, 100)
    for label, p in CASES.items():
        cycle(*p, preload=10.0, n=20)  # imports and lambda caches
        t250, _ = best_of(lambda p=p: cycle(*p, preload=10.0, n=250), args.repeat)
        t500, c = best_of(lambda p=p: cycle(*p, preload=10.0, n=500), args.repeat)
        tk, ck = best_of(lambda p=p: cycle(*p, preload=10.0, n=500, stiffness=50.0), args.repeat)
        tpre, pc = best_of(lambda p=p: preload_curve(preloads, *p), max(3, args.repeat // 2))
        print(f"{label}:")
        print(f"  cycle, 2 x 250 points (500 in all)   {ms(t250)}   (target <= 50 ms)")
        print(f"  cycle, 2 x 500 points                {ms(t500)}")
        print(f"  cycle, 2 x 500 points, spring k = 50 {ms(tk)}   ({len(ck.jumps)} jumps)")
        print(f"  pull-off and energy, 100 preloads    {ms(tpre)}   (target <= 1000 ms)")
        if args.reference:
            d = np.array([c.d_min + 0.5 * (c.u_in - c.u_end), c.d_min + (c.u_in - c.u_end) + 0.5])
            fast = cycle(*p, preload=10.0, d=d)
            t0 = time.perf_counter()
            err = 0.0
            for i, x in enumerate(d):
                a = reference.approach_point(x, *p)
                r = reference.retract_point(x, c.d_min, *p)
                for key in ("contacts", "F", "area", "P"):
                    err = max(err, abs(getattr(fast.approach, key)[i] / a[key] - 1),
                              abs(getattr(fast.retract, key)[i] / r[key] - 1))
            e_ref = reference.cycle_energy(c.d_min, c.d_max, *p)
            t_ref = time.perf_counter() - t0
            print(f"  reference: {len(d)} points on both branches and the energy in {t_ref:.1f} s; largest "
                  f"relative difference {err:.1e} (points), {abs(c.energy / e_ref - 1):.1e} (energy)")


if __name__ == "__main__":
    main()
