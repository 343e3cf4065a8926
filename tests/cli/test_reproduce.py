"""``asperity reproduce``: the README's main job, and its errors."""

import subprocess
import sys

from .helpers import one_line_error, run


def test_reproduce_command(tmp_path):
    # The README's main job, through the installed entry point's module.
    out = tmp_path / "paper"
    res = subprocess.run([sys.executable, "-m", "asperity.cli", "reproduce", "--out", str(out)],
                         capture_output=True, text=True, check=True)
    lines = res.stdout.splitlines()
    assert sum(line.startswith("Fig ") for line in lines) == 7 and "index.html" in lines[-1]
    assert (out / "index.html").exists() and (out / "table1.csv").exists()
    assert not [p.name for p in out.iterdir() if p.name.startswith(".")]  # no temporary files left


def test_reproduce_unwritable(capsys, tmp_path):
    blocker = tmp_path / "file"
    blocker.write_text("x")
    code, _, err = run(capsys, "reproduce", "--out", str(blocker / "sub"))
    assert code == 2 and err.count("\n") == 1 and "is a file, not a directory" in err


def test_reproduce_empty_out_is_an_error(capsys):
    code, _, err = run(capsys, "reproduce", "--out", "")
    assert one_line_error(code, err, "--out")


def test_reproduce_interrupted_leaves_no_partial_file(capsys, tmp_path, monkeypatch):
    # Interrupt the run in the middle of writing Fig 3's CSV: the earlier files are complete,
    # the CSV being written does not exist (no truncated file), no temporary file remains.
    import asperity.studies.report as report

    def interrupted(path, rows, columns):
        from asperity._atomic import atomic_path

        with atomic_path(path) as tmp:
            with open(tmp, "w") as fh:
                fh.write("curve,adhesion\nhalf a ro")
            raise KeyboardInterrupt

    monkeypatch.setattr(report, "write_csv", interrupted)
    out = tmp_path / "paper"
    code, _, err = run(capsys, "reproduce", "--out", str(out))
    assert code == 130 and "interrupted" in err
    names = sorted(p.name for p in out.iterdir())
    assert names == ["fig3.png", "fig3.svg"]
    assert (out / "fig3.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert (out / "fig3.svg").read_text().rstrip().endswith("</svg>")


def test_an_output_directory_in_a_missing_one_is_refused(capsys, tmp_path):
    """Found by a review: --out /missing/dir/x made the whole path where -o, --plot, --summits
    and sweep --out refuse a missing parent."""
    code, _, err = run(capsys, "reproduce", "--out", str(tmp_path / "missing" / "x"))
    assert code == 2 and "does not exist" in err and not (tmp_path / "missing").exists()
