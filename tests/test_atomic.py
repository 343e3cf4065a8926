"""``asperity._atomic``: a write either completes or leaves the target as it was."""

import os

import pytest

from asperity._atomic import atomic_path, atomic_write


def test_atomic_write_text_and_bytes(tmp_path):
    path = tmp_path / "a.txt"
    atomic_write(path, "h\u00e9\nx\r\n")
    assert path.read_bytes() == "h\u00e9\nx\r\n".encode()  # UTF-8, newlines untranslated
    atomic_write(str(path), b"\x00\x01")
    assert path.read_bytes() == b"\x00\x01" and os.listdir(tmp_path) == ["a.txt"]


def test_new_file_gets_the_usual_mode(tmp_path):
    umask = os.umask(0o022)
    try:
        atomic_write(tmp_path / "n", "x")
    finally:
        os.umask(umask)
    assert (tmp_path / "n").stat().st_mode & 0o777 == 0o644


@pytest.mark.parametrize("exc", [RuntimeError("boom"), KeyboardInterrupt()])
def test_failure_inside_keeps_the_old_file(tmp_path, exc):
    path = tmp_path / "f.csv"
    path.write_text("old")
    with pytest.raises(type(exc)):
        with atomic_path(path) as tmp:
            with open(tmp, "w") as fh:
                fh.write("new but unfin")
            raise exc
    assert path.read_text() == "old" and os.listdir(tmp_path) == ["f.csv"]


def test_failure_inside_creates_nothing(tmp_path):
    with pytest.raises(ValueError):
        with atomic_path(tmp_path / "new.png") as tmp:
            assert os.path.dirname(tmp) == str(tmp_path)  # same directory: the rename is atomic
            raise ValueError
    assert os.listdir(tmp_path) == []


def test_failing_rename_keeps_the_old_file(tmp_path, monkeypatch):
    path = tmp_path / "f"
    path.write_text("old")

    def no_replace(src, dst):
        raise OSError(5, "Input/output error")

    monkeypatch.setattr(os, "replace", no_replace)
    with pytest.raises(OSError):
        atomic_write(path, "new")
    monkeypatch.undo()
    assert path.read_text() == "old" and os.listdir(tmp_path) == ["f"]


def test_symlink_target_is_replaced_not_the_link(tmp_path):
    real = tmp_path / "real.txt"
    real.write_text("old")
    link = tmp_path / "link.txt"
    link.symlink_to(real)
    atomic_write(link, "new")
    assert link.is_symlink() and real.read_text() == "new"


def test_directory_and_missing_directory_are_errors(tmp_path):
    with pytest.raises(IsADirectoryError):
        atomic_write(tmp_path, "x")
    with pytest.raises(FileNotFoundError):
        atomic_write(tmp_path / "no" / "f", "x")
    assert os.listdir(tmp_path) == []


def test_device_is_written_in_place():
    atomic_write("/dev/null", "x")
    assert os.path.exists("/dev/null") and not os.path.isfile("/dev/null")


def test_wrong_data_type():
    with pytest.raises(TypeError, match="str or bytes"):
        atomic_write("/dev/null", 3)
