"""Input checks of file names: a file or directory name, an image file and its format.

Part of the input checks of :mod:`asperity._validation` (which re-exports them).
"""

from __future__ import annotations

__all__ = ["IMAGE_FORMATS", "check_path", "check_output_path", "check_image", "short_repr"]


def short_repr(value) -> str:
    """``repr(value)``, shortened for an error message (:func:`reprlib.repr`); NumPy numbers and
    arrays of numbers as plain Python ones (``1e+300``, ``[nan]``, not ``array(1.e+300)``)."""
    import reprlib

    import numpy as np

    if isinstance(value, np.generic | np.ndarray) and np.asarray(value).dtype.kind in "fiub":
        arr = np.asarray(value)
        value = arr.item() if arr.ndim == 0 else arr.tolist()
    return reprlib.repr(value)


def check_path(value, name: str, *, directory: bool = False) -> str:
    """A file (or, with ``directory``, a directory) name: ``str`` or ``os.PathLike``, not empty.

    A file name that is an existing directory is a :class:`ValueError`, as is a directory
    name that is an existing file; another type is a :class:`TypeError`.  Returns the name
    as ``str``.
    """
    import os

    if isinstance(value, bytes) or not isinstance(value, str | os.PathLike):
        raise TypeError(f"{name} must be a file name (str or os.PathLike), got {type(value).__name__} "
                        f"{short_repr(value)}")
    text = os.fspath(value)
    if not isinstance(text, str):
        raise TypeError(f"{name} must be a file name (str or os.PathLike), got {type(value).__name__}")
    if text == "":
        raise ValueError(f"{name} must not be empty")
    if not directory and os.path.isdir(text):
        raise ValueError(f"{name} = {text!r} is a directory; give a file name")
    if directory and os.path.exists(text) and not os.path.isdir(text):
        raise ValueError(f"{name} = {text!r} is a file, not a directory")
    return text


def check_output_path(value, name: str, *, directory: bool = False) -> str:
    """A file (or directory) to be written: :func:`check_path`, and its parent directory exists.

    Refusing a missing directory here names the path the user gave (the temporary file of
    :func:`asperity._atomic.atomic_path` would otherwise appear in a FileNotFoundError).
    """
    import os

    text = check_path(value, name, directory=directory)
    parent = os.path.dirname(os.path.abspath(text))
    if not os.path.isdir(parent):
        what = "is a file, not a directory" if os.path.exists(parent) else "does not exist"
        raise ValueError(f"{name} = {text!r}: {os.path.dirname(text) or parent!r} {what}")
    return text


#: Image formats the plotting functions write (matplotlib's Agg, PDF, SVG and PS back ends).
IMAGE_FORMATS = ("png", "pdf", "svg", "svgz", "eps", "ps", "jpg", "jpeg", "tif", "tiff", "webp")


def check_image(path, fmt=None, name: str = "path") -> tuple[str, str]:
    """An image file name and its format: ``fmt`` (a string of :data:`IMAGE_FORMATS`) or the
    extension of ``path`` (png without one), as ``(path, fmt)``; errors name ``name`` or ``fmt``."""
    import os

    path = check_output_path(path, name)
    if fmt is None:
        fmt, what = os.path.splitext(path)[1][1:].lower() or "png", f"{name} (its extension)"
    elif isinstance(fmt, str):
        fmt, what = fmt.lower(), "fmt"
    else:
        raise TypeError(f"fmt must be an image format name (a string), got {type(fmt).__name__}")
    if fmt not in IMAGE_FORMATS:
        raise ValueError(f"{what}: {fmt!r} is not an image format; give one of {', '.join(IMAGE_FORMATS)}")
    return path, fmt
