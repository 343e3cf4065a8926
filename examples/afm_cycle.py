"""Worked example: an AFM colloidal probe of gold on a rough gold surface, approach and retract.

Run:  python examples/afm_cycle.py [--out DIR] [--stiffness K] [--preload P]

A gold colloid (radius about 25 um) on a cantilever approaches a rough gold surface, is pressed
on with a preload, and is pulled off again.  The colloid meets the surface over the cap where
the gap is within a few summit heights: about 1 um^2, the nominal area here (flat-on-flat, as
the Greenwood-Williamson model assumes).  The surface: summit heights 2 nm rms, summit radius
100 nm, 2e14 summits per m^2 (one per 70 nm square), so N = 200 asperities.  Gold from the
materials table: clean surfaces in vacuum (work of adhesion 2 x 1.506 J/m^2).

It prints the pull-off force, the energy dissipated per cycle (joules, and joules per nominal
area), the jumps of the cantilever, and the pull-off against preload; it writes the measured
curve (cycle.csv), pull-off and energy against preload (preload.csv) and the figure
(afm_cycle.png): force against the cantilever base displacement in nanonewtons and nanometres,
the surface's own loop under displacement control, and pull-off and energy against preload.
Needs: pip install 'asperity[plot,units]'.
"""

import argparse
import pathlib
import warnings

import numpy as np

from asperity import AsperityWarning
from asperity.physical import PhysicalContact, Surface

#: The colloid-on-surface contact: summit height deviation, summit radius, summit density, nominal area (SI).
SURFACE = Surface(sigma_s=2e-9, R=100e-9, eta=2e14, area=1e-12)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", default="afm-cycle", help="output directory (default ./afm-cycle)")
    parser.add_argument("--stiffness", type=float, default=10.0, help="cantilever stiffness in N/m (default 10)")
    parser.add_argument("--preload", type=float, default=5e-6, help="largest compressive load in N (default 5 uN)")
    args = parser.parse_args(argv)
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)

    contact = PhysicalContact("Au", SURFACE)
    print(f"N = {contact.N:.0f} asperities, alpha = {contact.alpha:.4g}, beta = {contact.beta:.4g}, "
          f"gamma = {contact.gamma:.4g}, lambda = {contact.lam:.3g} (force unit N G b^2 = {contact.force_scale:.3g} N)")

    with warnings.catch_warnings(record=True) as notes:  # the library's notes, printed once below
        warnings.simplefilter("always", AsperityWarning)
        # 1. Displacement control (an infinitely stiff instrument): the surface's own hysteresis.
        surface_only = contact.cycle(preload=args.preload, n=400)
        # 2. Through the cantilever: the curve the AFM records, with jump-in and jump-out.
        measured = contact.cycle(preload=args.preload, n=400, stiffness=args.stiffness)
    for message in dict.fromkeys(str(n.message) for n in notes):
        # gold summits this sharp yield under the preload: the elastic (adhesive) model says so; its
        # plastic alternative has no adhesion and no unloading, so the loop is kept elastic here
        print(f"note: {message}")
    for name, c in (("displacement control", surface_only), (f"cantilever k = {args.stiffness:g} N/m", measured)):
        print(f"\n{name}: closest approach {c.d_min_m * 1e9:.3g} nm under {c.preload_N * 1e9:.4g} nN")
        print(f"  pull-off force {c.pull_off.force * 1e9:.4g} nN at separation {c.pull_off.d * 1e9:.3g} nm")
        print(f"  energy dissipated per cycle {c.energy_J:.4g} J = {c.energy_J_m2:.4g} J/m^2 of nominal area "
              f"({c.loop_count:.3g} asperities through the whole loop, {c.loop_energy_J:.3g} J each; "
              f"{c.jump_energy_J:.3g} J lost in the jumps)")
        for j in c.jumps:
            print(f"  jump {'into' if j['branch'] == 'approach' else 'out of'} contact at base position "
                  f"{j['d_base_m'] * 1e9:.4g} nm: separation {j['d_from_m'] * 1e9:.3g} -> {j['d_to_m'] * 1e9:.3g} nm, "
                  f"force {j['P_from_N'] * 1e9:.4g} -> {j['P_to_N'] * 1e9:.4g} nN")

    # 3. Pull-off and energy against preload (one vectorised call).
    preloads = np.geomspace(1e-9, 1e-4, 40)
    sweep = contact.preload_curve(preloads)
    paper = contact.pull_off()
    print(f"\npull-off against preload: {sweep.pull_off_N[0] * 1e9:.4g} nN at {preloads[0] * 1e9:.3g} nN, "
          f"{sweep.pull_off_N[-1] * 1e9:.4g} nN at {preloads[-1] * 1e9:.3g} nN "
          f"(the paper's pull-off, from full contact: {paper.force * 1e9:.4g} nN)")

    measured.to_csv(out / "cycle.csv")
    sweep.to_csv(out / "preload.csv")
    _plot(measured, surface_only, preloads, sweep, paper, out / "afm_cycle.png")
    print(f"wrote {out / 'cycle.csv'}, {out / 'preload.csv'} and {out / 'afm_cycle.png'}")
    return surface_only, measured, sweep


def _plot(measured, surface_only, preloads, sweep, paper, path):
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    from asperity.cycle_plot import plot_cycle

    fig = Figure(figsize=(15, 4.6), layout="constrained")
    FigureCanvasAgg(fig)
    ax1, ax4, ax2 = fig.subplots(1, 3)
    plot_cycle(measured, ax1, title=f"what the AFM records: cantilever {measured.stiffness_N_m:g} N/m")
    plot_cycle(surface_only, ax4, title="the surface's own loop (displacement control)")
    ax4.set_xlabel("separation d (nm)")
    ax2.semilogx(preloads * 1e9, sweep.pull_off_N * 1e9, "k-", label="pull-off force")
    ax2.axhline(paper.force * 1e9, color="k", ls="--", lw=0.8, label="paper's pull-off (full contact)")
    ax2.set_xlabel("preload (nN)")
    ax2.set_ylabel("pull-off force (nN)")
    ax3 = ax2.twinx()
    ax3.semilogx(preloads * 1e9, sweep.energy_J * 1e15, "tab:green", label="energy dissipated")
    ax3.set_ylabel("energy dissipated per cycle (fJ)", color="tab:green")
    ax2.legend(fontsize=8, loc="center left")
    ax2.set_title("pull-off and energy against preload (displacement control)", fontsize=9)
    fig.savefig(path, dpi=150)


if __name__ == "__main__":
    main()
