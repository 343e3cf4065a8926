"""Worked example: an AFM scan of a gold surface -> summit parameters -> friction and pull-off.

Run:  python examples/afm_gold.py [SCAN_FILE] [--out DIR]

Without SCAN_FILE it first writes a synthetic 5 x 5 um AFM scan (a self-affine Gaussian
surface, 6 nm rms, as SurfaceTopography generates) to DIR/gold_scan.x3p, so the example
runs anywhere; give your own AFM or profilometer file (any format SurfaceTopography reads)
to use real data.  Needs: pip install 'asperity[all]'.
"""

import argparse
import pathlib
import warnings

import numpy as np

from asperity import AsperityWarning
from asperity.physical import PhysicalContact
from asperity.topography import analyse_surface


def synthetic_scan(path: pathlib.Path, seed: int = 1) -> pathlib.Path:
    """A 512 x 512 scan of a 5 x 5 um self-affine surface (Hurst 0.8, 6 nm rms) as x3p."""
    from SurfaceTopography.Generation import fourier_synthesis

    topo = fourier_synthesis((512, 512), (5e-6, 5e-6), 0.8, rms_height=6e-9,
                             short_cutoff=0.1e-6, long_cutoff=2e-6, rng=np.random.default_rng(seed))
    topo.to_x3p(str(path))
    return path


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scan", nargs="?", help="AFM height map or profile (default: a synthetic scan)")
    parser.add_argument("--out", default="afm-gold", help="output directory (default ./afm-gold)")
    parser.add_argument("--area", type=float, default=1e-6, help="nominal contact area in m^2 (default 1 mm^2)")
    args = parser.parse_args(argv)
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    scan = pathlib.Path(args.scan) if args.scan else synthetic_scan(out / "gold_scan.x3p")

    # 1. Summit parameters two ways (spectral moments and summit detection).
    analysis = analyse_surface(scan, material=_gold())
    print(analysis.summary())

    # 2. The gold contact over the nominal area, from the spectral summit parameters.
    contact = PhysicalContact("Au", analysis.spectral.surface(args.area))
    print(f"\nN = {contact.N:.3g} asperities, alpha = {contact.alpha:.4g}, beta = {contact.beta:.4g}, "
          f"gamma = {contact.gamma:.4g}, lambda = {contact.lam:.3g}")
    print(f"plasticity index psi = {contact.plasticity_index:.3g} (gold asperities yield at "
          f"{contact.critical_interference:.2g} m: expect a note of asperity.PlasticityWarning; see "
          "examples/plasticity.py)")

    # 3. Friction coefficient versus load in newtons, and the pull-off force.
    loads = np.geomspace(1e-4, 10.0, 60)
    with warnings.catch_warnings(record=True) as caught:  # the library's validity notes, printed below
        warnings.simplefilter("always", AsperityWarning)
        curve = contact.load_curve(loads)
        dry = PhysicalContact("Au", analysis.spectral.surface(args.area), adhesion=False).load_curve(loads)
    for message in dict.fromkeys(str(w.message) for w in caught if issubclass(w.category, AsperityWarning)):
        print(f"note: {message}")
    pull = contact.pull_off()
    if pull.exists:
        print(f"pull-off force {pull.force:.4g} N at separation {pull.d * 1e9:.3g} nm")
    else:
        print("no pull-off force: the contact stays compressive out to 10 sigma")
    for P in (1e-3, 1e-1, 10.0):
        i = int(np.argmin(abs(loads - P)))
        print(f"  P = {loads[i]:8.3g} N: mu = {curve.mu[i]:.4g} (without adhesion {dry.mu[i]:.4g}), "
              f"real contact area {curve.area[i]:.3g} m^2 ({curve.area[i] / args.area:.2%} of nominal)")
    curve.to_csv(out / "mu_vs_load.csv")
    _plot(loads, curve, dry, pull, out / "afm_gold.png")
    print(f"wrote {out / 'mu_vs_load.csv'} and {out / 'afm_gold.png'}")
    return curve, pull


def _gold():
    from asperity.materials import material

    return material("Au")


def _plot(loads, curve, dry, pull, path):
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    fig = Figure(figsize=(6, 4.5), layout="constrained")
    ax = fig.add_subplot()
    ax.loglog(loads, curve.mu, "-", color="#b8860b", label="gold, with adhesion (Maugis-Dugdale)")
    ax.loglog(loads, dry.mu, "--", color="0.3", label="without adhesion (Hertz)")
    ax.set_xlabel("normal load $P$ (N)")
    ax.set_ylabel(r"friction coefficient $\mu$")
    ax.set_title(f"Au on a rigid flat, summits from an AFM scan; pull-off force {pull.force:.3g} N", fontsize=10)
    ax.legend()
    fig.savefig(path, dpi=150)


if __name__ == "__main__":
    main()
