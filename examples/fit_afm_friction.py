"""Worked example: fit friction-versus-load data with the rough-surface model and the single-asperity laws.

Run:  python examples/fit_afm_friction.py [DATA.csv] [--out DIR]

The default data file, examples/data/afm_friction_synthetic.csv, is SYNTHETIC: written by
examples/data/make_afm_friction.py from asperity's rough-surface model for a gold-like
colloidal probe (120 summits), with 3 % noise and a stated uncertainty column.  The example

1. fits the rough-surface model (``gw``, through a PhysicalContact: material and summit
   statistics known; the work of adhesion and the Hurtado-Kim shear strength of small
   contacts free, that of large contacts tied to it as in the paper, tau2 = tau1/30: the
   data hold no contact large enough to measure it on its own);
2. fits the laws AFM users fit by hand, F = tau pi a(P)^2 with the JKR, DMT and exact
   Maugis-Dugdale radius of a 2 um probe, the COS form and Amontons with an offset;
3. ranks all of them by AIC (with Wald intervals: the ranking needs none) and draws data,
   fits and residuals to DIR/fit_afm_friction.png.

Give your own file (columns 'load [nN]', 'friction [nN]', optionally 'friction_err [nN]')
to fit real data.  Needs: pip install 'asperity[fit,plot]'.
"""

import argparse
import dataclasses
import pathlib

import numpy as np

from asperity.fit import Comparison, compare_models, fit_friction_load, read_data
from asperity.materials import material
from asperity.physical import PhysicalContact, Surface

HERE = pathlib.Path(__file__).resolve().parent
DATA = HERE / "data" / "afm_friction_synthetic.csv"
#: What is known about the probe and the surface (an AFM scan would give the summit statistics).
SURFACE = Surface(sigma_s=2e-9, R=300e-9, eta=3e13, area=4e-12)
PROBE_RADIUS = 2e-6  # the radius of the colloidal probe, for the single-asperity laws


def fit_all(data):
    """(gw result, comparison of everything ranked by AIC)."""
    gold = dataclasses.replace(material("Au"), w=0.2)  # a first guess of w; the fit finds it
    contact = PhysicalContact(gold, SURFACE)
    gw = fit_friction_load(data, "gw", contact=contact, vary=["w_J_m2", "tau1_Pa"], expr={"tau2_Pa": "tau1_Pa / 30"})
    laws = compare_models(data, ["jkr", "dmt", "md", "cos", "amontons"], material=gold,
                          fix={"R_m": PROBE_RADIUS}, ci="wald")
    ranked = Comparison(tuple(sorted([gw, *laws.results], key=lambda r: r.aic)))
    return gw, ranked


def figure(data, ranked, path):
    """Data with every fitted curve (top) and the residuals of the best two (bottom)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(7.5, 6.0), layout="constrained")
    FigureCanvasAgg(fig)
    top, bottom = fig.subplots(2, 1, sharex=True, gridspec_kw={"height_ratios": [3, 1.2]})
    top.errorbar(data.x * 1e9, data.y * 1e9, yerr=data.y_err * 1e9, fmt="o", ms=4, color="k", label="synthetic data")
    for k, res in enumerate(ranked.results):
        cols = res.curve.columns()
        P, F = cols["P_N"], cols["F_N"]
        order = np.argsort(P)
        top.plot(P[order] * 1e9, F[order] * 1e9, "-", color=f"C{k}", lw=2 if k == 0 else 1,
                 label=f"{res.model}  (AIC {res.aic:.1f})")
        if k < 2:
            bottom.plot(data.x * 1e9, res.residuals, "o-", ms=3, color=f"C{k}", label=res.model)
    bottom.axhline(0.0, color="0.6", lw=0.8)
    top.set_ylabel("friction (nN)")
    top.legend(fontsize="small")
    bottom.set_xlabel("load (nN)")
    bottom.set_ylabel("residual / sigma")
    bottom.legend(fontsize="small")
    fig.suptitle("Friction against load: rough-surface model vs single-asperity laws", fontsize="medium")
    fig.savefig(path, dpi=130)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("data", nargs="?", default=str(DATA), help="friction-load CSV (default: the synthetic file)")
    parser.add_argument("--out", default="fit-afm", help="output directory (default ./fit-afm)")
    args = parser.parse_args(argv)
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    data = read_data(args.data)
    gw, ranked = fit_all(data)
    print(gw.summary())
    print(ranked.summary())
    best_law = next(r for r in ranked.results if r.model != "gw")
    print(f"best single-asperity law: {best_law.model}")
    print(best_law.summary())
    figure(data, ranked, out / "fit_afm_friction.png")
    print(f"figure: {out / 'fit_afm_friction.png'}")
    return gw, ranked


if __name__ == "__main__":
    main()
