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
