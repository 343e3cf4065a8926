"""Shared pieces of the command-line tests."""

import csv
import io
import json

from asperity.cli import main

MODEL = ["--alpha", "0.01", "--beta", "1000", "--gamma", "1e-3"]
AU = ["--material", "Au", "--sigma", "2nm", "--radius", "1um", "--density", "1e12/m^2", "--area", "1mm^2"]
#: The same contact with the library's names (the old spellings above stay as aliases).
AU_NEW = ["--material", "Au", "--sigma-s", "2nm", "--R", "1um", "--eta", "1e12/m^2", "--area", "1mm^2"]


def run(capsys, *argv):
    """Run ``asperity *argv`` in-process: (exit status, stdout, stderr)."""
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def rows_of(text):
    """The CSV rows of a command's output; the '#' lines describing a physical contact are skipped."""
    return list(csv.DictReader(io.StringIO("".join(line for line in text.splitlines(keepends=True)
                                                   if not line.startswith("#")))))


def comment_lines(text):
    """The '#' lines at the top of a physical result, without the '# '."""
    return [line[2:] for line in text.splitlines() if line.startswith("# ")]


def _reject_constant(name):
    raise ValueError(f"non-standard JSON constant {name}")


def strict_json(text):
    """Parse JSON as a strict parser would: NaN, Infinity and -Infinity are errors."""
    return json.loads(text, parse_constant=_reject_constant)


def one_line_error(code, err, needle=""):
    """The command-line contract for errors: status 2, one line, no traceback."""
    lines = err.strip().splitlines()
    return (code == 2 and len(lines) == 1 and lines[0].startswith("asperity: error:") and needle in lines[0]
            and "Traceback" not in err)
