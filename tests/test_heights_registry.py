"""The registry of height distributions and the command-line spelling (asperity.heights.registry)."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from asperity.heights import (
    DISTRIBUTIONS,
    GAUSSIAN,
    SPELLINGS,
    Empirical,
    Exponential,
    Johnson,
    Mixture,
    PearsonIII,
    Weibull,
    distribution,
    parse_heights,
    write_samples,
)


def test_every_family_is_registered_once():
    assert list(DISTRIBUTIONS) == ["gaussian", "exponential", "weibull", "pearson3", "johnson", "mixture",
                                   "empirical"]
    for name, cls in DISTRIBUTIONS.items():
        assert cls.name == name
    assert set(SPELLINGS) == {*DISTRIBUTIONS, "best"}


@pytest.mark.parametrize("spec, expected", [
    ("gaussian", GAUSSIAN),
    ("  Gaussian ", GAUSSIAN),
    ("exponential", Exponential()),
    ("weibull:skew=0.5", Weibull(0.5)),
    ("WEIBULL: skew = -0.3 ", Weibull(-0.3)),
    ("pearson3:skew=-0.3", PearsonIII(-0.3)),
    ("johnson:skew=0.5,kurt=4", Johnson(0.5, 4.0)),
    ("johnson:kurt=4,skew=0.5", Johnson(0.5, 4.0)),
    ("mixture:w=0.8,m1=0.5,s1=0.5,m2=-2,s2=1.2", Mixture(0.8, 0.5, 0.5, -2.0, 1.2)),
])
def test_spellings(spec, expected):
    assert parse_heights(spec) == expected
    assert parse_heights(expected) is expected  # a distribution passes through


@settings(max_examples=20, deadline=None)
@given(st.sampled_from(["weibull", "pearson3"]), st.floats(-0.99, 1.99).filter(lambda s: s == 0 or abs(s) >= 1e-3))
def test_spec_round_trip(name, skew):
    dist = distribution(name, skew=skew)
    assert parse_heights(dist.spec) == dist  # repr of a float round-trips exactly


def test_mixture_spec_round_trip():
    m = Mixture(w=0.7, m1=3.0, s1=0.4, m2=-1.0, s2=2.0)  # given in any unit: standardised
    assert parse_heights(m.spec) == m


def test_empirical_and_best_read_a_file(tmp_path):
    z = np.random.default_rng(4).weibull(1.6, 1500) * 3e-9  # metres
    path = tmp_path / "summits.txt"
    write_samples(path, z, header="z_m")
    emp = parse_heights(f"empirical:{path}")
    assert emp == Empirical.from_samples(z) and emp.spec == f"empirical:{path}"
    assert emp.source == str(path) and "summits.txt" in repr(emp)
    best = parse_heights(f"best:{path}")
    assert best.name in ("weibull", "pearson3", "johnson", "mixture")


@pytest.mark.parametrize("spec, needle", [
    ("", "empty distribution name in ''; valid: gaussian, exponential, weibull:skew=SKEW"),
    ("lognormal", "unknown distribution 'lognormal'; valid: gaussian"),
    ("weibull", "missing parameter(s) skew"),
    ("weibull:", "weibull needs its parameters: weibull:skew=SKEW"),
    ("gaussian:", "nothing after ':' in 'gaussian:'; gaussian has no parameters (spelling gaussian)"),
    ("exponential: ", "nothing after ':' in 'exponential: '; exponential has no parameters"),
    ("weibull:skew", "expected key=value"),
    ("weibull:skew=", "expected key=value"),
    ("weibull:skew=abc", "skew must be a number, got 'abc'"),
    ("weibull:skew=0.5,skew=0.4", "skew given twice"),
    ("weibull:kurt=3", "unknown parameter(s) kurt; its parameters: skew"),
    ("weibull:skew=5", "Weibull skewness"),
    ("weibull:skew=nan", "finite"),
    ("gaussian:skew=0", "unknown parameter(s) skew; its parameters: none"),
    ("johnson:skew=0.5", "missing parameter(s) kurt"),
    ("empirical", "needs a file of summit heights: empirical:FILE"),
    ("best:", "needs a file of summit heights: best:FILE"),
    ("empirical:/no/such/file.txt", "/no/such/file.txt: cannot read summit heights"),
])
def test_bad_spellings_name_the_valid_ones(spec, needle):
    with pytest.raises(ValueError) as err:
        parse_heights(spec)
    assert needle in str(err.value), str(err.value)


@pytest.mark.parametrize("bad", [None, 1.5, ["weibull"], b"weibull"])
def test_not_a_spelling(bad):
    with pytest.raises(ValueError, match="heights must be a spelling"):
        parse_heights(bad)


def test_distribution_by_name():
    assert distribution("Pearson3", skew=0.2) == PearsonIII(0.2)
    with pytest.raises(ValueError, match="unknown height distribution 'x'; valid: gaussian, exponential"):
        distribution("x")
    with pytest.raises(ValueError, match="empirical takes exactly one parameter, file"):
        distribution("empirical", skew=1.0)
    with pytest.raises(ValueError, match="name must be a string"):
        distribution(3)


def test_model_functions_take_any_distribution_and_refuse_others():
    import asperity
    from asperity.physical import PhysicalContact, Surface

    w = Weibull(0.4)
    c = asperity.load_curve([1.0, 10.0], 0.01, 1000.0, 1e-3, heights=w)
    assert c.parameters["heights"] == "weibull:skew=0.4"
    assert asperity.Model(0.01, 1000.0, heights=w).heights is w
    for call in (lambda: asperity.load_curve([1.0], 0.01, 1000.0, heights=3.0),
                 lambda: asperity.pull_off(0.01, 1000.0, 1e-3, heights=None),
                 lambda: asperity.contact_fraction(0.0, 0.01, 1000.0, heights=object()),
                 lambda: PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6), heights=["gaussian"])):
        with pytest.raises(ValueError, match="heights must be a HeightDistribution"):
            call()
    # a spec string is read as the command line reads it (test_every_curve_function_takes_a_spec_string)
    with pytest.raises(ValueError, match="unknown distribution"):
        PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6), heights="gauss")


def test_review_findings_on_specs_and_sample_files(tmp_path):
    """Found by a review: a mixture's deviation 0 was refused against '[0, 1e+06]', and a
    first line of numbers ('1,2') in a summit file was silently dropped as a header."""
    from asperity.heights import parse_heights
    from asperity.heights.samples import read_samples

    for s1 in ("-1", "0", "2e6", "nan"):
        with pytest.raises(ValueError, match=r"s1 \(component deviation\) must lie in \(0, 1e\+06\]"):
            parse_heights(f"mixture:w=0.5,m1=0,s1={s1},m2=1,s2=1")
    path = tmp_path / "z.txt"
    path.write_text("1,2\n" + "".join(f"{x}\n" for x in range(30)))
    with pytest.raises(ValueError, match="line 1: expected one number per line, got '1,2'"):
        read_samples(path)
    path.write_text("height [nm]\n" + "".join(f"{x}\n" for x in range(30)))
    assert read_samples(path).size == 30


def test_spelling_of_parameters_as_of_names():
    # A helper's trial: family names were case-insensitive, their keys not ('SKEW' refused), and
    # Python's float() let '1_0' (ten) and other scripts' digits through.
    from asperity.heights import Weibull, parse_heights

    assert parse_heights("Weibull:SKEW=0.5") == parse_heights("weibull:skew=0.5") == Weibull(skew=0.5)
    for bad in ("weibull:skew=1_0", "weibull:skew=\u0660.\u0665", "weibull:skew=0x1"):
        with pytest.raises(ValueError, match="skew must be a number"):
            parse_heights(bad)


def test_johnson_kurtosis_range_names_the_skewness_bound():
    from asperity.heights import Johnson

    with pytest.raises(ValueError, match=r"1 \+ skew\^2"):
        Johnson(skew=0.5, kurt=31.0)


def test_an_underflowing_parameter_says_so():
    from asperity.heights import parse_heights

    with pytest.raises(ValueError, match="smallest double"):
        parse_heights("weibull:skew=1e-400")


def test_every_curve_function_takes_a_spec_string():
    # A newcomer's trial: docs/heights.md says every curve function takes heights=, and
    # heights="exponential" was refused.
    import numpy as np

    import asperity
    from asperity.heights import parse_heights
    from asperity.physical import PhysicalContact, Surface

    spec = "weibull:skew=0.5"
    obj = parse_heights(spec)
    np.testing.assert_array_equal(asperity.load_curve([1.0, 10.0], 0.01, 1000, heights=spec).d,
                                  asperity.load_curve([1.0, 10.0], 0.01, 1000, heights=obj).d)
    assert asperity.pull_off(0.003, 1000, 1e-3, heights=spec) == asperity.pull_off(0.003, 1000, 1e-3, heights=obj)
    assert asperity.Model(0.01, 1000, heights=spec).heights == obj
    assert PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6), heights=spec).heights == obj
    assert asperity.cycle(0.02, 50, 0.02, preload=10.0, n=20, heights=spec).energy == \
        asperity.cycle(0.02, 50, 0.02, preload=10.0, n=20, heights=obj).energy
    with pytest.raises(ValueError, match="unknown distribution"):
        asperity.load_curve([1.0], 0.01, 1000, heights="weibul")
