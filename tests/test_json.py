"""``asperity._json``: strict JSON, NaN and infinity as null."""

import json
import math

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from asperity._json import dumps, json_safe


def _strict(text):
    def reject(name):
        raise ValueError(name)

    return json.loads(text, parse_constant=reject)


def test_non_finite_become_null_everywhere():
    value = {"a": float("nan"), "b": [np.inf, -np.inf, 1.5], "c": (np.float32(2.5), np.int64(3), np.bool_(True)),
             "d": np.array([[1.0, np.nan]]), "e": np.float64("nan"), "f": None, "g": "NaN"}
    assert _strict(dumps(value)) == {"a": None, "b": [None, None, 1.5], "c": [2.5, 3, True],
                                     "d": [[1.0, None]], "e": None, "f": None, "g": "NaN"}


def test_zero_d_array_and_indent():
    assert json_safe(np.array(np.inf)) is None and json_safe(np.array(2.0)) == 2.0
    assert dumps([1.0], indent=1) == "[\n 1.0\n]"


@given(st.recursive(st.floats() | st.integers() | st.booleans() | st.none() | st.text(max_size=5),
                    lambda inner: st.lists(inner, max_size=4) | st.dictionaries(st.text(max_size=3), inner,
                                                                              max_size=4), max_leaves=20))
def test_any_value_gives_strict_json_with_finite_numbers_kept(value):
    back = _strict(dumps(value))

    def same(a, b):
        if isinstance(a, float) and not math.isfinite(a):
            return b is None
        if isinstance(a, dict):
            return a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
        if isinstance(a, list):
            return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
        return a == b and type(a) is type(b)

    assert same(value, back)
