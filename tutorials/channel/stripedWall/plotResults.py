#!/usr/bin/env python3
"""Striped-wall tutorial: the measured slip tensor against the project's continuum reference.

Reads the calibration (calibration/gammaL.dat: where the wall acts, each sector's gamma_L and the slip
it gives), the sweeps (slipTensor's results per run: sweepAngle/, and at full size sweepGasFraction/,
sweepLocalSlip/, sweepHeight/, sweepHalfForce/, sweepForce/, sweepPeriod/) and the fluid at rest over
the stripes (rest/); computes the reference with stripedSlip at the calibrated slips in the channel between the
hydrodynamic walls; writes results.dat and stripedWall.png and exits non-zero when a check fails (the
first fluid layer's speed and areal density at 0 and 90 degrees are written as information).
Every check (issue 45) first requires the standard error of its comparison within a budget (BUDGETS:
full size and test mode, each derived from measured errors), then holds the value to a fixed bound of
three budgets, never widened by the run's own error:
  - b_par and b_perp (mean of the walls, from the hydrodynamic wall) within 3 budgets of the
    reference: in the angle sweep the weighted mean of the runs that drive each, elsewhere per run
    (gas fraction, local slip, height); and b_par - b_perp of the angle sweep, which does not depend
    on where the wall acts;
  - the transverse flux ratio within 3 budgets of the reference at every angle between 0 and 90 and
    every channel height, and zero within 3 budgets at theta 0 and 90; at theta 45 the flow turns
    towards the stripes: the ratio above 3 budgets (at full size: the test's 800 time units cannot
    decide it, information there);
  - the flux linear in the force: at half the force, the flux per unit force along and across the
    stripes within 3 budgets (relative) of the flux at the standard force (twice the force is
    information: there inertia takes ~3 % of the flux, README);
  - at the period 40 (sweepPeriod/), b_par at theta 0, b_perp at theta 90 and b_par - b_perp against
    the reference at that period, as above;
  - at rest, the layer next to the walls (within zc) holds the same density and kT over the gas and
    the no-slip sectors, their difference within 3 budgets of zero.
The test mode decides every check its runs allow (the angle sweep at 0, 45 and 90 degrees and the fluid
at rest) with the test's budgets, but the turn at theta 45 (information).
The standard error of a comparison holds the run's, the wall position's (slip lengths) and the
calibration's (the reference recomputed at each sector's slip +- its error).
"""
import math
import os
import re
import subprocess
import sys

import numpy as np

from dpdfoam.checks import Checks, as_number, write_results
from dpdfoam.io import latest, read_dict, read_sweep, read_table, read_text, wall_planes
from dpdfoam.plots import label, plt, save
from dpdfoam.stats import inverse_variance_mean

TEST_MODE = "-test" in sys.argv[1:]
# The test's 800 time units cannot decide the turn at theta 45 (its budget's bound, 3 x 0.04, lies above
# the reference's 0.051): information there, every other check of the test's runs decided.
TEST_INFORMATION = ("the flow turns towards the stripes",)
# A value within BOUND budgets of its expectation (issue 45: the bound fixed by the budget).
BOUND = 3.0
# Standard-error budgets (issue 45), (full size, test mode): each check requires its comparison's
# standard error below the budget, then the value within BOUND budgets. Full size from the README's
# runs of 2026-11-27 (the wall's position adds 0.091 to every b, the calibration 0.090-0.102 to its
# reference, mostly the no-slip sectors' b0 +- 0.10); test from its run of 2026-11-28 (800 time units;
# its three-point calibration: wall +- 0.30, b0 +- 0.33). None: that study does not run in the test.
BUDGETS = {
    # full: run 0.021-0.029 (+) wall 0.091 (+) calibration 0.099 = 0.137; test: 0.096-0.116 (+) 0.304 (+) 0.33 = 0.46
    "b, angle sweep": (0.16, 0.55),
    # full: run 0.020-0.108 (+) wall 0.091 (+) calibration 0.090-0.102 = 0.135-0.173 (phi2, b, H and L 40)
    "b, one run": (0.19, None),
    # full: run 0.036 (+) calibration 0.005 = 0.036 (the wall cancels); test: 0.151 (+) 0.019 = 0.152
    "b_par - b_perp, angle sweep": (0.05, 0.2),
    # full: run 0.100 (+) calibration 0.033 = 0.105 (L 40)
    "b_par - b_perp, L 40": (0.13, None),
    # full: 0.007-0.011 at 22.5-67.5 degrees; test: 0.009 at 45, 0.018 and 0.036 at 90 and 0 (the 3400-unit
    # runs' 0.009-0.017 x sqrt(3000 / 600 sampled) = 0.02-0.038)
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
}


def budget(kind, test=None):
    """The standard-error budget of a kind of check in this mode (or in the one `test` names); NaN, a
    failed check, for a study the mode has no budget for."""
    value = BUDGETS[kind][1 if (TEST_MODE if test is None else test) else 0]
    return float("nan") if value is None else value


ZC = 1.0
PAR_PERP = (("Parallel", "b_par"), ("Perpendicular", "b_perp"))


def striped_slip(gas_fraction, slip, height, period, angles):
    """stripedSlip's continuum result: slipParallel, slipPerpendicular and the flux ratio per angle."""
    text = subprocess.run(["stripedSlip", "-period", f"{period:g}", "-gasFraction", f"{gas_fraction:g}",
                           "-slip", f"{slip:.8g}", "-height", f"{height:.8g}", "-walls", "2",
                           "-angles", ",".join(f"{a:g}" for a in angles)], check=True, capture_output=True, text=True).stdout
    d = {k: float(v) for k, v in re.findall(r"^(slipParallel|slipPerpendicular)\s+(\S+);", text, re.M)}
    d["ratio"] = {float(a): float(r) for a, r in re.findall(r"angle(\S+) \{ slip \S+; transverseFluxRatio (\S+); \}", text)}
    return d


class Reference:
    """The continuum reference for one wall (gas fraction, gas sectors' slip b with its calibration
    error) in a channel of height H, with the no-slip sectors' residual slip b0 +- e0: to first order in
    b0 / L such a wall is a no-slip / (b - b0) wall b0 behind it, so the channel is 2 b0 higher and
    b_eff b0 larger. `error(get)` is the calibration's share: half the spread of the reference at each
    sector's slip +- its error, the two in quadrature."""

    def __init__(self, cal, gas_fraction, slip, slip_error, height, angles=(45.0,), period=None, label=None):
        b0, e0 = cal["gammaNoSlipSlip"], cal["gammaNoSlipSlipError"]
        self.angles, self.label = list(angles), label
        period = period or cal["period"]

        def solve(b, residual):
            d = striped_slip(gas_fraction, b - residual, height + 2 * residual, period, self.angles)
            d["slipParallel"] += residual
            d["slipPerpendicular"] += residual
            return d

        self.value = solve(slip, b0)
        self.shifted = [solve(slip + slip_error, b0), solve(max(slip - slip_error, 1e-9), b0),
                        solve(slip, b0 + e0), solve(slip, b0 - e0)]

    def __getitem__(self, key):
        return self.value[key]

    def error(self, get):
        s = [get(r) for r in self.shifted]
        return math.hypot(0.5 * (s[0] - s[1]), 0.5 * (s[2] - s[3]))


def read_runs(path, offset):
    """slipTensor's table, with b_par and b_perp moved to the hydrodynamic wall (b = apparent + offset)."""
    s = read_sweep(path)
    for name in ("Parallel", "Perpendicular"):
        s["b" + name] = 0.5 * (s[f"slip{name}_0"] + s[f"slip{name}_1"]) + offset
        s["e" + name] = 0.5 * np.hypot(s[f"slip{name}Error_0"], s[f"slip{name}Error_1"])
    return s


def compare(checks, label, measured, run_error, expected, calibration_error, wall_error, limit):
    """A check: the comparison's standard error (the run's, the wall position's and the calibration's
    in quadrature) below the budget `limit`, then measured within BOUND budgets of expected."""
    m, r, x, c, w = (as_number(v) for v in (measured, run_error, expected, calibration_error, wall_error))
    total = math.sqrt(r ** 2 + w ** 2 + c ** 2)
    return checks.bounded(f"{label} within {BOUND:g} x {limit:g} of the reference {x:.4f} (standard error below {limit:g})",
                          m - x, total, limit, -BOUND * limit, BOUND * limit,
                          f"{m:+.4f} +- {total:.4f} (run {r:.4f}, wall {w:.4f}, calibration {c:.4f}), difference {m - x:+.4f}")


def zero_flux(checks, angle, ratio, error, limit):
    """No transverse flux where nothing breaks the symmetry (theta 0 and 90): within BOUND budgets of 0."""
    ratio = as_number(ratio)
    return checks.bounded(f"no transverse flux at theta {angle:g} (within {BOUND:g} x {limit:g}, standard error below "
                          f"{limit:g})", ratio, error, limit, -BOUND * limit, BOUND * limit, f"{ratio:+.5f}")


def turns(checks, ratio, error, limit):
    """The flow turns towards the stripes at theta 45: the ratio above BOUND budgets."""
    ratio = as_number(ratio)
    return checks.bounded(f"the flow turns towards the stripes at theta 45 (ratio above {BOUND:g} x {limit:g}, standard "
                          f"error below {limit:g})", ratio, error, limit, BOUND * limit, None, f"{ratio:+.5f}")


def linear(checks, name, q1, e1, q2, e2, limit):
    """The flux per unit force at g / 2 (q2) as at g (q1): their relative difference within BOUND
    budgets (relative) of 0."""
    q1, e1, q2, e2 = (as_number(v) for v in (q1, e1, q2, e2))
    rel = q2 / q1 - 1.0 if q1 else float("nan")
    se = math.hypot(e1, e2) / abs(q1) if q1 else float("nan")
    return checks.bounded(f"flux {name} linear in the force: per unit force at g / 2 as at g, within {100 * BOUND * limit:g} % "
                          f"(standard error below {100 * limit:g} %)", rel, se, limit, -BOUND * limit, BOUND * limit,
                          f"{q2:.4f} against {q1:.4f}, difference {100 * rel:+.2f} +- {100 * se:.2f} %")


def same_at_rest(checks, q, gas, gas_error, no_slip, no_slip_error, limit):
    """At rest, quantity q within zc of the walls the same over gas and no-slip sectors: their difference
    within BOUND budgets of 0."""
    g, ge, n, ne = (as_number(v) for v in (gas, gas_error, no_slip, no_slip_error))
    se = math.hypot(ge, ne)
    return checks.bounded(f"at rest, {q} within zc of the walls the same over gas and no-slip sectors (within "
                          f"{BOUND:g} x {limit:g}, standard error below {limit:g})", g - n, se, limit,
                          -BOUND * limit, BOUND * limit, f"{g:.4f} against {n:.4f}, difference {g - n:+.4f} +- {se:.4f}")


def rest_layer(path, walls, period, gas_fraction):
    """Count-weighted density and kT, with errors, of the bins within zc of a wall, over the gas sectors
    (the first phi2 L of each period from x = 0, the stripes' offset) and the no-slip ones."""
    t = read_table(path)
    near = np.minimum(t["z"] - walls[0], walls[1] - t["z"]) < ZC
    gas = np.mod(t["x"], period) < gas_fraction * period
    out = {}
    for name, sel in (("gas", near & gas), ("noSlip", near & ~gas)):
        w = t["count"][sel]
        out[name] = {q: (float(np.sum(w * t[q][sel]) / np.sum(w)),
                         float(np.sqrt(np.sum((w * t[q + "Err"][sel]) ** 2)) / np.sum(w))) for q in ("density", "kT")}
    return out, t, near


def first_layer(path, walls, period, gas_fraction):
    """The first fluid layer against each wall (from the plane to the first density minimum past the
    peak: packed by smooth walls, a gentle rise with the fluid behind them), from a run's stripeGrid: its
    mean velocity over the period (mass-weighted, both walls) across the stripes (x) and along them (y),
    its areal density over the downstream half of the gas sectors (downstream: in the direction of the
    flow across the stripes) against the upstream half, relative, with the error of bins taken as
    independent, and its depth. None without a minimum within two cutoffs of the plane."""
    t = read_table(path)
    d = np.minimum(t["z"] - walls[0], walls[1] - t["z"])
    depths = np.unique(np.round(d, 9))
    profile = np.array([np.mean(t["density"][np.isclose(d, v)]) for v in depths])
    peak = int(np.argmax(profile))
    minimum = peak + int(np.argmax(np.diff(profile[peak:]) > 0))  # the first bin where density rises again
    if depths[minimum] > 2.0 * ZC:
        return None  # no packed layer (a fluid without conservative force: its density is the bulk's)
    layer = d < depths[minimum] - 1e-9
    dz = depths[1] - depths[0]
    mass = t["density"][layer] * dz
    velocity = {axis: float(np.sum(mass * t["u" + axis][layer]) / np.sum(mass)) for axis in ("x", "y")}
    phase = np.mod(t["x"][layer], period) / (gas_fraction * period)  # 0..1 over a gas sector
    downstream = phase >= 0.5 if velocity["x"] >= 0.0 else phase < 0.5
    (down, de), (up, ue) = [(np.sum(mass[sel]), math.sqrt(np.sum((t["densityErr"][layer][sel] * dz) ** 2)))
                            for sel in (downstream & (phase < 1.0), ~downstream & (phase < 1.0))]
    return velocity, (down / up - 1.0, math.hypot(de / up, down * ue / up ** 2)), depths[minimum] - 0.5 * dz


def layer_study(sweep, s, ref, walls, period, gas_fraction, out):
    """The first layer in a sweep's runs at 0 and 90 degrees (information, README): against smooth walls
    alone it moves across the stripes at a smaller share of its speed along them than the continuum's
    b_perp / b_par and piles up downstream; with the fluid behind the walls it follows the continuum."""
    angles = [round(float(a), 2) for a in s["theta"]]
    if 0.0 not in angles or 90.0 not in angles:
        return
    runs, force = {}, {}
    for a in (0.0, 90.0):
        k = angles.index(a)
        runs[a] = first_layer(latest(f"{sweep}/{s['case'][k]}/postProcessing/profileBins/*/stripeGrid.dat"), walls,
                              period, gas_fraction)
        force[a] = math.hypot(*[float(c) for c in s["bodyForce/value"][k].strip("()").split(",")])
    if None in runs.values():
        return
    # Per unit force: in the continuum the mean slip velocity is b_eff times the wall's shear rate, the
    # same for both at the same force, so the ratio is b_perp / b_par.
    along, across = runs[0.0][0]["y"] / force[0.0], runs[90.0][0]["x"] / force[90.0]
    out.append(f"# L {period:g}, the first fluid layer (from the plane to {runs[0.0][2]:.2f}): its mean velocity per "
               f"unit force, along the stripes at theta 0 {along:.2f}, across them at theta 90 {across:.2f}: ratio "
               f"{across / along:.3f}, against the continuum's b_perp / b_par "
               f"{ref['slipPerpendicular'] / ref['slipParallel']:.3f}")
    out += [f"# L {period:g}, the first layer's areal density over the gas sectors, downstream half against "
            f"upstream half, theta {a:g}: {runs[a][1][0]:+.4f} +- {runs[a][1][1]:.4f}" for a in (0.0, 90.0)]


def anisotropy(checks, label, par, perp, ref, limit):
    """b_par - b_perp against the reference: it does not depend on where the wall acts."""
    compare(checks, label, par[0] - perp[0], math.hypot(par[1], perp[1]), ref["slipParallel"] - ref["slipPerpendicular"],
            ref.error(lambda r: r["slipParallel"] - r["slipPerpendicular"]), 0.0, limit)


def period_study(cal, sp, height, gas_fraction, checks, out, walls):
    """The same stripes at a larger period L (the same local slip and channel), along and across them."""
    period = float(sp["walls/lower/tunableSlip/stripes/period"][0])
    ref = Reference(cal, gas_fraction, cal["gammaGasSlip"], cal["gammaGasSlipError"], height, period=period)
    angles = [round(float(a), 2) for a in sp["theta"]]
    out.append(f"# period L {period:g} (b/L {cal['gammaGasSlip'] / period:.3f}): b_par at theta 0, b_perp at theta 90 "
               "(reference)")
    measured = {}
    for a, (key, name) in zip((0.0, 90.0), PAR_PERP):
        k = angles.index(a)
        measured[key] = (sp["b" + key][k], sp["e" + key][k])
        compare(checks, f"{name} at L {period:g}", *measured[key], ref["slip" + key],
                ref.error(lambda r, key=key: r["slip" + key]), cal["halfWidthError"], budget("b, one run"))
        out.append(f"{name}  {sp['b' + key][k]:.4f} +- {sp['e' + key][k]:.4f} ({ref['slip' + key]:.4f})")
    anisotropy(checks, f"b_par - b_perp at L {period:g} (the wall's position cancels)", measured["Parallel"],
               measured["Perpendicular"], ref, budget("b_par - b_perp, L 40"))
    layer_study("sweepPeriod", sp, ref, walls, period, gas_fraction, out)


def angle_study(cal, s, height, gas_fraction, checks, out):
    offset_err = cal["halfWidthError"]
    angles = [round(float(a), 2) for a in s["theta"]]  # the force's components were rounded to 8 digits
    ref = Reference(cal, gas_fraction, cal["gammaGasSlip"], cal["gammaGasSlipError"], height, angles)
    out.append("# theta  b_par +- err   b_perp +- err   b_eff(theta) +- err   nu_par nu_perp   flux along, across the "
               "stripes   transverse flux ratio +- err   reference b_eff, ratio")
    for k, a in enumerate(angles):
        c2, s2 = math.cos(math.radians(a)) ** 2, math.sin(math.radians(a)) ** 2
        out.append(f"{a:6g}  {s['bParallel'][k]:+.4f} +- {s['eParallel'][k]:.4f}  {s['bPerpendicular'][k]:+.4f} +- "
                   f"{s['ePerpendicular'][k]:.4f}  {s['slipEffective'][k] + cal['offset']:+.4f} +- "
                   f"{s['slipEffectiveError'][k]:.4f}  {s['nuParallel'][k]:.4f} {s['nuPerpendicular'][k]:.4f}  "
                   f"{s['fluxParallel'][k]:.4f} +- {s['fluxParallelError'][k]:.4f}  {s['fluxPerpendicular'][k]:.4f} +- "
                   f"{s['fluxPerpendicularError'][k]:.4f}  {s['transverseFluxRatio'][k]:+.5f} +- "
                   f"{s['transverseFluxRatioError'][k]:.5f}   "
                   f"{ref['slipParallel'] * c2 + ref['slipPerpendicular'] * s2:.4f} {ref['ratio'][a]:.5f}")
    means = {}
    for key, name in PAR_PERP:
        runs = np.isfinite(s["b" + key])
        mean, err = means[key] = inverse_variance_mean(s["b" + key][runs], s["e" + key][runs])
        compare(checks, f"{name} (angle sweep, weighted over {int(runs.sum())} runs)", mean, err, ref["slip" + key],
                ref.error(lambda r: r["slip" + key]), offset_err, budget("b, angle sweep"))
        out.append(f"# {name}: {mean:.4f} +- {err:.4f} (runs; wall +- {offset_err:.4f}), reference {ref['slip' + key]:.4f}")
    anisotropy(checks, "b_par - b_perp (angle sweep; the wall's position cancels)", means["Parallel"],
               means["Perpendicular"], ref, budget("b_par - b_perp, angle sweep"))
    for k, a in enumerate(angles):
        ratio, err = s["transverseFluxRatio"][k], s["transverseFluxRatioError"][k]
        if a == 45.0:
            turns(checks, ratio, err, budget("the flow turns"))
        if a % 90 == 0:
            zero_flux(checks, a, ratio, err, budget("zero flux"))
        else:
            compare(checks, f"transverse flux ratio at theta {a:g}", ratio, err, ref["ratio"][a],
                    ref.error(lambda r, a=a: r["ratio"][a]), 0.0, budget("flux ratio, angle sweep"))
    return ref


def tensor_rows(cal, s, checks, out, title, parameter, references):
    """Per run at 45 degrees: b_par, b_perp and the flux ratio against their references."""
    out.append(f"# {title}: {parameter}  b_par +- err (reference)  b_perp +- err (reference)  flux ratio +- err (reference)")
    for k, ref in enumerate(references):
        where = f"{parameter} {ref.label:g}"
        for key, name in PAR_PERP:
            compare(checks, f"{name} at {where}", s["b" + key][k], s["e" + key][k], ref["slip" + key],
                    ref.error(lambda r, key=key: r["slip" + key]), cal["halfWidthError"], budget("b, one run"))
        compare(checks, f"transverse flux ratio at {where}", s["transverseFluxRatio"][k], s["transverseFluxRatioError"][k],
                ref["ratio"][45.0], ref.error(lambda r: r["ratio"][45.0]), 0.0, budget("flux ratio, one run"))
        out.append(f"{ref.label:8g}  {s['bParallel'][k]:.4f} +- {s['eParallel'][k]:.4f} ({ref['slipParallel']:.4f})  "
                   f"{s['bPerpendicular'][k]:.4f} +- {s['ePerpendicular'][k]:.4f} ({ref['slipPerpendicular']:.4f})  "
                   f"{s['transverseFluxRatio'][k]:+.5f} +- {s['transverseFluxRatioError'][k]:.5f} ({ref['ratio'][45.0]:.5f})")


def force_study(s, k45, checks, out):
    """The flux per unit force at theta 45: at half the force (sweepHalfForce/) it must equal the
    standard force's, which is then on the linear (Stokes) branch; at twice the force (sweepForce/) it
    shows where that branch ends (information: inertia takes a part in g^2, README)."""
    for path, factor, what in (("sweepHalfForce/sweep.dat", 0.5, "half the force"), ("sweepForce/sweep.dat", 2.0, "twice the force")):
        if not os.path.exists(path):
            continue
        sf = read_runs(path, 0.0)
        out.append(f"# flux per unit force at theta 45: the standard force, {what}")
        for key, name in (("fluxParallel", "along the stripes"), ("fluxPerpendicular", "across them")):
            q1, e1 = s[key][k45], s[key + "Error"][k45]
            q2, e2 = sf[key][0] / factor, sf[key + "Error"][0] / factor
            se = math.hypot(e1, e2)
            out.append(f"{name}: {q1:.4f} +- {e1:.4f}, {q2:.4f} +- {e2:.4f} (difference {100 * (q2 / q1 - 1):+.1f} "
                       f"+- {100 * se / q1:.1f} %)")
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
        s = read_runs(f"{path}/sweep.dat", offset)
        if key == "phi2":
            refs = [Reference(cal, f, b, e, height, label=f) for f in s["walls/lower/tunableSlip/stripes/gasFraction"]]
        elif key == "b":
            refs = [Reference(cal, gas_fraction, bo, eo, height, label=bo) for bo, eo in zip(cal["slipTargets"], cal["gammaGasSlipErrorOf"])]
        else:
            planes = 2.0 * np.abs(np.array([float(p.strip("()").split(",")[2]) for p in s["walls/lower/point"]]))
            refs = [Reference(cal, gas_fraction, b, e, p - 2 * offset, label=p - 2 * offset) for p in planes]
        tensor_rows(cal, s, checks, out, title, key, refs)
        studies[key] = (s, refs)
    return studies


def main():
    cal = read_dict("calibration/gammaL.dat")
    period, offset = cal["period"], cal["offset"]
    walls = wall_planes()
    height = walls[1] - walls[0] - 2.0 * offset  # between the hydrodynamic walls
    gas_fraction = float(re.search(r"gasFraction\s+(\S+);", read_text("constant/dpdProperties")).group(1))
    checks = Checks()
    out = [f"# Striped walls, period L = {period:g}, phi2 {gas_fraction:g}, local slip b = {cal['gammaGasSlip']:g} "
           f"(b/L {cal['gammaGasSlip'] / period:g}), two walls in phase, H = {height:.3f} between the hydrodynamic walls",
           f"# calibration: gamma_L no slip {cal['gammaNoSlip']:.4f} (b0 {cal['gammaNoSlipSlip']:.4f} +- "
           f"{cal['gammaNoSlipSlipError']:.4f}), gas {cal['gammaGas']:.4f} (b {cal['gammaGasSlip']:.4f} +- "
           f"{cal['gammaGasSlipError']:.4f}); the wall acts {offset:.4f} +- {cal['halfWidthError']:.4f} in front of "
           "each plane"]
    s = read_runs("sweepAngle/sweep.dat", offset)
    ref = angle_study(cal, s, height, gas_fraction, checks, out)
    layer_study("sweepAngle", s, ref, walls, period, gas_fraction, out)
    studies = sweep_studies(cal, gas_fraction, height, checks, out)
    force_study(s, int(np.argmin(np.abs(s["theta"] - 45.0))), checks, out)
    if os.path.exists("sweepPeriod/sweep.dat"):
        period_study(cal, read_runs("sweepPeriod/sweep.dat", offset), height, gas_fraction, checks, out, walls)

    layer, grid, near = rest_layer(latest("rest/postProcessing/profileBins/*/stripeGrid.dat"), walls, period, gas_fraction)
    out += [f"# at rest, within zc of the walls over the {where} sectors: density {layer[where]['density'][0]:.4f} +- "
            f"{layer[where]['density'][1]:.4f}, kT {layer[where]['kT'][0]:.4f} +- {layer[where]['kT'][1]:.4f}"
            for where in ("gas", "noSlip")]
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
    period, offset = cal["period"], cal["offset"]
    fig, ax = plt.subplots(2, 3, figsize=(16, 9))
    ax = ax.ravel()
    fine = np.linspace(0, 90, 91)
    ax[0].plot(fine, ref["slipParallel"] * np.cos(np.radians(fine)) ** 2 + ref["slipPerpendicular"] * np.sin(np.radians(fine)) ** 2,
               "k-", label="continuum reference")
    ax[0].errorbar(s["theta"], s["slipEffective"] + offset, yerr=s["slipEffectiveError"], fmt="o", label="DPD (slipTensor)")
    label(ax[0], f"effective slip: phi2 {gas_fraction:g}, b/L {cal['gammaGasSlip'] / period:g}, H/L {height / period:.2f}",
          "theta (degrees from the stripes)", "b_eff(theta)")
    curve = Reference(cal, gas_fraction, cal["gammaGasSlip"], 0.0, height, range(0, 91, 5))["ratio"]
    ax[1].plot(list(curve), list(curve.values()), "k-", label="continuum reference")
    ax[1].errorbar(s["theta"], s["transverseFluxRatio"], yerr=s["transverseFluxRatioError"], fmt="o", label="DPD")
    ax[1].axhline(0, color="gray", ls=":")
    label(ax[1], "transverse flux, H = %.2f" % height, "theta (degrees)", "flux across the force / along it")
    for panel, key, xlabel in ((2, "phi2", "gas fraction phi2"), (3, "b", "local slip b of the gas sectors")):
        if key in studies:
            runs, refs = studies[key]
            x = [r.label for r in refs]
            for name, style, colour in (("Parallel", "o", "C0"), ("Perpendicular", "s", "C1")):
                ax[panel].errorbar(x, runs["b" + name], yerr=runs["e" + name], fmt=style, color=colour, label=f"b_{name[:4].lower()} DPD")
                ax[panel].plot(x, [r["slip" + name] for r in refs], "-", color=colour, label=f"b_{name[:4].lower()} reference")
            label(ax[panel], f"theta 45: against {key}", xlabel, "slip length")
    if "H" in studies:
        runs, refs = studies["H"]
        ax[4].errorbar([r.label for r in refs], runs["transverseFluxRatio"], yerr=runs["transverseFluxRatioError"], fmt="o", label="DPD")
        ax[4].plot([r.label for r in refs], [r["ratio"][45.0] for r in refs], "k-", label="continuum reference")
        label(ax[4], "theta 45, L = b: the flux ratio against H", "H (between the hydrodynamic walls)", "transverse flux ratio")
    for q, style in (("density", "o-"), ("kT", "s-")):
        col = [np.average(grid[q][near & (grid["x"] == x)], weights=grid["count"][near & (grid["x"] == x)]) for x in np.unique(grid["x"])]
        ax[5].plot(np.unique(grid["x"]), np.asarray(col) / np.mean(col), style, label=f"{q} / its mean")
    ax[5].axvspan(0, gas_fraction * period, color="lightblue", alpha=0.4, label="gas sector")
    label(ax[5], "at rest, within zc of the walls", "x (across the stripes)")
    for a in ax:
        if a.has_data():
            a.legend(fontsize=8)
    save(fig, "stripedWall.png", dpi=100)


if __name__ == "__main__":
    sys.exit(main())
