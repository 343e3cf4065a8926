"""The statistical model beside the boundary elements: table, agreement at light load, outputs, errors."""

import json

import numpy as np
import pytest

pytest.importorskip("ContactMechanics")

from asperity.materials import material  # noqa: E402
from asperity.physical import PhysicalContact  # noqa: E402
from asperity.topography import analyse_surface  # noqa: E402
from asperity.validation import SurfaceValidation, bem_contact, validate_surface  # noqa: E402
from asperity.validation.models import model_columns  # noqa: E402
from asperity.validation.progress import progress_bar  # noqa: E402
from asperity.validation.surfaces import synthetic_surface  # noqa: E402

# Elastic comparisons on gold, which yields at these loads: the plasticity note is expected.
pytestmark = pytest.mark.filterwarnings("ignore::asperity.plasticity.PlasticityWarning")


SIZE = 4e-6
AU = material("Au")


def light_loads(*ratios):
    return SIZE**2 * AU.E_star * np.array(ratios)


@pytest.fixture(scope="module")
def seeds():
    """Six Gaussian-correlated 64^2 surfaces (16 px per shortest wavelength) at two light loads."""
    P = light_loads(2e-4, 5e-4)
    return [validate_surface(synthetic_surface("gaussian", SIZE, 64, short_cutoff=SIZE / 16, seed=s), P,
                             material=AU) for s in range(6)]


def test_table_is_the_two_solutions(seeds):
    r = seeds[0]
    t = r.columns()
    assert list(t) == list(model_columns("gw"))
    topo = synthetic_surface("gaussian", SIZE, 64, short_cutoff=SIZE / 16, seed=0)
    bem = bem_contact(topo, t["P_N"], E_star=AU.E_star)
    np.testing.assert_array_equal(t["area_bem_m2"], bem.area)
    np.testing.assert_array_equal(t["spots_bem"], bem.spots)
    summits = analyse_surface(topo).spectral
    curve = PhysicalContact(AU, summits.surface(SIZE**2), adhesion=False).load_curve(t["P_N"])
    np.testing.assert_allclose(t["area_spectral_m2"], curve.area, rtol=1e-12)
    np.testing.assert_allclose(t["dev_spectral"], curve.area / bem.area - 1, rtol=1e-12)
    np.testing.assert_allclose(t["gap_spectral_m"], curve.d + summits.mean_summit_height, rtol=1e-12)
    np.testing.assert_allclose(t["contacts_spectral"], curve.contacts, rtol=1e-12)
    np.testing.assert_allclose(t["fraction_bem"], bem.area / SIZE**2)
    assert r.periodic if hasattr(r, "periodic") else r.bem.periodic


@pytest.mark.parametrize("column, model", [("spots_bem", "contacts_spectral"), ("spots_bem", "contacts_detected"),
                                           ("gap_bem_m", "gap_spectral_m"), ("gap_bem_m", "gap_detected_m")])
def test_light_load_within_seed_scatter(seeds, column, model):
    # At light load each contact spot is one asperity and the gap is set by the summit heights: the model's
    # mean over seeds lies within the boundary elements' seed-to-seed scatter (one standard deviation).
    bem = np.array([r.columns()[column] for r in seeds])
    gw = np.array([r.columns()[model] for r in seeds])
    assert np.all(np.abs(gw.mean(axis=0) - bem.mean(axis=0)) <= bem.std(axis=0, ddof=1))


def test_light_load_area_underestimated_as_reported(seeds):
    # The real area: GW falls short of the boundary elements even at light load (docs/validation.md);
    # the shortfall stays within 40 % here, and its sign is the same for the mean of the seeds.
    ratio = np.array([r.columns()["area_spectral_m2"] / r.columns()["area_bem_m2"] for r in seeds])
    assert np.all(ratio.mean(axis=0) < 1.0) and np.all(ratio.mean(axis=0) > 0.6)


def test_outputs(seeds, tmp_path):
    r = seeds[0]
    assert isinstance(r, SurfaceValidation) and len(r) == 2
    d = json.loads(r.to_json())
    assert d["table"]["P_N"] == pytest.approx(list(r.columns()["P_N"]))
    assert d["table"]["sep_bem_m"] == [None, None]  # periodic: NaN -> null
    assert d["costs"]["ratio"] == pytest.approx(r.cost_ratio) and r.cost_ratio > 0
    assert d["summits"]["spectral"]["eta"] == pytest.approx(r.analysis.spectral.eta)
    assert r.to_csv().splitlines()[0] == ",".join(model_columns("gw"))
    pd = pytest.importorskip("pandas")
    frame = r.to_dataframe()
    assert isinstance(frame, pd.DataFrame) and frame.attrs["units"]["P_N"] == "N"
    assert r.deviation("detected") == pytest.approx(np.max(np.abs(r.columns()["dev_detected"])))
    with pytest.raises(ValueError):
        r.deviation("bogus")
    with pytest.raises(ValueError, match="GW's methods are 'spectral' and 'detected'"):
        r.deviation("gw")
    lightest = float(np.min(r.columns()["fraction_bem"]))
    with pytest.raises(ValueError, match=f"no load has a boundary-element area fraction up to {lightest / 2:g}"):
        r.deviation("spectral", up_to=lightest / 2)  # found by a review: a silent NaN
    for bad in (0.0, -1.0, 2.0, float("nan")):
        with pytest.raises(ValueError, match="up_to"):
            r.deviation("spectral", up_to=bad)
    pytest.importorskip("matplotlib")
    r.plot(tmp_path / "v.png")
    assert (tmp_path / "v.png").read_bytes()[:4] == b"\x89PNG"


def test_files_and_bad_input(tmp_path):
    topo = synthetic_surface("gaussian", SIZE, 32, short_cutoff=SIZE / 8, seed=0)
    path = tmp_path / "s.npy"
    np.save(path, np.asarray(topo.heights()) * 1e9)
    r = validate_surface(path, light_loads(5e-4), material="Au", physical_sizes=("4um", "4um"), unit="nm")
    assert r.parameters["source"] == str(path) and not r.bem.periodic and np.isfinite(r.columns()["sep_bem_m"][0])
    bad = tmp_path / "bad.txt"
    bad.write_text("not a surface\n")
    with pytest.raises(ValueError, match="bad.txt"):
        validate_surface(bad, light_loads(5e-4), material="Au", physical_sizes=("4um", "4um"), unit="nm")
    with pytest.raises(ValueError, match="grid"):
        validate_surface(path, light_loads(5e-4), material="Au", physical_sizes=("4um", "4um"), unit="nm", grid=8)
    with pytest.raises(ValueError, match="load"):
        validate_surface(topo, [-1.0], material="Au")
    with pytest.raises(ValueError, match="interaction"):
        validate_surface(topo, light_loads(5e-4), material="Au", interaction="bogus")
    with pytest.raises(TypeError):
        validate_surface(topo, light_loads(5e-4), material="Au", unit="nm")
    with pytest.raises(TypeError):
        validate_surface(3.0, light_loads(5e-4), material="Au")


def test_a_gw_comparison_that_cannot_run_says_what_to_check(tmp_path):
    """Found by a user trial: a wave (no summits) gave only 'no summits found', and heights in
    metres read as nanometres only the model's 'P_max ... too large for alpha = 8e-11'."""
    topo = synthetic_surface("gaussian", SIZE, 32, short_cutoff=SIZE / 8, seed=0)
    path = tmp_path / "m.npy"
    np.save(path, np.asarray(topo.heights()))  # metres
    with pytest.raises(ValueError, match=r"m.npy: the GW model on its \w+ summits cannot carry these loads "
                                         r"\(P_max .*\); the map's rms height is \S+ m: check the height unit "
                                         r"\(unit=, --unit\)"):
        validate_surface(path, light_loads(5e-4), material="Au", physical_sizes=("4um", "4um"), unit="nm")
    x = np.arange(32) * SIZE / 32
    np.save(tmp_path / "wave.npy", 1e-8 * np.cos(2 * np.pi * x / SIZE)[:, None] * np.ones((1, 32)))
    with pytest.raises(ValueError, match=r"wave.npy: no summits found on the surface: the GW model needs summit "
                                         r"statistics; .* --model persson,bgt"):
        validate_surface(tmp_path / "wave.npy", [1e-3], material="Au", physical_sizes=("4um", "4um"), unit="m",
                         periodic=True)
    assert validate_surface(tmp_path / "wave.npy", [1e-3], material="Au", physical_sizes=("4um", "4um"), unit="m",
                            periodic=True, models=("persson", "bgt")).table["spots_bem"][0] == 1


def test_interaction_leaves_periodic_area_and_gap_unchanged():
    topo = synthetic_surface("self-affine", SIZE, 32, short_cutoff=SIZE / 8, seed=2)
    P = light_loads(5e-4, 2e-3)
    a = validate_surface(topo, P, material=AU).columns()
    b = validate_surface(topo, P, material=AU, interaction="cgp2008").columns()
    for name in ("area_spectral_m2", "gap_spectral_m", "contacts_detected"):
        np.testing.assert_allclose(b[name], a[name], rtol=1e-12)
    assert np.all(b["sep_spectral_m"] < a["sep_spectral_m"])  # the flat comes closer to the undeformed surface


def test_progress_plain_lines_without_tqdm(monkeypatch, capsys):
    from asperity.validation import progress

    monkeypatch.setattr(progress, "_tqdm", lambda: None)
    assert list(progress_bar([1e-3, 2e-3], enabled=True)) == [1e-3, 2e-3]
    err = capsys.readouterr().err.splitlines()
    assert err == ["bem: load 1/2 (P = 0.001 N)", "bem: load 2/2 (P = 0.002 N)"]
    assert list(progress_bar([1.0], enabled=False)) == [1.0]
    assert capsys.readouterr().err == ""


def test_progress_with_tqdm(capsys):
    pytest.importorskip("tqdm")
    assert list(progress_bar([1e-3, 2e-3], enabled=True)) == [1e-3, 2e-3]
    assert "bem" in capsys.readouterr().err


def test_stage_reports_the_steps_before_the_loads_and_hints_at_large_maps(capsys):
    """A review: a 4096^2 scan ran for minutes with nothing printed (the bar starts at the loads)."""
    from asperity.validation.progress import LARGE_MAP, stage

    stage("summit statistics of the 64 x 64 map", enabled=True, points=64 * 64)
    stage("boundary elements on 4096 x 4096 points, 8 loads", enabled=True, points=4096 * 4096)
    stage("quiet", enabled=False, points=LARGE_MAP + 1)
    err = capsys.readouterr().err.splitlines()
    assert err[0] == "bem: summit statistics of the 64 x 64 map"
    assert err[1].startswith("bem: boundary elements on 4096 x 4096 points, 8 loads (slow for this many points: "
                             "grid=512, command line --grid 512")
    assert len(err) == 2
