"""Notes on a comparison (asperity.validation.notes) and the summits' curvature ratio they use."""

import math
import warnings

import numpy as np
import pytest

from asperity.icha import icha_contact
from asperity.icha.summits import map_summits
from asperity.plasticity import PlasticityWarning
from asperity.validation.notes import ELONGATED_SHARE, SLOPE_LIMIT, comparison_notes, model_warning_notes


def test_curvature_ratio_of_an_egg_box_is_the_ratio_of_its_discrete_curvatures():
    """cos(kx x) + cos(ky y): at its maxima the central differences give the curvatures
    (2 - 2 cos k dx)/dx^2 exactly, so the ratio is known in closed form; round bumps give 1."""
    i = np.arange(64)
    X, Y = np.meshgrid(i, i, indexing="ij")
    for nx, ny in ((16, 16), (16, 32), (8, 64)):
        h = np.cos(2 * np.pi * X / nx) + np.cos(2 * np.pi * Y / ny)
        s = map_summits(h, (1.0, 1.0), periodic=True)
        expected = (1 - math.cos(2 * math.pi / nx)) / (1 - math.cos(2 * math.pi / ny))
        np.testing.assert_allclose(s.curvature_ratio, expected, rtol=1e-12)
    ridge = np.tile(np.cos(2 * np.pi * np.arange(64) / 16), (64, 1)).T + 1e-9 * Y * (64 - Y)
    assert np.all(map_summits(ridge, (1.0, 1.0), periodic=False).curvature_ratio > 1e3)


def _table(P, **cols):
    return {"P_N": np.asarray(P, dtype=float), **{k: np.asarray(v, dtype=float) for k, v in cols.items()}}


def test_area_above_the_nominal_area_is_noted_from_its_first_load():
    t = _table([1.0, 2.0, 3.0], area_bgt_m2=[0.5, 1.5, 2.5], area_icha_m2=[0.1, 0.2, 0.3],
               area_spectral_m2=[5.0, 5.0, 5.0])
    notes = comparison_notes(t, ("spectral", "icha", "bgt"), 1.0)
    assert notes == ["the real area of BGT exceeds the nominal area from P = 2 N (up to 2.5 times it, at P = 3 N) "
                     "(a light-load asymptote, linear in the load): not physical there"]


def test_negative_mean_gaps_are_noted_for_every_model_that_has_one():
    t = _table([1.0, 2.0], area_icha_m2=[0.1, 0.2], gap_icha_m=[1e-9, -2e-9], gap_spectral_m=[-1e-9, -3e-9],
               area_spectral_m2=[0.1, 0.2])
    notes = comparison_notes(t, ("spectral", "icha"), 1.0)
    assert len(notes) == 2
    # the least gap with its own load (a CLI check: the least gap was shown beside the first load)
    assert "GW (spectral summits) is negative from P = 1 N (down to -3e-09 m, at P = 2 N)" in notes[0]
    assert "ICHA is negative from P = 2 N (down to -2e-09 m, at P = 2 N)" in notes[1]


def test_slope_and_elongation_notes_have_thresholds():
    t = _table([1.0], area_persson_m2=[0.1])
    assert comparison_notes(t, ("persson",), 1.0, rms_slope=SLOPE_LIMIT, elongated=ELONGATED_SHARE) == []
    notes = comparison_notes(t, ("persson",), 1.0, rms_slope=3e7, elongated=0.5)
    assert "rms slope is 3e+07" in notes[0] and "check the height unit" in notes[0]
    assert notes[1].startswith("50 % of the map's summits are elongated")


def test_a_ridge_makes_icha_note_its_elongated_summits():
    """A sinusoidal ridge (found by a review: ICHA's area 42 times the nominal area, no
    note): every summit is elongated, and the comparison says so."""
    x = np.linspace(0, 6 * np.pi, 64)
    h = np.tile(5e-9 * np.sin(x), (64, 1)) + 1e-12 * np.random.default_rng(0).standard_normal((64, 64))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ImportWarning)  # SurfaceTopography's MPI stub, on first import
        Topography = pytest.importorskip("SurfaceTopography").Topography
    curve = icha_contact(Topography(h, (2e-6, 2e-6)), [1e-6], E_star=96.7e9, periodic=False)
    assert curve.elongated > 0.9


def test_model_warnings_become_notes_naming_the_method():
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        warnings.warn("up to 50% of the asperities in contact are past the critical interference for yield "
                      "(psi = 3) but the model is elastic: use plasticity='jackson-green'", PlasticityWarning)
        warnings.warn("the real contact area reaches 20 % of the nominal area", UserWarning)
        warnings.warn("the real contact area reaches 20 % of the nominal area", UserWarning)
    notes = model_warning_notes("detected", caught)
    assert notes == ["GW (detected summits): up to 50% of the asperities in contact are past the critical "
                     "interference for yield (psi = 3): the comparison is elastic, as the boundary elements are; a "
                     "real contact would yield there",
                     "GW (detected summits): the real contact area reaches 20 % of the nominal area"]


def test_validate_surface_puts_the_notes_in_its_parameters():
    pytest.importorskip("ContactMechanics")
    from asperity.validation import validate_surface
    from asperity.validation.surfaces import synthetic_surface

    topo = synthetic_surface("gaussian", 4e-6, 32, short_cutoff=4e-6 / 8, seed=0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # nothing leaks as a Python warning
        r = validate_surface(topo, [0.5], material="Au", models="gw,bgt")
    notes = r.parameters["warnings"]
    assert any(n.startswith("GW (spectral summits): up to") for n in notes)
    assert any(n.startswith("the real area of BGT exceeds the nominal area from P = 0.5 N") for n in notes)


def test_averaging_that_drops_points_is_noted():
    """Found by a review: ``--grid`` silently cropped a 160 x 96 scan to 159 x 96 points
    (and the nominal area with it); a grid that divides the scan says nothing."""
    pytest.importorskip("ContactMechanics")
    from asperity.validation import validate_surface

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ImportWarning)
        st = pytest.importorskip("SurfaceTopography")
    h = 1e-9 * np.random.default_rng(1).standard_normal((100, 60))
    topo = st.Topography(h, (4e-6, 2.4e-6), unit="m")
    r = validate_surface(topo, [1e-3], material="Au", models="persson", grid=34)
    assert tuple(r.parameters["nb_grid_pts"]) == (33, 20)
    assert ("grid=34: the 100 x 60 scan is averaged over 3 x 3 blocks; the points beyond whole blocks are dropped: "
            "99 x 60 points, 3.96e-06 x 2.4e-06 m, are compared") in r.parameters["warnings"]
    whole = validate_surface(topo, [1e-3], material="Au", models="persson", grid=50)
    assert not any(n.startswith("grid=") for n in whole.parameters["warnings"])


def test_the_averaging_note_counts_points_not_metres():
    """Found by a review: sizes compared with numpy's default atol (1e-8 m) hid the note on
    scans smaller than ~10 um."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ImportWarning)
        st = pytest.importorskip("SurfaceTopography")
    from asperity.validation.bem import subsample
    from asperity.validation.compare import _cropped

    h = np.random.default_rng(2).standard_normal((101, 101)) * 1e-10
    full = st.Topography(h, (1e-7, 1e-7), periodic=True, unit="m")
    notes = _cropped(full, subsample(full, 50), 50)
    assert len(notes) == 1 and "the points beyond whole blocks are dropped and periodicity" in notes[0]
    assert _cropped(full, subsample(full, 101), 101) == []
