#!/usr/bin/env python3
"""The continuum twin of a curved wall asking for slip under mesh refinement (docs/walls.md 3.9): pipe/
(radius R = 4 along y, drawn in gmsh) through makeFoamCase and simpleFoam on cells of 0.5 to 0.125, its
wall no-slip and slipping by b = 1 (each staircase face by b |n|_1), against the Navier-slip pipe flux
pi g R^4 (1 + 4 b / R) / (8 nu). Information (foamTwin.sh checks one size): twinRefinement.dat, .png.
Run from the tutorial (./Allrun does, after the channels), with calibration/slipCalibration made."""
import math
import os
import shutil
import sys

import numpy as np

from dpdfoam.checks import write_results
from dpdfoam.io import foam_last_residual, foam_latest_fields, run_logged, set_dictionary_value
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
    # U settles to 1e-12 within 76, 242, 881, 3327 iterations at h 0.5 to 0.0625 (b = 0; b = 1 about
    # twice as many); p's residual stays at round-off: the iterations are capped, U's residual checked.
    set_dictionary_value(os.path.join(case, "system/makeFoamCaseDict"), "maxIterations", str(int(1000 * (0.25 / h) ** 1.7)))
    run_logged(case, ["makeFoamCase", "-case", case])
    run_logged(case, [os.path.join(case, "simpleFoam", "Allrun")])
    residual = foam_last_residual(os.path.join(case, "simpleFoam"), "Uy")
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


if __name__ == "__main__":
    sys.exit(main())
