"""asperity.physical_results: SI results, the area-fraction flags and AreaFractionWarning."""

import json
import warnings

import numpy as np
import pytest

import asperity
from asperity.physical import PhysicalContact
from asperity.physical_results import (
    AREA_FRACTION_CAUTION,
    AREA_FRACTION_LIMIT,
    AreaFractionWarning,
    warn_area_fraction,
)
from asperity.surface import Surface

#: Gold asperities of these surfaces yield (plasticity index psi ~ 23): the elastic model
#: warns (asperity.PlasticityWarning), tested in tests/test_plasticity.py, not here.
pytestmark = pytest.mark.filterwarnings("ignore::asperity.plasticity.PlasticityWarning")

#: A dense gold surface: N = 2e7 summits on 1 mm^2, whose real contact area grows past the
#: nominal one under large loads.
DENSE = Surface(5e-9, 0.8e-6, 2e13, 1e-6)


@pytest.fixture(scope="module")
def dense():
    return PhysicalContact("Au", DENSE, plastic_threshold=1.0)  # no yield note: only the area warns


def test_thresholds_and_category():
    assert (AREA_FRACTION_CAUTION, AREA_FRACTION_LIMIT) == (0.1, 1.0)
    assert issubclass(AreaFractionWarning, UserWarning) and asperity.AreaFractionWarning is AreaFractionWarning
    assert issubclass(AreaFractionWarning, asperity.AsperityWarning)  # one filter, one note mechanism


def test_small_area_fraction_gives_no_warning(dense):
    curve = dense.load_curve([1e-3, 1e-2])  # pytest turns any warning into an error
    assert curve.max_area_fraction < AREA_FRACTION_CAUTION
    assert not curve.area_fraction_high and not curve.exceeds_nominal_area


def test_caution_level_warns_once(dense):
    # Find, from the API's own areas, loads with 10 % < A/A0 < 100 %.
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", AreaFractionWarning)
        probe = dense.load_curve(np.geomspace(1e-2, 1e5, 60))
    fraction = probe.area / DENSE.area  # independent of the property under test
    inside = probe.P[(fraction > 0.1) & (fraction < 1.0)]
    assert inside.size >= 2
    with pytest.warns(AreaFractionWarning, match=r"of the nominal area \(above 10 % from P = ") as record:
        curve = dense.load_curve(inside)
    assert len(record) == 1  # once per call, not once per point
    assert f"from P = {inside.min():.4g} N" in str(record[0].message)  # all of them pass 10 %
    assert str(record[0].message) == curve.validity_warnings()[0]
    assert curve.area_fraction_high and not curve.exceeds_nominal_area
    assert curve.max_area_fraction == pytest.approx(np.max(curve.area) / DENSE.area, rel=1e-15)


def test_beyond_the_nominal_area_warns_that_the_model_is_broken(dense):
    with pytest.warns(AreaFractionWarning, match=r"times the nominal area .*not physical") as record:
        curve = dense.load_curve([1.0, 1e5])
    assert len(record) == 1 and curve.exceeds_nominal_area and curve.area[-1] > DENSE.area


def test_separation_curves_warn_too(dense):
    with pytest.warns(AreaFractionWarning):
        dense.separation_curve([-20e-9, 0.0])


def test_users_can_filter_or_escalate(dense):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", asperity.AreaFractionWarning)
        dense.load_curve([1e5])
    with warnings.catch_warnings():
        warnings.simplefilter("error", asperity.AreaFractionWarning)
        with pytest.raises(AreaFractionWarning):
            dense.load_curve([1e5])


def test_warning_points_at_the_callers_line(dense):
    with pytest.warns(AreaFractionWarning) as record:
        dense.load_curve([1e5])
    assert record[0].filename == __file__


def test_warn_area_fraction_checks_its_inputs():
    warn_area_fraction(0.05)
    warn_area_fraction(float("nan"))
    with pytest.raises(TypeError, match="fraction must be a real number"):
        warn_area_fraction("0.5")
    with pytest.raises(TypeError, match="stacklevel must be an integer"):
        warn_area_fraction(0.5, stacklevel=1.5)


def test_pull_off_reports_the_area_at_pull_off(dense):
    po = dense.pull_off()
    assert po.exists and po.nominal_area == DENSE.area
    ref = dense.separation_curve([po.d]).area[0]  # the API's own area at that separation
    assert po.area == pytest.approx(ref, rel=1e-12) and po.area_fraction == pytest.approx(ref / DENSE.area)
    d = po.to_dict()
    assert d == {"pull_off_N": po.force, "d_m": po.d, "exists": True, "area_m2": po.area,
                 "area_fraction": po.area_fraction}
    json.dumps(d, allow_nan=False)


def test_pull_off_without_adhesion_has_no_area():
    po = PhysicalContact("Au", DENSE, adhesion=False).pull_off()
    assert not po.exists and po.area == 0.0
    assert po.to_dict()["d_m"] is None
    json.dumps(po.to_dict(), allow_nan=False)


def test_the_above_100_percent_message_names_the_load_where_100_percent_is_passed():
    """Found by a review: the message said 'above 100 % from P = 0.1 N' where the area was
    12 % of the nominal; it must name the first load past 100 %, read off the curve."""
    contact = PhysicalContact("Au", Surface("2nm", "1um", "1e12/m^2", "1e-10m^2"), adhesion=False)
    P = [1e-2, 1e-1, 0.3, 1.0, 10.0]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        curve = contact.load_curve(P)
    fraction = np.asarray(curve.area_fraction)
    first = P[int(np.argmax(fraction > 1.0))]
    assert fraction.max() > 1.0 and fraction[1] < 1.0
    (message,) = curve.validity_warnings()
    assert f"above 100 % from P = {first:.4g} N" in message
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        below = contact.load_curve(P[:3])
    first10 = P[int(np.argmax(np.asarray(below.area_fraction) > 0.1))]
    assert f"above 10 % from P = {first10:.4g} N" in below.validity_warnings()[0]


@pytest.mark.parametrize("sigma_s, noted", [(1e-10, False), (1e-9, True)])
def test_the_pull_off_note_weighs_the_chance_that_no_asperity_touches(sigma_s, noted):
    """A user trial: one summit (N = 1) touching with probability 0.99998 was noted as 'carried
    by 1 asperities ... fewer than one, so ... most likely no pull-off'.  With N independent
    summits none touches with probability (1 - n/N)^N: 2e-5 there (no note), 0.525 for the
    rougher one (n = 0.475, noted with that probability)."""

    contact = PhysicalContact("Au", Surface(sigma_s, 5e-8, 1e12, 1e-12))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        po = contact.pull_off()
    notes = [str(w.message) for w in caught if "carried by" in str(w.message)]
    n = float(contact.separation_curve([po.d]).contacts[0])  # contact.N == 1
    assert contact.N == pytest.approx(1.0) and po.exists
    assert (n < 0.5) == noted and len(notes) == noted
    if noted:
        assert f"carried by {n:.3g} asperities" in notes[0] and f"with probability {1 - n:.3g}" in notes[0]


def test_a_pull_off_carried_by_less_than_one_asperity_is_noted():
    """Found by a review: a pull-off of 3e-23 N, carried by 6e-15 asperities on average, was
    reported like any other.  The note gives the expected number in contact at pull-off,
    N times the model's contact fraction there (read off the separation curve)."""
    from asperity.bodies import contact_material

    weak = PhysicalContact(contact_material(E="70GPa", nu=0.2, b="0.25nm", w="0.05J/m^2"),
                           Surface("2nm", "1um", "1e12/m^2", "1mm^2"))
    with pytest.warns(asperity.AsperityWarning, match=r"carried by (.*) asperities in contact") as record:
        po = weak.pull_off()
    expected = weak.separation_curve([po.d]).contacts[0]
    assert f"carried by {expected:.3g} asperities" in str(record[0].message) and expected < 1.0
    assert "has none in contact there with probability 1, so it would most likely show no pull-off" in \
        str(record[0].message)
    strong = PhysicalContact("Au", Surface("2nm", "1um", "1e12/m^2", "1mm^2"))
    with warnings.catch_warnings():
        warnings.simplefilter("error", asperity.AsperityWarning)
        warnings.simplefilter("ignore", asperity.PlasticityWarning)
        assert strong.pull_off().exists
