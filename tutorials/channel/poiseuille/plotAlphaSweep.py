#!/usr/bin/env python3
"""Scene 1's study of the bounce layer (./Allrun -alphaSweep): per alpha, for the FCC and the mask's
random wall (one seed each, alphaSweep/<case>_alpha<a>), the particles the layer returns and those
found behind the wall per unit time and area, the density next to the wall, the slip length, nu and
kT within one cutoff of the wall. Writes resultsAlphaSweep.dat and alphaSweep.png; information, no
checks (the published scene's checks are plotResults.py's).
"""
import sys

from dpdfoam.channel import no_wall_reference
from dpdfoam.checks import write_results
from dpdfoam.io import body_force, numbered_cases
from dpdfoam.plots import label, plt, save
from plotResults import QUANTITIES, SeedRun  # this tutorial's runs, beside this script

CASES = (("FCC", "fcc", "blockFrozenWallDict"), ("random, mask", "randomMask", "randomEquilWallDict"))
SHOWN = (("slip", "slip length b"), ("nu", "nu"), ("rhoNear", "density within one cutoff / bulk"),
         ("kTNear", "kT within one cutoff"), ("returned", "returned per unit time and area"),
         ("crossed", "found behind the wall per unit time and area"))


def main():
    ref = no_wall_reference()
    nu_ref, kT_of_shear = ref["nu"], ref["kT_of_shear"]
    g = body_force("fcc")
    lines = [f"# The bounce layer's thickness alpha (one seed each): nu without walls {nu_ref:.5f}",
             "# wall         alpha " + " ".join(f"{k:>14s}" for k in QUANTITIES)]
    sweeps = {}
    for wall, case, builder in CASES:
        cases = numbered_cases(f"alphaSweep/{case}_alpha", "./Allrun -alphaSweep", "plotAlphaSweep", "<a>")
        alphas, runs = [a for a, _ in cases], [SeedRun(p, builder, kT_of_shear, g, nu_ref) for _, p in cases]
        sweeps[wall] = (alphas, runs)
        lines += [f"{wall.replace(' ', '_'):12s} {a:6g} " + " ".join(f"{r.q[k]:14.5f}" for k in QUANTITIES)
                  for a, r in zip(alphas, runs)]
    write_results("resultsAlphaSweep.dat", lines)

    fig, ax = plt.subplots(2, 3, figsize=(14, 8))
    for a, (key, title) in zip(ax.flat, SHOWN):
        for (wall, (alphas, runs)), marker in zip(sweeps.items(), "os"):
            a.plot(alphas, [r.q[key] for r in runs], marker + "-", mfc="none", label=wall)
        a.set_xscale("log")
        label(a, title, "alpha", legend=8)
    ax[0, 1].axhline(nu_ref, color="k", lw=0.8)
    fig.suptitle("Scene 1: the bounce layer's thickness alpha r_c")
    save(fig, "alphaSweep.png")
    print("Written alphaSweep.png and resultsAlphaSweep.dat")
    return 0


if __name__ == "__main__":
    sys.exit(main())
