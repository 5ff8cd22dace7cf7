#!/usr/bin/env python3
"""Speed-accuracy tutorial: picture, results table and checks.

Reads postProcessing/integratorSpeedAccuracy/speedAccuracy.dat (one row per integrator and step) and
draws, one curve per integrator, |error| against the cost of one time unit for the kinetic
temperature, the pressure and the viscosity (the last two against the reference run of the table's
header: the reference integrator at a step smaller than any studied, so no run is its own reference),
and the stability map (the step at which each integrator's kT error passes 1 % and 5 %, by linear
interpolation between the measured steps, and the first step at which the run's monitor stopped it).
Writes results.dat and exits non-zero when a check fails.

results.dat also gives
  - the recommended step per integrator: the largest measured step below which the kT error stays
    within 1 % (|error| <= 1 % at it and at every smaller measured step);
  - the speed-up at equal accuracy against Groot-Warren (lambda 0.65) at dt 0.02. "Equal accuracy":
    a step of a method qualifies when each of its kT, pressure and viscosity errors is no larger than
    Groot-Warren's at 0.02 within error bars, |e| <= |e_GW| + 2 sqrt(se^2 + se_GW^2) (two combined
    standard errors); the method's equal-accuracy step is the largest step up to which every measured
    step qualifies. Speed-up = cost(GW at 0.02) / cost(method at that step), cost being seconds per
    particle per time unit.

Cost is CPU time (all threads) per particle per time unit: each integrator's median cost per
particle-step over its stable runs, over dt (dpdfoam.stepstudy.apply_cost_model); the per-run costs stay
in the table, results.dat gives the medians and their spread.
"""
import sys

from dpdfoam.checks import Checks
from dpdfoam.io import write_whole
from dpdfoam.plots import label as label_axes, plt, save
from dpdfoam.stepstudy import (apply_cost_model, as_accurate, crossing, draw_errors_against_cost, draw_stability_map,
                               first_unstable, largest_step, measured)

TABLE = "postProcessing/integratorSpeedAccuracy/speedAccuracy.dat"
BASELINE = ("GrootWarren0.65", 0.02)  # the method and step the speed-up is measured against
QUANTITIES = (("kT", "kT"), ("P", "pressure"), ("nu", "viscosity"))
# The table's columns after the integrator, as named here: the errors of kT, of the pressure (P) and of
# the viscosity (nu), each relative, with its standard error (<name>se); nu and P against the reference.
COLUMNS = "dt kT kTse pressure pressureSe P Pse viscosity viscositySe nu nuse cost unstable after".split()
ERROR_LEVELS = ((0.01, "tab:green"), (0.05, "tab:orange"))  # 1 % and 5 %: the lines, the stability map's kT


def read_rows(path):
    """The rows by integrator, each sorted by step, and the reference run: (label, dt, pressure, its SE,
    nu, its SE)."""
    rows, reference = {}, None
    with open(path) as f:
        for line in f:
            if line.startswith("# reference run:"):
                w = line.split(":", 1)[1].split()
                reference = (w[0], float(w[2]), float(w[4]), float(w[5]), float(w[7]), float(w[8]))
            if line.startswith("#") or not line.strip():
                continue
            fields = line.split()
            p = dict(zip(COLUMNS, (float(x) for x in fields[1:])))
            p["unstable"] = int(p["unstable"]) == 1
            rows.setdefault(fields[0], []).append(p)
    for points in rows.values():
        points.sort(key=lambda r: r["dt"])
    return rows, reference


def reference_name(reference):
    """What the pressure and the viscosity errors are taken against."""
    return "%s at dt %g (reference run)" % reference[:2] if reference else "the reference run"


def draw_errors(ax, rows, q, name, against):
    draw_errors_against_cost(ax, rows, q, ERROR_LEVELS)
    label_axes(ax, None, "cost: CPU seconds per particle per time unit (median step cost / dt)",
               "|%s error| (%%)  (labels: dt)" % name, legend=7)
    ax.set_title("%s error against cost (against %s)" % (name, against), fontsize=10)


def draw_stability(ax, rows):
    draw_stability_map(ax, rows, "kT", ERROR_LEVELS)
    ax.set_title("stability map: | measured, o kT error 1 % (green) and 5 % (orange), x blow-up", fontsize=9)


def plot(rows, reference):
    fig, axes = plt.subplots(2, 2, figsize=(13, 10))
    for ax, (q, name) in zip(axes.flat[:3], QUANTITIES):
        draw_errors(ax, rows, q, name, "set kT" if q == "kT" else reference_name(reference))
    draw_stability(axes.flat[3], rows)
    save(fig, "speedAccuracy.png", dpi=120)


def fmt(x):
    return "-" if x is None else "%g" % x


def cost_lines(costs, reference):
    lines = ["# Cost per particle-step (CPU seconds; median, lowest and highest over the stable runs; the",
             "# cost of one time unit at dt is the median over dt)",
             "# integrator median lowest highest"]
    lines += ["%-16s %-10.3g %-10.3g %.3g" % (label, median, low, high) for label, (median, low, high) in costs.items()]
    if reference:
        lines += ["#", "# Reference run: %s at dt %g (smaller than every studied step): pressure %.4f +- %.4f, nu %.4f +- %.4f"
                  % reference]
    return lines


def stability_lines(rows):
    lines = ["#", "# Stability map and recommended step (kT error; crossings interpolated between measured steps,",
             "# '-' when not reached; recommended: largest measured step with |kT error| <= 1 % up to it)",
             "# integrator dt1percent dt5percent dtBlowUp recommendedDt1percent"]
    for label, points in rows.items():
        c1, c5, u = crossing(points, "kT", 0.01), crossing(points, "kT", 0.05), first_unstable(points)
        r = largest_step(points, lambda p: not (p["unstable"] or abs(p["kT"]) > 0.01))  # the recommended step
        lines.append("%-16s %-10s %-10s %-8s %s" % (label, c1 or "-", c5 or "-", fmt(u), fmt(r and r["dt"])))
    return lines


def speed_up_lines(rows, reference):
    label, dt = BASELINE
    base = next((p for p in rows.get(label, []) if abs(p["dt"] - dt) < 1e-12), None)
    if base is None or base["unstable"]:
        return ["# no speed-up: %s at dt %g was not measured (or not stable)" % BASELINE]
    quantities = [q for q, _ in QUANTITIES if measured(base, q)]
    lines = ["#",
             "# Equal accuracy against %s at dt %g (errors: kT %.3g +- %.3g, pressure %.3g +- %.3g, viscosity %.3g +- %.3g;"
             % (label, dt, base["kT"], base["kTse"], base["P"], base["Pse"], base["nu"], base["nuse"]),
             "# pressure and viscosity against %s): a step qualifies when each of its %s errors is at most" % (
                 reference_name(reference), ", ".join(quantities)),
             "# GW's + 2 combined SE; the equal-accuracy step is the largest one up to which every step qualifies.",
             "# speedUp = cost(GW at %g) / cost(method at its equal-accuracy step)." % dt,
             "# integrator equalAccuracyDt secondsPerParticleTimeUnit speedUp"]
    best = None
    for name, points in rows.items():
        p = largest_step(points, lambda p: as_accurate(p, base, quantities))
        if p is None:
            lines.append("%-16s -" % name)
            continue
        speed_up = base["cost"] / p["cost"]
        lines.append("%-16s %-8g %-10.3g %.2f" % (name, p["dt"], p["cost"], speed_up))
        if best is None or speed_up > best[1]:
            best = (name, speed_up, p["dt"])
    if best:
        lines.append("# best: %s at dt %g simulates one time unit %.2f times faster than %s at dt %g"
                     % (best[0], best[2], best[1], label, dt))
    return lines


# Standard-error budgets of the checked runs (the smallest studied step of each Verlet-type scheme) and
# the fixed bounds derived from them. A run noisier than its budget fails: it cannot decide. Errors of
# pressure and nu are relative to the reference run and include its error (it samples 4 x longer).
# Measured (2026-11-24): full study (dt 0.005; kT and pressure over 100 time units, nu over 150 from
# the fit block by block): kT 0.0020-0.0051, pressure 0.00044-0.00074, nu 0.043-0.056; test mode
# (dt 0.01; 40 and 60 time units): kT 0.0035-0.0046, pressure 0.0006-0.0007, nu 0.054-0.10.
# Budgets about 1.5 x the largest measured. Bounds, fixed: kT within 3 % (at dt <= 0.02 every
# Verlet-type scheme's kT error is below 1 %, Groot-Warren 0.5's reaching it at 0.019-0.023: 1 % plus
# three test budgets), pressure within 0.5 % (measured within 0.1 % up to dt 0.05: seven budgets),
# viscosity within 10 % plus 4 budgets (0.44, test 0.70): a coarse check, named so, that catches only
# gross errors (a factor two, a unit slip): one run's nu is known to ~5 % at best here.
BUDGETS = {False: {"kT": 0.008, "P": 0.0011, "nu": 0.085}, True: {"kT": 0.007, "P": 0.0011, "nu": 0.15}}
BOUNDS = {test: {"kT": 0.03, "P": 0.005, "nu": 0.10 + 4 * BUDGETS[test]["nu"]} for test in (False, True)}
NAMES = {"kT": "kT", "P": "P", "nu": "nu (coarse)"}


def checks(rows, reference, test_mode):
    """Every Verlet-type scheme at its smallest studied step (at most 0.02): each standard error within
    its budget, then kT within 3 % of the set kT, pressure within 0.5 % and viscosity within 10 % plus
    4 budgets of the reference run (BOUNDS, fixed); the largest step stops every scheme when it
    is 0.15 or more (measured blow-up 0.12-0.13). Each check is named by what its failure means; a NaN
    fails it (dpdfoam.checks)."""
    out = Checks()
    budgets, bounds = BUDGETS[test_mode], BOUNDS[test_mode]
    out.add("no reference run in the table", reference is not None, "", *(reference[2:3] if reference else ()))
    for label, points in rows.items():
        first, last = points[0], points[-1]
        if label != "Euler" and first["dt"] <= 0.02:
            if not out.add("%s: unstable at dt %g" % (label, first["dt"]), not first["unstable"]):
                continue
            # Every quantity is measured at these steps: a missing (NaN) one fails below.
            for q in ("kT", "P", "nu"):
                se, bound, name = first[q + "se"], bounds[q], NAMES[q]
                if out.add("%s: %s standard error %.3g over its budget %.3g at dt %g" % (label, name, se, budgets[q], first["dt"]),
                           se <= budgets[q]):
                    out.add("%s: %s error %.3g +- %.3g beyond %.3g at dt %g" % (label, name, first[q], se, bound, first["dt"]),
                            abs(first[q]) <= bound)
        out.add("%s: not stopped at dt %g" % (label, last["dt"]), not (last["dt"] >= 0.15 and not last["unstable"]))
    return out


def main():
    rows, reference = read_rows(TABLE)
    costs = apply_cost_model(rows)
    plot(rows, reference)
    text = "\n".join(cost_lines(costs, reference) + stability_lines(rows) + speed_up_lines(rows, reference)) + "\n"
    write_whole("results.dat", text)
    print(text, end="")
    failures = checks(rows, reference, "-test" in sys.argv[1:])
    failures.print_failures(summary=False)
    return failures.status()


if __name__ == "__main__":
    sys.exit(main())
