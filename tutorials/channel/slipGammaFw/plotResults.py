#!/usr/bin/env python3
"""Slip by gamma_fw tutorial: pictures, results table and the checks of what the scene must show.

Reads the tables runSweep wrote (sweep2D/sweep.dat, threeD/sweep3D/sweep.dat, variants/sweep.dat)
and each run's profile, draws the slip length and the fitted viscosity against gamma_fw (2-D and
3-D), the velocity profiles, and the density at the wall of the standard wall against the two
variants (slipGammaFw.png), writes results.dat with the published table (published.dat) beside the
measured one, and exits non-zero when a check fails. At full size a published point outside the
paper's tolerance passes only where the -planeNearRow variant's point lies within it (the measured
ingredient that accounts for the difference: where the bounce-back plane sits).

With -planeNearRow: the named variant whose wall rows sit 0.14 and 0.717 behind the bounce-back plane,
from sweepPlaneNearRow/, written to resultsPlaneNearRow.dat and slipGammaFwPlaneNearRow.png, with the
same monotonic checks and the published comparison (full size), the published scene's runs drawn
beside it when they exist.
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
from dpdResults import (compare_with_published, latest, published_checks, read_published, read_sweep,  # noqa: E402
                        read_table, walls_mean_slip)

TEST_MODE = "-test" in sys.argv[1:]
PLANE_NEAR_ROW = "-planeNearRow" in sys.argv[1:]
# The published comparison (issue 25), on the 2-D runs (the published scene): each point within
# max(0.3 r_c, 30 %) of the published slip length, decided only when the mean of the walls is known to
# a third of that point's tolerance. The paper states no errors: differences are given in units of
# this run's error alone. The test channel (d = 10) is not the published scene: there the table is
# information.
PUBLISHED_ABSOLUTE, PUBLISHED_RELATIVE = 0.3, 0.30


def profile(sweep_dir, case):
    return read_table(latest(f"{sweep_dir}/{case}/postProcessing/profileBins/*/channelProfile.dat"))


def walls(path):
    with open(path) as f:
        zs = sorted(float(p) for p in re.findall(r"point\s*\(\s*\S+\s+\S+\s+(\S+)\s*\)", f.read()))
    return zs[0], zs[-1]


def monotonic_checks(label, gammas, b, err):
    """Slip grows as gamma_fw falls. Over the whole range the rise must exceed three combined standard
    errors (decisive); no step down in gamma_fw may lower the slip length by more than three standard
    errors (a real reversal). Neighbouring steps may differ by less than their errors (in 3-D the slip
    at gamma_fw 1 and 2 is the same within 0.004): their sign alone is not a check."""
    order = np.argsort(gammas)
    out = []
    for lo, hi in zip(order[:-1], order[1:]):
        step, se = b[lo] - b[hi], math.hypot(err[lo], err[hi])
        ok = step > -3 * se
        out.append((f"{label}: slip length not decisively smaller at gamma_fw "
                    f"{gammas[lo]:g} than at {gammas[hi]:g}", ok, f"{step:+.4f} +- {se:.4f}"))
    lo, hi = order[0], order[-1]
    rise, se = b[lo] - b[hi], math.hypot(err[lo], err[hi])
    out.append((f"{label}: slip length larger at gamma_fw {gammas[lo]:g} than at {gammas[hi]:g} by more than "
                "three standard errors", rise > 3 * se, f"{rise:+.4f} +- {se:.4f}"))
    return out


def wall_gap(prof, z_low, z_high, cutoff=1.0):
    """The depletion at the walls: the fluid missing within one cutoff of a wall, as a width,
    integral of max(0, 1 - rho / rho_centre) dz over the bins there, mean of the two walls."""
    z, rho = prof["z"], prof["density"]
    centre = np.abs(z - 0.5 * (z_low + z_high)) < 0.25 * (z_high - z_low)
    missing = np.clip(1.0 - rho / np.mean(rho[centre]), 0.0, None) * (z[1] - z[0])
    near = np.minimum(z - z_low, z_high - z) < cutoff
    return 0.5 * np.sum(missing[near])


def main():
    s2 = read_sweep("sweep2D/sweep.dat")
    s3 = read_sweep("threeD/sweep3D/sweep.dat")
    sv = read_sweep("variants/sweep.dat")
    g2 = s2["pairCoeffs/fluid-wall/gamma"]
    g3 = s3["pairCoeffs/fluid-wall/gamma"]
    b2, e2 = walls_mean_slip(s2)
    b3, e3 = walls_mean_slip(s3)
    z_low, z_high = walls("constant/dpdProperties")

    # The same checks in both modes and both dimensions. The errors come from the fit block by block
    # (fitSlipLength: the bins move together); the test's 3-D runs sample 2000 time units, since six
    # seeds of 250 (2026-11-21) scattered by 0.07 in the slip length against a rise of 0.10 from
    # gamma_fw 13.5 to 1: at 2000 the rise is ~4 of its standard errors.
    checks = monotonic_checks("2-D", g2, b2, e2) + monotonic_checks("3-D", g3, b3, e3)
    # The variants leave a gap at the wall: more fluid missing next to it than at the standard wall
    # (same gamma_fw, 4.5). A bin's density is known to ~1 %, so the depletion to ~0.005: a
    # difference of 0.1 (a tenth of a cutoff of fluid) is decisive.
    k45 = int(np.argmin(np.abs(g2 - 4.5)))
    gap_std = wall_gap(profile("sweep2D", s2["case"][k45]), z_low, z_high)
    gaps = [wall_gap(profile("variants", c), z_low, z_high) for c in sv["case"]]
    names = ["a_wf = 3 a", "wall 3 x denser"]
    for name, gap in zip(names, gaps):
        checks.append((f"{name}: a wider gap at the wall than the standard wall's (depletion + 0.1)",
                       gap > gap_std + 0.1, f"{gap:.3f} against {gap_std:.3f}"))

    published = read_published("published.dat")
    comparison = published_comparison(published, g2, b2, e2)
    if not TEST_MODE:
        checks += published_checks(comparison, "2-D slip length", "gamma_fw {:g}", accounted_by_plane_depth(published))

    with open("results.dat", "w") as f:
        f.write(f"# Slip by gamma_fw, Poiseuille between frozen walls, d = {z_high - z_low:g}: slip length\n"
                "# (lower upper, and mean of the walls) and nu of the parabola fit\n")
        for label, s, g, b, e in (("2-D", s2, g2, b2, e2), ("3-D", s3, g3, b3, e3)):
            for k in range(len(g)):
                f.write(f"{label} gamma_fw {g[k]:5g}  b {s['slipLength_0'][k]:+.4f} {s['slipLength_1'][k]:+.4f}"
                        f"  mean {b[k]:+.4f} +- {e[k]:.4f}  nu {s['nu'][k]:.4f} +- {s['nuError'][k]:.4f}\n")
        for name, k in zip(names, range(len(sv["case"]))):
            f.write(f"2-D {name} (gamma_fw 4.5): b {sv['slipLength_0'][k]:+.4f} {sv['slipLength_1'][k]:+.4f}"
                    f"  nu {sv['nu'][k]:.4f} +- {sv['nuError'][k]:.4f}  depletion at the wall {gaps[k]:.3f}\n")
        f.write(f"2-D standard wall (gamma_fw 4.5): depletion at the wall {gap_std:.3f}\n")
        write_comparison(f, published, comparison)
        for name, ok, value in checks:
            f.write(f"check  {'PASS' if ok else 'FAIL'}  {name}: {value}\n")
    print(open("results.dat").read(), end="")

    fig, ax = plt.subplots(2, 2, figsize=(12, 8.5))
    ax = ax.ravel()
    ax[0].errorbar(g2, b2, yerr=e2, fmt="o-", label="2-D (published)")
    ax[0].errorbar(g3, b3, yerr=e3, fmt="s--", label="3-D")
    draw_published_slip(ax[0], published)
    ax[1].errorbar(g2, s2["nu"], yerr=s2["nuError"], fmt="o-", label="2-D")
    ax[1].errorbar(g3, s3["nu"], yerr=s3["nuError"], fmt="s--", label="3-D")
    ax[1].set_xscale("log"); ax[1].set_xlabel("gamma_fw"); ax[1].set_ylabel("nu (parabola fit)")
    ax[1].set_title("fitted viscosity")
    draw_profiles(ax[2], "sweep2D", s2["case"], g2)
    ax[2].set_xlabel("z"); ax[2].set_ylabel("u_x"); ax[2].set_title("2-D velocity profiles")
    p = profile("sweep2D", s2["case"][k45])
    ax[3].plot(p["z"], p["density"], "k-", label="standard wall (a_wf = a)")
    for name, c in zip(names, sv["case"]):
        p = profile("variants", c)
        ax[3].plot(p["z"], p["density"], "-", label=name)
    ax[3].set_xlabel("z"); ax[3].set_ylabel("density"); ax[3].set_title("2-D density, gamma_fw 4.5: the gap at the wall")
    for a in ax:
        a.legend(fontsize=8)
    for a in ax[2:]:
        for w in (z_low, z_high):
            a.axvline(w, color="gray", ls=":")
    fig.suptitle("Slip by the wall's dissipative coupling gamma_fw (Poiseuille, rho 3, a 25)")
    fig.tight_layout()
    fig.savefig("slipGammaFw.png", dpi=100)
    print("Written slipGammaFw.png and results.dat")
    return 0 if all(ok for _, ok, _ in checks) else 1


def draw_published_slip(ax, published):
    table = published["tables"]["Table 1"]
    ax.plot(table["gamma_fw"], table["slipLength"], "rD", label="published (2-D, Table 1)")
    ax.set_xscale("log"); ax.set_xlabel("gamma_fw"); ax.set_ylabel("slip length (mean of the walls)")
    ax.set_title("slip length against gamma_fw")


def draw_profiles(ax, sweep_dir, cases, gammas):
    colours = plt.cm.viridis(np.linspace(0, 0.9, len(gammas)))
    for k, c in enumerate(cases):
        p = profile(sweep_dir, c)
        ax.errorbar(p["z"], p["ux"], yerr=p["uxErr"], fmt="o", ms=2, color=colours[k], label=f"gamma_fw {gammas[k]:g}")


def published_comparison(published, gammas, b, err):
    return compare_with_published(published["tables"]["Table 1"], "gamma_fw", gammas, b, err,
                                  absolute=PUBLISHED_ABSOLUTE, relative=PUBLISHED_RELATIVE)


def accounted_by_plane_depth(published):
    """The published scene's differences from the paper are held to the ingredient that accounts for
    them (tutorials/channel/slipSensitivity): the variant with the rows nearer the bounce-back plane,
    when it ran."""
    ingredient = "where the bounce-back plane sits (the variant with the rows 0.14 and 0.717 behind it)"
    how = "./Allrun runs it after the published sweeps; ./Allrun -planeNearRow alone"
    if not os.path.exists("sweepPlaneNearRow/sweep.dat"):
        return ingredient, [], how
    sv = read_sweep("sweepPlaneNearRow/sweep.dat")
    return ingredient, published_comparison(published, sv["pairCoeffs/fluid-wall/gamma"], *walls_mean_slip(sv)), how


def write_comparison(f, published, comparison):
    f.write(f"# published: {published['source']}, Table 1 (no errors stated: differences in units of this run's "
            f"error){' (information: the test channel, d = 10, is not the published scene)' if TEST_MODE else ''}\n")
    f.write("# gamma_fw  2-D slipLength (mean of walls) +- err   published   difference  (standard errors)\n")
    for g, b, e, p, _, _ in comparison:
        f.write(f"published {g:5g}  {b:+.4f} +- {e:.4f}   {p:.4f}   {b - p:+.4f}  ({(b - p) / e:+.1f})\n")


def main_plane_near_row():
    """The named variant: its sweep against the paper, with the published wall's runs beside it."""
    sv = read_sweep("sweepPlaneNearRow/sweep.dat")
    gv = sv["pairCoeffs/fluid-wall/gamma"]
    bv, ev = walls_mean_slip(sv)
    z_low, z_high = walls("constant/dpdProperties")
    published = read_published("published.dat")
    comparison = published_comparison(published, gv, bv, ev)
    checks = monotonic_checks("2-D, plane near the row", gv, bv, ev)
    if not TEST_MODE:
        checks += published_checks(comparison, "2-D slip length (plane near the row)", "gamma_fw {:g}")

    with open("resultsPlaneNearRow.dat", "w") as f:
        f.write(f"# Slip by gamma_fw, 2-D Poiseuille, d = {z_high - z_low:g}, the wall's rows 0.14 and 0.717 behind "
                "the bounce-back plane\n# (named variant; published: 0.289 and 0.866): slip length (lower upper, "
                "mean of the walls) and nu of the parabola fit\n")
        for k in range(len(gv)):
            f.write(f"2-D planeNearRow gamma_fw {gv[k]:5g}  b {sv['slipLength_0'][k]:+.4f} {sv['slipLength_1'][k]:+.4f}"
                    f"  mean {bv[k]:+.4f} +- {ev[k]:.4f}  nu {sv['nu'][k]:.4f} +- {sv['nuError'][k]:.4f}"
                    f"  slip velocity {0.5 * (sv['slipVelocity_0'][k] + sv['slipVelocity_1'][k]):.4f}\n")
        write_comparison(f, published, comparison)
        for name, ok, value in checks:
            f.write(f"check  {'PASS' if ok else 'FAIL'}  {name}: {value}\n")
    print(open("resultsPlaneNearRow.dat").read(), end="")

    fig, ax = plt.subplots(1, 2, figsize=(12, 4.5))
    ax[0].errorbar(gv, bv, yerr=ev, fmt="o-", label="rows 0.14 / 0.717 behind the plane (variant)")
    if os.path.exists("sweep2D/sweep.dat"):
        s2 = read_sweep("sweep2D/sweep.dat")
        b2, e2 = walls_mean_slip(s2)
        ax[0].errorbar(s2["pairCoeffs/fluid-wall/gamma"], b2, yerr=e2, fmt="s--", label="rows 0.289 / 0.866 (published wall)")
    draw_published_slip(ax[0], published)
    draw_profiles(ax[1], "sweepPlaneNearRow", sv["case"], gv)
    for w in (z_low, z_high):
        ax[1].axvline(w, color="gray", ls=":")
    ax[1].set_xlabel("z"); ax[1].set_ylabel("u_x"); ax[1].set_title("velocity profiles (variant)")
    for a in ax:
        a.legend(fontsize=8)
    fig.suptitle("Slip by gamma_fw with the wall's rows nearer the bounce-back plane (named variant)")
    fig.tight_layout()
    fig.savefig("slipGammaFwPlaneNearRow.png", dpi=100)
    print("Written slipGammaFwPlaneNearRow.png and resultsPlaneNearRow.dat")
    return 0 if all(ok for _, ok, _ in checks) else 1


if __name__ == "__main__":
    sys.exit(main_plane_near_row() if PLANE_NEAR_ROW else main())
