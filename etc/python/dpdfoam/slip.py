"""Tunable-slip and striped walls: a slip calibration read backwards (the gamma_L for a slip length),
calibrateWall's runs and the no-slip friction they give, slipTensor's runs with the two walls' mean slips,
stripedSlip's continuum reference of a striped wall and the checks against it, and a stripeGrid's fluid
layers over the stripes' sectors (docs/walls.md 3.5-3.7)."""
import math
import re
import subprocess
import sys

import numpy as np

from .channel import walls_mean_slip
from .checks import as_number
from .io import latest, latest_fit, parse_dict, read_dict, read_sweep, read_table, read_text, sweep_vector


def calibrated_walls(path, slips):
    """The walls a slip calibration gives the asked slip lengths, as dpdFoamLike's walls asking them
    take them (the slipCalibration tool, docs/walls.md 3.8): the calibration's range (smallestSlip,
    largestSlip, wallOffset) and per asked b a dict gammaL, slipLengthError (the calibration's error of
    b there), planeOffset and slipLeft (b itself within the range; below it the stiffest friction's
    slip); None for a b outside 0 .. largestSlip."""
    def tool(*asked):
        run = subprocess.run(["slipCalibration", "-file", path, *asked], capture_output=True, text=True)
        if run.returncode != 0:
            sys.exit(f"slipCalibration -file {path} {' '.join(asked)}: {run.stderr.strip()}")
        return parse_dict(run.stdout)
    summary = tool()
    inside = [b for b in slips if 0.0 <= b <= summary["largestSlip"]]
    asked = tool("-slipLength", *(f"{b:.17g}" for b in inside)) if inside else {}
    keys = ("gammaL", "slipLengthError", "planeOffset", "slipLeft")
    walls = {b: {k: asked[k][i] for k in keys} for i, b in enumerate(inside)}
    return summary, [walls.get(b) for b in slips]


def bracketed_frictions(path, slips):
    """Per asked slip length the calibration's (gammaL, error of b there) where it brackets b (calibrated_walls:
    smallestSlip <= b <= largestSlip; below, the stiffest friction leaves its own slip), else None."""
    summary, walls = calibrated_walls(path, slips)
    return [(w["gammaL"], w["slipLengthError"]) if w and b >= summary["smallestSlip"] else None
            for b, w in zip(slips, walls)]


def read_calibration_runs(directory):
    """calibrateWall's runs in directory: hydrodynamicWall.dat's entries (lists as arrays) and the sweep's gamma_L."""
    fit = read_dict(f"{directory}/hydrodynamicWall.dat")
    fit = {k: np.asarray(v) if isinstance(v, list) else v for k, v in fit.items()}
    sweep = read_sweep(f"{directory}/sweepPoiseuille/sweep.dat")
    return fit, np.asarray(sweep["walls/lower/tunableSlip/gammaL"], dtype=float)


def calibration_lines(gammas, fit):
    """hydrodynamicWall's fit as lines: per gamma_L (in order) b from the hydrodynamic wall and the planes'
    apparent slips."""
    b, err = fit["slipLength"], fit["slipLengthError"]
    return (["# gamma_L  b (from the hydrodynamic wall) +- err   apparent Couette / Poiseuille (from the planes)"]
            + [f"{gammas[k]:7g}  {b[k]:+.4f} +- {err[k]:.4f}   {fit['apparentSlipCouette'][k]:+.4f} / "
               f"{fit['apparentSlipPoiseuille'][k]:+.4f}" for k in np.argsort(gammas)]
            + [f"# chi2 per degree of freedom of the wall's fit: {fit['chi2PerDof']:.3f} ({fit['dof']:g} dof)"])


def slip_not_rising_checks(checks, gammas, b, err, end_budget, bound=3.0):
    """From each gamma_L to the next stiffer one the slip length must not rise decisively: the step
    b(softer) - b(stiffer) no lower than -bound budgets, its standard error below one (end_budget(b) of
    both ends in quadrature). A sweep of fewer than two gamma_L fails."""
    gammas, b, err = (np.asarray(v, dtype=float) for v in (gammas, b, err))
    order = np.argsort(gammas)
    if len(order) < 2:
        checks.fail(f"the calibration sweeps at least two gamma_L ({len(order)} here)")
    for lo, hi in zip(order[:-1], order[1:]):
        step, se = b[lo] - b[hi], math.hypot(err[lo], err[hi])
        budget = math.hypot(end_budget(b[lo]), end_budget(b[hi]))
        checks.bounded(f"slip length not decisively larger at gamma_L {gammas[hi]:g} than at {gammas[lo]:g} (standard "
                       f"error below {budget:.3g})", step, se, budget, -bound * budget, None)


def stiff_end(gammas, b, err):
    """The calibration's stiffest gamma_L (its index) and its last step: b at the next softer gamma_L less b there, and
    its standard error."""
    order = np.argsort(gammas)
    stiff, before = order[-1], order[-2]
    return stiff, b[before] - b[stiff], math.hypot(err[before], err[stiff])


def no_slip_friction(bracketed, gammas, b, err, z=3.0):
    """The no-slip wall's (gamma_L, b, error of b): where the calibration brackets b = 0 (bracketed: its gamma_L
    and error), that; where the friction saturates first (the last step below z standard errors), the stiffest
    gamma_L with the slip it leaves; else None."""
    if bracketed:
        return bracketed[0], 0.0, bracketed[1]
    stiff, step, se = stiff_end(gammas, b, err)
    return (gammas[stiff], b[stiff], err[stiff]) if step < z * se else None


def slip_choices(case="."):
    """What dpdFoamLike's log says each wall asking `slipLength b;` was given (docs/walls.md 3.8): per
    wall (gammaL, the calibration's b error there, how far behind where it was put the wall acts, its
    error)."""
    pattern = (r"Slip length\s*: wall \w+: slipLength \S+ from \S+: gammaL (\S+) \(b \+- (\S+) there\), "
               r"acting (\S+) \+- (\S+) behind")
    return [tuple(float(v) for v in m) for m in re.findall(pattern, read_text(f"{case}/log.dpdFoamLike"))]


def asked_slip_measured(case="."):
    """A channel whose walls ask for a slip length: the walls' mean b from its latest fit, the run's
    error, the calibration's error at that b (shared by the walls, it adds to their mean whole, and it
    carries where the calibration places the wall: docs/analysis.md 5.3), and slip_choices."""
    fit = latest_fit(case)
    b, e = fit.get("slipLength", [math.nan] * 2), fit.get("slipLengthError", [math.nan] * 2)
    walls = slip_choices(case)
    return 0.5 * (b[0] + b[1]), 0.5 * math.hypot(*e), walls[0][1] if walls else math.nan, walls


def read_slip_tensor(path, offset=0.0):
    """runSweep's table of slipTensor's runs, with the two walls' mean slips moved by offset (from the
    planes to where the wall acts, b = apparent + offset): bParallel, bPerpendicular, bEffective, each
    with its <name>Error; "angle": theta to 0.01 degree (the force's components were written to 8 digits)."""
    s = read_sweep(path)
    for name in ("Parallel", "Perpendicular"):
        b, s["b" + name + "Error"] = walls_mean_slip(s, "slip" + name)
        s["b" + name] = b + offset
    s["bEffective"], s["bEffectiveError"] = s["slipEffective"] + offset, s["slipEffectiveError"]
    s["angle"] = [round(float(a), 2) for a in s["theta"]]
    return s


# slipTensor's two principal slip lengths: the stem of their columns (b<stem>, slip<stem>) and their name.
PRINCIPAL_SLIPS = (("Parallel", "b_par"), ("Perpendicular", "b_perp"))


def run_value(table, key, k):
    """Run k's value of a sweep table's column and its <column>Error."""
    return table[key][k], table[key + "Error"][k]


def run_force(table, k):
    """The size of run k's body force (a sweep table's bodyForce/value)."""
    return math.hypot(*sweep_vector(table["bodyForce/value"][k]))


def striped_slip(gas_fraction, slip, height, period, angles):
    """stripedSlip's continuum result for two walls in phase: slipParallel, slipPerpendicular and
    "ratio", the transverse flux ratio per angle."""
    text = subprocess.run(["stripedSlip", "-period", f"{period:g}", "-gasFraction", f"{gas_fraction:g}",
                           "-slip", f"{slip:.8g}", "-height", f"{height:.8g}", "-walls", "2",
                           "-angles", ",".join(f"{a:g}" for a in angles)], check=True, capture_output=True, text=True).stdout
    d = {k: float(v) for k, v in re.findall(r"^(slipParallel|slipPerpendicular)\s+(\S+);", text, re.M)}
    d["ratio"] = {float(a): float(r) for a, r in re.findall(r"angle(\S+) \{ slip \S+; transverseFluxRatio (\S+); \}", text)}
    return d


class StripedReference:
    """The continuum reference for a striped wall (gas fraction, the gas sectors' slip b with its
    calibration error, period) in a channel of height H, with the no-slip sectors' residual slip
    (b0, e0): to first order in b0 / L such a wall is a no-slip / (b - b0) wall b0 behind it, so the
    channel is 2 b0 higher and b_eff b0 larger. Entries: slipParallel, slipPerpendicular, anisotropy
    (their difference, which does not depend on where the wall acts) and ratio {angle: flux ratio}.
    error(key) is the calibration's share: half the spread of the reference at each sector's slip +- its
    error, the two in quadrature."""

    def __init__(self, gas_fraction, slip, slip_error, height, period, residual, angles=(45.0,), label=None):
        b0, e0 = residual
        self.angles, self.label = list(angles), label

        def solve(b, residual):
            d = striped_slip(gas_fraction, b - residual, height + 2 * residual, period, self.angles)
            d["slipParallel"] += residual
            d["slipPerpendicular"] += residual
            d["anisotropy"] = d["slipParallel"] - d["slipPerpendicular"]
            return d

        self.value = solve(slip, b0)
        self.shifted = [solve(slip + slip_error, b0), solve(max(slip - slip_error, 1e-9), b0),
                        solve(slip, b0 + e0), solve(slip, b0 - e0)]

    def __getitem__(self, key):
        return self.value[key]

    @staticmethod
    def _entry(d, key, angle):
        return d[key] if angle is None else d[key][angle]

    def at(self, key, angle=None):
        """An entry; the ratio's at an angle."""
        return self._entry(self.value, key, angle)

    def error(self, key, angle=None):
        s = [self._entry(r, key, angle) for r in self.shifted]
        return math.hypot(0.5 * (s[0] - s[1]), 0.5 * (s[2] - s[3]))

    def effective(self, theta):
        """b_eff = b_par cos^2 theta + b_perp sin^2 theta (theta in degrees from the stripes)."""
        rad = np.radians(theta)
        return self["slipParallel"] * np.cos(rad) ** 2 + self["slipPerpendicular"] * np.sin(rad) ** 2


def reference_check(checks, name, measured, run_error, ref, key, wall_error, budget, angle=None, bound=3.0):
    """measured against a StripedReference's key (at angle): the comparison's standard error (the run's, the wall
    position's and the calibration's in quadrature) below the budget, then within bound budgets."""
    m, r, w = (as_number(v) for v in (measured, run_error, wall_error))
    x, c = as_number(ref.at(key, angle)), as_number(ref.error(key, angle))
    total = math.sqrt(r ** 2 + w ** 2 + c ** 2)
    return checks.within_budgets(f"{name} within {bound:g} x {budget:g} of the reference {x:.4f} (standard error below "
                                 f"{budget:g})", m - x, total, budget, f"{m:+.4f} +- {total:.4f} (run {r:.4f}, wall "
                                 f"{w:.4f}, calibration {c:.4f}), difference {m - x:+.4f}", -bound, bound)


def principal_slip_checks(checks, where, table, rows, ref, wall_error, budget, bound=3.0):
    """b_par and b_perp of single runs of a slipTensor table (rows: the run of each) against the reference."""
    for (key, name), k in zip(PRINCIPAL_SLIPS, rows):
        reference_check(checks, f"{name} at {where}", *run_value(table, "b" + key, k), ref, "slip" + key, wall_error,
                        budget, bound=bound)


def anisotropy_check(checks, name, par, perp, ref, budget, bound=3.0):
    """b_par - b_perp ((value, error) each) against the reference: it does not depend on where the wall acts."""
    return reference_check(checks, name, par[0] - perp[0], math.hypot(par[1], perp[1]), ref, "anisotropy", 0.0, budget,
                           bound=bound)


def zero_flux_check(checks, angle, ratio, error, budget, bound=3.0):
    """No transverse flux where nothing breaks the symmetry (theta 0 and 90): the ratio within bound budgets of 0."""
    ratio = as_number(ratio)
    return checks.near_zero(f"no transverse flux at theta {angle:g}", ratio, error, budget, f"{ratio:+.5f}", bound)


def turn_check(checks, ratio, error, budget, bound=3.0):
    """The flow turns towards the stripes at theta 45: the transverse flux ratio above bound budgets."""
    ratio = as_number(ratio)
    return checks.within_budgets(f"the flow turns towards the stripes at theta 45 (ratio above {bound:g} x {budget:g}, "
                                 f"standard error below {budget:g})", ratio, error, budget, f"{ratio:+.5f}", bound,
                                 None)


def same_at_rest_check(checks, q, gas, gas_error, no_slip, no_slip_error, budget, bound=3.0):
    """At rest, q within zc of the walls the same over gas and no-slip sectors: the difference within bound budgets."""
    g, ge, n, ne = (as_number(v) for v in (gas, gas_error, no_slip, no_slip_error))
    se = math.hypot(ge, ne)
    return checks.near_zero(f"at rest, {q} within zc of the walls the same over gas and no-slip sectors", g - n, se,
                            budget, f"{g:.4f} against {n:.4f}, difference {g - n:+.4f} +- {se:.4f}", bound)


def distance_to_walls(table, walls):
    return np.minimum(table["z"] - walls[0], walls[1] - table["z"])


def gas_sectors(x, period, gas_fraction):
    """Whether x lies over a gas sector: the first gas_fraction x period of each period from x = 0 (the
    stripes' offset)."""
    return np.mod(x, period) < gas_fraction * period


def near_wall_sectors(table, walls, period, gas_fraction, depth):
    """Count-weighted density and kT, with errors, of a stripeGrid's bins within depth of a wall over the
    gas sectors and over the no-slip ones: {"gas" | "noSlip": {"density" | "kT": (mean, error)}}, and
    the mask of the bins within depth."""
    near = distance_to_walls(table, walls) < depth
    gas = gas_sectors(table["x"], period, gas_fraction)
    out = {}
    for name, sel in (("gas", near & gas), ("noSlip", near & ~gas)):
        w = table["count"][sel]
        out[name] = {q: (float(np.sum(w * table[q][sel]) / np.sum(w)),
                         float(np.sqrt(np.sum((w * table[q + "Err"][sel]) ** 2)) / np.sum(w))) for q in ("density", "kT")}
    return out, near


def first_layer(table, walls, period, gas_fraction, cutoff):
    """The first fluid layer against each wall (from the plane to the first density minimum past the
    peak: packed by smooth walls, a gentle rise with the fluid behind them), from a run's stripeGrid: its
    mean velocity over the period (mass-weighted, both walls) across the stripes (x) and along them (y),
    its areal density over the downstream half of the gas sectors (downstream: in the direction of the
    flow across the stripes) against the upstream half, relative, with the error of bins taken as
    independent, and its depth. None without a minimum within two cutoffs of the plane."""
    t = table
    d = distance_to_walls(t, walls)
    depths = np.unique(np.round(d, 9))
    profile = np.array([np.mean(t["density"][np.isclose(d, v)]) for v in depths])
    peak = int(np.argmax(profile))
    rises = np.flatnonzero(np.diff(profile[peak:]) > 0)
    if not len(rises):
        return None  # no minimum past the peak (the densest depth the last: a density rising to the bulk)
    minimum = peak + int(rises[0])  # the first bin where density rises again
    if depths[minimum] > 2.0 * cutoff:
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


def first_layers(sweep, table, angles, walls, period, gas_fraction, cutoff):
    """first_layer of a slipTensor sweep's runs (in directory sweep) at angles, each with its force's size:
    {angle: (layer, force)}."""
    layers = {}
    for a in angles:
        k = table["angle"].index(a)
        grid = read_table(latest(f"{sweep}/{table['case'][k]}/postProcessing/profileBins/*/stripeGrid.dat"))
        layers[a] = (first_layer(grid, walls, period, gas_fraction, cutoff), run_force(table, k))
    return layers
