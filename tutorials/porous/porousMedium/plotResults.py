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
Each check first asserts that the noise of its quantity is within a budget (NOISE_BUDGETS below), so
that a run too noisy to decide fails instead of passing more easily; the bound is then fixed.
Test mode (40 x 40 mask, 160 time units of sampling): each bound the full one plus three test budgets
(fixed, derived below for the shorter run). There the crack line (noise ~0.12 over 40 bins) only
catches gross errors (a slipping or missing wall, a unit slip); the full scene decides it.

Where the two disagree: each fluid bin gets the local pore size (the diameter of the largest disc in
the fluid that covers it, from the mask) and its distance to the solid; results.dat gives the relative
L2 and the mean-velocity ratio per class of each.
"""
import os
import sys

import numpy as np

from dpdfoam.checks import Checks, write_results
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
NOISE_BUDGETS = {False: {"line": 0.05, "mean": 0.003, "kT": 0.0012, "wall": 0.0003},
                 True: {"line": 0.15, "mean": 0.018, "kT": 0.003, "wall": 0.004}}
BUDGET = NOISE_BUDGETS[test_mode]
WIDEN = 3.0 if test_mode else 0.0  # test bounds: the full bound plus three test budgets, fixed


def next_to_grains(bins, near, prof, lines):
    """Over the bins near the grains: the mean DPD and simpleFoam velocities, the DPD mean's standard
    error, and the velocity scale, the continuum's peak along the lines (the crack's), with its line."""
    peaks = {name: np.nanmax(prof["u_" + name]) for name in lines}
    line = max(peaks, key=peaks.get)
    return dict(bins.region_means(near), peak=peaks[line], line=line)


def make_checks(cmp, lines, kT, inside, wall):
    """The checks: each quantity's noise within its budget, then its fixed bound (module docstring)."""
    line_tol = 0.10 + WIDEN * BUDGET["line"]
    mean_tol = 0.10 + WIDEN * BUDGET["mean"]
    kT_tol = 0.035 + WIDEN * BUDGET["kT"]
    # Next to the grains: 10 % of the crack's peak. In the test's small mask the bins the grains cut
    # hold more of the flow: simpleFoam's own velocity there is ~11 % of the peak (0.0195 of 0.182),
    # so a correct no-slip run sits at the bound. There the bound is the continuum's value plus the
    # 3 %-of-peak allowance of the next check, plus three test budgets like every test bound; a
    # slipping wall (velocity of the order of the pore's) is still far above it.
    u_peak, u_dpd, u_fvm = wall["peak"], wall["dpd"], wall["fvm"]
    wall_bound = 0.1 * u_peak
    if test_mode:
        wall_bound = max(wall_bound, abs(u_fvm) + 0.03 * u_peak) + WIDEN * BUDGET["wall"] * u_peak
    super_err = cmp["superficialVelocityDPDErr"] / cmp["superficialVelocityFVM"]
    noise = {**{f"line {name}" if len(lines) > 1 else "line": line["noiseL2"] for name, line in lines.items()},
             "mean": super_err, "kT": kT.error, "wall": wall["se"] / u_peak}
    checks = Checks()
    for name, value in noise.items():
        limit = BUDGET[name.split()[0]]
        checks.add(f"noise of the {name} within its budget {limit:g}", value <= limit, f"{value:.4g}")
    checks.add(f"mean kT of the bins within {kT_tol:.3f} of 1", abs(kT.bins - 1) < kT_tol, f"{kT.bins:.4f}")
    checks.add(f"mean kT of the log's series within {kT_tol:.3f} of 1", abs(kT.mean - 1) < kT_tol, f"{kT.mean:.4f} +- {kT.error:.4f}")
    checks.add("no fluid particle inside the solid at the end", inside == 0, f"{inside}")
    checks.add(f"velocity next to the grains < {wall_bound / u_peak:.1%} of the {wall['line']}'s peak", abs(u_dpd) < wall_bound,
               f"{u_dpd:.4f} (peak {u_peak:.4f})")
    checks.add("velocity next to the grains within 3 % of the peak of simpleFoam's there",
               abs(u_dpd - u_fvm) < 0.03 * u_peak + WIDEN * BUDGET["wall"] * u_peak,
               f"DPD {u_dpd:.4f}, simpleFoam {u_fvm:.4f} over {wall['bins']} bins")
    for name, line in lines.items():
        checks.add(f"{name} centre line: relative L2 < {line_tol:.3f}", line["L2"] < line_tol,
                   f"{line['L2']:.4f} (noise {line['noiseL2']:.4f}, {int(line['points'])} bins)")
    checks.add(f"mean velocity over the compared bins within {mean_tol:.3f}", abs(cmp["meanVelocityRatio"] - 1) < mean_tol,
               f"{cmp['meanVelocityRatio']:.4f}")
    checks.add(f"superficial velocity (permeability) within {mean_tol:.3f}", abs(cmp["permeabilityRatio"] - 1) < mean_tol,
               f"{cmp['permeabilityRatio']:.4f} +- {super_err:.4f}")
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
