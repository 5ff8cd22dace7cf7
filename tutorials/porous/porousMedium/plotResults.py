#!/usr/bin/env python3
"""Porous medium tutorial (docs/scenes.md scene 6): pictures, results table and the checks.

Reads the DPD 2-D field (postProcessing/profileBins/<time>/flowField.dat, 1 x 1 bins), the solver's
log (kT series, particles inside the solid, run time), the simpleFoam twin (simpleFoam/<time>/C, U,
constant/dpdCase for nu), compareFVM's result (postProcessing/compareFVM/<time>/compare.dat,
profiles.dat), the built counts (log.randomEquilWall) and the paper's (published.dat, when there).
Writes porousMedium.png (DPD |u|, density, kT series, profiles across the flow at the sections),
compareFVM.png (DPD |u|, simpleFoam |u|, their difference, the lines) and results.dat; exits non-zero
when a check fails. Everything about the geometry comes from the case: the lines are those of
system/makeFoamCaseDict (compareFVM compares each; the tutorial's is its crack's centre line, which
crackFromMask.py moves onto the crack of a mask of one's own), the sections those of system/controlDict,
and the grains, the pores and the bins next to them from the mask (constant/dpdProperties, at the
bins' centres over the box of system/randomEquilWallDict).

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
Test mode (40 x 40 mask, 160 time units of sampling): the same checks, each bound the full one plus
three test budgets (fixed, derived below for the shorter run). Next to the grains the bound is the
larger of 10 % of the peak and simpleFoam's own velocity there plus 3 % of the peak (in the small mask
the continuum itself has ~11 % there). In test mode the crack line (noise ~0.12 over 40 bins) only
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
from dpdfoam.io import (dictionary_value, foam_latest_time, foam_vector_field, latest, log_values, read_compare,
                        read_dict, read_sections, read_table, read_text, run_finished)
from dpdfoam.mask import case_mask, distance_to_solid, local_pore_size, on_grid
from dpdfoam.plots import label, plt, save
from dpdfoam.published import read_published

test_mode = "-test" in sys.argv[1:]

# Noise budgets (the largest noise at which a check still decides). Full scene, measured (README;
# 2026-11-24): crack noiseL2 0.023-0.024, superficial velocity 0.12 % (relative), kT of the log's series
# 0.0005-0.0006, near-grain velocity 0.013 % of the peak; budgets about twice that. Test (160 time units on the 40 x 40 mask; measured at 40 time units:
# noiseL2 0.233, superficial 2.7 %, kT 0.0047, near-grain velocity 0.63 % of the peak; four times the
# sampling halves each): budgets 1.3 x the expected. Velocity next to the grains: standard error of
# the mean over the near-grain bins, relative to the crack's peak.
NOISE_BUDGETS = {
    False: {"line": 0.05, "mean": 0.003, "kT": 0.0012, "wall": 0.0003},
    True: {"line": 0.15, "mean": 0.018, "kT": 0.003, "wall": 0.004},
}


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
    text = read_text("log.randomEquilWall")
    counts = [re.search(rf"^{what} particles *: *(\d+)", text, re.M) for what in ("Fluid", "Frozen")]
    if None in counts:
        sys.exit("plotResults: log.randomEquilWall gives no particle counts")
    return [int(m.group(1)) for m in counts]


def foam_on_bins(xs, zs):
    """simpleFoam's U gathered into the DPD bins (mean over the fluid cells in each; NaN in solid), and
    the fraction of each bin's cells that are fluid."""
    t = foam_latest_time("simpleFoam")
    C, U = foam_vector_field(f"simpleFoam/{t}/C"), foam_vector_field(f"simpleFoam/{t}/U")
    w = xs[1] - xs[0]
    i = np.floor((C[:, 0] - (xs[0] - w / 2)) / w).astype(int)
    k = np.floor((C[:, 2] - (zs[0] - w / 2)) / w).astype(int)
    n = np.zeros((len(zs), len(xs)))
    np.add.at(n, (k, i), 1)
    out = []
    for comp in (0, 2):
        s = np.zeros((len(zs), len(xs)))
        np.add.at(s, (k, i), U[:, comp])
        out.append(np.where(n > 0, s / np.maximum(n, 1), np.nan))
    return out[0], out[1], n / n.max()


def class_table(key, edges, ud, uf, err, rho, whole):
    """Per class of key: bins, L2, noise L2, flow ratio DPD/FVM, mean FVM velocity, and the mean DPD
    density of the class's bins that lie wholly in the fluid (whole; nan where none do): a throat the
    walls' repulsion reaches across is depleted, which the continuum does not know."""
    rows = []
    for lo, hi in zip(edges[:-1], edges[1:]):
        sel = (key >= lo) & (key < hi) & np.isfinite(uf) & np.isfinite(ud)
        if sel.sum() < 3:
            continue
        l2 = np.sqrt(np.sum((ud[sel] - uf[sel]) ** 2) / np.sum(uf[sel] ** 2))
        noise = np.sqrt(np.sum(err[sel] ** 2) / np.sum(uf[sel] ** 2))
        dense = sel & whole
        density = rho[dense].mean() if dense.any() else float("nan")
        rows.append((lo, hi, int(sel.sum()), l2, noise, ud[sel].sum() / uf[sel].sum(), uf[sel].mean(), density))
    return rows


def class_lines(name, rows):
    return [f"{name} {r[0]:g} {r[1]:g} {r[2]} {r[3]:.4f} {r[4]:.4f} {r[5]:.4f} {r[6]:.5f} {r[7]:.3f}" for r in rows]


def main():
    table = latest("postProcessing/profileBins/*/flowField.dat")
    g = read_table(table)
    xs, zs = np.unique(g["x"]), np.unique(g["z"])
    shape = (len(zs), len(xs))
    grid = {k: v.reshape(shape) for k, v in g.items()}
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
    kT_bins = np.sum(grid["kT"][fluid] * count[fluid]) / np.sum(count[fluid])
    w = count / count.sum()
    mean_u = [np.sum(w * grid[c]) for c in ("ux", "uy", "uz")]
    flow_kT = sum(np.sum(w * (grid[c] - m) ** 2) for c, m in zip(("ux", "uy", "uz"), mean_u)) / 3
    in_window = times >= sample_start
    kT_log = kts[in_window].mean()
    # Standard error of the series' mean: reports lie 10 time units or more apart, far beyond the
    # kinetic temperature's correlation time (~1), so they count as independent.
    kT_log_err = np.std(kts[in_window], ddof=1) / np.sqrt(max(1, in_window.sum()))

    # The two fields on the bins.
    ufx, ufz, fvm_fraction = foam_on_bins(xs, zs)
    # Maps show the bins holding at least a quarter of a full bin's particles: in bins the grains'
    # surface cuts, the few particles in the sliver of fluid carry a large, biased mean (README).
    shown = count >= 0.25 * np.median(count[count > 0])
    speed_dpd = np.where(shown, np.hypot(grid["ux"], grid["uz"]), np.nan)
    # The mask at the bins' centres (the tutorial's: one pixel a bin).
    mask, mask_path, box_lo, box_hi = case_mask()
    solid = on_grid(mask, box_lo, box_hi, xs, zs)
    dist = distance_to_solid(solid)
    pore = local_pore_size(dist)
    compared = fluid & np.isfinite(ufx)
    ud, uf, ue = grid["ux"][compared], ufx[compared], grid["uxErr"][compared]
    # The field away from the surface: bins whose every continuum cell is fluid.
    interior = compared & (fvm_fraction == 1)
    l2_interior = np.sqrt(np.sum((grid["ux"][interior] - ufx[interior]) ** 2) / np.sum(ufx[interior] ** 2))
    noise_interior = np.sqrt(np.sum(grid["uxErr"][interior] ** 2) / np.sum(ufx[interior] ** 2))

    # Next to the grains: bins the grains' surface passes through (the bin is solid in part: both
    # sides have cells there), i.e. fluid bins adjacent to a solid bin of the mask. The velocity scale:
    # the continuum's peak along the lines (the crack's).
    near = compared & (dist < 0.75)
    peaks = {name: np.nanmax(prof["u_" + name]) for name in lines}
    peak_line = max(peaks, key=peaks.get)
    u_peak = peaks[peak_line]
    u_wall_dpd, u_wall_fvm = grid["ux"][near].mean(), ufx[near].mean()

    # Where they disagree: by local pore size and by distance to the solid.
    rho_c, whole_c = grid["density"][compared], (fvm_fraction == 1)[compared]
    by_pore = class_table(pore[compared], [0, 3, 5, 8, 12, 1e9], ud, uf, ue, rho_c, whole_c)
    by_dist = class_table(dist[compared], [0, 0.75, 1.5, 3, 1e9], ud, uf, ue, rho_c, whole_c)
    worst = max(by_pore, key=lambda r: r[3])

    ratio_super = cmp["permeabilityRatio"]
    super_err = cmp["superficialVelocityDPDErr"] / cmp["superficialVelocityFVM"]
    budget = NOISE_BUDGETS[test_mode]
    widen = 3.0 if test_mode else 0.0  # test bounds: the full bound plus three test budgets, fixed
    line_tol = 0.10 + widen * budget["line"]
    mean_tol = 0.10 + widen * budget["mean"]
    kT_tol = 0.035 + widen * budget["kT"]
    # Next to the grains: 10 % of the crack's peak. In the test's small mask the bins the grains cut
    # hold more of the flow: simpleFoam's own velocity there is ~11 % of the peak (0.0195 of 0.182),
    # so a correct no-slip run sits at the bound. There the bound is the continuum's value plus the
    # 3 %-of-peak allowance of the next check, plus three test budgets like every test bound; a
    # slipping wall (velocity of the order of the pore's) is still far above it.
    wall_se = np.sqrt(np.mean(grid["uxErr"][near] ** 2) / near.sum())
    wall_bound = 0.1 * u_peak
    if test_mode:
        wall_bound = max(wall_bound, abs(u_wall_fvm) + 0.03 * u_peak) + widen * budget["wall"] * u_peak
    noise = {**{f"line {name}" if len(lines) > 1 else "line": line["noiseL2"] for name, line in lines.items()},
             "mean": super_err, "kT": kT_log_err, "wall": wall_se / u_peak}
    checks = Checks()
    for name, value in noise.items():
        limit = budget[name.split()[0]]
        checks.add(f"noise of the {name} within its budget {limit:g}", value <= limit, f"{value:.4g}")
    checks.add(f"mean kT of the bins within {kT_tol:.3f} of 1", abs(kT_bins - 1) < kT_tol, f"{kT_bins:.4f}")
    checks.add(f"mean kT of the log's series within {kT_tol:.3f} of 1", abs(kT_log - 1) < kT_tol, f"{kT_log:.4f} +- {kT_log_err:.4f}")
    checks.add("no fluid particle inside the solid at the end", inside == 0, f"{inside}")
    checks.add(f"velocity next to the grains < {wall_bound / u_peak:.1%} of the {peak_line}'s peak", abs(u_wall_dpd) < wall_bound,
               f"{u_wall_dpd:.4f} (peak {u_peak:.4f})")
    checks.add("velocity next to the grains within 3 % of the peak of simpleFoam's there",
               abs(u_wall_dpd - u_wall_fvm) < 0.03 * u_peak + widen * budget["wall"] * u_peak,
               f"DPD {u_wall_dpd:.4f}, simpleFoam {u_wall_fvm:.4f} over {near.sum()} bins")
    for name, line in lines.items():
        checks.add(f"{name} centre line: relative L2 < {line_tol:.3f}", line["L2"] < line_tol,
                   f"{line['L2']:.4f} (noise {line['noiseL2']:.4f}, {int(line['points'])} bins)")
    checks.add(f"mean velocity over the compared bins within {mean_tol:.3f}", abs(cmp["meanVelocityRatio"] - 1) < mean_tol,
               f"{cmp['meanVelocityRatio']:.4f}")
    checks.add(f"superficial velocity (permeability) within {mean_tol:.3f}", abs(ratio_super - 1) < mean_tol,
               f"{ratio_super:.4f} +- {super_err:.4f}")

    # The system's kT over the whole run (the log's series about the local flow): its largest
    # deviation from the set kT, a quantity the paper reports.
    worst_kT = int(np.argmax(np.abs(kts - 1.0)))
    fluid_built, frozen_built = built_counts()
    paper = read_published("published.dat")["tables"].get("counts") if os.path.exists("published.dat") else None
    write_results("results.dat", [
        f"# Porous medium (docs/scenes.md scene 6){' - TEST MODE' if test_mode else ''}: {table}, {cmp_path}",
        f"mask               {mask_path}  ({shape[1]} x {shape[0]} bins of 1 r_c)",
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
        f"uNextToGrains      DPD {u_wall_dpd:.5f}  simpleFoam {u_wall_fvm:.5f}  {peak_line} peak {u_peak:.4f}",
        f"L2field            {cmp['L2']:.5f}  (noise {cmp['noiseL2']:.5f}; Linf {cmp['Linf']:.4f})",
        f"L2interior         {l2_interior:.5f}  (noise {noise_interior:.5f}; {interior.sum()} bins whose continuum cells are all fluid)"]
        + [f"{'L2' + name:<18} {line['L2']:.5f}  (noise {line['noiseL2']:.5f}; Linf {line['Linf']:.4f}; mean ratio "
           f"{line['meanVelocityRatio']:.4f})" for name, line in lines.items()] + [
        f"meanVelocityRatio  {cmp['meanVelocityRatio']:.5f}  (DPD {cmp['meanVelocityDPD']:.5f}, simpleFoam {cmp['meanVelocityFVM']:.5f})",
        f"superficialVelocity DPD {cmp['superficialVelocityDPD']:.6f} +- {cmp['superficialVelocityDPDErr']:.6f}  "
        f"simpleFoam {cmp['superficialVelocityFVM']:.6f}",
        f"permeabilityDPD    {cmp['permeabilityDPD']:.5f} +- {cmp['permeabilityDPDErr']:.5f}",
        f"permeabilityFVM    {cmp['permeabilityFVM']:.5f}\npermeabilityRatio  {ratio_super:.5f}",
        "# by local pore size (diameter of the largest fluid disc covering the bin): lo hi bins L2 noiseL2 meanRatio uFVMmean densityWholeBins"]
        + class_lines("poreSize ", by_pore)
        + ["# by distance from the bin centre to the solid: lo hi bins L2 noiseL2 meanRatio uFVMmean densityWholeBins"]
        + class_lines("wallDistance", by_dist)
        + [f"worstPoreClass     {worst[0]:g}-{worst[1]:g}: L2 {worst[3]:.4f}, mean ratio {worst[5]:.4f}"], checks)

    ext = [xs[0] - 0.5, xs[-1] + 0.5, zs[0] - 0.5, zs[-1] + 0.5]
    plot_fields(grid, speed_dpd, ufx, xs, zs, times, kts, flow_kT, kT_bins, sample_start, inside, ext, os.path.dirname(table))
    plot_comparison(grid, speed_dpd, np.hypot(ufx, ufz), ufx, compared & shown, cmp, lines, prof, twin, l2_interior, ext)
    print("Written porousMedium.png, compareFVM.png and results.dat")
    return checks.status()


def plot_fields(grid, speed_dpd, ufx, xs, zs, times, kts, flow_kT, kT_bins, sample_start, inside, ext, directory):
    fig, ax = plt.subplots(2, 2, figsize=(13, 11))
    im = ax[0, 0].imshow(speed_dpd, origin="lower", extent=ext, cmap="viridis")
    fig.colorbar(im, ax=ax[0, 0], label="|u|")
    ax[0, 0].set_title("DPD |u| (flowField.vti)")
    im = ax[0, 1].imshow(np.where(grid["count"] > 0, grid["density"], np.nan), origin="lower", extent=ext, cmap="magma")
    fig.colorbar(im, ax=ax[0, 1], label="number density")
    ax[0, 1].set_title("DPD density")
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
    for a, field, title in ((ax[0, 0], speed_dpd, "DPD |u|"), (ax[0, 1], speed_fvm, "simpleFoam |u| (on the DPD bins)")):
        im = a.imshow(field, origin="lower", extent=ext, cmap="viridis", vmin=0, vmax=vmax)
        fig.colorbar(im, ax=a, label="|u|")
        a.set_title(title)
    diff = np.where(shown, grid["ux"] - ufx, np.nan)
    lim = np.nanpercentile(np.abs(diff), 99)
    im = ax[1, 0].imshow(diff, origin="lower", extent=ext, cmap="RdBu_r", vmin=-lim, vmax=lim)
    fig.colorbar(im, ax=ax[1, 0], label="ux DPD - ux simpleFoam")
    ax[1, 0].set_title(f"difference: L2 field {cmp['L2']:.3f}, interior {l2_interior:.3f}", fontsize=10)
    # Each line of system/makeFoamCaseDict: the bins on it (profiles.dat: x z uDPD uDPDErr uFVM u_<line>).
    for name in lines:
        on = np.isfinite(prof["u_" + name])
        along = "x" if np.ptp(prof["x"][on]) >= np.ptp(prof["z"][on]) else "z"
        dots = ax[1, 1].errorbar(prof[along][on], prof["uDPD"][on], yerr=prof["uDPDErr"][on], fmt="o", ms=2,
                                 label=f"DPD (bins on the line {name}, {on.sum()})")
        ax[1, 1].plot(prof[along][on], prof["u_" + name][on], "-", color=dots[0].get_color(), lw=1.2,
                      label=f"simpleFoam, nu = {twin['nu']:.4f}")
    label(ax[1, 1], "lines of system/makeFoamCaseDict: " + "; ".join(f"{n} L2 {line['L2']:.4f}" for n, line in lines.items())
          + f"; k DPD/FVM {cmp['permeabilityRatio']:.3f}", "position along the line", "ux", legend=8)
    save(fig, "compareFVM.png")


if __name__ == "__main__":
    sys.exit(main())
