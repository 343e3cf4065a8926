"""Worked example: when do asperities yield, and what does it change?

Run:  python examples/plasticity.py [--out DIR]

Two contacts, both without adhesion (the elastic-plastic law has none):

1. A polished disk under a flat slider, R = 5 um, sigma_s = 1 nm, in silicon and in nickel.
   The plasticity index psi = (E*/H)(sigma_s/R)^(1/2) says silicon stays elastic (psi = 0.25)
   and nickel yields (psi = 4.9): the elastic model warns for nickel
   (asperity.PlasticityWarning), and the Jackson-Green law gives a larger real area, a
   mean pressure near the hardness and a higher friction force at the same load.
2. A nanometre gold contact, summits of R = 20 nm and 100 nm on sigma_s = 1 nm.  With the
   handbook hardness every contacting asperity yields at once (omega_c < 0.1 pm).  The
   Nix-Gao size effect, H = H0 (1 + h*/omega)^(1/2) at each asperity's interference omega,
   raises the critical interference to a fraction of a nanometre and lets most asperities
   stay elastic.  h* = 1 um is an illustrative value of the order Nix and Gao report for
   annealed fcc metals (1.6 um for copper); the table has no sourced h* for gold.

Writes DIR/plasticity.png (three panels) and DIR/plasticity.csv; needs matplotlib for the
figure (pip install 'asperity[plot]').
"""

import argparse
import pathlib
import warnings

import numpy as np

from asperity import PlasticityWarning
from asperity.physical import PhysicalContact, Surface

DISK = Surface(sigma_s=1e-9, R=5e-6, eta=1e11, area=1e-6)  # 1 mm^2 of a polished disk
DISK_LOADS = np.geomspace(1e-4, 10.0, 30)  # N
GOLD_RADII = (20e-9, 100e-9)
GOLD_LOADS = np.geomspace(1e-7, 1e-3, 30)  # N on 100 um^2
H_STAR = 1e-6  # m, illustrative (see the module docstring)


def gold_surface(R):
    return Surface(sigma_s=1e-9, R=R, eta=1e15, area=1e-10)


def disk_curves():
    """Elastic and Jackson-Green load curves of the silicon and nickel disks, and the warnings met."""
    out = {}
    for name in ("Si", "Ni"):
        elastic = PhysicalContact(name, DISK, adhesion=False)
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always", PlasticityWarning)
            e = elastic.load_curve(DISK_LOADS)
        p = PhysicalContact(name, DISK, adhesion=False, plasticity="jackson-green").load_curve(DISK_LOADS)
        out[name] = {"contact": elastic, "elastic": e, "plastic": p,
                     "warnings": [str(w.message) for w in caught if w.category is PlasticityWarning]}
    return out


def gold_curves():
    """Jackson-Green load curves of the gold nano-contacts, without and with the size effect."""
    out = {}
    for R in GOLD_RADII:
        plain = PhysicalContact("Au", gold_surface(R), adhesion=False, plasticity="jackson-green")
        sized = PhysicalContact("Au", gold_surface(R), adhesion=False, plasticity="jackson-green",
                                hardness=plain.hardness, h_star=H_STAR)
        out[R] = {"plain": plain, "sized": sized, "plain_curve": plain.load_curve(GOLD_LOADS),
                  "sized_curve": sized.load_curve(GOLD_LOADS)}
    return out


def share(curve):
    """Share of the asperities in contact that have yielded."""
    return curve.plastic / curve.contacts


def figure(disks, gold, path):
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    fig = Figure(figsize=(13, 4), layout="constrained")
    FigureCanvasAgg(fig)
    ax1, ax2, ax3 = fig.subplots(1, 3)
    for name, style in (("Si", "b"), ("Ni", "r")):
        d = disks[name]
        ax1.loglog(DISK_LOADS, d["elastic"].area, style + "o--", markevery=4, markerfacecolor="none",
                   label=f"{name}, elastic")
        ax1.loglog(DISK_LOADS, d["plastic"].area, style + "-", label=f"{name}, Jackson-Green")
        ax2.semilogx(DISK_LOADS, d["plastic"].mu, style + "-", label=f"{name}, Jackson-Green")
        ax2.semilogx(DISK_LOADS, d["elastic"].mu, style + "o--", markevery=4, markerfacecolor="none",
                     label=f"{name}, elastic")
    ax1.set(xlabel="load $P$ (N)", ylabel="real contact area (m$^2$)", title="polished disk, R = 5 um")
    ax2.set(xlabel="load $P$ (N)", ylabel=r"$\mu$ (Hurtado-Kim on the real area)", title="polished disk")
    ax1.legend(fontsize=8)
    ax2.legend(fontsize=8)
    for R, style in zip(GOLD_RADII, ("k", "g"), strict=True):
        g = gold[R]
        ax3.semilogx(GOLD_LOADS, share(g["plain_curve"]), style + "--", label=f"R = {R * 1e9:g} nm, H = 188 MPa")
        ax3.semilogx(GOLD_LOADS, share(g["sized_curve"]), style + "-",
                     label=f"R = {R * 1e9:g} nm, Nix-Gao h* = {H_STAR * 1e6:g} um")
    ax3.set(xlabel="load $P$ (N)", ylabel="yielded share of the contacts", ylim=(0, 1.05),
            title="nanometre gold contact, sigma_s = 1 nm")
    ax3.legend(fontsize=8)
    fig.savefig(path, dpi=120)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", default="plasticity", help="output directory (default ./plasticity)")
    args = parser.parse_args(argv)
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)

    disks = disk_curves()
    print("1. Polished disk, sigma_s = 1 nm, R = 5 um, no adhesion")
    for name, d in disks.items():
        c, e, p = d["contact"], d["elastic"], d["plastic"]
        print(f"  {name}: psi = {c.plasticity_index:.3g}, omega_c = {c.critical_interference:.3g} m; "
              f"at {DISK_LOADS[-1]:g} N: yielded {share(p)[-1]:.1%} of the contacts, real area x"
              f"{p.area[-1] / e.area[-1]:.3g}, mean pressure {p.pressure[-1] / 1e6:.4g} MPa "
              f"(elastic {e.pressure[-1] / 1e6:.4g} MPa, hardness {c.hardness / 1e6:.4g} MPa), "
              f"mu {p.mu[-1]:.3g} (elastic {e.mu[-1]:.3g})")
        for message in d["warnings"]:
            print(f"     the elastic model warned: {message}")

    gold = gold_curves()
    print("\n2. Nanometre gold contact, sigma_s = 1 nm, Jackson-Green law, no adhesion")
    for R, g in gold.items():
        print(f"  R = {R * 1e9:g} nm: omega_c = {g['plain'].critical_interference:.3g} m without, "
              f"{g['sized'].critical_interference:.3g} m with the size effect (h* = {H_STAR:g} m); yielded share "
              f"at {GOLD_LOADS[0]:g} N: {share(g['plain_curve'])[0]:.1%} -> {share(g['sized_curve'])[0]:.1%}, "
              f"at {GOLD_LOADS[-1]:g} N: {share(g['plain_curve'])[-1]:.1%} -> {share(g['sized_curve'])[-1]:.1%}")

    rows = ["load_N,R_m,yielded_share_plain,yielded_share_size_effect,mu_plain,mu_size_effect"]
    for R, g in gold.items():
        for i, P in enumerate(GOLD_LOADS):
            values = (P, R, share(g["plain_curve"])[i], share(g["sized_curve"])[i], g["plain_curve"].mu[i],
                      g["sized_curve"].mu[i])
            rows.append(",".join(repr(float(v)) for v in values))  # plain numbers (NumPy 2 reprs np.float64(...))
    (out / "plasticity.csv").write_text("\n".join(rows) + "\n", encoding="utf-8")
    try:
        figure(disks, gold, out / "plasticity.png")
        print(f"\nwrote {out / 'plasticity.png'} and {out / 'plasticity.csv'}")
    except ImportError:
        print(f"\nwrote {out / 'plasticity.csv'} (no figure: pip install 'asperity[plot]')")
    return disks, gold


if __name__ == "__main__":
    main()
