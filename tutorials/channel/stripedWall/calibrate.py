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
import sys

from dpdfoam.checks import Checks, print_file
from dpdfoam.plots import label, plt, save
from dpdfoam.slip import (bracketed_frictions, calibration_lines, no_slip_friction, read_calibration_runs,
                          slip_not_rising_checks, stiff_end)


# The slip length's standard error grows with b (b = u_slip / shear rate): full size 0.10-0.15 where b is
# below 1, 4-5 % of b from 2.5 to 25 and 13 % at 48 (README, 2026-11-27); the test's shorter runs 0.33 at
# the stiff end to 3.8 at gamma_L 0.05. A step's budget is the walls' budgets in quadrature, each
# B_SHARE of b plus a floor; "b does not rise" then allows 3 budgets, fixed by b, not by the run's noise.
B_SHARE = 0.2
B_FLOOR = {False: 0.15, True: 0.5}  # key: test


def slip_budget(b, test):
    return B_SHARE * abs(b) + B_FLOOR[test]


def rise_checks(checks, gammas, b, err, test):
    """b must not rise decisively from each gamma_L to the next stiffer one (each end's budget slip_budget)."""
    return slip_not_rising_checks(checks, gammas, b, err, lambda slip: slip_budget(slip, test))


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


def draw(hw, gammas, picks):
    """calibration.png: the uniform wall's b against gamma_L, each picked gamma_L starred."""
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    ax.errorbar(gammas, hw["slipLength"], yerr=hw["slipLengthError"], fmt="o-",
                label="uniform wall: b from the hydrodynamic wall")
    for name, (gamma, slip, e) in picks.items():
        ax.plot(gamma, slip, "r*", ms=12)
        ax.annotate(f"{name} {gamma:.3g} (b {slip:.2f})", (gamma, slip), textcoords="offset points", xytext=(-60, 12))
    ax.axhline(0.0, color="gray", ls=":")
    ax.set_xscale("log")
    label(ax, f"calibration: the wall acts {hw['offset']:.3f} in front of its plane", "gamma_L", "slip length b", legend=8)
    save(fig, "calibration.png", dpi=100)


def main():
    args = arguments()
    hw, gammas = read_calibration_runs("calibration")
    b, err = hw["slipLength"], hw["slipLengthError"]
    span = f"b from {b.min():.3f} to {b.max():.3f}"
    checks = Checks()
    rise_checks(checks, gammas, b, err, args.test)
    # Each asked slip length's friction and error as dpdFoamLike's walls would take them; bracketed
    # where it lies within the calibrated range (below it the stiffest friction leaves its own slip).
    gas, at_zero, *other_gases = bracketed_frictions("calibration/slipCalibration", [args.slip, 0.0] + args.slips)
    picks = {}
    if checks.add(f"the sweep brackets b = {args.slip:g} (gammaGas)", gas is not None, span):
        picks["gammaGas"] = (gas[0], args.slip, gas[1])
    # The other local slip lengths the study sweeps (-slips): their gas gamma_L as lists.
    others = list(zip(args.slips, other_gases))
    for b_other, found_other in others:
        checks.add(f"the sweep brackets b = {b_other:g} (gammaGasOf)", found_other is not None, span)
    # No slip: where b crosses 0, or, where the friction saturates first (the stiffest step of the sweep
    # no longer lowers b decisively), the stiffest gamma_L with the slip it leaves, b0 (plotResults.py
    # holds the stripes to the reference with that residual slip).
    last_step = stiff_end(gammas, b, err)[1]
    no_slip = no_slip_friction(at_zero, gammas, b, err)
    if no_slip:
        picks["gammaNoSlip"] = no_slip
    checks.add("the sweep brackets b = 0, or b saturates at the stiff end (gammaNoSlip)", "gammaNoSlip" in picks,
               f"{span}; last step {last_step:+.3f}")

    write_calibration(hw, args.period, args.slip, picks, others)
    print("\n".join(calibration_lines(gammas, hw)))
    print("\n".join(checks.lines()))
    draw(hw, gammas, picks)
    print("Written calibration.png and calibration/gammaL.dat")
    return checks.status()


if __name__ == "__main__":
    sys.exit(main())
