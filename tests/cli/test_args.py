"""``asperity.cli._args``: lists, quantities, the shared groups and what they build."""

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from asperity.cli import parse_list
from asperity.cli._args import MAX_POINTS, UsageError, join_negative_lists, quantity_list

from .helpers import AU, MODEL, one_line_error, run


def test_parse_list():
    np.testing.assert_allclose(parse_list("0,0.5,1", log=False, name="x"), [0, 0.5, 1])
    np.testing.assert_allclose(parse_list("1:100:3", log=True, name="x"), [1, 10, 100])
    np.testing.assert_allclose(parse_list("0:1:3", log=False, name="x"), [0, 0.5, 1])


def test_parse_list_ranges_are_numpy_spacings():
    assert np.array_equal(parse_list("1e-3:1e4:37", log=True, name="x"), np.geomspace(1e-3, 1e4, 37))
    assert np.array_equal(parse_list("-1:4:50", log=False, name="x"), np.linspace(-1, 4, 50))
    assert np.array_equal(parse_list(" 2 , -3.5 ", log=False, name="x"), [2.0, -3.5])  # spaces around items


FINITE = st.floats(allow_nan=False, allow_infinity=False)


@given(st.lists(FINITE, min_size=1, max_size=40))
def test_parse_list_round_trips_finite_floats(values):
    got = parse_list(",".join(repr(v) for v in values), log=False, name="--x")
    assert [repr(float(v)) for v in got] == [repr(float(v)) for v in values]


@given(st.lists(FINITE, max_size=10), st.integers(min_value=0), st.sampled_from(["", " ", "\t"]))
def test_parse_list_rejects_any_empty_item(values, where, blank):
    items = [repr(v) for v in values]
    items.insert(where % (len(items) + 1), blank)
    with pytest.raises(UsageError, match="--x: empty item"):
        parse_list(",".join(items), log=False, name="--x")


@pytest.mark.parametrize("text, needle", [
    ("0,,1", "empty item"), ("1,", "empty item"), (",1", "empty item"), ("", "empty item"), (",", "empty item"),
    ("1:2:3:4", "three fields"), ("1:2", "three fields"), (":", "three fields"), ("1::3:", "three fields"),
    ("1:2:2.5", "positive integer"), ("1:2:0", "positive integer"), ("1:2:-3", "positive integer"),
    ("1:2:", "positive integer"), ("1:2:x", "positive integer"), ("1:2:1e3", "positive integer"),
    ("1,inf", "finite"), ("nan", "finite"), ("1e400", "finite"), ("-inf:1:3", "finite"), ("0:nan:3", "finite"),
    ("a,b", "expected numbers"), ("1:b:3", "expected numbers"), ("1;2", "expected numbers"),
])
def test_malformed_lists_are_errors(text, needle):
    with pytest.raises(UsageError) as exc:
        parse_list(text, log=False, name="--x")
    assert str(exc.value).startswith("--x: ") and needle in str(exc.value)


def test_log_range_needs_positive_ends():
    with pytest.raises(UsageError, match="start, stop > 0"):
        parse_list("0:1:5", log=True, name="--P")


@pytest.mark.parametrize("text", [
    f"0:1:{MAX_POINTS + 1}",
    "1:2:" + "9" * 30,  # would need more memory than any machine has: must fail before allocating
    ",".join(["1"] * (MAX_POINTS + 1)),
])
def test_list_sizes_are_bounded(text):
    with pytest.raises(UsageError) as exc:
        parse_list(text, log=True, name="--P")
    assert str(exc.value).startswith("--P: ") and str(MAX_POINTS) in str(exc.value)
    assert len(str(exc.value)) < 200  # the list itself is not echoed in full


def test_list_of_max_points_is_allowed():
    assert parse_list(f"1:2:{MAX_POINTS}", log=False, name="--d").size == MAX_POINTS


def test_linear_range_beyond_float_step():
    # stop - start overflows, the points do not: no warning, no error, exact ends.
    got = parse_list("-1.5e308:1.5e308:3", log=False, name="--d")
    assert got.tolist() == [-1.5e308, 0.0, 1.5e308]


@pytest.mark.parametrize("text, needle", [
    ("1mN,,2mN", "empty item"), ("1mN:1N", "three fields"), ("1mN:1N:2.5", "positive integer"),
    (f"1mN:1N:{MAX_POINTS + 1}", str(MAX_POINTS)), ("1mN:1N:0", "positive integer"),
])
def test_malformed_quantity_lists_are_errors(text, needle):
    pytest.importorskip("pint")
    with pytest.raises(UsageError) as exc:
        quantity_list(text, "N", log=True, name="--load")
    assert str(exc.value).startswith("--load: ") and needle in str(exc.value)


def test_quantity_list_converts_units():
    pytest.importorskip("pint")
    np.testing.assert_allclose(quantity_list("1mN,2N,30uN", "N", log=True, name="--load"), [1e-3, 2, 3e-5],
                               rtol=1e-15)
    np.testing.assert_allclose(quantity_list("1mN:1N:4", "N", log=True, name="--load"), np.geomspace(1e-3, 1, 4),
                               rtol=1e-15)
    np.testing.assert_allclose(quantity_list("-2nm:2nm:5", "m", log=False, name="--separation"),
                               np.linspace(-2e-9, 2e-9, 5), rtol=1e-15, atol=1e-30)


@pytest.mark.parametrize("argv", [
    ["load", *MODEL, "--P", "1,,2"],
    ["load", *MODEL, "--P", f"1:2:{MAX_POINTS + 1}"],
    ["separation", *MODEL, "--d", "0,"],
    ["separation", *MODEL, "--d", "0:1"],
    ["md", "--lam", "1", "--delta", "0,,1"],
    ["md", "--lam", "1", "--delta", "0:1:2.5"],
    ["load", *AU, "--load", "1mN,"],
    ["separation", *AU, "--separation", f"0nm:1nm:{10 * MAX_POINTS}"],
])
def test_malformed_lists_on_the_command_line(capsys, argv):
    option = next(a for a in argv if a in ("--P", "--d", "--delta", "--load", "--separation"))
    code, out, err = run(capsys, *argv)
    assert one_line_error(code, err, option) and out == ""


def test_join_negative_lists():
    assert join_negative_lists(["--d", "-1,0", "--x", "-.5", "-o", "-1"]) == ["--d=-1,0", "--x=-.5", "-o", "-1"]
    assert join_negative_lists(["--d=-1", "--nu", "-0.2"]) == ["--d=-1", "--nu=-0.2"]
    assert join_negative_lists(["--plot", "-x.png"]) == ["--plot", "-x.png"]
    assert join_negative_lists(["--w", "-inf", "--E", "-NaN", "--h", "-Infinity"]) == [
        "--w=-inf", "--E=-NaN", "--h=-Infinity"]
    assert join_negative_lists(["--plot", "-info.png"]) == ["--plot=-info.png"]  # a value either way


def test_a_negative_infinity_is_refused_by_its_option(capsys):
    """``--profile-budget -inf`` reaches the option's own check (one line naming it), not
    argparse's 'expected one argument'."""
    from asperity.cli import main

    assert main(["load", "--P", "1", "--alpha", "0.1", "--beta", "1000", "--gamma", "-inf"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "gamma" in err and "expected one argument" not in err


@pytest.mark.parametrize("argv, needle", [
    (["load", *AU, "--load", "1"], "--load"),                  # missing unit
    (["load", *AU, "--load", "1m"], "--load"),                 # wrong dimension
    (["load", *AU[:2], "--load", "1mN"], "--sigma"),           # incomplete surface
    (["load", *AU, "--P", "1"], "--load"),                     # dimensionless list with material
    (["load", *AU, "--alpha", "0.1", "--load", "1mN"], "not both"),
    (["load", "--material", "Unobtainium", *AU[2:], "--load", "1mN"], "Unobtainium"),
    (["separation", *AU[:2], "--sigma", "-2nm", *AU[4:], "--separation", "0nm"], "sigma"),
    (["load", "--beta", "10", "--P", "1"], "--alpha"),
    (["pulloff", "--alpha", "0.01", "--beta", "10"], "--gamma"),
])
def test_physical_errors(capsys, argv, needle):
    code, _, err = run(capsys, *argv)
    assert code == 2 and err.count("\n") == 1 and needle in err, err


def test_negative_quantity_is_a_value_not_an_option(capsys):
    argv = ["separation", *AU[:2], "--sigma", "-2nm", *AU[4:], "--separation", "0nm"]
    code, _, err = run(capsys, *argv)
    assert code == 2 and "sigma_s must be > 0" in err


def test_contact_from_args_is_the_library_contact():
    pytest.importorskip("pint")
    from asperity.cli import build_parser
    from asperity.cli._build import contact_from_args, is_physical
    from asperity.physical import PhysicalContact, Surface

    args = build_parser().parse_args(["load", *AU, "--no-adhesion", "--load", "1mN"])
    assert is_physical(args)
    got = contact_from_args(args)
    ref = PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6), adhesion=False)
    assert got.parameters() == ref.parameters()


@pytest.mark.parametrize("argv, needle", [
    (["load", *MODEL, "--P", "1", "-o", ""], "-o/--output"),
    (["load", *MODEL, "--P", "1", "--output", ""], "-o/--output"),
    (["load", *MODEL, "--P", "1", "--plot", ""], "--plot"),
    (["separation", *MODEL, "--d", "1", "--plot", "{tmp}"], "--plot"),
    (["load", *MODEL, "--P", "1", "-o", "{tmp}"], "directory"),
    (["materials", "-o", ""], "-o/--output"),
    (["md", "--lam", "1", "--pulloff", "-o", "{tmp}"], "directory"),
    (["pulloff", *MODEL, "-o", ""], "-o/--output"),
    (["surface", "x.x3p", "-o", ""], "-o/--output"),
    (["reproduce", "--out", ""], "--out"),
])
def test_output_paths_are_checked(capsys, tmp_path, argv, needle):
    code, out, err = run(capsys, *(a.replace("{tmp}", str(tmp_path)) for a in argv))
    assert one_line_error(code, err, needle) and out == ""
    assert list(tmp_path.iterdir()) == []


def test_non_finite_list_items_are_named_by_option_and_text(capsys):
    """Found by a review: ``--load 'nan N'`` said 'P must be finite ..., got array([nan])' and
    ``--load nan`` suggested the refused spelling 'nan N'."""
    from asperity.cli import main

    contact = ["--material", "Au", "--sigma-s", "2nm", "--R", "1um", "--eta", "1e12/m^2", "--area", "1mm^2"]
    for value, needle in (("nan N", "--load: 'nan N' is not a finite quantity"),
                          ("1e400N", "--load: '1e400N' is not a finite quantity"),
                          ("1mN:inf N:3", "--load: 'inf N' is not a finite quantity"),
                          ("nan", "(e.g. '1 N'), got the bare number 'nan'")):
        assert main(["load", *contact, "--load", value]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and needle in err, err


def test_options_that_would_be_ignored_are_refused(capsys):
    """Found by a review: ``--no-adhesion --w 1J/m^2`` and ``--law jackson-green
    --plastic-threshold 0.5`` ran without a word, the option ignored."""
    from asperity.cli import main

    contact = ["--material", "Au", "--sigma-s", "2nm", "--R", "1um", "--eta", "1e12/m^2", "--area", "1mm^2",
               "--load", "1mN"]
    for extra, needle in ((["--no-adhesion", "--w", "1J/m^2"], "--w describe the adhesion, which --no-adhesion"),
                          (["--no-adhesion", "--sigma0", "1GPa", "--h", "1nm"], "--h, --sigma0 describe the adhesion"),
                          (["--no-adhesion", "--law", "jackson-green", "--plastic-threshold", "0.5"],
                           "--plastic-threshold applies to the elastic law")):
        assert main(["load", *contact, *extra]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and needle in err, err
    assert main(["load", *contact, "--no-adhesion", "--plastic-threshold", "0.5", "--format", "csv"]) == 0


def test_the_elastic_law_in_any_case_takes_the_plastic_threshold(capsys):
    """A review: '--law Elastic --plastic-threshold' was refused as if plastic."""
    from asperity.cli import main

    contact = ["--material", "Au", "--sigma-s", "2nm", "--R", "1um", "--eta", "1e12/m^2", "--area", "1mm^2",
               "--load", "1mN", "--format", "csv"]
    assert main(["load", *contact, "--law", "Elastic", "--plastic-threshold", "0.5"]) == 0
    capsys.readouterr()


@pytest.mark.parametrize("text", ["1:10:1", "1uN:10uN:1"])
def test_a_range_of_one_point_that_would_drop_its_stop_is_refused(text):
    """A review: --load 1uN:10uN:1 computed 1 uN alone, the stop silently ignored."""
    with pytest.raises(UsageError, match="a range of one point would drop its stop"):
        parse_list(text, log=True, name="--P") if "u" not in text else quantity_list(text, "N", log=True, name="--load")
    assert list(parse_list("5:5:1", log=True, name="--P")) == [5.0]
    assert list(parse_list("1:1.0:1", log=True, name="--P")) == [1.0]  # the same value, written twice
    assert list(quantity_list("1uN:1 uN:1", "N", log=True, name="--load")) == [1e-6]


@pytest.mark.parametrize("value", ["1_0", "\u0661\u0660", "2.0", ""])
def test_integer_options_take_ascii_integers(value):
    from asperity.cli._args import integer

    with pytest.raises(ValueError):
        integer(value)
    assert integer(" 12 ") == 12 and integer.__name__ == "int"


@pytest.mark.parametrize("count", ["1_0", "\u0661\u0660", "2.0", "-3"])
def test_a_range_count_is_an_ascii_integer(count):
    with pytest.raises(UsageError, match="count in start:stop:count must be a positive integer"):
        parse_list(f"1:10:{count}", log=True, name="--P")


@pytest.mark.parametrize("command, argv, required", [
    ("cycle", ["--alpha", "0.02", "--beta", "50", "--dmin", "-1"], True),
    ("pulloff", ["--alpha", "0.02", "--beta", "50"], True),
    ("load", ["--alpha", "0.02", "--beta", "50", "--P", "1"], False),
    ("separation", ["--alpha", "0.02", "--beta", "50", "--d", "1"], False),
])
def test_gamma_help_says_what_the_command_does_without_it(capsys, command, argv, required):
    # A helper's trial: cycle and pulloff said "default 0" and then refused to run without --gamma.
    from asperity.cli import main

    with pytest.raises(SystemExit):
        main([command, "--help"])
    text = " ".join(capsys.readouterr().out.split())
    start = text.index("--gamma GAMMA ")  # the option list, after the usage line
    line = text[start:text.index("--nu NU", start)]
    code = main([command, *argv])
    err = capsys.readouterr().err
    if required:
        assert "required here" in line and "default 0" not in line
        assert code == 2 and "--gamma" in err
    else:
        assert "default 0" in line and code == 0, err
