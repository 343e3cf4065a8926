"""Speed of the Jackson-Green law, on one core (run: .venv/bin/python benchmarks/bench_plasticity.py).

Target: a 1000-load mu-P curve with the elastic-plastic law (with and without the Nix-Gao
size effect) within 3x of the same curve with the elastic (Hertz) law, new Model each time
(the law's set-up included), best of 7; and its agreement with the reference path.
"""

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # one core, no BLAS thread noise

import time  # noqa: E402

import numpy as np  # noqa: E402

from asperity import JacksonGreen, Model, reference  # noqa: E402

ALPHA, BETA, NU, H, H_STAR = 0.05, 1000.0, 0.3, 0.005, 0.5


def best_of(fn, repeat=7):
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - t)
    return min(times), out


def main():
    loads = np.geomspace(1.0, 1e5, 1000)
    Model(ALPHA, BETA, nu=NU, law=JacksonGreen(H)).load_curve(loads[:5])  # warm-up
    t_el, _ = best_of(lambda: Model(ALPHA, BETA, nu=NU).load_curve(loads))
    t_jg, curve = best_of(lambda: Model(ALPHA, BETA, nu=NU, law=JacksonGreen(H)).load_curve(loads))
    t_ng, _ = best_of(lambda: Model(ALPHA, BETA, nu=NU, law=JacksonGreen(H, H_STAR)).load_curve(loads))
    pick = [0, 500, 999]
    refs = [reference.jg_load_point(loads[i], ALPHA, BETA, NU, H) for i in pick]
    err = max(max(abs(curve.F[i] / r["F"] - 1), abs(curve.area[i] / r["area"] - 1), abs(curve.d[i] - r["d"]))
              for i, r in zip(pick, refs, strict=True))
    print(f"1000-load mu-P curve (alpha={ALPHA}, beta={BETA:g}, nu={NU}, H/E*={H}), new Model each time:")
    print(f"  elastic (Hertz)              {t_el * 1e3:7.2f} ms")
    print(f"  Jackson-Green                {t_jg * 1e3:7.2f} ms   ({t_jg / t_el:.2f}x, target <= 3x)")
    print(f"  Jackson-Green + Nix-Gao      {t_ng * 1e3:7.2f} ms   ({t_ng / t_el:.2f}x, target <= 3x)")
    print(f"  max difference from the reference path (F, area relative; d absolute): {err:.1e}")


if __name__ == "__main__":
    main()
