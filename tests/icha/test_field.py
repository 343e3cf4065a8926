"""The Hertzian displacement field and the periodic Green's function of asperity.icha.field.

Expected values come from closed forms (Hertz, Boussinesq), numerical integration of the
Hertz pressure, direct sums over images, and ContactMechanics' periodic half-space."""

import math

import numpy as np
import pytest
from scipy import integrate

from asperity.icha.field import (
    FreeKernel,
    PeriodicKernel,
    hertz_displacement,
    hertz_excess,
)
from asperity.icha.rectangle import boussinesq_rectangle_mean

E = 1e11


def hertz(R, a):
    """Force and interference of a Hertz contact of radius a on a cap of radius R."""
    return 4 * E * a**3 / (3 * R), a * a / R


def test_centre_edge_and_far_field():
    R, a = 2e-7, 3e-8
    F, delta = hertz(R, a)
    assert hertz_displacement(0.0, a, F, E) == pytest.approx(delta, rel=1e-14)
    # Inside, the deformed surface follows the sphere: u(r) = delta - r^2/2R
    r = np.linspace(0, a, 7)
    np.testing.assert_allclose(hertz_displacement(r, a, F, E), delta - r**2 / (2 * R), rtol=1e-13)
    # Continuous at the edge (half the central value), Boussinesq far away
    assert hertz_displacement(a * (1 + 1e-12), a, F, E) == pytest.approx(delta / 2, rel=1e-9)
    far = 1e4 * a
    assert hertz_displacement(far, a, F, E) == pytest.approx(F / (math.pi * E * far), rel=1e-8)
    assert hertz_displacement(far, 0.0, F, E) == pytest.approx(F / (math.pi * E * far), rel=1e-15)


@pytest.mark.parametrize("r_over_a", [1.2, 2.0, 5.0])
def test_outside_equals_integrated_hertz_pressure(r_over_a):
    # u(r) = int p(s) / (pi E |x - s|) dA over the Hertz pressure p = p0 sqrt(1 - s^2/a^2)
    a, F = 1.0, 1.0
    p0 = 3 * F / (2 * math.pi * a**2)
    r = r_over_a * a

    def integrand(phi, s):
        return p0 * math.sqrt(1 - s * s) * s / (math.pi * E * math.sqrt(r * r + s * s - 2 * r * s * math.cos(phi)))

    u, _ = integrate.dblquad(integrand, 0, a, 0, 2 * math.pi, epsabs=0, epsrel=1e-11)
    assert hertz_displacement(r, a, F, E) == pytest.approx(u, rel=1e-8)


def test_excess_series_and_integral():
    a = 1.0
    r = np.array([1.5, 9.999, 10.0, 10.001, 30.0])        # across the switch to the series at r = 10 a
    exact = hertz_displacement(r, a, 1.0, 1 / math.pi) - 1 / r          # pi E* = 1 (cancellation ~1e-16 r/a^2)
    np.testing.assert_allclose(hertz_excess(r, a), exact, rtol=1e-7)
    np.testing.assert_allclose(hertz_excess(1e3, a) * 1e3**3, 0.1, rtol=1e-5)   # a^2/10 r^3
    # The excess integrates to zero over the plane (same total force as the point force)
    inner, _ = integrate.quad(lambda r: float(hertz_excess(r, a)) * 2 * math.pi * r, 1e-12, a, limit=200)
    outer, _ = integrate.quad(lambda r: float(hertz_excess(r, a)) * 2 * math.pi * r, a, np.inf, limit=400)
    assert abs(inner + outer) < 1e-6 * abs(inner)


def test_rectangle_mean():
    lx, ly, x0, y0 = 2.0, 1.0, 0.3, 0.6

    def f(y, x):
        return 1 / math.hypot(x - x0, y - y0)

    total = 0.0
    for xa, xb in ((0, x0), (x0, lx)):
        for ya, yb in ((0, y0), (y0, ly)):
            total += integrate.dblquad(f, xa, xb, ya, yb, epsabs=0, epsrel=1e-10)[0]
    assert boussinesq_rectangle_mean(x0, y0, lx, ly) == pytest.approx(total / (lx * ly), rel=1e-8)


def image_sum(dx, dy, L, M):
    n = np.arange(-M, M + 1)
    X, Y = np.meshgrid(n * L + dx, n * L + dy, indexing="ij")
    return float(np.sum(1 / np.hypot(X, Y)))


def test_periodic_kernel_equals_image_sum():
    # Differences of the field are gauge-free; square image sums of M shells converge as
    # c1/M + c2/M^2: Richardson on M = 20, 40, 80 removes both.
    L = 4e-6
    k = PeriodicKernel(L, L)
    pairs = [((L / 8, 0.0), (L / 2, L / 2)), ((0.1 * L, 0.37 * L), (0.45 * L, 0.05 * L))]
    for (x1, y1), (x2, y2) in pairs:
        s = [image_sum(x1, y1, L, M) - image_sum(x2, y2, L, M) for M in (20, 40, 80)]
        r1 = [2 * s[1] - s[0], 2 * s[2] - s[1]]
        ours = float(k.point_field(x1, y1) - k.point_field(x2, y2))
        assert ours == pytest.approx((4 * r1[1] - r1[0]) / 3, rel=1e-5)


def test_periodic_kernel_symmetry_periodicity_and_mean():
    lx, ly = 3e-6, 2e-6
    k = PeriodicKernel(lx, ly)
    x, y = 0.37e-6, -0.21e-6
    assert k.point_field(x, y) == pytest.approx(k.point_field(-x, -y), rel=1e-12)
    assert k.point_field(x + lx, y - 2 * ly) == pytest.approx(k.point_field(x, y), rel=1e-12)
    # Zero mean over the cell: integrate on a fine grid, the 1/r singularity at 0 analytically
    n = 600
    X, Y = np.meshgrid((np.arange(n) + 0.5) * lx / n, (np.arange(n) + 0.5) * ly / n, indexing="ij")
    g = k.point_field(X, Y) - 1 / np.hypot(*k.nearest(X, Y)[:2])
    smooth = float(np.mean(g))
    # mean of the nearest-image 1/r over the rectangle centred on the source
    singular = float(boussinesq_rectangle_mean(lx / 2, ly / 2, lx, ly))
    assert abs(smooth + singular) < 1e-3 * singular


def test_periodic_kernel_against_contact_mechanics():
    # A Hertz pressure on a disc of 6 pixels, spread on the grid, through ContactMechanics'
    # periodic half-space, against our Hertz field with all images, 3 radii away and more.
    cm = pytest.importorskip("ContactMechanics")
    L, n = 4e-6, 128
    dx = L / n
    k = PeriodicKernel(L, L)
    x = np.arange(n) * dx
    X, Y, r = k.nearest(*np.meshgrid(x, x, indexing="ij"))
    a = 6 * dx
    p = np.sqrt(np.clip(1 - (r / a) ** 2, 0, None))
    u = -np.asarray(cm.PeriodicFFTElasticHalfSpace((n, n), E, (L, L)).evaluate_disp(p / p.sum()))  # F = 1 N
    ours = k.unit_field(X, Y, np.full(r.shape, a)) / (math.pi * E)
    far = r >= 3 * a
    i0 = np.argmax(np.where(far, r, -1))             # both fields are defined up to a constant
    ref = u[far] - u.flat[i0]
    np.testing.assert_allclose(ours[far] - ours.flat[i0], ref, atol=2e-3 * np.max(np.abs(ref)))


def test_unit_field_consistent_with_point_matrix():
    L = 1e-6
    k = PeriodicKernel(L, L)
    x, y = np.array([0.1e-6, 0.4e-6, 0.9e-6]), np.array([0.2e-6, 0.7e-6, 0.95e-6])
    r, G = k.point_matrix(x, y)
    a = 1e-9
    u = k.unit_field(x[:, None] - x[None, :], y[:, None] - y[None, :], np.full((3, 3), a))
    off = ~np.eye(3, dtype=bool)
    np.testing.assert_allclose(u[off], G[off] + hertz_excess(r[off], a), rtol=1e-9)
    np.testing.assert_allclose(np.diag(G), k.self_images)
    assert np.allclose(np.diag(u), k.self_images + 3 * math.pi / (4 * a))   # own Hertz centre + images
    rf, Gf = FreeKernel().point_matrix(x, y)
    np.testing.assert_allclose(Gf[off], 1 / rf[off])


@pytest.mark.parametrize("args, message", [((-1.0, 1.0, 1.0, E), "r must be >= 0"),
                                           ((1.0, -1.0, 1.0, E), "a must be >= 0"),
                                           ((0.0, 0.0, 1.0, E), "r must be > 0 where a = 0"),
                                           ((1.0, 1.0, 1.0, 0.0), "E_star"),
                                           ((np.nan, 1.0, 1.0, E), "finite")])
def test_bad_input(args, message):
    with pytest.raises(ValueError, match=message):
        hertz_displacement(*args)
    with pytest.raises(ValueError, match="within the rectangle"):
        boussinesq_rectangle_mean(2.0, 0.5, 1.0, 1.0)
    with pytest.raises(ValueError, match="size_x"):
        PeriodicKernel(0.0, 1.0)


def test_excess_derivative_in_the_radius():
    r = np.array([0.5, 0.9, 1.1, 2.0, 9.0, 11.0, 50.0])
    a, h = 1.0, 1e-6
    numeric = (FreeKernel.spot_excess(r, a + h) - FreeKernel.spot_excess(r, a - h)) / (2 * h)
    np.testing.assert_allclose(FreeKernel.spot_excess_da(r, a), numeric, rtol=1e-6)
    assert PeriodicKernel.spot_excess_da is FreeKernel.spot_excess_da or \
        np.allclose(PeriodicKernel.spot_excess_da(r, a), numeric, rtol=1e-6)
