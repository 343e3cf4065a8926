"""Atomic file output: write to a temporary file beside the target, then rename it into place.

Every file asperity writes (``-o`` and ``--plot`` on the command line, the CSVs, figures
and ``index.html`` of :func:`asperity.studies.reproduce`, ``to_csv(path)``) goes through
:func:`atomic_path` or :func:`atomic_write`.  The data go to a temporary file in the
target's directory (so the rename never crosses a file system), are flushed to disk, and
the file is renamed onto the target with :func:`os.replace`, which is atomic on POSIX and
Windows.  An exception or an interruption (``KeyboardInterrupt``) before the rename
deletes the temporary file: the target is then either untouched (a file that existed
keeps its old content) or absent, never truncated or half written.

A target that exists and is not a regular file (``/dev/stdout``, ``/dev/null``, a named
pipe) cannot be replaced: it is written in place.  A symbolic link is followed, so the
file it points to is replaced, not the link.  A directory is refused
(:class:`IsADirectoryError`).
"""

from __future__ import annotations

import contextlib
import os
import stat
import tempfile
from collections.abc import Iterator

__all__ = ["atomic_path", "atomic_write"]


def _new_file_mode() -> int:
    """Permissions a plain ``open(path, "w")`` would give a new file (0o666 less the umask)."""
    umask = os.umask(0)
    os.umask(umask)
    return 0o666 & ~umask


@contextlib.contextmanager
def atomic_path(path) -> Iterator[str]:
    """Yield a temporary path beside ``path``; on success, rename it onto ``path``.

    Write the whole output to the yielded path (e.g. ``fig.savefig(tmp, format="png")``:
    the temporary name ends in ``.tmp``, so pass the format explicitly).  When the block
    ends normally the file is flushed to disk and renamed onto ``path``; when it raises
    (or is interrupted) the temporary file is removed and ``path`` is left as it was.

    Parameters
    ----------
    path : str or os.PathLike
        The file to create or replace.  Its directory must exist.

    Yields
    ------
    str
        The temporary file's path (an empty file already exists there).

    Raises
    ------
    IsADirectoryError
        If ``path`` is an existing directory.
    OSError
        If the directory does not exist or is not writable, or on any write error.
    """
    target = os.path.realpath(os.fspath(path))
    try:
        info = os.stat(target)
    except FileNotFoundError:
        info = None
    if info is not None and stat.S_ISDIR(info.st_mode):
        raise IsADirectoryError(21, "Is a directory", os.fspath(path))
    if info is not None and not stat.S_ISREG(info.st_mode):  # a device or a pipe: write in place
        yield target
        return
    directory, name = os.path.split(target)
    fd, tmp = tempfile.mkstemp(dir=directory, prefix=f".{name}.", suffix=".tmp")
    os.close(fd)
    try:
        yield tmp
        os.chmod(tmp, stat.S_IMODE(info.st_mode) if info is not None else _new_file_mode())
        fd = os.open(tmp, os.O_RDONLY)
        try:
            os.fsync(fd)
        finally:
            os.close(fd)
        os.replace(tmp, target)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp)
        raise


def atomic_write(path, data: str | bytes) -> None:
    """Write ``data`` to ``path`` atomically (see :func:`atomic_path`).

    Parameters
    ----------
    path : str or os.PathLike
        The file to create or replace.
    data : str or bytes
        Text (written as UTF-8, newlines untranslated) or bytes.

    Raises
    ------
    TypeError
        If ``data`` is neither str nor bytes.
    OSError
        As :func:`atomic_path`.
    """
    if isinstance(data, str):
        data = data.encode("utf-8")
    elif not isinstance(data, bytes | bytearray | memoryview):
        raise TypeError(f"data must be str or bytes, got {type(data).__name__}")
    with atomic_path(path) as tmp, open(tmp, "wb") as fh:
        fh.write(data)
