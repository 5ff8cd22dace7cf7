"""The contraction tutorials (docs/scenes.md scene 7: tutorials/contraction/squareContraction and
rampContraction): picture, results table and the checks of what the scene must show, the same for
every shape. A tutorial's plotResults.py calls main(title, arguments) in the tutorial directory: the
scene is the case there, the -chains variant (FENE chains in the flow) the copy in chains/ (with
-lowG, chainsLowG/).

Reads the 2-D fields and the sections profileBins wrote (postProcessing/profileBins/<time>/), and
the solver's log; draws the velocity map and, at each section, velocity, density and temperature
across the channel; writes results.dat (per section the mass flux, the peak and mean ux, the most
negative ux and the width and flux of reversed flow, density and kT; the difference between the
profiles at x = -25.5 and -16.5 with its noise); exits non-zero when a check fails:
  - no fluid particle inside the solid at the end (the solver's own count, log.dpdFoamLike);
  - the mean kT of the fluid is the set kT = 1 within 1 %, its standard error (the bins' kT errors,
    count-weighted) first within 0.001 (measured 0.0006 in the test modes, 2026-11-30): the
    Groot-Warren step 0.02 errs by well under 1 % (README, integrators), the bounce layer emits at
    kT, and the flow's viscous heating raises the mean by 0.1-0.4 % (measured 1.0008-1.0042 at full
    size, 1.0019-1.0042 in the test modes);
  - the mass flux rho ux integrated across the channel is the same at every section (steady,
    incompressible flow: what enters the contraction leaves it): each section's standard error within
    a budget relative to the mean flux (full 0.5 %, test 4 %: measured 0.25-0.48 % and 1.5-2.9 %),
    then every section within a fixed share of the mean flux (full 0.5 %, test 2 %). The sections'
    time-averaged fluxes differ only by the change of the mass between them over the window, far
    less than a section's own error, which holds every fluctuation of the flow through it: measured
    within 0.06 % at full size and 0.6 % in the test modes (2026-11-29/30).
The -chains variant (fluid and beads together in flowField) has the same checks, the solver's count
of particles inside the solid covering the beads too (it counts every mobile particle), and also
draws the beads' density (beadField) at the sections and on the grid, the chains' R_g, span and end-
to-end extension along x by where their centres lie (chainStatistics binned along x), and the chains
at the start (0/) and in the latest snapshot; it writes resultsChains.dat and contractionChains.png,
and checks that the latest snapshot still holds every bead and bond insertChains made (chains x
length beads, chains x (length - 1) bonds) and that the longest bond the log reports stays below
r_max.
Every check fails on a NaN (dpdfoam.checks).
"""
import math
import os
import re
import sys

import numpy as np
from matplotlib.collections import LineCollection

from .checks import Checks, as_number, print_file
from .io import header_means, latest, latest_dir, log_values, read_columns, read_dict, read_sections, read_table, read_text
from .plots import draw_map, label, plt, save
from .snapshots import chain_segments
from .sweep import weighted_error

SECTION_COLUMNS = "x flux fluxErr uxMax density kT uxMean uxMin reversedWidth reversedFlux"
FLUID_BIN = 10  # particle-samples in a bin the fluid fills


def solver_log(case="."):
    """The particles inside the solid at the end, the kT series and the bounce layer's (returned, crossed)."""
    text = read_text(os.path.join(case, "log.dpdFoamLike"))
    inside = log_values(text, r"inside walls now (\d+)", int)
    kts = log_values(text, r"kT = ([-0-9.eE+]+)")
    layer = re.findall(r"geometry returned (\d+) crossed (\d+);", text)
    if not inside or not kts:
        sys.exit("plotResults: log.dpdFoamLike has no report")
    return inside[-1], kts, [(int(a), int(b)) for a, b in layer]


def section_row(x, s):
    """SECTION_COLUMNS at a section: x, the mass flux rho ux dz across it with its error, the peak ux,
    the mean density and kT over the bins the fluid fills, the mean ux over them (particle-weighted),
    the most negative ux, and the width and mass flux of the reversed flow (the fluid bins whose ux lies
    below zero by more than two standard errors: a bin at the noise is not reversed flow)."""
    dz = s["z"][1] - s["z"][0]
    flux = np.sum(s["density"] * s["ux"]) * dz
    flux_err = math.sqrt(np.sum((s["density"] * s["uxErr"]) ** 2 + (s["ux"] * s["densityErr"]) ** 2)) * dz
    fluid = s["count"] >= FLUID_BIN
    ux, weight = s["ux"][fluid], s["count"][fluid]
    reversed_bins = ux < -2.0 * s["uxErr"][fluid]
    return (x, flux, flux_err, np.max(s["ux"]), np.mean(s["density"][fluid]),
            np.sum(s["kT"][fluid] * weight) / np.sum(weight), np.sum(ux * weight) / np.sum(weight), np.min(ux),
            np.sum(reversed_bins) * dz, np.sum(s["density"][fluid][reversed_bins] * ux[reversed_bins]) * dz)


def upstream_difference(sections):
    """How far the profile at the second section differs from the one at the first (both upstream of
    the contraction: x = -16.5 and -25.5 at full size): the two x, the RMS of ux(second) - ux(first)
    over the bins both sections fill, and its noise, the RMS of their combined standard errors (a
    difference at the noise is no difference)."""
    (x1, a), (x2, b) = sections[0], sections[1]
    both = (a["count"] >= FLUID_BIN) & (b["count"] >= FLUID_BIN)
    diff = b["ux"][both] - a["ux"][both]
    noise = np.hypot(a["uxErr"][both], b["uxErr"][both])
    return x1, x2, float(np.sqrt(np.mean(diff ** 2))), float(np.sqrt(np.mean(noise ** 2)))


def draw_sections(ax_ux, ax_rho, ax_kT, sections):
    for x, s in sections:
        fluid = s["count"] >= FLUID_BIN
        ax_ux.plot(s["z"], s["ux"], label=f"x = {x:g}")
        ax_rho.plot(s["z"], s["density"], label=f"x = {x:g}")
        ax_kT.plot(s["z"][fluid], s["kT"][fluid], label=f"x = {x:g}")
    for ax, name in ((ax_ux, "ux"), (ax_rho, "density"), (ax_kT, "kT")):
        label(ax, None, "z", name, legend=8)
    ax_ux.set_title("velocity across the channel at the sections")


KT_BUDGET, KT_BOUND = 0.001, 0.01  # the mean kT's standard error, then its distance from 1 (docstring)
FLUX_BUDGET = {False: 0.005, True: 0.04}  # a section's standard error over the mean flux (full, test)
FLUX_BOUND = {False: 0.005, True: 0.02}  # a section's flux from the mean, over the mean flux


def flow_checks(checks, rows, mean_kT, inside, kT_error, test_mode, inside_what):
    """The scene's checks (module docstring), each named by what a failure means."""
    checks.add(f"{inside} {inside_what} inside the solid at the end", inside == 0)
    checks.bounded(f"the mean kT differs from 1 by more than {KT_BOUND:.0%} (standard error below {KT_BUDGET:g})",
                   as_number(mean_kT) - 1.0, kT_error, KT_BUDGET, -KT_BOUND, KT_BOUND)
    fluxes = np.array([r[1] for r in rows])
    errors = np.array([r[2] for r in rows])
    mean_flux = np.mean(fluxes)
    budget, allowed = FLUX_BUDGET[test_mode], FLUX_BOUND[test_mode] * abs(mean_flux)
    checks.add(f"a section's flux is too noisy to decide: standard errors {errors} against the budget "
               f"{budget:.1%} of the mean flux {mean_flux:.4g}", np.all(errors <= budget * abs(mean_flux)))
    checks.add(f"the flux differs between sections: {fluxes} (allowed deviation {allowed:.4g})",
               np.all(np.abs(fluxes - mean_flux) <= allowed))
    checks.add(f"no flow along the body force: mean flux {mean_flux}", mean_flux > 0)


def write_flow_table(f, flow, extra_columns="", extra=None, inside_what="fluid particles"):
    rows, mean_kT, inside, kT_error, layer, upstream = flow
    f.write(f"# {SECTION_COLUMNS}{extra_columns}   (flux = integral of rho ux dz at the section; reversed: the "
            "fluid bins with ux below 0 by more than 2 standard errors, their width and flux)\n")
    for k, r in enumerate(rows):
        values = list(r) + (list(extra[k]) if extra else [])
        f.write(" ".join(f"{v:.6g}" for v in values) + "\n")
    f.write(f"# mean kT {mean_kT:.5f} +- {kT_error:.5f}; {inside_what} inside the solid at the end {inside}\n")
    f.write(f"# ux at x = {upstream[1]:g} against x = {upstream[0]:g}: RMS difference {upstream[2]:.5f}, "
            f"its noise {upstream[3]:.5f}\n")
    if layer:
        f.write(f"# bounce layer: {sum(a for a, _ in layer)} returned, {sum(b for _, b in layer)} still crossed the surface\n")


def report(table, checks):
    """The table as written, then the failed checks; exits 1 when one failed."""
    print_file(table)
    checks.print_failures()
    if checks.failures():
        sys.exit(1)


def flow_summary(case):
    """What both the scene and the variant read: the grid, its sections and (rows, mean kT, inside,
    the mean kT's standard error, the bounce layer's counts, the upstream difference)."""
    d = latest_dir(os.path.join(case, "postProcessing/profileBins/*"))
    grid = read_table(os.path.join(d, "flowField.dat"))
    sections = read_sections(d, "flowField")
    if len(sections) != 5:
        sys.exit(f"plotResults: expected 5 sections in {d}, found {len(sections)}")
    inside, _, layer = solver_log(case)
    # The mean kT of the fluid, weighted by the particle-samples of each bin (bins with a few
    # particles at the walls carry little weight).
    full = grid["count"] >= FLUID_BIN
    mean_kT = np.sum(grid["kT"][full] * grid["count"][full]) / np.sum(grid["count"][full])
    kT_error = weighted_error(grid["count"][full], grid["kTErr"][full])
    rows = [section_row(x, s) for x, s in sections]
    return d, grid, sections, (rows, mean_kT, inside, kT_error, layer, upstream_difference(sections))


def main(title, arguments):
    """The scene in the tutorial directory, or with -chains its variant (-lowG: the low-g one)."""
    test_mode = "-test" in arguments
    if "-chains" in arguments:
        main_chains(title, test_mode, "chainsLowG" if "-lowG" in arguments else "chains")
        return
    _, grid, sections, flow = flow_summary(".")
    fig, axes = plt.subplots(2, 2, figsize=(12, 8))
    draw_map(fig, axes[0, 0], grid, "ux", "ux on the x-z grid (flowField.vti)")
    draw_sections(axes[0, 1], axes[1, 0], axes[1, 1], sections)
    fig.suptitle(title + (" - test mode" if test_mode else ""))
    save(fig, "contraction.png")
    with open("results.dat", "w") as f:
        write_flow_table(f, flow)
    checks = Checks()
    flow_checks(checks, *flow[:4], test_mode, "fluid particles")
    report("results.dat", checks)


# ---- The -chains variant ----------------------------------------------------------------------------


def bead_row(x, beads, fluid):
    """The beads at one section: their mean density over the bins the fluid fills, and their flux."""
    dz = beads["z"][1] - beads["z"][0]
    filled = fluid["count"] >= FLUID_BIN
    # Bins no bead visited have no bead velocity (NaN) and no beads: they carry no bead flux.
    flux = np.sum(np.where(beads["count"] > 0, beads["density"] * beads["ux"], 0.0)) * dz
    return np.mean(beads["density"][filled]), flux


def chain_bin_row(bins, x):
    """The chains whose centres lie in the x bin holding the section x: samples, R_g^2, span along x and
    the rms end-to-end extension along x."""
    width = bins["x"][1] - bins["x"][0]
    k = int(np.clip(np.floor((x - (bins["x"][0] - 0.5 * width)) / width), 0, len(bins["x"]) - 1))
    return bins["samples"][k], bins["Rg2"][k], bins["span"][k], math.sqrt(bins["Rx2"][k])


def longest_bond(case):
    """The longest bond of any report in the solver's log, and r_max."""
    found = re.findall(r"bonds: longest ([-0-9.eE+naifNAIF]+) of rMax ([0-9.eE+]+)", read_text(os.path.join(case, "log.dpdFoamLike")))
    if not found:
        return float("nan"), float("nan")
    return max(float(a) for a, _ in found), float(found[-1][1])


def draw_chain_bins(ax, bins, sections):
    ax.plot(bins["x"], np.sqrt(bins["Rg2"]), "o-", label="R_g")
    ax.plot(bins["x"], bins["span"], "s-", label="span along x")
    ax.plot(bins["x"], np.sqrt(bins["Rx2"]), "^-", label="rms end-to-end along x")
    for x, _ in sections:
        ax.axvline(x, color="grey", lw=0.8, ls="--")
    label(ax, "chain size and extension along the flow", "x of the chain's centre (sections dashed)", "length", legend=8)


def draw_snapshot(ax, grid, snap):
    # The solid in grey (the bins no mobile particle visited), so that the chains stand out.
    xs, zs = np.unique(grid["x"]), np.unique(grid["z"])
    solid = (grid["count"] == 0).reshape(len(zs), len(xs))
    ax.imshow(solid, origin="lower", extent=[xs[0], xs[-1], zs[0], zs[-1]], aspect="equal", cmap="Greys", vmin=0, vmax=2.5)
    label(ax, f"chains at t = {snap['time']:g} (solid grey)", "x", "z")
    colours = plt.cm.tab20(np.mod(snap["chain"], 20))
    segments = np.stack([snap["starts"][:, [0, 2]], snap["ends"][:, [0, 2]]], axis=1)
    ax.add_collection(LineCollection(segments, colors=colours, linewidths=1.0))
    ax.plot(snap["beads"][:, 0], snap["beads"][:, 2], ".", color="black", ms=1.5)


def draw_bead_sections(ax, bead_sections):
    for x, s in bead_sections:
        ax.plot(s["z"], s["density"], label=f"x = {x:g}")
    label(ax, "bead density across the channel at the sections", "z", "bead density", legend=8)


def chain_checks(checks, inserted, snap, bond):
    """The variant's own checks: every bead and bond insertChains made is still there, and no bond
    reached r_max (the run stops if one does: this reads what the log says)."""
    chains, length = inserted
    checks.add(f"{len(snap['beads'])} beads in {snap['path']}, insertChains made {chains * length}",
               len(snap["beads"]) == chains * length)
    checks.add(f"{len(snap['starts'])} bonds in {snap['path']}, insertChains made {chains * (length - 1)}",
               len(snap["starts"]) == chains * (length - 1))
    checks.add(f"longest bond {bond[0]} against r_max {bond[1]} (log.dpdFoamLike)", bond[0] < bond[1])


def write_chain_table(path, flow, extra, inserted, snap, bond, means):
    """resultsChains.dat: the scene's table with the beads' and chains' columns, and the chains' summary."""
    with open(path, "w") as f:
        write_flow_table(f, flow, " beadDensity beadFlux chainSamples Rg2 spanX RxRms", extra,
                         "mobile particles (fluid and beads)")
        f.write("# bead columns: the beads alone at the section; chain columns: the chains whose centres lie in\n"
                "# the x bin of chainStatistics holding the section (R_g^2, span along x, rms end-to-end along x)\n")
        f.write(f"# chains {inserted[0]} of {inserted[1]} beads; latest snapshot {len(snap['beads'])} beads, "
                f"{len(snap['starts'])} bonds; longest bond in the log {bond[0]:.4g} of rMax {bond[1]:g}\n")
        f.write("# over the sampling: " + "; ".join(f"{k} {m:.5g} +- {e:.2g}" for k, (m, e) in means.items()) + "\n")


def main_chains(title, test_mode, case="chains"):
    d, grid, sections, flow = flow_summary(case)
    bead_grid = read_table(os.path.join(d, "beadField.dat"))
    bead_sections = read_sections(d, "beadField")
    if [x for x, _ in bead_sections] != [x for x, _ in sections]:
        sys.exit(f"plotResults: beadField's sections in {d} are not flowField's")
    bins = read_columns(latest(os.path.join(case, "postProcessing/chains/*/chainBins.dat")), ("x", "samples", "Rg2", "span", "Rx2"))
    snap, bond = chain_segments(latest(os.path.join(case, "[0-9]*/particles.h5"))), longest_bond(case)
    inserted = read_dict(os.path.join(case, "system/insertChainsDict"))
    inserted = (int(inserted["chains"]), int(inserted["length"]))
    extra = [bead_row(x, b, s) + chain_bin_row(bins, x) for (x, b), (_, s) in zip(bead_sections, sections)]

    fig, axes = plt.subplots(5, 2, figsize=(13, 18.5))
    draw_map(fig, axes[0, 0], grid, "ux", "ux of fluid and beads on the x-z grid (flowField.vti)")
    draw_map(fig, axes[0, 1], bead_grid, "density", "bead density on the x-z grid (beadField.vti)", cmap="magma")
    draw_sections(axes[1, 0], axes[1, 1], axes[2, 0], sections)
    draw_bead_sections(axes[2, 1], bead_sections)
    draw_chain_bins(axes[3, 0], bins, sections)
    draw_snapshot(axes[3, 1], grid, snap)
    draw_snapshot(axes[4, 0], grid, chain_segments(os.path.join(case, "0", "particles.h5")))
    axes[4, 1].axis("off")
    # chains/ gives resultsChains.dat and contractionChains.png, chainsLowG/ the same names with LowG.
    suffix = case[0].upper() + case[1:]
    g = re.search(r"bodyForce\s*\{[^}]*value\s+\(\s*(\S+)", read_text(os.path.join(case, "constant/dpdProperties"))).group(1)
    fig.suptitle(f"{title}, {inserted[0]} FENE chains of {inserted[1]} beads, g {g}" + (" - test mode" if test_mode else ""))
    save(fig, f"contraction{suffix}.png", dpi=100)

    means = header_means(latest(os.path.join(case, "postProcessing/chains/*/chainStatistics.dat")))
    write_chain_table(f"results{suffix}.dat", flow, extra, inserted, snap, bond, means)
    checks = Checks()
    flow_checks(checks, *flow[:4], test_mode, "mobile particles (fluid or beads)")
    chain_checks(checks, inserted, snap, bond)
    report(f"results{suffix}.dat", checks)
