#!/usr/bin/env python3
"""The walled scenes' speed-accuracy chart: tables, picture and checks.

Reads the study (system/walledStepDict: the scenes, the integrators, the tolerances) and every run the
Allrun made, runs/<scene>-<integrator>-dt<step>/ (dpdfoam.stepruns: the solver's log and CPU time,
fitSlipLength's fit, the profile's sampled blocks), and for each scene and integrator takes against the
smallest step (the reference; its run stable) the differences of
  - nu, fitSlipLength's, relative;
  - the slip length b, the mean of the two walls' (their errors averaged: both move with the fit's
    curvature), in length units;
  - kT within one cutoff of the walls (the profile's bins there, weighted by their particle-samples;
    error over ten groups of consecutive sampling blocks), relative;
each with the two runs' combined standard error. A step keeps the reference when nu is within nuTolerance
(2 %), b within max(bTolerance x cutoff, bErrors combined standard errors) (max(0.05, 3 SE)) and kT within
kTTolerance (1 %); the largest step is the largest measured one up to which every step keeps it
(dpdfoam.stepstudy.largest_step). A run the monitor stopped (log: "went unstable") is unstable.

Cost: CPU seconds (user + system, log.cpuTime) per particle-step of the mobile particles; each
integrator's median over its stable runs of the scene (dpdfoam.stepstudy.apply_cost_model: a step costs
the same at any dt, so one run slowed by other jobs moves nothing) divided by dt gives the cost of one
time unit per particle. results.dat keeps each run's own cost too.

Writes results.dat (per scene the runs' table and the largest steps, then the checks) and walledStep.png
(per scene: nu, b and kT next to the walls against dt, and each difference over its tolerance against
the cost; one curve per integrator) and exits non-zero when a check fails (checks() below).
"""
import math
import os
import re
import subprocess
import sys

from dpdfoam.checks import Checks
from dpdfoam.io import dictionary_value
from dpdfoam.plots import label as label_axes, plt, save
from dpdfoam.stepruns import (QUANTITIES, Tolerances, against_smallest, draw_against_dt, draw_scaled_errors_against_cost,
                              draw_tolerance_band, keeps, limiting_step, scene_text)
from dpdfoam.stepruns import scene_rows as read_scene
from dpdfoam.stepstudy import apply_cost_model, first_unstable, largest_step

STUDY = "system/walledStepDict"
RUNS = "runs"
NAMES = {"nu": "nu", "b": "b", "kTwall": "kT next to the walls"}


def study():
    """The scenes, the integrators' labels and the tolerances of system/walledStepDict."""
    scenes = dictionary_value(STUDY, "scenes").strip("()").split()
    text = subprocess.run(["dpdDictionary", STUDY, "-entry", "integrators", "-value"], check=True, capture_output=True,
                          text=True).stdout
    labels = re.findall(r"^    ([^ {};]+)$", text, re.M)
    tol = Tolerances(*(float(dictionary_value(STUDY, k)) for k in ("nuTolerance", "bTolerance", "bErrors", "kTTolerance")))
    return scenes, labels, tol


def read_all(scenes, labels, tol):
    """{scene: {integrator: rows}} with the differences from the smallest step and the cost model applied;
    {scene: {integrator: (median, lowest, highest) CPU seconds per particle-step}}."""
    rows, costs = {}, {}
    for scene in scenes:
        r = read_scene(RUNS, scene, labels)
        if not r:
            continue
        for points in r.values():
            against_smallest(points, tol)
        costs[scene] = apply_cost_model(r)
        rows[scene] = r
    return rows, costs


# ---- Picture -------------------------------------------------------------------------------------------

def plot(rows):
    n = len(rows)
    fig, axes = plt.subplots(n, 4, figsize=(20, 4.3 * n), squeeze=False)
    for (scene, r), ax in zip(rows.items(), axes):
        draw_against_dt(ax[0], r, "nu")
        draw_tolerance_band(ax[0], r, "nu", relative=True)
        label_axes(ax[0], f"{scene}: nu (fitSlipLength)", None, "nu", legend=7)
        draw_against_dt(ax[1], r, "b")
        label_axes(ax[1], f"{scene}: slip length (mean of the walls)", None, "b", legend=7)
        draw_against_dt(ax[2], r, "kTwall")
        draw_tolerance_band(ax[2], r, "kTwall", relative=True)
        label_axes(ax[2], f"{scene}: kT within a cutoff of the walls", None, "kT", legend=7)
        draw_scaled_errors_against_cost(ax[3], r, NAMES)
        ax[3].set_title(f"{scene}: difference / tolerance against cost (labels: dt)", fontsize=10)
        if ax[3].get_legend_handles_labels()[0]:
            ax[3].legend(fontsize=6)
    fig.suptitle("Walled scenes: nu, b and kT next to the walls against the step (dotted: the tolerance around "
                 "the smallest step; x: stopped by the run monitor)", fontsize=11)
    save(fig, "walledStep.png", dpi=100)


# ---- Tables --------------------------------------------------------------------------------------------

def pm(value, error, digits=4, sign=""):
    if not math.isfinite(value):
        return "-"
    return f"{value:{sign}.{digits}f}+-{error:.{digits}f}"


def difference(p, q, percent):
    if p["unstable"] or not math.isfinite(p[q]):
        return "-"
    if p.get("reference"):
        return "ref"
    scale = 100.0 if percent else 1.0
    return f"{scale * p[q]:+.2f}+-{scale * p[q + 'se']:.2f}" if percent else f"{p[q]:+.3f}+-{p[q + 'se']:.3f}"


def fmt(x, spec=".3g"):
    return "-" if x is None or (isinstance(x, float) and not math.isfinite(x)) else format(x, spec)


def scene_lines(scene, r, costs):
    any_run = next(iter(r.values()))[0]
    lines = ["#", f"# Scene {scene}: " + "; ".join(scene_text(any_run["case"])),
             f"# endTime {any_run['endTime']:g} at every step; fitSlipLength's errors: " +
             ", ".join(sorted({p['errors'] for pts in r.values() for p in pts if p['errors']})),
             "# integrator      dt     run              nu                 b (mean of walls)   kT next to walls    "
             "dnu(%)       db             tol(b)  dkT(%)       CPU s/p-step  CPU s/p/time unit  keeps"]
    for label, points in r.items():
        for p in points:
            run = f"stopped at {p['stoppedAt']:g}" if p["unstable"] else f"{p['steps']} steps"
            lines.append(f"{label:<16} {p['dt']:<6g} {run:<16} {pm(p['nuValue'], p['nuValueSe']):<18} "
                         f"{pm(p['bValue'], p['bValueSe'], 3, '+'):<19} {pm(p['kTwallValue'], p['kTwallValueSe']):<19} "
                         f"{difference(p, 'nu', True):<12} {difference(p, 'b', False):<14} {fmt(p.get('bTol')):<7} "
                         f"{difference(p, 'kTwall', True):<12} {fmt(p['stepCost']):<13} {fmt(p['cost']):<18} "
                         f"{'ref' if p.get('reference') else ('yes' if keeps(p) else 'no: ' + ','.join(p['limits']) if not p['unstable'] else 'no')}")
    lines += ["# Cost per particle-step (CPU seconds; median, lowest and highest over the stable runs)"]
    lines += [f"#   {label:<16} {median:.3g} ({low:.3g} to {high:.3g})" for label, (median, low, high) in costs.items()]
    return lines


def largest_lines(rows):
    lines = ["#", "# Largest step: the largest measured step up to which every step keeps nu within the tolerance,",
             "# b within max(tolerance x cutoff, bErrors combined SE) and kT next to the walls within the tolerance of",
             "# the same integrator's smallest step ('-' when the next step is not measured); limitedBy: what the",
             "# next larger step failed (unstable: stopped by the monitor); cost of a time unit at the largest step",
             "# (CPU s per particle, the median step cost / dt) and the speed-up against the smallest step.",
             "# scene           integrator       largestDt  limitedBy             firstUnstable  CPU s/p/time unit  speedUp"]
    for scene, r in rows.items():
        best = None
        for label, points in r.items():
            p = largest_step(points, keeps)
            nxt = limiting_step(points)
            why = "-" if nxt is None else (f"unstable at {nxt['dt']:g}" if nxt["unstable"] else
                                           f"{','.join(nxt['limits'])} at {nxt['dt']:g}")
            u = first_unstable(points)
            ref = next((q for q in points if q.get("reference")), None)
            speed = ref["cost"] / p["cost"] if p and ref and math.isfinite(p["cost"]) else float("nan")
            lines.append(f"{scene:<17} {label:<16} {fmt(p and p['dt'], 'g'):<10} {why:<21} {fmt(u, 'g'):<14} "
                         f"{fmt(p['cost'] if p else None):<18} {fmt(speed, '.2f')}")
            if p and math.isfinite(p["cost"]) and (best is None or p["cost"] < best[2]):
                best = (label, p["dt"], p["cost"])
        if best:
            lines.append(f"# {scene}: cheapest time unit within the tolerances: {best[0]} at dt {best[1]:g}, "
                         f"{best[2]:.3g} CPU s per particle")
    return lines


# ---- Checks --------------------------------------------------------------------------------------------
#
# At each integrator's smallest step, the scene's quantities against what its tutorial measured, and the
# two integrators against each other; the steps at which a run must be stopped. Each statistical check
# is dpdfoam.checks.Checks.bounded: its standard error within a budget first, then the value within a
# fixed bound built from the budget (a NaN fails). Budgets: about 1.5 x the largest standard error
# measured at that size (README); the full study's are the test's scaled by the square root of the
# sampled times, times two (the jackknife over super-blocks against the test's block errors), until the
# full study is run. nu and kT relative, b in length units (the mean of the walls, its error the mean of
# the walls' errors).
BUDGETS = {  # {scene: {quantity: (full, test)}}
    "latticeWall": {"nu": (0.007, 0.011), "b": (0.02, 0.03), "kTwall": (0.002, 0.0045)},
    "randomWall": {"nu": (0.015, 0.035), "b": (0.04, 0.065), "kTwall": (0.002, 0.0045)},
    "tunableSlip": {"nu": (0.015, 0.06), "b": (0.05, 0.21), "kTwall": (0.002, 0.006)},
}
# What each scene measured elsewhere, checked at the smallest step of every integrator: nu (reference,
# relative bound), b (reference, bound: a fixed margin plus 3 budgets where the reference is itself a
# measurement), kT next to the walls (a band: a sanity bound, named coarse).
#   - nu of this fluid without walls (rho 4, a 18.75): 0.2749 +- 0.0009 (latticeWall/viscosity in
#     tutorials/channel/poiseuille/latticeWall), the wall fit's within 3 % of it there;
#   - the calibrated lattice wall and the random wall: no slip, |b| < 0.1, as there;
#   - the tunable-slip wall at gamma_L 2: b 1.02 +- 0.03, nu 0.423 (dt 0.01, tutorials/channel/
#     tunableSlip/README), within 10 % (its nu scattered by 3 % over gamma_L there) plus 3 budgets;
#   - kT within a cutoff of the walls: 1.00-1.10 at the frozen walls (viscous heating at the wall shear
#     rate 1.45: 1.02-1.06 measured at both), 0.97-1.03 at the tunable-slip wall (a bath at kT).
EXPECTED = {
    "latticeWall": {"nu": (0.2749, 0.03), "b": (0.0, 0.1, 0), "kTwall": (1.00, 1.10)},
    "randomWall": {"nu": (0.2749, 0.03), "b": (0.0, 0.1, 0), "kTwall": (1.00, 1.10)},
    "tunableSlip": {"nu": (0.423, 0.10), "b": (1.02, 0.102, 3), "kTwall": (0.97, 1.03)},
}
# Checks whose bound is wide against what they could tell apart at that size, named "(coarse)" (the kT
# bands always are): in the test mode the tunable-slip wall's nu and b (their budgets a third of their
# bounds), the random wall's nu (block errors of 200 time units differ by 4 x between its two runs) and
# b (its bound 1.5 budgets).
COARSE = {False: set(), True: {("tunableSlip", "nu"), ("tunableSlip", "b"), ("randomWall", "nu"), ("randomWall", "b")}}
# Steps at which a scene's run must be stopped by the monitor (the Allrun records it, does not fail): the
# tunable-slip wall's WCA repulsion (sigma 0.5) is integrable only up to dt = sigma / 50 = 0.01
# (tests/walls/TunableSlipWallTest.cpp); at 0.03-0.05 every run measured here went non-finite within
# 25 time units.
MUST_STOP = {"tunableSlip": 0.04}


def budget(scene, q, test_mode):
    return BUDGETS.get(scene, {}).get(q, (float("nan"), float("nan")))[1 if test_mode else 0]


def coarse(scene, q, test_mode):
    return " (coarse)" if (scene, q) in COARSE[test_mode] else ""


def expected_checks(out, scene, label, first, test_mode):
    """The smallest step's nu, b and kT next to the walls against EXPECTED[scene] (none for another scene)."""
    for q, expected in EXPECTED.get(scene, {}).items():
        b, name = budget(scene, q, test_mode), f"{scene} {label}"
        value, se, dt = first[q + "Value"], first[q + "ValueSe"], first["dt"]
        relative_se = se / value if value else float("nan")
        if q == "kTwall":
            low, high = expected
            out.bounded(f"{name}: kT next to the walls in [{low:g}, {high:g}] (coarse) at dt {dt:g}",
                        value, relative_se, b, low, high)
        elif q == "nu":
            ref, margin = expected
            out.bounded(f"{name}: nu {value:.4f} within {100 * margin:g} % of {ref:g}{coarse(scene, q, test_mode)} at dt {dt:g}",
                        value / ref - 1.0, relative_se, b, -margin, margin)
        else:
            ref, margin, budgets = expected
            bound = margin + budgets * b
            out.bounded(f"{name}: b {value:+.3f} within {bound:.3g} of {ref:g}{coarse(scene, q, test_mode)} at dt {dt:g}",
                        value - ref, se, b, -bound, bound)


# The integrators agree at their smallest step (the reference of each): nu within 3 %, b within 0.1 and
# kT next to the walls within 2 % (twice the study's tolerances: the smallest step itself may carry part
# of one), or 3 combined budgets where that is wider.
AGREEMENT = {"nu": 0.03, "b": 0.1, "kTwall": 0.02}


def agreement_checks(out, scene, refs, test_mode):
    """The integrators' smallest steps (the same dt) agree: each difference within AGREEMENT or 3
    combined budgets (sqrt(2) budgets), whichever is wider, its error within the combined budget."""
    labels = list(refs)
    for i in range(len(labels)):
        for j in range(i + 1, len(labels)):
            p, s = refs[labels[i]], refs[labels[j]]
            if abs(p["dt"] - s["dt"]) > 1e-12:
                continue
            for q in QUANTITIES:
                b = math.sqrt(2) * budget(scene, q, test_mode)
                if q == "b":
                    d, e = p["bValue"] - s["bValue"], math.hypot(p["bValueSe"], s["bValueSe"])
                else:
                    d = p[q + "Value"] / s[q + "Value"] - 1.0
                    e = math.hypot(p[q + "ValueSe"] / p[q + "Value"], s[q + "ValueSe"] / s[q + "Value"])
                bound = max(AGREEMENT[q], 3 * b)
                out.bounded(f"{scene}: {NAMES[q]} of {labels[i]} and {labels[j]} agree within {bound:.3g}"
                            f"{'' if q == 'b' else ' (relative)'}{coarse(scene, q, test_mode)} at dt {p['dt']:g}",
                            d, e, b, -bound, bound)


def checks(rows, test_mode):
    out = Checks()
    for scene, r in rows.items():
        refs = {}
        for label, points in r.items():
            first = points[0]
            if out.add(f"{scene} {label}: the smallest step {first['dt']:g} ran without the monitor stopping it",
                       not first["unstable"]):
                refs[label] = first
                expected_checks(out, scene, label, first, test_mode)
        agreement_checks(out, scene, refs, test_mode)
        for label, points in r.items():
            for p in points:
                if scene in MUST_STOP and p["dt"] >= MUST_STOP[scene] - 1e-12:
                    out.add(f"{scene} {label}: the monitor stopped the run at dt {p['dt']:g} (WCA wall beyond "
                            f"sigma / 50), recorded as unstable", p["unstable"])
    return out


def main():
    test_mode = "-test" in sys.argv[1:]
    scenes, labels, tol = study()
    rows, costs = read_all(scenes, labels, tol)
    if not rows:
        sys.exit(f"plotResults: no runs in {RUNS}/ (run ./Allrun)")
    plot(rows)
    lines = [f"# walledStep ({'test mode' if test_mode else 'full study'}): each run the same physical time; against "
             "the same integrator's smallest step: nu within "
             f"{100 * tol.nu:g} %, b within max({tol.b:g} r_c, {tol.bErrors:g} combined SE), kT within one cutoff of "
             f"the walls within {100 * tol.kT:g} %",
             "# (values +- standard errors; differences relative in %, b in length units; CPU s: user + system of the "
             "solver)"]
    for scene, r in rows.items():
        lines += scene_lines(scene, r, costs[scene])
    lines += largest_lines(rows)
    out = checks(rows, test_mode)
    text = "\n".join(lines) + "\n#\n" + "\n".join(out.lines()) + "\n"
    with open("results.dat.tmp", "w") as f:  # replaced whole: a reader never sees half a table
        f.write(text)
    os.replace("results.dat.tmp", "results.dat")
    print(text, end="")
    out.print_failures()
    return out.status()


if __name__ == "__main__":
    sys.exit(main())
