r"""Parameter sweeps at any scale: grids or lists of parameter sets, on one core or a Dask cluster.

:func:`sweep` computes, for every parameter set of a grid (named dimensions: alpha,
gamma, ...) or of a list of points, the curve at given loads or separations and the
pull-off force, and returns an :class:`xarray.Dataset` with units in its attributes,
streamed to NetCDF or Zarr when a file is given.  One :class:`asperity.Model` per set
computes it, so a sweep equals a loop over Models cell by cell.

Modules: :mod:`~asperity.sweeps.spec` (the sets, their chunks, the fingerprint),
:mod:`~asperity.sweeps.compute` (one chunk: what a task runs),
:mod:`~asperity.sweeps.store` (NetCDF, Zarr, memory; resuming) and
:mod:`~asperity.sweeps.run` (serial or Dask execution, progress).  Needs the ``sweep``
extra: ``pip install 'asperity[sweep]'`` (xarray, dask[distributed], netCDF4, zarr, tqdm);
without Dask a sweep runs serially.

References
----------
.. [1] Adams et al., Eqs (1), (6), (10), (18), (21), Table 1.
.. [2] xarray: labelled N-D arrays, https://docs.xarray.dev; Dask distributed,
   https://distributed.dask.org.
"""

from .compute import compute_chunk, compute_set
from .run import sweep
from .spec import CHUNK_SETS, MODEL_NAMES, PHYSICAL_NAMES, SweepSpec, default_chunk_sets, make_spec, read_points

__all__ = ["sweep", "SweepSpec", "make_spec", "read_points", "compute_chunk", "compute_set", "CHUNK_SETS",
           "MODEL_NAMES", "PHYSICAL_NAMES", "default_chunk_sets"]
