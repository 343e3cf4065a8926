"""``asperity md``: one Maugis-Dugdale asperity against the library."""

import numpy as np
import pytest

import asperity

from .helpers import one_line_error, rows_of, run


def test_md_commands(capsys):
    code, out, _ = run(capsys, "md", "--lam", "1", "--delta", "-0.5,0,1", "--format", "csv")
    assert code == 0
    rows = rows_of(out)
    A, P, t = asperity.md_solve(np.array([-0.5, 0, 1]), 1.0)
    np.testing.assert_allclose([float(r["A"]) for r in rows], A, rtol=1e-15)
    np.testing.assert_allclose([float(r["m"]) for r in rows], np.sqrt(1 + t**2), rtol=1e-15)
    code, out, _ = run(capsys, "md", "--lam", "1e4", "--pulloff", "--format", "csv")
    rows = {r["control"]: float(r["P"]) for r in rows_of(out)}
    assert rows["load"] == pytest.approx(-1.5, rel=1e-3)
    assert rows["displacement"] == pytest.approx(-5 / 6, rel=1e-3)


@pytest.mark.parametrize("argv, call", [
    (["--lam", "-1", "--pulloff"], lambda: asperity.md_pull_off(-1.0, "load")),
    (["--lam", "nan", "--pulloff"], lambda: asperity.md_pull_off(float("nan"), "load")),
    (["--lam", "1", "--delta", "-5"], lambda: asperity.md_solve(np.array([-5.0]), 1.0)),
    (["--lam", "0", "--delta", "1"], lambda: asperity.md_solve(np.array([1.0]), 0.0)),
])
def test_md_errors_are_the_library_errors(capsys, argv, call):
    # The command repeats none of md_solve's checks: its message is the library's.
    with pytest.raises(ValueError) as exc:
        call()
    code, _, err = run(capsys, "md", *argv)
    assert one_line_error(code, err) and err.strip() == f"asperity: error: {exc.value}"
