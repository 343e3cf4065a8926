"""Where a sweep's results go: NetCDF, Zarr or memory, chunk by chunk, resumable.

A store is created from the :class:`~asperity.sweeps.spec.SweepSpec` before any chunk is
computed (once the workers are reachable: ``start()``): every variable with its
dimensions, units and meaning (attributes), the coordinates, the constant parameters,
the asperity version and the sweep's fingerprint as global attributes, and a
``chunk_done`` flag per chunk.  Each finished chunk is
written into its region and then flagged, so memory stays bounded by the chunks in
flight whatever the grid's size.

Files are written as ``OUT.partial`` and renamed to ``OUT`` when every chunk is done
(atomic).  An interrupted sweep leaves ``OUT.partial``; resuming checks its fingerprint
(a store of another sweep is refused, never mixed) and computes only the chunks not
flagged.  NetCDF goes through netCDF4 directly (no Dask needed); Zarr (a directory
ending in ``.zarr``, format 2) through xarray's region writes.
"""

from __future__ import annotations

import math
import os
import shutil
import textwrap

import numpy as np

from .._optional import require
from .._version import __version__
from .spec import SweepSpec

__all__ = ["open_store", "open_result", "store_bytes", "hdf5_chunk", "MemoryStore", "NetCDFStore", "ZarrStore",
           "MESSAGE_CHARS", "HDF5_CHUNK_VALUES"]

#: Longest message kept per set (Zarr stores fixed-width strings).
MESSAGE_CHARS = 400
_PURPOSE = "sweeps"


def _attrs(spec: SweepSpec) -> dict:
    """Global attributes: what was computed, with which version, and the fingerprint."""
    import json

    out = {"title": "asperity parameter sweep", "asperity_version": __version__, "sweep_kind": spec.kind,
           "sweep_fingerprint": spec.fingerprint(), "sweep_spec": json.dumps(spec.describe())}
    for k, v in spec.constants.items():
        out[k] = v
    return out


#: Most values in one HDF5 chunk of a NetCDF sweep (1 GiB of doubles; HDF5's limit is 4 GiB).
HDF5_CHUNK_VALUES = 2**27


def hdf5_chunk(sizes: tuple[int, ...], limit: int = HDF5_CHUNK_VALUES) -> tuple[int, ...]:
    """The chunk shape ``sizes`` cut along its last dimensions until it holds at most ``limit`` values.

    Parameters
    ----------
    sizes : tuple of int
        The sweep's chunk (sets along the parameter dimensions, and the loads of a curve).
    limit : int
        Most values per chunk.

    Returns
    -------
    tuple of int
        Each at least 1 and at most the given size.
    """
    out = [max(1, int(n)) for n in sizes]
    for i in reversed(range(len(out))):
        total = math.prod(out)
        if total <= limit:
            break
        out[i] = max(1, out[i] // math.ceil(total / limit))
    return tuple(out)


def _var_dims(spec: SweepSpec, where: str) -> tuple[str, ...]:
    return spec.dims + ((spec.axis,) if where == "curve" else ())


def _axis_attrs(spec: SweepSpec, name: str) -> dict:
    from ..quantities import quantity

    if name == "point":
        return {"long_name": "index of the parameter set in the list of points", "units": "1"}
    if name == spec.axis:
        q = quantity({"P_N": "P", "d_m": "d"}.get(name, name))
        return ({"long_name": q.si_meaning, "units": q.si_unit} if spec.kind == "physical"
                else {"long_name": q.meaning, "units": q.unit})
    if name == "material":
        return {"long_name": "material (asperity materials)"}
    q = quantity(name)
    unit = q.si_unit if spec.kind == "physical" else q.unit
    return {"long_name": q.meaning, "units": unit or "1", "log_scale": int(q.log)}


def _coordinates(spec: SweepSpec) -> dict[str, tuple[tuple[str, ...], np.ndarray]]:
    """Coordinate name -> (dims, values)."""
    out = {}
    if spec.dims == ("point",):
        out["point"] = (("point",), np.arange(spec.shape[0]))
        for k, v in spec.coords.items():
            out[k] = (("point",), v)
    else:
        for k, v in spec.coords.items():
            out[k] = ((k,), v)
    out[spec.axis] = ((spec.axis,), spec.values)
    return out


class MemoryStore:
    """The results held in memory (``out=None``): for small sweeps and tests."""

    path = None

    def __init__(self, spec: SweepSpec):
        self.spec = spec
        shape, m = spec.shape, spec.values.size
        self.data = {k: np.full(shape + ((m,) if where == "curve" else ()), np.nan)
                     for k, (_, _, where) in spec.variables().items()}
        self.data["message"] = np.full(shape, "", dtype=object)
        self.done = np.zeros(spec.n_chunks, dtype=bool)

    def start(self) -> None:
        """Create the store's file (new stores; called once the workers are reachable)."""

    def missing(self) -> list[int]:
        return [int(k) for k in np.flatnonzero(~self.done)]

    def write(self, k: int, result: dict) -> None:
        region = self.spec.chunk_region(k)
        for name, arr in self.data.items():
            arr[region] = np.asarray(result[name]).reshape(arr[region].shape)
        self.done[k] = True

    def finish(self):
        """The results as an :class:`xarray.Dataset`."""
        xr = require("xarray", purpose=_PURPOSE)
        spec = self.spec
        ds = xr.Dataset(coords={k: (dims, v, _axis_attrs(spec, k)) for k, (dims, v) in _coordinates(spec).items()},
                        attrs=_attrs(spec))
        for k, (meaning, unit, where) in spec.variables().items():
            ds[k] = (_var_dims(spec, where), self.data[k], {"long_name": meaning, "units": unit})
        ds["message"] = (spec.dims, self.data["message"].astype(str),
                         {"long_name": "why the set was not computed ('' if it was)"})
        return ds

    def close(self):
        pass


class NetCDFStore(MemoryStore):
    """A NetCDF-4 file written chunk by chunk through netCDF4 (``OUT.partial`` until done)."""

    def __init__(self, spec: SweepSpec, path: str, *, create: bool):
        self.nc = require("netCDF4", purpose=_PURPOSE)
        self.spec, self.path, self.partial, self.new = spec, path, path + ".partial", create
        self.ds = None if create else self.nc.Dataset(self.partial, "a")

    def start(self) -> None:
        if self.new:
            self._create(self.nc)
            self.ds = self.nc.Dataset(self.partial, "a")
            self.new = False

    def _create(self, nc):
        spec = self.spec
        with nc.Dataset(self.partial, "w", format="NETCDF4") as ds:
            for name, size in zip(spec.dims, spec.shape, strict=True):
                ds.createDimension(name, size)
            ds.createDimension(spec.axis, spec.values.size)
            ds.createDimension("chunk", spec.n_chunks)
            for k, (dims, v) in _coordinates(spec).items():
                var = ds.createVariable(k, str if v.dtype == object else v.dtype, dims)
                var[:] = v
                var.setncatts(_axis_attrs(spec, k))
            # CF: the parameters of a list of points are auxiliary coordinates of every variable.
            aux = " ".join(k for k, (dims, _) in _coordinates(spec).items() if dims != (k,))
            extra = {"coordinates": aux} if aux else {}
            # Stored in the sweep's own chunks: HDF5 then allocates a chunk when it is written (a user
            # trial: contiguous variables were allocated and NaN-filled in full before the first
            # result, 4.6 GB in 10 s for 1e8 sets, a 27 GB .partial after a minute).
            chunk = tuple(s.stop - s.start for s in spec.chunk_region(0))
            for k, (meaning, unit, where) in spec.variables().items():
                sizes = hdf5_chunk(chunk + ((spec.values.size,) if where == "curve" else ()))
                var = ds.createVariable(k, "f8", _var_dims(spec, where), fill_value=np.nan, chunksizes=sizes)
                var.setncatts({"long_name": meaning, "units": unit, **extra})
            var = ds.createVariable("message", str, spec.dims)
            var.setncatts({"long_name": "why the set was not computed ('' if it was)", **extra})
            done = ds.createVariable("chunk_done", "i1", ("chunk",), fill_value=False)
            done[:] = 0
            done.long_name = "1 where the chunk of parameter sets is written (for resuming)"
            ds.setncatts(_attrs(spec))

    def missing(self) -> list[int]:
        if self.new:
            return list(range(self.spec.n_chunks))
        return [int(k) for k in np.flatnonzero(np.asarray(self.ds["chunk_done"][:]) == 0)]

    def write(self, k: int, result: dict) -> None:
        region = self.spec.chunk_region(k)
        for name, (_, _, where) in self.spec.variables().items():
            var = self.ds[name]
            var[region + ((slice(None),) if where == "curve" else ())] = np.asarray(result[name]).reshape(
                tuple(s.stop - s.start for s in region) + ((self.spec.values.size,) if where == "curve" else ()))
        msg = np.asarray(result["message"], dtype=object).reshape(tuple(s.stop - s.start for s in region))
        self.ds["message"][region] = msg
        self.ds.sync()
        self.ds["chunk_done"][k] = 1
        self.ds.sync()

    def close(self):
        if self.ds is not None and self.ds.isopen():
            self.ds.close()

    def finish(self):
        self.close()
        os.replace(self.partial, self.path)
        return open_result(self.path)


class ZarrStore(MemoryStore):
    """A Zarr (format 2) directory written by xarray region writes (``OUT.partial`` until done)."""

    def __init__(self, spec: SweepSpec, path: str, *, create: bool):
        self.xr = require("xarray", purpose=_PURPOSE)
        require("zarr", purpose=_PURPOSE)
        self.spec, self.path, self.partial, self.new = spec, path, path + ".partial", create

    def start(self) -> None:
        if self.new:
            self._create()
            self.new = False

    def _chunks(self, where):
        j, step, _ = self.spec._split()
        shape = self.spec.shape
        chunks = tuple(1 for _ in shape[:j]) + (min(step, shape[j]),) + tuple(shape[j + 1:])
        return chunks + ((self.spec.values.size,) if where == "curve" else ())

    def _create(self):
        da = require("dask.array", purpose=_PURPOSE)
        spec, xr = self.spec, self.xr
        ds = xr.Dataset(coords={k: (dims, v.astype(str) if v.dtype == object else v, _axis_attrs(spec, k))
                                for k, (dims, v) in _coordinates(spec).items()}, attrs=_attrs(spec))
        for k, (meaning, unit, where) in spec.variables().items():
            shape = spec.shape + ((spec.values.size,) if where == "curve" else ())
            ds[k] = (_var_dims(spec, where), da.full(shape, np.nan, chunks=self._chunks(where)),
                     {"long_name": meaning, "units": unit})
        ds["message"] = (spec.dims, da.full(spec.shape, "", dtype=f"<U{MESSAGE_CHARS}",
                                             chunks=self._chunks("set")),
                         {"long_name": "why the set was not computed ('' if it was)"})
        ds["chunk_done"] = ("chunk", np.zeros(spec.n_chunks, dtype="i1"),
                            {"long_name": "1 where the chunk of parameter sets is written (for resuming)"})
        encoding = {k: {"chunks": self._chunks(w)} for k, (_, _, w) in spec.variables().items()}
        encoding["message"] = {"chunks": self._chunks("set")}
        encoding["chunk_done"] = {"chunks": (1,)}
        ds.to_zarr(self.partial, mode="w", compute=False, zarr_format=2, consolidated=False, encoding=encoding)

    def missing(self) -> list[int]:
        if self.new:
            return list(range(self.spec.n_chunks))
        done = self.xr.open_zarr(self.partial, consolidated=False)["chunk_done"].values
        return [int(k) for k in np.flatnonzero(done == 0)]

    def write(self, k: int, result: dict) -> None:
        spec, xr = self.spec, self.xr
        region = spec.chunk_region(k)
        sizes = tuple(s.stop - s.start for s in region)
        part = xr.Dataset()
        for name, (_, _, where) in spec.variables().items():
            part[name] = (_var_dims(spec, where), np.asarray(result[name]).reshape(
                sizes + ((spec.values.size,) if where == "curve" else ())))
        msg = np.array([m[:MESSAGE_CHARS] for m in result["message"]], dtype=f"<U{MESSAGE_CHARS}")
        part["message"] = (spec.dims, msg.reshape(sizes))
        part.to_zarr(self.partial, region=dict(zip(spec.dims, region, strict=True)), consolidated=False)
        xr.Dataset({"chunk_done": ("chunk", np.ones(1, dtype="i1"))}).to_zarr(
            self.partial, region={"chunk": slice(k, k + 1)}, consolidated=False)

    def finish(self):
        # consolidated metadata, so that xr.open_zarr's default finds it (without, every open
        # warned: found by a review); written in the partial store, before it becomes the result
        require("zarr", purpose=_PURPOSE).consolidate_metadata(self.partial, zarr_format=2)
        if os.path.exists(self.path):
            shutil.rmtree(self.path)
        os.replace(self.partial, self.path)
        return open_result(self.path)


def open_result(path) -> object:
    """A finished sweep's Dataset, read lazily from ``path`` (NetCDF or ``.zarr``), without the
    ``chunk_done`` bookkeeping of resuming."""
    xr = require("xarray", purpose=_PURPOSE)
    path = os.fspath(path)
    ds = xr.open_zarr(path, consolidated=False) if path.rstrip("/").endswith(".zarr") else xr.open_dataset(path)
    return ds.drop_vars("chunk_done", errors="ignore")


def _stored_fingerprint(path: str, zarr: bool) -> str | None:
    xr = require("xarray", purpose=_PURPOSE)
    try:
        if zarr:
            return xr.open_zarr(path, consolidated=False).attrs.get("sweep_fingerprint")
        with xr.open_dataset(path) as ds:
            return ds.attrs.get("sweep_fingerprint")
    except Exception as err:  # noqa: BLE001 - whatever the backends say, it is no sweep store
        reason = textwrap.shorten(" ".join(str(err).split()), 200, placeholder=" ...")
        raise ValueError(f"{path} is not a sweep store ({type(err).__name__}: {reason}); choose another output "
                         "or delete it") from None


def store_bytes(spec: SweepSpec) -> int:
    r"""Bytes the results of a sweep take, at least (what the room checks of :func:`open_store` use).

    .. math:: B = N_{sets}\,\big(8\,(n_{curve}\,m + n_{set}) + 4\,c\big)

    with :math:`m` loads (or separations) per curve, :math:`n_{curve}` variables per point of
    a curve and :math:`n_{set}` per set (float64), and :math:`c` = :data:`MESSAGE_CHARS`
    characters of message per set (fixed-width UTF-32 in Zarr).

    Parameters
    ----------
    spec : SweepSpec
        The sweep (:func:`asperity.sweeps.spec.make_spec`).

    Returns
    -------
    int
        Bytes, the stores' compression and metadata not counted.
    """
    m = spec.values.size
    per_set = sum(m if where == "curve" else 1 for _, _, where in spec.variables().values()) * 8
    return spec.n_sets * (per_set + 4 * MESSAGE_CHARS)


def _gb(n: float) -> str:
    return f"{n / 1e9:.3g} GB"


def _check_room(spec: SweepSpec, out: str | None) -> None:
    """Refuse a sweep whose results cannot fit: in memory (``out=None``) half the machine's
    memory, on disk the free space where ``out`` goes (found by a review: a 2000^3 grid
    filled the disk, then failed with a traceback)."""
    need = store_bytes(spec)
    if out is None:
        try:
            memory = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
        except (ValueError, OSError, AttributeError):
            return
        if need > memory / 2:
            raise ValueError(f"the sweep's results ({spec.n_sets} parameter sets) take about {_gb(need)}, more than "
                             f"half this machine's memory ({_gb(memory)}): give out= (a .zarr or NetCDF store, "
                             "written chunk by chunk) or a smaller grid")
        return
    free = shutil.disk_usage(os.path.dirname(os.path.abspath(out)) or ".").free
    if need > free:
        raise ValueError(f"the sweep's results ({spec.n_sets} parameter sets) take about {_gb(need)}, more than the "
                         f"{_gb(free)} free where {out} goes: choose a smaller grid or another disk")


def open_store(spec: SweepSpec, out: str | None, *, resume: bool):
    """The store for ``spec`` at ``out`` (memory if None), new or resumed.

    Raises
    ------
    ValueError
        If ``out`` (or its ``.partial``) holds another sweep (a different fingerprint: other
        parameters, loads, chunking or asperity version) or is not a sweep store, if ``out``
        exists and ``resume`` is False, an interrupted sweep is there and ``resume`` is
        False, or the results would not fit (:func:`store_bytes`: half the machine's memory
        without ``out``, the free disk space with it).
    """
    if out is None:
        _check_room(spec, None)
        return MemoryStore(spec)
    out = os.fspath(out)
    zarr = out.rstrip("/").endswith(".zarr")
    cls = ZarrStore if zarr else NetCDFStore
    partial = out + ".partial"
    mine = spec.fingerprint()
    for path, what in ((out, "a finished sweep"), (partial, "an interrupted sweep")):
        if not os.path.exists(path):
            continue
        theirs = _stored_fingerprint(path, zarr)
        if theirs != mine:
            raise ValueError(f"{path} holds {what} with other arguments (parameters, loads, chunking or asperity "
                             "version differ): refusing to mix two grids; choose another output or delete it")
        if not resume:
            raise ValueError(f"{path} holds {what} of these arguments: pass resume=True (--resume) to "
                             f"{'complete' if path == partial else 'reuse'} it, or delete it")
        if path == out:
            return None  # finished already: nothing to compute
        return cls(spec, out, create=False)
    _check_room(spec, out)
    return cls(spec, out, create=True)
