#!/usr/bin/env python3
"""Poiseuille tutorial: picture and results table, and the checks of what the scene must show.

Reads the channel's profile and fit (postProcessing/...) and the viscosity measured without walls
(viscosity/postProcessing/...), draws velocity, density and temperature across the channel with the
analytic profile, writes results.dat, and exits non-zero when a check fails. Then compares the
lattice walls with the random walls of randomMask/ and randomGmsh/ (wallComparison.py): walls.png,
resultsWalls.dat and their checks.
"""
import math
import sys

import numpy as np

import wallComparison as wc  # this tutorial's wall comparison, beside this script
from dpdfoam.channel import no_wall_reference
from dpdfoam.checks import Checks, as_number, write_results
from dpdfoam.io import body_force, latest_fit, latest_profile, read_dict, wall_planes
from dpdfoam.plots import draw_kT_of_shear, draw_no_slip_poiseuille, label, mark_walls, plt, save
from dpdfoam.stats import chi2_bounds

RUNS = (("lattice", "."), ("mask", "randomMask"), ("gmsh", "randomGmsh"))
NAMES = ("nu", "slipLower", "slipUpper")
# No slip: |b| below this at every wall (docs/walls.md 3.2: |b| < 0.1 moves the centre line by 4 b / d
# < 1 % at d = 40).
SLIP_BOUND = 0.1
# Standard-error budgets (issue 45; full size, test mode); the bounds stay the physical 3 % and 0.1,
# at least 2.5 budgets wide. The lattice channel's slip, fitSlipLength's error: full 0.0076-0.0091
# (README), test 0.017-0.027 (2026-11-28): a third of the bound at full size, 0.04 in the test.
LATTICE_SLIP_BUDGET = (SLIP_BOUND / 3, 0.04)
# Each random wall against nu without walls (relative, with the reference's error) and its slip; full
# size fitSlipLength's errors (the lattice channel's nu 0.34 %; slips 0.0023-0.0092, README), test the
# jackknife's over 5 super-blocks (nu 0.43-1.13 %, slips 0.004-0.028: README and 2026-11-28).
RANDOM_NU_BUDGET = (0.01, 0.015)
RANDOM_SLIP_BUDGET = (SLIP_BOUND / 3, 0.04)
# The channel bulk's kT against the no-wall box's (standard error of the difference: the bins' kT errors,
# count-weighted, and the box's mean in quadrature; measured 0.0010 test, 0.00013 full size, 2026-11-28)
# and the interior density's flatness (the largest relative standard error of a bin: 0.42 % test,
# 0.017 % full size): budgets about twice the largest measured, then the fixed bounds.
KT_BUDGET = (0.001, 0.002)
DENSITY_BUDGET = 0.01


def no_slip_check(checks, where, slip, error, budget):
    """|slip length| < SLIP_BOUND at a wall, its standard error first below its budget (issue 45)."""
    return checks.bounded(f"|slip length| < {SLIP_BOUND:g} at the {where} (standard error below {budget:.3g})", slip,
                          error, budget, -SLIP_BOUND, SLIP_BOUND)


def nu_check(checks, where, nu, error, nu_ref, nu_ref_error, budget, bound=0.03):
    """nu within `bound` (relative) of nu without walls, the combined relative standard error first
    below its budget (issue 45)."""
    nu, error, nu_ref, nu_ref_error = (as_number(v) for v in (nu, error, nu_ref, nu_ref_error))
    rel, sigma = nu / nu_ref - 1.0, math.hypot(error, nu_ref_error) / nu_ref
    return checks.bounded(f"nu({where}) within {100 * bound:g} % of nu(no walls) (standard error below {100 * budget:g} %)",
                          rel, sigma, budget, -bound, bound, f"{100 * rel:+.2f} % +- {100 * sigma:.2f} %")


def compare_walls(g, nu_ref, nu_ref_err, cutoff, test):
    """Lattice walls against random walls from the mask and the gmsh file: walls.png, resultsWalls.dat
    and the checks (docs/walls.md 3.2: the random walls give the same Poiseuille profile)."""
    lo, hi = latest_fit()["wallPosition"]
    tau1 = (hi - lo) ** 2 / (math.pi ** 2 * nu_ref)
    runs = [wc.WallRun(name, case, "channelProfile") for name, case in RUNS]
    too_short = [r.too_short for r in runs if r.too_short]
    errors = ("fitSlipLength's (blocks shorter than tau1 = d^2/(pi^2 nu))" if too_short else
              f"fitSlipLength's jackknife over super-blocks of {runs[0].super_block_time:g} (tau1 = d^2/(pi^2 nu) = {tau1:.0f})")
    checks, lines = Checks(), [f"# Lattice and random walls, d = {hi - lo:g}, g = {g:g}; errors: {errors}"]
    for r in runs:
        (v, e), (bulk, near) = r.values(), r.near_wall_density(cutoff)
        blocks = f"{r.super_blocks} super-blocks of {r.super_block_time:g}, " if r.super_blocks else ""
        lines.append(f"{r.label:8s} nu {v[0]:.4f} +- {e[0]:.4f}  slip {v[1]:+.4f} +- {e[1]:.4f}  {v[2]:+.4f} +- {e[2]:.4f}  "
                     f"({blocks}bin-error inefficiency s = {r.inefficiency:.2f})")
        lines.append(f"{r.label:8s} density bulk {bulk:.4f}; within one cutoff of the lower / upper wall: mean "
                     f"{near[0][0]:.3f} / {near[1][0]:.3f}, lowest bin {near[0][1]:.3f} / {near[1][1]:.3f} (x bulk)")
    wall_pairs(checks, lines, runs, tau1)
    # Each random wall on its own, held to what the lattice walls are held to (main checks): with the
    # jackknife's errors, or fitSlipLength's where the blocks are too few for it.
    mode = 1 if test else 0
    for r in runs[1:]:
        v, e = r.values()
        nu_check(checks, f"{r.label} walls", v[0], e[0], nu_ref, nu_ref_err, RANDOM_NU_BUDGET[mode])
        for k, side in ((1, "lower"), (2, "upper")):
            no_slip_check(checks, f"{side} {r.label} wall", v[k], e[k], RANDOM_SLIP_BUDGET[mode])
    write_results("resultsWalls.dat", lines, checks)
    plot_walls(runs, g, nu_ref, (lo, hi), cutoff)
    return checks


def wall_pairs(checks, lines, runs, tau1):
    """The walls compared pair by pair, or, where a run holds too few super-blocks (fitSlipLengthDict's
    superBlocks), a failed check: the full scene's slowest mode (tau1 ~ 600) needs a production run of ~6000 for five
    independent blocks; without them there are no honest error bars and no verdict, and a missing
    verdict fails (issue 45; the test run is long enough and decides)."""
    too_short = [r.too_short for r in runs if r.too_short]
    if too_short:
        lines.append(f"# no verdict: {too_short[0]} (tau1 = {tau1:.0f})")
        checks.add("random and lattice walls compared over independent blocks (no verdict without the super-blocks "
                   "of fitSlipLengthDict)", False, f"{too_short[0]} (tau1 = {tau1:.0f})")
    else:
        compare_pairs(runs, checks, lines)


def compare_pairs(runs, checks, lines):
    n = np.count_nonzero(runs[0].fitted)
    dof = wc.effective_dof(runs, n)
    low, high = chi2_bounds(dof)
    lines.append(f"# profile differences over the {n} bins of the fit range: effective independent bins "
                 f"{dof:.1f} (the slow modes correlate neighbours), so chi2/dof is expected in "
                 f"[{low:.2f}, {high:.2f}] (3 sigma)")
    # The mask and the gmsh file build the same random wall, and random and lattice walls must give
    # the same profile (docs/walls.md 3.2). A Poiseuille profile is fixed by nu and the two slip lengths
    # (g and d being the same): those are checked pair by pair with jackknife errors over independent
    # super-blocks. The per-bin chi2 of the difference is reported, not checked: its bin errors
    # (profileBins' times sqrt(s), s pooled from five super-blocks) miss most of the slow mode's
    # coherent fluctuation, which the jackknife catches (test: gmsh - lattice nu differed by 1.3
    # jackknife errors while the per-bin chi2/dof was 6 over ~5 effective bins).
    for a, b in ((runs[1], runs[2]), (runs[1], runs[0]), (runs[2], runs[0])):
        for k, name in enumerate(NAMES):
            diff, sigma, dof = wc.agreement(a, b, k)
            wc.agreement_check(checks, name, a.label, b.label, diff, sigma, wc.PAIR_BUDGETS[name], dof)
        chi2, bins = wc.profile_chi2(a, b)
        lines.append(f"compared  ux({a.label}) - ux({b.label}) per bin: chi2/dof {chi2:.3f} over {bins} bins "
                     f"(3-sigma range with per-bin errors [{low:.2f}, {high:.2f}])")


def plot_walls(runs, g, nu_ref, walls, cutoff):
    lo, hi = walls
    fig, ax = plt.subplots(2, 2, figsize=(12, 8.5))
    draw_no_slip_poiseuille(ax[0, 0], walls, g, nu_ref, f"analytic, no slip, nu = {nu_ref:.4f} (no-wall run)")
    lattice = runs[0]
    for r, marker in zip(runs, "osd"):
        t = r.table
        v, e = r.values()
        ax[0, 0].errorbar(t["z"], t["ux"], yerr=r.ux_error, fmt=marker, ms=3, mfc="none",
                          label=f"{r.label} walls: nu {v[0]:.3f} +- {e[0]:.3f}, slip {v[1]:+.3f} / {v[2]:+.3f}")
        ax[1, 0].plot(t["z"], t["density"], marker + "-", ms=3, mfc="none", label=f"{r.label} walls")
        dist = np.concatenate([t["z"] - lo, hi - t["z"]])
        near = dist < 2.0 * cutoff
        ax[1, 1].plot(dist[near], np.concatenate([t["density"], t["density"]])[near], marker, ms=4, mfc="none",
                      label=f"{r.label} walls (both walls)")
        if r is not lattice:
            both = r.fitted & lattice.fitted
            ax[0, 1].errorbar(t["z"][both], (t["ux"] - lattice.table["ux"])[both],
                              yerr=np.hypot(r.ux_error, lattice.ux_error)[both], fmt=marker, ms=3, mfc="none",
                              label=f"{r.label} - lattice")
    ax[0, 1].axhline(0.0, color="k", lw=0.8)
    label(ax[0, 0], "velocity", "z", "u_x", legend=7)
    label(ax[0, 1], "random minus lattice walls (fit range; long-block errors)", "z", "du_x", legend=8)
    label(ax[1, 0], "density", "z", "number density", legend=8)
    label(ax[1, 1], "density next to the walls", "distance from the wall", "number density", legend=8)
    mark_walls([ax[0, 0], ax[1, 0]], walls)
    fig.suptitle(f"Poiseuille flow between lattice and random equilibrated walls, d = {hi - lo:g}, g = {g:g}")
    save(fig, "walls.png")
    print("Written walls.png and resultsWalls.dat")


def main():
    test = "-test" in sys.argv
    prof, fit, ref = latest_profile(), latest_fit(), no_wall_reference()
    periodic = ref["table"]
    props = read_dict("constant/dpdProperties")
    z, rho, kT, count = prof["z"], prof["density"], prof["kT"], prof["count"]
    walls, g = wall_planes(), body_force()
    kT_set, cutoff = float(props.get("kT", 1.0)), float(props.get("cutoff", 1.0))
    d, centre = walls[1] - walls[0], 0.5 * (walls[0] + walls[1])
    nu_wall, nu_wall_err, nu_ref, nu_ref_err = fit["nu"], fit["nuError"], ref["nu"], ref["nuError"]
    # A missing error is NaN: the checks that read it fail (issue 45), where 0 would pass any budget.
    slip, slip_err = fit["slipLength"], fit.get("slipLengthError", [float("nan"), float("nan")])
    interior = np.abs(z - centre) < 0.5 * d - 1.0
    rho_mean = np.average(rho[interior])
    flatness = np.max(np.abs(rho[interior] / rho_mean - 1.0))
    kT_mean = np.average(kT, weights=count)
    # kT against the local shear rate: channel bulk (beyond 3 cutoffs from the walls, which take heat
    # away) against the periodic box without walls at the same shear rate.
    shear_p, kT_p = kT_of_shear = ref["kT_of_shear"]
    bulk = np.abs(z - centre) < 0.5 * d - 3.0 * cutoff
    kT_matched = np.interp(g * np.abs(z - centre) / nu_ref, shear_p, kT_p)
    heating_diff = np.average(kT[bulk] - kT_matched[bulk], weights=count[bulk])
    heating_error = math.hypot(np.sqrt(np.sum((count[bulk] * prof["kTErr"][bulk]) ** 2)) / np.sum(count[bulk]),
                               np.sqrt(np.sum((periodic["count"] * periodic["kTErr"]) ** 2)) / np.sum(periodic["count"]))
    density_error = np.max(prof["densityErr"][interior] / rho[interior])
    # In the full channel (d = 40) the bulk lies 3 to 20 cutoffs from the walls: +0.3 % measured, held
    # to 1 %. In the test channel (d = 10) it lies only 3 to 5 cutoffs from the walls, whose frozen
    # particles are a heat sink that reaches it: -0.6 +- 0.4 % over four seeds (-1.1, -0.8, -0.5,
    # -0.2 %), so the test holds it to 2 % (4 standard deviations beyond that mean), still far below
    # what a wrong thermostat or a missing heating would give (the heating itself is +4 %).
    kT_tolerance = 0.02 if test else 0.01
    kT_periodic_mean = np.average(periodic["kT"], weights=periodic["count"])

    # The 3 % bound on nu decides only if the combined standard error is at most 1 % (a 3 % difference
    # is then 3 of them): a run noisier than that fails instead of passing more easily. Measured, errors
    # from the fits block by block: 0.69 % in the test mode (the channel's 0.6 % dominates), 0.34 % at
    # full size (2026-11-24).
    rel_nu = nu_wall / nu_ref - 1.0
    nu_sigma = math.hypot(nu_wall_err, nu_ref_err) / nu_ref
    checks = Checks()
    checks.add("nu(wall fit) within 3% of nu(no walls), its standard error within 1%",
               abs(rel_nu) < 0.03 and nu_sigma <= 0.01, f"{100 * rel_nu:+.2f} % (1 sigma {100 * nu_sigma:.2f} %)")
    kT_budget = KT_BUDGET[1 if test else 0]
    checks.bounded(f"kT within {100 * kT_tolerance:g}% of the no-wall fluid's at the same shear rate (channel bulk; "
                   f"standard error below {kT_budget:g})", heating_diff / kT_set, heating_error / kT_set, kT_budget,
                   -kT_tolerance, kT_tolerance, f"mean difference {heating_diff:+.4f} +- {heating_error:.4f} (channel mean "
                   f"kT {kT_mean:.4f}, no-wall box {kT_periodic_mean:.4f})")
    checks.bounded(f"density flat within 5% beyond one cutoff from the walls (a bin's relative standard error below "
                   f"{DENSITY_BUDGET:.0%})", flatness, density_error, DENSITY_BUDGET, None, 0.05,
                   f"max deviation {100 * flatness:.2f} %, a bin's relative standard error at most {100 * density_error:.2f} %")
    # No slip. The test keeps the full scene's wall shear rate, so its slip length is measured to
    # about +-0.01 (standard error from the blocks) and the bound is decisive in both modes.
    for k, side in ((0, "lower"), (1, "upper")):
        no_slip_check(checks, f"{side} wall", slip[k], slip_err[k], LATTICE_SLIP_BUDGET[1 if test else 0])
    checks.include(compare_walls(g, nu_ref, nu_ref_err, cutoff, test))

    write_results("results.dat", [
        "# Poiseuille between frozen three-layer walls: results",
        f"nu_wallFit        {nu_wall:.5f} +- {nu_wall_err:.5f}",
        f"nu_noWalls        {nu_ref:.5f} +- {nu_ref_err:.5f}",
        f"nu_relativeDiff   {100 * rel_nu:+.3f} %",
        f"nu_kineticTheory  {fit.get('nuKineticTheory', float('nan')):.5f} (estimate)",
        f"slipLength        {slip[0]:+.4f} +- {slip_err[0]:.4f}  {slip[1]:+.4f} +- {slip_err[1]:.4f}",
        f"slipVelocity      {fit['slipVelocity'][0]:+.4f}  {fit['slipVelocity'][1]:+.4f}",
        f"kT_mean           {kT_mean:.5f} (set {kT_set}; no-wall box at the same shear rates {kT_periodic_mean:.5f})",
        f"kT_bulkVsNoWall   {heating_diff:+.5f} (channel bulk minus no-wall box at the same shear rate)",
        f"kT_maxShear       {kT_p[-1]:.5f} (no-wall box at shear {shear_p[-1]:.3f}: viscous heating)",
        f"kT_centre         {np.average(kT[np.abs(z - centre) < 1.0]):.5f} (within one cutoff of the centre)",
        f"density_interior  {rho_mean:.4f}, flat within {100 * flatness:.2f} %"], checks)

    fig, ax = plt.subplots(1, 3, figsize=(15, 4.6))
    ax[0].errorbar(z, prof["ux"], yerr=prof["uxErr"], fmt="o", ms=3, label="DPD, frozen three-layer walls")
    draw_no_slip_poiseuille(ax[0], walls, g, nu_ref, f"analytic, no slip, nu = {nu_ref:.4f} (no-wall run)")
    label(ax[0], "velocity", "z", "u_x", legend=8)
    ax[1].plot(z, rho, "o-", ms=3)
    ax[1].axhline(rho_mean, color="k", lw=0.8)
    label(ax[1], "density", "z", "number density")
    ax[2].plot(z, kT, "o-", ms=3)
    ax[2].axhline(kT_set, color="k", lw=0.8, label="set kT")
    draw_kT_of_shear(ax[2], centre, kT_of_shear, g, nu_ref)
    ax[2].set_ylim(kT_set * 0.9, kT_set * 1.15)
    label(ax[2], "temperature", "z", "kT about the local flow", legend=8)
    mark_walls(ax, walls)
    fig.suptitle(f"Poiseuille flow, d = {d:g}, g = {g:g}: nu = {nu_wall:.4f} (walls) vs {nu_ref:.4f} (no walls), "
                 f"slip {slip[0]:+.3f} / {slip[1]:+.3f}")
    save(fig, "poiseuille.png")
    print("Written poiseuille.png and results.dat")
    return checks.status()


if __name__ == "__main__":
    sys.exit(main())
