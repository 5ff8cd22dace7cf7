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
from dpdfoam.couette import growth_checks, kT_check, nu_checks, plot, stress_flat_check, stress_flatness
# The fixed bounds (nu, the stress's flatness, kT), dpdfoam.couette's; checkBoundsChannel.sh reads them here.
from dpdfoam.couette import FLAT_BOUND, KT_BOUND, NU_BOUND  # noqa: F401
from dpdfoam.io import dictionary_numbers, latest_fit, latest_profile, wall_planes
from dpdfoam.published import published_checks, read_published, table_value
from dpdfoam.sweep import (accounted_by, per_wall, published_comparison, published_lines, sweep_slip, variant_of,
                           weighted_error)

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
# Issue 45: the shear stress's flatness (the largest deviation of a slab two cutoffs thick from the mean
# over the slabs) first with a slab's largest standard error, relative to the mean stress, within its
# budget, then within 5 %, fixed. Test (2026-11-30, a_ww 5 of each scene): the slabs' errors 1.5-1.7 %,
# budget 2 %; full size (60 x 5 cross-section: 10 times the test's slab volume, 5-10 times its sampled
# time, a third of its shear rate) an estimated 0.45-0.65 %, budget 1 % (the README records the
# deviations, 0.7-2.1 %, not the slabs' errors).
FLAT_BUDGETS = {False: 0.01, True: 0.02}
# The mean kT (count-weighted over the bins) against the set kT plus the viscous heating: the relative
# difference's standard error (the bins' kT errors, count-weighted, and the heating's from eta's and the
# shear rate's errors) first within its budget, then within 1 %, fixed. Test (2026-11-30): 0.12-0.13 %,
# budget 0.3 %; full size an estimated 0.02 % (the test's scaled as above), budget 0.1 %. README: kT
# 1.0019-1.0031 against 1.0010-1.0014 at full size (0.1 %), the test 0.1-0.7 %.
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


def accounted_by_wall_density(table, cutoff):
    """The published scene's differences from the paper are held to the ingredient that accounts for
    them (tutorials/channel/slipSensitivity): the calibrated-wall variant's comparison, when it ran."""
    return accounted_by("the wall's density (the calibrated-wall variant, 0.9 of it)",
                        "./Allrun runs it after the published sweep; ./Allrun -calibratedWall alone",
                        "sweepCalibratedWall/sweep.dat", A_WW,
                        lambda *slip: published_comparison(table, "a_ww", *slip, cutoff=cutoff))


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
    plot(sweep, profiles, kT_expected, a_wf, (b, b_err, b_mean, b_mean_err), published, nu_nw, walls, fluid, SUFFIX,
         VARIANTS.get(VARIANT), NO_SLIP_BOUND if NO_SLIP_WALL else None)
    return checks.status()


if __name__ == "__main__":
    sys.exit(main())
