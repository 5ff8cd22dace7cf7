#!/usr/bin/env python3
"""The walled scenes' speed-accuracy chart: tables, picture and checks.

Reads the study (system/walledStepDict: the scenes, the integrators, the steps, the tolerances) and every
run the Allrun made, runs/<scene>-<integrator>-dt<step>/ (dpdfoam.stepruns: the solver's log and CPU
time, fitSlipLength's fit, the profile's sampled blocks), and for each scene and integrator takes
against the smallest step (the reference; its run stable) the differences of
  - nu, fitSlipLength's, relative;
  - the slip length b, the mean of the two walls' (their errors averaged: both move with the fit's
    curvature), in length units;
  - kT within one cutoff of the walls (the profile's bins there, weighted by their particle-samples;
    error over ten groups of consecutive sampling blocks), relative;
each with the two runs' combined standard error. A step keeps the reference when nu is within nuTolerance
(2 %), b within max(bTolerance x cutoff, bErrors combined standard errors) (max(0.05, 3 SE)) and kT within
kTTolerance (1 %); the largest step is the largest measured one up to which every step keeps it
(dpdfoam.stepstudy.largest_step). A run the monitor stopped (log: "went unstable") is unstable.

Cost: CPU seconds (user + system) per particle-step of the mobile particles, each integrator's median
over its stable runs of the scene, over dt: the cost of one time unit per particle (dpdfoam.stepruns).

Writes results.dat (per scene the runs' table and the largest steps, then the checks) and walledStep.png
(per scene: nu, b and kT next to the walls against dt, and each difference over its tolerance against
the cost; one curve per integrator) and exits non-zero when a check fails (checks() below).
"""
import math
import sys

from dpdfoam.checks import Checks, as_number
from dpdfoam.stepruns import NAMES, NAN, QUANTITIES, draw_study, read_runs, read_study, study_lines, write_whole

STUDY = "system/walledStepDict"
RUNS = "runs"

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
    return BUDGETS.get(scene, {}).get(q, (NAN, NAN))[1 if test_mode else 0]


def coarse(scene, q, test_mode):
    return " (coarse)" if (scene, q) in COARSE[test_mode] else ""


def ratio(a, b):
    return a / b if b else NAN


def expected_check(out, scene, label, q, value, se, dt, test_mode):
    """One quantity of an integrator's smallest step (value, its standard error, at dt: plain numbers, a
    missing or empty one fails) against EXPECTED[scene][q]: kT next to the walls in its band, nu within
    its relative margin of the reference, b within the margin plus its budgets of it."""
    value, se, dt = as_number(value), as_number(se), as_number(dt)
    b, name, expected = budget(scene, q, test_mode), f"{scene} {label}", EXPECTED[scene][q]
    relative_se = ratio(se, value)
    if q == "kTwall":
        low, high = expected
        return out.bounded(f"{name}: kT next to the walls in [{low:g}, {high:g}] (coarse) at dt {dt:g}",
                           value, relative_se, b, low, high)
    if q == "nu":
        ref, margin = expected
        return out.bounded(f"{name}: nu {value:.4f} within {100 * margin:g} % of {ref:g}{coarse(scene, q, test_mode)} "
                           f"at dt {dt:g}", value / ref - 1.0, relative_se, b, -margin, margin)
    ref, margin, budgets = expected
    bound = margin + budgets * b
    return out.bounded(f"{name}: b {value:+.3f} within {bound:.3g} of {ref:g}{coarse(scene, q, test_mode)} at dt {dt:g}",
                       value - ref, se, b, -bound, bound)


def expected_checks(out, scene, label, first, test_mode):
    """The smallest step's nu, b and kT next to the walls against EXPECTED[scene] (none for another scene)."""
    for q in EXPECTED.get(scene, {}):
        expected_check(out, scene, label, q, first[q + "Value"], first[q + "ValueSe"], first["dt"], test_mode)


# The integrators agree at their smallest step (the reference of each): nu within 3 %, b within 0.1 and
# kT next to the walls within 2 % (twice the study's tolerances: the smallest step itself may carry part
# of one), or 3 combined budgets where that is wider.
AGREEMENT = {"nu": 0.03, "b": 0.1, "kTwall": 0.02}


def agreement_check(out, scene, labels, q, p, s, dt, test_mode):
    """Two integrators' (labels) q at the same smallest step dt (p, s: (value, standard error), plain
    numbers) agree: the difference (b: p - s; nu, kT: p / s - 1) within AGREEMENT[q] or 3 combined
    budgets (sqrt(2) budgets), whichever is wider, its error within the combined budget."""
    pv, pe, sv, se, dt = (as_number(x) for x in (*p, *s, dt))
    b = math.sqrt(2) * budget(scene, q, test_mode)
    d, e = (pv - sv, math.hypot(pe, se)) if q == "b" else (ratio(pv, sv) - 1.0, math.hypot(ratio(pe, pv), ratio(se, sv)))
    bound = max(AGREEMENT[q], 3 * b)
    return out.bounded(f"{scene}: {NAMES[q]} of {labels[0]} and {labels[1]} agree within {bound:.3g}"
                       f"{'' if q == 'b' else ' (relative)'}{coarse(scene, q, test_mode)} at dt {dt:g}",
                       d, e, b, -bound, bound)


def agreement_checks(out, scene, refs, test_mode):
    """Each pair of integrators' smallest steps (refs: {integrator: row}) at the same dt: agreement_check
    of each quantity."""
    labels = list(refs)
    for i in range(len(labels)):
        for j in range(i + 1, len(labels)):
            p, s = refs[labels[i]], refs[labels[j]]
            if abs(p["dt"] - s["dt"]) > 1e-12:
                continue
            for q in QUANTITIES:
                agreement_check(out, scene, (labels[i], labels[j]), q, (p[q + "Value"], p[q + "ValueSe"]),
                                (s[q + "Value"], s[q + "ValueSe"]), p["dt"], test_mode)


def missing_checks(out, rows, study):
    """Every scene, integrator and step of the study (dpdfoam.stepruns.Study) has its run: one failed check
    per scene and integrator that lacks one (none when all are there)."""
    for scene in study.scenes:
        for label in study.integrators:
            run = [p["dt"] for p in rows.get(scene, {}).get(label, [])]
            missing = [f"{dt:g}" for dt in study.steps if not any(abs(dt - d) < 1e-9 for d in run)]
            if missing:
                out.fail(f"{scene} {label}: no run at dt {', '.join(missing)} ({RUNS}/{scene}-{label}-dt*)")


def checks(rows, test_mode, study):
    """rows ({scene: {integrator: rows by dt}}, read_runs'): each integrator's smallest step stable and
    against EXPECTED, the integrators agree there, MUST_STOP's runs stopped; every run of the study there."""
    out = Checks()
    for scene, r in rows.items():
        refs = {}
        for label, points in r.items():
            first = points[0] if points else {"dt": NAN, "unstable": True}  # no run: missing_checks says so
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
    missing_checks(out, rows, study)
    return out


def main():
    test_mode = "-test" in sys.argv[1:]
    study = read_study(STUDY)
    rows, costs = read_runs(RUNS, study.scenes, study.integrators, study.tol)
    if not rows:
        sys.exit(f"plotResults: no runs in {RUNS}/ (run ./Allrun)")
    draw_study(rows, "walledStep.png", "Walled scenes: nu, b and kT next to the walls against the step (dotted: the "
               "tolerance around the smallest step; x: stopped by the run monitor)")
    out = checks(rows, test_mode, study)
    lines = study_lines("walledStep", test_mode, study.tol, rows, costs)
    text = "\n".join(lines) + "\n#\n" + "\n".join(out.lines()) + "\n"
    write_whole("results.dat", text)
    print(text, end="")
    out.print_failures()
    return out.status()


if __name__ == "__main__":
    sys.exit(main())
