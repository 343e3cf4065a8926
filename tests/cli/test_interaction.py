"""``--interaction`` of ``asperity load`` and ``asperity separation`` against the library."""

import numpy as np
import pytest

import asperity
from asperity.interaction import MeanFieldInteraction, cgp_compliance
from asperity.physical import PhysicalContact, Surface

from .helpers import AU_NEW, rows_of, run

pytestmark = pytest.mark.filterwarnings("ignore::asperity.plasticity.PlasticityWarning")

DIMLESS = ["--alpha", "0.05", "--beta", "100"]


@pytest.mark.parametrize("kind, option, values", [("load", "--P", [0.5, 3.0, 40.0]),
                                                  ("separation", "--d", [0.5, 1.5, 2.5])])
@pytest.mark.parametrize("spec", ["cgp2008:k=0.04", "CGP2008: k = 0.04", "cgp2008:K=4e-2"])
def test_dimensionless_equals_model(capsys, kind, option, values, spec):
    code, out, err = run(capsys, kind, *DIMLESS, option, ",".join(map(str, values)), "--interaction", spec,
                         "--format", "csv")
    assert code == 0, err
    model = asperity.Model(0.05, 100, 0.0, interaction=MeanFieldInteraction(0.04))
    assert out == getattr(model, f"{kind}_curve")(values).to_csv()
    plain = getattr(asperity.Model(0.05, 100, 0.0), f"{kind}_curve")(values)
    # the correction changes the separations (load control) or the loads (separation control)
    changed = "d" if kind == "load" else "P"
    assert not np.allclose([float(r[changed]) for r in rows_of(out)], getattr(plain, changed))


@pytest.mark.parametrize("kind, option, values, si", [("load", "--load", "1mN,30mN", [1e-3, 3e-2]),
                                                      ("separation", "--separation", "3nm,5nm", [3e-9, 5e-9])])
def test_physical_equals_contact(capsys, kind, option, values, si):
    code, out, err = run(capsys, kind, *AU_NEW, option, values, "--no-adhesion", "--interaction", "cgp2008",
                         "--format", "csv")
    assert code == 0, err
    contact = PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6), adhesion=False, interaction="cgp2008")
    ref = getattr(contact, f"{kind}_curve")(si)
    rows = rows_of(out)
    for column, attr in (("d_m", "d"), ("P_N", "P"), ("area_m2", "area"), ("F_N", "F")):
        np.testing.assert_allclose([float(r[column]) for r in rows], getattr(ref, attr), rtol=1e-14)
    assert "interaction: cgp2008" in out
    k = cgp_compliance(1e12, 1e-6, contact.material.b, 2e-9, contact.material.nu)
    assert contact.interaction.compliance == pytest.approx(k, rel=1e-15)


def test_none_is_plain_gw(capsys):
    a = run(capsys, "load", *DIMLESS, "--P", "1,10", "--interaction", "none", "--format", "csv")
    b = run(capsys, "load", *DIMLESS, "--P", "1,10", "--format", "csv")
    assert a[0] == 0 and a[1] == b[1]


@pytest.mark.parametrize("argv, words", [
    ([*DIMLESS, "--P", "1", "--interaction", "cgp2008"], "needs its compliance"),
    ([*DIMLESS, "--P", "1", "--interaction", "cgp2008:k=-1"], ">= 0"),
    ([*DIMLESS, "--P", "1", "--interaction", "cgp2008:k=nan"], ">= 0"),
    ([*DIMLESS, "--P", "1", "--interaction", "cgp2008:k=inf"], ">= 0"),
    ([*DIMLESS, "--P", "1", "--interaction", "cgp2008:k=x"], "expected a number"),
    ([*DIMLESS, "--P", "1", "--interaction", "cgp2008:tau=1"], "needs its compliance"),
    ([*DIMLESS, "--P", "1", "--interaction", "bogus"], "expected one of none, cgp2008"),
    ([*DIMLESS, "--P", "1", "--interaction", "none:k=1"], "takes no parameter"),
    ([*DIMLESS, "--gamma", "0.01", "--P", "1", "--interaction", "cgp2008:k=0.1"], "non-adhesive"),
    ([*AU_NEW, "--load", "1mN", "--interaction", "cgp2008"], "add --no-adhesion"),
    ([*AU_NEW, "--load", "1mN", "--no-adhesion", "--interaction", "cgp2008:k=0.1"], "follows from eta"),
])
def test_refused_with_one_line(capsys, argv, words):
    code, out, err = run(capsys, "load", *argv)
    assert code == 2 and out == ""
    assert len(err.strip().splitlines()) == 1 and words in err and "--interaction" in err


def test_only_curve_commands_take_it(capsys):
    code, out, err = run(capsys, "pulloff", *DIMLESS, "--gamma", "0.01", "--interaction", "cgp2008:k=0.1")
    assert code == 2 and out == "" and "--interaction" in err


def test_an_underflowing_compliance_says_so(capsys):
    code, out, err = run(capsys, "load", *DIMLESS, "--P", "1", "--interaction", "cgp2008:k=1e-400")
    assert code == 2 and "smaller than the smallest double" in err
