"""The boundary-element setup against closed forms (Hertz, Westergaard), grid refinement, bad input."""

import json
import math

import numpy as np
import pytest

pytest.importorskip("ContactMechanics")
from SurfaceTopography import Topography, UniformLineScan  # noqa: E402

from asperity.validation import MIN_GRID, bem_contact, subsample  # noqa: E402
from asperity.validation.surfaces import synthetic_surface  # noqa: E402

E_STAR = 1e11


def sphere(n, size, radius):
    x = (np.arange(n) + 0.5) * size / n - size / 2
    X, Y = np.meshgrid(x, x, indexing="ij")
    return Topography(-(X**2 + Y**2) / (2 * radius), (size, size), periodic=False, unit="m")


def test_hertz_sphere_radius_and_penetration():
    # Free boundaries: a rigid sphere on a half-space, Hertz: a = (3PR/4E*)^(1/3), delta = a^2/R.
    R, size, n = 2e-6, 1e-6, 96
    topo = sphere(n, size, R)
    P = np.array([2e-4, 5e-4])  # contact radii of 14 and 19 pixels
    c = bem_contact(topo, P, E_star=E_STAR, periodic=False)
    a_hertz = (3 * P * R / (4 * E_STAR)) ** (1 / 3)
    np.testing.assert_allclose(np.sqrt(c.area / math.pi), a_hertz, rtol=0.02)
    h = np.asarray(topo.detrend("height").heights())
    delta = h.max() - c.separation  # the flat's approach past the top of the sphere
    np.testing.assert_allclose(delta, a_hertz**2 / R, rtol=0.02)
    assert list(c.spots) == [1, 1] and c.periodic is False
    assert np.all(np.diff(c.area) > 0)


@pytest.mark.parametrize("p_ratio", [0.05, 0.3, 0.8])
def test_westergaard_wavy_surface(p_ratio):
    # Periodic: h = D cos(2 pi x / lam); full contact at p* = pi E* D / lam; below, the contact half-width a
    # obeys p/p* = sin^2(pi a / lam) (Westergaard 1939; Johnson 1985, 13.2), so the area fraction is
    # (2/pi) arcsin(sqrt(p/p*)).
    n, lam, D = 256, 1e-6, 5e-9
    x = np.arange(n) * lam / n
    h = D * np.cos(2 * np.pi * x / lam)[:, None] * np.ones((1, 16))
    topo = Topography(h, (lam, lam * 16 / n), periodic=True, unit="m")
    p_star = math.pi * E_STAR * D / lam
    c = bem_contact(topo, [p_ratio * p_star * lam * lam * 16 / n], E_star=E_STAR)
    expected = 2 / math.pi * math.asin(math.sqrt(p_ratio))
    assert c.area_fraction[0] == pytest.approx(expected, abs=2.0 / n)
    assert c.spots[0] == 1 and math.isnan(c.separation[0])


@pytest.mark.parametrize("p_ratio", [0.01, 0.1])
def test_a_file_solved_as_periodic_is_levelled_as_periodic(tmp_path, capsys, p_ratio):
    """Found by a user trial: 'asperity bem wave.npy --periodic' levelled the map read from the
    file (free) by a fitted plane, then solved it as a periodic cell: the tilt left a step at
    the seam and Westergaard's light-load area came out 39 % low, in two spots.  Now the file
    asked to be periodic is that periodic map: Westergaard within two pixels, one spot, equal
    to the periodic Topography's solution; the command line gives the same."""
    from asperity.bodies import contact_material
    from asperity.validation import validate_surface

    from ..cli.helpers import run

    n, lam, D = 128, 2e-6, 10e-9
    x = np.arange(n) * lam / n
    h = D * np.cos(2 * np.pi * x / lam)[:, None] * np.ones((1, n))
    np.save(tmp_path / "wave.npy", h)
    p_star = math.pi * E_STAR * D / lam
    load = p_ratio * p_star * lam * lam
    expected = 2 / math.pi * math.asin(math.sqrt(p_ratio))
    kws = {"material": contact_material(E=f"{E_STAR}Pa", nu=0.0), "models": ("persson",)}
    got = validate_surface(tmp_path / "wave.npy", [load], physical_sizes=(lam, lam), unit="m", periodic=True, **kws)
    direct = bem_contact(Topography(h, (lam, lam), periodic=True, unit="m"), [load], E_star=E_STAR)
    assert got.table["fraction_bem"][0] == pytest.approx(expected, abs=2.0 / n)
    assert got.table["spots_bem"][0] == 1 and got.parameters["periodic"] is True
    assert got.table["fraction_bem"][0] == direct.area_fraction[0]
    code, out, err = run(capsys, "bem", str(tmp_path / "wave.npy"), "--size", f"{lam}m,{lam}m", "--unit", "m",
                             "--E", f"{E_STAR}Pa", "--nu", "0", "--periodic", "--load", f"{load}N", "--model",
                             "persson", "--format", "json")
    assert code == 0, err
    assert json.loads(out)["table"]["fraction_bem"] == [got.table["fraction_bem"][0]]


def test_periodic_with_a_grid_that_drops_edge_points_and_undefined_data(tmp_path):
    """A review of the fix above: with grid=64 on a 130-point cosine the averaging dropped an
    edge point and the periodicity with it, so bem_contact levelled by a plane again (0.023
    for 0.064) while validate_surface gave 0.0698; and a masked pixel was solved as a height
    once the map was rebuilt as periodic.  Now both give the same periodic answer, and
    undefined data is refused with periodic=True as without it."""
    from asperity.bodies import contact_material
    from asperity.validation import validate_surface

    n, lam, D = 130, 2e-6, 10e-9
    x = np.arange(n) * lam / n
    h = D * np.cos(2 * np.pi * x / lam)[:, None] * np.ones((1, n))
    free = Topography(h, (lam, lam), periodic=False, unit="m")
    p_star = math.pi * E_STAR * D / lam
    load = 0.01 * p_star * lam * lam
    expected = 2 / math.pi * math.asin(math.sqrt(0.01))
    direct = bem_contact(free, [load], E_star=E_STAR, periodic=True, grid=64)
    assert direct.nb_grid_pts == (43, 43) and direct.periodic  # 3 x 3 blocks: 129 of 130 points kept
    assert direct.area_fraction[0] == pytest.approx(expected, abs=2.0 / 43) and direct.spots[0] == 1
    got = validate_surface(free, [load], material=contact_material(E=f"{E_STAR}Pa", nu=0.0), models=("persson",),
                           periodic=True, grid=64)
    assert got.table["fraction_bem"][0] == direct.area_fraction[0]
    assert not any("periodicity" in w for w in got.parameters["warnings"])
    masked = Topography(np.ma.masked_array(h, mask=np.eye(n, dtype=bool) & (np.arange(n) == 5)), (lam, lam),
                        periodic=False, unit="m")
    for periodic in (None, True):
        with pytest.raises(ValueError, match="undefined data"):
            bem_contact(masked, [load], E_star=E_STAR, periodic=periodic)


def test_grid_refinement_lowers_pixel_area():
    # The same band-limited surface on two grids: pixel-counted areas fall with refinement and converge.
    coarse, fine = (synthetic_surface("gaussian", 2e-6, n, short_cutoff=2e-6 / 8, seed=3) for n in (32, 64))
    P = 4e-12 * 1.0e11 * np.array([1e-3, 4e-3])
    a, b = (bem_contact(t, P, E_star=E_STAR).area for t in (coarse, fine))
    assert np.all(a >= b)
    np.testing.assert_allclose(a, b, rtol=0.12)


def test_warm_start_matches_cold_start_and_order():
    topo = synthetic_surface("self-affine", 2e-6, 32, short_cutoff=2e-6 / 8, seed=1)
    P = 4e-12 * 1.0e11 * np.array([4e-3, 1e-3, 2e-3])
    warm = bem_contact(topo, P, E_star=E_STAR)
    np.testing.assert_array_equal(warm.P, P)
    for i, load in enumerate(P):
        cold = bem_contact(topo, [load], E_star=E_STAR)
        assert cold.area[0] == pytest.approx(warm.area[i], rel=0.02)
        assert cold.mean_gap[0] == pytest.approx(warm.mean_gap[i], rel=1e-3)


def test_subsample_block_average():
    h = np.arange(64 * 48, dtype=float).reshape(64, 48)
    topo = Topography(h, (6.4e-6, 4.8e-6), periodic=True, unit="m")
    assert subsample(topo, None) is topo and subsample(topo, 64) is topo
    small = subsample(topo, 32)
    np.testing.assert_allclose(small.heights(), h.reshape(32, 2, 24, 2).mean(axis=(1, 3)))
    assert small.physical_sizes == pytest.approx((6.4e-6, 4.8e-6)) and small.is_periodic
    odd = subsample(Topography(h[:62], (6.2e-6, 4.8e-6), periodic=True, unit="m"), 30)
    assert odd.nb_grid_pts == (20, 16) and not odd.is_periodic  # 2 rows dropped: no longer periodic
    assert odd.physical_sizes == pytest.approx((6.0e-6, 4.8e-6))


@pytest.mark.parametrize("grid", [8, MIN_GRID - 1, 2.5, True, "64"])
def test_bad_grid(grid):
    topo = synthetic_surface("gaussian", 2e-6, 32, short_cutoff=2e-6 / 8)
    with pytest.raises(ValueError, match="grid"):
        bem_contact(topo, [1e-3], E_star=E_STAR, grid=grid)


@pytest.mark.parametrize("P", [[0.0], [-1e-3], [math.nan], [math.inf], [], np.ones(1001), "x", [True], [[1e-3]]])
def test_bad_loads(P):
    topo = synthetic_surface("gaussian", 2e-6, 32, short_cutoff=2e-6 / 8)
    with pytest.raises((ValueError, TypeError), match="load"):
        bem_contact(topo, P, E_star=E_STAR)


def test_bad_surfaces_and_options():
    topo = synthetic_surface("gaussian", 2e-6, 32, short_cutoff=2e-6 / 8)
    with pytest.raises(TypeError, match="SurfaceTopography"):
        bem_contact(np.zeros((32, 32)), [1e-3], E_star=E_STAR)
    line = UniformLineScan(np.sin(np.arange(64.0)), 1e-6, periodic=True, unit="m")
    with pytest.raises(ValueError, match="2-d map"):
        bem_contact(line, [1e-3], E_star=E_STAR)
    tiny = Topography(np.random.default_rng(0).normal(size=(12, 12)) * 1e-9, (1e-6, 1e-6), unit="m")
    with pytest.raises(ValueError, match="too small"):
        bem_contact(tiny, [1e-3], E_star=E_STAR)
    for kwargs in ({"E_star": -1.0}, {"E_star": E_STAR, "tolerance": 0.5}, {"E_star": E_STAR, "maxiter": 0}):
        with pytest.raises(ValueError):
            bem_contact(topo, [1e-3], **kwargs)
    with pytest.raises(ValueError, match="did not converge"):
        bem_contact(topo, [1e-3], E_star=E_STAR, maxiter=1)


def test_table_of_a_curve():
    pd = pytest.importorskip("pandas")
    c = bem_contact(synthetic_surface("gaussian", 2e-6, 32, short_cutoff=2e-6 / 8), [1e-3, 2e-3], E_star=E_STAR)
    assert c.to_csv().splitlines()[0] == ",".join(c.columns())
    assert isinstance(c.to_dataframe(), pd.DataFrame) and len(c) == 2
