"""A pull-off and friction map over roughness and adhesion, with asperity.sweep.

Runs the same code on a laptop (a local Dask cluster, one worker per core, when
``asperity[sweep]`` is installed) and on a cluster (``--scheduler tcp://HOST:8786``):

    python examples/sweep_map.py                        # 12 x 12 sets, 50 loads each
    asperity plot sweep-map/map.nc --x alpha --y gamma --z mu --at P=10

It writes ``sweep-map/map.nc`` (NetCDF; the dimensions alpha, gamma and P, units in the
attributes), a heat map of the pull-off force, and prints where adhesion turns the
contact sticky (a pull-off above the load scale of one asperity).
"""

from __future__ import annotations

import argparse
import os

import numpy as np

import asperity
from asperity.cli.plot import heat_map


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", default="sweep-map", help="output directory (default: sweep-map)")
    parser.add_argument("--scheduler", default=None, help="'serial', 'local' or a Dask scheduler address")
    parser.add_argument("--n", type=int, default=12, help="grid points per parameter (default 12)")
    args = parser.parse_args(argv)
    os.makedirs(args.out, exist_ok=True)
    path = os.path.join(args.out, "map.nc")
    ds = asperity.sweep(alpha=np.geomspace(1e-3, 0.1, args.n), beta=1000.0,
                        gamma=np.geomspace(1e-5, 1e-2, args.n), P=np.geomspace(1e-2, 1e4, 50),
                        out=path, scheduler=args.scheduler, resume=os.path.exists(path))
    heat_map(ds, "alpha", "gamma", "pull_off", {}, os.path.join(args.out, "pull_off.png"), "png")
    sticky = ds.pull_off > 1.0
    print(f"{int(ds.message.size)} parameter sets in {path}; "
          f"{int((ds.message != '').sum())} outside the model's domain")
    for g in ds.gamma.values[::3]:
        row = sticky.sel(gamma=g).values
        where = f"for alpha <= {ds.alpha.values[row].max():.3g}" if row.any() else "for no alpha of the grid"
        print(f"gamma = {g:.3g}: pull-off above 1 (N G b^2) {where}")
    return ds


if __name__ == "__main__":
    main()
