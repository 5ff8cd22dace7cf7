#!/usr/bin/env python3
"""Slip length as the user's input (docs/walls.md 3.8): the b each channel asked for against the one
fitSlipLength measures from where its walls were put (the two walls' mean), the run's error and the
calibration's at that b in quadrature. results.dat and slipLength.png.

Checks (the standard error below its budget, then the difference within a fixed bound):
  - every asked b measured within max(0.15, 10 %) of the ask (budget half the bound);
  - the Couette and the Poiseuille channel asking the same b (1) within 0.1 of each other;
  - near the walls kT within 1 % of 1 over the first cutoff of fluid, the density's peak at most 1.2
    times the bulk's (every channel; its standard error below PEAK_BUDGETS).
Information: the image-mask channel against the planar one asking the same b; each channel against its
simpleFoam twin with the asked b. The test mode: the same checks, bounds of three budgets (TEST_BUDGETS).
"""
import math
import sys

import numpy as np

from dpdfoam.channel import near_wall_layer
from dpdfoam.checks import Checks, as_number, write_results
from dpdfoam.io import dictionary_number, latest_compare, latest_profile, read_dict, read_sweep
from dpdfoam.slip import asked_slip_measured
from dpdfoam.slip_length import central, draw, peak_errors

TEST_MODE = "-test" in sys.argv[1:]
KT_BOUND = 0.01  # relative
PEAK_BOUND = 1.2
# Issue 45: the density's peak over the bulk's (the largest bin against the middle fifth's mean) first
# with its standard error (the peak bin's and the bulk mean's errors in quadrature) within its budget,
# then at most PEAK_BOUND, fixed. Measured: full size (2026-11-29, both calibrations' runs) 0.0008-0.0012
# (peaks 1.070-1.096), budget 0.005; the test (2026-11-29) 0.0017-0.0021 (1.051-1.096), budget 0.01.
PEAK_BUDGETS = {False: 0.005, True: 0.01}  # full size, test mode
SAME_ASK_BOUND = 0.1  # two channels asking the same b: Couette against Poiseuille
# The test's budgets (bound: 3 budgets) from its two runs of 2026-11-29: b's total error 0.27-0.34, mostly
# the calibration's; Couette - Poiseuille 0.096-0.115. kT as at full size (its error 0.001 in the test).
TEST_BUDGETS = {"b": 0.4, "same": 0.15}


def asked_check(checks, where, asked, value, run, calibration):
    bound = 3 * TEST_BUDGETS["b"] if TEST_MODE else max(0.15, 0.1 * asked)
    budget, total = TEST_BUDGETS["b"] if TEST_MODE else bound / 2, math.hypot(as_number(run), as_number(calibration))
    checks.bounded(f"{where}: b measured within {bound:g} of the asked {asked:g} (standard error below {budget:g})",
                   as_number(value) - asked, total, budget, -bound, bound,
                   f"{as_number(value):.3f} +- {total:.3f} (run {as_number(run):.3f}, calibration {as_number(calibration):.3f})")


def peak_check(checks, where, peak, peak_err, bulk, bulk_err, budget=PEAK_BUDGETS[TEST_MODE]):
    """The density's peak over the bulk's: its standard error within the budget, then at most PEAK_BOUND."""
    peak, peak_err, bulk, bulk_err = (as_number(v) for v in (peak, peak_err, bulk, bulk_err))
    ratio = peak / bulk
    error = abs(ratio) * math.hypot(peak_err / peak, bulk_err / bulk)
    checks.bounded(f"{where}: the density's peak at most {PEAK_BOUND:g} times the bulk's (standard error below "
                   f"{budget:g})", ratio, error, budget, None, PEAK_BOUND,
                   f"{ratio:.3f} +- {error:.4f} ({peak:.3f} against {bulk:.3f})")


def channel(checks, case, where, asked):
    """One channel asking b, its checks; (b, its run's and calibration's errors, walls, kT, error, peak)."""
    value, run, calibration, walls = asked_slip_measured(case)
    asked_check(checks, where, asked, value, run, calibration)
    t = latest_profile(case)
    middle = central(t["z"])
    kT, kT_err, peak, bulk = near_wall_layer(t, middle)
    checks.bounded(f"{where}: kT over the first cutoff of fluid within {100 * KT_BOUND:g} % of 1 (standard error below "
                   f"{100 * KT_BOUND / 3:g} %)", kT - 1.0, kT_err, KT_BOUND / 3, -KT_BOUND, KT_BOUND,
                   f"kT {kT:.4f} +- {kT_err:.4f}")
    peak_err, bulk_err = peak_errors(t, middle)
    peak_check(checks, where, peak, peak_err, bulk, bulk_err)
    return value, run, calibration, walls, kT, kT_err, peak / bulk


def channel_rows(checks, out, sweep, kind, ask_entry):
    """Each channel of a sweep and its results line; rows of (asked, measured, total error, case, run's error)."""
    s = read_sweep(f"{sweep}/sweep.dat")
    rows = []
    for k, case in enumerate(s["case"]):
        asked = float(s[ask_entry][k])
        value, run, calibration, walls, kT, kT_err, peak = channel(checks, f"{sweep}/{case}", f"{kind} asking {asked:g}", asked)
        gamma, offset = (walls[0][0], walls[0][2]) if walls else (math.nan, math.nan)
        twin = latest_compare(f"{sweep}/{case}")
        out.append(f"{asked:8g}   {value:+.3f} +- {run:.3f}   {calibration:.3f}   {gamma:8.4f}   {offset:.3f}   "
                   f"{kT:.4f} +- {kT_err:.4f}   {peak:.3f}   {twin['meanVelocityRatio']:.4f}   {twin['L2']:.4f} "
                   f"({twin['noiseL2']:.4f})")
        rows.append((asked, value, math.hypot(run, calibration), f"{sweep}/{case}", run))
    return rows


def main():
    checks, out = Checks(), []
    cal = read_dict("calibration/slipCalibration")
    out.append(f"# calibration: gamma_L {cal['gammaL']}, b {np.round(cal['slipLength'], 3).tolist()}, the wall acting "
               f"{cal['wallOffset']:.3f} +- {cal['wallOffsetError']:.3f} in front of its plane")
    out.append("# asked b   measured b +- run  calibration   gamma_L  acting behind the wall   kT near walls  density peak"
               "   the simpleFoam twin with the asked b: mean velocity DPD / FVM, L2 (its noise part)")
    rows = channel_rows(checks, out, "sweepPoiseuille", "Poiseuille", "walls/lower/slipLength")
    out.append("# the channel drawn as an image mask (one geometry wall, b from the mask's surface; its twin's partialSlip "
               "on the mesh's staircase of solid cells, flat here):")
    mask_rows = channel_rows(checks, out, "sweepMask", "Mask channel", "walls/channel/slipLength")
    for asked_b, mv, _, _, me in mask_rows:  # information: the runs' errors alone, the calibration shared
        for _, pv, _, _, pe in (r for r in rows if r[0] == asked_b):
            se = math.hypot(me, pe)
            out.append(f"# mask - planes asking {asked_b:g}: {mv - pv:+.3f} +- {se:.3f} ({(mv - pv) / se:+.1f} standard errors)")
    asked = dictionary_number("couette/constant/dpdProperties", "walls/lower/slipLength")
    value, run, calibration, _, kT, kT_err, peak = channel(checks, "couette", f"Couette asking {asked:g}", asked)
    twin = latest_compare("couette")
    out.append(f"# Couette asking {asked:g}: {value:+.3f} +- {run:.3f} (calibration {calibration:.3f}); kT near walls "
               f"{kT:.4f} +- {kT_err:.4f}, density peak {peak:.3f}; against its simpleFoam twin with the asked b: "
               f"L2 {twin['L2']:.4f} (its noise part {twin['noiseL2']:.4f})")
    same = [r for r in rows if r[0] == asked]
    if not same:
        checks.fail(f"a Poiseuille channel asking the Couette channel's {asked:g}")
    budget = TEST_BUDGETS["same"] if TEST_MODE else SAME_ASK_BOUND / 2
    bound = 3 * budget if TEST_MODE else SAME_ASK_BOUND
    for _, pv, _, _, pe in same:  # the runs' errors alone: the shared calibration cancels
        checks.bounded(f"Couette and Poiseuille asking {asked:g} within {bound:g} of each other (standard error below "
                       f"{budget:g})", value - pv, math.hypot(run, pe), budget, -bound, bound, f"{value:.3f} against {pv:.3f}")
    write_results("results.dat", out, checks)
    draw(rows, mask_rows, (asked, value, math.hypot(run, calibration)))
    print("Written slipLength.png and results.dat")
    return checks.status()


if __name__ == "__main__":
    sys.exit(main())
