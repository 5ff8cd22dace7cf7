#!/usr/bin/env python3
"""Couette slip tutorial: pictures, results table and the checks of what the scene must show.

Reads sweep/sweep.dat (one row per a_ww, written by runSweep) and each run's profile
(sweep/<run>/postProcessing/profileBins/<time>/channelProfile.dat), draws velocity, density,
temperature and shear stress across the channel for every a_ww (couetteSlip.png), the density near
the walls for every a_wf (couetteSlip_nearWall.png), writes results.dat with the published table
(published.dat) beside the measured one, and exits non-zero when a check fails.

With -noSlipWall: the calibrated variant (gamma_fw 36) from sweepNoSlipWall/, written to
resultsNoSlipWall.dat and couetteSlipNoSlipWall.png; its check is the no-slip wall at a_ww = 5.
With -calibratedWall: the variant whose wall is 0.9 as dense as published, from sweepCalibratedWall/,
written to resultsCalibratedWall.dat and couetteSlipCalibratedWall.png; at full size it is held to
the published table like the published set.
"""
import math
import os
import sys

import numpy as np

from dpdfoam.channel import walls_mean_slip
from dpdfoam.checks import Checks, write_results
from dpdfoam.io import dictionary_number, latest_fit, latest_profile, read_sweep, wall_planes
from dpdfoam.plots import label, mark_walls, plt, save
from dpdfoam.published import compare_with_published, published_checks, read_published, table_value

TEST_MODE = "-test" in sys.argv[1:]
VARIANTS = {"-noSlipWall": "the calibrated no-slip wall, gamma_fw 36",
            "-calibratedWall": "calibrated wall: 0.9 of the published wall density, spacing 0.5556 along the flow"}
VARIANT = next((a for a in sys.argv[1:] if a in VARIANTS), None)
NO_SLIP_WALL = VARIANT == "-noSlipWall"
SUFFIX = VARIANT[1].upper() + VARIANT[2:] if VARIANT else ""
CASE = f"sweep{SUFFIX}/couetteSlip" if VARIANT else "."
SWEEP = f"sweep{SUFFIX}"
# The channel's nu = stress / (rho shear rate) is held to the viscosity of the same fluid without walls,
# measured by this tutorial's own run (viscosity/: periodic reverse Poiseuille at the channel's shear
# rate). The check decides only when the combined standard error of the two is within its budget:
# full size, nu without walls +-1.4 % and the channel's +-0.3 % (measured), budget 2 %; test mode,
# the channel's 10 x 3 x 10 run adds +-1.5-2 %, budget 3 %. Then |difference| within 5 %, fixed.
NU_BUDGET = 0.03 if TEST_MODE else 0.02
NU_BOUND = 0.05
# The published comparison (issue 25): each point within max(0.3 r_c, 30 %) of the published slip
# length. It decides only when the mean of the walls is known to a third of that point's tolerance
# (the bound is then at least 3 standard errors wide); the paper states no errors, so the difference
# is given in units of this run's error alone.
PUBLISHED_ABSOLUTE, PUBLISHED_RELATIVE = 0.3, 0.30
# The calibrated variant's no-slip check, |b| < 0.1 r_c at a_ww = 5, decides when the mean of the walls
# is known to 0.03 (full size: 0.024 measured over 1000 sampled time units; test: ~0.01-0.02).
NO_SLIP_BOUND, NO_SLIP_BUDGET = 0.1, 0.03


def viscous_heating(eta, shear, rho, gamma, cutoff):
    """Rise of kT from DPD's own viscous heating in Couette flow (uniform shear).

    Shear heats the fluid at eta shear^2 per volume; the pair thermostat takes heat out at
    gamma rho^2 C (kT - kT0) per volume, C = int w_D d^3r = 4 pi rc^3 / 30 (the standard weight; see
    tutorials/channel/poiseuille/plotResults.py). In balance kT - kT0 = eta shear^2 / (rho^2 gamma C).
    """
    return eta * shear * shear / (rho * rho * gamma * 4.0 * math.pi * cutoff ** 3 / 30.0)


def slab_means(z, values, errors, low, high, width):
    """Means (and standard errors) of a profile over slabs of the given width from low to high."""
    means, errs = [], []
    for a in np.arange(low, high - 1e-9, width):
        sel = (z > a) & (z < a + width)
        if sel.any():
            means.append(np.mean(values[sel]))
            errs.append(math.sqrt(np.sum(errors[sel] ** 2)) / sel.sum())
    return np.array(means), np.array(errs)


def comparison_of(table, keys, b, err, cutoff):
    return compare_with_published(table, "a_ww", keys, b, err, absolute=PUBLISHED_ABSOLUTE * cutoff,
                                  relative=PUBLISHED_RELATIVE)


def accounted_by_wall_density(table, cutoff):
    """The published scene's differences from the paper are held to the ingredient that accounts for
    them (tutorials/channel/slipSensitivity): the calibrated-wall variant's comparison, when it ran."""
    how = "./Allrun runs it after the published sweep; ./Allrun -calibratedWall alone"
    ingredient = "the wall's density (the calibrated-wall variant, 0.9 of it)"
    if not os.path.exists("sweepCalibratedWall/sweep.dat"):
        return (ingredient, [], how)
    variant = read_sweep("sweepCalibratedWall/sweep.dat")
    return (ingredient, comparison_of(table, variant["pairCoeffs/wall-wall/a"], *walls_mean_slip(variant), cutoff), how)


def stress_flatness(prof, walls, cutoff):
    """The largest deviation of the shear stress from its mean over slabs two cutoffs thick across the
    whole channel (wall layers included), and a slab's relative error. A slab's standard error is ~1.5 %
    of the stress in the test (one-cutoff slabs: 2.1 %, too close to the bound), so 5 % is > 3 sigma."""
    slabs, slab_err = slab_means(prof["z"], prof["sigmaxz"], prof["sigmaxzErr"], *walls, 2 * cutoff)
    return np.max(np.abs(slabs / np.mean(slabs) - 1.0)), np.mean(slab_err) / np.mean(slabs)


def first_channel_checks(checks, a_ww, flat, slab_error, nu, nu_err, nu_nw, nu_nw_err, kT_mean, kT_expected, heating):
    """The stress, viscosity and kT checks, at the first a_ww."""
    rel_nu, rel_nu_se = nu / nu_nw - 1.0, math.hypot(nu_err / nu_nw, nu * nu_nw_err / nu_nw ** 2)
    checks.add(f"shear stress flat within 5 % across the channel (a_ww = {a_ww:g})", flat < 0.05,
               f"max slab deviation {100 * flat:.2f} % (slab error ~{100 * slab_error:.1f} %)")
    checks.add(f"nu = stress / (rho shear rate) and nu without walls: combined standard error within "
               f"{100 * NU_BUDGET:g} % (a_ww = {a_ww:g})", rel_nu_se <= NU_BUDGET, f"{100 * rel_nu_se:.2f} %")
    checks.add(f"nu = stress / (rho shear rate) within {100 * NU_BOUND:g} % of nu without walls (a_ww = {a_ww:g})",
               abs(rel_nu) <= NU_BOUND, f"{nu:.4f} +- {nu_err:.4f} against {nu_nw:.4f} +- {nu_nw_err:.4f} ({100 * rel_nu:+.2f} %)")
    checks.add(f"mean kT within 1 % of the set kT plus the viscous heating (a_ww = {a_ww:g})",
               abs(kT_mean / kT_expected - 1.0) < 0.01, f"{kT_mean:.4f} against {kT_expected:.4f} (heating {heating:+.4f})")


def main():
    sweep = read_sweep(f"{SWEEP}/sweep.dat")
    nu_fit = latest_fit("viscosity")
    nu_nw, nu_nw_err = float(nu_fit["nu"]), float(nu_fit["nuError"])
    props = f"{CASE}/constant/dpdProperties"
    fluid = {k: dictionary_number(props, entry, default) for k, entry, default in (
        ("a", "pairCoeffs/fluid-fluid/a", None), ("gamma", "pairCoeffs/fluid-fluid/gamma", None),
        ("gamma_fw", "pairCoeffs/fluid-wall/gamma", None), ("kT", "kT", 1.0), ("cutoff", "cutoff", 1.0))}
    walls = wall_planes(props)
    d, cutoff = walls[1] - walls[0], fluid["cutoff"]

    a_ww = sweep["pairCoeffs/wall-wall/a"]
    a_wf = np.sqrt(a_ww * fluid["a"])
    b = np.vstack([sweep["slipLength_0"], sweep["slipLength_1"]]).T
    b_err = np.vstack([sweep["slipLengthError_0"], sweep["slipLengthError_1"]]).T
    us = np.vstack([sweep["slipVelocity_0"], sweep["slipVelocity_1"]]).T
    # The two walls' mean: a fluctuation of the channel's mean velocity (the slowest mode, time
    # d^2 / (pi^2 nu)) moves the two slip lengths in opposite directions and cancels in the mean.
    b_mean, b_mean_err = walls_mean_slip(sweep)
    profiles = [latest_profile(f"{SWEEP}/{c}") for c in sweep["case"]]

    checks = Checks()
    if NO_SLIP_WALL:
        # The calibrated wall: no slip at the first (smallest a_ww) setting, on the mean of the walls.
        checks.add(f"no-slip variant: the slip length's standard error within {NO_SLIP_BUDGET:g} (a_ww = {a_ww[0]:g})",
                   b_mean_err[0] <= NO_SLIP_BUDGET, f"{b_mean_err[0]:.4f}")
        checks.add(f"no-slip variant: |slip length| < {NO_SLIP_BOUND:g} r_c at a_ww = {a_ww[0]:g} (mean of the walls)",
                   abs(b_mean[0]) < NO_SLIP_BOUND * cutoff,
                   f"{b_mean[0]:+.4f} +- {b_mean_err[0]:.4f} (walls {b[0, 0]:+.3f}, {b[0, 1]:+.3f})")
    published = read_published("published.dat")
    table = published["tables"]["Table 1"]
    comparison = comparison_of(table, a_ww, b_mean, b_mean_err, cutoff)
    if not NO_SLIP_WALL and not TEST_MODE:
        checks.extend(published_checks(comparison, "slip length", "a_ww = {:g}",
                                       None if VARIANT else accounted_by_wall_density(table, cutoff)))
    # Slip grows with a_wf: each step up in a_ww raises the mean slip length.
    for k in range(1, len(a_ww)):
        step = b_mean[k] - b_mean[k - 1]
        checks.add(f"slip length grows from a_wf = {a_wf[k - 1]:.2f} to {a_wf[k]:.2f}", step > 0,
                   f"{step:+.4f} +- {math.hypot(b_mean_err[k], b_mean_err[k - 1]):.4f}")

    rows = []
    for k, prof in enumerate(profiles):
        shear, eta, nu = sweep["shearRate"][k], sweep["eta"][k], sweep["nu"][k]
        heating = viscous_heating(eta, shear, sweep["densityKineticTheory"][k], fluid["gamma"], cutoff)
        kT_expected = fluid["kT"] + heating
        flat, slab_error = stress_flatness(prof, walls, cutoff)
        kT_mean = np.average(prof["kT"], weights=prof["count"])
        if k == 0:
            first_channel_checks(checks, a_ww[k], flat, slab_error, nu, sweep["nuError"][k], nu_nw, nu_nw_err, kT_mean,
                                 kT_expected, heating)
        rows.append((a_ww[k], a_wf[k], b[k], b_err[k], us[k], shear, sweep["shearRateError"][k], eta,
                     sweep["etaError"][k], nu, sweep["nuError"][k], flat, kT_mean, kT_expected))

    lines = [f"# Couette flow between sliding three-layer walls, d = {d:g}, a_ff = {fluid['a']:g}, gamma {fluid['gamma']:g}, "
             f"gamma_fw {fluid['gamma_fw']:g} ({VARIANTS[VARIANT] if VARIANT else 'the published parameters'}): one row per a_ww",
             "# a_ww  a_wf   slipLength(lower upper) +- err      slipVelocity(lower upper)  shearRate +- err"
             "      eta +- err        nu +- err         stressFlat%  kT  kT_expected"]
    for (aw, af, bb, be, uu, sh, she, et, ete, nu, nue, fl, kt, kte) in rows:
        lines.append(f"{aw:5g} {af:6.2f}  {bb[0]:+.4f} {bb[1]:+.4f} +- {be[0]:.4f} {be[1]:.4f}  "
                     f"{uu[0]:+.4f} {uu[1]:+.4f}  {sh:.5f} +- {she:.5f}  {et:.4f} +- {ete:.4f}  "
                     f"{nu:.4f} +- {nue:.4f}  {100 * fl:5.2f}  {kt:.4f} {kte:.4f}")
    lines.append(f"# nu without walls {nu_nw:.4f} +- {nu_nw_err:.4f} (viscosity/: reverse Poiseuille, the same fluid)")
    lines.append(f"# published: {published['source']}, Table 1 (no errors stated: differences in units of this run's error)")
    if TEST_MODE or VARIANT:
        lines.append("# (information: this run is not the published scene"
                     f"{' (the test channel: d = 10, shear rate 0.6)' if TEST_MODE else ''}"
                     f"{' (' + VARIANTS[VARIANT] + ')' if VARIANT else ''})")
    lines.append("# a_ww  slipLength(mean of walls) +- err   published   difference  (standard errors)  shearRate  published")
    for aw, bm, be, bp, _, _ in comparison:
        k = int(np.flatnonzero(np.isclose(a_ww, aw))[0])
        lines.append(f"published {aw:5g}  {bm:+.4f} +- {be:.4f}   {bp:.4f}   {bm - bp:+.4f}  ({(bm - bp) / be:+.1f})  "
                     f"{sweep['shearRate'][k]:.4f}  {table_value(table, 'a_ww', aw, 'shearRate'):.4f}")
    write_results(f"results{SUFFIX}.dat", lines, checks)
    plot(sweep, profiles, rows, a_ww, a_wf, b, b_err, b_mean, b_mean_err, published, nu_nw, walls, fluid)
    return checks.status()


def plot(sweep, profiles, rows, a_ww, a_wf, b, b_err, b_mean, b_mean_err, published, nu_nw, walls, fluid):
    table = published["tables"]["Table 1"]
    colours = plt.cm.viridis(np.linspace(0, 0.9, len(profiles)))
    fig, ax = plt.subplots(2, 3, figsize=(16, 8.5))
    ax = ax.ravel()
    for k, prof in enumerate(profiles):
        name, c = f"a_ww {a_ww[k]:g} (a_wf {a_wf[k]:.2f})", colours[k]
        ax[0].errorbar(prof["z"], prof["ux"], yerr=prof["uxErr"], fmt="o", ms=2, color=c, label=name)
        ax[1].plot(prof["z"], prof["density"], "-", color=c, label=name)
        ax[2].plot(prof["z"], prof["kT"], "-", color=c, label=name)
        ax[3].errorbar(prof["z"], prof["sigmaxz"], yerr=prof["sigmaxzErr"], fmt="o", ms=2, color=c, label=name)
        ax[2].axhline(rows[k][13], color=c, ls="--", lw=0.8)
    if "wallVelocity_1" in sweep:
        u_wall = 0.5 * (sweep["wallVelocity_1"][0] - sweep["wallVelocity_0"][0])
        ax[0].plot(walls, [-u_wall, u_wall], "k-", lw=0.8, label="no slip")
    ax[0].set_title("velocity u_x"); ax[1].set_title("density"); ax[2].set_title("kT about the local flow (dashed: set + viscous heating)")
    ax[3].set_title("shear stress sigma_xz")
    ax[4].errorbar(a_wf, b[:, 0], yerr=b_err[:, 0], fmt="v-", label="lower wall")
    ax[4].errorbar(a_wf, b[:, 1], yerr=b_err[:, 1], fmt="^-", label="upper wall")
    ax[4].errorbar(a_wf, b_mean, yerr=b_mean_err, fmt="ko-", label="mean")
    ax[4].plot(table["a_wf"], table["slipLength"], "rs", label="published (Table 1)")
    a_line = np.linspace(min(table["a_wf"]), max(table["a_wf"]), 100)
    ax[4].plot(a_line, published["fits"]["slipLength"][1](a_line), "r--", lw=0.8, label="published fit")
    if NO_SLIP_WALL:
        ax[4].axhspan(-NO_SLIP_BOUND, NO_SLIP_BOUND, color="gray", alpha=0.2, label="|b| < 0.1")
    label(ax[4], "slip length against a_wf", "a_wf", "slip length")
    ax[5].errorbar(a_wf, [r[9] for r in rows], yerr=[r[10] for r in rows], fmt="o-", label="stress / (rho shear rate)")
    ax[5].axhline(nu_nw, color="k", lw=0.8, label="no walls (reverse Poiseuille)")
    label(ax[5], "viscosity", "a_wf", "nu")
    for a in ax[:4]:
        a.set_xlabel("z")
    mark_walls(ax[:4], walls)
    for a in ax:
        a.legend(fontsize=7)
    fig.suptitle(f"Couette flow, d = {walls[1] - walls[0]:g}, gamma_fw {fluid['gamma_fw']:g}: slip against the wall-fluid "
                 f"repulsion (a_wf = sqrt(a_ww a_ff)){' - ' + VARIANTS[VARIANT] if VARIANT else ''}")
    save(fig, f"couetteSlip{SUFFIX}.png", dpi=100)

    fig, ax = plt.subplots(figsize=(7, 4.5))
    for k, prof in enumerate(profiles):
        z = prof["z"]
        near = np.minimum(z - walls[0], walls[1] - z)
        order = np.argsort(near)
        lower = z < 0.5 * (walls[0] + walls[1])
        for sel, style in ((lower, "-"), (~lower, "--")):
            o = order[sel[order]]
            ax.plot(near[o], prof["density"][o], style, color=colours[k], label=f"a_wf {a_wf[k]:.2f}" if style == "-" else None)
    ax.set_xlim(0, 3 * fluid["cutoff"])
    label(ax, "density near the wall for each a_wf", "distance from the wall (solid: lower, dashed: upper)",
          "number density", legend=8)
    save(fig, f"couetteSlip{SUFFIX}_nearWall.png", dpi=100)
    print(f"Written couetteSlip{SUFFIX}.png, couetteSlip{SUFFIX}_nearWall.png and results{SUFFIX}.dat")


if __name__ == "__main__":
    sys.exit(main())
