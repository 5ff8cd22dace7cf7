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
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

PROJECT = os.environ.get("DPD_PROJECT_DIR", os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../.."))
sys.path.insert(0, os.path.join(PROJECT, "etc"))
from dpdResults import latest, read_dict, read_published, read_sweep  # noqa: E402

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
# the paper there (full size); the test's short runs again decide a change of 1 r_c.
SCENE2_TEST_BUDGET = 0.33

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
    names = open(f"{directory}/ingredients").read().split()
    if len(names) != len(sweep["case"]):
        sys.exit(f"plotResults: {len(names)} ingredient names for {len(sweep['case'])} runs in {directory}")
    runs = []
    for k, name in enumerate(names):
        b0, b1 = sweep["slipLength_0"][k], sweep["slipLength_1"][k]
        b, e = mean_of_walls(b0, b1, sweep["slipLengthError_0"][k], sweep["slipLengthError_1"][k])
        runs.append((name, b0, b1, b, e))
    return sweep, runs


def scene2_table(f):
    """Scene 2's rows (ingredient, gamma_fw, b lower, b upper, mean, error) and their checks, written to
    the open results file: each ingredient's change from the published set at the same gamma_fw."""
    sweep, runs = sweep_runs("sweepScene2")
    rows = [(name, g, b0, b1, b, e) for (name, b0, b1, b, e), g in zip(runs, sweep["pairCoeffs/fluid-wall/gamma"])]
    table = read_published(os.path.join(PROJECT, "tutorials/channel/slipGammaFw/published.dat"))["tables"]["Table 1"]

    def published_b(gamma):
        return float(table["slipLength"][np.flatnonzero(np.isclose(table["gamma_fw"], gamma))[0]])

    base = {g: (b, e) for name, g, _, _, b, e in rows if name == "published"}
    f.write(f"# Scene 2: 2-D Poiseuille, slip by gamma_fw{' (test channel, d = 10)' if TEST_MODE else ''} "
            "(Li, Hu and Zhou 2009, Table 1)\n")
    f.write("# ingredient      gamma_fw  b lower   b upper   mean +- err        change from the published set +- err  (errors)\n")
    checks = []
    for name, g, b0, b1, b, e in rows:
        if name == "published":
            f.write(f"scene2 {name:15s} {g:5g}  {b0:+.4f}  {b1:+.4f}  {b:+.4f} +- {e:.4f}   -   (paper {published_b(g):g})\n")
            continue
        d, de = b - base[g][0], math.hypot(e, base[g][1])
        f.write(f"scene2 {name:15s} {g:5g}  {b0:+.4f}  {b1:+.4f}  {b:+.4f} +- {e:.4f}   {d:+.4f} +- {de:.4f}  ({d / de:+.1f})\n")
        # The change must be found, or known well enough to rule it out as the cause of the difference.
        budget = SCENE2_TEST_BUDGET if TEST_MODE else abs(base[g][0] - published_b(g)) / 3
        checks.append((f"scene 2, {name} at gamma_fw {g:g}: the change decided (at least 3 standard errors, or "
                       f"its standard error within {budget:.3g})", bool(abs(d) >= 3 * de or de <= budget),
                       f"{d:+.4f} +- {de:.4f}"))
    for g, (b, e) in sorted(base.items()):
        f.write(f"# scene 2, the published set here minus the paper at gamma_fw {g:g}: {b - published_b(g):+.4f} +- {e:.4f}\n")
    for name in dict.fromkeys(r[0] for r in rows):
        f.write(f"# scene 2, {name}: {WHAT_SCENE2.get(name, '')}\n")
    return (rows, published_b), checks


def scene2_plot(ax, rows, published_b):
    """Each scene-2 ingredient's slip length at each gamma_fw, beside the paper's."""
    names = list(dict.fromkeys(r[0] for r in rows))
    gammas = sorted(set(r[1] for r in rows))
    for j, g in enumerate(gammas):
        sel = [r for r in rows if r[1] == g]
        x = np.array([names.index(r[0]) for r in sel]) + 0.1 * (j - 0.5 * (len(gammas) - 1))
        line = ax.errorbar(x, [r[4] for r in sel], yerr=[r[5] for r in sel], fmt="o", capsize=3,
                           label=f"gamma_fw {g:g}")
        ax.axhline(published_b(g), color=line[0].get_color(), ls="--", lw=0.8, label=f"paper at gamma_fw {g:g}")
    ax.set_xticks(np.arange(len(names)))
    ax.set_xticklabels(names, rotation=20)
    ax.set_ylabel("slip length (mean of the walls)")
    ax.set_title("2-D Poiseuille scene: one unstated ingredient changed at a time")
    ax.legend(fontsize=8)


def main():
    sweep, runs = sweep_runs("sweep")
    rows = [run + (shear,) for run, shear in zip(runs, sweep["shearRate"])]
    fit = read_dict(latest("sweep/fitRange/postProcessing/fitSlipLength/*/fit.dat"))
    b, e = mean_of_walls(fit["slipLength"][0], fit["slipLength"][1], fit["slipLengthError"][0], fit["slipLengthError"][1])
    rows.append(("fitRange", fit["slipLength"][0], fit["slipLength"][1], b, e, fit["shearRate"]))

    published = read_published(os.path.join(PROJECT, "tutorials/channel/couetteSlip/published.dat"))["tables"]["Table 1"]
    b_published = float(published["slipLength"][np.flatnonzero(np.isclose(published["a_ww"], A_WW))[0]])
    base_b, base_e = rows[0][3], rows[0][4]
    checks = []
    with open("results.dat", "w") as f:
        f.write(f"# Slip sensitivity, Couette scene 3 at a_ww = {A_WW:g}{' (test channel, d = 10)' if TEST_MODE else ''}: "
                f"published b = {b_published:g} (Xu et al. 2019, Table 1)\n")
        f.write("# ingredient      b lower   b upper   mean +- err        change from the published set +- err  (errors)  shear rate\n")
        for name, b0, b1, b, e, shear in rows:
            if name == "published":
                f.write(f"{name:15s} {b0:+.4f}  {b1:+.4f}  {b:+.4f} +- {e:.4f}   -                                      {shear:.4f}\n")
                continue
            # The fit range reuses the baseline's data: the two errors are correlated, and the
            # independent combination is an upper bound.
            d, de = b - base_b, math.hypot(e, base_e)
            f.write(f"{name:15s} {b0:+.4f}  {b1:+.4f}  {b:+.4f} +- {e:.4f}   {d:+.4f} +- {de:.4f}  ({d / de:+.1f})"
                    f"{'  (same data: error an upper bound)' if name == 'fitRange' else ''}  {shear:.4f}\n")
            checks.append((f"{name}: the change decided (at least 3 standard errors, or its standard error within "
                           f"{DIFFERENCE_BUDGET:g})", bool(abs(d) >= 3 * de or de <= DIFFERENCE_BUDGET),
                           f"{d:+.4f} +- {de:.4f}"))
        f.write(f"# the published set here minus the paper: {base_b - b_published:+.4f} +- {base_e:.4f}\n")
        for name, _, _, _, _, _ in rows:
            f.write(f"# {name}: {WHAT.get(name, '')}\n")
        scene2, scene2_checks = scene2_table(f)
        checks += scene2_checks
        for name, ok, value in checks:
            f.write(f"check  {'PASS' if ok else 'FAIL'}  {name}: {value}\n")
    print(open("results.dat").read(), end="")

    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(15, 4.8), gridspec_kw={"width_ratios": [3, 2]})
    labels = [r[0] for r in rows]
    means = np.array([r[3] for r in rows])
    errs = np.array([r[4] for r in rows])
    x = np.arange(len(rows))
    ax.errorbar(x, means, yerr=errs, fmt="ko", capsize=3, label="this code (mean of the walls)")
    ax.axhline(b_published, color="r", ls="--", label=f"published {b_published:g}")
    ax.axhline(base_b, color="gray", ls=":", label="published parameters here")
    ax.set_xticks(x)
    ax.set_xticklabels(labels, rotation=20)
    ax.set_ylabel("slip length")
    ax.set_title(f"Couette scene at a_ww = {A_WW:g}: one unstated ingredient changed at a time")
    ax.legend(fontsize=8)
    scene2_plot(ax2, *scene2)
    fig.tight_layout()
    fig.savefig("sensitivity.png", dpi=100)
    print("Written sensitivity.png and results.dat")
    return 0 if all(ok for _, ok, _ in checks) else 1


if __name__ == "__main__":
    sys.exit(main())
