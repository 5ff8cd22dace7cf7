"""The Couette slip scene (tutorials/channel/couetteSlip; Smiatek et al.): Couette flow between sliding
three-layer walls, one run per a_ww of runSweep's sweep. The checks of the first channel (the shear
stress's flatness, nu against the fluid without walls, the mean kT against the set kT plus the viscous
heating) and the slip's growth with a_wf, each at a tutorial's budget (issue 45: the standard error first
within the budget, then the value within a fixed bound), and the pictures.

    flat, slab_error = stress_flatness(prof, walls, cutoff)
    stress_flat_check(checks, a_ww, flat, slab_error, budget); nu_checks(...); kT_check(...)
    growth_checks(checks, a_wf, b, err, step_budget, rise_budget)
    plot(sweep, profiles, kT_expected, a_wf, slip, published, nu_nw, walls, fluid, suffix, variant, no_slip_bound)
"""
import math

import numpy as np

from .checks import as_number
from .plots import label, mark_walls, plt, save
from .sweep import draw_near_walls, draw_profiles, slab_means, sweep_colours

# The fixed bounds (issue 45; the tutorial's budgets decide first): nu = stress / (rho shear rate) within 5 %
# of the same fluid's without walls; the shear stress's largest slab deviation within 5 %; the mean kT
# within 1 % of the set kT plus the viscous heating.
NU_BOUND = 0.05
FLAT_BOUND = 0.05
KT_BOUND = 0.01

# The profile panels of couetteSlip.png: column, with error bars, title.
PROFILE_PANELS = (("ux", True, "velocity u_x"), ("density", False, "density"),
                  ("kT", False, "kT about the local flow (dashed: set + viscous heating)"),
                  ("sigmaxz", True, "shear stress sigma_xz"))


def stress_flatness(prof, walls, cutoff):
    """The largest deviation of the shear stress from its mean over slabs two cutoffs thick across the
    whole channel (wall layers included), and a slab's largest standard error relative to the mean (the
    deviation's error at most; one-cutoff slabs: 2.1 % in the test, too close to the bound)."""
    slabs, slab_err = slab_means(prof["z"], prof["sigmaxz"], prof["sigmaxzErr"], *walls, 2 * cutoff)
    return np.max(np.abs(slabs / np.mean(slabs) - 1.0)), np.max(slab_err) / abs(np.mean(slabs))


def growth_checks(checks, a_wf, b, err, step_budget, rise_budget):
    """The slip length grows with a_wf (issue 45): no step up in a_wf lowers the mean of the walls by
    more than 3 step budgets, and over the whole sweep it rises by more than 3 rise budgets, each first
    with its standard error (the two means' errors in quadrature) within its budget; a sign alone is no
    check. Two runs at least, each with its a_wf (a finite number), slip length and error."""
    a_wf, b, err = (np.array([as_number(v) for v in x], dtype=float) for x in (a_wf, b, err))
    if len(a_wf) < 2 or len(b) != len(a_wf) or len(err) != len(a_wf) or not np.all(np.isfinite(a_wf)):
        checks.fail(f"slip length against a_wf: {len(a_wf)} a_wf {list(a_wf)}, {len(b)} slip lengths, {len(err)} "
                    "errors (two runs at least, each with its a_wf, slip and error)")
        return
    order = np.argsort(a_wf)
    for lo, hi in zip(order[:-1], order[1:]):
        checks.bounded(f"slip length grows from a_wf = {a_wf[lo]:.2f} to {a_wf[hi]:.2f}: not lower by more than "
                       f"3 x {step_budget:g} (standard error below {step_budget:g})", b[hi] - b[lo],
                       math.hypot(err[hi], err[lo]), step_budget, lower=-3 * step_budget)
    lo, hi = order[0], order[-1]
    checks.bounded(f"slip length larger at a_wf = {a_wf[hi]:.2f} than at {a_wf[lo]:.2f} by more than 3 x {rise_budget:g} "
                   f"(standard error below {rise_budget:g})", b[hi] - b[lo], math.hypot(err[hi], err[lo]), rise_budget,
                   lower=3 * rise_budget)


def stress_flat_check(checks, a_ww, flat, flat_err, budget):
    """The shear stress's largest slab deviation: its error first within the budget, then below FLAT_BOUND."""
    flat, flat_err = as_number(flat), as_number(flat_err)
    checks.bounded(f"shear stress flat within {100 * FLAT_BOUND:g} % across the channel (a_ww = {a_ww:g}; a slab's "
                   f"standard error below {100 * budget:g} %)", flat, flat_err, budget, None, FLAT_BOUND,
                   f"max slab deviation {100 * flat:.2f} % (a slab's error at most {100 * flat_err:.2f} %)")


def nu_checks(checks, a_ww, nu, nu_err, nu_nw, nu_nw_err, budget):
    """nu = stress / (rho shear rate) against nu without walls: the combined standard error within the
    budget, then the difference within NU_BOUND."""
    nu, nu_err, nu_nw, nu_nw_err = (as_number(v) for v in (nu, nu_err, nu_nw, nu_nw_err))
    rel_nu, rel_nu_se = nu / nu_nw - 1.0, math.hypot(nu_err / nu_nw, nu * nu_nw_err / nu_nw ** 2)
    checks.add(f"nu = stress / (rho shear rate) and nu without walls: combined standard error within "
               f"{100 * budget:g} % (a_ww = {a_ww:g})", rel_nu_se <= budget, f"{100 * rel_nu_se:.2f} %")
    checks.add(f"nu = stress / (rho shear rate) within {100 * NU_BOUND:g} % of nu without walls (a_ww = {a_ww:g})",
               abs(rel_nu) <= NU_BOUND and rel_nu_se <= budget,
               f"{nu:.4f} +- {nu_err:.4f} against {nu_nw:.4f} +- {nu_nw_err:.4f} ({100 * rel_nu:+.2f} %)")


def kT_check(checks, a_ww, kT_mean, kT_err, kT_expected, expected_err, heating, budget):
    """The mean kT against the set kT plus the viscous heating: the relative difference's standard error
    (the mean's and the heating's in quadrature) first within the budget, then within KT_BOUND."""
    kT_mean, kT_err, kT_expected, expected_err = (as_number(v) for v in (kT_mean, kT_err, kT_expected, expected_err))
    rel, rel_se = kT_mean / kT_expected - 1.0, math.hypot(kT_err, expected_err) / kT_expected
    checks.bounded(f"mean kT within {100 * KT_BOUND:g} % of the set kT plus the viscous heating (a_ww = {a_ww:g}; "
                   f"standard error below {100 * budget:g} %)", rel, rel_se, budget, -KT_BOUND, KT_BOUND,
                   f"{kT_mean:.4f} +- {kT_err:.4f} against {kT_expected:.4f} +- {expected_err:.4f} (heating "
                   f"{as_number(heating):+.4f})")


def plot(sweep, profiles, kT_expected, a_wf, slip, published, nu_nw, walls, fluid, suffix="", variant=None,
         no_slip_bound=None):
    """couetteSlip<suffix>.png: the profiles across the channel, the slip and nu against a_wf; the density near
    the walls (couetteSlip<suffix>_nearWall.png). variant: the variant's words for the title (None: the
    published scene); no_slip_bound: the no-slip variant's band |b| < bound, drawn when given."""
    b, b_err, b_mean, b_mean_err = slip
    table = published["tables"]["Table 1"]
    fig, ax = plt.subplots(2, 3, figsize=(16, 8.5))
    ax = ax.ravel()
    names = [f"a_ww {aw:g} (a_wf {af:.2f})" for aw, af in zip(sweep["pairCoeffs/wall-wall/a"], a_wf)]
    for a, (column, errors, title) in zip(ax, PROFILE_PANELS):
        draw_profiles(a, profiles, names, column, errors)
        label(a, title, "z")
    for kT, colour in zip(kT_expected, sweep_colours(len(profiles))):
        ax[2].axhline(kT, color=colour, ls="--", lw=0.8)
    if "wallVelocity_1" in sweep:
        u_wall = 0.5 * (sweep["wallVelocity_1"][0] - sweep["wallVelocity_0"][0])
        ax[0].plot(walls, [-u_wall, u_wall], "k-", lw=0.8, label="no slip")
    ax[4].errorbar(a_wf, b[:, 0], yerr=b_err[:, 0], fmt="v-", label="lower wall")
    ax[4].errorbar(a_wf, b[:, 1], yerr=b_err[:, 1], fmt="^-", label="upper wall")
    ax[4].errorbar(a_wf, b_mean, yerr=b_mean_err, fmt="ko-", label="mean")
    ax[4].plot(table["a_wf"], table["slipLength"], "rs", label="published (Table 1)")
    a_line = np.linspace(min(table["a_wf"]), max(table["a_wf"]), 100)
    ax[4].plot(a_line, published["fits"]["slipLength"][1](a_line), "r--", lw=0.8, label="published fit")
    if no_slip_bound is not None:
        ax[4].axhspan(-no_slip_bound, no_slip_bound, color="gray", alpha=0.2, label=f"|b| < {no_slip_bound:g}")
    label(ax[4], "slip length against a_wf", "a_wf", "slip length")
    ax[5].errorbar(a_wf, sweep["nu"], yerr=sweep["nuError"], fmt="o-", label="stress / (rho shear rate)")
    ax[5].axhline(nu_nw, color="k", lw=0.8, label="no walls (reverse Poiseuille)")
    label(ax[5], "viscosity", "a_wf", "nu")
    mark_walls(ax[:4], walls)
    for a in ax:
        a.legend(fontsize=7)
    fig.suptitle(f"Couette flow, d = {walls[1] - walls[0]:g}, gamma_fw {fluid['gamma_fw']:g}: slip against the wall-fluid "
                 f"repulsion (a_wf = sqrt(a_ww a_ff)){' - ' + variant if variant else ''}")
    save(fig, f"couetteSlip{suffix}.png", dpi=100)

    fig, ax = plt.subplots(figsize=(7, 4.5))
    draw_near_walls(ax, profiles, [f"a_wf {a:.2f}" for a in a_wf], walls)
    ax.set_xlim(0, 3 * fluid["cutoff"])
    label(ax, "density near the wall for each a_wf", "distance from the wall (solid: lower, dashed: upper)",
          "number density", legend=8)
    save(fig, f"couetteSlip{suffix}_nearWall.png", dpi=100)
    print(f"Written couetteSlip{suffix}.png, couetteSlip{suffix}_nearWall.png and results{suffix}.dat")
