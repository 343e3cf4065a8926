"""asperity.icha: summits, the interacting and coalescing Hertzian asperity model, its limits.

Expected values come from the slow path (asperity.reference.hertz_sum: loops and bisection),
closed forms (Hertz, the equivalent spot of a merge) and symmetries (a tiled periodic map)."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from asperity.icha import MapSummits, icha_contact, icha_curve, map_summits, merge_spots
from asperity.reference import hertz_sum as ref

E = 1e11


def rough_map(n=40, seed=0, periodic=True):
    """A smooth random periodic map: Gaussian-filtered noise, heights in nm over a 2 um square."""
    rng = np.random.default_rng(seed)
    q = np.fft.fftfreq(n)
    spec = np.fft.fft2(rng.standard_normal((n, n))) * np.exp(-(q[:, None] ** 2 + q[None, :] ** 2) * 120)
    h = np.real(np.fft.ifft2(spec))
    return h / h.std() * 5e-9, (2e-6 / n, 2e-6 / n)


def test_a_plateau_across_the_periodic_seam_is_one_summit():
    h = np.zeros((8, 8))
    h[0, 3] = h[7, 3] = 1.0
    assert len(map_summits(h, (1.0, 1.0), periodic=True)) == 1
    h[3, 3] = 1.0
    h2 = np.zeros((8, 8))
    h2[0, 0] = h2[7, 7] = h2[3, 3] = 1.0  # across the corner, diagonally
    assert len(map_summits(h, (1.0, 1.0), periodic=True)) == len(map_summits(h2, (1.0, 1.0), periodic=True)) == 2


def caps_of(s):
    return [(float(x), float(y), float(z), float(R)) for x, y, z, R in zip(s.x, s.y, s.z, s.R, strict=True)]


@pytest.mark.parametrize("periodic", [True, False])
@pytest.mark.parametrize("radius", ["geometric", "mean"])
@pytest.mark.parametrize("step", [0.0, 2e-9], ids=["float", "quantized"])
def test_summits_equal_slow_path(periodic, radius, step):
    # quantized: plateaus and shoulders (a review: the slow path and the library counted an
    # L-shaped plateau twice and every shoulder; a periodic map lost plateaus across its seam)
    h, (dx, dy) = rough_map(seed=3)
    h = np.round(h / step) * step if step else h
    s = map_summits(h, (dx, dy), periodic=periodic, radius=radius)
    slow = ref.summits(h, dx, dy, periodic, radius)
    assert len(s) == len(slow) > 5
    np.testing.assert_allclose(np.array(caps_of(s)), np.array(slow), rtol=1e-12, atol=1e-24)
    assert s.size == (h.shape[0] * dx, h.shape[1] * dy) and s.density == len(s) / (4e-12)


def test_hertz_sum_without_interaction_or_coalescence():
    h, px = rough_map(seed=1)
    s = map_summits(h, px, periodic=True)
    P = np.array([1e-6, 1e-5, 1e-4, 1e-3])
    c = icha_curve(s, P, E_star=E, interaction=False, coalescence=False)
    for i, p in enumerate(P):
        area, n, d = ref.hertz_sum(caps_of(s), p, E)
        assert c.area[i] == pytest.approx(area, rel=1e-10)
        assert c.spots[i] == n and c.mean_gap[i] == pytest.approx(d, rel=1e-10, abs=1e-20)
    np.testing.assert_allclose(c.force_sum, P, rtol=1e-12)


def test_interaction_on_a_free_map_equals_slow_path():
    h, px = rough_map(n=32, seed=2, periodic=False)
    s = map_summits(h, px, periodic=False)
    for p in (3e-5, 3e-4):
        c = icha_curve(s, [p], E_star=E, coalescence=False)
        area, n, d, forces = ref.interacting_free(caps_of(s), p, E)
        assert c.spots[0] == n
        assert c.area[0] == pytest.approx(area, rel=1e-7)
        assert c.separation[0] == pytest.approx(d, rel=1e-7)


def test_force_balance_and_load_order():
    h, px = rough_map(seed=4)
    s = map_summits(h, px, periodic=True)
    P = np.array([3e-4, 1e-5, 1e-3, 1e-4])
    c = icha_curve(s, P, E_star=E)
    np.testing.assert_allclose(c.force_sum, P, rtol=1e-11)
    assert np.all(np.diff(c.area[[1, 3, 0, 2]]) > 0)                     # reported in the order given
    assert c.merges[2] >= c.merges[0] >= c.merges[3] >= c.merges[1]
    assert np.all(np.isnan(c.separation))                                 # periodic: a gauge
    free = icha_curve(map_summits(h, px, periodic=False), P, E_star=E)
    np.testing.assert_allclose(free.force_sum, P, rtol=1e-11)
    assert np.all(np.isfinite(free.separation)) and np.all(free.mean_gap > free.separation)


def test_warm_start_equals_cold_start_without_coalescence():
    h, px = rough_map(seed=5)
    s = map_summits(h, px, periodic=True)
    P = [1e-5, 1e-4, 1e-3]
    together = icha_curve(s, P, E_star=E, coalescence=False)
    for i, p in enumerate(P):
        alone = icha_curve(s, [p], E_star=E, coalescence=False)
        assert alone.area[0] == pytest.approx(together.area[i], rel=1e-9)
        assert alone.spots[0] == together.spots[i]


def test_reduces_to_hertz_as_the_load_vanishes():
    h, px = rough_map(seed=6)
    s = map_summits(h, px, periodic=True)
    P = np.geomspace(1e-9, 1e-4, 6)
    inter = icha_curve(s, P, E_star=E)
    alone = icha_curve(s, P, E_star=E, interaction=False, coalescence=False)
    dev = np.abs(inter.area / alone.area - 1)
    assert dev[0] < 1e-9 and inter.spots[0] == alone.spots[0] == 1     # one contact: only its images
    assert dev[-1] > 1e-3                                                 # interaction matters under load


def scattered(spread, n=6):
    """n caps on a fixed pattern scaled by ``spread`` (summit density ~ 1/spread^2), free half-space."""
    rng = np.random.default_rng(0)
    x, y = rng.uniform(0, 1, n) * spread, rng.uniform(0, 1, n) * spread
    z = rng.normal(0, 5e-9, n)
    return MapSummits(x=x, y=y, z=z, R=np.full(n, 2e-7), size=(spread, spread), periodic=False)


def test_reduces_to_hertz_as_the_summit_density_vanishes():
    P = 2e-4
    devs = []
    for spread in (1e-6, 4e-6, 16e-6, 64e-6):
        s = scattered(spread)
        inter = icha_curve(s, [P], E_star=E, coalescence=False)
        alone = icha_curve(s, [P], E_star=E, interaction=False, coalescence=False)
        devs.append(abs(inter.area[0] / alone.area[0] - 1))
    devs = np.array(devs)
    assert devs[0] > 1e-3 and devs[-1] < 1e-3
    np.testing.assert_allclose(devs[1:] / devs[:-1], 0.25, rtol=0.2)    # the field falls as 1/distance


def test_tiled_periodic_map_repeats_the_solution():
    h, px = rough_map(n=32, seed=7)
    one = icha_curve(map_summits(h, px, periodic=True), [2e-4, 1e-3], E_star=E)
    four = icha_curve(map_summits(np.tile(h, (2, 2)), px, periodic=True), [8e-4, 4e-3], E_star=E)
    # equal up to the Hertz excess of the farther images, dropped (a^2/10 r^2 of their field: ~1e-5 here)
    np.testing.assert_allclose(four.area, 4 * one.area, rtol=1e-4)
    np.testing.assert_array_equal(four.spots, 4 * one.spots)
    np.testing.assert_allclose(four.mean_gap, one.mean_gap, atol=2e-3 * h.std())
    plain = [icha_curve(map_summits(m, px, periodic=True), P, E_star=E, interaction=False).area
             for m, P in ((h, [2e-4, 1e-3]), (np.tile(h, (2, 2)), [8e-4, 4e-3]))]
    np.testing.assert_allclose(plain[1], 4 * plain[0], rtol=1e-12)


@settings(max_examples=50, deadline=None)
@given(st.floats(1e-6, 1.0), st.floats(1e-9, 1e-6), st.floats(1e-6, 1.0), st.floats(1e-9, 1e-6))
def test_merge_conserves_force_and_area(F1, a1, F2, a2):
    F, a, R, delta = merge_spots(F1, a1, F2, a2, E)
    assert F == pytest.approx(F1 + F2, rel=1e-14)
    assert math.pi * a**2 == pytest.approx(math.pi * (a1**2 + a2**2), rel=1e-14)
    assert F == pytest.approx(4 * E * a**3 / (3 * R), rel=1e-12) and delta == pytest.approx(a * a / R, rel=1e-14)


def test_two_caps_coalesce_into_one_hertz_spot():
    # Two equal caps 10 nm apart, no interaction: they touch at once, merge with the area of
    # both, then grow as one Hertz cap of the equivalent radius 4 E a^3 / 3 F.
    R, z = 2e-7, 1e-9
    s = MapSummits(x=np.array([0.0, 1e-8]), y=np.zeros(2), z=np.full(2, z), R=np.full(2, R), size=(1e-6, 1e-6),
                   periodic=False)
    P1, P2 = 1e-6, 1e-5
    a1 = (3 * (P1 / 2) * R / (4 * E)) ** (1 / 3)
    assert 2 * a1 > 1e-8                                                   # the circles overlap at P1
    c = icha_curve(s, [P1, P2], E_star=E, interaction=False)
    assert list(c.spots) == [1, 1] and list(c.merges) == [1, 1]
    assert c.area[0] == pytest.approx(2 * math.pi * a1**2, rel=1e-12)       # area conserved by the merge
    _, a_eq, R_eq, _ = merge_spots(P1 / 2, a1, P1 / 2, a1, E)
    assert c.area[1] == pytest.approx(math.pi * (3 * P2 * R_eq / (4 * E)) ** (2 / 3), rel=1e-10)
    np.testing.assert_allclose(c.force_sum, [P1, P2], rtol=1e-12)
    apart = icha_curve(s, [P1, P2], E_star=E, interaction=False, coalescence=False)
    assert list(apart.spots) == [2, 2] and apart.area[0] == pytest.approx(c.area[0], rel=1e-12)


def test_a_summit_reaching_a_spot_coalesces_at_once():
    # A small summit 20 nm from a blunt cap, 0.05 nm above the cap's sphere there: it comes
    # into contact inside the growing spot and joins it (it never counts as a spot of its own).
    s = MapSummits(x=np.array([0.0, 2e-8]), y=np.zeros(2), z=np.array([2e-9, 1.85e-9]), R=np.array([1e-6, 1e-7]),
                   size=(1e-6, 1e-6), periodic=False)
    P = np.geomspace(1e-7, 1e-4, 6)
    c = icha_curve(s, P, E_star=E)
    assert list(c.spots) == [1] * 6 and list(c.merges) == [0, 0, 1, 1, 1, 1]
    np.testing.assert_allclose(c.force_sum, P, rtol=1e-12)
    apart = icha_curve(s, P, E_star=E, coalescence=False)
    assert list(apart.spots) == [1, 1, 2, 2, 2, 2]


def test_coalescence_with_interaction_on_a_rough_map():
    h, px = rough_map(seed=8)
    s = map_summits(h, px, periodic=True)
    P = np.geomspace(1e-5, 3e-3, 5)
    c = icha_curve(s, P, E_star=E)
    apart = icha_curve(s, P, E_star=E, coalescence=False)
    assert c.merges[-1] > 0 and np.all(c.spots <= apart.spots)
    np.testing.assert_allclose(c.force_sum, P, rtol=1e-11)


def test_icha_contact_reads_a_topography():
    st_ = pytest.importorskip("SurfaceTopography")
    h, px = rough_map(seed=9)
    topo = st_.Topography(h * 1e9, (2.0, 2.0), periodic=True, unit="um")      # heights in um? no: nm values
    topo_m = st_.Topography(h * 1e9 * 1e-6, (2e-6, 2e-6), periodic=True, unit="m")
    a = icha_contact(topo, [1e-4], E_star=E)
    b = icha_curve(map_summits(h * 1e3, px, periodic=True), [1e-4], E_star=E)
    c = icha_contact(topo_m, [1e-4], E_star=E)
    assert a.area[0] == pytest.approx(b.area[0], rel=1e-9) == c.area[0]
    assert a.setup_seconds > 0 and a.periodic
    free = icha_contact(topo_m, [1e-4], E_star=E, periodic=False)
    assert not free.periodic
    frame = pytest.importorskip("pandas") and a.to_dataframe()
    assert list(frame.columns) == list(a.columns()) and a.to_csv().startswith("P_N,")


@pytest.mark.parametrize("kwargs, error, message", [
    ({"P": [-1.0]}, ValueError, "P \\(load\\)"), ({"P": [np.nan]}, ValueError, "finite"),
    ({"E_star": 0.0}, ValueError, "E_star"), ({"interaction": "yes"}, TypeError, "interaction"),
    ({"coalescence": 1}, TypeError, "coalescence"), ({"summits": np.zeros(3)}, TypeError, "MapSummits"),
])
def test_bad_input(kwargs, error, message):
    h, px = rough_map(seed=1)
    args = {"summits": map_summits(h, px, periodic=True), "P": [1e-4], "E_star": E} | kwargs
    with pytest.raises(error, match=message):
        icha_curve(args.pop("summits"), args.pop("P"), **args)


def test_bad_maps(monkeypatch):
    with pytest.raises(ValueError, match="2-d map"):
        map_summits(np.zeros(10), (1.0, 1.0), periodic=True)
    with pytest.raises(ValueError, match="no summit"):
        map_summits(np.zeros((8, 8)), (1.0, 1.0), periodic=True)
    with pytest.raises(ValueError, match="radius"):
        map_summits(rough_map()[0], (1.0, 1.0), periodic=True, radius="median")
    with pytest.raises(TypeError, match="periodic"):
        map_summits(rough_map()[0], (1.0, 1.0), periodic="yes")
    with pytest.raises(ValueError, match="pixel_size"):
        map_summits(rough_map()[0], (1.0, -1.0), periodic=True)
    from asperity.icha import contact

    monkeypatch.setattr(contact, "MAX_SUMMITS", 3)
    h, px = rough_map(seed=1)
    with pytest.raises(ValueError, match="more than 3"):
        icha_curve(map_summits(h, px, periodic=True), [1e-4], E_star=E)
    with pytest.raises(TypeError, match="SurfaceTopography"):
        icha_contact(h, [1e-4], E_star=E)
    with pytest.raises(ValueError, match="a1"):
        merge_spots(1.0, 0.0, 1.0, 1e-9, E)
    with pytest.raises(ValueError, match="E_star"):
        merge_spots(1.0, 1e-9, 1.0, 1e-9, -E)
