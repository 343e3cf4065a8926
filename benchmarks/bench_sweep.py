"""Throughput of asperity.sweep, serial and on a local Dask cluster (run: .venv/bin/python benchmarks/bench_sweep.py).

Targets (issue #12): on 2 workers a scaling efficiency >= 80 % over one core, and 10^4
parameter sets of 100 loads with adhesion in <= 15 s on the 2-core machine.  The grid is
alpha x gamma (beta = 1000, loads 1e-2..1e5), the results streamed to a NetCDF file.
Each figure is the best of ``--repeat`` runs; the workers are started and warmed up
(imports, a first small sweep) before timing.  Other jobs on the machine slow it down:
check ``uptime`` and compare figures measured in the same run.
"""

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # one core per process, no BLAS thread noise

import argparse  # noqa: E402
import logging  # noqa: E402
import math  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402

import numpy as np  # noqa: E402

import asperity  # noqa: E402

LOADS = np.geomspace(1e-2, 1e5, 100)


def grid(n_sets):
    """alpha x gamma with about n_sets cells over the typical adhesive range."""
    n = max(1, round(math.sqrt(n_sets)))
    m = max(1, round(n_sets / n))
    return dict(alpha=np.geomspace(1e-3, 0.1, n), beta=1000.0, gamma=np.geomspace(1e-5, 1e-2, m), P=LOADS)


def _cpu(scheduler):
    """CPU seconds used so far by the processes that compute: this one, or the workers."""
    if scheduler == "serial":
        return time.process_time()
    return sum(scheduler.run(time.process_time).values())


def timed(n_sets, scheduler, repeat):
    """Best wall time of ``repeat`` sweeps, the CPU seconds of that run, and the sets that failed."""
    best, cpu = math.inf, math.inf
    for _ in range(repeat):
        with tempfile.TemporaryDirectory() as tmp:
            c, t = _cpu(scheduler), time.perf_counter()
            ds = asperity.sweep(**grid(n_sets), out=os.path.join(tmp, "map.nc"), scheduler=scheduler)
            wall, used = time.perf_counter() - t, _cpu(scheduler) - c
            if wall < best:
                best, cpu = wall, used
            failed = int((ds.message.values != "").sum())
            ds.close()
    return best, cpu, failed


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sets", type=int, default=1024, help="parameter sets for the throughput figures")
    parser.add_argument("--big", type=int, default=10_000, help="parameter sets of the large run on 2 workers "
                                                                 "(0: skip)")
    parser.add_argument("--repeat", type=int, default=3, help="best of this many runs")
    parser.add_argument("--dask-defaults", action="store_true",
                        help="workers with Dask's default settings instead of asperity's (LOCAL_WORKER_CONFIG)")
    args = parser.parse_args()
    import contextlib

    from distributed import Client, LocalCluster

    from asperity.sweeps.run import local_worker_settings

    asperity.sweep(**grid(16), scheduler="serial")  # imports and caches warm
    print(f"load average before: {os.getloadavg()[0]:.2f} (other jobs on the machine slow every figure)")
    t1, c1, failed = timed(args.sets, "serial", args.repeat)
    n = grid(args.sets)
    n_sets = n["alpha"].size * n["gamma"].size
    print(f"grid: {n_sets} sets (alpha x gamma), {LOADS.size} loads each, adhesion; {failed} outside the domain")
    print(f"  serial       {t1:7.2f} s   {n_sets / t1:8.0f} sets/s   {t1 / n_sets * 1e3:6.2f} ms/set "
          f"({c1 / n_sets * 1e3:.2f} ms CPU)")
    settings = contextlib.nullcontext() if args.dask_defaults else local_worker_settings()  # as 'asperity sweep'
    with settings, LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                dashboard_address=":0", silence_logs=logging.ERROR) as cluster, \
            Client(cluster) as client:
        client.run(lambda: __import__("asperity.sweeps.compute"))
        asperity.sweep(**grid(64), scheduler=client, chunk_sets=8)  # workers warm
        t2, c2, _ = timed(args.sets, client, args.repeat)
        eff = t1 / t2 / 2
        print(f"  2 workers    {t2:7.2f} s   {n_sets / t2:8.0f} sets/s   scaling efficiency {eff * 100:5.1f} %"
              f"   (target >= 80 %; workers' CPU {c2 / n_sets * 1e3:.2f} ms/set)")
        if args.big:
            tb, cb, failed = timed(args.big, client, 1)
            nb = grid(args.big)
            nb = nb["alpha"].size * nb["gamma"].size
            print(f"  {nb} sets of {LOADS.size} loads on 2 workers: {tb:6.2f} s   ({failed} outside the domain; "
                  f"target <= 15 s); the workers' CPU {cb:.1f} s, i.e. {cb / 2:.1f} s on two free cores")
        print(f"load average after: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
