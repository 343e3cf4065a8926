"""Speed of the fits, on one core (run: .venv/bin/python benchmarks/bench_fit.py).

Targets (issue #8): the rough-surface model with adhesion, 3 free parameters (alpha, beta,
gamma), fitted to 50 friction-load points in <= 2 s; a joint fit of 5 data sets (five
roughnesses alpha_1..alpha_5, shared beta and gamma: 7 free parameters, 150 points) in
<= 10 s.  Reports best-of-N wall times (N = --repeat), residual evaluations per fit, model
evaluations actually computed (the rest come from the per-fit cache), the cost of one
evaluation and how much of it is building the Model, and the one-off cost of importing
lmfit (a fresh interpreter).
"""

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # one core, no BLAS thread noise

import argparse  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402

import asperity  # noqa: E402
from asperity.fit import fit_friction_load, fit_joint, friction_load_data  # noqa: E402

TRUTH = {"alpha": 0.012, "beta": 800.0, "gamma": 2e-3}
ALPHAS = (0.004, 0.006, 0.008, 0.010, 0.012)


def noisy(P, alpha, beta, gamma, seed, rel=0.02):
    F = asperity.load_curve(P, alpha, beta, gamma).F
    return friction_load_data(P, F * (1 + rel * np.random.default_rng(seed).standard_normal(P.size)),
                              F_err=rel * F, name=f"alpha={alpha:g}")


def best_of(fn, repeat):
    times, out = [], None
    for _ in range(repeat):
        t = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t)
    return min(times), out


def import_time():
    code = "import time; t = time.perf_counter(); import lmfit; print(time.perf_counter() - t)"
    res = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    return float(res.stdout)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--repeat", type=int, default=3, help="best of this many runs")
    args = parser.parse_args()
    P = np.geomspace(1.0, 1e4, 50)
    data = noisy(P, *TRUTH.values(), seed=1)
    start = {"alpha": 0.008, "beta": 1500.0, "gamma": 1e-3}
    fit_friction_load(data, "gw", start=start, ci="wald")  # warm-up: imports, lmfit
    t_wald, res = best_of(lambda: fit_friction_load(data, "gw", start=start, ci="wald"), args.repeat)
    t_auto, res_auto = best_of(lambda: fit_friction_load(data, "gw", start=start, ci="auto"), args.repeat)

    # Cost of one model evaluation, and of building the Model alone.
    a, b, g = (res.values[k] for k in ("alpha", "beta", "gamma"))
    n = 20
    t_eval, _ = best_of(lambda: [asperity.Model(a * (1 + 1e-7 * i), b, g).load_curve(P) for i in range(n)], 3)
    t_build, _ = best_of(lambda: [asperity.Model(a * (1 + 1e-7 * i), b, g) for i in range(n)], 3)
    t_eval, t_build = t_eval / n, t_build / n

    sets = [noisy(np.geomspace(1.0, 1e4, 30), alpha, TRUTH["beta"], TRUTH["gamma"], seed=10 + k)
            for k, alpha in enumerate(ALPHAS)]
    start_j = {"alpha": 0.008, "beta": 1500.0, "gamma": 1e-3}
    t_joint, joint = best_of(lambda: fit_joint(sets, "gw", shared=["beta", "gamma"], start=start_j, ci="wald"),
                             args.repeat)

    print("Rough-surface model with adhesion, 50 friction-load points, 3 free parameters (alpha, beta, gamma):")
    print(f"  fit, Wald intervals        {t_wald:7.3f} s   (target <= 2 s)   {res.nfev} residual evaluations, "
          f"{res.model_evaluations} models computed")
    print(f"  fit, ci='auto' (profiles)  {t_auto:7.3f} s   {res_auto.nfev} + {res_auto.profile_nfev} (profile) "
          f"evaluations; profiled: {[k for k, p in res_auto.parameters.items() if p.method == 'profile']}")
    print(f"  one evaluation (Model + load_curve, 50 loads) {t_eval * 1e3:.2f} ms, of which building the Model "
          f"{t_build * 1e3:.2f} ms ({t_build / t_eval:.0%})")
    print("  recovered: " + ", ".join(f"{k} = {res.values[k]:.5g} (true {v:g}, 95% "
                                      f"[{res.parameters[k].ci95[0]:.4g}, {res.parameters[k].ci95[1]:.4g}])"
                                      for k, v in TRUTH.items()))
    print(f"Joint fit of 5 data sets (30 points each, alpha_1..5 own, beta and gamma shared, 7 free): "
          f"{t_joint:.3f} s   (target <= 10 s)")
    print(f"  {joint.nfev} residual evaluations, {joint.model_evaluations} models computed "
          f"(a Jacobian column of alpha_k recomputes data set k only)")
    print(f"  beta = {joint.values['beta']:.5g}, gamma = {joint.values['gamma']:.5g}; alphas "
          + ", ".join(f"{joint.values[f'alpha_{k + 1}']:.4g}" for k in range(5)))
    print(f"Importing lmfit in a fresh interpreter (once per process): {import_time():.2f} s")


if __name__ == "__main__":
    main()
