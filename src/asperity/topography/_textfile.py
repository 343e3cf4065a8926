"""Text height matrices as SurfaceTopography's text reader takes them.

Its reader takes whitespace-separated UTF-8 without a byte-order mark.  Two spellings that
spreadsheets and Windows write are brought to that form before it reads them, each only
when it is unambiguous (user trials):

* a byte-order mark: UTF-8 (the first scan line was dropped with it, unnoted) or UTF-16
  (refused), decoded;
* a matrix of numbers separated by commas or semicolons (``np.savetxt(..., delimiter=",")``,
  refused before): every data line cut by the delimiter into as many cells, each a plain
  number, and no blank inside a cell (a decimal comma between blanks, ``1,5 2,3``, is left
  alone and refused), the delimiters made blanks; ``#`` lines are kept.
"""

from __future__ import annotations

import codecs
import io
import re

_BOMS = ((codecs.BOM_UTF8, "utf-8-sig"), (codecs.BOM_UTF16_LE, "utf-16"), (codecs.BOM_UTF16_BE, "utf-16"))
_NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?|[+-]?(?:nan|NaN|NAN|inf|Inf)")
#: Files read whole to look for a delimited matrix (larger ones go to SurfaceTopography as they are).
MAX_TEXT = 256 * 2**20


def open_bytes(name):
    """The file as a binary file object; a text matrix with a byte-order mark or delimiters as
    whitespace-separated UTF-8 (see the module docstring)."""
    fobj = open(name, "rb")
    head = fobj.read(4096)
    encoding = next((enc for bom, enc in _BOMS if head.startswith(bom)), None)
    if encoding is None and not _maybe_delimited(head):
        fobj.seek(0)
        return fobj
    with fobj:  # a marked file whole (cut, it would lose its end: a review); a delimited one up to MAX_TEXT
        raw = head + fobj.read(4 * MAX_TEXT if encoding is not None else MAX_TEXT)
    if encoding is not None and len(raw) > 4 * MAX_TEXT:
        raise ValueError(f"{name}: a text map of more than {4 * MAX_TEXT // 2**20} MB; save it in a binary format "
                         "(.npy, NetCDF)")
    if encoding is None and len(raw) > MAX_TEXT:
        return open(name, "rb")
    try:
        text = raw.decode(encoding or "utf-8")
    except UnicodeDecodeError:
        if encoding is None:  # not text after all: as it is
            return open(name, "rb")
        raise ValueError(f"{name}: not a readable topography file (it starts with a {encoding} byte-order "
                         "mark but is not such text)") from None
    return io.BytesIO((_whitespace_matrix(text) or text).encode("utf-8"))


def _maybe_delimited(head: bytes) -> bool:
    """A text start whose first line that is not a comment holds a comma or semicolon."""
    if b"\x00" in head:
        return False
    for line in head.decode("utf-8", errors="replace").splitlines():
        if line.strip() and not line.lstrip().startswith("#"):
            return "," in line or ";" in line
    return False


def _whitespace_matrix(text: str) -> str | None:
    """``text`` with its delimiter made blanks if it is a delimited matrix of numbers (a
    delimiter ending every line, a spreadsheet's, dropped), else None."""
    lines = text.splitlines()
    is_data = [bool(line.strip()) and not line.lstrip().startswith("#") for line in lines]
    data = [line.strip() for line, k in zip(lines, is_data, strict=True) if k]
    if not data:
        return None
    for d in (",", ";"):
        trailing = all(x.endswith(d) for x in data)
        rows = [(x[:-1] if trailing else x).split(d) for x in data]
        if len(rows[0]) < 2 or any(len(r) != len(rows[0]) for r in rows):
            continue
        if all(_NUMBER.fullmatch(c.strip()) for r in rows for c in r):  # no blank inside a number
            it = iter(rows)
            return "\n".join(" ".join(c.strip() for c in next(it)) if k else line
                             for line, k in zip(lines, is_data, strict=True)) + "\n"
    return None


def ragged_note(name) -> str:
    """'; line K holds n numbers, the others m' for a text matrix with one line of another
    length (a user trial: a short line was reported as an unknown format), a word on decimal
    commas between blanks, else ''."""
    try:
        with open(name, "rb") as fobj:
            raw = fobj.read(MAX_TEXT + 1)
        text = raw.decode("utf-8-sig") if len(raw) <= MAX_TEXT else ""
    except (OSError, UnicodeDecodeError):
        return ""
    numbered = [(i + 1, line.strip()) for i, line in enumerate(text.splitlines())
                if line.strip() and line.lstrip()[:1] not in ("#", "%")]
    d = next((d for d in (",", ";") if sum(d in line for _, line in numbered) > len(numbered) // 2), None)
    counts = [(i, len(line.removesuffix(d).split(d)) if d else len(line.split())) for i, line in numbered]
    if len(counts) < 3:
        return ""
    values = [n for _, n in counts]
    common = max(set(values), key=values.count)
    odd = [(i, n) for i, n in counts if n != common]
    if not odd and re.search(r"\d,\d+\s", text):
        return "; decimal commas ('1,5') are not read: write decimal points"
    if not odd or len(odd) > len(counts) // 2:
        return ""
    return (f"; line {odd[0][0]} holds {odd[0][1]} values, the others {common}" if len(odd) == 1 else
            f"; {len(odd)} lines (the first, line {odd[0][0]}) hold other numbers of values than the {common} "
            "of the rest")
