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
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.environ.get("DPD_PROJECT_DIR", os.path.join(os.path.dirname(__file__), "../../..")), "etc"))
from dpdResults import (compare_with_published, latest, published_checks, read_dict, read_published, read_sweep,  # noqa: E402
                        read_table, walls_mean_slip)

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


def no_wall_viscosity():
    """nu and its standard error from viscosity/'s fit."""
    fit = read_dict(latest("viscosity/postProcessing/fitSlipLength/*/fit.dat"))
    return float(fit["nu"]), float(fit["nuError"])


def entry(text, pattern, default=None):
    m = re.search(pattern, text, re.S)
    return float(m.group(1)) if m else default


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
    edges = np.arange(low, high - 1e-9, width)
    for a in edges:
        sel = (z > a) & (z < a + width)
        if sel.any():
            means.append(np.mean(values[sel]))
            errs.append(math.sqrt(np.sum(errors[sel] ** 2)) / sel.sum())
    return np.array(means), np.array(errs)


def accounted_by_wall_density(table, cutoff):
    """The published scene's differences from the paper are held to the ingredient that accounts for
    them (tutorials/channel/slipSensitivity): the calibrated-wall variant's comparison, when it ran."""
    how = "./Allrun runs it after the published sweep; ./Allrun -calibratedWall alone"
    path = "sweepCalibratedWall/sweep.dat"
    if not os.path.exists(path):
        return ("the wall's density (the calibrated-wall variant, 0.9 of it)", [], how)
    variant = read_sweep(path)
    b, e = walls_mean_slip(variant)
    rows = compare_with_published(table, "a_ww", variant["pairCoeffs/wall-wall/a"], b, e,
                                  absolute=PUBLISHED_ABSOLUTE * cutoff, relative=PUBLISHED_RELATIVE)
    return ("the wall's density (the calibrated-wall variant, 0.9 of it)", rows, how)


def main():
    sweep = read_sweep(f"{SWEEP}/sweep.dat")
    nu_nw, nu_nw_err = no_wall_viscosity()
    with open(f"{CASE}/constant/dpdProperties") as f:
        props = f.read()
    a_ff = entry(props, r"fluid-fluid\s*\{[^}]*\ba\s+([^;\s]+)")
    gamma_ff = entry(props, r"fluid-fluid\s*\{[^}]*gamma\s+([^;\s]+)")
    gamma_fw = entry(props, r"fluid-wall\s*\{[^}]*gamma\s+([^;\s]+)")
    kT_set = entry(props, r"^\s*kT\s+([^;\s]+)", 1.0)
    cutoff = entry(props, r"^\s*cutoff\s+([^;\s]+)", 1.0)
    zw = sorted(float(p) for p in re.findall(r"point\s*\(\s*\S+\s+\S+\s+(\S+)\s*\)", props))
    z_low, z_high = zw[0], zw[-1]
    d = z_high - z_low

    a_ww = sweep["pairCoeffs/wall-wall/a"]
    a_wf = np.sqrt(a_ww * a_ff)
    b = np.vstack([sweep["slipLength_0"], sweep["slipLength_1"]]).T
    b_err = np.vstack([sweep["slipLengthError_0"], sweep["slipLengthError_1"]]).T
    us = np.vstack([sweep["slipVelocity_0"], sweep["slipVelocity_1"]]).T
    # The two walls' mean: a fluctuation of the channel's mean velocity (the slowest mode, time
    # d^2 / (pi^2 nu)) moves the two slip lengths in opposite directions and cancels in the mean.
    b_mean, b_mean_err = walls_mean_slip(sweep)

    profiles = [read_table(latest(f"{SWEEP}/{c}/postProcessing/profileBins/*/channelProfile.dat"))
                for c in sweep["case"]]

    checks = []
    if NO_SLIP_WALL:
        # The calibrated wall: no slip at the first (smallest a_ww) setting, on the mean of the walls (a
        # fluctuation of the channel's mean velocity moves the two walls' slip in opposite directions).
        checks += [
            (f"no-slip variant: the slip length's standard error within {NO_SLIP_BUDGET:g} (a_ww = {a_ww[0]:g})",
             b_mean_err[0] <= NO_SLIP_BUDGET, f"{b_mean_err[0]:.4f}"),
            (f"no-slip variant: |slip length| < {NO_SLIP_BOUND:g} r_c at a_ww = {a_ww[0]:g} (mean of the walls)",
             abs(b_mean[0]) < NO_SLIP_BOUND * cutoff,
             f"{b_mean[0]:+.4f} +- {b_mean_err[0]:.4f} (walls {b[0, 0]:+.3f}, {b[0, 1]:+.3f})"),
        ]
    published = read_published("published.dat")
    table = published["tables"]["Table 1"]
    comparison = compare_with_published(table, "a_ww", a_ww, b_mean, b_mean_err, absolute=PUBLISHED_ABSOLUTE * cutoff,
                                         relative=PUBLISHED_RELATIVE)
    if not NO_SLIP_WALL and not TEST_MODE:
        checks += published_checks(comparison, "slip length", "a_ww = {:g}",
                                   None if VARIANT else accounted_by_wall_density(table, cutoff))
    # Slip grows with a_wf: each step up in a_ww raises the mean slip length.
    for k in range(1, len(a_ww)):
        step = b_mean[k] - b_mean[k - 1]
        checks.append((f"slip length grows from a_wf = {a_wf[k - 1]:.2f} to {a_wf[k]:.2f}", step > 0,
                       f"{step:+.4f} +- {math.hypot(b_mean_err[k], b_mean_err[k - 1]):.4f}"))

    rows = []
    for k, prof in enumerate(profiles):
        z = prof["z"]
        shear = sweep["shearRate"][k]
        nu = sweep["nu"][k]
        eta = sweep["eta"][k]
        rho = sweep["densityKineticTheory"][k]
        # Stress flat: means over slabs two cutoffs thick across the whole channel (wall layers
        # included) against the channel's mean. A slab's standard error is ~1.5 % of the stress in
        # the test (one-cutoff slabs: 2.1 %, too close to the bound), so 5 % is > 3 sigma.
        slabs, slab_err = slab_means(z, prof["sigmaxz"], prof["sigmaxzErr"], z_low, z_high, 2 * cutoff)
        sigma_mean = np.mean(slabs)
        flat = np.max(np.abs(slabs / sigma_mean - 1.0))
        rel_nu = nu / nu_nw - 1.0
        rel_nu_se = math.hypot(sweep["nuError"][k] / nu_nw, nu * nu_nw_err / nu_nw ** 2)
        heating = viscous_heating(eta, shear, rho, gamma_ff, cutoff)
        kT_mean = np.average(prof["kT"], weights=prof["count"])
        kT_expected = kT_set + heating
        rows.append((a_ww[k], a_wf[k], b[k], b_err[k], us[k], shear, sweep["shearRateError"][k], eta,
                     sweep["etaError"][k], nu, sweep["nuError"][k], flat, kT_mean, kT_expected))
        if k == 0:
            checks += [
                (f"shear stress flat within 5 % across the channel (a_ww = {a_ww[k]:g})", flat < 0.05,
                 f"max slab deviation {100 * flat:.2f} % (slab error ~{100 * np.mean(slab_err) / sigma_mean:.1f} %)"),
                (f"nu = stress / (rho shear rate) and nu without walls: combined standard error within "
                 f"{100 * NU_BUDGET:g} % (a_ww = {a_ww[k]:g})", rel_nu_se <= NU_BUDGET, f"{100 * rel_nu_se:.2f} %"),
                (f"nu = stress / (rho shear rate) within {100 * NU_BOUND:g} % of nu without walls (a_ww = {a_ww[k]:g})",
                 abs(rel_nu) <= NU_BOUND,
                 f"{nu:.4f} +- {sweep['nuError'][k]:.4f} against {nu_nw:.4f} +- {nu_nw_err:.4f} ({100 * rel_nu:+.2f} %)"),
                (f"mean kT within 1 % of the set kT plus the viscous heating (a_ww = {a_ww[k]:g})",
                 abs(kT_mean / kT_expected - 1.0) < 0.01,
                 f"{kT_mean:.4f} against {kT_expected:.4f} (heating {heating:+.4f})"),
            ]

    results = f"results{SUFFIX}.dat"
    with open(results, "w") as f:
        f.write(f"# Couette flow between sliding three-layer walls, d = {d:g}, a_ff = {a_ff:g}, gamma {gamma_ff:g}, "
                f"gamma_fw {gamma_fw:g} ({VARIANTS[VARIANT] if VARIANT else 'the published parameters'}): one row per a_ww\n")
        f.write("# a_ww  a_wf   slipLength(lower upper) +- err      slipVelocity(lower upper)  shearRate +- err"
                "      eta +- err        nu +- err         stressFlat%  kT  kT_expected\n")
        for (aw, af, bb, be, uu, sh, she, et, ete, nu, nue, fl, kt, kte) in rows:
            f.write(f"{aw:5g} {af:6.2f}  {bb[0]:+.4f} {bb[1]:+.4f} +- {be[0]:.4f} {be[1]:.4f}  "
                    f"{uu[0]:+.4f} {uu[1]:+.4f}  {sh:.5f} +- {she:.5f}  {et:.4f} +- {ete:.4f}  "
                    f"{nu:.4f} +- {nue:.4f}  {100 * fl:5.2f}  {kt:.4f} {kte:.4f}\n")
        f.write(f"# nu without walls {nu_nw:.4f} +- {nu_nw_err:.4f} (viscosity/: reverse Poiseuille, the same fluid)\n")
        f.write(f"# published: {published['source']}, Table 1 (no errors stated: differences in units of this run's error)\n")
        if TEST_MODE or VARIANT:
            f.write("# (information: this run is not the published scene"
                    f"{' (the test channel: d = 10, shear rate 0.6)' if TEST_MODE else ''}"
                    f"{' (' + VARIANTS[VARIANT] + ')' if VARIANT else ''})\n")
        f.write("# a_ww  slipLength(mean of walls) +- err   published   difference  (standard errors)  "
                "shearRate  published\n")
        for aw, bm, be, bp, _, _ in comparison:
            k = int(np.flatnonzero(np.isclose(a_ww, aw))[0])
            sp = table["shearRate"][np.flatnonzero(np.isclose(table["a_ww"], aw))[0]]
            f.write(f"published {aw:5g}  {bm:+.4f} +- {be:.4f}   {bp:.4f}   {bm - bp:+.4f}  ({(bm - bp) / be:+.1f})  "
                    f"{sweep['shearRate'][k]:.4f}  {sp:.4f}\n")
        for name, ok, value in checks:
            f.write(f"check  {'PASS' if ok else 'FAIL'}  {name}: {value}\n")
    print(open(results).read(), end="")

    colours = plt.cm.viridis(np.linspace(0, 0.9, len(profiles)))
    fig, ax = plt.subplots(2, 3, figsize=(16, 8.5))
    ax = ax.ravel()
    for k, prof in enumerate(profiles):
        label = f"a_ww {a_ww[k]:g} (a_wf {a_wf[k]:.2f})"
        c = colours[k]
        ax[0].errorbar(prof["z"], prof["ux"], yerr=prof["uxErr"], fmt="o", ms=2, color=c, label=label)
        ax[1].plot(prof["z"], prof["density"], "-", color=c, label=label)
        ax[2].plot(prof["z"], prof["kT"], "-", color=c, label=label)
        ax[3].errorbar(prof["z"], prof["sigmaxz"], yerr=prof["sigmaxzErr"], fmt="o", ms=2, color=c, label=label)
        ax[2].axhline(rows[k][13], color=c, ls="--", lw=0.8)
    u_wall = 0.5 * (sweep["wallVelocity_1"][0] - sweep["wallVelocity_0"][0]) if "wallVelocity_1" in sweep else None
    if u_wall is not None:
        ax[0].plot([z_low, z_high], [-u_wall, u_wall], "k-", lw=0.8, label="no slip")
    ax[0].set_title("velocity u_x"); ax[1].set_title("density"); ax[2].set_title("kT about the local flow (dashed: set + viscous heating)")
    ax[3].set_title("shear stress sigma_xz")
    ax[4].errorbar(a_wf, b[:, 0], yerr=b_err[:, 0], fmt="v-", label="lower wall")
    ax[4].errorbar(a_wf, b[:, 1], yerr=b_err[:, 1], fmt="^-", label="upper wall")
    ax[4].errorbar(a_wf, b_mean, yerr=b_mean_err, fmt="ko-", label="mean")
    ax[4].plot(table["a_wf"], table["slipLength"], "rs", label="published (Table 1)")
    _, fit = published["fits"]["slipLength"]
    a_line = np.linspace(min(table["a_wf"]), max(table["a_wf"]), 100)
    ax[4].plot(a_line, fit(a_line), "r--", lw=0.8, label="published fit")
    if NO_SLIP_WALL:
        ax[4].axhspan(-NO_SLIP_BOUND, NO_SLIP_BOUND, color="gray", alpha=0.2, label="|b| < 0.1")
    ax[4].set_xlabel("a_wf"); ax[4].set_ylabel("slip length"); ax[4].set_title("slip length against a_wf")
    ax[5].errorbar(a_wf, np.array([r[9] for r in rows]), yerr=np.array([r[10] for r in rows]), fmt="o-",
                   label="stress / (rho shear rate)")
    ax[5].axhline(nu_nw, color="k", lw=0.8, label="no walls (reverse Poiseuille)")
    ax[5].set_xlabel("a_wf"); ax[5].set_ylabel("nu"); ax[5].set_title("viscosity")
    for a in ax[:4]:
        a.set_xlabel("z")
        for w in (z_low, z_high):
            a.axvline(w, color="gray", ls=":")
    for a in ax:
        a.legend(fontsize=7)
    fig.suptitle(f"Couette flow, d = {d:g}, gamma_fw {gamma_fw:g}: slip against the wall-fluid repulsion (a_wf = sqrt(a_ww a_ff))"
                 f"{' - ' + VARIANTS[VARIANT] if VARIANT else ''}")
    fig.tight_layout()
    fig.savefig(f"couetteSlip{SUFFIX}.png", dpi=100)

    fig, ax = plt.subplots(figsize=(7, 4.5))
    for k, prof in enumerate(profiles):
        z = prof["z"]
        near = np.minimum(z - z_low, z_high - z)
        order = np.argsort(near)
        lower = z < 0.5 * (z_low + z_high)
        for sel, style in ((lower, "-"), (~lower, "--")):
            o = order[sel[order]]
            ax.plot(near[o], prof["density"][o], style, color=colours[k],
                    label=f"a_wf {a_wf[k]:.2f}" if style == "-" else None)
    ax.set_xlim(0, 3 * cutoff)
    ax.set_xlabel("distance from the wall (solid: lower, dashed: upper)")
    ax.set_ylabel("number density")
    ax.set_title("density near the wall for each a_wf")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(f"couetteSlip{SUFFIX}_nearWall.png", dpi=100)
    print(f"Written couetteSlip{SUFFIX}.png, couetteSlip{SUFFIX}_nearWall.png and {results}")
    return 0 if all(ok for _, ok, _ in checks) else 1


if __name__ == "__main__":
    sys.exit(main())
