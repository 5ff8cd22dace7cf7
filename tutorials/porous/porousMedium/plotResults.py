#!/usr/bin/env python3
"""Porous medium tutorial (docs/scenes.md scene 6): porousMedium.png (DPD |u|, density, kT series,
profiles across the flow at the sections), compareFVM.png (DPD |u|, simpleFoam |u|, their difference,
the lines), results.dat and the checks (non-zero exit when one fails).

Reads the DPD x-z field (profileBins' flowField.dat, 1 x 1 bins), the solver's log, the simpleFoam twin
(simpleFoam/), compareFVM's compare.dat and profiles.dat, the built counts (log.randomEquilWall) and the
paper's (published.dat, when there). The geometry comes from the case: the lines of
system/makeFoamCaseDict (compareFVM compares each; the tutorial's is its crack's centre line, which
crackFromMask.py moves onto the crack of a mask of one's own), the sections of system/controlDict, and
the grains, the pores and the bins next to them from the mask (dpdfoam.mask, at the bins' centres).

Checks, full scene (the issue's criteria):
  - mean kT within 3.5 % of the set kT = 1: the bins' kT (about each bin's own mean velocity), and the
    log's series (the monitor's kT is about the local flow, fitted in cells across x and z; the flow's
    kinetic energy per degree of freedom, which a global mean would have counted, is reported);
  - no fluid particle inside the solid at the end (the solver's count);
  - velocity near zero next to the grains: over the bins the grains' surface passes through, the mean
    DPD velocity is below 10 % of the lines' peak (the crack's) and within 3 % of that peak of the
    continuum's in the same bins (a slipping wall would leave a velocity of the order of the pore's);
  - each line (the crack's centre line): relative L2 of DPD against simpleFoam < 10 %;
  - mean velocity within 10 %: meanVelocityRatio (over the compared bins) and the superficial velocity
    (Darcy permeability) ratio.
Each check (issue 45) first holds the noise of its quantity (its standard error; the line's noise L2)
within a budget (NOISE_BUDGETS below), so that a run too noisy to decide fails instead of passing more
easily, then the value within a fixed bound; a NaN, missing or empty number fails.
Test mode (40 x 40 mask, 160 time units of sampling): the bounds of a mean (kT, the velocity next to the
grains, the mean velocity) are the full ones plus three test budgets (fixed, derived below for the
shorter run); the crack line's, where the noise adds in quadrature, is TEST_LINE_BOUND (derived below).

Where the two disagree: each fluid bin gets the local pore size (the diameter of the largest disc in
the fluid that covers it, from the mask) and its distance to the solid; results.dat gives the relative
L2 and the mean-velocity ratio per class of each.
"""
import os
import sys

from dpdfoam.checks import write_results
from dpdfoam.fields import CLASS_COLUMNS, FlowTemperature, TwinBins, class_lines, compare_summary, read_grid
from dpdfoam.io import built_particles, finished_solver_log, function_start, latest, latest_compare_lines, read_dict
from dpdfoam.mask import case_regions_on_grid
from dpdfoam.porous import PorousChecks, next_to_grains, plot_comparison, plot_fields
from dpdfoam.published import read_published

test_mode = "-test" in sys.argv[1:]

# Noise budgets (the largest noise at which a check still decides). Full scene, measured (README;
# 2026-11-24): crack noiseL2 0.023-0.024, superficial velocity 0.12 % (relative), kT of the log's series
# 0.0005-0.0006, near-grain velocity 0.013 % of the peak; budgets about twice that. Test (160 time
# units on the 40 x 40 mask; measured at 40 time units: noiseL2 0.233, superficial 2.7 %, kT 0.0047,
# near-grain velocity 0.63 % of the peak; four times the sampling halves each): budgets 1.3 x the
# expected. Velocity next to the grains: standard error of the mean over the near-grain bins, relative
# to the crack's peak.
#   Test mode, measured (2026-11-30, five seeds: 2031, the tutorial's, and 1001-1004): noiseL2
#   0.129-0.141, superficial 1.33-1.43 %, kT 0.0015-0.0024, next to the grains 0.31 % of the peak.
#   The mean velocity's test bound stays 0.10 + 3 x 0.018 = 0.154: between seeds (the walls' realisation
#   and the viscosity box's nu, 0.263-0.284) the mean velocity ratio spreads 0.908-1.040 and the
#   permeability ratio 0.952-1.081 (standard deviations 0.051 and 0.052, three to four times the
#   quoted standard error), so that a bound tighter than ~0.15 would fail a correct run of another seed.
NOISE_BUDGETS = {False: {"line": 0.05, "mean": 0.003, "kT": 0.0012, "wall": 0.0003},
                 True: {"line": 0.15, "mean": 0.018, "kT": 0.003, "wall": 0.004}}
# The full scene's bounds: kT within 3.5 % of 1; next to the grains below 10 % of the crack's peak, and
# within 3 % of that peak of simpleFoam's there; the crack line's relative L2 below 10 %; the mean and
# superficial velocities within 10 % of simpleFoam's.
KT_BOUND, WALL_BOUND, WALL_TWIN_BOUND, LINE_BOUND, MEAN_BOUND = 0.035, 0.10, 0.03, 0.10, 0.10
WIDEN = 3.0  # test bounds of a mean: the full bound plus three test budgets, fixed
# The crack line in test mode. The noise adds to the L2 in quadrature, L2^2 = L2_flow^2 + noiseL2^2, so
# that adding three noise budgets (0.10 + 3 x 0.15 = 0.55, the bound until 2026-11-30) let a halved flow
# pass (L2 ~0.52). The bound: the full bound and the noise budget in quadrature, sqrt(0.10^2 + 0.15^2) =
# 0.180, plus three standard deviations of the L2 itself over the line's 40 bins, whose noise is
# independent from bin to bin: sd(L2^2) = sqrt(2 noise^4 + 4 L2_flow^2 noise^2) / sqrt(40) = 0.0069, sd(L2)
# = 0.019: 0.180 + 0.058 = 0.24. Measured over the five seeds: 0.150-0.184 (mean 0.170, standard
# deviation 0.013; noise 0.129-0.141, the line's mean ratio 0.90-0.99), 5 standard deviations below.
TEST_LINE_BOUND = 0.24
# The checks at these budgets and bounds (dpdfoam.porous.PorousChecks), each also this module's function
# (tests/apps/checkBoundsPolymerPorous.sh calls them so).
CHECKS = PorousChecks(NOISE_BUDGETS, {"kT": KT_BOUND, "wall": WALL_BOUND, "twin": WALL_TWIN_BOUND, "line": LINE_BOUND,
                                      "mean": MEAN_BOUND}, TEST_LINE_BOUND, WIDEN, test_mode)
bound, kT_check, inside_check, wall_checks = CHECKS.bound, CHECKS.kT_check, CHECKS.inside_check, CHECKS.wall_checks
line_check, mean_check, make_checks = CHECKS.line_check, CHECKS.mean_check, CHECKS.make_checks


def main():
    table = latest("postProcessing/profileBins/*/flowField.dat")
    xs, zs, grid = read_grid(table)
    times, kts, inside, crossed, (steps, seconds, rate) = finished_solver_log()
    cmp_path, cmp, lines, prof = latest_compare_lines()
    twin = read_dict("simpleFoam/constant/dpdCase")   # nu and where it came from
    sample_start = function_start(".", "flowField")

    # Temperature: the bins' kT (about each bin's own flow) and the log's series (about the local flow,
    # system/Monitors); the flow's part (kT.flow) is what a global mean would have added, for reference.
    # Standard error of the series' mean: reports lie 10 time units or more apart, far beyond the
    # kinetic temperature's correlation time (~1), so they count as independent. Its largest deviation
    # from the set kT over the whole run is a quantity the paper reports.
    fluid = grid["count"] >= 10
    kT = FlowTemperature(grid, fluid, times, kts, sample_start)

    # The two fields on the bins. Maps show the bins holding at least a quarter of a full bin's
    # particles: in bins the grains' surface cuts, the few particles in the sliver of fluid carry a large,
    # biased mean (README).
    bins = TwinBins(xs, zs, grid, fluid)
    # The mask at the bins' centres (the tutorial's: one pixel a bin).
    mask_path, dist, pore = case_regions_on_grid(xs, zs)
    # The field away from the surface: bins whose every continuum cell is fluid.
    l2_interior, noise_interior = bins.interior_l2()
    # Next to the grains: bins the grains' surface passes through (the bin is solid in part: both
    # sides have cells there), i.e. fluid bins adjacent to a solid bin of the mask.
    wall = next_to_grains(bins, bins.compared & (dist < 0.75), prof, lines)

    # Where they disagree: by local pore size and by distance to the solid.
    by_pore = bins.class_table(pore, [0, 3, 5, 8, 12, 1e9])
    by_dist = bins.class_table(dist, [0, 0.75, 1.5, 3, 1e9])
    worst = max(by_pore, key=lambda r: r[3])
    checks = make_checks(cmp, lines, kT, inside, wall)

    fluid_built, frozen_built = built_particles()
    paper = read_published("published.dat")["tables"].get("counts") if os.path.exists("published.dat") else None
    write_results("results.dat", [
        f"# Porous medium (docs/scenes.md scene 6){' - TEST MODE' if test_mode else ''}: {table}, {cmp_path}",
        f"mask               {mask_path}  ({len(xs)} x {len(zs)} bins of 1 r_c)",
        f"porosity           DPD {cmp['porosityDPD']:.4f}  simpleFoam {cmp['porosityFVM']:.4f}"
        + (f"  published {paper['porosity'][0]:g}" if paper else ""),
        f"particles          fluid {fluid_built}  frozen {frozen_built} (every solid particle within one cutoff"
        f" of the fluid; {frozen_built / (fluid_built + frozen_built):.1%} of all)"
        + (f"; published fluid {paper['fluid'][0]:.0f}, frozen {paper['frozen'][0]:.0f}"
           f" ({paper['frozen'][0] / (paper['fluid'][0] + paper['frozen'][0]):.1%})" if paper else ""),
        f"nu                 {twin['nu']:.5f}  ({twin['nuSource']})",
        f"runTime            {seconds:.0f} s for {steps} steps; {rate:.4g} particle-steps/s",
        *kT.lines(),
        f"insideAtEnd        {inside}\ncrossedBounceLayer {crossed}  (whole run)",
        f"uNextToGrains      DPD {wall['dpd']:.5f}  simpleFoam {wall['fvm']:.5f}  {wall['line']} peak {wall['peak']:.4f}",
        f"L2field            {cmp['L2']:.5f}  (noise {cmp['noiseL2']:.5f}; Linf {cmp['Linf']:.4f})",
        f"L2interior         {l2_interior:.5f}  (noise {noise_interior:.5f}; {bins.interior.sum()} bins whose continuum cells are all fluid)"]
        + compare_summary(cmp, lines)
        + [f"# by local pore size (diameter of the largest fluid disc covering the bin): {CLASS_COLUMNS}"]
        + class_lines("poreSize ", by_pore)
        + [f"# by distance from the bin centre to the solid: {CLASS_COLUMNS}"]
        + class_lines("wallDistance", by_dist)
        + [f"worstPoreClass     {worst[0]:g}-{worst[1]:g}: L2 {worst[3]:.4f}, mean ratio {worst[5]:.4f}"], checks)

    plot_fields(bins, kT, inside, os.path.dirname(table))
    plot_comparison(bins, cmp, lines, prof, twin, l2_interior)
    print("Written porousMedium.png, compareFVM.png and results.dat")
    return checks.status()


if __name__ == "__main__":
    sys.exit(main())
