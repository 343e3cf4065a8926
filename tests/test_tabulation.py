"""The tabulation of the per-asperity law (asperity.tabulation): growing, checking, plugging in a law."""

import numpy as np
import pytest

from asperity.asperity_law import AsperityLaw, ModelParameters
from asperity.heights import GAUSSIAN, Exponential, Mixture
from asperity.tabulation import Tabulation, check_separation, check_tabulation

P = ModelParameters(0.01, 1000.0, 1e-3)


def test_extended_reuses_or_grows_over_the_union():
    tab = Tabulation(P, -3.0, 10.0)
    assert tab.extended(-1.0, 5.0) is tab
    wide = tab.extended(-6.0, 4.0)
    assert (wide.d_min, wide.d_max) == (-6.0, 10.0) and wide.law is tab.law and wide.heights is tab.heights
    fresh = Tabulation(P, -6.0, 10.0)  # the same nodes as building it at once
    d = np.array([-5.0, 0.0, 9.0])
    np.testing.assert_array_equal(wide.sums(d)[0], fresh.sums(d)[0])


def test_check_tabulation():
    tab = Tabulation(P, -3.0, 10.0)
    assert check_tabulation(tab, -3, 10) == (-3.0, 10.0)
    assert check_tabulation(tab, -30.0, 10.0, covered=False) == (-30.0, 10.0)
    with pytest.raises(ValueError, match=r"d_lo, d_hi = -30, 10 lie outside the separations the tabulation serves"):
        check_tabulation(tab, -30.0, 10.0)
    with pytest.raises(ValueError, match="must be <"):
        check_tabulation(tab, 2.0, 2.0)
    with pytest.raises(ValueError, match="tab must be"):
        check_tabulation(None, 0.0, 1.0)
    with pytest.raises(ValueError, match="d_lo"):
        check_tabulation(tab, [0.0, 1.0], 2.0)


def test_law_and_heights_are_checked():
    with pytest.raises(ValueError, match="ContactLaw"):
        Tabulation(P, 0.0, 1.0, law=object())
    with pytest.raises(ValueError, match="built for"):
        Tabulation(P, 0.0, 1.0, law=AsperityLaw(ModelParameters(0.01, 1000.0)))
    with pytest.raises(ValueError, match="heights"):
        Tabulation(P, 0.0, 1.0, heights=object())
    assert Tabulation(P, 0.0, 1.0, heights="gaussian").heights == GAUSSIAN  # a spec string
    assert Tabulation(P, 0.0, 1.0, GAUSSIAN, law=AsperityLaw(P)).law.params == P


def test_check_separation_range():
    np.testing.assert_array_equal(check_separation([-1e4, 30.0]), [-1e4, 30.0])
    with pytest.raises(ValueError, match=r"d \(separation d/sigma\) must lie in"):
        check_separation([30.5])


@pytest.mark.parametrize("heights", [GAUSSIAN, Mixture(), Exponential()], ids=repr)
@pytest.mark.parametrize("bad", [[-8.0], [2.0, 50.0], [np.nan], [np.inf]])
def test_separations_outside_the_nodes_are_refused(heights, bad):
    """A review: beyond its range a Gaussian tabulation gave 867011 for 867062 at d = -8 and 0
    at d = -50 (its nodes end), and 0 at NaN; the exponential one already refused."""
    tab = Tabulation(ModelParameters(0.01, 1000.0), -2.0, 4.0, heights)
    with pytest.raises(ValueError, match="^d|outside the range"):
        tab.evaluate(bad)
    with pytest.raises(ValueError, match="^d|outside the range"):
        tab.sums(bad, order=1)


def test_order_is_checked():
    tab = Tabulation(ModelParameters(0.01, 1000.0), -2.0, 4.0)
    for bad in (3, -1, 1.5, True, "1"):
        with pytest.raises(ValueError, match="^order must be 0, 1 or 2"):
            tab.sums([0.0], order=bad)
    assert tab.evaluate(np.empty((0, 3)))["P"].shape == (0, 3)
