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

from dpdfoam.checks import Checks, as_number, write_results
from dpdfoam.io import dictionary_number, latest, read_dict, read_table, wall_planes
from dpdfoam.plots import label, plt, save
from dpdfoam.slip import StripedReference, first_layer, near_wall_sectors, read_slip_tensor
from dpdfoam.stats import inverse_variance_mean

TEST_MODE = "-test" in sys.argv[1:]
# The fluid: the review's (a = 0, the default) or the standard fluid's sweep (-a25, run in a25/).
FLUID = "a25" if "-a25" in sys.argv[1:] else "a0"
# The test's 800 time units cannot decide the turn at theta 45 (its budget's bound, 3 x 0.04, lies above
# the reference's 0.051): information there, every other check of the test's runs decided.
TEST_INFORMATION = ("the flow turns towards the stripes",)
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
    value = BUDGETS[fluid or FLUID].get(kind, (None, None))[1 if (TEST_MODE if test is None else test) else 0]
    return float("nan") if value is None else value


ZC = 1.0
PAR_PERP = (("Parallel", "b_par"), ("Perpendicular", "b_perp"))


def reference(cal, gas_fraction, slip, slip_error, height, angles=(45.0,), period=None, label=None):
    """stripedSlip's reference (dpdfoam.slip) with the calibration's no-slip sectors' residual slip."""
    return StripedReference(gas_fraction, slip, slip_error, height, period or cal["period"],
                            (cal["gammaNoSlipSlip"], cal["gammaNoSlipSlipError"]), angles, label)


def pm(value, error, digits=4, sign=""):
    """'value +- error' as results.dat writes it."""
    return f"{value:{sign}.{digits}f} +- {error:.{digits}f}"


def run(s, key, k):
    """Run k's value of a column and its error."""
    return s[key][k], s[key + "Error"][k]


def within(checks, name, value, error, limit, text, lower=-BOUND, upper=BOUND):
    """A check (issue 45): the standard error below the budget `limit`, then the value within lower to
    upper budgets (None: no bound on that side)."""
    return checks.bounded(name, value, error, limit, lower * limit, None if upper is None else upper * limit, text)


def near_zero(checks, what, value, error, limit, text):
    """what's value within BOUND budgets of 0."""
    return within(checks, f"{what} (within {BOUND:g} x {limit:g}, standard error below {limit:g})", value, error, limit,
                  text)


def against(checks, name, measured, run_error, ref, key, wall_error, limit, angle=None):
    """measured against the reference's key: the comparison's standard error (the run's, the wall
    position's and the calibration's in quadrature) below the budget `limit`, then within BOUND budgets."""
    m, r, w = (as_number(v) for v in (measured, run_error, wall_error))
    x, c = as_number(ref.at(key, angle)), as_number(ref.error(key, angle))
    total = math.sqrt(r ** 2 + w ** 2 + c ** 2)
    return within(checks, f"{name} within {BOUND:g} x {limit:g} of the reference {x:.4f} (standard error below {limit:g})",
                  m - x, total, limit, f"{m:+.4f} +- {total:.4f} (run {r:.4f}, wall {w:.4f}, calibration {c:.4f}), "
                  f"difference {m - x:+.4f}")


def slip_checks(checks, where, s, rows, ref, wall_error):
    """b_par and b_perp of single runs (rows: the run of each) against the reference."""
    for (key, name), k in zip(PAR_PERP, rows):
        against(checks, f"{name} at {where}", *run(s, "b" + key, k), ref, "slip" + key, wall_error, budget("b, one run"))


def anisotropy(checks, name, par, perp, ref, limit):
    """b_par - b_perp against the reference: it does not depend on where the wall acts."""
    against(checks, name, par[0] - perp[0], math.hypot(par[1], perp[1]), ref, "anisotropy", 0.0, limit)


def zero_flux(checks, angle, ratio, error, limit):
    """No transverse flux where nothing breaks the symmetry (theta 0 and 90): within BOUND budgets of 0."""
    ratio = as_number(ratio)
    return near_zero(checks, f"no transverse flux at theta {angle:g}", ratio, error, limit, f"{ratio:+.5f}")


def turns(checks, ratio, error, limit):
    """The flow turns towards the stripes at theta 45: the ratio above BOUND budgets."""
    ratio = as_number(ratio)
    return within(checks, f"the flow turns towards the stripes at theta 45 (ratio above {BOUND:g} x {limit:g}, standard "
                  f"error below {limit:g})", ratio, error, limit, f"{ratio:+.5f}", BOUND, None)


def same_at_rest(checks, q, gas, gas_error, no_slip, no_slip_error, limit):
    """At rest, quantity q within zc of the walls the same over gas and no-slip sectors: their difference
    within BOUND budgets of 0."""
    g, ge, n, ne = (as_number(v) for v in (gas, gas_error, no_slip, no_slip_error))
    se = math.hypot(ge, ne)
    return near_zero(checks, f"at rest, {q} within zc of the walls the same over gas and no-slip sectors", g - n, se,
                     limit, f"{g:.4f} against {n:.4f}, difference {g - n:+.4f} +- {se:.4f}")


def linear(checks, name, q1, e1, q2, e2, limit):
    """The flux per unit force at g / 2 (q2) as at g (q1): their relative difference within BOUND
    budgets (relative) of 0."""
    q1, e1, q2, e2 = (as_number(v) for v in (q1, e1, q2, e2))
    rel = q2 / q1 - 1.0 if q1 else float("nan")
    se = math.hypot(e1, e2) / abs(q1) if q1 else float("nan")
    return within(checks, f"flux {name} linear in the force: per unit force at g / 2 as at g, within "
                  f"{100 * BOUND * limit:g} % (standard error below {100 * limit:g} %)", rel, se, limit,
                  f"{q2:.4f} against {q1:.4f}, difference {100 * rel:+.2f} +- {100 * se:.2f} %")


def layer_study(sweep, s, ref, walls, period, gas_fraction, out):
    """The first layer in a sweep's runs at 0 and 90 degrees (information, README): against smooth walls
    alone it moves across the stripes at a smaller share of its speed along them than the continuum's
    b_perp / b_par and piles up downstream; with the fluid behind the walls it follows the continuum."""
    if 0.0 not in s["angle"] or 90.0 not in s["angle"]:
        return
    runs, force = {}, {}
    for a in (0.0, 90.0):
        k = s["angle"].index(a)
        grid = read_table(latest(f"{sweep}/{s['case'][k]}/postProcessing/profileBins/*/stripeGrid.dat"))
        runs[a] = first_layer(grid, walls, period, gas_fraction, ZC)
        force[a] = math.hypot(*[float(c) for c in s["bodyForce/value"][k].strip("()").split(",")])
    if None in runs.values():
        out.append(f"# L {period:g}: no first fluid layer (no density minimum within two cutoffs of the plane: nothing "
                   "packs against the wall, as in a fluid without conservative force)")
        return
    # Per unit force: in the continuum the mean slip velocity is b_eff times the wall's shear rate, the
    # same for both at the same force, so the ratio is b_perp / b_par.
    along, across = runs[0.0][0]["y"] / force[0.0], runs[90.0][0]["x"] / force[90.0]
    out.append(f"# L {period:g}, the first fluid layer (from the plane to {runs[0.0][2]:.2f}): its mean velocity per "
               f"unit force, along the stripes at theta 0 {along:.2f}, across them at theta 90 {across:.2f}: ratio "
               f"{across / along:.3f}, against the continuum's b_perp / b_par "
               f"{ref['slipPerpendicular'] / ref['slipParallel']:.3f}")
    out += [f"# L {period:g}, the first layer's areal density over the gas sectors, downstream half against "
            f"upstream half, theta {a:g}: {pm(*runs[a][1], sign='+')}" for a in (0.0, 90.0)]


def period_study(cal, sp, height, gas_fraction, checks, out, walls):
    """The same stripes at a larger period L (the same local slip and channel), along and across them."""
    period = float(sp["walls/lower/tunableSlip/stripes/period"][0])
    ref = reference(cal, gas_fraction, cal["gammaGasSlip"], cal["gammaGasSlipError"], height, period=period)
    out.append(f"# period L {period:g} (b/L {cal['gammaGasSlip'] / period:.3f}): b_par at theta 0, b_perp at theta 90 "
               "(reference)")
    rows = [sp["angle"].index(a) for a in (0.0, 90.0)]  # b_par from the run along the stripes, b_perp across
    slip_checks(checks, f"L {period:g}", sp, rows, ref, cal["halfWidthError"])
    out += [f"{name}  {pm(*run(sp, 'b' + key, k))} ({ref['slip' + key]:.4f})" for (key, name), k in zip(PAR_PERP, rows)]
    anisotropy(checks, f"b_par - b_perp at L {period:g} (the wall's position cancels)",
               *[run(sp, "b" + key, k) for (key, _), k in zip(PAR_PERP, rows)], ref, budget("b_par - b_perp, L 40"))
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
    for key, name in PAR_PERP:
        runs = np.isfinite(s["b" + key])
        mean, err = means[key] = inverse_variance_mean(s["b" + key][runs], s["b" + key + "Error"][runs])
        against(checks, f"{name} (angle sweep, weighted over {int(runs.sum())} runs)", mean, err, ref, "slip" + key,
                wall_error, budget("b, angle sweep"))
        out.append(f"# {name}: {pm(mean, err)} (runs; wall +- {wall_error:.4f}), reference {ref['slip' + key]:.4f}")
    anisotropy(checks, "b_par - b_perp (angle sweep; the wall's position cancels)", means["Parallel"],
               means["Perpendicular"], ref, budget("b_par - b_perp, angle sweep"))
    for k, a in enumerate(s["angle"]):
        ratio, err = run(s, "transverseFluxRatio", k)
        if a == 45.0:
            turns(checks, ratio, err, budget("the flow turns"))
        if a % 90 == 0:
            zero_flux(checks, a, ratio, err, budget("zero flux"))
        else:
            against(checks, f"transverse flux ratio at theta {a:g}", ratio, err, ref, "ratio", 0.0,
                    budget("flux ratio, angle sweep"), a)
    return ref


def tensor_rows(cal, s, checks, out, title, parameter, references):
    """Per run at 45 degrees: b_par, b_perp and the flux ratio against their references."""
    out.append(f"# {title}: {parameter}  b_par +- err (reference)  b_perp +- err (reference)  flux ratio +- err (reference)")
    for k, ref in enumerate(references):
        where = f"{parameter} {ref.label:g}"
        slip_checks(checks, where, s, (k, k), ref, cal["halfWidthError"])
        against(checks, f"transverse flux ratio at {where}", *run(s, "transverseFluxRatio", k), ref, "ratio", 0.0,
                budget("flux ratio, one run"), 45.0)
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
            planes = 2.0 * np.abs(np.array([float(p.strip("()").split(",")[2]) for p in s["walls/lower/point"]]))
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
        same_at_rest(checks, q, *layer["gas"][q], *layer["noSlip"][q], budget(f"at rest, {q}"))
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
    ax[0].errorbar(s["theta"], s["bEffective"], yerr=s["bEffectiveError"], fmt="o", label="DPD (slipTensor)")
    label(ax[0], f"effective slip: phi2 {gas_fraction:g}, b/L {cal['gammaGasSlip'] / period:g}, H/L {height / period:.2f}",
          "theta (degrees from the stripes)", "b_eff(theta)")
    curve = reference(cal, gas_fraction, cal["gammaGasSlip"], 0.0, height, range(0, 91, 5))["ratio"]
    ax[1].plot(list(curve), list(curve.values()), "k-", label="continuum reference")
    ax[1].errorbar(s["theta"], s["transverseFluxRatio"], yerr=s["transverseFluxRatioError"], fmt="o", label="DPD")
    ax[1].axhline(0, color="gray", ls=":")
    label(ax[1], "transverse flux, H = %.2f" % height, "theta (degrees)", "flux across the force / along it")
    for panel, key, xlabel in ((2, "phi2", "gas fraction phi2"), (3, "b", "local slip b of the gas sectors")):
        if key in studies:
            runs, refs = studies[key]
            x = [r.label for r in refs]
            for name, style, colour in (("Parallel", "o", "C0"), ("Perpendicular", "s", "C1")):
                ax[panel].errorbar(x, runs["b" + name], yerr=runs["b" + name + "Error"], fmt=style, color=colour,
                                   label=f"b_{name[:4].lower()} DPD")
                ax[panel].plot(x, [r["slip" + name] for r in refs], "-", color=colour, label=f"b_{name[:4].lower()} reference")
            label(ax[panel], f"theta 45: against {key}", xlabel, "slip length")
    if "H" in studies:
        runs, refs = studies["H"]
        ax[4].errorbar([r.label for r in refs], runs["transverseFluxRatio"], yerr=runs["transverseFluxRatioError"], fmt="o", label="DPD")
        ax[4].plot([r.label for r in refs], [r.at("ratio", 45.0) for r in refs], "k-", label="continuum reference")
        label(ax[4], "theta 45, L = b: the flux ratio against H", "H (between the hydrodynamic walls)", "transverse flux ratio")
    for q, style in (("density", "o-"), ("kT", "s-")):
        col = [np.average(grid[q][near & (grid["x"] == x)], weights=grid["count"][near & (grid["x"] == x)]) for x in np.unique(grid["x"])]
        ax[5].plot(np.unique(grid["x"]), np.asarray(col) / np.mean(col), style, label=f"{q} / its mean")
    ax[5].axvspan(0, gas_fraction * period, color="lightblue", alpha=0.4, label="gas sector")
    label(ax[5], "at rest, within zc of the walls", "x (across the stripes)")
    for a in ax:  # the default's studies fill three panels; -a25's every one
        if a.has_data():
            a.legend(fontsize=8)
        else:
            a.set_visible(False)
    save(fig, "stripedWall.png", dpi=100)


if __name__ == "__main__":
    sys.exit(main())
