"""Every unit spelling the help promises gives exactly what the Python API gives.

For each option with a unit and each spelling (nm, um, µm, μm, micron, m, Å, pm; mN, uN,
µN, nN, N; GPa, MPa, kPa, Pa; J/m^2, mJ/m^2, N/m; 1/m^2, 1/um^2, um^-2, m^-2; mm^2, um^2,
m^2), the command's JSON equals the API called with the same text, and the SI value equals
the number typed by hand.
"""

import json

import numpy as np
import pytest

from asperity.bodies import contact_material
from asperity.physical import PhysicalContact
from asperity.surface import Surface

from .helpers import run, strict_json

#: Gold asperities of these surfaces yield (plasticity index psi ~ 23): the elastic model
#: warns (asperity.PlasticityWarning), tested in tests/test_plasticity.py, not here.
pytestmark = pytest.mark.filterwarnings("ignore::asperity.plasticity.PlasticityWarning")

pytest.importorskip("pint")

#: The reference contact: option -> (text, SI value); each case replaces one of them.
BASE = {"sigma-s": ("2nm", 2e-9), "R": ("1um", 1e-6), "eta": ("1e12/m^2", 1e12), "area": ("1mm^2", 1e-6)}

LENGTHS = [("2nm", 2e-9), ("2 nm", 2e-9), ("0.002um", 2e-9), ("0.002µm", 2e-9), ("0.002μm", 2e-9),
           ("0.002micron", 2e-9), ("2e-9m", 2e-9), ("20Å", 2e-9), ("2000pm", 2e-9)]
STRESSES = [("70GPa", 70e9), ("70000MPa", 70e9), ("7e7kPa", 70e9), ("7e10Pa", 70e9), ("70 GPa", 70e9)]
ENERGIES = [("0.1J/m^2", 0.1), ("100mJ/m^2", 0.1), ("0.1N/m", 0.1), ("0.1 J/m**2", 0.1)]
DENSITIES = [("1e12/m^2", 1e12), ("1/um^2", 1e12), ("1um^-2", 1e12), ("1e12m^-2", 1e12), ("1/µm^2", 1e12),
             ("1 µm^-2", 1e12)]
AREAS = [("1mm^2", 1e-6), ("1e-6m^2", 1e-6), ("1e6um^2", 1e-6), ("1 mm**2", 1e-6)]

#: option -> (what it sets in the API, spellings); the second element scales the case (2nm -> 2 * factor).
CASES = (
    [("sigma-s", t, v) for t, v in LENGTHS] + [("sigma", t, v) for t, v in LENGTHS[:2]]
    + [("R", t, v * 500) for t, v in LENGTHS] + [("radius", "1um", 1e-6)]
    + [("eta", t, v) for t, v in DENSITIES] + [("density", "1/um^2", 1e12)]
    + [("area", t, v) for t, v in AREAS]
    + [("b", t, v / 8) for t, v in LENGTHS] + [("h", t, v / 4) for t, v in LENGTHS[:4]]
    + [("E", t, v) for t, v in STRESSES] + [("E2", t, v) for t, v in STRESSES[:3]]
    + [("sigma0", t, v / 70) for t, v in STRESSES[:4]] + [("tau", t, v / 1400) for t, v in STRESSES]
    + [("w", t, v) for t, v in ENERGIES] + [("rms", t, v) for t, v in LENGTHS[:5]]
)


def _scaled(text: str, factor: float) -> str:
    """``'2nm'`` scaled by ``factor``: ``'1000nm'`` for 500 (the number in front, the unit kept)."""
    import re

    number, unit = re.match(r"^([0-9.eE+-]+)(.*)$", text).groups()
    return f"{float(number) * factor:.12g}{unit}"


def _api(option: str, text: str):
    """The API's contact with ``text`` passed as is (a string with a unit), and the CLI's arguments."""
    surface = {"sigma_s": BASE["sigma-s"][0], "R": BASE["R"][0], "eta": BASE["eta"][0], "area": BASE["area"][0]}
    flags = {"sigma_s": "--sigma-s", "R": "--R", "eta": "--eta", "area": "--area"}
    key = {"sigma": "sigma_s", "sigma-s": "sigma_s", "radius": "R", "density": "eta"}.get(option, option)
    if option in ("sigma", "radius", "density"):  # the old spellings
        flags[key] = f"--{option}"
    body, argv, friction, rms = {"material": "Au"}, ["--material", "Au"], {}, None
    if key in surface:
        surface[key] = text
    elif key == "rms":
        rms = text
    elif key == "tau":
        friction = {"friction": text}
        argv += ["--tau", text]
    elif key == "E2":
        body.update(E2=text, nu2=0.3, w=0.5)
        argv += ["--E2", text, "--nu2", "0.3", "--w", "0.5J/m^2"]
    elif key == "sigma0":
        body.update(sigma0=text, w=0.1)
        argv += ["--sigma0", text, "--w", "0.1J/m^2"]
    else:
        body[key] = text
        argv += [f"--{option}", text]
    if rms is None:
        surf = Surface(**surface)
        argv += [flags["sigma_s"], surface["sigma_s"]]
    else:
        surf = Surface.from_rms(rms, surface["R"], surface["eta"], surface["area"], alpha_n=10.0)
        argv += ["--rms", rms, "--bandwidth", "10"]
    for name in ("R", "eta", "area"):
        argv += [flags[name], surface[name]]
    return PhysicalContact(contact_material(**body), surf, **friction), argv


def _expected(contact, curve):
    cols = curve.columns()
    rows = [{k: float(v[i]) for k, v in cols.items()} for i in range(len(curve))]
    return json.loads(json.dumps({"contact": contact.to_dict(), "rows": rows}).replace("NaN", "null"))


SI_FIELD = {"sigma-s": "sigma_s_m", "sigma": "sigma_s_m", "R": "R_m", "radius": "R_m", "eta": "eta_per_m2",
            "density": "eta_per_m2", "area": "area_m2", "b": "b_m", "h": "h_m", "w": "w_J_m2"}


@pytest.mark.parametrize("option, text, value", CASES, ids=[f"{o}={t}" for o, t, _ in CASES])
def test_option_spellings_equal_the_api(capsys, option, text, value):
    if option in ("R", "b", "h", "sigma0", "tau"):
        factor = {"R": 500, "b": 1 / 8, "h": 1 / 4, "sigma0": 1 / 70, "tau": 1 / 1400}[option]
        text = _scaled(text, factor)
    contact, argv = _api(option, text)
    code, out, err = run(capsys, "separation", *argv, "--separation", "1nm", "--format", "json")
    assert code == 0, err
    got = strict_json(out)
    assert got == _expected(contact, contact.separation_curve(["1nm"]))
    d = got["contact"]
    if option in SI_FIELD:
        assert d[SI_FIELD[option]] == pytest.approx(value, rel=1e-14)
    elif option == "E":
        assert d["body1"]["E_Pa"] == pytest.approx(value, rel=1e-14)
    elif option == "E2":
        assert d["body2"]["E_Pa"] == pytest.approx(value, rel=1e-14)
    elif option == "sigma0":
        assert d["h_m"] == pytest.approx(0.1 / value, rel=1e-14)
    elif option == "tau":
        assert d["friction"]["tau_Pa"] == pytest.approx(value, rel=1e-14)
    elif option == "rms":
        assert d["sigma_s_m"] == pytest.approx(value * (1 - 0.8968 / 10) ** 0.5, rel=1e-14)


LOADS = [("1mN,1N", [1e-3, 1.0]), ("1000uN,1N", [1e-3, 1.0]), ("1000µN,1e3mN", [1e-3, 1.0]),
         ("1e6nN,1N", [1e-3, 1.0]), ("0.001N,1 N", [1e-3, 1.0]), ("1mN:1N:4", np.geomspace(1e-3, 1, 4)),
         ("1000uN:1000mN:4", np.geomspace(1e-3, 1, 4))]


@pytest.mark.parametrize("text, values", LOADS, ids=[t for t, _ in LOADS])
def test_load_spellings(capsys, text, values):
    contact = PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6))
    code, out, _ = run(capsys, "load", "--material", "Au", "--sigma-s", "2nm", "--R", "1um", "--eta", "1e12/m^2",
                       "--area", "1mm^2", "--load", text, "--format", "json")
    assert code == 0
    got = strict_json(out)
    np.testing.assert_allclose([r["P_N"] for r in got["rows"]], values, rtol=1e-14)
    assert got["rows"] == _expected(contact, contact.load_curve(text.split(",") if ":" not in text
                                                                else values))["rows"]


SEPARATIONS = [("0nm,2nm", [0.0, 2e-9]), ("0um,0.002µm", [0.0, 2e-9]), ("-1nm:2nm:4", np.linspace(-1e-9, 2e-9, 4)),
               ("-10Å,20Å", [-1e-9, 2e-9]), ("0m,2e-9m", [0.0, 2e-9])]


@pytest.mark.parametrize("text, values", SEPARATIONS, ids=[t for t, _ in SEPARATIONS])
def test_separation_spellings(capsys, text, values):
    contact = PhysicalContact("Au", Surface(2e-9, 1e-6, 1e12, 1e-6))
    code, out, _ = run(capsys, "separation", "--material", "Au", "--sigma-s", "2nm", "--R", "1um", "--eta",
                       "1e12/m^2", "--area", "1mm^2", "--separation", text, "--format", "json")
    assert code == 0
    got = strict_json(out)
    np.testing.assert_allclose([r["d_m"] for r in got["rows"]], values, rtol=1e-14, atol=1e-24)
    api = contact.separation_curve(text.split(",") if ":" not in text else values)
    assert got["rows"] == _expected(contact, api)["rows"]


# -- asperity surface: --size, --unit, --b ------------------------------------------------------------

HEIGHT_UNITS = [("m", 1.0), ("mm", 1e-3), ("um", 1e-6), ("µm", 1e-6), ("μm", 1e-6), ("nm", 1e-9), ("Å", 1e-10),
                ("pm", 1e-12)]
SIZES = ["5um,5um", "5um", "5µm,5μm", "5000nm,5e-6m", "5micron,5 um", "0.005mm,5um"]


@pytest.fixture(scope="module")
def heights():
    pytest.importorskip("SurfaceTopography")
    from SurfaceTopography.Generation import fourier_synthesis

    topo = fourier_synthesis((64, 64), (5e-6, 5e-6), 0.8, rms_height=6e-9, short_cutoff=0.3e-6,
                             long_cutoff=2e-6, rng=np.random.default_rng(11))
    return topo.heights()  # metres


def _surface_json(capsys, *argv):
    code, out, err = run(capsys, "surface", *argv, "--format", "json")
    assert code == 0, err
    return strict_json(out)


@pytest.mark.parametrize("unit, scale", HEIGHT_UNITS, ids=[u for u, _ in HEIGHT_UNITS])
def test_height_units(capsys, tmp_path, heights, unit, scale):
    from asperity.topography import analyse_surface

    path = tmp_path / "scan.npy"
    np.save(path, heights / scale)
    got = _surface_json(capsys, str(path), "--size", "5um,5um", "--unit", unit)
    api = analyse_surface(path, physical_sizes=("5um", "5um"), unit=unit).to_dict()
    assert got == json.loads(json.dumps(api))
    metres = tmp_path / "metres.npy"
    np.save(metres, heights)
    in_metres = analyse_surface(metres, physical_sizes=(5e-6, 5e-6), unit="m")
    assert got["spectral"]["sigma_s"] == pytest.approx(in_metres.spectral.sigma_s, rel=1e-9)
    assert got["physical_sizes"] == pytest.approx([5e-6, 5e-6], rel=1e-14)


@pytest.mark.parametrize("size", SIZES)
def test_scan_size_spellings(capsys, tmp_path, heights, size):
    from asperity.topography import analyse_surface

    path = tmp_path / "scan.npy"
    np.save(path, heights * 1e9)
    got = _surface_json(capsys, str(path), "--size", size, "--unit", "nm")
    api = analyse_surface(path, physical_sizes=tuple(size.split(",")), unit="nm").to_dict()
    assert got == json.loads(json.dumps(api))
    assert got["physical_sizes"] == pytest.approx([5e-6, 5e-6], rel=1e-14)


@pytest.mark.parametrize("b, value", [("0.2885nm", 2.885e-10), ("2.885Å", 2.885e-10), ("288.5pm", 2.885e-10),
                                      ("2.885e-10m", 2.885e-10)])
def test_surface_burgers_vector_spellings(capsys, tmp_path, heights, b, value):
    from asperity.topography import analyse_surface

    path = tmp_path / "scan.npy"
    np.save(path, heights)
    got = _surface_json(capsys, str(path), "--size", "5um", "--unit", "m", "--b", b)
    assert got["b"] == pytest.approx(value, rel=1e-14)
    assert got == json.loads(json.dumps(analyse_surface(path, physical_sizes=("5um",), unit="m", b=b).to_dict()))
