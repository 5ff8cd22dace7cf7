#!/usr/bin/env python3
"""Scene 1's study of the bounce layer (./Allrun -alphaSweep): per alpha, for the FCC and the mask's
random wall (one seed each, alphaSweep/<case>_alpha<a>), the particles the layer returns and those
found behind the wall per unit time and area, the density next to the wall, the slip length, nu and
kT within one cutoff of the wall. Writes resultsAlphaSweep.dat and alphaSweep.png; information, no
checks (the published scene's checks are plotResults.py's).
"""
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotResults import QUANTITIES, SeedRun, reference, vector  # noqa: E402
from dpdResults import dictionary_value  # noqa: E402

CASES = (("FCC", "fcc", "blockFrozenWallDict"), ("random, mask", "randomMask", "randomEquilWallDict"))


def main():
    nu_ref, _, kT_of_shear = reference()
    g = float(vector(dictionary_value("fcc/constant/dpdProperties", "bodyForce/value"))[0])
    lines = [f"# The bounce layer's thickness alpha (one seed each): nu without walls {nu_ref:.5f}",
             "# wall         alpha " + " ".join(f"{k:>14s}" for k in QUANTITIES)]
    sweeps = {}
    for label, case, builder in CASES:
        paths = glob.glob(f"alphaSweep/{case}_alpha*")
        if not paths:
            sys.exit(f"plotAlphaSweep: no alphaSweep/{case}_alpha<a> (run ./Allrun -alphaSweep)")
        alphas = np.array([float(p.rsplit("alpha", 1)[1]) for p in paths])
        order = np.argsort(alphas)
        runs = [SeedRun(paths[k], builder, kT_of_shear, g, nu_ref) for k in order]
        sweeps[label] = (alphas[order], runs)
        for a, r in zip(alphas[order], runs):
            lines.append(f"{label.replace(' ', '_'):12s} {a:6g} " + " ".join(f"{r.q[k]:14.5f}" for k in QUANTITIES))
    with open("resultsAlphaSweep.dat", "w") as f:
        f.write("\n".join(lines) + "\n")
    print(open("resultsAlphaSweep.dat").read(), end="")

    shown = (("slip", "slip length b"), ("nu", "nu"), ("rhoNear", "density within one cutoff / bulk"),
             ("kTNear", "kT within one cutoff"), ("returned", "returned per unit time and area"),
             ("crossed", "found behind the wall per unit time and area"))
    fig, ax = plt.subplots(2, 3, figsize=(14, 8))
    for a, (key, title) in zip(ax.flat, shown):
        for (label, (alphas, runs)), marker in zip(sweeps.items(), "os"):
            a.plot(alphas, [r.q[key] for r in runs], marker + "-", mfc="none", label=label)
        a.set_xscale("log"); a.set_xlabel("alpha"); a.set_title(title); a.legend(fontsize=8)
    ax[0, 1].axhline(nu_ref, color="k", lw=0.8)
    fig.suptitle("Scene 1: the bounce layer's thickness alpha r_c")
    fig.tight_layout()
    fig.savefig("alphaSweep.png", dpi=110)
    print("Written alphaSweep.png and resultsAlphaSweep.dat")
    return 0


if __name__ == "__main__":
    sys.exit(main())
