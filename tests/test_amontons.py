"""Amontons' law with an adhesion offset (asperity.amontons)."""

import numpy as np
import pytest

from asperity.amontons import amontons_friction


def test_linear_with_offset():
    P = np.array([-1.0, 0.0, 2.0, 10.0])
    np.testing.assert_array_equal(amontons_friction(P, mu0=0.25, P0=1.0), [0.0, 0.25, 0.75, 2.75])
    np.testing.assert_array_equal(amontons_friction(P[1:], mu0=[0.1, 0.2, 0.3], P0=0.0), [0.0, 0.4, 3.0])


@pytest.mark.parametrize("kwargs, match", [({"mu0": -0.1, "P0": 0.0}, "^mu0 must be >= 0"),
                                           ({"mu0": 0.1, "P0": None}, "^P0 must be a real"),
                                           ({"mu0": 0.1, "P0": 0.5}, "friction force would be negative"),
                                           ({"mu0": [0.1, 0.2], "P0": [1.0, 2.0, 3.0]},
                                            "^P, mu0, P0 must have shapes that broadcast together")])
def test_bad_input(kwargs, match):
    with pytest.raises(ValueError, match=match):
        amontons_friction([-1.0], **kwargs)
