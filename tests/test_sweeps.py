"""asperity.sweep: equal to a loop over Models cell by cell, on one core and on Dask; faults; stores."""

import os
import signal
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import asperity
from asperity import sweeps
from asperity.friction_stress import HurtadoKim
from asperity.physical import PhysicalContact
from asperity.surface import Surface
from asperity.sweeps import store as store_module

xr = pytest.importorskip("xarray")

LOADS = np.geomspace(1e-2, 1e4, 6)
ALPHAS = np.array([0.003, 0.01, 0.05])
GAMMAS = np.array([0.0, 1e-4, 1e-3, 1e-2])
CURVE = ("d", "F", "mu", "area", "pressure", "contacts")


def grid(**extra):
    return dict(alpha=ALPHAS, beta=1000.0, gamma=GAMMAS, P=LOADS, scheduler="serial", **extra)


def loop_cell(alpha, beta, gamma, loads, **kw):
    """What a user would write: one Model per cell, its load curve and pull-off."""
    m = asperity.Model(alpha, beta, gamma, **kw)
    c = m.load_curve(loads)
    return c, m.pull_off()


def assert_same(a, b):
    """Two sweeps equal cell by cell, bit for bit (NaN where NaN), messages too."""
    assert set(a.data_vars) == set(b.data_vars)
    for name in a.data_vars:
        x, y = a[name].values, b[name].values
        if x.dtype.kind == "f":
            np.testing.assert_array_equal(x, y, err_msg=name)
        else:
            assert (x == y).all(), name


@pytest.fixture(scope="module")
def serial():
    return asperity.sweep(**grid())


def test_sweep_equals_a_loop_over_models(serial):
    assert serial.mu.dims == ("alpha", "gamma", "P")
    assert serial.pull_off.dims == ("alpha", "gamma")
    np.testing.assert_array_equal(serial.alpha.values, ALPHAS)
    np.testing.assert_array_equal(serial.P.values, LOADS)
    for i, a in enumerate(ALPHAS):
        for j, g in enumerate(GAMMAS):
            c, po = loop_cell(a, 1000.0, g, LOADS)
            for name in CURVE:
                np.testing.assert_array_equal(serial[name].values[i, j], getattr(c, name), err_msg=name)
            assert serial.pull_off.values[i, j] == po.force
            np.testing.assert_array_equal(serial.pull_off_d.values[i, j], po.d)
            assert serial.message.values[i, j] == ""


def test_units_and_metadata_come_from_the_registry(serial):
    from asperity.quantities import CURVE_COLUMNS, MODEL_PARAMETERS

    assert serial.mu.attrs["units"] == CURVE_COLUMNS["mu"].unit
    assert serial.F.attrs["long_name"] == CURVE_COLUMNS["F"].meaning
    assert serial.alpha.attrs["long_name"] == MODEL_PARAMETERS["alpha"].meaning
    assert serial.alpha.attrs["log_scale"] == 1 and serial.P.attrs["units"] == "N G b^2"
    assert serial.attrs["asperity_version"] == asperity.__version__
    assert serial.attrs["beta"] == 1000.0 and serial.attrs["nu"] == 0.3  # constants, defaults included
    assert len(serial.attrs["sweep_fingerprint"]) == 64


def test_domain_error_becomes_nan_and_a_message():
    # gamma = 0 cannot carry a tensile load; a too weak adhesion leaves the Maugis range.
    ds = asperity.sweep(alpha=0.003, beta=1000.0, gamma=[0.0, 1e-3, 1e-30], P=[-1.0, 10.0], scheduler="serial")
    assert ds.gamma.values.tolist() == [0.0, 1e-30, 1e-3]  # stored in increasing order
    msg = {g: ds.message.sel(gamma=g).item() for g in (0.0, 1e-3, 1e-30)}
    assert msg[0.0].startswith("note: P (load) must be > 0 (without adhesion, gamma = 0)")
    assert msg[0.0].endswith("NaN at the 1 load(s) below it, the others computed")
    assert msg[1e-3] == ""
    assert "lambda" in msg[1e-30] and "outside" in msg[1e-30]
    bad = ds.sel(gamma=1e-30)
    assert np.isnan(bad.mu.values).all() and np.isnan(bad.pull_off.values).all()
    c, po = loop_cell(0.003, 1000.0, 1e-3, [-1.0, 10.0])
    np.testing.assert_array_equal(ds.F.sel(gamma=1e-3).values, c.F)
    assert ds.pull_off.sel(gamma=1e-3).item() == po.force
    # Found by a user trial: the load below gamma = 0's least one blanked the load it can carry
    # and the pull-off too; now only that load is NaN, the rest equal the model's
    c, po = loop_cell(0.003, 1000.0, 0.0, [10.0])
    hertz = ds.sel(gamma=0.0)
    for name in ("d", "F", "mu", "area", "pressure", "contacts"):
        assert np.isnan(hertz[name].values[0]) and hertz[name].values[1] == getattr(c, name)[0], name
    assert hertz.pull_off.item() == po.force == 0.0


def test_one_load_below_the_pull_off_is_nan_alone_in_every_route(tmp_path, capsys):
    """The same for an adhesive set and a physical contact: NaN at the loads below minus the
    pull-off force, the others and the pull-off computed as the library's load curve does."""
    from asperity.physical import PhysicalContact, Surface

    ds = asperity.sweep(alpha=0.003, beta=1000.0, gamma=1e-3, P=[-1000.0, -1.0, 1.0], scheduler="serial")
    c, po = loop_cell(0.003, 1000.0, 1e-3, [-1.0, 1.0])
    F = ds.F.values.ravel()  # one set: a dimension 'point' of one
    assert np.isnan(F[0]) and F[1:].tolist() == c.F.tolist()
    assert ds.pull_off.item() == po.force and "-320.127 (minus the pull-off force)" in ds.message.item()
    phys = asperity.sweep(material="Au", sigma_s=2e-9, R=1e-6, eta=1e12, area=1e-6, P=[-100.0, 1e-3, 1e-2],
                          scheduler="serial")
    contact = PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", asperity.AsperityWarning)
        curve = contact.load_curve([1e-3, 1e-2])
    area = phys.area_m2.values.ravel()
    assert np.isnan(area[0]) and area[1:].tolist() == curve.area.tolist()
    assert "N (minus the pull-off force)" in phys.message.item() and "NaN at the 1 load(s)" in phys.message.item()


def test_points_from_a_dict_and_from_csv(tmp_path):
    pts = {"alpha": [0.003, 0.01, 0.05], "gamma": [1e-3, 0.0, 5e-3], "nu": [0.3, 0.25, 0.2]}
    ds = asperity.sweep(points=pts, beta=300.0, P=LOADS, scheduler="serial")
    assert ds.mu.dims == ("point", "P") and list(ds.gamma.dims) == ["point"]
    for k in range(3):
        c, po = loop_cell(pts["alpha"][k], 300.0, pts["gamma"][k], LOADS, nu=pts["nu"][k])
        np.testing.assert_array_equal(ds.mu.values[k], c.mu)
        assert ds.pull_off.values[k] == po.force
    path = tmp_path / "sets.csv"
    path.write_text("alpha,gamma,nu\n" + "\n".join(f"{a},{g},{n}" for a, g, n in zip(*pts.values())) + "\n")
    assert_same(asperity.sweep(points=str(path), beta=300.0, P=LOADS, scheduler="serial"), ds)


def test_separations_and_hurtado_kim_constants():
    d = np.array([-1.0, 0.0, 2.0])
    ds = asperity.sweep(alpha=0.01, beta=1000.0, gamma=1e-3, tau_f1=[0.01, 0.02], a1=30.0, d=d,
                        scheduler="serial")
    assert ds.P.dims == ("tau_f1", "d")
    for i, t in enumerate([0.01, 0.02]):
        m = asperity.Model(0.01, 1000.0, 1e-3, friction=HurtadoKim(tau_f1=t, a1=30.0))
        c = m.separation_curve(d)
        np.testing.assert_array_equal(ds.F.values[i], c.F)
        np.testing.assert_array_equal(ds.P.values[i], c.P)
        assert ds.pull_off.values[i] == m.pull_off().force


def test_physical_sweep_equals_physical_contacts():
    loads = np.array([1e-4, 1e-3])
    ds = asperity.sweep(material=["Au", "Si"], sigma_s=[1e-9, 2e-9], R=1e-6, eta=1e12, area=1e-6, P=loads,
                        scheduler="serial")
    assert ds.F_N.dims == ("material", "sigma_s", "P_N") and ds.F_N.attrs["units"] == "N"
    assert list(ds.material.values) == ["Au", "Si"]
    for i, mat in enumerate(["Au", "Si"]):
        for j, s in enumerate([1e-9, 2e-9]):
            pc = PhysicalContact(mat, Surface(s, 1e-6, 1e12, 1e-6))
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always", asperity.AsperityWarning)
                c = pc.load_curve(loads)
            # gold yields at these loads: the set is computed and its message holds the library's note
            notes = [str(w.message) for w in caught]
            assert str(ds.message.values[i, j]) == "; ".join(f"note: {n}" for n in dict.fromkeys(notes))
            np.testing.assert_array_equal(ds.F_N.values[i, j], c.F)
            np.testing.assert_array_equal(ds.d_m.values[i, j], c.d)
            assert ds.pull_off_N.values[i, j] == pc.pull_off().force and ds.gamma.values[i, j] == pc.gamma


@pytest.mark.parametrize("name", ["map.nc", "map.zarr"])
def test_stores_equal_memory(tmp_path, serial, name):
    out = tmp_path / name
    ds = asperity.sweep(**grid(out=str(out), chunk_sets=5))
    assert os.path.exists(out) and not os.path.exists(str(out) + ".partial")
    assert_same(ds.load(), serial)
    assert ds.mu.attrs == serial.mu.attrs and ds.attrs["beta"] == 1000.0  # another chunking: another fingerprint
    ds.close()


def test_chunks_tile_the_grid_once():
    spec = sweeps.make_spec({"alpha": ALPHAS, "gamma": GAMMAS, "beta": 1.0, "nu": [0.1, 0.2]}, P=[1.0],
                            chunk_sets=3)
    seen = np.zeros(spec.shape, dtype=int)
    for k in range(spec.n_chunks):
        seen[spec.chunk_region(k)] += 1
        assert len(spec.chunk_parameters(k)) == seen[spec.chunk_region(k)].size
    assert (seen == 1).all()


def test_a_different_rerun_into_the_same_store_is_refused(tmp_path):
    out = str(tmp_path / "map.nc")
    asperity.sweep(**grid(out=out)).close()
    with pytest.raises(ValueError, match="refusing to mix two grids"):
        asperity.sweep(alpha=ALPHAS * 2, beta=1000.0, gamma=GAMMAS, P=LOADS, out=out, scheduler="serial",
                       resume=True)
    with pytest.raises(ValueError, match="resume=True"):
        asperity.sweep(**grid(out=out))
    again = asperity.sweep(**grid(out=out, resume=True))  # finished: reused as it is
    assert again.attrs["sweep_fingerprint"] and again.mu.shape == (3, 4, 6)
    again.close()


@pytest.mark.parametrize("name", ["map.nc", "map.zarr"])
def test_interrupted_sweep_resumes_computing_only_missing_chunks(tmp_path, monkeypatch, serial, name):
    out = str(tmp_path / name)
    cls = store_module.ZarrStore if name.endswith("zarr") else store_module.NetCDFStore
    real_write = cls.write
    written = []

    def interrupting(self, k, result):
        if len(written) == 2:
            raise KeyboardInterrupt  # as Ctrl-C after two chunks
        real_write(self, k, result)
        written.append(k)
    monkeypatch.setattr(cls, "write", interrupting)
    with pytest.raises(KeyboardInterrupt):
        asperity.sweep(**grid(out=out, chunk_sets=2))
    assert os.path.exists(out + ".partial") and not os.path.exists(out)
    monkeypatch.setattr(cls, "write", real_write)
    with pytest.raises(ValueError, match="interrupted sweep"):
        asperity.sweep(**grid(out=out, chunk_sets=2))  # no silent restart
    computed = []
    real_compute = sweeps.run.compute_chunk

    def counting(kind, sets, *args):
        computed.append(len(sets))
        return real_compute(kind, sets, *args)
    monkeypatch.setattr(sweeps.run, "compute_chunk", counting)
    ds = asperity.sweep(**grid(out=out, chunk_sets=2, resume=True))
    spec = sweeps.make_spec({"alpha": ALPHAS, "beta": 1000.0, "gamma": GAMMAS}, P=LOADS, chunk_sets=2)
    assert len(computed) == spec.n_chunks - 2 and sum(computed) == ALPHAS.size * GAMMAS.size - 4
    assert_same(ds.load(), serial)
    ds.close()


def test_a_netcdf_sweep_allocates_its_results_as_they_are_written(tmp_path, monkeypatch):
    """Found by a user trial: the NetCDF variables were contiguous, so the first write allocated
    and NaN-filled the whole file (4.6 GB in 10 s for 1e8 values, a 27 GB .partial left by an
    interrupted run).  Stored in the sweep's chunks, a .partial holds about what was written:
    after 1 of 120 chunks of 1.8 MB of results in all, well under a tenth of it."""
    import netCDF4

    out = str(tmp_path / "lazy.nc")
    kwargs = dict(alpha=np.geomspace(1e-3, 0.1, 30), beta=1000.0, gamma=np.geomspace(1e-6, 1e-2, 40),
                  P=np.geomspace(1e-2, 1e5, 32), scheduler="serial", chunk_sets=10)
    spec = sweeps.make_spec({k: v for k, v in kwargs.items() if k not in ("P", "scheduler", "chunk_sets")},
                            P=kwargs["P"], chunk_sets=10)
    floats = store_module.store_bytes(spec) - spec.n_sets * 4 * store_module.MESSAGE_CHARS
    real_write = store_module.NetCDFStore.write

    def once(self, k, result):
        real_write(self, k, result)
        raise KeyboardInterrupt
    monkeypatch.setattr(store_module.NetCDFStore, "write", once)
    with pytest.raises(KeyboardInterrupt):
        asperity.sweep(out=out, **kwargs)
    assert spec.n_chunks == 120 and floats > 1e6
    assert os.path.getsize(out + ".partial") < 0.1 * floats, (os.path.getsize(out + ".partial"), floats)
    with netCDF4.Dataset(out + ".partial") as ds:
        assert ds["mu"].chunking() == [1, 10, 32] and int(np.asarray(ds["chunk_done"][:]).sum()) == 1
    monkeypatch.setattr(store_module.NetCDFStore, "write", real_write)
    done = asperity.sweep(out=out, resume=True, **kwargs)
    assert_same(done.load(), asperity.sweep(**kwargs))
    done.close()


@pytest.mark.parametrize("kwargs, match", [
    (dict(alpha=0.01, beta=1.0, P=[1.0], kappa=2.0), "unexpected keyword"),
    (dict(alpha=0.01, beta=1.0, sigma_s=1e-9, P=[1.0]), "not both"),
    (dict(alpha=0.01, beta=1.0), "give loads P or separations d"),
    (dict(alpha=0.01, beta=1.0, P=[1.0], d=[0.0]), "give loads P or separations d"),
    (dict(alpha=[0.01, 0.01], beta=1.0, P=[1.0]), r"alpha must hold distinct values .* got 0.01 more than once"),
    (dict(alpha=0.01, beta=1.0, P=[1.0, 1.0]), "P must hold distinct values"),
    (dict(alpha=0.01, beta=1.0, P=np.ones(1_000_001)), "at most 1000000 values"),
    (dict(material=["Au", "Au"], sigma_s=2e-9, R=1e-6, eta=1e12, area=1e-6, P=[1e-3]), "'Au' more than once"),
    (dict(alpha=[0.01, -1.0], beta=1.0, P=[1.0]), "alpha must satisfy 0 < alpha"),
    (dict(alpha=0.01, P=[1.0]), "needs beta"),
    (dict(alpha=0.01, beta=1.0, P=[[1.0]]), "P must be 1-D"),
    (dict(alpha=0.01, beta=1.0, P=[1.0], chunk_sets=0), "chunk_sets"),
    (dict(alpha=0.01, beta=1.0, P=[1.0], scheduler=3), "scheduler must be"),
    (dict(points={"alpha": [0.01, 0.02], "beta": [1.0]}, P=[1.0]), "same length"),
    (dict(points={"alpha": [0.01]}, alpha=0.01, beta=1.0, P=[1.0]), "both in points"),
    (dict(material=3, sigma_s=1e-9, R=1e-6, eta=1e12, area=1e-6, P=[1.0]), "material must be"),
])
def test_bad_arguments_are_refused(kwargs, match):
    with pytest.raises((ValueError, TypeError), match=match):
        asperity.sweep(**kwargs)


def test_bad_points_file(tmp_path):
    path = tmp_path / "p.csv"
    path.write_text("alpha,beta\n0.01,abc\n")
    with pytest.raises(ValueError, match="is not a number"):
        asperity.sweep(points=str(path), P=[1.0], scheduler="serial")
    with pytest.raises(ValueError, match="cannot read"):
        asperity.sweep(points=str(tmp_path / "none.csv"), P=[1.0], scheduler="serial")
    # a review: a doubled header name read as 'a sweep needs beta'; 'points: points:' in messages
    path.write_text("alpha,alpha\n0.01,0.02\n")
    with pytest.raises(ValueError, match=r"^points: '.*p\.csv' names alpha twice in its header$"):
        asperity.sweep(points=str(path), P=[1.0], scheduler="serial")
    path.write_bytes(b"\xcd\xff\x00garbage")
    with pytest.raises(ValueError, match=r"^points: cannot read '.*p\.csv': 'utf-8' codec"):
        asperity.sweep(points=str(path), P=[1.0], scheduler="serial")


def test_without_xarray_the_hint_names_the_extra(monkeypatch):
    monkeypatch.setitem(sys.modules, "xarray", None)
    with pytest.raises(ImportError, match=r"pip install 'asperity\[sweep\]'"):
        asperity.sweep(alpha=0.01, beta=1.0, P=[1.0])


def test_progress_bar_with_eta(capsys):
    asperity.sweep(alpha=ALPHAS, beta=1000.0, gamma=1e-3, P=LOADS, scheduler="serial", progress=True,
                   chunk_sets=1)
    err = capsys.readouterr().err
    assert "asperity sweep" in err and "3/3" in err and "<" in err  # tqdm's elapsed<remaining


# -- Dask ----------------------------------------------------------------------------------------
distributed = pytest.importorskip("distributed")


@pytest.fixture(scope="module")
def cluster():
    import logging

    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=":0", silence_logs=logging.CRITICAL) as cl, \
            distributed.Client(cl) as client:
        yield client


def test_two_workers_equal_serial_cell_by_cell(cluster, serial, tmp_path):
    ds = asperity.sweep(**dict(grid(chunk_sets=2), scheduler=cluster))
    assert_same(ds, serial)
    zarr = asperity.sweep(**dict(grid(chunk_sets=3, out=str(tmp_path / "m.zarr")), scheduler=cluster))
    assert_same(zarr.load(), serial)


def test_a_killed_worker_does_not_lose_the_sweep(cluster, serial, monkeypatch):
    pids = list(cluster.run(os.getpid).values())
    real_write = store_module.MemoryStore.write
    killed = []

    def kill_after_first(self, k, result):
        real_write(self, k, result)
        if not killed:  # mid-sweep: tasks are in flight on both workers
            os.kill(pids[0], signal.SIGKILL)
            killed.append(pids[0])
    monkeypatch.setattr(store_module.MemoryStore, "write", kill_after_first)
    ds = asperity.sweep(**dict(grid(chunk_sets=1), scheduler=cluster))
    assert killed
    assert_same(ds, serial)
    cluster.wait_for_workers(2, timeout=60)  # the nanny restarts it for the next test


def test_out_and_points_of_a_wrong_type_are_named(tmp_path):
    """Found by tests/test_fuzz_api.py: out and points name themselves, before any work."""
    pytest.importorskip("xarray")
    base = dict(alpha=[0.01, 0.02], beta=1000.0, gamma=1e-3, P=[1.0], scheduler="serial")
    for kwargs, error, needle in (({"out": True}, TypeError, "^out must be a file name"),
                                  ({"out": tmp_path}, ValueError, "^out = .* is a directory"),
                                  ({"points": True, "alpha": None}, TypeError, "^points must be a dict"),
                                  ({"points": str(tmp_path), "alpha": None}, ValueError, "^points: path"),
                                  ({"points": {"a": [1.0]}, "alpha": None}, ValueError, r"\['a'\] in points")):
        with pytest.raises(error, match=needle):
            sweeps.sweep(**{**base, **kwargs})
    assert not list(tmp_path.iterdir())


def test_the_local_cluster_runs_its_workers_with_asperity_settings(serial):
    """The default cluster ('local') lifts Dask's malloc trim threshold (a parameter set cost
    1.69 ms of CPU instead of 1.30 ms under Dask's 64 KiB) and switches off the worker profiler."""
    from asperity.sweeps import run as run_module

    cluster, client = run_module._local_cluster()
    try:
        # on the loopback interface only: the scheduler, the workers and the dashboard (a review
        # saw the dashboard on 0.0.0.0)
        assert cluster.scheduler_address.startswith("tcp://127.0.0.1:")
        assert all(w.startswith("tcp://127.0.0.1:") for w in client.scheduler_info()["workers"])
        dashboard = client.run_on_scheduler(lambda dask_scheduler: dask_scheduler.http_server.port)
        sockets = client.run_on_scheduler(lambda dask_scheduler: [s.getsockname()[0] for s in
                                                                  dask_scheduler.http_server._sockets.values()])
        assert dashboard > 0 and set(sockets) == {"127.0.0.1"}, sockets
        env = client.run(lambda: os.environ.get("MALLOC_TRIM_THRESHOLD_"))
        assert set(env.values()) == {str(128 * 2**20)}
        profiling = client.run(lambda: __import__("dask").config.get("distributed.worker.profile.enabled"))
        assert set(profiling.values()) == {False}
        assert_same(asperity.sweep(**dict(grid(chunk_sets=2), scheduler=client)), serial)
        client.restart()  # a restarted worker (after a crash) keeps the settings
        assert set(client.run(lambda: os.environ.get("MALLOC_TRIM_THRESHOLD_")).values()) == {str(128 * 2**20)}
        profiling = client.run(lambda: __import__("dask").config.get("distributed.worker.profile.enabled"))
        assert set(profiling.values()) == {False}
    finally:
        client.close()
        cluster.close()


INTERRUPTED_START = """
import signal, sys
import distributed
from asperity.sweeps import run

def interrupt(signum, frame):
    raise KeyboardInterrupt

real_init = distributed.LocalCluster.__init__

def starting(self, *args, **kwargs):  # Ctrl-C 0.3 s into the cluster's start (it takes seconds)
    signal.setitimer(signal.ITIMER_REAL, 0.3)
    real_init(self, *args, **kwargs)

signal.signal(signal.SIGALRM, interrupt)
distributed.LocalCluster.__init__ = starting
try:
    run._local_cluster()
except KeyboardInterrupt:
    print("interrupted while starting")
"""


def test_an_interrupt_while_the_local_cluster_starts_leaves_no_exit_traceback(tmp_path):
    """Found by a user trial: Ctrl-C or SIGTERM in the first seconds of a sweep printed
    'asperity: interrupted', then 28 lines of distributed's exit hook failing to close the
    half-built cluster ('AssertionError: Status.init')."""
    import subprocess
    import sys

    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(Path(asperity.__file__).parents[1]),
                                                       os.environ.get("PYTHONPATH", "")]))
    done = subprocess.run([sys.executable, "-c", INTERRUPTED_START], capture_output=True, text=True, timeout=120,
                          env=env, cwd=tmp_path)
    assert done.stdout.strip() == "interrupted while starting", (done.stdout, done.stderr)
    # (a worker process caught mid-spawn may still print its own unpickling traceback: that one
    # is multiprocessing's, in the child; the exit hook's is the parent's and is gone)
    assert "Exception ignored" not in done.stderr and "close_clusters" not in done.stderr, done.stderr


def test_store_bytes_is_at_least_what_the_results_hold(serial):
    """The size estimate behind the room checks: 8 bytes per value of every variable, counted
    from the spec, against what the computed dataset's float variables hold."""
    from asperity.sweeps.spec import make_spec

    spec = make_spec({"alpha": ALPHAS, "beta": 1000.0, "gamma": GAMMAS}, P=LOADS)
    floats = sum(serial[k].nbytes for k in serial.data_vars if serial[k].dtype.kind == "f")
    assert floats == spec.n_sets * (store_module.store_bytes(spec) / spec.n_sets - 4 * store_module.MESSAGE_CHARS)


@pytest.mark.parametrize("name", ["big.nc", "big.zarr"])
def test_a_grid_larger_than_the_free_disk_is_refused_before_any_file(tmp_path, monkeypatch, name):
    """Found by a review: a 2000^3 grid filled the disk, then failed with a traceback."""
    import collections

    usage = collections.namedtuple("usage", "total used free")
    monkeypatch.setattr(store_module.shutil, "disk_usage", lambda path: usage(1e12, 1e12 - 1e3, 1e3))
    with pytest.raises(ValueError, match=r"take about .* GB, more than the 1e-06 GB free where"):
        asperity.sweep(**grid(out=str(tmp_path / name)))
    assert not list(tmp_path.iterdir())


def test_a_grid_larger_than_half_the_memory_is_refused_in_memory(monkeypatch):
    sizes = {"SC_PAGE_SIZE": 4096, "SC_PHYS_PAGES": 10}
    monkeypatch.setattr(store_module.os, "sysconf", lambda name: sizes[name])
    with pytest.raises(ValueError, match=r"more than half this machine's memory .*give out="):
        asperity.sweep(**grid())


def test_a_file_that_is_no_sweep_store_is_named(tmp_path):
    out = tmp_path / "c.nc"
    (tmp_path / "c.nc.partial").write_text("x\n")
    with pytest.raises(ValueError, match=r"c.nc.partial is not a sweep store \(.*\); choose another output"):
        asperity.sweep(**grid(out=str(out)))


def test_a_write_error_is_one_named_error_and_keeps_the_chunks(tmp_path, monkeypatch):
    """A store that cannot be written (a full disk: netCDF4 raises RuntimeError 'HDF error')
    ends the sweep with a ValueError naming the store; the partial store stays for resuming."""
    calls = []

    def failing(self, k, result):
        calls.append(k)
        raise RuntimeError("NetCDF: HDF error")
    monkeypatch.setattr(store_module.NetCDFStore, "write", failing)
    out = tmp_path / "s.nc"
    with pytest.raises(ValueError, match=r"cannot write the sweep to .*s.nc \(RuntimeError: NetCDF: HDF error\); the "
                                         r"chunks written are kept for resume=True"):
        asperity.sweep(**grid(out=str(out)))
    assert calls and os.path.exists(str(out) + ".partial")


def test_a_list_of_points_may_repeat_values():
    ds = asperity.sweep(points={"alpha": [0.01, 0.01], "beta": [1000.0, 300.0]}, P=[1.0], scheduler="serial")
    for i, beta in enumerate((1000.0, 300.0)):
        assert ds.mu.values[i, 0] == asperity.Model(0.01, beta).load_curve([1.0]).mu[0]


def test_a_zarr_path_with_a_trailing_slash_is_the_directory(tmp_path, serial):
    """Found by a review: ``out='s.zarr/'`` put the partial store inside the target and the
    finished sweep was deleted; the slash now names the same directory as without it."""
    out = tmp_path / "s.zarr"
    ds = asperity.sweep(**grid(out=str(out) + "/"))
    assert out.is_dir() and not os.path.exists(str(out) + ".partial")
    assert_same(ds.load(), serial)
    ds.close()


def test_an_error_of_the_computation_is_not_called_a_write_error(tmp_path, monkeypatch):
    """Only the store's own file errors become 'cannot write the sweep'."""
    from asperity.sweeps import run as run_module

    def broken(*args, **kwargs):
        raise NotImplementedError("a bug in a chunk")
    monkeypatch.setattr(run_module, "compute_chunk", broken)
    with pytest.raises(NotImplementedError, match="a bug in a chunk"):
        asperity.sweep(**grid(out=str(tmp_path / "b.nc")))


def test_a_grid_given_out_of_order_is_stored_in_increasing_order(tmp_path):
    """Found by a review: an unsorted grid was stored as given, so nearest selection failed
    ('index must be monotonic') and `asperity plot` drew cells in the wrong places."""
    ds = asperity.sweep(alpha=[0.1, 0.001, 0.01], beta=1000.0, gamma=[1e-2, 1e-5], P=[10.0, 1.0], scheduler="serial")
    assert ds.alpha.values.tolist() == [0.001, 0.01, 0.1] and ds.gamma.values.tolist() == [1e-5, 1e-2]
    assert ds.P.values.tolist() == [1.0, 10.0]
    assert ds.mu.sel(P=9.0, method="nearest").shape == (3, 2)
    for a in (0.1, 0.001):
        m = asperity.Model(alpha=a, beta=1000.0, gamma=1e-5)
        np.testing.assert_array_equal(ds.F.sel(alpha=a, gamma=1e-5).values, m.load_curve([1.0, 10.0]).F)


@pytest.mark.parametrize("kwargs, match", [
    ({"out": "map.csv"}, r"out must end in .nc, .nc4, .netcdf or .cdf \(a NetCDF file\) or .zarr"),
    ({"out": "map"}, r"out must end in .nc"),
    ({"out": "map.ZARR"}, r"out must end in .nc"),
])
def test_an_output_that_is_neither_netcdf_nor_zarr_is_refused(tmp_path, kwargs, match):
    with pytest.raises(ValueError, match=match):
        asperity.sweep(alpha=0.01, beta=1000.0, P=[1.0], scheduler="serial", out=str(tmp_path / kwargs["out"]))
    assert os.listdir(tmp_path) == []


def test_a_misspelt_material_is_refused_before_the_sweep():
    with pytest.raises(ValueError, match=r"^material: unknown material 'Xx'; known: Au"):
        asperity.sweep(material=["Au", "Xx"], sigma_s=2e-9, R=1e-6, eta=1e12, area=1e-6, P=[1e-3],
                       scheduler="serial")


def test_a_zarr_result_opens_without_warnings(tmp_path):
    """Found by a review: without consolidated metadata every xr.open_zarr warned."""
    xr = pytest.importorskip("xarray")
    pytest.importorskip("zarr")
    asperity.sweep(alpha=[0.01, 0.02], beta=1000.0, P=[1.0], scheduler="serial", out=str(tmp_path / "m.zarr"))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert xr.open_zarr(tmp_path / "m.zarr").mu.shape == (2, 1)


@pytest.mark.parametrize("name", ["m.nc4", "m.NC", "m.netcdf"])
def test_netcdf_outputs_of_other_spellings_are_written(tmp_path, name):
    """The review of the suffix check: .nc4, .netcdf and upper case were NetCDF before it."""
    xr = pytest.importorskip("xarray")
    pytest.importorskip("netCDF4")
    asperity.sweep(alpha=[0.01, 0.02], beta=1000.0, P=[1.0], scheduler="serial", out=str(tmp_path / name))
    with xr.open_dataset(tmp_path / name) as ds:
        assert ds.mu.shape == (2, 1)


@pytest.mark.parametrize("sizes, limit", [((1, 10, 32), 2**27), ((256, 10**6), 2**27), ((10**6, 10**6), 2**27),
                                          ((2, 3, 5), 7), ((3, 0), 10)])
def test_an_hdf5_chunk_holds_at_most_the_limit(sizes, limit):
    """HDF5 refuses chunks of 4 GiB or more: a sweep's chunk (chunk_sets up to the caller,
    curves up to 1e6 loads) is cut along its last dimensions to at most 2^27 doubles; one
    within the limit is kept as it is, and the sets of a chunk are cut only when one set's
    curve alone is too long."""
    import math

    got = store_module.hdf5_chunk(sizes, limit)
    assert math.prod(got) <= limit and all(1 <= g <= max(1, n) for g, n in zip(got, sizes, strict=True))
    if math.prod(max(1, n) for n in sizes) <= limit:
        assert got == tuple(max(1, n) for n in sizes)
    if math.prod(sizes[:-1]) <= limit < math.prod(sizes):
        assert got[:-1] == sizes[:-1] and got[-1] >= sizes[-1] // math.ceil(math.prod(sizes) / limit)


def test_a_load_at_the_floor_in_newtons_never_blanks_its_set():
    """A review: a load equal to the floor a physical set reports (in newtons) can round one
    step below the model's own floor once divided by N G b^2; the retry then raised and the
    whole set was NaN (3 of 120 sets).  Now such a load is dropped too, the others computed."""
    from asperity.load_control import LoadOutOfRange
    from asperity.physical import PhysicalContact, Surface
    from asperity.sweeps.compute import compute_set

    checked = 0
    for name in ("Au", "Cu", "Ag", "Pt", "Ni"):
        for sigma_s in np.geomspace(5e-10, 4e-9, 6):
            for R in (1e-7, 1e-6):
                params = dict(material=name, sigma_s=float(sigma_s), R=R, eta=1e12, area=1e-6)
                contact = PhysicalContact(name, Surface(float(sigma_s), R, 1e12, 1e-6))
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore", asperity.AsperityWarning)
                    try:
                        contact.load_curve([-1e9])
                    except LoadOutOfRange as err:
                        floor = err.floor
                    out = compute_set("physical", params, "P_N", np.array([-1e9, floor, 1e-3]))
                assert np.isnan(out["F_N"][0]) and np.isfinite(out["F_N"][2]), params
                checked += 1
    assert checked == 60
