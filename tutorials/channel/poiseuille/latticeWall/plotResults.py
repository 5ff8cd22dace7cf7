#!/usr/bin/env python3
"""Poiseuille tutorial: picture and results table, and the checks of what the scene must show.

Reads the channel's profile and fit (postProcessing/...) and the viscosity measured without walls
(viscosity/postProcessing/...), draws velocity, density and temperature across the channel with the
analytic profile, writes results.dat, and exits non-zero when a check fails. Then compares the
lattice walls with the random walls of randomMask/ and randomGmsh/ (wallComparison.py): walls.png,
resultsWalls.dat and their checks.
"""
import sys

import wallComparison as wc  # this tutorial's wall comparison, beside this script
from dpdfoam.channel import no_wall_reference
from dpdfoam.checks import Checks, relative_difference, write_results
from dpdfoam.io import body_force, latest_fit, latest_profile, read_dict, wall_planes
from dpdfoam.lattice_wall import channel_measures, draw_channel

# Standard-error budgets (issue 45; full size, test mode); the bounds stay the physical 3 % and 0.1,
# at least 2.5 budgets wide. The lattice channel's slip, fitSlipLength's error: full 0.0076-0.0091
# (README), test 0.017-0.027 (2026-11-28): a third of the bound at full size, 0.04 in the test.
LATTICE_SLIP_BUDGET = (wc.SLIP_BOUND / 3, 0.04)
# The channel bulk's kT against the no-wall box's (standard error of the difference: the bins' kT errors,
# count-weighted, and the box's mean in quadrature; measured 0.0010 test, 0.00013 full size, 2026-11-28)
# and the interior density's flatness (the largest relative standard error of a bin: 0.42 % test,
# 0.017 % full size): budgets about twice the largest measured, then the fixed bounds.
KT_BUDGET = (0.001, 0.002)
DENSITY_BUDGET = 0.01


def main():
    test = "-test" in sys.argv
    mode = 1 if test else 0
    prof, fit, ref = latest_profile(), latest_fit(), no_wall_reference()
    props = read_dict("constant/dpdProperties")
    walls, g = wall_planes(), body_force()
    kT_set, cutoff = float(props.get("kT", 1.0)), float(props.get("cutoff", 1.0))
    nu_wall, nu_wall_err, nu_ref, nu_ref_err = fit["nu"], fit["nuError"], ref["nu"], ref["nuError"]
    # A missing error is NaN: the checks that read it fail (issue 45), where 0 would pass any budget.
    slip, slip_err = fit["slipLength"], fit.get("slipLengthError", [float("nan"), float("nan")])
    m = channel_measures(prof, ref, walls, g, cutoff)
    # In the full channel (d = 40) the bulk lies 3 to 20 cutoffs from the walls: +0.3 % measured, held
    # to 1 %. In the test channel (d = 10) it lies only 3 to 5 cutoffs from the walls, whose frozen
    # particles are a heat sink that reaches it: -0.6 +- 0.4 % over four seeds (-1.1, -0.8, -0.5,
    # -0.2 %), so the test holds it to 2 % (4 standard deviations beyond that mean), still far below
    # what a wrong thermostat or a missing heating would give (the heating itself is +4 %).
    kT_tolerance = 0.02 if test else 0.01

    # The 3 % bound on nu decides only if the combined standard error is at most 1 % (a 3 % difference
    # is then 3 of them): a run noisier than that fails instead of passing more easily. Measured, errors
    # from the fits block by block: 0.69 % in the test mode (the channel's 0.6 % dominates), 0.34 % at
    # full size (2026-11-24).
    rel_nu, nu_sigma = relative_difference(nu_wall, nu_wall_err, nu_ref, nu_ref_err)
    checks = Checks()
    checks.add("nu(wall fit) within 3% of nu(no walls), its standard error within 1%",
               abs(rel_nu) < 0.03 and nu_sigma <= 0.01, f"{100 * rel_nu:+.2f} % (1 sigma {100 * nu_sigma:.2f} %)")
    checks.bounded(f"kT within {100 * kT_tolerance:g}% of the no-wall fluid's at the same shear rate (channel bulk; "
                   f"standard error below {KT_BUDGET[mode]:g})", m["heating"] / kT_set, m["heatingError"] / kT_set,
                   KT_BUDGET[mode], -kT_tolerance, kT_tolerance, f"mean difference {m['heating']:+.4f} +- "
                   f"{m['heatingError']:.4f} (channel mean kT {m['kT']:.4f}, no-wall box {m['kTBox']:.4f})")
    checks.bounded(f"density flat within 5% beyond one cutoff from the walls (a bin's relative standard error below "
                   f"{DENSITY_BUDGET:.0%})", m["flatness"], m["densityError"], DENSITY_BUDGET, None, 0.05,
                   f"max deviation {100 * m['flatness']:.2f} %, a bin's relative standard error at most "
                   f"{100 * m['densityError']:.2f} %")
    # No slip. The test keeps the full scene's wall shear rate, so its slip length is measured to
    # about +-0.01 (standard error from the blocks) and the bound is decisive in both modes.
    for k, side in ((0, "lower"), (1, "upper")):
        wc.no_slip_check(checks, f"{side} wall", slip[k], slip_err[k], LATTICE_SLIP_BUDGET[mode])
    checks.include(wc.compare_walls(g, nu_ref, nu_ref_err, cutoff, test))

    shear_p, kT_p = ref["kT_of_shear"]
    write_results("results.dat", [
        "# Poiseuille between frozen three-layer walls: results",
        f"nu_wallFit        {nu_wall:.5f} +- {nu_wall_err:.5f}",
        f"nu_noWalls        {nu_ref:.5f} +- {nu_ref_err:.5f}",
        f"nu_relativeDiff   {100 * rel_nu:+.3f} %",
        f"nu_kineticTheory  {fit.get('nuKineticTheory', float('nan')):.5f} (estimate)",
        f"slipLength        {slip[0]:+.4f} +- {slip_err[0]:.4f}  {slip[1]:+.4f} +- {slip_err[1]:.4f}",
        f"slipVelocity      {fit['slipVelocity'][0]:+.4f}  {fit['slipVelocity'][1]:+.4f}",
        f"kT_mean           {m['kT']:.5f} (set {kT_set}; no-wall box at the same shear rates {m['kTBox']:.5f})",
        f"kT_bulkVsNoWall   {m['heating']:+.5f} (channel bulk minus no-wall box at the same shear rate)",
        f"kT_maxShear       {kT_p[-1]:.5f} (no-wall box at shear {shear_p[-1]:.3f}: viscous heating)",
        f"kT_centre         {m['kTCentre']:.5f} (within one cutoff of the centre)",
        f"density_interior  {m['rho']:.4f}, flat within {100 * m['flatness']:.2f} %"], checks)
    draw_channel(prof, m["rho"], walls, g, ref, kT_set, f"nu = {nu_wall:.4f} (walls) vs {nu_ref:.4f} (no walls), "
                 f"slip {slip[0]:+.3f} / {slip[1]:+.3f}")  # poiseuille.png
    print("Written poiseuille.png and results.dat")
    return checks.status()


if __name__ == "__main__":
    sys.exit(main())
