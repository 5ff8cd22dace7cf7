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
from dpdfoam.poiseuille import QUANTITIES, SeedRun, draw_alpha_sweep

CASES = (("FCC", "fcc", "blockFrozenWallDict"), ("random, mask", "randomMask", "randomEquilWallDict"))


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

    draw_alpha_sweep(sweeps, nu_ref)
    print("Written alphaSweep.png and resultsAlphaSweep.dat")
    return 0


if __name__ == "__main__":
    sys.exit(main())
