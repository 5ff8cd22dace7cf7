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
import re
import sys

import numpy as np

from dpdfoam.checks import Checks, write_results
from dpdfoam.fields import bin_temperatures, extent, foam_on_bins, read_grid, relative_l2
from dpdfoam.io import (dictionary_value, latest, log_count, log_values, read_compare, read_dict, read_sections,
                        read_table, read_text, run_finished)
from dpdfoam.mask import case_mask, distance_to_solid, local_pore_size, on_grid
from dpdfoam.plots import draw_compare_lines, draw_field, label, plt, save
from dpdfoam.published import read_published
from dpdfoam.stats import mean_and_error

test_mode = "-test" in sys.argv[1:]

# Noise budgets (the largest noise at which a check still decides). Full scene, measured (README;
# 2026-11-24): crack noiseL2 0.023-0.024, superficial velocity 0.12 % (relative), kT of the log's series
# 0.0005-0.0006, near-grain velocity 0.013 % of the peak; budgets about twice that. Test (160 time
# units on the 40 x 40 mask; measured at 40 time units: noiseL2 0.233, superficial 2.7 %, kT 0.0047,
# near-grain velocity 0.63 % of the peak; four times the sampling halves each): budgets 1.3 x the
# expected. Velocity next to the grains: standard error of
# the mean over the near-grain bins, relative to the crack's peak.
NOISE_BUDGETS = {
    False: {"line": 0.05, "mean": 0.003, "kT": 0.0012, "wall": 0.0003},
    True: {"line": 0.15, "mean": 0.018, "kT": 0.003, "wall": 0.004},
}
BUDGET = NOISE_BUDGETS[test_mode]
WIDEN = 3.0 if test_mode else 0.0  # test bounds: the full bound plus three test budgets, fixed
CLASS_COLUMNS = "lo hi bins L2 noiseL2 meanRatio uFVMmean densityWholeBins"


def solver_log():
    """The report times and kT series, the particles inside the solid at the end, those the bounce layer
    found crossed over the run, and the run's (steps, seconds, rate)."""
    text = read_text("log.dpdFoamLike")
    times, kts = log_values(text, r"^Time = ([-0-9.eE+]+)", flags=re.M), log_values(text, r"kT = ([-0-9.eE+]+)")
    inside = log_values(text, r"inside walls now (\d+)", int)
    crossed = log_values(text, r"geometry returned \d+ crossed (\d+);", int)
    if not kts or not inside or "Run finished" not in text:
        sys.exit("plotResults: log.dpdFoamLike has no report or no end")
    return np.array(times[-len(kts):]), np.array(kts), inside[-1], sum(crossed), run_finished(text)


def built_counts():
    """The fluid and frozen particles randomEquilWall built (its log)."""
    counts = [log_count("log.randomEquilWall", f"{what} particles") for what in ("Fluid", "Frozen")]
    if not all(isinstance(n, int) for n in counts):
        sys.exit("plotResults: log.randomEquilWall gives no particle counts")
    return counts


def next_to_grains(grid, ufx, near, prof, lines):
    """Over the bins near the grains: the mean DPD and simpleFoam velocities, the DPD mean's standard
    error, and the velocity scale, the continuum's peak along the lines (the crack's), with its line."""
    peaks = {name: np.nanmax(prof["u_" + name]) for name in lines}
    line = max(peaks, key=peaks.get)
    se = np.sqrt(np.mean(grid["uxErr"][near] ** 2) / near.sum())
    return dict(dpd=grid["ux"][near].mean(), fvm=ufx[near].mean(), se=se, peak=peaks[line], line=line, bins=near.sum())


def class_table(key, edges, ud, uf, err, rho, whole):
    """Per class of key: bins, L2, noise L2, flow ratio DPD/FVM, mean FVM velocity, and the mean DPD
    density of the class's bins that lie wholly in the fluid (whole; nan where none do): a throat the
    walls' repulsion reaches across is depleted, which the continuum does not know."""
    rows = []
    for lo, hi in zip(edges[:-1], edges[1:]):
        sel = (key >= lo) & (key < hi) & np.isfinite(uf) & np.isfinite(ud)
        if sel.sum() < 3:
            continue
        l2, noise = relative_l2(ud[sel], uf[sel], err[sel])
        dense = sel & whole
        density = rho[dense].mean() if dense.any() else float("nan")
        rows.append((lo, hi, int(sel.sum()), l2, noise, ud[sel].sum() / uf[sel].sum(), uf[sel].mean(), density))
    return rows


def class_lines(name, rows):
    return [f"{name} {r[0]:g} {r[1]:g} {r[2]} {r[3]:.4f} {r[4]:.4f} {r[5]:.4f} {r[6]:.5f} {r[7]:.3f}" for r in rows]


def make_checks(cmp, lines, kT_bins, kT_log, kT_log_err, inside, wall):
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
             "mean": super_err, "kT": kT_log_err, "wall": wall["se"] / u_peak}
    checks = Checks()
    for name, value in noise.items():
        limit = BUDGET[name.split()[0]]
        checks.add(f"noise of the {name} within its budget {limit:g}", value <= limit, f"{value:.4g}")
    checks.add(f"mean kT of the bins within {kT_tol:.3f} of 1", abs(kT_bins - 1) < kT_tol, f"{kT_bins:.4f}")
    checks.add(f"mean kT of the log's series within {kT_tol:.3f} of 1", abs(kT_log - 1) < kT_tol, f"{kT_log:.4f} +- {kT_log_err:.4f}")
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
    times, kts, inside, crossed, (steps, seconds, rate) = solver_log()
    cmp_path = latest("postProcessing/compareFVM/*/compare.dat")
    cmp, lines = read_compare(cmp_path)
    if not lines:
        sys.exit("plotResults: compare.dat has no line (system/makeFoamCaseDict: lines)")
    prof = read_table(os.path.join(os.path.dirname(cmp_path), "profiles.dat"))
    twin = read_dict("simpleFoam/constant/dpdCase")   # nu and where it came from
    sample_start = float(dictionary_value("system/controlDict", "functions/flowField/startTime"))

    # Temperature: the bins' kT (about each bin's own flow) and the log's series (about the local flow,
    # system/Monitors); flow_kT is what a global mean would have added, for reference.
    count = grid["count"]
    fluid = count >= 10
    kT_bins, flow_kT = bin_temperatures(grid, fluid)
    # Standard error of the series' mean: reports lie 10 time units or more apart, far beyond the
    # kinetic temperature's correlation time (~1), so they count as independent.
    kT_log, kT_log_err = mean_and_error(kts[times >= sample_start])

    # The two fields on the bins.
    ufx, ufz, fvm_cells = foam_on_bins("simpleFoam", xs, zs)
    fvm_fraction = fvm_cells / fvm_cells.max()
    # Maps show the bins holding at least a quarter of a full bin's particles: in bins the grains'
    # surface cuts, the few particles in the sliver of fluid carry a large, biased mean (README).
    shown = count >= 0.25 * np.median(count[count > 0])
    speed_dpd = np.where(shown, np.hypot(grid["ux"], grid["uz"]), np.nan)
    # The mask at the bins' centres (the tutorial's: one pixel a bin).
    mask, mask_path, box_lo, box_hi = case_mask()
    dist = distance_to_solid(on_grid(mask, box_lo, box_hi, xs, zs))
    pore = local_pore_size(dist)
    compared = fluid & np.isfinite(ufx)
    ud, uf, ue = grid["ux"][compared], ufx[compared], grid["uxErr"][compared]
    # The field away from the surface: bins whose every continuum cell is fluid.
    interior = compared & (fvm_fraction == 1)
    l2_interior, noise_interior = relative_l2(grid["ux"][interior], ufx[interior], grid["uxErr"][interior])
    # Next to the grains: bins the grains' surface passes through (the bin is solid in part: both
    # sides have cells there), i.e. fluid bins adjacent to a solid bin of the mask.
    wall = next_to_grains(grid, ufx, compared & (dist < 0.75), prof, lines)

    # Where they disagree: by local pore size and by distance to the solid.
    rho_c, whole_c = grid["density"][compared], (fvm_fraction == 1)[compared]
    by_pore = class_table(pore[compared], [0, 3, 5, 8, 12, 1e9], ud, uf, ue, rho_c, whole_c)
    by_dist = class_table(dist[compared], [0, 0.75, 1.5, 3, 1e9], ud, uf, ue, rho_c, whole_c)
    worst = max(by_pore, key=lambda r: r[3])
    checks = make_checks(cmp, lines, kT_bins, kT_log, kT_log_err, inside, wall)

    # The system's kT over the whole run (the log's series about the local flow): its largest
    # deviation from the set kT, a quantity the paper reports.
    worst_kT = int(np.argmax(np.abs(kts - 1.0)))
    fluid_built, frozen_built = built_counts()
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
        "kTSeries           (" + " ".join(f"{t:g}:{k:.4f}" for t, k in zip(times, kts)) + ")",
        f"kTLog              {kT_log:.5f} +- {kT_log_err:.5f}  (mean of the series from t = {sample_start:g})",
        f"kTFlowPart         {flow_kT:.5f}  (flow's kinetic energy per degree of freedom, from the bins: what a global mean would add)",
        f"kTBins             {kT_bins:.5f}",
        f"kTMaxDeviation     {kts[worst_kT] - 1:+.5f}  (largest of the log's {len(kts)} reports over the run, at t = {times[worst_kT]:g})",
        f"insideAtEnd        {inside}\ncrossedBounceLayer {crossed}  (whole run)",
        f"uNextToGrains      DPD {wall['dpd']:.5f}  simpleFoam {wall['fvm']:.5f}  {wall['line']} peak {wall['peak']:.4f}",
        f"L2field            {cmp['L2']:.5f}  (noise {cmp['noiseL2']:.5f}; Linf {cmp['Linf']:.4f})",
        f"L2interior         {l2_interior:.5f}  (noise {noise_interior:.5f}; {interior.sum()} bins whose continuum cells are all fluid)"]
        + [f"{'L2' + name:<18} {line['L2']:.5f}  (noise {line['noiseL2']:.5f}; Linf {line['Linf']:.4f}; mean ratio "
           f"{line['meanVelocityRatio']:.4f})" for name, line in lines.items()] + [
        f"meanVelocityRatio  {cmp['meanVelocityRatio']:.5f}  (DPD {cmp['meanVelocityDPD']:.5f}, simpleFoam {cmp['meanVelocityFVM']:.5f})",
        f"superficialVelocity DPD {cmp['superficialVelocityDPD']:.6f} +- {cmp['superficialVelocityDPDErr']:.6f}  "
        f"simpleFoam {cmp['superficialVelocityFVM']:.6f}",
        f"permeabilityDPD    {cmp['permeabilityDPD']:.5f} +- {cmp['permeabilityDPDErr']:.5f}",
        f"permeabilityFVM    {cmp['permeabilityFVM']:.5f}\npermeabilityRatio  {cmp['permeabilityRatio']:.5f}",
        f"# by local pore size (diameter of the largest fluid disc covering the bin): {CLASS_COLUMNS}"]
        + class_lines("poreSize ", by_pore)
        + [f"# by distance from the bin centre to the solid: {CLASS_COLUMNS}"]
        + class_lines("wallDistance", by_dist)
        + [f"worstPoreClass     {worst[0]:g}-{worst[1]:g}: L2 {worst[3]:.4f}, mean ratio {worst[5]:.4f}"], checks)

    ext = extent(xs, zs)
    plot_fields(grid, speed_dpd, ufx, xs, zs, times, kts, flow_kT, kT_bins, sample_start, inside, ext, os.path.dirname(table))
    plot_comparison(grid, speed_dpd, np.hypot(ufx, ufz), ufx, compared & shown, cmp, lines, prof, twin, l2_interior, ext)
    print("Written porousMedium.png, compareFVM.png and results.dat")
    return checks.status()


def plot_fields(grid, speed_dpd, ufx, xs, zs, times, kts, flow_kT, kT_bins, sample_start, inside, ext, directory):
    fig, ax = plt.subplots(2, 2, figsize=(13, 11))
    draw_field(fig, ax[0, 0], speed_dpd, ext, "DPD |u| (flowField.vti)", "|u|")
    draw_field(fig, ax[0, 1], np.where(grid["count"] > 0, grid["density"], np.nan), ext, "DPD density", "number density",
               cmap="magma")
    ax[1, 0].plot(times, kts, "o-", ms=3, label="log: kT about the local flow")
    ax[1, 0].axhline(1 + flow_kT, color="gray", ls=":", label=f"1 + flow part {flow_kT:.4f} (a global mean)")
    ax[1, 0].axhline(kT_bins, color="r", ls="--", label=f"bins (about local flow): {kT_bins:.4f}")
    ax[1, 0].axhline(1, color="k", lw=0.8)
    ax[1, 0].axvline(sample_start, color="k", ls=":", lw=0.8)
    label(ax[1, 0], f"kT series; {inside} particles inside the solid at the end", "time", "kT", legend=8)
    # The sections of system/controlDict (the tutorial's: the crack at its narrowest and widest).
    for x, s in read_sections(directory, "flowField"):
        col = int(np.argmin(np.abs(xs - x)))
        ok = s["count"] >= 10
        line = ax[1, 1].errorbar(s["z"][ok], s["ux"][ok], yerr=s["uxErr"][ok], fmt="o", ms=2, label=f"DPD x = {x:g}")
        ax[1, 1].plot(zs, ufx[:, col], "-", color=line[0].get_color(), lw=1, label=f"simpleFoam x = {x:g}")
    label(ax[1, 1], "across the flow at the sections of system/controlDict", "z", "ux", legend=8)
    save(fig, "porousMedium.png")


def plot_comparison(grid, speed_dpd, speed_fvm, ufx, shown, cmp, lines, prof, twin, l2_interior, ext):
    fig, ax = plt.subplots(2, 2, figsize=(13, 11))
    vmax = np.nanmax(speed_fvm)
    draw_field(fig, ax[0, 0], speed_dpd, ext, "DPD |u|", "|u|", vmin=0, vmax=vmax)
    draw_field(fig, ax[0, 1], speed_fvm, ext, "simpleFoam |u| (on the DPD bins)", "|u|", vmin=0, vmax=vmax)
    diff = np.where(shown, grid["ux"] - ufx, np.nan)
    lim = np.nanpercentile(np.abs(diff), 99)
    draw_field(fig, ax[1, 0], diff, ext, f"difference: L2 field {cmp['L2']:.3f}, interior {l2_interior:.3f}",
               "ux DPD - ux simpleFoam", title_size=10, cmap="RdBu_r", vmin=-lim, vmax=lim)
    draw_compare_lines(ax[1, 1], prof, lines, twin["nu"])  # each line of system/makeFoamCaseDict
    label(ax[1, 1], "lines of system/makeFoamCaseDict: " + "; ".join(f"{n} L2 {line['L2']:.4f}" for n, line in lines.items())
          + f"; k DPD/FVM {cmp['permeabilityRatio']:.3f}", "position along the line", "ux", legend=8)
    save(fig, "compareFVM.png")


if __name__ == "__main__":
    sys.exit(main())
