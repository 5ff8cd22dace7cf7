#!/usr/bin/env python3
"""Slip by gamma_fw tutorial: pictures, results table and the checks of what the scene must show.

Reads the tables runSweep wrote (sweep2D/sweep.dat, threeD/sweep3D/sweep.dat, variants/sweep.dat)
and each run's profile, draws the slip length and the fitted viscosity against gamma_fw (2-D and
3-D), the velocity profiles, and the density at the wall of the standard wall against the two
variants (slipGammaFw.png), writes results.dat with the published table (published.dat) beside the
measured one, and exits non-zero when a check fails. At full size a published point outside the
paper's tolerance passes only where the -planeNearRow variant's point lies within it (the measured
ingredient that accounts for the difference: where the bounce-back plane sits).

With -planeNearRow: the named variant whose wall rows sit 0.14 and 0.717 behind the bounce-back plane,
from sweepPlaneNearRow/, written to resultsPlaneNearRow.dat and slipGammaFwPlaneNearRow.png, with the
same monotonic checks and the published comparison (full size), the published scene's runs drawn
beside it when they exist.
"""
import os
import sys

import numpy as np

from dpdfoam.checks import Checks, as_number, write_results
from dpdfoam.io import latest_profile, read_sweep, wall_planes
from dpdfoam.plots import label, mark_walls, plt, save
from dpdfoam.published import published_checks, read_published
from dpdfoam.sweep import (accounted_by, draw_profiles, published_comparison, published_lines, slip_falls_checks,
                           sweep_slip, wall_depletion)

TEST_MODE = "-test" in sys.argv[1:]
PLANE_NEAR_ROW = "-planeNearRow" in sys.argv[1:]
GAMMA = "pairCoeffs/fluid-wall/gamma"
VARIANT_NAMES = ["a_wf = 3 a", "wall 3 x denser"]
TEST_NOTE = " (information: the test channel, d = 10, is not the published scene)"
# The published comparison (issue 25's bound, dpdfoam.sweep) on the 2-D runs (the published scene); the
# test channel (d = 10) is not the published scene: there the table is information.
# The slip's rise with falling gamma_fw (issue 45, sweep.slip_falls_checks): each step's and the whole
# range's standard error (the two slips' errors in quadrature) first within its budget, then the step
# above -3 budgets (no reversal) and the rise above +3 budgets (decisive); bounds fixed by the budgets,
# not by the run's errors; in 3-D the slip at gamma_fw 1 and 2 is the same within 0.004. Budgets (step,
# rise), full size from the README's runs of 2026-11-24/27, test from 2026-11-28:
MONOTONIC_BUDGETS = {
    # full: b's errors 0.013, 0.023, 0.013, 0.011: steps 0.026, 0.026, 0.017, rise 0.017; test (2026-11-28): steps 0.059, 0.038, rise 0.055
    "2-D": {"full": (0.035, 0.025), "test": (0.08, 0.07)},
    # full: b's errors 0.006-0.009: steps <= 0.013 (1 against 2: 0.0106), rise 0.009; test (1 and 13.5 only): 0.019
    "3-D": {"full": (0.017, 0.013), "test": (0.025, 0.025)},
    # full: b's errors 0.029, 0.025, 0.015, 0.012: steps 0.038, 0.029, 0.019, rise 0.031; test (1 and 13.5): 0.061
    "2-D, plane near the row": {"full": (0.05, 0.04), "test": (0.08, 0.08)},
}


def monotonic(checks, label, gammas, b, err):
    """The slip's rise with falling gamma_fw, with this mode's budgets for `label`."""
    slip_falls_checks(checks, label, "gamma_fw", gammas, b, err, *MONOTONIC_BUDGETS[label]["test" if TEST_MODE else "full"])


# The variants' gap at the wall against the standard wall's (same gamma_fw, 4.5): the difference's
# standard error (the two profiles' in quadrature) first within GAP_BUDGET, then the difference above
# GAP_MARGIN, a tenth of a cutoff of fluid, three budgets. Measured: the test's variants 0.32-0.33 above
# the standard wall, the errors 0.0014-0.0016 (2026-11-29); full size 0.32-0.33 (README).
GAP_MARGIN, GAP_BUDGET = 0.1, 0.033


def gap_checks(checks, gaps, standard):
    """One check a variant: (gap, error) pairs against the standard wall's (gap, error)."""
    standard = [as_number(v) for v in standard]
    for name, (gap, err) in zip(VARIANT_NAMES, gaps):
        gap, err = as_number(gap), as_number(err)
        checks.bounded(f"{name}: a wider gap at the wall than the standard wall's (depletion + {GAP_MARGIN})",
                       gap - standard[0], np.hypot(err, standard[1]), GAP_BUDGET, lower=GAP_MARGIN,
                       text=f"{gap:.3f} +- {err:.3f} against {standard[0]:.3f} +- {standard[1]:.3f}")
    if len(gaps) != len(VARIANT_NAMES):
        checks.add(f"the {len(VARIANT_NAMES)} variants' gaps measured", False, f"{len(gaps)} measured")


def slip_comparison(published, gammas, b, err):
    return published_comparison(published["tables"]["Table 1"], "gamma_fw", gammas, b, err)


def accounted_by_plane_depth(published):
    """The published scene's differences from the paper are held to the ingredient that accounts for
    them (tutorials/channel/slipSensitivity): the variant with the rows nearer the bounce-back plane,
    when it ran."""
    return accounted_by("where the bounce-back plane sits (the variant with the rows 0.14 and 0.717 behind it)",
                        "./Allrun runs it after the published sweeps; ./Allrun -planeNearRow alone",
                        "sweepPlaneNearRow/sweep.dat", GAMMA, lambda *slip: slip_comparison(published, *slip))


def comparison_lines(published, comparison):
    return published_lines(published, comparison, ["# gamma_fw  2-D slipLength (mean of walls) +- err   published   "
                                                    "difference  (standard errors)"], TEST_NOTE if TEST_MODE else "")


def sweep_lines(name, s, g, b, e, extra=lambda k: ""):
    return [f"{name} gamma_fw {g[k]:5g}  b {s['slipLength_0'][k]:+.4f} {s['slipLength_1'][k]:+.4f}"
            f"  mean {b[k]:+.4f} +- {e[k]:.4f}  nu {s['nu'][k]:.4f} +- {s['nuError'][k]:.4f}{extra(k)}" for k in range(len(g))]


def draw_published_slip(ax, published):
    table = published["tables"]["Table 1"]
    ax.plot(table["gamma_fw"], table["slipLength"], "rD", label="published (2-D, Table 1)")
    ax.set_xscale("log")
    label(ax, "slip length against gamma_fw", "gamma_fw", "slip length (mean of the walls)", legend=8)


def draw_velocities(ax, sweep_dir, sweep, gammas):
    draw_profiles(ax, [latest_profile(f"{sweep_dir}/{c}") for c in sweep["case"]], [f"gamma_fw {g:g}" for g in gammas])


def main():
    s2, g2, b2, e2 = sweep_slip("sweep2D/sweep.dat", GAMMA)
    s3, g3, b3, e3 = sweep_slip("threeD/sweep3D/sweep.dat", GAMMA)
    sv = read_sweep("variants/sweep.dat")
    walls = wall_planes()
    # The same checks in both modes and both dimensions. The errors come from the fit block by block
    # (fitSlipLength: the bins move together); the test's 3-D runs sample 2000 time units, since six
    # seeds of 250 (2026-11-21) scattered by 0.07 in the slip length against a rise of 0.10 from
    # gamma_fw 13.5 to 1: at 2000 the rise is ~4 of its standard errors.
    checks = Checks()
    monotonic(checks, "2-D", g2, b2, e2)
    monotonic(checks, "3-D", g3, b3, e3)
    # The variants leave a gap at the wall: more fluid missing next to it than at the standard wall.
    standard = latest_profile(f"sweep2D/{s2['case'][int(np.argmin(np.abs(g2 - 4.5)))]}")
    variants = [latest_profile(f"variants/{c}") for c in sv["case"]]
    gap_std, gaps = wall_depletion(standard, walls), [wall_depletion(p, walls) for p in variants]
    gap_checks(checks, gaps, gap_std)
    published = read_published("published.dat")
    comparison = slip_comparison(published, g2, b2, e2)
    if not TEST_MODE:
        checks.extend(published_checks(comparison, "2-D slip length", "gamma_fw {:g}", accounted_by_plane_depth(published)))

    lines = [f"# Slip by gamma_fw, Poiseuille between frozen walls, d = {walls[1] - walls[0]:g}: slip length",
             "# (lower upper, and mean of the walls) and nu of the parabola fit"]
    lines += sweep_lines("2-D", s2, g2, b2, e2) + sweep_lines("3-D", s3, g3, b3, e3)
    lines += [f"2-D {name} (gamma_fw 4.5): b {sv['slipLength_0'][k]:+.4f} {sv['slipLength_1'][k]:+.4f}"
              f"  nu {sv['nu'][k]:.4f} +- {sv['nuError'][k]:.4f}  depletion at the wall {gaps[k][0]:.3f} +- {gaps[k][1]:.3f}"
              for name, k in zip(VARIANT_NAMES, range(len(sv["case"])))]
    lines.append(f"2-D standard wall (gamma_fw 4.5): depletion at the wall {gap_std[0]:.3f} +- {gap_std[1]:.3f}")
    write_results("results.dat", lines + comparison_lines(published, comparison), checks)

    fig, ax = plt.subplots(2, 2, figsize=(12, 8.5))
    ax = ax.ravel()
    ax[0].errorbar(g2, b2, yerr=e2, fmt="o-", label="2-D (published)")
    ax[0].errorbar(g3, b3, yerr=e3, fmt="s--", label="3-D")
    draw_published_slip(ax[0], published)
    ax[1].errorbar(g2, s2["nu"], yerr=s2["nuError"], fmt="o-", label="2-D")
    ax[1].errorbar(g3, s3["nu"], yerr=s3["nuError"], fmt="s--", label="3-D")
    ax[1].set_xscale("log")
    label(ax[1], "fitted viscosity", "gamma_fw", "nu (parabola fit)", legend=8)
    draw_velocities(ax[2], "sweep2D", s2, g2)
    label(ax[2], "2-D velocity profiles", "z", "u_x", legend=8)
    ax[3].plot(standard["z"], standard["density"], "k-", label="standard wall (a_wf = a)")
    for name, p in zip(VARIANT_NAMES, variants):
        ax[3].plot(p["z"], p["density"], "-", label=name)
    label(ax[3], "2-D density, gamma_fw 4.5: the gap at the wall", "z", "density", legend=8)
    mark_walls(ax[2:], walls)
    fig.suptitle("Slip by the wall's dissipative coupling gamma_fw (Poiseuille, rho 3, a 25)")
    save(fig, "slipGammaFw.png", dpi=100)
    print("Written slipGammaFw.png and results.dat")
    return checks.status()


def main_plane_near_row():
    """The named variant: its sweep against the paper, with the published wall's runs beside it."""
    sv, gv, bv, ev = sweep_slip("sweepPlaneNearRow/sweep.dat", GAMMA)
    walls = wall_planes()
    published = read_published("published.dat")
    comparison = slip_comparison(published, gv, bv, ev)
    checks = Checks()
    monotonic(checks, "2-D, plane near the row", gv, bv, ev)
    if not TEST_MODE:
        checks.extend(published_checks(comparison, "2-D slip length (plane near the row)", "gamma_fw {:g}"))
    lines = [f"# Slip by gamma_fw, 2-D Poiseuille, d = {walls[1] - walls[0]:g}, the wall's rows 0.14 and 0.717 behind "
             "the bounce-back plane", "# (named variant; published: 0.289 and 0.866): slip length (lower upper, "
             "mean of the walls) and nu of the parabola fit"]
    lines += sweep_lines("2-D planeNearRow", sv, gv, bv, ev, lambda k: "  slip velocity "
                         f"{0.5 * (sv['slipVelocity_0'][k] + sv['slipVelocity_1'][k]):.4f}")
    write_results("resultsPlaneNearRow.dat", lines + comparison_lines(published, comparison), checks)

    fig, ax = plt.subplots(1, 2, figsize=(12, 4.5))
    ax[0].errorbar(gv, bv, yerr=ev, fmt="o-", label="rows 0.14 / 0.717 behind the plane (variant)")
    if os.path.exists("sweep2D/sweep.dat"):
        _, g2, b2, e2 = sweep_slip("sweep2D/sweep.dat", GAMMA)
        ax[0].errorbar(g2, b2, yerr=e2, fmt="s--", label="rows 0.289 / 0.866 (published wall)")
    draw_published_slip(ax[0], published)
    draw_velocities(ax[1], "sweepPlaneNearRow", sv, gv)
    mark_walls(ax[1], walls)
    label(ax[1], "velocity profiles (variant)", "z", "u_x", legend=8)
    fig.suptitle("Slip by gamma_fw with the wall's rows nearer the bounce-back plane (named variant)")
    save(fig, "slipGammaFwPlaneNearRow.png", dpi=100)
    print("Written slipGammaFwPlaneNearRow.png and resultsPlaneNearRow.dat")
    return checks.status()


if __name__ == "__main__":
    sys.exit(main_plane_near_row() if PLANE_NEAR_ROW else main())
