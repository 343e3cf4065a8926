"""The Chebyshev helpers of asperity.quadrature against numpy.polynomial.chebyshev."""

import numpy as np
import pytest
from numpy.polynomial import chebyshev as C

from asperity.quadrature import chebyshev_basis, gauss_legendre, legendre_to_chebyshev


@pytest.mark.parametrize("n", [2, 5, 12, 20])
def test_chebyshev_basis_points_coefficients_and_derivative(n):
    x, T, D = chebyshev_basis(n)
    np.testing.assert_allclose(np.sort(x), np.sort(C.chebroots([0] * n + [1])), atol=1e-14)
    rng = np.random.default_rng(n)
    c = rng.normal(size=n)                       # a polynomial of degree n - 1 ...
    np.testing.assert_allclose(T @ C.chebval(x, c), c, atol=1e-12)  # ... is recovered from its values
    np.testing.assert_allclose(D @ c, np.append(C.chebder(c), 0.0), atol=1e-11)


@pytest.mark.parametrize("n", [1, 4, 16])
def test_legendre_to_chebyshev_interpolates_on_the_panel(n):
    x, _ = gauss_legendre(n)
    c = np.random.default_rng(7).normal(size=n)
    values = C.chebval(2.0 * x - 1.0, c)
    np.testing.assert_allclose(legendre_to_chebyshev(n) @ values, c, atol=1e-11)


@pytest.mark.parametrize("f, n", [(chebyshev_basis, 1), (chebyshev_basis, 1001), (legendre_to_chebyshev, 0),
                                  (chebyshev_basis, 2.5), (legendre_to_chebyshev, "4")])
def test_bad_sizes_are_named(f, n):
    with pytest.raises((ValueError, TypeError), match="n"):
        f(n)


def test_cached_tables_are_read_only():
    # A review: scaling a returned table in place changed every later curve.
    for arrays in (gauss_legendre(16), chebyshev_basis(20), (legendre_to_chebyshev(16),)):
        for a in arrays:
            with pytest.raises(ValueError, match="read-only"):
                a *= 1.01
