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

import numpy as np

from dpdfoam.checks import Checks, as_number, finite, write_results
from dpdfoam.fields import CLASS_COLUMNS, FlowTemperature, TwinBins, class_lines, compare_summary, extent, read_grid
from dpdfoam.io import (built_particles, finished_solver_log, function_start, latest, latest_compare_lines, read_dict,
                        read_sections)
from dpdfoam.mask import case_regions_on_grid
from dpdfoam.plots import draw_compare_lines, draw_field, draw_kT_series, draw_sections_twin, draw_twin_fields, label, plt, save
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


def bound(kind, test):
    """A check's fixed bound: the full scene's, in test mode widened by three test budgets (the crack line:
    TEST_LINE_BOUND)."""
    full = {"kT": KT_BOUND, "wall": WALL_BOUND, "twin": WALL_TWIN_BOUND, "line": LINE_BOUND, "mean": MEAN_BOUND}[kind]
    if not test:
        return full
    if kind == "line":
        return TEST_LINE_BOUND
    return full + WIDEN * NOISE_BUDGETS[True]["wall" if kind == "twin" else kind]


def next_to_grains(bins, near, prof, lines):
    """Over the bins near the grains: the mean DPD and simpleFoam velocities, the DPD mean's standard
    error, and the velocity scale, the continuum's peak along the lines (the crack's), with its line."""
    peaks = {name: np.nanmax(prof["u_" + name]) for name in lines}
    line = max(peaks, key=peaks.get)
    return dict(bins.region_means(near), peak=peaks[line], line=line)


def kT_check(checks, what, kT, error, test):
    """The mean kT within the bound of 1, the kT's standard error (the log series') within its budget."""
    budget, tol = NOISE_BUDGETS[test]["kT"], bound("kT", test)
    shown = f"{as_number(kT):.4f}" + (f" +- {as_number(error):.4f}" if what != "the bins" else "")
    return checks.bounded(f"mean kT of {what} within {tol:.3f} of 1 (standard error below {budget:g})", kT, error, budget,
                          1.0 - tol, 1.0 + tol, shown)


def inside_check(checks, inside):
    """No fluid particle inside the solid at the end (the solver's count): exactly 0; a missing count fails."""
    return checks.add("no fluid particle inside the solid at the end", inside == 0 and finite(inside), f"{inside}")


def wall_checks(checks, u_dpd, u_fvm, error, peak, line, bins, test):
    """Velocity near zero next to the grains (the mean DPD velocity over the bins the grains' surface
    passes through, its standard error, the twin's mean there, the crack's peak): below 10 % of the peak,
    and within 3 % of that peak of simpleFoam's there, each in units of the peak, its standard error first
    within the budget. In the test's small mask the bins the grains cut hold more of the flow:
    simpleFoam's own velocity there is ~11 % of the peak (0.0195 of 0.182), so a correct no-slip run would
    sit at the bound; there the first bound is the larger of 10 % and the continuum's value plus the 3 %
    of the second check, plus three test budgets like every test bound of a mean; a slipping wall
    (velocity of the order of the pore's) is still far above it."""
    u_dpd, u_fvm, error, peak = (as_number(v) for v in (u_dpd, u_fvm, error, peak))
    peak = peak if peak > 0 else float("nan")  # no flow to scale by: fails
    budget = NOISE_BUDGETS[test]["wall"]
    wall_bound = WALL_BOUND
    if test:
        wall_bound = max(WALL_BOUND, abs(u_fvm / peak) + WALL_TWIN_BOUND) + WIDEN * budget
    twin_bound = bound("twin", test)
    ok = checks.bounded(f"velocity next to the grains < {wall_bound:.1%} of the {line}'s peak (standard error below "
                        f"{budget:g} of it)", u_dpd / peak, error / peak, budget, -wall_bound, wall_bound,
                        f"{u_dpd:.4f} (peak {peak:.4f})")
    return checks.bounded(f"velocity next to the grains within {twin_bound:.1%} of the peak of simpleFoam's there "
                          f"(standard error below {budget:g} of it)", (u_dpd - u_fvm) / peak, error / peak, budget,
                          -twin_bound, twin_bound, f"DPD {u_dpd:.4f}, simpleFoam {u_fvm:.4f} over {bins} bins") and ok


def line_check(checks, name, l2, noise, points, test):
    """A line of system/makeFoamCaseDict (the crack's centre line): the relative L2 of DPD against
    simpleFoam below the bound, its noise L2 (what the DPD errors alone give) first within the budget."""
    budget, tol = NOISE_BUDGETS[test]["line"], bound("line", test)
    return checks.bounded(f"{name} centre line: relative L2 < {tol:.3f} (noise L2 below {budget:g})", l2, noise, budget,
                          None, tol, f"{as_number(l2):.4f} (noise {as_number(noise):.4f}, "
                          f"{int(as_number(points)) if finite(points) else points} bins)")


def mean_check(checks, what, ratio, error, test):
    """A mean velocity of DPD over simpleFoam's (over the compared bins; the superficial velocity, i.e. the
    permeability): within the bound of 1, the superficial velocity's relative standard error first within
    the budget."""
    budget, tol = NOISE_BUDGETS[test]["mean"], bound("mean", test)
    return checks.bounded(f"{what} within {tol:.3f} (standard error below {budget:g})", ratio, error, budget, 1.0 - tol,
                          1.0 + tol, f"{as_number(ratio):.4f} +- {as_number(error):.4f}")


def make_checks(cmp, lines, kT, inside, wall, test=None):
    """The checks (module docstring), from compareFVM's summary and lines, the kT (FlowTemperature), the
    particles inside the solid and the velocity next to the grains (next_to_grains)."""
    test = test_mode if test is None else test
    twin = as_number(cmp["superficialVelocityFVM"])
    super_err = as_number(cmp["superficialVelocityDPDErr"]) / twin if twin > 0 else float("nan")  # no twin flow: fails
    checks = Checks()
    kT_check(checks, "the bins", kT.bins, kT.error, test)
    kT_check(checks, "the log's series", kT.mean, kT.error, test)
    inside_check(checks, inside)
    wall_checks(checks, wall["dpd"], wall["fvm"], wall["se"], wall["peak"], wall["line"], wall["bins"], test)
    for name, line in lines.items():
        line_check(checks, name, line["L2"], line["noiseL2"], line["points"], test)
    mean_check(checks, "mean velocity over the compared bins", cmp["meanVelocityRatio"], super_err, test)
    mean_check(checks, "superficial velocity (permeability)", cmp["permeabilityRatio"], super_err, test)
    return checks


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


def plot_fields(bins, kT, inside, directory):
    fig, ax = plt.subplots(2, 2, figsize=(13, 11))
    grid, ext = bins.grid, extent(bins.xs, bins.zs)
    draw_field(fig, ax[0, 0], bins.dpd_speed(), ext, "DPD |u| (flowField.vti)", "|u|")
    draw_field(fig, ax[0, 1], np.where(grid["count"] > 0, grid["density"], np.nan), ext, "DPD density", "number density",
               cmap="magma")
    draw_kT_series(ax[1, 0], kT)
    label(ax[1, 0], f"kT series; {inside} particles inside the solid at the end", "time", "kT", legend=8)
    # The sections of system/controlDict (the tutorial's: the crack at its narrowest and widest).
    draw_sections_twin(ax[1, 1], read_sections(directory, "flowField"), bins.xs, bins.zs, bins.ufx)
    label(ax[1, 1], "across the flow at the sections of system/controlDict", "z", "ux", legend=8)
    save(fig, "porousMedium.png")


def plot_comparison(bins, cmp, lines, prof, twin, l2_interior):
    fig, ax = plt.subplots(2, 2, figsize=(13, 11))
    draw_twin_fields(fig, [ax[0, 0], ax[0, 1], ax[1, 0]], bins.dpd_speed(), bins.twin_speed(), bins.difference(), extent(bins.xs, bins.zs),
                     f"difference: L2 field {cmp['L2']:.3f}, interior {l2_interior:.3f}")
    draw_compare_lines(ax[1, 1], prof, lines, twin["nu"])  # each line of system/makeFoamCaseDict
    label(ax[1, 1], "lines of system/makeFoamCaseDict: " + "; ".join(f"{n} L2 {line['L2']:.4f}" for n, line in lines.items())
          + f"; k DPD/FVM {cmp['permeabilityRatio']:.3f}", "position along the line", "ux", legend=8)
    save(fig, "compareFVM.png")


if __name__ == "__main__":
    sys.exit(main())
