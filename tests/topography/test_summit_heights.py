"""Summit heights of a measured surface: their skewness is recovered and the fits reach the model."""

import json

import numpy as np
import pytest
from scipy import stats

from asperity.heights import PearsonIII, parse_heights, read_samples
from asperity.topography import analyse_surface
from asperity.topography.detected import detected_summit_heights

from .synthetic import DX, ST, synthetic_profile

SKEW = 0.8


def bump_field(apex, spacing_px=9, radius=2e-6):
    """Paraboloid bumps on a square lattice with the given apex heights [m] (one per cell)."""
    cells = apex.shape[0]
    n = cells * spacing_px + 2
    idx = np.arange(n) - 1
    rel = (idx % spacing_px - (spacing_px - 1) / 2) * DX
    x, y = np.meshgrid(rel, rel, indexing="ij")
    cell = np.clip(idx // spacing_px, 0, cells - 1)
    top = apex[cell[:, None], cell[None, :]]
    return ST.Topography(top - (x**2 + y**2) / (2 * radius), (n * DX, n * DX), unit="m")


@pytest.fixture(scope="module")
def skewed():
    """30 x 30 bumps whose apex heights are drawn from a Pearson III of skewness 0.8 (sigma 2 nm)."""
    p = PearsonIII(SKEW)
    rng = np.random.default_rng(8)
    z = stats.pearson3(SKEW).rvs(size=(30, 30), random_state=rng) * 2e-9
    assert p.support[0] < z.min() / 2e-9
    return z, analyse_surface(bump_field(z))


def test_a_known_summit_skewness_is_recovered(skewed):
    apex, result = skewed
    z = result.summit_heights
    assert z.size == apex.size  # every bump is a summit, nothing else is
    drawn = stats.skew(apex.ravel())
    assert result.heights.skewness == pytest.approx(drawn, abs=0.02)  # the detrending only tilts
    assert result.heights.skewness == pytest.approx(SKEW, abs=3 * np.sqrt(6 / apex.size))  # sampling: 3 SE
    assert result.heights.kurtosis == pytest.approx(stats.kurtosis(apex.ravel(), fisher=False), abs=0.05)
    # the summits are the apexes, up to the mean plane the detrending removes (affine in the cell)
    i, j = np.meshgrid(np.arange(30), np.arange(30), indexing="ij")
    basis = np.stack([np.ones(900), i.ravel(), j.ravel()], axis=1)
    diff = z - apex.ravel()
    residual = diff - basis @ np.linalg.lstsq(basis, diff, rcond=None)[0]
    assert np.max(np.abs(residual)) < 1e-6 * apex.std()


def test_the_skewed_family_beats_the_gaussian(skewed):
    _, result = skewed
    ranking = [r.name for r in result.heights.ranking]
    assert ranking.index("gaussian") > 0
    assert ranking[0] in ("pearson3", "weibull", "johnson", "mixture")
    best = result.heights.best
    assert parse_heights(best.spec) == best


def test_summary_json_and_summit_file(skewed, tmp_path):
    _, result = skewed
    text = result.summary()
    assert "skewness" in text and "ranked by AIC" in text and f"--heights {result.heights.best.spec}" in text
    d = result.to_dict()
    json.dumps(d, allow_nan=False)
    assert d["heights"]["best"] == result.heights.best.spec
    path = tmp_path / "summits.txt"
    result.write_summits(path)
    np.testing.assert_array_equal(read_samples(path), result.summit_heights)
    assert parse_heights(f"empirical:{path}").samples == result.summit_heights.size


def test_detected_summit_heights_are_the_detected_summits(skewed):
    _, result = skewed
    assert result.detected.n_summits == result.summit_heights.size
    assert result.detected.sigma_s == pytest.approx(np.std(result.summit_heights), rel=1e-12)


def test_line_scans_fit_their_peaks_with_a_warning():
    h, _ = synthetic_profile(4096, roll_px=256, min_px=8, seed=3)
    scan = ST.UniformLineScan(h, 4096 * DX, unit="m")
    result = analyse_surface(scan)
    assert result.heights is not None and result.heights.n == detected_summit_heights(scan).size
    assert any("profile peaks" in w for w in result.warnings)


def test_no_fit_without_enough_summits():
    field = bump_field(np.full((3, 3), 1e-9) + np.arange(9).reshape(3, 3) * 1e-10)
    result = analyse_surface(field)
    assert result.heights is None and any("no height distribution fitted" in w for w in result.warnings)
    with pytest.raises(ValueError, match="at least 20"):
        result.write_summits("never-written.txt")
    no_fit = analyse_surface(field, heights=False)
    assert no_fit.heights is None and not any("height distribution" in w for w in no_fit.warnings)
    with pytest.raises(TypeError, match="heights must be True or False"):
        analyse_surface(field, heights="yes")
