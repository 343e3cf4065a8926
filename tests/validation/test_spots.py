"""Contact spots: edge-connected regions, joined across periodic edges."""

import numpy as np
import pytest

from asperity.validation.spots import count_spots, label_spots


def test_edges_and_corners():
    m = np.zeros((8, 8), bool)
    m[2:4, 2:4] = True          # one 2x2 spot
    m[5, 5] = m[6, 6] = True    # touching at a corner only: two spots
    assert count_spots(m, periodic=False) == 3
    assert count_spots(np.zeros((4, 4), bool), periodic=True) == 0
    assert count_spots(np.ones((4, 4), bool), periodic=True) == 1


def test_periodic_wrap_joins_spots():
    m = np.zeros((6, 7), bool)
    m[0, 3] = m[-1, 3] = True   # across the x edges
    m[2, 0] = m[2, -1] = True   # across the y edges
    m[0, 0] = m[-1, -1] = True  # diagonal across the corner: not edge-connected
    assert count_spots(m, periodic=False) == 6
    labels, n = label_spots(m, periodic=True)
    assert n == 4
    assert labels[0, 3] == labels[-1, 3] and labels[2, 0] == labels[2, -1]
    assert set(np.unique(labels)) == set(range(n + 1))


def test_chain_of_wraps_is_one_spot():
    m = np.zeros((5, 5), bool)
    m[:, 0] = True              # a column touching both y edges through m[:, -1]
    m[:, -1] = True
    m[0, 2] = m[-1, 2] = True   # separate short spot wrapping in x
    assert count_spots(m, periodic=True) == 2


@pytest.mark.parametrize("bad, error", [(np.zeros(4, bool), ValueError), (np.zeros((3, 3)), TypeError),
                                        (True, TypeError), (None, TypeError)])
def test_bad_masks(bad, error):
    with pytest.raises(error):
        count_spots(bad, periodic=True)
