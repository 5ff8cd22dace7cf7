"""Lattice and random walls compared with honest error bars (plotResults.py: walls.png, resultsWalls.dat
and their checks; docs/walls.md 3.2: the random walls give the same Poiseuille profile). The errors are
long-block ones (dpdfoam.sweep.LongBlockRun): the slowest mode, tau1 = d^2 / (pi^2 nu) (37 time units for
d = 10, 600 for d = 40), outlasts the sampling blocks (25), joined into super-blocks of about 2 tau1 (the
test's: 75 for 2 tau1 = 75.2).
"""
import math

import numpy as np

from dpdfoam.checks import Checks, as_number, relative_difference, write_results
from dpdfoam.io import latest_fit
from dpdfoam.plots import draw_no_slip_poiseuille, label, mark_walls, plt, save
from dpdfoam.stats import chi2_bounds
from dpdfoam.sweep import LongBlockRun, agreement, effective_dof, long_block_lines, near_both_walls, profile_chi2

RUNS = (("lattice", "."), ("mask", "randomMask"), ("gmsh", "randomGmsh"))
NAMES = ("nu", "slipLower", "slipUpper")
# No slip: |b| below this at every wall (docs/walls.md 3.2: |b| < 0.1 moves the centre line by 4 b / d
# < 1 % at d = 40).
SLIP_BOUND = 0.1
# Each random wall against nu without walls (relative, with the reference's error) and its slip; full
# size fitSlipLength's errors (the lattice channel's nu 0.34 %; slips 0.0023-0.0092, README), test the
# jackknife's over 5 super-blocks (nu 0.43-1.13 %, slips 0.004-0.028: README and 2026-11-28).
RANDOM_NU_BUDGET = (0.01, 0.015)
RANDOM_SLIP_BUDGET = (SLIP_BOUND / 3, 0.04)
# Budgets of the pair comparisons' standard errors (issue 45): the difference's jackknife error (two
# runs' in quadrature) first below its budget, then the difference within 3 budgets of zero, a bound
# fixed by the budget (not widened with the run's own error). Each jackknife error has 4 degrees of
# freedom (5 super-blocks), so the budget stands ~1.4 times above the largest measured.
PAIR_BOUND = 3.0
PAIR_BUDGETS = {
    # test (d = 10): nu differences 0.0027-0.0037 (README), 0.0016-0.0021 (2026-11-28); full size: no
    # verdict (too few super-blocks), the same budgets once it runs long enough
    "nu": 0.005,
    # test: slip differences 0.012-0.033 (README), 0.008-0.022 (2026-11-28)
    "slipLower": 0.045,
    "slipUpper": 0.045,
}


def no_slip_check(checks, where, slip, error, budget):
    """|slip length| < SLIP_BOUND at a wall, its standard error first below its budget (issue 45)."""
    return checks.bounded(f"|slip length| < {SLIP_BOUND:g} at the {where} (standard error below {budget:.3g})", slip,
                          error, budget, -SLIP_BOUND, SLIP_BOUND)


def nu_check(checks, where, nu, error, nu_ref, nu_ref_error, budget, bound=0.03):
    """nu within `bound` (relative) of nu without walls, the combined relative standard error first
    below its budget (issue 45)."""
    rel, sigma = relative_difference(nu, error, nu_ref, nu_ref_error)
    return checks.bounded(f"nu({where}) within {100 * bound:g} % of nu(no walls) (standard error below {100 * budget:g} %)",
                          rel, sigma, budget, -bound, bound, f"{100 * rel:+.2f} % +- {100 * sigma:.2f} %")


def agreement_check(checks, name, label_a, label_b, diff, sigma, budget, dof=float("nan")):
    """Two walls agree on quantity `name`: the difference's standard error below `budget`, then the
    difference within PAIR_BOUND budgets of zero (issue 45)."""
    diff = as_number(diff)
    return checks.bounded(f"{name}: {label_a} and {label_b} walls agree within {PAIR_BOUND:g} x {budget:g} (standard error "
                          f"below {budget:g})", diff, sigma, budget, -PAIR_BOUND * budget, PAIR_BOUND * budget,
                          f"{diff:+.4f} +- {as_number(sigma):.4f} ({as_number(dof):.1f} degrees of freedom)")


def compare_walls(g, nu_ref, nu_ref_err, cutoff, test):
    """Lattice walls against random walls from the mask and the gmsh file: walls.png, resultsWalls.dat
    and the checks."""
    lo, hi = latest_fit()["wallPosition"]
    tau1 = (hi - lo) ** 2 / (math.pi ** 2 * nu_ref)
    runs = [LongBlockRun(name, case, "channelProfile") for name, case in RUNS]
    too_short = [r.too_short for r in runs if r.too_short]
    errors = ("fitSlipLength's (blocks shorter than tau1 = d^2/(pi^2 nu))" if too_short else
              f"fitSlipLength's jackknife over super-blocks of {runs[0].super_block_time:g} (tau1 = d^2/(pi^2 nu) = {tau1:.0f})")
    checks, lines = Checks(), [f"# Lattice and random walls, d = {hi - lo:g}, g = {g:g}; errors: {errors}"]
    for r in runs:
        lines += long_block_lines(r, cutoff)
    wall_pairs(checks, lines, runs, tau1)
    # Each random wall on its own, held to what the lattice walls are held to (main checks): with the
    # jackknife's errors, or fitSlipLength's where the blocks are too few for it.
    mode = 1 if test else 0
    for r in runs[1:]:
        v, e = r.values()
        nu_check(checks, f"{r.label} walls", v[0], e[0], nu_ref, nu_ref_err, RANDOM_NU_BUDGET[mode])
        for k, side in ((1, "lower"), (2, "upper")):
            no_slip_check(checks, f"{side} {r.label} wall", v[k], e[k], RANDOM_SLIP_BUDGET[mode])
    write_results("resultsWalls.dat", lines, checks)
    plot_walls(runs, g, nu_ref, (lo, hi), cutoff)
    return checks


def wall_pairs(checks, lines, runs, tau1):
    """The walls compared pair by pair, or, where a run holds too few super-blocks (fitSlipLengthDict's
    superBlocks), a failed check: the full scene's slowest mode (tau1 ~ 600) needs a production run of
    ~6000 for five independent blocks; without them there are no honest error bars and no verdict, and a
    missing verdict fails (issue 45; the test run decides)."""
    too_short = [r.too_short for r in runs if r.too_short]
    if too_short:
        lines.append(f"# no verdict: {too_short[0]} (tau1 = {tau1:.0f})")
        checks.add("random and lattice walls compared over independent blocks (no verdict without the super-blocks "
                   "of fitSlipLengthDict)", False, f"{too_short[0]} (tau1 = {tau1:.0f})")
    else:
        compare_pairs(runs, checks, lines)


def compare_pairs(runs, checks, lines):
    """nu and the slip lengths pair by pair, and the profiles' per-bin chi2 (reported)."""
    n = np.count_nonzero(runs[0].fitted)
    dof = effective_dof(runs, n)
    low, high = chi2_bounds(dof)
    lines.append(f"# profile differences over the {n} bins of the fit range: effective independent bins "
                 f"{dof:.1f} (the slow modes correlate neighbours), so chi2/dof is expected in "
                 f"[{low:.2f}, {high:.2f}] (3 sigma)")
    # The mask and the gmsh file build the same random wall, and random and lattice walls must give
    # the same profile (docs/walls.md 3.2). A Poiseuille profile is fixed by nu and the two slip lengths
    # (g and d being the same): those are checked pair by pair with jackknife errors over independent
    # super-blocks. The per-bin chi2 of the difference is reported, not checked: its bin errors
    # (profileBins' times sqrt(s), s pooled from five super-blocks) miss most of the slow mode's
    # coherent fluctuation, which the jackknife catches (test: gmsh - lattice nu differed by 1.3
    # jackknife errors while the per-bin chi2/dof was 6 over ~5 effective bins).
    for a, b in ((runs[1], runs[2]), (runs[1], runs[0]), (runs[2], runs[0])):
        for k, name in enumerate(NAMES):
            diff, sigma, dof = agreement(a, b, k)
            agreement_check(checks, name, a.label, b.label, diff, sigma, PAIR_BUDGETS[name], dof)
        chi2, bins = profile_chi2(a, b)
        lines.append(f"compared  ux({a.label}) - ux({b.label}) per bin: chi2/dof {chi2:.3f} over {bins} bins "
                     f"(3-sigma range with per-bin errors [{low:.2f}, {high:.2f}])")


def plot_walls(runs, g, nu_ref, walls, cutoff):
    """walls.png: velocity, its difference from the lattice walls', density, density next to the walls."""
    fig, ax = plt.subplots(2, 2, figsize=(12, 8.5))
    draw_no_slip_poiseuille(ax[0, 0], walls, g, nu_ref, f"analytic, no slip, nu = {nu_ref:.4f} (no-wall run)")
    lattice = runs[0]
    for r, marker in zip(runs, "osd"):
        t = r.table
        v, e = r.values()
        ax[0, 0].errorbar(t["z"], t["ux"], yerr=r.ux_error, fmt=marker, ms=3, mfc="none",
                          label=f"{r.label} walls: nu {v[0]:.3f} +- {e[0]:.3f}, slip {v[1]:+.3f} / {v[2]:+.3f}")
        ax[1, 0].plot(t["z"], t["density"], marker + "-", ms=3, mfc="none", label=f"{r.label} walls")
        ax[1, 1].plot(*near_both_walls(t["z"], t["density"], walls, 2.0 * cutoff), marker, ms=4, mfc="none",
                      label=f"{r.label} walls (both walls)")
        if r is not lattice:
            both = r.fitted & lattice.fitted
            ax[0, 1].errorbar(t["z"][both], (t["ux"] - lattice.table["ux"])[both],
                              yerr=np.hypot(r.ux_error, lattice.ux_error)[both], fmt=marker, ms=3, mfc="none",
                              label=f"{r.label} - lattice")
    ax[0, 1].axhline(0.0, color="k", lw=0.8)
    label(ax[0, 0], "velocity", "z", "u_x", legend=7)
    label(ax[0, 1], "random minus lattice walls (fit range; long-block errors)", "z", "du_x", legend=8)
    label(ax[1, 0], "density", "z", "number density", legend=8)
    label(ax[1, 1], "density next to the walls", "distance from the wall", "number density", legend=8)
    mark_walls([ax[0, 0], ax[1, 0]], walls)
    fig.suptitle(f"Poiseuille flow between lattice and random equilibrated walls, d = {walls[1] - walls[0]:g}, g = {g:g}")
    save(fig, "walls.png")
    print("Written walls.png and resultsWalls.dat")
