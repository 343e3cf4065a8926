"""The plotting functions name a bad argument before drawing (found by tests/test_fuzz_api.py)."""

import pytest

from asperity._validation import IMAGE_FORMATS, check_image


def test_check_image_takes_the_format_from_fmt_or_the_extension(tmp_path):
    assert check_image(tmp_path / "a.PDF") == (str(tmp_path / "a.PDF"), "pdf")
    assert check_image(tmp_path / "a", "SVG") == (str(tmp_path / "a"), "svg")
    assert check_image(tmp_path / "a")[1] == "png" and "png" in IMAGE_FORMATS
    for path, fmt, error, needle in ((tmp_path / "a.txt", None, ValueError, r"^path \(its extension\): 'txt'"),
                                     (tmp_path / "a.png", "abc", ValueError, "^fmt: 'abc' is not an image format"),
                                     (tmp_path / "a.png", True, TypeError, "^fmt must be"),
                                     (None, None, TypeError, "^path"), (tmp_path, None, ValueError, "directory")):
        with pytest.raises(error, match=needle):
            check_image(path, fmt)


def test_plot_functions_refuse_bad_arguments(tmp_path):
    pytest.importorskip("matplotlib")
    import asperity
    from asperity.cycle_plot import plot_cycle
    from asperity.fit.plot import plot_fit
    from asperity.validation.plot import plot_validation

    with pytest.raises(TypeError, match="^result must be an asperity.fit FitResult"):
        plot_fit(None, tmp_path / "f.png")
    with pytest.raises(TypeError, match="^result must be a SurfaceValidation"):
        plot_validation(None, tmp_path / "v.png")
    c = asperity.cycle(0.02, 50.0, 0.02, preload=10.0, n=20)
    with pytest.raises(TypeError, match="^ax must be matplotlib Axes"):
        plot_cycle(c, ax=True)
    with pytest.raises(TypeError, match="^result must be a CycleResult"):
        plot_cycle(None)
    assert not list(tmp_path.iterdir())  # nothing written
