"""Worked example: a worn (skewed) surface against the Gaussian of the same sigma_s.

Run:  python examples/skewed_surface.py [SCAN_FILE] [--out DIR]

Without SCAN_FILE it writes a synthetic 5 x 5 um scan of a run-in surface to
DIR/worn_scan.x3p: a self-affine Gaussian surface (6 nm rms) whose highest 15 % of heights
have been worn down to a third, so its summit heights are negatively skewed, as on
polished, run-in or plateau-honed parts.  Then:

1. the summit parameters (sigma_s, R, eta) and the skewness and kurtosis of the detected
   summit heights; the height distributions fitted to them, ranked by AIC;
2. a gold contact with these summit parameters, once with Gaussian heights (the paper's
   Eq 19) and once with the best-ranked distribution -- the same sigma_s, R and eta, only
   the shape differs;
3. mu(P) from 10 mN to 1 kN and the pull-off force of both, written to DIR/skewed_surface.png and
   DIR/mu_gaussian_vs_measured.csv.

Needs: pip install 'asperity[all]'.
"""

import argparse
import pathlib

import numpy as np

from asperity.heights import GAUSSIAN
from asperity.physical import PhysicalContact
from asperity.topography import analyse_surface

#: The worn surface: heights above this quantile are worn down to WEAR of their excess.
WORN_QUANTILE, WEAR = 0.85, 1.0 / 3.0


def worn_scan(path: pathlib.Path, seed: int = 1) -> pathlib.Path:
    """A 512 x 512 scan of a 5 x 5 um self-affine surface (Hurst 0.8, 6 nm rms), its top worn flat, as x3p."""
    import warnings

    with warnings.catch_warnings():  # SurfaceTopography's notice that mpi4py (not needed here) is missing
        warnings.filterwarnings("ignore", message="Could not import mpi4py", category=ImportWarning)
        from SurfaceTopography import Topography
        from SurfaceTopography.Generation import fourier_synthesis

    topo = fourier_synthesis((512, 512), (5e-6, 5e-6), 0.8, rms_height=6e-9,
                             short_cutoff=0.1e-6, long_cutoff=2e-6, rng=np.random.default_rng(seed))
    h = topo.heights()
    level = np.quantile(h, WORN_QUANTILE)
    worn = np.where(h > level, level + WEAR * (h - level), h)
    Topography(worn, topo.physical_sizes, unit="m").to_x3p(str(path))
    return path


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("scan", nargs="?", help="AFM height map (default: a synthetic worn surface)")
    parser.add_argument("--out", default="skewed-surface", help="output directory (default ./skewed-surface)")
    parser.add_argument("--area", type=float, default=1e-6, help="nominal contact area in m^2 (default 1 mm^2)")
    args = parser.parse_args(argv)
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    scan = pathlib.Path(args.scan) if args.scan else worn_scan(out / "worn_scan.x3p")

    # 1. Summit parameters, the shape of the summit heights, and the ranked fits.
    analysis = analyse_surface(scan)
    print(analysis.summary())
    fit = analysis.heights
    measured = fit.best

    # 2. The same summit parameters (detected: sigma_s is the summits' own deviation), two shapes.
    surface = analysis.detected.surface(args.area)
    contacts = {"Gaussian (Eq 19)": PhysicalContact("Au", surface, heights=GAUSSIAN),
                f"measured shape ({measured.name})": PhysicalContact("Au", surface, heights=measured)}

    # 3. mu(P) and pull-off for both.  The model is elastic; gold asperities this sharp yield
    # (asperity.PlasticityWarning): the comparison is of the two shapes in the elastic model,
    # and the note is printed once.
    import warnings

    from asperity import AsperityWarning

    loads = np.geomspace(1e-2, 1e3, 60)
    with warnings.catch_warnings(record=True) as caught:  # yield, and a real area past 10 % of the nominal
        warnings.simplefilter("always", AsperityWarning)
        curves = {name: c.load_curve(loads) for name, c in contacts.items()}
        pulls = {name: c.pull_off() for name, c in contacts.items()}
    for note in dict.fromkeys(str(w.message).split(" but ")[0].split(": neighbouring")[0] for w in caught
                              if issubclass(w.category, AsperityWarning)):
        print(f"note (elastic model): {note}")
    print(f"\nsummit skewness {fit.skewness:.3g}, kurtosis {fit.kurtosis:.3g}; sigma_s = "
          f"{surface.sigma_s * 1e9:.3g} nm, R = {surface.R * 1e6:.3g} um, eta = {surface.eta * 1e-12:.3g} /um^2")
    for name in contacts:
        c, p = curves[name], pulls[name]
        mu = ", ".join(f"{c.mu[np.argmin(abs(loads - P))]:.4g}" for P in (1.0, 100.0, 1000.0))
        print(f"  {name:28s} pull-off {p.force:.4g} N; mu at 1 N, 100 N, 1000 N: {mu}")
    gauss, skew = (curves[n] for n in contacts)
    _write_csv(out / "mu_gaussian_vs_measured.csv", loads, gauss.mu, skew.mu)
    _plot(loads, curves, pulls, analysis, out / "skewed_surface.png")
    print(f"wrote {out / 'mu_gaussian_vs_measured.csv'} and {out / 'skewed_surface.png'}")
    return analysis, curves, pulls


def _write_csv(path, loads, mu_gauss, mu_measured):
    lines = ["P_N,mu_gaussian,mu_measured"] + [f"{float(p)!r},{float(a)!r},{float(b)!r}"
                                                for p, a, b in zip(loads, mu_gauss, mu_measured, strict=True)]
    path.write_text("\n".join(lines) + "\n")


def _plot(loads, curves, pulls, analysis, path):
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    fig = Figure(figsize=(10, 4.2), layout="constrained")
    ax, hx = fig.subplots(1, 2)
    styles = ("-", "--")
    for (name, curve), style in zip(curves.items(), styles, strict=True):
        ax.loglog(loads, curve.mu, style, label=f"{name}; pull-off {pulls[name].force:.3g} N")
    ax.set_xlabel("normal load $P$ (N)")
    ax.set_ylabel(r"friction coefficient $\mu$")
    ax.set_title("Au on a rigid flat: same $\\sigma_s$, $R$, $\\eta$; two height shapes", fontsize=10)
    ax.legend(fontsize=8)

    z = analysis.summit_heights
    zs = (z - z.mean()) / z.std()
    hx.hist(zs, bins=40, density=True, color="0.8", label=f"{zs.size} detected summits")
    grid = np.linspace(zs.min() - 1.0, zs.max() + 1.0, 400)
    hx.semilogy(grid, GAUSSIAN.pdf(grid), "-", label="Gaussian")
    hx.semilogy(grid, np.maximum(analysis.heights.best.pdf(grid), 1e-6), "--",
                label=f"best fit ({analysis.heights.best.name}, by AIC)")
    hx.set_ylim(1e-4, 1.0)
    hx.set_xlabel(r"summit height $(z - \bar z)/\sigma_s$")
    hx.set_ylabel("density")
    hx.set_title(f"skewness {analysis.heights.skewness:.2f}, kurtosis {analysis.heights.kurtosis:.2f}",
                 fontsize=10)
    hx.legend(fontsize=8)
    fig.savefig(path, dpi=150)


if __name__ == "__main__":
    main()
