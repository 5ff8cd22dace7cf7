#!/usr/bin/env python3
"""Couette slip tutorial: pictures, results table and the checks of what the scene must show.

Reads sweep/sweep.dat (runSweep's, one row per a_ww) and each run's latest channelProfile.dat; draws
velocity, density, temperature and shear stress across the channel per a_ww (couetteSlip.png) and the
density near the walls per a_wf (couetteSlip_nearWall.png); writes results.dat with the published
table (published.dat) beside the measured one; non-zero exit when a check fails. -noSlipWall: the
calibrated variant (gamma_fw 36, sweepNoSlipWall/, resultsNoSlipWall.dat), checked for no slip at
a_ww = 5; -calibratedWall: the wall 0.9 as dense as published (sweepCalibratedWall/,
resultsCalibratedWall.dat), held to the published table at full size like the published set.
"""
import math
import sys

import numpy as np

from dpdfoam.channel import viscous_heating
from dpdfoam.checks import Checks, as_number, write_results
from dpdfoam.io import dictionary_numbers, latest_fit, latest_profile, wall_planes
from dpdfoam.plots import label, mark_walls, plt, save
from dpdfoam.published import published_checks, read_published, table_value
from dpdfoam.sweep import (accounted_by, draw_near_walls, draw_profiles, per_wall, published_comparison,
                           published_lines, slab_means, sweep_colours, sweep_slip, variant_of, weighted_error)

TEST_MODE = "-test" in sys.argv[1:]
VARIANTS = {"-noSlipWall": "the calibrated no-slip wall, gamma_fw 36",
            "-calibratedWall": "calibrated wall: 0.9 of the published wall density, spacing 0.5556 along the flow"}
VARIANT, SUFFIX = variant_of(sys.argv, VARIANTS)
NO_SLIP_WALL = VARIANT == "-noSlipWall"
SWEEP = f"sweep{SUFFIX}"
CASE = f"{SWEEP}/couetteSlip" if VARIANT else "."
A_WW = "pairCoeffs/wall-wall/a"
# The channel's nu = stress / (rho shear rate) against the same fluid's without walls (viscosity/:
# periodic reverse Poiseuille at the channel's shear rate), decided when the two's combined standard
# error is within budget (full size: +-1.4 % and +-0.3 % measured, budget 2 %; test: the 10 x 3 x 10
# channel adds +-1.5-2 %, budget 3 %); then |difference| within 5 %, fixed.
NU_BUDGETS = {False: 0.02, True: 0.03}  # full size, test mode
NU_BUDGET = NU_BUDGETS[TEST_MODE]
NU_BOUND = 0.05
# Issue 45: the shear stress's flatness (the largest deviation of a slab two cutoffs thick from the mean
# over the slabs) first with a slab's largest standard error, relative to the mean stress, within its
# budget, then within 5 %, fixed. Test (2026-11-30, a_ww 5 of each scene): the slabs' errors 1.5-1.7 %,
# budget 2 %; full size (60 x 5 cross-section: 10 times the test's slab volume, 5-10 times its sampled
# time, a third of its shear rate) an estimated 0.45-0.65 %, budget 1 % (the README records the
# deviations, 0.7-2.1 %, not the slabs' errors).
FLAT_BOUND = 0.05
FLAT_BUDGETS = {False: 0.01, True: 0.02}
# The mean kT (count-weighted over the bins) against the set kT plus the viscous heating: the relative
# difference's standard error (the bins' kT errors, count-weighted, and the heating's from eta's and the
# shear rate's errors) first within its budget, then within 1 %, fixed. Test (2026-11-30): 0.12-0.13 %,
# budget 0.3 %; full size an estimated 0.02 % (the test's scaled as above), budget 0.1 %. README: kT
# 1.0019-1.0031 against 1.0010-1.0014 at full size (0.1 %), the test 0.1-0.7 %.
KT_BOUND = 0.01
KT_BUDGETS = {False: 0.001, True: 0.003}
# The slip's growth with a_wf (issue 45; dpdfoam.sweep.slip_falls_checks's rule, rising): each step up
# in a_ww first with its standard error (the two means' errors in quadrature) within the step budget,
# then not lower by more than 3 step budgets (no real reversal: neighbouring steps are a few errors
# apart, the no-slip wall's 0.034 +- 0.035); over the whole sweep the rise's standard error within the
# rise budget, then the rise above 3 rise budgets (decisive). Budgets (step, rise) per scene, sized on
# the README's runs: the published scene at full size (2026-11-27): steps' errors 0.081, 0.110, 0.219,
# 0.315, the rise's 0.242 (rise 3.556); the calibrated wall (2026-11-25): 0.066, 0.090, 0.125, 0.147,
# rise 0.109 (2.497); the no-slip wall (2026-11-24): steps +- 0.03-0.04, a_ww 5's error 0.024 (rise
# 0.300); the test (2026-11-30; a_ww 5 and 25, the published scene only): the one step 3.255 +- 0.097.
# The test's variants run a_ww 5 alone: no budget (NaN: a growth check there fails).
GROWTH_BUDGETS = {None: {False: (0.4, 0.3), True: (0.15, 0.15)},
                  "-calibratedWall": {False: (0.2, 0.15), True: None},
                  "-noSlipWall": {False: (0.06, 0.06), True: None}}
# The published comparison (issue 25, dpdfoam.sweep): each point within max(0.3 r_c, 30 %) of the
# published slip length, decided only when the mean of the walls is known to a third of that point's
# tolerance; the paper states no errors, so the difference is given in units of this run's error alone.
# The calibrated variant's no-slip check, |b| < 0.1 r_c at a_ww = 5, decides when the mean of the walls
# is known to 0.03 (full size: 0.024 measured over 1000 sampled time units; test: ~0.01-0.02).
NO_SLIP_BOUND, NO_SLIP_BUDGET = 0.1, 0.03
# The profile panels of couetteSlip.png: column, with error bars, title.
PROFILE_PANELS = (("ux", True, "velocity u_x"), ("density", False, "density"),
                  ("kT", False, "kT about the local flow (dashed: set + viscous heating)"),
                  ("sigmaxz", True, "shear stress sigma_xz"))


def accounted_by_wall_density(table, cutoff):
    """The published scene's differences from the paper are held to the ingredient that accounts for
    them (tutorials/channel/slipSensitivity): the calibrated-wall variant's comparison, when it ran."""
    return accounted_by("the wall's density (the calibrated-wall variant, 0.9 of it)",
                        "./Allrun runs it after the published sweep; ./Allrun -calibratedWall alone",
                        "sweepCalibratedWall/sweep.dat", A_WW,
                        lambda *slip: published_comparison(table, "a_ww", *slip, cutoff=cutoff))


def stress_flatness(prof, walls, cutoff):
    """The largest deviation of the shear stress from its mean over slabs two cutoffs thick across the
    whole channel (wall layers included), and a slab's largest standard error relative to the mean (the
    deviation's error at most; one-cutoff slabs: 2.1 % in the test, too close to the bound)."""
    slabs, slab_err = slab_means(prof["z"], prof["sigmaxz"], prof["sigmaxzErr"], *walls, 2 * cutoff)
    return np.max(np.abs(slabs / np.mean(slabs) - 1.0)), np.max(slab_err) / abs(np.mean(slabs))


def no_slip_checks(checks, a_ww, b_mean, b_mean_err, b_walls, cutoff=1.0):
    """The calibrated no-slip wall at its first (smallest) a_ww, on the mean of the walls: its standard
    error within NO_SLIP_BUDGET, then |b| < NO_SLIP_BOUND r_c. b_walls: the two walls' slip lengths."""
    b_mean, b_mean_err = as_number(b_mean), as_number(b_mean_err)
    lower, upper = (as_number(v) for v in b_walls)
    checks.add(f"no-slip variant: the slip length's standard error within {NO_SLIP_BUDGET:g} (a_ww = {a_ww:g})",
               b_mean_err <= NO_SLIP_BUDGET, f"{b_mean_err:.4f}")
    checks.add(f"no-slip variant: |slip length| < {NO_SLIP_BOUND:g} r_c at a_ww = {a_ww:g} (mean of the walls)",
               abs(b_mean) < NO_SLIP_BOUND * cutoff and b_mean_err <= NO_SLIP_BUDGET,
               f"{b_mean:+.4f} +- {b_mean_err:.4f} (walls {lower:+.3f}, {upper:+.3f})")


def growth_budgets(variant, test):
    """(step, rise) budgets of GROWTH_BUDGETS for a scene (None: the published one) and mode; NaN where none."""
    budgets = GROWTH_BUDGETS.get(variant, {}).get(test)
    return budgets if budgets else (float("nan"), float("nan"))


def growth_checks(checks, a_wf, b, err, step_budget, rise_budget):
    """The slip length grows with a_wf (issue 45): no step up in a_wf lowers the mean of the walls by
    more than 3 step budgets, and over the whole sweep it rises by more than 3 rise budgets, each first
    with its standard error (the two means' errors in quadrature) within its budget; a sign alone is no
    check. Two runs at least, each with its a_wf (a finite number), slip length and error."""
    a_wf, b, err = (np.array([as_number(v) for v in x], dtype=float) for x in (a_wf, b, err))
    if len(a_wf) < 2 or len(b) != len(a_wf) or len(err) != len(a_wf) or not np.all(np.isfinite(a_wf)):
        checks.fail(f"slip length against a_wf: {len(a_wf)} a_wf {list(a_wf)}, {len(b)} slip lengths, {len(err)} "
                    "errors (two runs at least, each with its a_wf, slip and error)")
        return
    order = np.argsort(a_wf)
    for lo, hi in zip(order[:-1], order[1:]):
        checks.bounded(f"slip length grows from a_wf = {a_wf[lo]:.2f} to {a_wf[hi]:.2f}: not lower by more than "
                       f"3 x {step_budget:g} (standard error below {step_budget:g})", b[hi] - b[lo],
                       math.hypot(err[hi], err[lo]), step_budget, lower=-3 * step_budget)
    lo, hi = order[0], order[-1]
    checks.bounded(f"slip length larger at a_wf = {a_wf[hi]:.2f} than at {a_wf[lo]:.2f} by more than 3 x {rise_budget:g} "
                   f"(standard error below {rise_budget:g})", b[hi] - b[lo], math.hypot(err[hi], err[lo]), rise_budget,
                   lower=3 * rise_budget)


def slip_checks(checks, a_ww, a_wf, b, b_mean, b_mean_err, comparison, table, cutoff):
    """The variant's no slip, the published comparison and the slip's growth with a_wf."""
    if NO_SLIP_WALL:
        # The calibrated wall: no slip at the first (smallest) setting, on the mean of the walls.
        no_slip_checks(checks, a_ww[0], b_mean[0], b_mean_err[0], b[0], cutoff)
    if not NO_SLIP_WALL and not TEST_MODE:
        checks.extend(published_checks(comparison, "slip length", "a_ww = {:g}",
                                       None if VARIANT else accounted_by_wall_density(table, cutoff)))
    # The test's variants run one a_ww: nothing to grow (at full size a single run fails the check).
    if len(a_ww) > 1 or not TEST_MODE:
        growth_checks(checks, a_wf, b_mean, b_mean_err, *growth_budgets(VARIANT, TEST_MODE))


def stress_flat_check(checks, a_ww, flat, flat_err, budget):
    """The shear stress's largest slab deviation: its error first within the budget, then below FLAT_BOUND."""
    flat, flat_err = as_number(flat), as_number(flat_err)
    checks.bounded(f"shear stress flat within {100 * FLAT_BOUND:g} % across the channel (a_ww = {a_ww:g}; a slab's "
                   f"standard error below {100 * budget:g} %)", flat, flat_err, budget, None, FLAT_BOUND,
                   f"max slab deviation {100 * flat:.2f} % (a slab's error at most {100 * flat_err:.2f} %)")


def nu_checks(checks, a_ww, nu, nu_err, nu_nw, nu_nw_err, budget):
    """nu = stress / (rho shear rate) against nu without walls: the combined standard error within the
    budget, then the difference within NU_BOUND."""
    nu, nu_err, nu_nw, nu_nw_err = (as_number(v) for v in (nu, nu_err, nu_nw, nu_nw_err))
    rel_nu, rel_nu_se = nu / nu_nw - 1.0, math.hypot(nu_err / nu_nw, nu * nu_nw_err / nu_nw ** 2)
    checks.add(f"nu = stress / (rho shear rate) and nu without walls: combined standard error within "
               f"{100 * budget:g} % (a_ww = {a_ww:g})", rel_nu_se <= budget, f"{100 * rel_nu_se:.2f} %")
    checks.add(f"nu = stress / (rho shear rate) within {100 * NU_BOUND:g} % of nu without walls (a_ww = {a_ww:g})",
               abs(rel_nu) <= NU_BOUND and rel_nu_se <= budget,
               f"{nu:.4f} +- {nu_err:.4f} against {nu_nw:.4f} +- {nu_nw_err:.4f} ({100 * rel_nu:+.2f} %)")


def kT_check(checks, a_ww, kT_mean, kT_err, kT_expected, expected_err, heating, budget):
    """The mean kT against the set kT plus the viscous heating: the relative difference's standard error
    (the mean's and the heating's in quadrature) first within the budget, then within KT_BOUND."""
    kT_mean, kT_err, kT_expected, expected_err = (as_number(v) for v in (kT_mean, kT_err, kT_expected, expected_err))
    rel, rel_se = kT_mean / kT_expected - 1.0, math.hypot(kT_err, expected_err) / kT_expected
    checks.bounded(f"mean kT within {100 * KT_BOUND:g} % of the set kT plus the viscous heating (a_ww = {a_ww:g}; "
                   f"standard error below {100 * budget:g} %)", rel, rel_se, budget, -KT_BOUND, KT_BOUND,
                   f"{kT_mean:.4f} +- {kT_err:.4f} against {kT_expected:.4f} +- {expected_err:.4f} (heating "
                   f"{as_number(heating):+.4f})")


def first_channel_checks(checks, a_ww, flat, nu, kT, heating):
    """The stress, viscosity and kT checks at the first a_ww, at this mode's budgets: flat (deviation,
    its error), nu (nu, error, nu without walls, error), kT (mean, error, expected, error)."""
    stress_flat_check(checks, a_ww, *flat, FLAT_BUDGETS[TEST_MODE])
    nu_checks(checks, a_ww, *nu, NU_BUDGET)
    kT_check(checks, a_ww, *kT, heating, KT_BUDGETS[TEST_MODE])


def main():
    sweep, a_ww, b_mean, b_mean_err = sweep_slip(f"{SWEEP}/sweep.dat", A_WW)
    nu_fit = latest_fit("viscosity")
    nu_nw, nu_nw_err = float(nu_fit["nu"]), float(nu_fit["nuError"])
    props = f"{CASE}/constant/dpdProperties"
    fluid = dictionary_numbers(props, {"a": "pairCoeffs/fluid-fluid/a", "gamma": "pairCoeffs/fluid-fluid/gamma",
                                       "gamma_fw": "pairCoeffs/fluid-wall/gamma", "kT": "kT", "cutoff": "cutoff"},
                               kT=1.0, cutoff=1.0)
    walls = wall_planes(props)
    d, cutoff = walls[1] - walls[0], fluid["cutoff"]
    a_wf = np.sqrt(a_ww * fluid["a"])
    # The two walls' mean (sweep_slip): a fluctuation of the channel's mean velocity (the slowest mode,
    # time d^2 / (pi^2 nu)) moves the two slip lengths in opposite directions and cancels in the mean.
    b, b_err, us = (per_wall(sweep, column) for column in ("slipLength", "slipLengthError", "slipVelocity"))
    profiles = [latest_profile(f"{SWEEP}/{c}") for c in sweep["case"]]
    published = read_published("published.dat")
    table = published["tables"]["Table 1"]
    comparison = published_comparison(table, "a_ww", a_ww, b_mean, b_mean_err, cutoff=cutoff)
    checks = Checks()
    slip_checks(checks, a_ww, a_wf, b, b_mean, b_mean_err, comparison, table, cutoff)

    lines = [f"# Couette flow between sliding three-layer walls, d = {d:g}, a_ff = {fluid['a']:g}, gamma {fluid['gamma']:g}, "
             f"gamma_fw {fluid['gamma_fw']:g} ({VARIANTS[VARIANT] if VARIANT else 'the published parameters'}): one row per a_ww",
             "# a_ww  a_wf   slipLength(lower upper) +- err      slipVelocity(lower upper)  shearRate +- err"
             "      eta +- err        nu +- err         stressFlat%  kT  kT_expected"]
    kT_expected = []
    for k, prof in enumerate(profiles):
        shear, eta, nu, nu_err = sweep["shearRate"][k], sweep["eta"][k], sweep["nu"][k], sweep["nuError"][k]
        heating = viscous_heating(eta, shear, sweep["densityKineticTheory"][k], fluid["gamma"], cutoff)
        kT_expected.append(fluid["kT"] + heating)
        flat, slab_error = stress_flatness(prof, walls, cutoff)
        kT_mean = np.average(prof["kT"], weights=prof["count"])
        if k == 0:
            # The expected kT's error: the heating's, eta shear^2 (eta's and the shear rate's errors).
            heating_err = heating * math.hypot(sweep["etaError"][k] / eta, 2 * sweep["shearRateError"][k] / shear)
            first_channel_checks(checks, a_ww[k], (flat, slab_error), (nu, nu_err, nu_nw, nu_nw_err),
                                 (kT_mean, weighted_error(prof["count"], prof["kTErr"]), kT_expected[k], heating_err),
                                 heating)
        lines.append(f"{a_ww[k]:5g} {a_wf[k]:6.2f}  {b[k, 0]:+.4f} {b[k, 1]:+.4f} +- {b_err[k, 0]:.4f} {b_err[k, 1]:.4f}  "
                     f"{us[k, 0]:+.4f} {us[k, 1]:+.4f}  {shear:.5f} +- {sweep['shearRateError'][k]:.5f}  "
                     f"{eta:.4f} +- {sweep['etaError'][k]:.4f}  {nu:.4f} +- {nu_err:.4f}  {100 * flat:5.2f}  "
                     f"{kT_mean:.4f} {kT_expected[k]:.4f}")
    lines.append(f"# nu without walls {nu_nw:.4f} +- {nu_nw_err:.4f} (viscosity/: reverse Poiseuille, the same fluid)")
    info = (["# (information: this run is not the published scene"
             f"{' (the test channel: d = 10, shear rate 0.6)' if TEST_MODE else ''}"
             f"{' (' + VARIANTS[VARIANT] + ')' if VARIANT else ''})"] if TEST_MODE or VARIANT else [])
    lines += published_lines(published, comparison, info + [
        "# a_ww  slipLength(mean of walls) +- err   published   difference  (standard errors)  shearRate  published"],
        extra=lambda row: f"  {sweep['shearRate'][np.isclose(a_ww, row[0])][0]:.4f}  "
                          f"{table_value(table, 'a_ww', row[0], 'shearRate'):.4f}")
    write_results(f"results{SUFFIX}.dat", lines, checks)
    plot(sweep, profiles, kT_expected, a_wf, (b, b_err, b_mean, b_mean_err), published, nu_nw, walls, fluid)
    return checks.status()


def plot(sweep, profiles, kT_expected, a_wf, slip, published, nu_nw, walls, fluid):
    """couetteSlip.png: the profiles across the channel, the slip and nu against a_wf; the density near the walls."""
    b, b_err, b_mean, b_mean_err = slip
    table = published["tables"]["Table 1"]
    fig, ax = plt.subplots(2, 3, figsize=(16, 8.5))
    ax = ax.ravel()
    names = [f"a_ww {aw:g} (a_wf {af:.2f})" for aw, af in zip(sweep["pairCoeffs/wall-wall/a"], a_wf)]
    for a, (column, errors, title) in zip(ax, PROFILE_PANELS):
        draw_profiles(a, profiles, names, column, errors)
        label(a, title, "z")
    for kT, colour in zip(kT_expected, sweep_colours(len(profiles))):
        ax[2].axhline(kT, color=colour, ls="--", lw=0.8)
    if "wallVelocity_1" in sweep:
        u_wall = 0.5 * (sweep["wallVelocity_1"][0] - sweep["wallVelocity_0"][0])
        ax[0].plot(walls, [-u_wall, u_wall], "k-", lw=0.8, label="no slip")
    ax[4].errorbar(a_wf, b[:, 0], yerr=b_err[:, 0], fmt="v-", label="lower wall")
    ax[4].errorbar(a_wf, b[:, 1], yerr=b_err[:, 1], fmt="^-", label="upper wall")
    ax[4].errorbar(a_wf, b_mean, yerr=b_mean_err, fmt="ko-", label="mean")
    ax[4].plot(table["a_wf"], table["slipLength"], "rs", label="published (Table 1)")
    a_line = np.linspace(min(table["a_wf"]), max(table["a_wf"]), 100)
    ax[4].plot(a_line, published["fits"]["slipLength"][1](a_line), "r--", lw=0.8, label="published fit")
    if NO_SLIP_WALL:
        ax[4].axhspan(-NO_SLIP_BOUND, NO_SLIP_BOUND, color="gray", alpha=0.2, label="|b| < 0.1")
    label(ax[4], "slip length against a_wf", "a_wf", "slip length")
    ax[5].errorbar(a_wf, sweep["nu"], yerr=sweep["nuError"], fmt="o-", label="stress / (rho shear rate)")
    ax[5].axhline(nu_nw, color="k", lw=0.8, label="no walls (reverse Poiseuille)")
    label(ax[5], "viscosity", "a_wf", "nu")
    mark_walls(ax[:4], walls)
    for a in ax:
        a.legend(fontsize=7)
    fig.suptitle(f"Couette flow, d = {walls[1] - walls[0]:g}, gamma_fw {fluid['gamma_fw']:g}: slip against the wall-fluid "
                 f"repulsion (a_wf = sqrt(a_ww a_ff)){' - ' + VARIANTS[VARIANT] if VARIANT else ''}")
    save(fig, f"couetteSlip{SUFFIX}.png", dpi=100)

    fig, ax = plt.subplots(figsize=(7, 4.5))
    draw_near_walls(ax, profiles, [f"a_wf {a:.2f}" for a in a_wf], walls)
    ax.set_xlim(0, 3 * fluid["cutoff"])
    label(ax, "density near the wall for each a_wf", "distance from the wall (solid: lower, dashed: upper)",
          "number density", legend=8)
    save(fig, f"couetteSlip{SUFFIX}_nearWall.png", dpi=100)
    print(f"Written couetteSlip{SUFFIX}.png, couetteSlip{SUFFIX}_nearWall.png and results{SUFFIX}.dat")


if __name__ == "__main__":
    sys.exit(main())
