"""``asperity pulloff``: the pull-off force against the library."""

import json

import pytest

import asperity

from .helpers import AU, run


def test_pulloff_and_table(capsys):
    code, out, _ = run(capsys, "pulloff", "--alpha", "0.003", "--beta", "1000", "--gamma", "1e-3",
                       "--format", "json")
    assert code == 0
    got = json.loads(out)
    ref = asperity.pull_off(0.003, 1000, 1e-3)
    assert got["pull_off"] == pytest.approx(ref.force, rel=1e-15) and got == ref.to_dict()
    code, out, _ = run(capsys, "pulloff", "--alpha", "0.003", "--beta", "1000", "--gamma", "1e-3",
                       "--format", "table")
    assert "pull_off" in out.splitlines()[0]


def test_physical_pulloff(capsys):
    from asperity.physical import PhysicalContact, Surface

    code, out, _ = run(capsys, "pulloff", *AU, "--format", "json")
    got = json.loads(out)
    contact = PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6))
    ref = contact.pull_off()
    assert set(got) == {"contact", "rows"} and len(got["rows"]) == 1
    assert got["rows"][0] == ref.to_dict() and got["contact"] == contact.to_dict()
    assert got["rows"][0]["pull_off_N"] == pytest.approx(ref.force, rel=1e-14)


def test_pulloff_without_adhesion_has_null_separation(capsys):
    # gamma = 0: no tensile force, the separation is undefined (NaN in the API, null in JSON).
    ref = asperity.pull_off(0.01, 1000, 0.0)
    code, out, _ = run(capsys, "pulloff", "--alpha", "0.01", "--beta", "1000", "--gamma", "0", "--format", "json")
    assert code == 0 and out.strip() == json.dumps({"pull_off": ref.force, "d": None, "exists": False})


def test_pulloff_table_without_a_pull_off_shows_a_dash(capsys):
    """Found by a review: the table printed the undefined separation as 'None'."""
    code, out, _ = run(capsys, "pulloff", "--alpha", "0.01", "--beta", "1000", "--gamma", "0", "--format", "table")
    header, row = out.strip().splitlines()
    assert code == 0 and header.split() == ["pull_off", "d", "exists"] and row.split() == ["0", "-", "False"]


@pytest.mark.parametrize("option", ["--d-max", "--dmax"])  # cycle's spelling too
@pytest.mark.parametrize("d_max", ["2.5", "5nm", "5e-9m", "0.005 um"])
def test_physical_d_max_as_a_number_or_a_length_equals_the_library(capsys, d_max, option):
    """A review: --d-max 5nm was refused ('invalid float value') where cycle's --dmax needs a unit;
    with a physical contact it now takes both (a number in units of sigma_s, as before)."""
    from asperity.physical import PhysicalContact, Surface

    code, out, err = run(capsys, "pulloff", *AU, option, d_max, "--format", "json")
    assert code == 0, err
    contact = PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6))
    api = float(d_max) if d_max[0].isdigit() and d_max.replace(".", "").isdigit() else d_max
    assert json.loads(out)["rows"][0] == contact.pull_off(api).to_dict()
    # a length is d_max/sigma_s: 5 nm over sigma_s = 2 nm is 2.5
    assert contact.pull_off("5nm").force == contact.pull_off(2.5).force


@pytest.mark.parametrize("argv, needle", [
    (["--alpha", "0.003", "--beta", "1000", "--gamma", "1e-3", "--d-max", "5nm"], "--d-max: expected a number"),
    ([*AU, "--d-max", "5um"], "d_max = 5um is 2500 sigma_s"),
    ([*AU, "--d-max", "1kg"], "d_max must have units compatible with m"),
    ([*AU, "--d-max", "-1nm"], "d_max must be > 0 m"),
])
def test_bad_d_max_is_one_line(capsys, argv, needle):
    code, out, err = run(capsys, "pulloff", *argv)
    assert code == 2 and out == "" and err.count("\n") == 1 and needle in err, err
