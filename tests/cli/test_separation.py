"""``asperity separation``: dimensionless and physical separation curves against the library."""

import json

import numpy as np
import pytest

import asperity

from .helpers import AU, MODEL, run

#: Gold asperities of these surfaces yield (plasticity index psi = 23): the elastic model
#: warns (asperity.PlasticityWarning).  The warning itself is tested in tests/test_plasticity.py.
pytestmark = pytest.mark.filterwarnings("ignore::asperity.plasticity.PlasticityWarning")


def test_separation_json_matches_library(capsys):
    code, out, _ = run(capsys, "separation", *MODEL, "--d", "-1,0,2.5", "--format", "json")
    assert code == 0
    rows = json.loads(out)
    ref = asperity.separation_curve([-1, 0, 2.5], 0.01, 1000, 1e-3)
    assert [r["d"] for r in rows] == [-1, 0, 2.5]
    np.testing.assert_allclose([r["F"] for r in rows], ref.F, rtol=1e-15)
    assert set(rows[0]) == {"d", "P", "F", "mu", "area", "pressure", "contacts"}


def test_separation_range_is_linear(capsys):
    code, out, _ = run(capsys, "separation", *MODEL, "--d", "-1:4:11", "--format", "csv")
    assert code == 0
    assert out == asperity.separation_curve(np.linspace(-1, 4, 11), 0.01, 1000, 1e-3).to_csv()


def test_physical_separation(capsys):
    from asperity.physical import PhysicalContact, Surface

    contact = PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6), adhesion=False)
    code, out, _ = run(capsys, "separation", *AU, "--no-adhesion", "--separation", "-2nm,0nm,3nm",
                       "--format", "json")
    assert code == 0
    got = json.loads(out)
    assert set(got) == {"contact", "rows"} and got["contact"] == json.loads(json.dumps(contact.to_dict()))
    np.testing.assert_allclose([r["P_N"] for r in got["rows"]], contact.separation_curve([-2e-9, 0, 3e-9]).P,
                               rtol=1e-14)
