"""Running a sweep: serially, on a local Dask cluster or on any Dask scheduler.

:func:`sweep` builds the :class:`~asperity.sweeps.spec.SweepSpec`, opens the store,
and hands the missing chunks to an executor:

* ``scheduler=None`` (default): a :class:`distributed.LocalCluster` with one
  single-threaded worker process per core when Dask's distributed scheduler is installed
  (``pip install 'asperity[sweep]'``), else the calling process, one chunk after another;
* ``"serial"``: the calling process; ``"local"``: a LocalCluster as above;
* an address (``"tcp://10.0.0.1:8786"``) or a :class:`distributed.Client`: an existing
  cluster (dask-jobqueue on a batch system, a Kubernetes Dask cluster, ...).

Tasks are chunks of parameter sets (:func:`~asperity.sweeps.spec.default_chunk_sets`: up
to 256, about half a second of work, so the scheduler's overhead of a few milliseconds
per task is small; at least 32 chunks for smaller grids, to keep every worker busy).
At most a few tasks per worker thread are in flight: each result is written to the
store by this process as it arrives and then dropped, so memory is bounded whatever the
grid's size.  Dask retries a task whose worker dies (``retries`` more for a task
that raises), so a killed worker does not lose the sweep.
"""

from __future__ import annotations

import contextlib
import logging
import os
import sys

from .._optional import require
from .._validation import check_output_path
from .compute import compute_chunk
from .spec import make_spec
from .store import open_result, open_store

__all__ = ["sweep", "CONNECT_TIMEOUT"]

#: Seconds to wait for a scheduler given by its address.
CONNECT_TIMEOUT = 20


def _serial(spec, todo, done):
    variables = spec.variables()
    for k in todo:
        done(k, compute_chunk(spec.kind, spec.chunk_parameters(k), spec.axis, spec.values, variables))


def _on_dask(client, spec, todo, done, retries):
    distributed = require("distributed", purpose="sweeps on Dask")
    variables = spec.variables()
    nthreads = max(1, sum(client.nthreads().values()))
    window = 2 * nthreads + 1  # in flight at once: keeps every worker busy, memory bounded
    # The loads travel with each task (their size is small beside the task's results): no
    # scattered data that a lost worker would take with it.
    values = spec.values
    tag = spec.fingerprint()[:10]
    pending = iter(todo)

    def submit(k):
        return client.submit(compute_chunk, spec.kind, spec.chunk_parameters(k), spec.axis, values, variables,
                             key=f"asperity-sweep-{tag}-{k}", pure=False, retries=retries)

    futures = {}
    for k in pending:
        futures[submit(k)] = k
        if len(futures) >= window:
            break
    queue = distributed.as_completed(list(futures))
    for future in queue:
        k = futures.pop(future)
        done(k, future.result())
        future.release()
        nxt = next(pending, None)
        if nxt is not None:
            new = submit(nxt)
            futures[new] = nxt
            queue.add(new)


#: Dask settings of the local cluster's workers.  Dask's nannies start workers with
#: ``MALLOC_TRIM_THRESHOLD_=65536`` (give freed memory back to the system early), which makes
#: the model's many small NumPy temporaries cost system calls: a parameter set took 1.69 ms of
#: CPU in such a worker against 1.30 ms in the main process, and 1.37 ms with the threshold
#: at 128 MiB (a task holds a few MB).  The statistical profiler samples every 10 ms.
LOCAL_WORKER_CONFIG = {"distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_": 128 * 2**20,
                       "distributed.worker.profile.enabled": False}


@contextlib.contextmanager
def local_worker_settings():
    """:data:`LOCAL_WORKER_CONFIG` while a local cluster starts its workers.

    A nanny takes the variables it sets before spawning a worker from this process's
    environment first and from Dask's configuration second (a ``MALLOC_TRIM_THRESHOLD_``
    the user set is kept, unless it is Dask's own 65536, left there by an earlier cluster),
    once, when it is made; whenever it (re)starts a worker it writes
    them into this process's environment, as Dask does with its own defaults.  The value set
    here for the making is restored afterwards.
    """
    import dask

    key = "MALLOC_TRIM_THRESHOLD_"
    old = os.environ.get(key)
    ours = old is None or old == "65536"  # unset, or Dask's default left behind by an earlier cluster
    if ours:
        os.environ[key] = str(LOCAL_WORKER_CONFIG[f"distributed.nanny.pre-spawn-environ.{key}"])
    try:
        with dask.config.set(LOCAL_WORKER_CONFIG):
            yield
    finally:
        if ours:
            if old is None:
                os.environ.pop(key, None)
            else:
                os.environ[key] = old


def _local_cluster():
    distributed = require("distributed", purpose="sweeps on Dask")
    n = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)
    before = set(distributed.SpecCluster._instances)
    try:
        with local_worker_settings():
            # config=: each nanny hands it to every worker it starts, restarts included
            # on the loopback interface only, its dashboard too (a review saw it on 0.0.0.0)
            cluster = distributed.LocalCluster(n_workers=n, threads_per_worker=1, processes=True, host="127.0.0.1",
                                               dashboard_address="127.0.0.1:0", silence_logs=logging.ERROR,
                                               config={"distributed.worker.profile.enabled": False})
    except BaseException:
        # Ctrl-C or SIGTERM while the cluster starts (a user trial): a half-built cluster would be
        # closed again by distributed's exit hook, which fails on its state with a 28-line
        # traceback after 'asperity: interrupted'; its worker processes end with this one.
        for half_built in set(distributed.SpecCluster._instances) - before:
            half_built.shutdown_on_close = False
        raise
    return cluster, distributed.Client(cluster)


def _client(scheduler):
    """(client, closer) for ``scheduler``; (None, None) for serial execution."""
    if scheduler == "serial":
        return None, None
    if scheduler is None:
        try:
            require("distributed", purpose="sweeps on Dask")
        except ImportError:
            return None, None
        scheduler = "local"
    if scheduler == "local":
        cluster, client = _local_cluster()

        def close():
            client.close()
            cluster.close()
        return client, close
    if isinstance(scheduler, str):
        if ":" not in scheduler.strip():
            raise ValueError(f"scheduler must be None, 'serial', 'local' or a scheduler address such as "
                             f"'tcp://host:8786', got {scheduler!r}")
        distributed = require("distributed", purpose="sweeps on Dask")
        try:
            client = distributed.Client(scheduler, timeout=CONNECT_TIMEOUT)
        except (OSError, TimeoutError, ValueError, TypeError) as err:
            raise ValueError(f"cannot reach the Dask scheduler at {scheduler!r}: {err}") from None
        return client, client.close
    if hasattr(scheduler, "submit") and hasattr(scheduler, "nthreads"):
        return scheduler, None  # the caller's client: the caller closes it
    raise ValueError(f"scheduler must be None, 'serial', 'local', a scheduler address or a distributed.Client, "
                     f"got {scheduler!r}")


def _progress(total, enabled):
    if not enabled:
        return None
    try:
        tqdm = require("tqdm", purpose="the progress bar").tqdm
    except ImportError:
        return None
    return tqdm(total=total, unit="set", desc="asperity sweep", file=sys.stderr, smoothing=0.1)


#: Names of a NetCDF output (case-insensitive); a Zarr store's ends in ``.zarr``.
NETCDF_SUFFIXES = (".nc", ".nc4", ".netcdf", ".cdf")


def sweep(*, alpha=None, beta=None, gamma=None, nu=None, h_over_b=None, tau_f1=None, tau_f2=None, a1=None,
          a2=None, material=None, sigma_s=None, R=None, eta=None, area=None, w=None, b=None, points=None, P=None,
          d=None,
          out=None, scheduler=None, resume=False, chunk_sets=None, retries=3, progress=False):
    r"""Curves and pull-off over a grid (or a list) of parameter sets, as an :class:`xarray.Dataset`.

    Every parameter given as a 1-D array is a dimension of the grid (their outer product,
    in the order of the signature); scalars are constant; the others take their defaults
    (:mod:`asperity.quantities`).  ``points`` instead lists the sets (one dimension
    ``point``).  Each set is one :class:`asperity.Model` (or
    :class:`asperity.physical.PhysicalContact`): its curve at the loads ``P`` (or
    separations ``d``) and its pull-off, exactly as a loop over Models would give them.

    .. math::
        \mu(\text{set}, P) = \bar F(\bar d)/P \ \text{on}\ \bar P(\bar d) = P,\qquad
        P_{off}(\text{set}) = \max\big(0, -\min_{\bar d}\bar P(\bar d)\big)

    Parameters
    ----------
    alpha, beta, gamma, nu, h_over_b : float or 1-D array_like, optional
        Dimensionless model parameters (Eqs 7, 15, 16; ranges in :mod:`asperity.quantities`).
    tau_f1, tau_f2, a1, a2 : float or 1-D array_like, optional
        Hurtado-Kim constants (Eqs 2-3; defaults: the paper's).
    material : str or list of str, optional
        Material name(s) from :func:`asperity.materials.material_names`: a physical sweep,
        with ``sigma_s`` (m), ``R`` (m), ``eta`` (1/m^2) and ``area`` (m^2).
    sigma_s, R, eta, area : float or 1-D array_like, optional
        Surface of a physical sweep (SI units), > 0.
    w, b : float or 1-D array_like, optional
        Work of adhesion (J/m^2, >= 0; 0: no adhesion) and Burgers vector (m, > 0) of a
        physical sweep, replacing the material's
        (:func:`asperity.bodies.contact_material`): a material without them in the table
        (diamond has no w, mica no b) can be swept with them.
    points : dict of 1-D arrays or str, optional
        A list of parameter sets: columns of equal length, or the path of a CSV file with a
        header of parameter names.
    P, d : 1-D array_like
        Loads (:math:`P/NGb^2`; newtons in a physical sweep) or separations
        (:math:`d/\sigma`; metres): give one.
    out : str or path, optional
        NetCDF file (``.nc``) or Zarr directory (``.zarr``) to stream the results to; None
        keeps them in memory (small sweeps).
    scheduler : None, 'serial', 'local', str or distributed.Client
        Where to compute (module docstring): default a local Dask cluster if Dask is
        installed, else serial.
    resume : bool
        Complete the interrupted sweep at ``out`` (computing only its missing chunks), or
        reuse a finished one, if its arguments match.
    chunk_sets : int, optional
        Parameter sets per task, >= 1 (default: a 32nd of the sets, within 32..256).
    retries : int
        Extra tries of a task that raises on a worker (default 3).
    progress : bool
        Show a progress bar with ETA on standard error (needs tqdm).

    Returns
    -------
    xarray.Dataset
        Dimensions: the varying parameters (or ``point``) and ``P``/``d`` (``P_N``/``d_m``);
        variables ``mu``, ``d`` (or ``P``), ``F``, ``area``, ``pressure``, ``contacts``
        (SI names in a physical sweep), ``pull_off``, ``pull_off_d`` and ``message`` ('';
        ``'note: ...'`` when the library warned about the set's validity, e.g. yielded
        asperities with the elastic law; or why a set lies outside the model's domain, its
        values then NaN); units and meanings
        in ``attrs``; the constant parameters, the asperity version and the sweep's
        fingerprint in the global ``attrs``.  Backed by the file when ``out`` is given.

    Raises
    ------
    ValueError
        For an invalid parameter, or a store at ``out`` that holds another sweep (never
        mixed) or that exists without ``resume``.
    ImportError
        Without xarray (``pip install 'asperity[sweep]'``), or netCDF4/zarr/dask as needed.

    Examples
    --------
    >>> ds = sweep(alpha=[0.003, 0.01], beta=1000.0, gamma=1e-3, P=[1.0, 10.0], scheduler="serial")
    >>> ds.mu.dims
    ('alpha', 'P')
    >>> round(float(ds.pull_off.sel(alpha=0.003)), 1)  # Table 1 prints 320.1
    320.1

    References
    ----------
    Adams et al., Eqs (1), (6), (10), (18), (21), Table 1.
    """
    require("xarray", purpose="sweeps")
    if not isinstance(resume, bool) or not isinstance(progress, bool):
        raise ValueError("resume and progress must be True or False")
    if isinstance(retries, bool) or not isinstance(retries, int) or retries < 0:
        raise ValueError(f"retries must be an integer >= 0, got {retries!r}")
    parameters = dict(alpha=alpha, beta=beta, gamma=gamma, nu=nu, h_over_b=h_over_b, tau_f1=tau_f1,
                      tau_f2=tau_f2, a1=a1, a2=a2, material=material, sigma_s=sigma_s, R=R, eta=eta, area=area,
                      w=w, b=b)
    if out is not None:
        text = os.fspath(out) if isinstance(out, os.PathLike) else out
        if isinstance(text, str) and text.rstrip("/").endswith(".zarr"):
            out = text.rstrip("/")  # 'map.zarr/' is the directory map.zarr (its partial beside it)
        out = check_output_path(out, "out", directory=str(out).endswith(".zarr"))
        if not (str(out).lower().endswith(NETCDF_SUFFIXES) or str(out).endswith(".zarr")):  # (any other name
            # was silently NetCDF: a review)
            raise ValueError(f"out must end in .nc, .nc4, .netcdf or .cdf (a NetCDF file) or .zarr (a Zarr "
                             f"directory), got {str(out)!r}; "
                             "a table of the results: xarray's Dataset.to_dataframe() on the result")
    spec = make_spec(parameters, points=points, P=P, d=d, chunk_sets=chunk_sets)
    if not (scheduler is None or isinstance(scheduler, str) or hasattr(scheduler, "submit")):
        raise ValueError(f"scheduler must be None, 'serial', 'local', a scheduler address or a distributed.Client, "
                         f"got {scheduler!r}")
    store = open_store(spec, out, resume=resume)
    if store is None:  # a finished sweep of the same arguments
        return open_result(out)
    try:
        todo = store.missing()
        client, close = _client(scheduler) if todo else (None, None)  # before any file is made
        bar = None
        try:
            _on_store(store.start)
            bar = _progress(sum(_sets(spec, k) for k in todo), progress)

            def done(k, result):
                _on_store(store.write, k, result)
                if bar is not None:
                    bar.update(_sets(spec, k))
            if client is None:
                _serial(spec, todo, done)
            else:
                _on_dask(client, spec, todo, done, retries)
        finally:
            if close is not None:
                close()
            if bar is not None:
                bar.close()
    except _StoreFailure as failure:  # the store's file: a full disk, say (HDF error)
        _close_quietly(store)
        err = failure.__cause__
        raise ValueError(f"cannot write the sweep to {store.path} ({type(err).__name__}: {' '.join(str(err).split())})"
                         "; the chunks written are kept for resume=True (--resume)") from None
    except BaseException:
        store.close()
        raise
    try:
        return _on_store(store.finish)
    except _StoreFailure as failure:
        err = failure.__cause__
        raise ValueError(f"cannot finish the sweep at {store.path} ({type(err).__name__}: "
                         f"{' '.join(str(err).split())})") from None


class _StoreFailure(Exception):
    """An OSError or RuntimeError (netCDF4's 'HDF error') raised by the store itself, not by the
    computation; its ``__cause__`` is the original."""


def _on_store(method, *args):
    """``method(*args)`` of a store, its file errors raised as :class:`_StoreFailure`."""
    try:
        return method(*args)
    except (OSError, RuntimeError) as err:
        raise _StoreFailure() from err


def _close_quietly(store) -> None:
    try:
        store.close()
    except (OSError, RuntimeError):
        pass


def _sets(spec, k) -> int:
    region = spec.chunk_region(k)
    n = 1
    for s in region:
        n *= s.stop - s.start
    return n
