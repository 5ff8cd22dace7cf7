#!/usr/bin/env python3
"""Scene 1 as published (Liu and Chang 2010): FCC and random equilibrated walls side by side.

Reads every seed's run (runs/<case>_seed<n>: fit, profile, log), the viscosity without walls
(viscosity/) and the FCC channel's simpleFoam twin; writes results.dat (the paper's set-up beside the
built one, and per wall: nu, slip length, density and kT next to the wall, the bounce layer's turns
and failures per unit time and area, each a mean over the seeds with its standard error) and
poiseuille.png; exits non-zero when a check fails.

Errors: the paper averages over one window of 400 time units, about 1.2 times the channel's slowest
decay time d^2 / (pi^2 nu), too short to give its own error bar; the seeds are independent runs of
that protocol (each random-wall seed equilibrates a wall of its own), so their spread is the error of
one run, and the standard error of their mean is spread / sqrt(n). Each check holds a mean to a fixed
bound after requiring its standard error within a budget (a third of the bound for the slip length
and kT, 1 % for nu; FLAT_BUDGETS and TWIN_BUDGETS for the density's flatness and the twin).
"""
import sys

import numpy as np

from dpdfoam.channel import no_wall_reference
from dpdfoam.checks import Checks, as_number, relative_difference, write_results
from dpdfoam.io import body_force, dictionary_value, frozen_wall_counts, latest_compare, log_count
from dpdfoam.poiseuille import QUANTITIES, plot, seed_runs
from dpdfoam.published import read_published
from dpdfoam.snapshots import same_particles

WALLS = (("FCC", "fcc", "blockFrozenWallDict"), ("random", "randomMask", "randomEquilWallDict"))
# Issue 45, the density's flatness beyond one cutoff of the walls (the largest deviation of a bin from
# the mean, every seed): first a bin's largest standard error there, relative to the mean, within its
# budget, then the deviation within 5 %, fixed. Measured: full size (2026-11-27, 200 bins, 400 time units)
# 0.24-0.27 %, budget 0.5 %; the test (d = 10, 66 bins) 0.57-0.68 %, budget 1 %. The deviations are the
# walls' layering (FCC 3.9-4.2 % at 1.1 from the wall at full size, 3.7-4.5 % in the test; random 1.4-2.5 %).
FLAT_BOUND = 0.05
FLAT_BUDGETS = {False: 0.005, True: 0.01}  # full size, test mode
# The FCC channel against its simpleFoam twin: the relative L2 of each seed, first its noise part (the DPD
# bins' errors, compareFVM's noiseL2) within its budget, then below 3 %, fixed. Measured: full size
# 0.0008-0.0009 (L2 0.013-0.015), budget 0.003; the test 0.0052-0.0061 (L2 0.010-0.012), budget 0.01.
TWIN_BOUND = 0.03
TWIN_BUDGETS = {False: 0.003, True: 0.01}


def counts_table(wall, case, builder, published):
    """Built fluid and wall particles (seed 1) beside the paper's and the wall at the paper's depth."""
    log = f"runs/{case}_seed1/log.{builder[:-4]}"
    fluid, fluid_paper, wall_paper = log_count(log, "Fluid particles"), published[(case, "fluid")], published[(case, "wall")]
    built, full = frozen_wall_counts(log)
    return (f"{wall:14s} fluid {fluid} (published {fluid_paper}, {100 * (fluid / fluid_paper - 1):+.2f} %)"
            f"  wall at the published depth {full} (published {wall_paper}), built within one cutoff {built}")


def nu_check(checks, wall, nu, nu_err, nu_ref, nu_ref_err):
    """nu (mean over the seeds, its standard error) against nu without walls: the combined standard
    error within 1 %, then within 3 %."""
    rel, sigma = relative_difference(nu, nu_err, nu_ref, nu_ref_err)
    checks.add(f"{wall}: nu within 3 % of nu without walls, its standard error within 1 %",
               abs(rel) < 0.03 and sigma <= 0.01, f"{100 * rel:+.2f} % (1 sigma {100 * sigma:.2f} %)")


def bulk_kT_check(checks, wall, dkT, dkT_se, kT_set, kT_tolerance):
    """The bulk kT minus the no-wall fluid's at the same shear rate: its standard error within a third of
    the tolerance, then within it."""
    dkT, dkT_se, kT_set = as_number(dkT), as_number(dkT_se), as_number(kT_set)
    checks.add(f"{wall}: bulk kT within {100 * kT_tolerance:g} % of the no-wall fluid's at the same shear "
               f"rate, its standard error within a third of that", abs(dkT) < kT_tolerance * kT_set
               and dkT_se <= kT_tolerance * kT_set / 3, f"{dkT:+.4f} +- {dkT_se:.4f}")


def flat_check(checks, wall, flat, flat_err, budget):
    """The density's largest deviation beyond one cutoff (every seed): a bin's largest error there within
    the budget, then the deviation within FLAT_BOUND."""
    flat, flat_err = as_number(flat), as_number(flat_err)
    checks.bounded(f"{wall}: density flat within {100 * FLAT_BOUND:g} % beyond one cutoff of the walls (every seed; "
                   f"a bin's standard error below {100 * budget:g} %)", flat, flat_err, budget, None, FLAT_BOUND,
                   f"largest deviation {100 * flat:.2f} % (a bin's error at most {100 * flat_err:.2f} %)")


def no_slip_check(checks, wall, b, b_se):
    """No slip (docs/walls.md 3.2): |b| < 0.1 moves the centre line by 4 b / d < 1.3 % at d = 30; the
    standard error first within a third of that."""
    b, b_se = as_number(b), as_number(b_se)
    checks.add(f"{wall}: no slip, |b| < 0.1, its standard error within a third of that",
               abs(b) < 0.1 and b_se <= 0.1 / 3, f"{b:+.4f} +- {b_se:.4f}")


def twin_check(checks, worst, noise, budget):
    """The FCC channel's largest relative L2 against its simpleFoam twin over the seeds: the largest noise
    part within the budget, then the L2 below TWIN_BOUND."""
    worst, noise = as_number(worst), as_number(noise)
    checks.bounded(f"FCC: DPD within {100 * TWIN_BOUND:g} % (relative L2) of simpleFoam (nu without walls, no slip), "
                   f"every seed (its noise part below {budget:g})", worst, noise, budget, None, TWIN_BOUND,
                   f"largest L2 {worst:.4f} (noise L2 {noise:.4f})")


def wall_checks(checks, wall, runs, s, nu_ref, nu_ref_err, kT_set, kT_tolerance, test=False):
    nu_check(checks, wall, *s["nu"], nu_ref, nu_ref_err)
    bulk_kT_check(checks, wall, *s["kTBulkVsNoWall"], kT_set, kT_tolerance)
    flat_check(checks, wall, np.max([r.flatness for r in runs]), np.max([r.flatness_error for r in runs]),
               FLAT_BUDGETS[test])
    no_slip_check(checks, wall, *s["slip"])


def main():
    test = "-test" in sys.argv
    g = body_force("fcc")
    kT_set = float(dictionary_value("fcc/constant/dpdProperties", "kT"))
    ref = no_wall_reference()
    nu_ref, nu_ref_err, kT_of_shear = ref["nu"], ref["nuError"], ref["kT_of_shear"]
    published = read_published("published.dat")["counts"]
    lines = [f"# Scene 1 (Liu and Chang 2010) as published: g {g:g}; nu without walls {nu_ref:.5f} +- {nu_ref_err:.5f}",
             "# Built against published (seed 1)" + (": the test's narrow channel, not the published size" if test else ":")]
    results = {wall: seed_runs(case, builder, kT_of_shear, g, nu_ref) for wall, case, builder in WALLS}
    lines += ["#   " + counts_table(wall, case, builder, published) for wall, case, builder in WALLS]
    checks = Checks()
    same = same_particles("runs/randomGmsh/0/particles.h5", "runs/randomMask_seed1/0/particles.h5")
    checks.add("the gmsh file builds the mask's random wall (seed 1), particle for particle", same,
               "identical" if same else "different")

    lines.append("# Per wall, the mean over the seeds +- its standard error: nu; slip length b (the two walls' "
                 "mean); density within one cutoff of the walls and in their first bins, over the bulk's; kT within one "
                 "cutoff; kT of the bulk (beyond 3 cutoffs) minus the no-wall box's at the same shear rate; particles "
                 "the bounce layer turned round and particles found behind the wall, per unit time and wall area")
    lines.append("# wall           seeds " + " ".join(f"{k:>20s}" for k in QUANTITIES))
    for wall, (runs, s) in results.items():
        lines.append(f"{wall.replace(' ', '_'):16s} {len(runs):5d} " +
                     " ".join(f"{s[k][0]:11.5f} +- {s[k][1]:.5f}" for k in QUANTITIES))
        lines += [f"#   {r.path:22s} " + " ".join(f"{r.q[k]:20.5f}" for k in QUANTITIES) for r in runs]
        wall_checks(checks, wall, runs, s, nu_ref, nu_ref_err, kT_set, 0.02 if test else 0.01, test)

    fvm = [latest_compare(r.path) for r in results["FCC"][0]]
    twin_check(checks, np.max([c["L2"] for c in fvm]), max(c["noiseL2"] for c in fvm), TWIN_BUDGETS[test])
    write_results("results.dat", lines, checks)
    plot(results, g, nu_ref, kT_set, kT_of_shear)
    return checks.status()


if __name__ == "__main__":
    sys.exit(main())
