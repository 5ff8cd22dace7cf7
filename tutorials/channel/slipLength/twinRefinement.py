#!/usr/bin/env python3
"""The continuum twin of a curved wall that asks for a slip length (docs/walls.md 3.9), under mesh
refinement: pipe/ (a pipe of radius R = 4 along y, drawn in gmsh) through makeFoamCase and simpleFoam on
cells of h = 0.5 to 0.125, its wall no-slip (b = 0) and slipping by b = 1, against the Navier-slip pipe
flow u(r) = g (R^2 - r^2 + 2 b R) / (4 nu), flux Q = pi g R^4 (1 + 4 b / R) / (8 nu).

The twin's wall is the staircase of the faces its solid cells leave, partialSlip with valueFraction
(h/2) / (b_f + h/2) on each face, b_f = b |n|_1 with n the circle's normal there: the staircase is
|n|_1 times as long as the wall, and the flow runs along its faces. Information, not a check (foamTwin.sh
checks one size): twinRefinement.dat and twinRefinement.png give the flux's relative error against h.
Run from the tutorial (./Allrun does, after the channels), with calibration/slipCalibration made."""
import math
import os
import shutil
import subprocess
import sys

import numpy as np

from dpdfoam.checks import write_results
from dpdfoam.io import foam_latest_fields, set_dictionary_value
from dpdfoam.plots import label, plt, save

R, G, NU, BOX = 4.0, 0.02, 0.3, 10.0
SIZES = (0.5, 0.25, 0.125)  # 0.0625 takes ~20 minutes a twin: U needs ~3.7 times the iterations a halving
SLIPS = (0.0, 1.0)


def run_twin(case, b, h):
    """pipe/ copied to case with slip b and cells of h; the twin's flux through the pipe (cells along y
    carry the same flow: the mean over them)."""
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree("pipe", case)
    shutil.copy("calibration/slipCalibration", os.path.join(case, "constant", "slipCalibration"))
    set_dictionary_value(os.path.join(case, "constant/dpdProperties"), "walls/pipe/slipLength", f"{b:g}")
    n = int(round(BOX / h))
    set_dictionary_value(os.path.join(case, "system/makeFoamCaseDict"), "cells", f"({n} 1 {n})")
    # U settles to round-off (1e-12) within 76, 242, 881 and 3327 iterations at h 0.5 to 0.0625 (b = 0;
    # b = 1 about twice as many); p's normalised residual stays at the cut mesh's round-off, so the
    # iterations are capped, and U's residual is checked below.
    set_dictionary_value(os.path.join(case, "system/makeFoamCaseDict"), "maxIterations", str(int(1000 * (0.25 / h) ** 1.7)))
    for command in (["makeFoamCase", "-case", case], [os.path.join(case, "simpleFoam", "Allrun")]):
        with open(os.path.join(case, f"log.{os.path.basename(command[0])}"), "w") as log:
            if subprocess.run(command, stdout=log, stderr=subprocess.STDOUT).returncode != 0:
                sys.exit(f"twinRefinement: {' '.join(command)} failed (see {log.name})")
    last = [line for line in open(os.path.join(case, "simpleFoam", "log.simpleFoam")) if "Solving for Uy" in line][-1]
    residual = float(last.split("Initial residual = ")[1].split(",")[0])
    if not residual < 1e-10:
        sys.exit(f"twinRefinement: {case}'s twin did not converge (Uy's residual {residual:g})")
    _, (centres, velocity) = foam_latest_fields(os.path.join(case, "simpleFoam"), "C", "U")
    return float(np.sum(velocity[:, 1]) * h * h), len(centres)


def main():
    exact = {b: math.pi * G * R ** 4 * (1 + 4 * b / R) / (8 * NU) for b in SLIPS}
    rows, lines = {}, ["# the pipe's twin (R 4, g 0.02, nu 0.3) against the Navier-slip pipe flow: flux, its relative error",
                       "# b   h   cells   flux   exact   relative error"]
    for b in SLIPS:
        for h in SIZES:
            flux, cells = run_twin(os.path.join("twinRefinement", f"b{b:g}_h{h:g}"), b, h)
            error = flux / exact[b] - 1.0
            rows.setdefault(b, []).append((h, error))
            lines.append(f"{b:g}   {h:g}   {cells}   {flux:.6g}   {exact[b]:.6g}   {error:+.5f}")
    write_results("twinRefinement.dat", lines)
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for b, points in rows.items():
        h, e = np.array(points).T
        ax.loglog(h, np.abs(e), "o-", label=f"b = {b:g}")
    ax.loglog(np.array(SIZES), 0.1 * np.array(SIZES), "k:", lw=0.8, label="h / 10")
    label(ax, "the pipe's twin: |flux / Navier-slip flux - 1| against the cell size", "h (cell size)", "relative error", 8)
    save(fig, "twinRefinement.png")
    return 0


if __name__ == "__main__":
    sys.exit(main())
