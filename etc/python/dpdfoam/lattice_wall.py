"""The lattice-wall Poiseuille channel (tutorials/channel/poiseuille/latticeWall): the channel between
frozen three-layer lattice walls against the fluid without walls, the same channel between random
equilibrated walls compared with it, and its simpleFoam twin against the analytic parabola.

    m = channel_measures(prof, ref, walls, g, cutoff)       # interior density, kT against the no-wall box
    draw_channel(prof, m["rho"], walls, g, ref, kT_set, summary)      # poiseuille.png
    checks = compare_walls(runs, g, nu_ref, nu_ref_err, cutoff, nu_budget, slip_budget, pair_budgets)
    twin = foam_twin()                   # the case's compareFVM and its simpleFoam twin; draw_twin(twin)

Lattice and random walls compared with honest error bars (walls.png, resultsWalls.dat and their checks;
docs/walls.md 3.2: the random walls give the same Poiseuille profile). The errors are long-block ones
(dpdfoam.sweep.LongBlockRun): the slowest mode, tau1 = d^2 / (pi^2 nu) (37 time units for d = 10, 600 for
d = 40), outlasts the sampling blocks (25), joined into super-blocks of about 2 tau1 (the test's: 75 for
2 tau1 = 75.2).
"""
import math

import numpy as np

from .channel import poiseuille_velocity
from .checks import Checks, as_number, relative_difference, write_results
from .io import foam_latest_fields, foam_latest_time, latest_fit, read_compare, read_dict
from .plots import draw_kT_of_shear, draw_no_slip_poiseuille, label, mark_walls, plt, save
from .stats import chi2_bounds
from .sweep import (LongBlockRun, agreement, effective_dof, kT_over_no_wall, long_block_lines, near_both_walls,
                    profile_chi2, weighted_error)

NAMES = ("nu", "slipLower", "slipUpper")
# No slip: |b| below this at every wall (docs/walls.md 3.2: |b| < 0.1 moves the centre line by 4 b / d
# < 1 % at d = 40).
SLIP_BOUND = 0.1
# The pair comparisons (issue 45): the difference's jackknife error (two runs' in quadrature) first below
# its budget, then the difference within PAIR_BOUND budgets of zero, a bound fixed by the budget (not
# widened with the run's own error).
PAIR_BOUND = 3.0


def channel_measures(prof, ref, walls, g, cutoff):
    """The interior's density (mean, flatness, a bin's largest relative error), the mean kT, and the
    bulk's kT minus the no-wall box's at the same shear rate with the difference's standard error."""
    z, rho, count, box = prof["z"], prof["density"], prof["count"], ref["table"]
    d, centre = walls[1] - walls[0], 0.5 * (walls[0] + walls[1])
    interior = np.abs(z - centre) < 0.5 * d - 1.0
    rho_mean = np.average(rho[interior])
    # kT against the local shear rate: channel bulk (beyond 3 cutoffs from the walls, which take heat
    # away) against the periodic box without walls at the same shear rate.
    bulk = np.abs(z - centre) < 0.5 * d - 3.0 * cutoff
    return {"rho": rho_mean, "flatness": np.max(np.abs(rho[interior] / rho_mean - 1.0)),
            "densityError": np.max(prof["densityErr"][interior] / rho[interior]),
            "kT": np.average(prof["kT"], weights=count), "kTBox": np.average(box["kT"], weights=box["count"]),
            "kTCentre": np.average(prof["kT"][np.abs(z - centre) < 1.0]),
            "heating": kT_over_no_wall(prof, bulk, centre, g, ref["nu"], ref["kT_of_shear"]),
            "heatingError": math.hypot(weighted_error(count[bulk], prof["kTErr"][bulk]),
                                       weighted_error(box["count"], box["kTErr"]))}


def draw_channel(prof, rho_mean, walls, g, ref, kT_set, summary):
    """poiseuille.png: velocity with the analytic profile, density, kT with the no-wall box's."""
    z, nu_ref = prof["z"], ref["nu"]
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.6))
    ax[0].errorbar(z, prof["ux"], yerr=prof["uxErr"], fmt="o", ms=3, label="DPD, frozen three-layer walls")
    draw_no_slip_poiseuille(ax[0], walls, g, nu_ref, f"analytic, no slip, nu = {nu_ref:.4f} (no-wall run)")
    label(ax[0], "velocity", "z", "u_x", legend=8)
    ax[1].plot(z, prof["density"], "o-", ms=3)
    ax[1].axhline(rho_mean, color="k", lw=0.8)
    label(ax[1], "density", "z", "number density")
    ax[2].plot(z, prof["kT"], "o-", ms=3)
    ax[2].axhline(kT_set, color="k", lw=0.8, label="set kT")
    draw_kT_of_shear(ax[2], 0.5 * (walls[0] + walls[1]), ref["kT_of_shear"], g, nu_ref)
    ax[2].set_ylim(kT_set * 0.9, kT_set * 1.15)
    label(ax[2], "temperature", "z", "kT about the local flow", legend=8)
    mark_walls(ax, walls)
    fig.suptitle(f"Poiseuille flow, d = {walls[1] - walls[0]:g}, g = {g:g}: {summary}")
    save(fig, "poiseuille.png")


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


def compare_walls(cases, g, nu_ref, nu_ref_err, cutoff, nu_budget, slip_budget, pair_budgets):
    """Lattice walls against random walls from the mask and the gmsh file: walls.png, resultsWalls.dat
    and the checks. cases: (label, case directory) of each run, the lattice walls first; the random
    walls' budgets of nu (relative) and of the slip lengths, and the pairs' (PAIR_BUDGETS of NAMES)."""
    lo, hi = latest_fit()["wallPosition"]
    tau1 = (hi - lo) ** 2 / (math.pi ** 2 * nu_ref)
    runs = [LongBlockRun(name, case, "channelProfile") for name, case in cases]
    too_short = [r.too_short for r in runs if r.too_short]
    errors = ("fitSlipLength's (blocks shorter than tau1 = d^2/(pi^2 nu))" if too_short else
              f"fitSlipLength's jackknife over super-blocks of {runs[0].super_block_time:g} (tau1 = d^2/(pi^2 nu) = {tau1:.0f})")
    checks, lines = Checks(), [f"# Lattice and random walls, d = {hi - lo:g}, g = {g:g}; errors: {errors}"]
    for r in runs:
        lines += long_block_lines(r, cutoff)
    wall_pairs(checks, lines, runs, tau1, pair_budgets)
    # Each random wall on its own, held to what the lattice walls are held to (main checks): with the
    # jackknife's errors, or fitSlipLength's where the blocks are too few for it.
    for r in runs[1:]:
        v, e = r.values()
        nu_check(checks, f"{r.label} walls", v[0], e[0], nu_ref, nu_ref_err, nu_budget)
        for k, side in ((1, "lower"), (2, "upper")):
            no_slip_check(checks, f"{side} {r.label} wall", v[k], e[k], slip_budget)
    write_results("resultsWalls.dat", lines, checks)
    plot_walls(runs, g, nu_ref, (lo, hi), cutoff)
    return checks


def wall_pairs(checks, lines, runs, tau1, pair_budgets):
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
        compare_pairs(runs, checks, lines, pair_budgets)


def compare_pairs(runs, checks, lines, pair_budgets):
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
            agreement_check(checks, name, a.label, b.label, diff, sigma, pair_budgets[name], dof)
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


def foam_twin():
    """The DPD channel and its simpleFoam twin (makeFoamCase: nu measured without walls in viscosity/, no
    slip; simpleFoam/constant/dpdCase): compareFVM's whole-profile comparison and profiles, the twin's
    cells, and how far simpleFoam lies from the analytic parabola u = g (z - z_lo)(z_hi - z) / (2 nu).
    On a uniform mesh the finite-volume solution of this problem is exactly the parabola shifted by
    g h^2 / (8 nu) at the cell centres (the half-cell wall gradient (U_P - 0)/(h/2) is the one inexact
    term; the wall flux is fixed at g d / 2 by the force balance, so the shift is the same in every
    cell): solverError is the largest |U - (analytic + g h^2 / (8 nu))| / u_max (the solver's
    tolerance), discretisation the largest |U - analytic| / u_max."""
    t = foam_latest_time("postProcessing/compareFVM")
    cmp = read_compare(f"postProcessing/compareFVM/{t}/compare.dat")[0]  # the whole profile's, not a line's
    zb, ud, ue, uf = np.loadtxt(f"postProcessing/compareFVM/{t}/profiles.dat")[:, :4].T
    rec = read_dict("simpleFoam/constant/dpdCase")
    z_lo, z_hi = rec["meshMin"][2], rec["meshMax"][2]
    d, g, nu = z_hi - z_lo, rec["g"][0], rec["nu"]
    h = d / rec["cells"][2]
    ft, (cells, velocity) = foam_latest_fields("simpleFoam", "C", "U")
    z, u = cells[:, 2], velocity[:, 0]
    analytic = poiseuille_velocity(z, z_lo, z_hi, g, nu)
    u_max = g * d * d / (8 * nu)
    return {"time": t, "compare": cmp, "bins": (zb, ud, ue, uf), "foamTime": ft, "z": z, "u": u, "walls": (z_lo, z_hi),
            "d": d, "g": g, "nu": nu, "h": h, "solverError": np.max(np.abs(u - (analytic + g * h * h / (8 * nu)))) / u_max,
            "discretisation": np.max(np.abs(u - analytic)) / u_max}


def draw_twin(twin):
    """compareFVM.png: the DPD profile, simpleFoam's and the analytic one; DPD minus simpleFoam."""
    (zb, ud, ue, uf), (z_lo, z_hi), cmp = twin["bins"], twin["walls"], twin["compare"]
    g, nu, L2, noise = twin["g"], twin["nu"], cmp["L2"], cmp["noiseL2"]
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    zz = np.linspace(z_lo, z_hi, 200)
    ax[0].errorbar(zb, ud, yerr=ue, fmt="o", ms=3, label="DPD (profileBins)")
    ax[0].plot(twin["z"], twin["u"], "r-", lw=1.5, label=f"simpleFoam, nu = {nu:.4f} (no walls), no slip")
    ax[0].plot(zz, poiseuille_velocity(zz, z_lo, z_hi, g, nu), "k:", lw=1, label="analytic, no slip")
    label(ax[0], f"channel d = {twin['d']:g}: DPD and simpleFoam", "z", "u_x", legend=8)
    ax[1].errorbar(zb, ud - uf, yerr=ue, fmt="o", ms=3)
    ax[1].axhline(0, color="k", lw=0.8)
    label(ax[1], f"L2 = {L2:.4f} (noise {noise:.4f}), Linf = {cmp['Linf']:.4f}", "z", "u_DPD - u_simpleFoam")
    save(fig, "compareFVM.png", dpi=120)
