#!/usr/bin/env python3
"""Tunable-slip tutorial: slip length against gamma_L, measured and predicted; results table; checks.

For every gammaL-<value>/ case: the fit (postProcessing/fitSlipLength/<time>/fit.dat: measured slip
length per wall, nu, the predicted slip length), the profile (density next to the walls) and the log
(crossings of the wall planes). Writes results.dat and slipLength.png, exits non-zero when a check fails.

The prediction b / z_c = 2/alpha - 7/15 - 19 alpha/1800 (alpha = z_c^2 gamma_L rho / eta) assumes the
fluid fills the friction layer at the bulk density. The WCA wall empties the first ~sigma of it, so the
table also gives the near-wall density and the prediction with the friction the measured density
profile actually feels (alpha_eff, see effective_alpha).
"""
import glob
import sys

import numpy as np

from dpdfoam.checks import Checks, print_file
from dpdfoam.io import latest_fit, latest_profile, log_values, read_text
from dpdfoam.plots import label, plt, save

ZC = 1.0  # constant/dpdProperties: tunableSlip zc
COLUMNS = ["gammaL", "alpha", "bMeasured", "bError", "bLower", "bUpper", "bPredicted", "alphaEff",
           "bPredictedEff", "nu", "nuError", "rhoCentral", "rhoNearWall", "crossed"]
# The slip length's standard error (from the fit block by block), measured 2026-11-24: mean of the
# walls 0.050-0.055 in the test (900 sampled time units); each wall 0.052-0.105 (RMS 0.076) over five
# seeds of the full run at gamma_L 0.5 (1000 sampled), the mean of the walls no larger. The budget,
# 1.5 x that RMS, serves both.
B_ERROR_BUDGET = 0.115


def layer(z, wall, inward):
    """The bins within zc of a wall, and their distance s from it."""
    s = (z - wall) * inward
    return (s > 0) & (s < ZC), s


def effective_alpha(z, rho, wall, inward, gamma_l, eta):
    """alpha with the density the friction layer really has.

    Integrating the Stokes equation across the layer, the wall's drag per area on a plug moving at u
    is gamma_L u int_0^zc rho(z) w_L(z) dz, which is rho zc/2 gamma_L u for a uniform density: alpha
    (the leading 2/alpha of the prediction) scales with that integral, so
    alpha_eff = alpha * int rho w_L dz / (rho_bulk zc / 2) = 2 gamma_L zc int rho w_L dz / eta.
    """
    inside, s = layer(z, wall, inward)
    w = 1.0 - s[inside] / ZC
    return 2.0 * gamma_l * ZC * np.sum(rho[inside] * w) * abs(z[1] - z[0]) / eta


def predicted(alpha):
    return ZC * (2.0 / alpha - 7.0 / 15.0 - 19.0 * alpha / 1800.0)


def case_row(case):
    gamma_l = float(case.split("-", 1)[1])
    fit, prof = latest_fit(case), latest_profile(case)
    z, rho = prof["z"], prof["density"]
    walls = ((fit["wallPosition"][0], 1), (fit["wallPosition"][1], -1))
    rho_c, nu = fit["slipPredictionDensity"], fit["slipPredictionNu"]
    alpha_eff = np.mean([effective_alpha(z, rho, w, inward, gamma_l, rho_c * nu) for w, inward in walls])
    b, b_err = fit["slipLength"], fit["slipLengthError"]
    return {
        "gammaL": gamma_l, "alpha": fit["slipPredictionAlpha"][0],
        "bMeasured": 0.5 * (b[0] + b[1]), "bError": 0.5 * np.hypot(b_err[0], b_err[1]), "bLower": b[0], "bUpper": b[1],
        "bPredicted": 0.5 * sum(fit["slipLengthPredicted"]), "alphaEff": alpha_eff, "bPredictedEff": predicted(alpha_eff),
        "nu": nu, "nuError": fit["nuError"], "rhoCentral": rho_c,
        "rhoNearWall": 0.5 * sum(float(np.mean(rho[layer(z, w, inward)[0]])) for w, inward in walls),
        # particles found behind a wall plane over the run (the reflection safety net's count)
        "crossed": sum(log_values(read_text(f"{case}/log.dpdFoamLike"), r"crossed (\d+)", int)),
    }


def write_table(rows):
    with open("results.dat", "w") as f:
        f.write("# Tunable-slip walls (zc 1, WCA eps 1 sigma 0.5), Poiseuille d = 10, rho 3, g 0.02.\n"
                "# bMeasured: mean of the two walls' fitted slip lengths (bulk fit, 1 excluded at each wall),\n"
                "# bPredicted: 2/alpha - 7/15 - 19 alpha/1800 with the fitted nu and the central density,\n"
                "# bPredictedEff: the same with alpha from the measured density in the friction layer,\n"
                "# rhoNearWall: mean density within zc of the walls; crossed: particles behind a plane.\n")
        f.write("# " + " ".join(f"{c:>13}" for c in COLUMNS) + "\n")
        for r in rows:
            f.write("  " + " ".join(f"{r[c]:13.5g}" for c in COLUMNS) + "\n")
    print_file("results.dat")
    print()


def plot(rows):
    g = np.array([r["gammaL"] for r in rows])
    fig, ax = plt.subplots(figsize=(6, 4.5))
    ax.errorbar(g, [r["bMeasured"] for r in rows], yerr=[r["bError"] for r in rows], fmt="o", capsize=3,
                label="measured (fitSlipLength)")
    # The prediction as a curve, with the mean viscosity and density of the runs.
    eta = np.mean([r["nu"] * r["rhoCentral"] for r in rows])
    rho = np.mean([r["rhoCentral"] for r in rows])
    gg = np.geomspace(g.min() / 1.5, g.max() * 1.5, 200)
    ax.plot(gg, predicted(ZC * ZC * gg * rho / eta), "-", label=r"predicted, bulk $\rho$ in the layer")
    ax.plot(g, [r["bPredictedEff"] for r in rows], "s", mfc="none", label=r"predicted, measured $\rho(z)$ in the layer")
    ax.axhline(0.0, color="0.6", lw=0.8)
    ax.set_xscale("log")
    label(ax, r"Tunable-slip walls: $z_c = 1$, Poiseuille $d = 10$, $\rho = 3$", r"wall friction $\gamma_L$",
          r"slip length $b$ (from the wall plane)", legend=8)
    save(fig, "slipLength.png", dpi=120)


def check(rows):
    checks = Checks()
    for r in rows:
        checks.add(f"gammaL {r['gammaL']}: {r['crossed']} particles crossed a WCA wall", r["crossed"] == 0)
    for ra, rc in zip(rows, rows[1:]):
        # More friction, less slip: each step in gamma_L must lower b by more than the noise.
        a, c = ra["bMeasured"], rc["bMeasured"]
        checks.add(f"slip length does not fall from gammaL {ra['gammaL']} ({a:.3f}) to {rc['gammaL']} ({c:.3f})",
                   a - c > 3.0 * np.hypot(ra["bError"], rc["bError"]))
    for r in rows:
        # Where the prediction applies (large slip, alpha < 2), the measurement with the layer's own
        # density must meet it within 15 % plus 3 error budgets, fixed: the slip length's standard error
        # (from the fit block by block) must first be within B_ERROR_BUDGET, or the run cannot decide.
        # An alpha_eff that is not a number cannot say whether it applies: that fails.
        if not np.isfinite(r["alphaEff"]):
            checks.fail(f"gammaL {r['gammaL']}: alpha_eff {r['alphaEff']} (no density in the friction layer)")
        elif r["alphaEff"] < 2.0:
            gap = abs(r["bMeasured"] - r["bPredictedEff"])
            if checks.add(f"gammaL {r['gammaL']}: slip-length error {r['bError']:.3f} over its budget "
                          f"{B_ERROR_BUDGET} (too noisy to test the prediction)", r["bError"] <= B_ERROR_BUDGET):
                checks.add(f"gammaL {r['gammaL']}: b = {r['bMeasured']:.3f} +- {r['bError']:.3f} but "
                           f"{r['bPredictedEff']:.3f} predicted from the layer's density",
                           gap <= 0.15 * abs(r["bPredictedEff"]) + 3.0 * B_ERROR_BUDGET)
    return checks


def main():
    cases = sorted(glob.glob("gammaL-*"), key=lambda c: float(c.split("-", 1)[1]))
    if not cases:
        sys.exit("plotResults: no gammaL-* cases (run Allrun)")
    rows = [case_row(c) for c in cases]
    write_table(rows)
    plot(rows)
    checks = check(rows)
    checks.print_failures(summary=False)
    failed = len(checks.failures())
    print("All checks passed." if not failed else f"{failed} check(s) failed.")
    return checks.status()


if __name__ == "__main__":
    sys.exit(main())
