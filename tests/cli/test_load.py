"""``asperity load``: dimensionless and physical load curves against the library."""

import numpy as np
import pytest

import asperity

from .helpers import AU, MODEL, rows_of, run

#: Gold asperities of these surfaces yield (plasticity index psi = 23): the elastic model
#: warns (asperity.PlasticityWarning).  The warning itself is tested in tests/test_plasticity.py.
pytestmark = pytest.mark.filterwarnings("ignore::asperity.plasticity.PlasticityWarning")


def test_load_csv_matches_library(capsys):
    code, out, _ = run(capsys, "load", *MODEL, "--P", "1:1e4:5", "--format", "csv")
    assert code == 0
    rows = rows_of(out)
    assert list(rows[0]) == ["d", "P", "F", "mu", "area", "pressure", "contacts"]
    ref = asperity.load_curve(np.geomspace(1, 1e4, 5), 0.01, 1000, 1e-3)
    for key in ("d", "P", "F", "mu", "area", "pressure", "contacts"):
        np.testing.assert_allclose([float(r[key]) for r in rows], getattr(ref, key), rtol=1e-15)


def test_load_csv_is_the_library_csv(capsys):
    # The command's CSV is the library's own to_csv text, byte for byte (full-precision floats).
    code, out, _ = run(capsys, "load", *MODEL, "--P", "0.5,3,1e3", "--format", "csv")
    assert code == 0
    assert out == asperity.load_curve([0.5, 3, 1e3], 0.01, 1000, 1e-3).to_csv()


def test_physical_load_matches_library(capsys):
    from asperity.physical import PhysicalContact, Surface

    code, out, _ = run(capsys, "load", *AU, "--load", "1mN:1N:4", "--format", "csv")
    assert code == 0
    rows = rows_of(out)
    assert list(rows[0]) == ["d_m", "P_N", "F_N", "mu", "area_m2", "pressure_Pa", "contacts"]
    ref = PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6)).load_curve(np.geomspace(1e-3, 1, 4))
    np.testing.assert_allclose([float(r["P_N"]) for r in rows], ref.P, rtol=1e-14)
    np.testing.assert_allclose([float(r["F_N"]) for r in rows], ref.F, rtol=1e-14)
    np.testing.assert_allclose([float(r["d_m"]) for r in rows], ref.d, rtol=1e-14)


def test_physical_load_list_with_units(capsys):
    from asperity.physical import PhysicalContact, Surface

    code, out, _ = run(capsys, "load", *AU, "--load", "1mN,0.5N,2000mN", "--format", "csv")
    assert code == 0
    ref = PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6)).load_curve([1e-3, 0.5, 2.0])
    np.testing.assert_allclose([float(r["P_N"]) for r in rows_of(out)], ref.P, rtol=1e-14)


def test_note_when_real_area_approaches_nominal(capsys):
    argv = ["load", "--material", "Au", "--sigma", "5nm", "--radius", "0.8um", "--density", "2e13/m^2",
            "--area", "1mm^2", "--load", "1N,1e5N", "--format", "csv"]
    code, out, err = run(capsys, *argv)
    rows = rows_of(out)
    assert code == 0 and float(rows[1]["area_m2"]) > 0.1e-6
    assert "note:" in err and "nominal" in err
