#!/usr/bin/env python3
"""Striped-wall tutorial, the calibration: which gamma_L gives which local slip length.

Reads hydrodynamicWall's fit of the uniform-wall sweep (calibration/hydrodynamicWall.dat: the wall's
position, shared by every gamma_L, and each gamma_L's slip length b from it, with errors) and the
sweep's gamma_L (calibration/sweepPoiseuille/sweep.dat). Picks the gas sectors' gamma_L (b = the
target, -slip; and the other targets of -slips b1,b2,...) as a wall asking that slip length takes it
from the sweep's calibration (calibration/slipCalibration, through the slipCalibration tool: b linear in
1/gamma_L between the two sweep points that bracket it, with the interpolated error); and the no-slip
gamma_L the same way at b = 0 or, where the friction saturates before b reaches 0, the stiffest gamma_L
with the slip it leaves. Writes calibration/gammaL.dat (a dictionary the Allrun
and plotResults.py read) and calibration.png; exits non-zero when either is not found or b rises with
gamma_L.
"""
import argparse
import math
import sys

import numpy as np

from dpdfoam.checks import Checks, print_file
from dpdfoam.io import read_dict, read_sweep
from dpdfoam.plots import label, plt, save
from dpdfoam.slip import calibrated_walls


# The slip length's standard error grows with b (b = u_slip / shear rate): full size 0.10-0.15 where b is
# below 1, 4-5 % of b from 2.5 to 25 and 13 % at 48 (README, 2026-11-27); the test's shorter runs 0.33 at
# the stiff end to 3.8 at gamma_L 0.05. A step's budget is the walls' budgets in quadrature, each
# B_SHARE of b plus a floor; "b does not rise" then allows 3 budgets, fixed by b, not by the run's noise.
B_SHARE = 0.2
B_FLOOR = {False: 0.15, True: 0.5}  # key: test


def slip_budget(b, test):
    return B_SHARE * abs(b) + B_FLOOR[test]


def rise_checks(checks, gammas, b, err, test):
    """From each gamma_L to the next stiffer one the slip length must not rise decisively: the step
    b(softer) - b(stiffer) no lower than -3 budgets, its standard error below one (slip_budget of both
    ends in quadrature). A sweep of fewer than two gamma_L fails."""
    gammas, b, err = (np.asarray(v, dtype=float) for v in (gammas, b, err))
    order = np.argsort(gammas)
    if len(order) < 2:
        checks.fail(f"the calibration sweeps at least two gamma_L ({len(order)} here)")
    for lo, hi in zip(order[:-1], order[1:]):
        step, se = b[lo] - b[hi], math.hypot(err[lo], err[hi])
        budget = math.hypot(slip_budget(b[lo], test), slip_budget(b[hi], test))
        checks.bounded(f"slip length not decisively larger at gamma_L {gammas[hi]:g} than at {gammas[lo]:g} (standard "
                       f"error below {budget:.3g})", step, se, budget, -3 * budget, None)


def arguments():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-period", type=float, default=10.0, help="the stripes' period L")
    parser.add_argument("-slip", type=float, default=10.0, help="the gas sectors' local slip length")
    parser.add_argument("-slips", type=lambda text: [float(v) for v in text.split(",")], default=[],
                        help="the other local slip lengths the study sweeps: b1,b2,...")
    parser.add_argument("-test", action="store_true")
    return parser.parse_known_args()[0]  # (the Allrun's other options, -noFluidBehind, are not this script's)


def write_calibration(hw, period, slip_target, picks, others):
    with open("calibration/gammaL.dat", "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary; object gammaL; }\n\n")
        f.write("// The striped wall's calibration (calibrate.py from calibration/hydrodynamicWall.dat): the wall acts\n"
                "// `offset` in front of each plane; b from there, interpolated in 1/gamma_L.\n")
        f.write(f"halfWidth       {hw['halfWidth']:.6f};\nhalfWidthError  {hw['halfWidthError']:.6f};\n"
                f"offset          {hw['offset']:.6f};\nperiod          {period:g};\nslipTarget      {slip_target:g};\n")
        for name, (gamma, slip, e) in picks.items():
            f.write(f"{name:<17} {gamma:.6f};\n{name + 'Slip':<17} {slip:.6f};\n{name + 'SlipError':<17} {e:.6f};\n")
        found = [(b_other, g) for b_other, g in others if g]
        if found:
            f.write(f"slipTargets       ({' '.join(f'{b_other:g}' for b_other, _ in found)});\n"
                    f"gammaGasOf        ({' '.join(f'{g[0]:.6f}' for _, g in found)});\n"
                    f"gammaGasSlipErrorOf ({' '.join(f'{g[1]:.6f}' for _, g in found)});\n")
    print_file("calibration/gammaL.dat")


def main():
    args = arguments()
    period, slip_target, test = args.period, args.slip, args.test
    hw = {k: np.asarray(v) if isinstance(v, list) else v for k, v in read_dict("calibration/hydrodynamicWall.dat").items()}
    gammas = np.asarray(read_sweep("calibration/sweepPoiseuille/sweep.dat")["walls/lower/tunableSlip/gammaL"], dtype=float)
    b, err = hw["slipLength"], hw["slipLengthError"]
    span = f"b from {b.min():.3f} to {b.max():.3f}"
    checks = Checks()
    rise_checks(checks, gammas, b, err, test)
    order = np.argsort(gammas)
    picks = {}
    # Each asked slip length's friction and error as dpdFoamLike's walls would take them; bracketed
    # where it lies within the calibrated range (below it the stiffest friction leaves its own slip).
    summary, walls = calibrated_walls("calibration/slipCalibration", [slip_target, 0.0] + args.slips)
    bracketed = lambda b, wall: (wall["gammaL"], wall["slipLengthError"]) if wall and b >= summary["smallestSlip"] else None
    found = bracketed(slip_target, walls[0])
    checks.add(f"the sweep brackets b = {slip_target:g} (gammaGas)", found is not None, span)
    if found:
        picks["gammaGas"] = (found[0], slip_target, found[1])
    # The other local slip lengths the study sweeps (-slips): their gas gamma_L as lists.
    others = [(b_other, bracketed(b_other, wall)) for b_other, wall in zip(args.slips, walls[2:])]
    for b_other, found_other in others:
        checks.add(f"the sweep brackets b = {b_other:g} (gammaGasOf)", found_other is not None, span)
    # No slip: where b crosses 0, or, where the friction saturates first (the stiffest step of the sweep
    # no longer lowers b decisively), the stiffest gamma_L with the slip it leaves, b0 (plotResults.py
    # holds the stripes to the reference with that residual slip).
    found = bracketed(0.0, walls[1])
    stiff, before = order[-1], order[-2]
    if found:
        picks["gammaNoSlip"] = (found[0], 0.0, found[1])
    elif b[before] - b[stiff] < 3 * math.hypot(err[before], err[stiff]):
        picks["gammaNoSlip"] = (gammas[stiff], b[stiff], err[stiff])
    checks.add("the sweep brackets b = 0, or b saturates at the stiff end (gammaNoSlip)", "gammaNoSlip" in picks,
               f"{span}; last step {b[before] - b[stiff]:+.3f}")

    write_calibration(hw, period, slip_target, picks, others)
    print("# gamma_L  b (from the hydrodynamic wall) +- err   apparent Couette / Poiseuille (from the planes)")
    for k in order:
        print(f"{gammas[k]:7g}  {b[k]:+.4f} +- {err[k]:.4f}   {hw['apparentSlipCouette'][k]:+.4f} / "
              f"{hw['apparentSlipPoiseuille'][k]:+.4f}")
    print(f"# chi2 per degree of freedom of the wall's fit: {hw['chi2PerDof']:.3f} ({hw['dof']:g} dof)")
    print("\n".join(checks.lines()))

    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    ax.errorbar(gammas, b, yerr=err, fmt="o-", label="uniform wall: b from the hydrodynamic wall")
    for name, (gamma, slip, e) in picks.items():
        ax.plot(gamma, slip, "r*", ms=12)
        ax.annotate(f"{name} {gamma:.3g} (b {slip:.2f})", (gamma, slip), textcoords="offset points", xytext=(-60, 12))
    ax.axhline(0.0, color="gray", ls=":")
    ax.set_xscale("log")
    label(ax, f"calibration: the wall acts {hw['offset']:.3f} in front of its plane", "gamma_L", "slip length b", legend=8)
    save(fig, "calibration.png", dpi=100)
    print("Written calibration.png and calibration/gammaL.dat")
    return checks.status()


if __name__ == "__main__":
    sys.exit(main())
