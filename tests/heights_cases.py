"""Height distributions the tests share, each beside its independent reference density.

The reference densities (``asperity.reference.heights``) are rebuilt from the definitions
with mpmath; they are slow to build (a Johnson S_B fit takes ~20 s), so each is built once
per test session.
"""

import functools

import numpy as np

from asperity.heights import Empirical, Exponential, Johnson, Mixture, PearsonIII, Weibull

#: Empirical summit heights with a known, skewed parent (gamma of shape 3: skewness 1.15).
SAMPLES = np.random.default_rng(20240613).gamma(3.0, size=900)

#: id -> (fast distribution factory, reference name, reference parameters)
CASES = {
    "exponential": (Exponential, "exponential", {}),
    "weibull+0.5": (lambda: Weibull(skew=0.5), "weibull", {"skew": 0.5}),
    "weibull-0.8": (lambda: Weibull(skew=-0.8), "weibull", {"skew": -0.8}),
    "weibull+1.8": (lambda: Weibull(skew=1.8), "weibull", {"skew": 1.8}),
    "pearson3+1": (lambda: PearsonIII(skew=1.0), "pearson3", {"skew": 1.0}),
    "pearson3-1.2": (lambda: PearsonIII(skew=-1.2), "pearson3", {"skew": -1.2}),
    "pearson3+0.3": (lambda: PearsonIII(skew=0.3), "pearson3", {"skew": 0.3}),
    "johnsonSU": (lambda: Johnson(skew=0.5, kurt=4.0), "johnson", {"skew": 0.5, "kurt": 4.0}),
    "johnsonSB": (lambda: Johnson(skew=-0.5, kurt=3.2), "johnson", {"skew": -0.5, "kurt": 3.2}),
    "mixture": (lambda: Mixture(w=0.8, m1=0.5, s1=0.5, m2=-2.0, s2=1.2), "mixture",
                {"w": 0.8, "m1": 0.5, "s1": 0.5, "m2": -2.0, "s2": 1.2}),
    "empirical": (lambda: Empirical.from_samples(SAMPLES), "gauss_mixture", None),
}

#: The cases cheap enough for the slow reference curves (no S_B fit by quadrature).
CURVE_CASES = ["exponential", "weibull+0.5", "weibull-0.8", "pearson3-1.2", "johnsonSU", "mixture", "empirical"]


@functools.cache
def fast(case: str):
    """The fast-path distribution of a case (built once)."""
    return CASES[case][0]()


@functools.cache
def reference(case: str):
    """The reference density of a case (built once), from the definitions only."""
    from asperity.reference.heights import reference_density

    _, name, params = CASES[case]
    if params is None:  # the empirical estimate: its Gaussian components, standardised again
        w, m, s = fast(case).translates()
        params = {"weights": tuple(w), "means": tuple(m), "sds": (s,) * len(w)}
    return reference_density(name, **params)
