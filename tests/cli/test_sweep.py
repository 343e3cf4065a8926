"""``asperity sweep``: the file it writes equals asperity.sweep's result for every spelling."""

import numpy as np
import pytest

import asperity

from .helpers import one_line_error, run

xr = pytest.importorskip("xarray")
pytest.importorskip("netCDF4")


def same(path, ds):
    with xr.open_dataset(path) if not str(path).endswith(".zarr") else xr.open_zarr(path, consolidated=False) as f:
        f = f.drop_vars("chunk_done").load()
    assert set(f.data_vars) == set(ds.data_vars) and f.attrs == ds.attrs
    for name in ds.variables:
        a, b = f[name].values, ds[name].values
        if a.dtype.kind == "f":
            np.testing.assert_array_equal(a, b, err_msg=name)
        else:
            assert (a == b).all(), name


def test_grid_with_ranges_equals_the_api(capsys, tmp_path):
    out = tmp_path / "map.nc"
    code, text, err = run(capsys, "sweep", "--alpha", "1e-3:0.1:3", "--beta", "1000", "--gamma", "0,1e-4,1e-3",
                          "--P", "1e-2:1e3:4", "--out", str(out), "--scheduler", "serial", "--no-progress")
    assert code == 0, err
    assert text.strip() == f"wrote {out}: 9 parameter sets"
    ds = asperity.sweep(alpha=np.geomspace(1e-3, 0.1, 3), beta=1000.0, gamma=np.array([0, 1e-4, 1e-3]),
                        P=np.geomspace(1e-2, 1e3, 4), scheduler="serial")
    same(out, ds)


def test_zarr_separations_hk_and_chunks_equal_the_api(capsys, tmp_path):
    out = tmp_path / "map.zarr"
    code, text, err = run(capsys, "sweep", "--alpha", "0.01", "--beta", "100,1000", "--gamma", "1e-3", "--nu",
                          "0.25", "--h-over-b", "2", "--tau-f1", "0.01,0.03", "--a2", "1e5", "--d", "-1,0,2",
                          "--out", str(out), "--scheduler", "serial", "--chunk-sets", "1")
    assert code == 0, err
    ds = asperity.sweep(alpha=0.01, beta=np.array([100.0, 1000.0]), gamma=1e-3, nu=0.25, h_over_b=2.0,
                        tau_f1=np.array([0.01, 0.03]), a2=1e5, d=np.array([-1.0, 0.0, 2.0]), scheduler="serial",
                        chunk_sets=1)
    same(out, ds)


def test_points_csv_and_failed_sets_counted(capsys, tmp_path):
    pts = tmp_path / "sets.csv"
    pts.write_text("alpha,beta,gamma\n0.003,1000,1e-3\n0.01,1000,0\n0.01,1000,1e-30\n")
    out = tmp_path / "pts.nc"
    code, text, err = run(capsys, "sweep", "--points", str(pts), "--P=-1,10", "--out", str(out),
                          "--scheduler", "serial")
    assert code == 0, err
    # gamma = 0 cannot carry P = -1 (NaN there, noted), 1e-30 leaves Maugis's range (NaN, counted)
    assert "3 parameter sets, 1 outside the model's domain (NaN; see the message variable), 1 with a validity " \
           "note of the library (see the message variable), of which 1 with NaN at the loads below their least " \
           "load" in text
    same(out, asperity.sweep(points=str(pts), P=np.array([-1.0, 10.0]), scheduler="serial"))


def test_physical_sweep_with_units_equals_the_api(capsys, tmp_path):
    pytest.importorskip("pint")
    out = tmp_path / "au.nc"
    code, _, err = run(capsys, "sweep", "--material", "Au,Si", "--sigma", "1nm,2nm", "--radius", "1um",
                       "--density", "1e12/m^2", "--area", "1mm^2", "--load", "0.1mN,1mN", "--out", str(out),
                       "--scheduler", "serial")
    assert code == 0, err
    same(out, asperity.sweep(material=["Au", "Si"], sigma_s=np.array([1e-9, 2e-9]), R=1e-6, eta=1e12, area=1e-6,
                             P=np.array([1e-4, 1e-3]), scheduler="serial"))


def test_resume_and_refusal(capsys, tmp_path):
    out = tmp_path / "map.nc"
    argv = ["sweep", "--alpha", "0.01,0.02", "--beta", "1000", "--P", "1,10", "--out", str(out),
            "--scheduler", "serial"]
    assert run(capsys, *argv)[0] == 0
    code, _, err = run(capsys, *argv)
    assert one_line_error(code, err, "--resume")
    assert run(capsys, *argv, "--resume")[0] == 0
    other = ["sweep", "--alpha", "0.01,0.03", "--beta", "1000", "--P", "1,10", "--out", str(out), "--resume",
             "--scheduler", "serial"]
    code, _, err = run(capsys, *other)
    assert one_line_error(code, err, "refusing to mix two grids")


@pytest.mark.parametrize("argv, needle", [
    (["--alpha", "0.01", "--beta", "1000"], "give one of --P or --d"),
    (["--alpha", "0.01", "--beta", "1000", "--P", "1", "--d", "0"], "give one of --P or --d"),
    (["--alpha", "0.01", "--beta", "1000", "--load", "1mN"], "give one of --P or --d"),
    (["--alpha", "0.01,,2", "--beta", "1000", "--P", "1"], "empty item"),
    (["--alpha", "0:0.1:3", "--beta", "1000", "--P", "1"], "log-spaced range"),
    (["--alpha", "-0.01", "--beta", "1000", "--P", "1"], "alpha must satisfy"),
    (["--beta", "1000", "--P", "1"], "needs alpha"),
    (["--points", "nowhere.csv", "--P", "1"], "no such file"),
    (["--points", ".", "--P", "1"], "is a directory, not a CSV file"),
    (["--material", "Au,", "--P", "1"], "empty name"),
    (["--alpha", "0.01", "--beta", "1000", "--P", "1", "--chunk-sets", "0"], "chunk_sets"),
    (["--alpha", "1e-3:0.1:2000", "--beta", "1:1e4:2000", "--gamma", "1e-5:1e-2:2000", "--P", "1"],
     "more than the"),  # 8e9 sets: about 1.3e4 GB, refused before any file is made
])
def test_errors_are_one_line(capsys, tmp_path, argv, needle):
    code, _, err = run(capsys, "sweep", *argv, "--out", str(tmp_path / "x.nc"), "--scheduler", "serial")
    assert one_line_error(code, err, needle), err


def test_scheduler_address_equals_the_api(capsys, tmp_path):
    distributed = pytest.importorskip("distributed")
    import logging

    out = tmp_path / "map.nc"
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=True, host="127.0.0.1",
                                  dashboard_address=":0", silence_logs=logging.CRITICAL) as cluster:
        code, _, err = run(capsys, "sweep", "--alpha", "0.003,0.01", "--beta", "1000", "--gamma", "1e-3",
                           "--P", "1,10", "--out", str(out), "--scheduler", cluster.scheduler_address,
                           "--chunk-sets", "1")
    assert code == 0, err
    same(out, asperity.sweep(alpha=np.array([0.003, 0.01]), beta=1000.0, gamma=1e-3, P=np.array([1.0, 10.0]),
                             scheduler="serial", chunk_sets=1))


def test_unreachable_scheduler_is_one_line_and_writes_nothing(capsys, tmp_path, monkeypatch):
    pytest.importorskip("distributed")
    from asperity.sweeps import run as sweep_run

    monkeypatch.setattr(sweep_run, "CONNECT_TIMEOUT", 1)
    code, _, err = run(capsys, "sweep", "--alpha", "0.01", "--beta", "1000", "--P", "1", "--out",
                       str(tmp_path / "m.nc"), "--scheduler", "tcp://127.0.0.1:9")
    assert one_line_error(code, err, "cannot reach the Dask scheduler")
    assert list(tmp_path.iterdir()) == []


def test_an_existing_directory_that_is_no_sweep_is_named(capsys, tmp_path):
    """Found by a review: an empty ``map.zarr/`` was refused as 'a directory; give a file
    name', though a Zarr store is a directory; now the library says it is no sweep store."""
    (tmp_path / "map.zarr").mkdir()
    code, _, err = run(capsys, "sweep", "--alpha", "0.01", "--beta", "1000", "--P", "1", "--out",
                       str(tmp_path / "map.zarr"), "--scheduler", "serial")
    assert one_line_error(code, err, "map.zarr is not a sweep store"), err


def test_a_binary_points_file_is_one_line_naming_it(capsys, tmp_path):
    """A review: "'utf-8' codec can't decode byte 0xcd", naming neither the option nor the file."""
    path = tmp_path / "points.csv"
    path.write_bytes(b"\xcd\xff\x00garbage")
    code, _, err = run(capsys, "sweep", "--points", str(path), "--P", "1", "--out", str(tmp_path / "x.nc"))
    assert code == 2 and err.count("\n") == 1 and f"--points {str(path)!r}: cannot read it as text" in err, err


def test_a_physical_sweep_over_the_work_of_adhesion_and_a_burgers_vector_equals_the_api(capsys, tmp_path):
    """Found by a review: diamond (no w in the table) and mica (no b) could not be swept, and the
    per-set messages advised --w and --b, which the sweep did not have."""
    pytest.importorskip("pint")
    out = tmp_path / "dm.nc"
    code, _, err = run(capsys, "sweep", "--material", "diamond,mica", "--sigma-s", "2nm", "--R", "1um",
                       "--eta", "1e12/m^2", "--area", "1mm^2", "--w", "0J/m^2,0.1J/m^2", "--b", "0.25nm",
                       "--load", "1mN,1N", "--out", str(out), "--scheduler", "serial")
    assert code == 0, err
    ds = asperity.sweep(material=["diamond", "mica"], sigma_s=2e-9, R=1e-6, eta=1e12, area=1e-6,
                        w=np.array([0.0, 0.1]), b=2.5e-10, P=np.array([1e-3, 1.0]), scheduler="serial")
    same(out, ds)
    from asperity.bodies import contact_material
    from asperity.physical import PhysicalContact, Surface

    contact = PhysicalContact(contact_material("mica", w=0.1, b=2.5e-10), Surface(2e-9, 1e-6, 1e12, 1e-6))
    np.testing.assert_array_equal(ds.F_N.sel(material="mica", w=0.1).values, contact.load_curve([1e-3, 1.0]).F)
    with pytest.warns(asperity.AsperityWarning, match="no pull-off"):  # the set's note, as a warning here
        assert ds.pull_off_N.sel(material="mica", w=0.1).item() == contact.pull_off().force
    assert (ds.message.sel(w=0.0).values == "").all()
