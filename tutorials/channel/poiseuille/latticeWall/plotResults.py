#!/usr/bin/env python3
"""Poiseuille tutorial: picture and results table, and the checks of what the scene must show.

Reads the channel's profile and fit (postProcessing/...) and the viscosity measured without walls
(viscosity/postProcessing/...), draws velocity, density and temperature across the channel with the
analytic profile, writes results.dat, and exits non-zero when a check fails. Then compares the
lattice walls with the random walls of randomMask/ and randomGmsh/ (wallComparison.py): walls.png,
resultsWalls.dat and their checks.
"""
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.environ.get("DPD_PROJECT_DIR", os.path.join(os.path.dirname(__file__), "../../../..")), "etc"))
from dpdResults import kT_against_shear, latest, read_dict, read_table  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import wallComparison as wc  # noqa: E402


def compare_walls(g, nu_ref, cutoff, test):
    """Lattice walls against random walls from the mask and the gmsh file: walls.png, resultsWalls.dat
    and the checks (docs/walls.md 3.2: the random walls give the same Poiseuille profile)."""
    control = read_dict("system/controlDict")
    lattice_fit = read_dict(latest("postProcessing/fitSlipLength/*/fit.dat"))
    lo, hi = lattice_fit["wallPosition"]
    tau1 = (hi - lo) ** 2 / (math.pi ** 2 * nu_ref)
    sample_time = control["sampleInterval"] * control["deltaT"]
    runs = [wc.WallRun(label, case, "channelProfile", sample_time, tau1)
            for label, case in (("lattice", "."), ("mask", "randomMask"), ("gmsh", "randomGmsh"))]
    too_short = [r.too_short for r in runs if r.too_short]
    names = ("nu", "slipLower", "slipUpper")
    errors = ("fitSlipLength's (blocks shorter than tau1 = d^2/(pi^2 nu))" if too_short else
              f"jackknife over super-blocks of ~{wc.SUPER_BLOCK_TAUS:g} tau1 = {wc.SUPER_BLOCK_TAUS * tau1:.0f} "
              "(tau1 = d^2/(pi^2 nu))")
    checks, lines = [], [f"# Lattice and random walls, d = {hi - lo:g}, g = {g:g}; errors: {errors}"]
    for r in runs:
        v, e = r.values()
        bulk, near = r.near_wall_density(cutoff)
        lines.append(f"{r.label:8s} nu {v[0]:.4f} +- {e[0]:.4f}  slip {v[1]:+.4f} +- {e[1]:.4f}  {v[2]:+.4f} +- {e[2]:.4f}  "
                     f"(fitSlipLength's own errors {r.fit['nuError']:.4f}, {r.fit['slipLengthError'][0]:.4f}, "
                     f"{r.fit['slipLengthError'][1]:.4f}; {r.super_blocks} super-blocks of {r.super_block_time:g}, "
                     f"bin-error inefficiency s = {r.inefficiency:.2f})")
        lines.append(f"{r.label:8s} density bulk {bulk:.4f}; within one cutoff of the lower / upper wall: mean "
                     f"{near[0][0]:.3f} / {near[1][0]:.3f}, lowest bin {near[0][1]:.3f} / {near[1][1]:.3f} (x bulk)")
    if too_short:
        # The full scene's slowest mode (tau1 ~ 600) needs a production run of ~6000 for five
        # independent blocks: without them there are no honest error bars, so no verdict (the test
        # run is long enough and must decide).
        lines.append(f"# no verdict: {too_short[0]}; "
                     f"a production time >= {wc.MIN_SUPER_BLOCKS * wc.SUPER_BLOCK_TAUS * tau1:.0f} is needed")
        if test:
            checks.append(("random and lattice walls compared over independent blocks", False, too_short[0]))
        write_checks("resultsWalls.dat", lines, checks)
        plot_walls(runs, g, nu_ref, (lo, hi), cutoff)
        return checks
    n = np.count_nonzero(runs[0].fitted)
    dof_eff = wc.effective_dof(runs, n)
    low, high = wc.chi2_bounds(dof_eff)
    lines.append(f"# profile differences over the {n} bins of the fit range: effective independent bins {dof_eff:.1f} "
                 f"(the slow modes correlate neighbours), so chi2/dof is expected in [{low:.2f}, {high:.2f}] (3 sigma)")
    # The mask and the gmsh file build the same random wall, and random and lattice walls must give
    # the same profile (docs/walls.md 3.2). A Poiseuille profile is fixed by nu and the two slip lengths
    # (g and d being the same): those are checked pair by pair with jackknife errors over independent
    # super-blocks. The per-bin chi2 of the difference is reported, not checked: its bin errors
    # (profileBins' times sqrt(s), s pooled from five super-blocks) miss most of the slow mode's
    # coherent fluctuation, which the jackknife catches (test: gmsh - lattice nu differed by 1.3
    # jackknife errors while the per-bin chi2/dof was 6 over ~5 effective bins).
    for i, j in ((1, 2), (1, 0), (2, 0)):
        a, b = runs[i], runs[j]
        for k, name in enumerate(names):
            diff, sigma, allowed = wc.agreement(a, b, k)
            what = f"{name}: {a.label} and {b.label} walls agree within 3 combined standard errors (t-widened for their few blocks)"
            checks.append((what, abs(diff) < allowed, f"{diff:+.4f} +- {sigma:.4f} (allowed {allowed:.4f})"))
        chi2, bins = wc.profile_chi2(a, b)
        lines.append(f"compared  ux({a.label}) - ux({b.label}) per bin: chi2/dof {chi2:.3f} over {bins} bins "
                     f"(3-sigma range with per-bin errors [{low:.2f}, {high:.2f}])")
    # Each random wall on its own, held to what the lattice walls are held to (main checks).
    for r in runs[1:]:
        v, e = r.values()
        rel = v[0] / nu_ref - 1.0
        checks.append((f"nu({r.label} walls) within 3% of nu(no walls)", abs(rel) < 0.03, f"{100 * rel:+.2f} %"))
        for k, side in ((1, "lower"), (2, "upper")):
            checks.append((f"|slip length| < 0.1 at the {side} {r.label} wall", abs(v[k]) < 0.1, f"{v[k]:+.4f} +- {e[k]:.4f}"))
    write_checks("resultsWalls.dat", lines, checks)
    plot_walls(runs, g, nu_ref, (lo, hi), cutoff)
    return checks


def write_checks(path, lines, checks):
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
        for name, ok, value in checks:
            f.write(f"check  {'PASS' if ok else 'FAIL'}  {name}: {value}\n")
    print(open(path).read(), end="")


def plot_walls(runs, g, nu_ref, walls, cutoff):
    lo, hi = walls
    d, centre = hi - lo, 0.5 * (lo + hi)
    fig, ax = plt.subplots(2, 2, figsize=(12, 8.5))
    zz = np.linspace(lo, hi, 400)
    ax[0, 0].plot(zz, g * d * d / (8 * nu_ref) * (1 - (2 * (zz - centre) / d) ** 2), "k-", lw=1.2,
                  label=f"analytic, no slip, nu = {nu_ref:.4f} (no-wall run)")
    lattice = runs[0]
    for r, marker in zip(runs, "osd"):
        t = r.table
        v, e = r.values()
        ax[0, 0].errorbar(t["z"], t["ux"], yerr=r.ux_error, fmt=marker, ms=3, mfc="none",
                          label=f"{r.label} walls: nu {v[0]:.3f} +- {e[0]:.3f}, slip {v[1]:+.3f} / {v[2]:+.3f}")
        ax[1, 0].plot(t["z"], t["density"], marker + "-", ms=3, mfc="none", label=f"{r.label} walls")
        dist = np.concatenate([t["z"] - lo, hi - t["z"]])
        near = dist < 2.0 * cutoff
        ax[1, 1].plot(dist[near], np.concatenate([t["density"], t["density"]])[near], marker, ms=4, mfc="none",
                      label=f"{r.label} walls (both walls)")
        if r is not lattice:
            both = r.fitted & lattice.fitted
            ax[0, 1].errorbar(t["z"][both], (t["ux"] - lattice.table["ux"])[both],
                              yerr=np.hypot(r.ux_error, lattice.ux_error)[both], fmt=marker, ms=3, mfc="none",
                              label=f"{r.label} - lattice")
    ax[0, 1].axhline(0.0, color="k", lw=0.8)
    ax[0, 0].set_title("velocity"); ax[0, 0].set_xlabel("z"); ax[0, 0].set_ylabel("u_x"); ax[0, 0].legend(fontsize=7)
    ax[0, 1].set_title("random minus lattice walls (fit range; long-block errors)")
    ax[0, 1].set_xlabel("z"); ax[0, 1].set_ylabel("du_x"); ax[0, 1].legend(fontsize=8)
    ax[1, 0].set_title("density"); ax[1, 0].set_xlabel("z"); ax[1, 0].set_ylabel("number density")
    ax[1, 0].legend(fontsize=8)
    ax[1, 1].set_title("density next to the walls"); ax[1, 1].set_xlabel("distance from the wall")
    ax[1, 1].set_ylabel("number density"); ax[1, 1].legend(fontsize=8)
    for a in (ax[0, 0], ax[1, 0]):
        for zw in walls:
            a.axvline(zw, color="gray", ls=":")
    fig.suptitle(f"Poiseuille flow between lattice and random equilibrated walls, d = {d:g}, g = {g:g}")
    fig.tight_layout()
    fig.savefig("walls.png", dpi=110)
    print("Written walls.png and resultsWalls.dat")


def main():
    test = "-test" in sys.argv
    prof = read_table(latest("postProcessing/profileBins/*/channelProfile.dat"))
    fit = read_dict(latest("postProcessing/fitSlipLength/*/fit.dat"))
    ref = read_dict(latest("viscosity/postProcessing/fitSlipLength/*/fit.dat"))
    periodic = read_table(latest("viscosity/postProcessing/profileBins/*/viscosityProfile.dat"))
    props = read_dict("constant/dpdProperties")
    z, ux, uxErr = prof["z"], prof["ux"], prof["uxErr"]
    rho, kT, count = prof["density"], prof["kT"], prof["count"]

    # Geometry and forcing, as the case sets them.
    zLow, zHigh = -20.0, 20.0
    with open("constant/dpdProperties") as f:
        points = re.findall(r"point\s*\(\s*\S+\s+\S+\s+(\S+)\s*\)", f.read())
    if len(points) == 2:
        zLow, zHigh = sorted(float(p) for p in points)
    with open("constant/dpdProperties") as f:
        g = float(re.search(r"value\s*\(\s*(\S+)", f.read()).group(1))
    kTset = float(props.get("kT", 1.0))
    cutoff = float(props.get("cutoff", 1.0))
    d = zHigh - zLow
    centre = 0.5 * (zLow + zHigh)

    nu_wall, nu_wall_err = fit["nu"], fit["nuError"]
    nu_ref, nu_ref_err = ref["nu"], ref["nuError"]
    slip = fit["slipLength"]
    slip_err = fit.get("slipLengthError", [0.0, 0.0])
    interior = np.abs(z - centre) < 0.5 * d - 1.0
    rho_mean = np.average(rho[interior])
    flatness = np.max(np.abs(rho[interior] / rho_mean - 1.0))
    kT_mean = np.average(kT, weights=count)
    # kT against the local shear rate: channel bulk (beyond 3 cutoffs from the walls, which take heat
    # away) against the periodic box without walls at the same shear rate.
    shear_p, kT_p = kT_against_shear(periodic, g, nu_ref)
    shear_c = g * np.abs(z - centre) / nu_ref
    bulk = np.abs(z - centre) < 0.5 * d - 3.0 * cutoff
    kT_matched = np.interp(shear_c, shear_p, kT_p)
    heating_diff = np.average(kT[bulk] - kT_matched[bulk], weights=count[bulk])
    # In the full channel (d = 40) the bulk lies 3 to 20 cutoffs from the walls: +0.3 % measured, held
    # to 1 %. In the test channel (d = 10) it lies only 3 to 5 cutoffs from the walls, whose frozen
    # particles are a heat sink that reaches it: -0.6 +- 0.4 % over four seeds (-1.1, -0.8, -0.5,
    # -0.2 %), so the test holds it to 2 % (4 standard deviations beyond that mean), still far below
    # what a wrong thermostat or a missing heating would give (the heating itself is +4 %).
    kT_tolerance = 0.02 if test else 0.01
    kT_periodic_mean = np.average(periodic["kT"], weights=periodic["count"])

    # Checks (the criteria), written so that NaN fails. The 3 % bound on nu decides only if the
    # combined standard error is at most 1 % (a 3 % difference is then 3 of them): a run noisier than
    # that fails instead of passing more easily. Measured, errors from the fits block by block: 0.69 %
    # in the test mode (the channel's 0.6 % dominates), 0.34 % at full size (2026-11-24).
    rel_nu = nu_wall / nu_ref - 1.0
    nu_sigma = math.hypot(nu_wall_err, nu_ref_err) / nu_ref
    checks = [
        ("nu(wall fit) within 3% of nu(no walls), its standard error within 1%",
         abs(rel_nu) < 0.03 and nu_sigma <= 0.01, f"{100 * rel_nu:+.2f} % (1 sigma {100 * nu_sigma:.2f} %)"),
        (f"kT within {100 * kT_tolerance:g}% of the no-wall fluid's at the same shear rate (channel bulk)",
         abs(heating_diff / kTset) < kT_tolerance, f"mean difference {heating_diff:+.4f} (channel mean kT "
         f"{kT_mean:.4f}, no-wall box {kT_periodic_mean:.4f})"),
        ("density flat within 5% beyond one cutoff from the walls", flatness < 0.05, f"max deviation {100 * flatness:.2f} %"),
    ]
    # No slip. The test keeps the full scene's wall shear rate, so its slip length is measured to
    # about +-0.01 (standard error from the blocks) and the bound is decisive in both modes.
    checks += [
        ("|slip length| < 0.1 at the lower wall", abs(slip[0]) < 0.1, f"{slip[0]:+.4f} +- {slip_err[0]:.4f}"),
        ("|slip length| < 0.1 at the upper wall", abs(slip[1]) < 0.1, f"{slip[1]:+.4f} +- {slip_err[1]:.4f}"),
    ]

    checks += compare_walls(g, nu_ref, cutoff, test)

    with open("results.dat", "w") as f:
        f.write("# Poiseuille between frozen three-layer walls: results\n")
        f.write(f"nu_wallFit        {nu_wall:.5f} +- {nu_wall_err:.5f}\n")
        f.write(f"nu_noWalls        {nu_ref:.5f} +- {nu_ref_err:.5f}\n")
        f.write(f"nu_relativeDiff   {100 * rel_nu:+.3f} %\n")
        f.write(f"nu_kineticTheory  {fit.get('nuKineticTheory', float('nan')):.5f} (estimate)\n")
        f.write(f"slipLength        {slip[0]:+.4f} +- {slip_err[0]:.4f}  {slip[1]:+.4f} +- {slip_err[1]:.4f}\n")
        f.write(f"slipVelocity      {fit['slipVelocity'][0]:+.4f}  {fit['slipVelocity'][1]:+.4f}\n")
        f.write(f"kT_mean           {kT_mean:.5f} (set {kTset}; no-wall box at the same shear rates {kT_periodic_mean:.5f})\n")
        f.write(f"kT_bulkVsNoWall   {heating_diff:+.5f} (channel bulk minus no-wall box at the same shear rate)\n")
        f.write(f"kT_maxShear       {kT_p[-1]:.5f} (no-wall box at shear {shear_p[-1]:.3f}: viscous heating)\n")
        f.write(f"kT_centre         {np.average(kT[np.abs(z - centre) < 1.0]):.5f} (within one cutoff of the centre)\n")
        f.write(f"density_interior  {rho_mean:.4f}, flat within {100 * flatness:.2f} %\n")
        for name, ok, value in checks:
            f.write(f"check  {'PASS' if ok else 'FAIL'}  {name}: {value}\n")
    print(open("results.dat").read(), end="")

    fig, ax = plt.subplots(1, 3, figsize=(15, 4.6))
    zz = np.linspace(zLow, zHigh, 400)
    analytic = g * d * d / (8 * nu_ref) * (1 - (2 * (zz - centre) / d) ** 2)
    ax[0].errorbar(z, ux, yerr=uxErr, fmt="o", ms=3, label="DPD, frozen three-layer walls")
    ax[0].plot(zz, analytic, "k-", lw=1.2, label=f"analytic, no slip, nu = {nu_ref:.4f} (no-wall run)")
    ax[0].set_xlabel("z"); ax[0].set_ylabel("u_x"); ax[0].legend(fontsize=8); ax[0].set_title("velocity")
    ax[1].plot(z, rho, "o-", ms=3)
    ax[1].axhline(rho_mean, color="k", lw=0.8)
    ax[1].set_xlabel("z"); ax[1].set_ylabel("number density"); ax[1].set_title("density")
    ax[2].plot(z, kT, "o-", ms=3)
    ax[2].axhline(kTset, color="k", lw=0.8, label="set kT")
    ax[2].plot(centre + shear_p * nu_ref / g, kT_p, "k--", lw=0.8, label="no-wall box at the same shear rate")
    ax[2].plot(centre - shear_p * nu_ref / g, kT_p, "k--", lw=0.8)
    ax[2].legend(fontsize=8)
    ax[2].set_ylim(kTset * 0.9, kTset * 1.15)
    ax[2].set_xlabel("z"); ax[2].set_ylabel("kT about the local flow"); ax[2].set_title("temperature")
    for a in ax:
        for zw in (zLow, zHigh):
            a.axvline(zw, color="gray", ls=":")
    fig.suptitle(f"Poiseuille flow, d = {d:g}, g = {g:g}: nu = {nu_wall:.4f} (walls) vs {nu_ref:.4f} (no walls), "
                 f"slip {slip[0]:+.3f} / {slip[1]:+.3f}")
    fig.tight_layout()
    fig.savefig("poiseuille.png", dpi=110)
    print("Written poiseuille.png and results.dat")
    return 0 if all(ok for _, ok, _ in checks) else 1


if __name__ == "__main__":
    sys.exit(main())
