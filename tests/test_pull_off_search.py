"""The pull-off search (asperity.pull_off_search) against a brute-force scan of the force."""

import json
import math

import numpy as np
import pytest

from asperity.asperity_law import ModelParameters
from asperity.pull_off_search import PullOff, find_pull_off
from asperity.tabulation import Tabulation


@pytest.mark.parametrize("params", [(0.003, 1000.0, 1e-3), (0.01, 100.0, 1e-3), (0.3, 30.0, 0.0759)])
def test_minimum_of_a_dense_scan(params):
    tab = Tabulation(ModelParameters(*params), -3.0, 10.0)
    po = find_pull_off(tab, -3.0, 10.0)
    d = np.linspace(-3.0, 10.0, 130001)  # every 1e-4 sigma
    P = tab.sums(d)[0][:, 1]
    i = int(np.argmin(P))
    assert po.exists and po.force >= -P[i] and po.force == pytest.approx(-P[i], rel=1e-7)
    assert po.d == pytest.approx(d[i], abs=2e-4)
    slope = tab.sums([po.d], order=1)[1][0, 1]
    assert abs(slope) < 1e-6 * po.force  # a stationary point


def test_no_adhesion_no_pull_off():
    po = find_pull_off(Tabulation(ModelParameters(0.01, 1000.0), -3.0, 10.0), -3.0, 10.0)
    assert po == PullOff(0.0, po.d, False) and math.isnan(po.d)


def test_weak_adhesion_stays_compressive():
    # gamma = 1e-5: the adhesive tension is far out, beyond d = 1
    tab = Tabulation(ModelParameters(0.01, 1000.0, 1e-5), -3.0, 10.0)
    po = find_pull_off(tab, -3.0, 1.0)
    assert not po.exists and po.force == 0.0


def test_minimum_on_the_end_of_the_interval():
    # cut the interval before the minimum: the force still falls at d_hi, which is returned
    tab = Tabulation(ModelParameters(0.003, 1000.0, 1e-3), -3.0, 10.0)
    full = find_pull_off(tab, -3.0, 10.0)
    cut = find_pull_off(tab, -3.0, full.d - 0.3)
    assert cut.d == full.d - 0.3 and cut.force < full.force and cut.exists


def test_reuses_a_grid_and_checks_it():
    tab = Tabulation(ModelParameters(0.003, 1000.0, 1e-3), -3.0, 10.0)
    grid = np.linspace(-3.0, 10.0, 261)
    P = tab.sums(grid)[0][:, 1]
    assert find_pull_off(tab, -3.0, 10.0, grid, P).force == pytest.approx(find_pull_off(tab, -3.0, 10.0).force,
                                                                          rel=1e-13)
    with pytest.raises(ValueError, match="both"):
        find_pull_off(tab, -3.0, 10.0, grid=grid)
    with pytest.raises(ValueError, match="serves"):
        find_pull_off(tab, -3.0, 20.0)


def test_to_dict_is_strict_json_and_as_dict_is_its_alias():
    po = PullOff(0.0, math.nan, False)
    assert po.to_dict() == {"pull_off": 0.0, "d": None, "exists": False}
    json.dumps(po.to_dict(), allow_nan=False)
    real = PullOff(12.5, 0.7, True)
    assert real.as_dict() == real.to_dict() == {"pull_off": 12.5, "d": 0.7, "exists": True}
    assert PullOff.as_dict is PullOff.to_dict
