#!/usr/bin/env python3
"""Striped-wall tutorial: the measured slip tensor against the project's continuum reference.

Reads the calibration (calibration/gammaL.dat: where the wall acts, each sector's gamma_L and the slip
it gives), the sweeps (slipTensor's results per run: sweepAngle/, and at full size sweepGasFraction/,
sweepLocalSlip/, sweepHeight/, sweepHalfForce/, sweepForce/, sweepPeriod/) and the fluid at rest over
the stripes (rest/); computes the reference with stripedSlip at the calibrated slips in the channel
between the hydrodynamic walls (dpdfoam.slip); writes results.dat and stripedWall.png and exits non-zero
when a check fails (the first fluid layer's speed and areal density at 0 and 90 degrees: information).
Every check (issue 45) first requires the standard error of its comparison (the run's, the wall
position's for slip lengths, and the calibration's: the reference recomputed at each sector's slip +-
its error) below a budget (BUDGETS: full size and test mode, each derived from measured errors), then
holds the value to a fixed bound of three budgets, never widened by the run's own error:
  - b_par and b_perp (mean of the walls, from the hydrodynamic wall) within 3 budgets of the
    reference: in the angle sweep the weighted mean of the runs that drive each, elsewhere per run
    (gas fraction, local slip, height); and b_par - b_perp of the angle sweep, which does not depend
    on where the wall acts;
  - the transverse flux ratio within 3 budgets of the reference at every angle between 0 and 90 and
    every channel height, and zero within 3 budgets at theta 0 and 90; at theta 45 the flow turns
    towards the stripes: the ratio above 3 budgets;
  - the flux linear in the force: at half the force, the flux per unit force along and across the
    stripes within 3 budgets (relative) of the flux at the standard force (twice the force is
    information: there inertia takes ~3 % of the flux, README);
  - at the period 40 (sweepPeriod/), b_par at theta 0, b_perp at theta 90 and b_par - b_perp against
    the reference at that period, as above;
  - at rest, the layer next to the walls (within zc) holds the same density and kT over the gas and
    the no-slip sectors, their difference within 3 budgets of zero.
The default (the review's fluid, a = 0) runs the angle sweep at 0 and 90 degrees only (b_par, b_perp,
their difference and zero transverse flux) and the fluid at rest; -a25 (the standard fluid, run in
a25/) every study. The test mode decides every check its runs allow (the angle sweep at 0 and 90
degrees, -a25 also 45, and the fluid at rest) with the test's budgets, but the turn at theta 45
(information: TEST_INFORMATION).
"""
import math
import os
import sys

import numpy as np

from dpdfoam.checks import Checks, as_number, mode_budget, plus_minus as pm, write_results
from dpdfoam.io import dictionary_number, latest, read_dict, read_table, sweep_vector, wall_planes
from dpdfoam.plots import column_bars, label, legend_or_hide, plt, save
from dpdfoam.slip import (PRINCIPAL_SLIPS, StripedReference, anisotropy_check, first_layers, near_wall_sectors,
                          principal_slip_checks, read_slip_tensor, reference_check, run_value as run,
                          same_at_rest_check, turn_check, zero_flux_check)
from dpdfoam.stats import inverse_variance_mean

TEST_MODE = "-test" in sys.argv[1:]
# The fluid: the review's (a = 0, the default) or the standard fluid's sweep (-a25, run in a25/).
FLUID = "a25" if "-a25" in sys.argv[1:] else "a0"
# The test's 800 time units cannot decide the turn at theta 45 (its budget's bound, 3 x 0.04, lies above
# the reference's 0.051): information there, every other check of the test's runs decided.
TEST_INFORMATION = ("the flow turns towards the stripes",)  # (dpdfoam.slip.turn_check's name)
# A value within BOUND budgets of its expectation (issue 45: the bound fixed by the budget).
BOUND = 3.0
# Standard-error budgets (issue 45) per fluid, (full size, test mode). None: that study does not run.
BUDGETS = {
    # a = 25: full size from the README's runs of 2026-11-27 (the wall's position adds 0.091 to every b,
    # the calibration 0.090-0.102 to its reference, mostly the no-slip sectors' b0 +- 0.10); test from
    # its run of 2026-11-28 (800 time units; its three-point calibration: wall +- 0.30, b0 +- 0.33).
    "a25": {
        # full: run 0.021-0.029 (+) wall 0.091 (+) calibration 0.099 = 0.137; test: 0.096-0.116 (+) 0.304 (+) 0.33 = 0.46
        "b, angle sweep": (0.16, 0.55),
        # full: run 0.020-0.108 (+) wall 0.091 (+) calibration 0.090-0.102 = 0.135-0.173 (phi2, b, H and L 40)
        "b, one run": (0.19, None),
        # full: run 0.036 (+) calibration 0.005 = 0.036 (the wall cancels); test: 0.151 (+) 0.019 = 0.152
        "b_par - b_perp, angle sweep": (0.05, 0.2),
        # full: run 0.100 (+) calibration 0.033 = 0.105 (L 40)
        "b_par - b_perp, L 40": (0.13, None),
        # full: 0.007-0.011 at 22.5-67.5 degrees; test: 0.009 at 45, 0.018 and 0.036 at 90 and 0 (the
        # 3400-unit runs' 0.009-0.017 x sqrt(3000 / 600 sampled) = 0.02-0.038)
        "flux ratio, angle sweep": (0.013, 0.04),
        # full: 0.005-0.017 (phi2, b and H)
        "flux ratio, one run": (0.02, None),
        # full: 0.007 (10400 time units at 45 degrees); test: as the angle sweep's ratio
        "the flow turns": (0.01, 0.04),
        # full: 0.012 at 0, 0.009 at 90 degrees; test: 0.036 at 0, 0.018 at 90
        "zero flux": (0.015, 0.04),
        # relative: full 1.4 % along, 1.6 % across (g / 2 against g)
        "flux linear": (0.02, None),
        # full: 0.007 (1000 time units sampled); test: 0.015 (400 sampled)
        "at rest, density": (0.01, 0.02),
        # full: 0.0021; test: 0.0046
        "at rest, kT": (0.003, 0.006),
    },
    # a = 0 (theta 0 and 90 only): full size from the README's run of 2026-11-29 (13600 time units at
    # g 0.002; the wall's position adds 0.083 to every b, the calibration 0.094 to its reference);
    # test from its run of 2026-11-29 (800 time units; its three-point calibration: wall +- 0.37, b0
    # +- 0.41). Each about 1.2 x the largest measured, a share of room for the estimate's own scatter.
    "a0": {
        # full: run 0.057-0.062 (+) wall 0.083 (+) calibration 0.094 = 0.138-0.140; test: 0.29-0.34 (+) 0.37 (+) 0.40-0.41 = 0.62-0.64
        "b, angle sweep": (0.17, 0.8),
        # full: run 0.084 (+) calibration 0.008 = 0.085; test: 0.444 (+) 0.025 = 0.445
        "b_par - b_perp, angle sweep": (0.1, 0.55),
        # full: 0.0074 at 0, 0.0185 at 90 degrees; test: 0.065 at 0, 0.095 at 90
        "zero flux": (0.022, 0.12),
        # full: 0.0118, test: 0.025 (the layer within zc is half empty at a = 0: fewer particles, more
        # noise than a = 25's 0.007 over the same 1000 time units)
        "at rest, density": (0.014, 0.032),
        # full: 0.0022; test: 0.0051
        "at rest, kT": (0.003, 0.0065),
    },
}


def budget(kind, test=None, fluid=None):
    """The standard-error budget of a kind of check in this mode and fluid (or in the ones `test` and
    `fluid` name); NaN, a failed check, for a study that mode has no budget for."""
    return mode_budget(BUDGETS[fluid or FLUID], kind, TEST_MODE if test is None else test)


ZC = 1.0


def reference(cal, gas_fraction, slip, slip_error, height, angles=(45.0,), period=None, label=None):
    """stripedSlip's reference (dpdfoam.slip) with the calibration's no-slip sectors' residual slip."""
    return StripedReference(gas_fraction, slip, slip_error, height, period or cal["period"],
                            (cal["gammaNoSlipSlip"], cal["gammaNoSlipSlipError"]), angles, label)


def linear(checks, name, q1, e1, q2, e2, limit):
    """The flux per unit force at g / 2 (q2) as at g (q1): their relative difference within BOUND
    budgets (relative) of 0."""
    q1, e1, q2, e2 = (as_number(v) for v in (q1, e1, q2, e2))
    rel = q2 / q1 - 1.0 if q1 else float("nan")
    se = math.hypot(e1, e2) / abs(q1) if q1 else float("nan")
    return checks.within_budgets(f"flux {name} linear in the force: per unit force at g / 2 as at g, within "
                                 f"{100 * BOUND * limit:g} % (standard error below {100 * limit:g} %)", rel, se, limit,
                                 f"{q2:.4f} against {q1:.4f}, difference {100 * rel:+.2f} +- {100 * se:.2f} %",
                                 -BOUND, BOUND)


def layer_study(sweep, s, ref, walls, period, gas_fraction, out):
    """The first layer in a sweep's runs at 0 and 90 degrees (information, README): against smooth walls
    alone it moves across the stripes at a smaller share of its speed along them than the continuum's
    b_perp / b_par and piles up downstream; with the fluid behind the walls it follows the continuum."""
    if 0.0 not in s["angle"] or 90.0 not in s["angle"]:
        return
    layers = first_layers(sweep, s, (0.0, 90.0), walls, period, gas_fraction, ZC)
    if any(layer is None for layer, _ in layers.values()):
        out.append(f"# L {period:g}: no first fluid layer (no density minimum within two cutoffs of the plane: nothing "
                   "packs against the wall, as in a fluid without conservative force)")
        return
    (along_layer, along_force), (across_layer, across_force) = layers[0.0], layers[90.0]
    # Per unit force: in the continuum the mean slip velocity is b_eff times the wall's shear rate, the
    # same for both at the same force, so the ratio is b_perp / b_par.
    along, across = along_layer[0]["y"] / along_force, across_layer[0]["x"] / across_force
    out.append(f"# L {period:g}, the first fluid layer (from the plane to {along_layer[2]:.2f}): its mean velocity per "
               f"unit force, along the stripes at theta 0 {along:.2f}, across them at theta 90 {across:.2f}: ratio "
               f"{across / along:.3f}, against the continuum's b_perp / b_par "
               f"{ref['slipPerpendicular'] / ref['slipParallel']:.3f}")
    out += [f"# L {period:g}, the first layer's areal density over the gas sectors, downstream half against "
            f"upstream half, theta {a:g}: {pm(*layers[a][0][1], sign='+')}" for a in (0.0, 90.0)]


def period_study(cal, sp, height, gas_fraction, checks, out, walls):
    """The same stripes at a larger period L (the same local slip and channel), along and across them."""
    period = float(sp["walls/lower/tunableSlip/stripes/period"][0])
    ref = reference(cal, gas_fraction, cal["gammaGasSlip"], cal["gammaGasSlipError"], height, period=period)
    out.append(f"# period L {period:g} (b/L {cal['gammaGasSlip'] / period:.3f}): b_par at theta 0, b_perp at theta 90 "
               "(reference)")
    rows = [sp["angle"].index(a) for a in (0.0, 90.0)]  # b_par from the run along the stripes, b_perp across
    principal_slip_checks(checks, f"L {period:g}", sp, rows, ref, cal["halfWidthError"], budget("b, one run"), BOUND)
    par, perp = (run(sp, "b" + key, k) for (key, _), k in zip(PRINCIPAL_SLIPS, rows))
    out += [f"{name}  {pm(*b)} ({ref['slip' + key]:.4f})" for (key, name), b in zip(PRINCIPAL_SLIPS, (par, perp))]
    anisotropy_check(checks, f"b_par - b_perp at L {period:g} (the wall's position cancels)", par, perp, ref,
                     budget("b_par - b_perp, L 40"), BOUND)
    layer_study("sweepPeriod", sp, ref, walls, period, gas_fraction, out)


def angle_study(cal, s, height, gas_fraction, checks, out):
    """The angle sweep: each run's row, b_par and b_perp weighted over the runs that drive each, b_par -
    b_perp, and the transverse flux ratio at each angle."""
    ref = reference(cal, gas_fraction, cal["gammaGasSlip"], cal["gammaGasSlipError"], height, s["angle"])
    out.append("# theta  b_par +- err   b_perp +- err   b_eff(theta) +- err   nu_par nu_perp   flux along, across the "
               "stripes   transverse flux ratio +- err   reference b_eff, ratio")
    for k, a in enumerate(s["angle"]):
        row = [f"{a:6g}"] + [pm(*run(s, key, k), sign="+") for key in ("bParallel", "bPerpendicular", "bEffective")]
        row += [f"{s['nuParallel'][k]:.4f} {s['nuPerpendicular'][k]:.4f}", pm(*run(s, "fluxParallel", k)),
                pm(*run(s, "fluxPerpendicular", k)), pm(*run(s, "transverseFluxRatio", k), 5, "+")]
        out.append("  ".join(row) + f"   {ref.effective(a):.4f} {ref.at('ratio', a):.5f}")
    wall_error, means = cal["halfWidthError"], {}
    for key, name in PRINCIPAL_SLIPS:
        runs = np.isfinite(s["b" + key])
        mean, err = means[key] = inverse_variance_mean(s["b" + key][runs], s["b" + key + "Error"][runs])
        reference_check(checks, f"{name} (angle sweep, weighted over {int(runs.sum())} runs)", mean, err, ref,
                        "slip" + key, wall_error, budget("b, angle sweep"), bound=BOUND)
        out.append(f"# {name}: {pm(mean, err)} (runs; wall +- {wall_error:.4f}), reference {ref['slip' + key]:.4f}")
    anisotropy_check(checks, "b_par - b_perp (angle sweep; the wall's position cancels)", means["Parallel"],
                     means["Perpendicular"], ref, budget("b_par - b_perp, angle sweep"), BOUND)
    for k, a in enumerate(s["angle"]):
        ratio, err = run(s, "transverseFluxRatio", k)
        if a == 45.0:
            turn_check(checks, ratio, err, budget("the flow turns"), BOUND)
        if a % 90 == 0:
            zero_flux_check(checks, a, ratio, err, budget("zero flux"), BOUND)
        else:
            reference_check(checks, f"transverse flux ratio at theta {a:g}", ratio, err, ref, "ratio", 0.0,
                            budget("flux ratio, angle sweep"), a, BOUND)
    return ref


def tensor_rows(cal, s, checks, out, title, parameter, references):
    """Per run at 45 degrees: b_par, b_perp and the flux ratio against their references."""
    out.append(f"# {title}: {parameter}  b_par +- err (reference)  b_perp +- err (reference)  flux ratio +- err (reference)")
    for k, ref in enumerate(references):
        where = f"{parameter} {ref.label:g}"
        principal_slip_checks(checks, where, s, (k, k), ref, cal["halfWidthError"], budget("b, one run"), BOUND)
        reference_check(checks, f"transverse flux ratio at {where}", *run(s, "transverseFluxRatio", k), ref, "ratio",
                        0.0, budget("flux ratio, one run"), 45.0, BOUND)
        out.append(f"{ref.label:8g}  {pm(*run(s, 'bParallel', k))} ({ref['slipParallel']:.4f})  "
                   f"{pm(*run(s, 'bPerpendicular', k))} ({ref['slipPerpendicular']:.4f})  "
                   f"{pm(*run(s, 'transverseFluxRatio', k), 5, '+')} ({ref.at('ratio', 45.0):.5f})")


def force_study(s, k45, checks, out):
    """The flux per unit force at theta 45: at half the force (sweepHalfForce/) it must equal the
    standard force's, which is then on the linear (Stokes) branch; at twice the force (sweepForce/) it
    shows where that branch ends (information: inertia takes a part in g^2, README)."""
    for path, factor, what in (("sweepHalfForce/sweep.dat", 0.5, "half the force"), ("sweepForce/sweep.dat", 2.0, "twice the force")):
        if not os.path.exists(path):
            continue
        sf = read_slip_tensor(path)
        out.append(f"# flux per unit force at theta 45: the standard force, {what}")
        for key, name in (("fluxParallel", "along the stripes"), ("fluxPerpendicular", "across them")):
            q1, e1 = run(s, key, k45)
            q2, e2 = sf[key][0] / factor, sf[key + "Error"][0] / factor
            out.append(f"{name}: {pm(q1, e1)}, {pm(q2, e2)} (difference {100 * (q2 / q1 - 1):+.1f} "
                       f"+- {100 * math.hypot(e1, e2) / q1:.1f} %)")
            if factor < 1.0:
                linear(checks, name, q1, e1, q2, e2, budget("flux linear"))


def sweep_studies(cal, gas_fraction, height, checks, out):
    """The full size's sweeps at 45 degrees (gas fraction, local slip, channel height), where they ran."""
    offset, b, e = cal["offset"], cal["gammaGasSlip"], cal["gammaGasSlipError"]
    studies = {}
    for key, path, title in (("phi2", "sweepGasFraction", "against the gas fraction (theta 45)"),
                             ("b", "sweepLocalSlip", "against the local slip (theta 45)"),
                             ("H", "sweepHeight", "against the channel's height (theta 45)")):
        if not os.path.exists(f"{path}/sweep.dat"):
            continue
        s = read_slip_tensor(f"{path}/sweep.dat", offset)
        if key == "phi2":
            refs = [reference(cal, f, b, e, height, label=f) for f in s["walls/lower/tunableSlip/stripes/gasFraction"]]
        elif key == "b":
            refs = [reference(cal, gas_fraction, bo, eo, height, label=bo) for bo, eo in zip(cal["slipTargets"], cal["gammaGasSlipErrorOf"])]
        else:
            planes = 2.0 * np.abs(np.array([sweep_vector(p)[2] for p in s["walls/lower/point"]]))
            refs = [reference(cal, gas_fraction, b, e, p - 2 * offset, label=p - 2 * offset) for p in planes]
        tensor_rows(cal, s, checks, out, title, key, refs)
        studies[key] = (s, refs)
    return studies


def main():
    cal = read_dict("calibration/gammaL.dat")
    period, offset = cal["period"], cal["offset"]
    walls = wall_planes()
    height = walls[1] - walls[0] - 2.0 * offset  # between the hydrodynamic walls
    gas_fraction = dictionary_number("constant/dpdProperties", "walls/lower/tunableSlip/stripes/gasFraction")
    checks = Checks()
    a = dictionary_number("constant/dpdProperties", "pairCoeffs/fluid-fluid/a")
    out = [f"# Striped walls in the fluid of a = {a:g} ({'the review' if a == 0 else 'the standard fluid'}), period L = {period:g}, phi2 {gas_fraction:g}, local slip b = {cal['gammaGasSlip']:g} "
           f"(b/L {cal['gammaGasSlip'] / period:g}), two walls in phase, H = {height:.3f} between the hydrodynamic walls",
           f"# calibration: gamma_L no slip {cal['gammaNoSlip']:.4f} (b0 "
           f"{pm(cal['gammaNoSlipSlip'], cal['gammaNoSlipSlipError'])}), gas {cal['gammaGas']:.4f} (b "
           f"{pm(cal['gammaGasSlip'], cal['gammaGasSlipError'])}); the wall acts "
           f"{pm(offset, cal['halfWidthError'])} in front of each plane"]
    s = read_slip_tensor("sweepAngle/sweep.dat", offset)
    ref = angle_study(cal, s, height, gas_fraction, checks, out)
    layer_study("sweepAngle", s, ref, walls, period, gas_fraction, out)
    studies = sweep_studies(cal, gas_fraction, height, checks, out)
    force_study(s, int(np.argmin(np.abs(s["theta"] - 45.0))), checks, out)
    if os.path.exists("sweepPeriod/sweep.dat"):
        period_study(cal, read_slip_tensor("sweepPeriod/sweep.dat", offset), height, gas_fraction, checks, out, walls)

    grid = read_table(latest("rest/postProcessing/profileBins/*/stripeGrid.dat"))
    layer, near = near_wall_sectors(grid, walls, period, gas_fraction, ZC)
    out += [f"# at rest, within zc of the walls over the {where} sectors: density {pm(*layer[where]['density'])}, "
            f"kT {pm(*layer[where]['kT'])}" for where in ("gas", "noSlip")]
    for q in ("density", "kT"):
        same_at_rest_check(checks, q, *layer["gas"][q], *layer["noSlip"][q], budget(f"at rest, {q}"), BOUND)
    # The test's short runs (800 time units) decide every check their outputs allow with the test's
    # budgets; the turn at theta 45 is information there (TEST_INFORMATION).
    checks.inform(lambda name: not TEST_MODE or not name.startswith(TEST_INFORMATION))
    write_results("results.dat", out, checks)
    draw(cal, s, ref, studies, grid, near, height, gas_fraction)
    print("Written stripedWall.png and results.dat")
    return checks.status()


def draw(cal, s, ref, studies, grid, near, height, gas_fraction):
    period = cal["period"]
    fig, ax = plt.subplots(2, 3, figsize=(16, 9))
    ax = ax.ravel()
    fine = np.linspace(0, 90, 91)
    ax[0].plot(fine, ref.effective(fine), "k-", label="continuum reference")
    column_bars(ax[0], s["theta"], s, "bEffective", "o", label="DPD (slipTensor)")
    label(ax[0], f"effective slip: phi2 {gas_fraction:g}, b/L {cal['gammaGasSlip'] / period:g}, H/L {height / period:.2f}",
          "theta (degrees from the stripes)", "b_eff(theta)")
    curve = reference(cal, gas_fraction, cal["gammaGasSlip"], 0.0, height, range(0, 91, 5))["ratio"]
    ax[1].plot(list(curve), list(curve.values()), "k-", label="continuum reference")
    column_bars(ax[1], s["theta"], s, "transverseFluxRatio", "o", label="DPD")
    ax[1].axhline(0, color="gray", ls=":")
    label(ax[1], "transverse flux, H = %.2f" % height, "theta (degrees)", "flux across the force / along it")
    for panel, key, xlabel in ((2, "phi2", "gas fraction phi2"), (3, "b", "local slip b of the gas sectors")):
        if key in studies:
            runs, refs = studies[key]
            x = [r.label for r in refs]
            for name, style, colour in (("Parallel", "o", "C0"), ("Perpendicular", "s", "C1")):
                column_bars(ax[panel], x, runs, "b" + name, style, color=colour, label=f"b_{name[:4].lower()} DPD")
                ax[panel].plot(x, [r["slip" + name] for r in refs], "-", color=colour, label=f"b_{name[:4].lower()} reference")
            label(ax[panel], f"theta 45: against {key}", xlabel, "slip length")
    if "H" in studies:
        runs, refs = studies["H"]
        column_bars(ax[4], [r.label for r in refs], runs, "transverseFluxRatio", "o", label="DPD")
        ax[4].plot([r.label for r in refs], [r.at("ratio", 45.0) for r in refs], "k-", label="continuum reference")
        label(ax[4], "theta 45, L = b: the flux ratio against H", "H (between the hydrodynamic walls)", "transverse flux ratio")
    for q, style in (("density", "o-"), ("kT", "s-")):
        col = [np.average(grid[q][near & (grid["x"] == x)], weights=grid["count"][near & (grid["x"] == x)]) for x in np.unique(grid["x"])]
        ax[5].plot(np.unique(grid["x"]), np.asarray(col) / np.mean(col), style, label=f"{q} / its mean")
    ax[5].axvspan(0, gas_fraction * period, color="lightblue", alpha=0.4, label="gas sector")
    label(ax[5], "at rest, within zc of the walls", "x (across the stripes)")
    legend_or_hide(ax, 8)  # the default's studies fill three panels; -a25's every one
    save(fig, "stripedWall.png", dpi=100)


if __name__ == "__main__":
    sys.exit(main())
