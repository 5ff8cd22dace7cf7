#!/usr/bin/env python3
"""Slip sensitivity study (issue 25 item 3): the change in the slip length of the published slip
scenes when one unstated ingredient is changed, with its error. Scene 3: the Couette case at
a_ww = 15; scene 2: the 2-D Poiseuille case at gamma_fw = 1 and 13.5.

Reads sweep/sweep.dat and sweepScene2/sweep.dat (runSweep: one row per run, the baselines first),
the ingredients files beside them (the runs' names in the same order) and sweep/fitRange (scene 3's
baseline fitted over the central part), writes results.dat (ingredient, slip length of each wall,
their mean, the change from the baseline and its combined standard error), sensitivity.png, and
exits non-zero when a check fails.
"""
import math
import sys

import numpy as np

from dpdfoam.checks import Checks, as_number, write_results
from dpdfoam.io import latest_fit, project_path, read_sweep, read_text
from dpdfoam.plots import label, plt, save
from dpdfoam.published import read_published, table_value

TEST_MODE = "-test" in sys.argv[1:]
A_WW = 15.0
# Each change must be decided either way: found (|change| at least 3 standard errors) or ruled out as
# the cause of the difference from the paper, which needs its standard error within a third of that
# difference. At full size the published set here exceeds the paper by 0.47 at a_ww 15
# (couetteSlip/README), so the budget is 0.15 (each run's mean of the walls is known to 0.08-0.2 over
# the published 500 sampled time units). The test's runs (d = 10, 70 sampled time units) are only
# asked to decide a change of 1 r_c: budget 0.33.
DIFFERENCE_BUDGET = 0.33 if TEST_MODE else 0.15
# Scene 2: the same rule at each gamma_fw, the budget a third of the published set's difference from
# the paper there at full size, stated (README, 2026-11-25: 1.455 at gamma_fw 1, 0.283 at 13.5), not
# taken from the run; the test's short runs again decide a change of 1 r_c.
SCENE2_BUDGETS = {1.0: 1.455 / 3, 13.5: 0.283 / 3}
SCENE2_TEST_BUDGET = 0.33


def scene2_budget(gamma, test):
    """Scene 2's budget at gamma_fw (NaN, which fails, for a gamma_fw the study does not state)."""
    return SCENE2_TEST_BUDGET if test else SCENE2_BUDGETS.get(float(gamma), float("nan"))

WHAT = {
    "published": "the published parameters (couetteSlip's defaults)",
    "halfStep": "deltaT 0.01 instead of 0.02",
    "lambda05": "Groot-Warren lambda 0.5 instead of 0.65",
    "denseWall": "wall lattice twice as dense: spacing 0.5 across the flow as along it (0.5 x 0.5, not 0.5 x 1)",
    "sparseWall": "wall lattice half as dense: spacing 1 along the flow as across it (1 x 1, not 0.5 x 1)",
    "layersOnPlane": "the three layers moved 0.1 towards the fluid (0.05, 0.25, 0.65 behind the reflection plane)",
    "labFrame": "bounce-forward's velocity reversed in the lab frame, not relative to the moving wall",
    "bounceBack": "bounce-back: the velocity of the step (half-kicked) reversed, not the one at the penetrated position",
    "fitRange": "the baseline's profile fitted over the central part (3 cutoffs excluded, not 1)",
}
WHAT_SCENE2 = {
    "published": "the published parameters (slipGammaFw's defaults: bounce-back, two rows in register, "
                 "the reflection plane half a lattice spacing in front of the first)",
    "specular": "specular reflection (only the normal velocity reversed) instead of bounce-back",
    "maxwellian": "diffuse (Maxwellian) reflection instead of bounce-back",
    "planeOnRow": "the reflection plane through the first row (rows 0 and 0.577 behind it, not 0.289 and 0.866)",
    "staggeredRows": "the second row in the hollows of the first (shifted by half the spacing), not in register",
}


def mean_of_walls(b0, b1, e0, e1):
    return 0.5 * (b0 + b1), 0.5 * math.hypot(e0, e1)


def sweep_runs(directory):
    """runSweep's table in DIRECTORY with the ingredient names beside it: (sweep, [(name, b lower,
    b upper, mean of the walls, its error)] in the table's order)."""
    sweep = read_sweep(f"{directory}/sweep.dat")
    names = read_text(f"{directory}/ingredients").split()
    if len(names) != len(sweep["case"]):
        sys.exit(f"plotResults: {len(names)} ingredient names for {len(sweep['case'])} runs in {directory}")
    return sweep, [(name, b0, b1) + mean_of_walls(b0, b1, e0, e1) for name, b0, b1, e0, e1 in zip(
        names, sweep["slipLength_0"], sweep["slipLength_1"], sweep["slipLengthError_0"], sweep["slipLengthError_1"])]


def decided(checks, name, change, error, budget):
    """The change must be found (at least 3 standard errors: its error within a third of it) or known well
    enough to rule it out as the cause of the difference (its standard error within the budget, fixed by
    the difference to explain, not by the run); a change, error or budget that is not a number (NaN,
    missing, empty) decides nothing."""
    change, error, budget = as_number(change), as_number(error), as_number(budget)
    checks.add(f"{name}: the change decided (at least 3 standard errors, or its standard error within {budget:.3g})",
               abs(change) >= 3 * error or error <= budget, f"{change:+.4f} +- {error:.4f}", change, error, budget)


def scene2_table(lines, checks):
    """Scene 2's rows (ingredient, gamma_fw, b lower, b upper, mean, error) and their lines and checks:
    each ingredient's change from the published set at the same gamma_fw."""
    sweep, runs = sweep_runs("sweepScene2")
    rows = [(name, g, b0, b1, b, e) for (name, b0, b1, b, e), g in zip(runs, sweep["pairCoeffs/fluid-wall/gamma"])]
    table = read_published(project_path("tutorials/channel/slipGammaFw/published.dat"))["tables"]["Table 1"]

    def published_b(gamma):
        return table_value(table, "gamma_fw", gamma, "slipLength")

    base = {g: (b, e) for name, g, _, _, b, e in rows if name == "published"}
    lines.append(f"# Scene 2: 2-D Poiseuille, slip by gamma_fw{' (test channel, d = 10)' if TEST_MODE else ''} "
                 "(Li, Hu and Zhou 2009, Table 1)")
    lines.append("# ingredient      gamma_fw  b lower   b upper   mean +- err        change from the published set +- err  (errors)")
    for name, g, b0, b1, b, e in rows:
        if name == "published":
            lines.append(f"scene2 {name:15s} {g:5g}  {b0:+.4f}  {b1:+.4f}  {b:+.4f} +- {e:.4f}   -   (paper {published_b(g):g})")
            continue
        d, de = b - base[g][0], math.hypot(e, base[g][1])
        lines.append(f"scene2 {name:15s} {g:5g}  {b0:+.4f}  {b1:+.4f}  {b:+.4f} +- {e:.4f}   {d:+.4f} +- {de:.4f}  ({d / de:+.1f})")
        budget = scene2_budget(g, TEST_MODE)
        decided(checks, f"scene 2, {name} at gamma_fw {g:g}", d, de, budget)
    lines += [f"# scene 2, the published set here minus the paper at gamma_fw {g:g}: {b - published_b(g):+.4f} +- {e:.4f}"
              for g, (b, e) in sorted(base.items())]
    lines += [f"# scene 2, {name}: {WHAT_SCENE2.get(name, '')}" for name in dict.fromkeys(r[0] for r in rows)]
    return rows, published_b


def scene2_plot(ax, rows, published_b):
    """Each scene-2 ingredient's slip length at each gamma_fw, beside the paper's."""
    names = list(dict.fromkeys(r[0] for r in rows))
    gammas = sorted(set(r[1] for r in rows))
    for j, g in enumerate(gammas):
        sel = [r for r in rows if r[1] == g]
        x = np.array([names.index(r[0]) for r in sel]) + 0.1 * (j - 0.5 * (len(gammas) - 1))
        line = ax.errorbar(x, [r[4] for r in sel], yerr=[r[5] for r in sel], fmt="o", capsize=3, label=f"gamma_fw {g:g}")
        ax.axhline(published_b(g), color=line[0].get_color(), ls="--", lw=0.8, label=f"paper at gamma_fw {g:g}")
    ax.set_xticks(np.arange(len(names)))
    ax.set_xticklabels(names, rotation=20)
    label(ax, "2-D Poiseuille scene: one unstated ingredient changed at a time", None, "slip length (mean of the walls)",
          legend=8)


def main():
    sweep, runs = sweep_runs("sweep")
    rows = [run + (shear,) for run, shear in zip(runs, sweep["shearRate"])]
    fit = latest_fit("sweep/fitRange")
    b, e = mean_of_walls(fit["slipLength"][0], fit["slipLength"][1], fit["slipLengthError"][0], fit["slipLengthError"][1])
    rows.append(("fitRange", fit["slipLength"][0], fit["slipLength"][1], b, e, fit["shearRate"]))

    table = read_published(project_path("tutorials/channel/couetteSlip/published.dat"))["tables"]["Table 1"]
    b_published = table_value(table, "a_ww", A_WW, "slipLength")
    base_b, base_e = rows[0][3], rows[0][4]
    checks = Checks()
    lines = [f"# Slip sensitivity, Couette scene 3 at a_ww = {A_WW:g}{' (test channel, d = 10)' if TEST_MODE else ''}: "
             f"published b = {b_published:g} (Xu et al. 2019, Table 1)",
             "# ingredient      b lower   b upper   mean +- err        change from the published set +- err  (errors)  shear rate"]
    for name, b0, b1, b, e, shear in rows:
        if name == "published":
            lines.append(f"{name:15s} {b0:+.4f}  {b1:+.4f}  {b:+.4f} +- {e:.4f}   -                                      {shear:.4f}")
            continue
        # The fit range reuses the baseline's data: the two errors are correlated, and the independent
        # combination is an upper bound.
        d, de = b - base_b, math.hypot(e, base_e)
        lines.append(f"{name:15s} {b0:+.4f}  {b1:+.4f}  {b:+.4f} +- {e:.4f}   {d:+.4f} +- {de:.4f}  ({d / de:+.1f})"
                     f"{'  (same data: error an upper bound)' if name == 'fitRange' else ''}  {shear:.4f}")
        decided(checks, name, d, de, DIFFERENCE_BUDGET)
    lines.append(f"# the published set here minus the paper: {base_b - b_published:+.4f} +- {base_e:.4f}")
    lines += [f"# {r[0]}: {WHAT.get(r[0], '')}" for r in rows]
    scene2 = scene2_table(lines, checks)
    write_results("results.dat", lines, checks)

    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(15, 4.8), gridspec_kw={"width_ratios": [3, 2]})
    x = np.arange(len(rows))
    ax.errorbar(x, [r[3] for r in rows], yerr=[r[4] for r in rows], fmt="ko", capsize=3, label="this code (mean of the walls)")
    ax.axhline(b_published, color="r", ls="--", label=f"published {b_published:g}")
    ax.axhline(base_b, color="gray", ls=":", label="published parameters here")
    ax.set_xticks(x)
    ax.set_xticklabels([r[0] for r in rows], rotation=20)
    label(ax, f"Couette scene at a_ww = {A_WW:g}: one unstated ingredient changed at a time", None, "slip length", legend=8)
    scene2_plot(ax2, *scene2)
    save(fig, "sensitivity.png", dpi=100)
    print("Written sensitivity.png and results.dat")
    return checks.status()


if __name__ == "__main__":
    sys.exit(main())
