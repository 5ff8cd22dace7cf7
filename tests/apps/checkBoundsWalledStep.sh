#!/bin/bash
# Issue 45's rule on broken inputs, on the check functions of tutorials/benchmarks/walledStep (no
# simulation, no executables: plain numbers): each integrator's smallest step against what the scenes
# measured elsewhere (expected_check: nu within its margin of the fluid's, b within its bound of no slip
# or of the tunable-slip wall's 1.02, kT next to the walls in its band), the two integrators against
# each other at that step (agreement_check), and the study as a whole (checks: the smallest step
# stable, the tunable-slip wall's runs stopped from dt 0.04, every scene, integrator and step run).
# Each check must fail for a NaN, inf, empty or missing value or error, a standard error over its
# budget and a value just outside its fixed bound, and pass for a good value and one just inside the
# bound: the test mode's kept figures (README, 2026-11-30) at the test's budgets, and the same values
# with the standard errors the README expects of the full study (nu 0.3 %, b 0.01 in the channels; nu
# 0.7 %, b 0.025 at the tunable-slip wall; kT 0.1 %: the full study is not run yet) at its budgets.
#   $1: the directory of the executables (unused), $2: the source directory
set -u
src=$2
. "$src/tests/shellTestFunctions" || exit 1
python=/usr/bin/python3
# Required dependencies (the tutorial's script imports them): a missing one fails the test (no skip).
requirePython "$python" numpy matplotlib h5py || finishTests checkBoundsWalledStep

out=$(PYTHONPATH="$src/tests/apps:$src/etc/python" PYTHONDONTWRITEBYTECODE=1 MPLBACKEND=Agg "$python" - "$src" 2>&1 <<'EOF'
import copy
import math
import sys

from boundcheck import INF, NAN, expect, print_summary, tutorial_loader
from dpdfoam.stepruns import Study, Tolerances

ws = tutorial_loader(sys.argv[1], "benchmarks")("walledStep", "walledStep")


def broken(what, add, good, noisy, quiet, outside, inside):
    """add(checks, value, error). good (value, error) passes; fails: the value NaN, inf, -inf, empty or
    missing, the error NaN, inf, empty or missing, the error `noisy` (just over its budget), each
    value of outside (name, value); passes: the error `quiet` (just within its budget), each value of
    inside (name, value)."""
    value, error = good
    expect(f"{what}: good {value:g} +- {error:g}", True, lambda c: add(c, value, error))
    for name, bad in (("NaN", NAN), ("inf", INF), ("-inf", -INF), ("empty", ""), ("missing", None)):
        expect(f"{what}: value {name}", False, lambda c: add(c, bad, error))
        if name != "-inf":
            expect(f"{what}: error {name}", False, lambda c: add(c, value, bad))
    expect(f"{what}: error just over its budget", False, lambda c: add(c, value, noisy))
    expect(f"{what}: error just within its budget", True, lambda c: add(c, value, quiet))
    for name, v in outside:
        expect(f"{what}: {name} ({v:.6g}), outside", False, lambda c: add(c, v, error))
    for name, v in inside:
        expect(f"{what}: {name} ({v:.6g}), inside", True, lambda c: add(c, v, error))


GW, VV = "GrootWarren0.65", "DPDVV"
SCENES = ("latticeWall", "tunableSlip", "randomWall")
# The test mode's figures at dt 0.01 (README, 2026-11-30; results.dat): {scene: {integrator: {q: (value,
# standard error)}}}.
TEST = {
    "latticeWall": {GW: {"nu": (0.2690, 0.0019), "b": (0.0332, 0.0177), "kTwall": (1.0345, 0.0029)},
                    VV: {"nu": (0.2713, 0.0017), "b": (0.0243, 0.0151), "kTwall": (1.0328, 0.0020)}},
    "tunableSlip": {GW: {"nu": (0.4078, 0.0167), "b": (0.985, 0.132), "kTwall": (1.0102, 0.0025)},
                    VV: {"nu": (0.4046, 0.0163), "b": (0.939, 0.140), "kTwall": (1.0052, 0.0039)}},
    "randomWall": {GW: {"nu": (0.2702, 0.0016), "b": (0.0089, 0.0314), "kTwall": (1.0498, 0.0029)},
                   VV: {"nu": (0.2677, 0.0060), "b": (-0.0085, 0.0421), "kTwall": (1.0393, 0.0020)}},
}
# The full study: the same values with the errors the README expects of it (relative for nu and kT).
FULL_ERRORS = {"latticeWall": {"nu": 0.003, "b": 0.01, "kTwall": 0.001},
               "randomWall": {"nu": 0.003, "b": 0.01, "kTwall": 0.001},
               "tunableSlip": {"nu": 0.007, "b": 0.025, "kTwall": 0.001}}


def figures(scene, label, test):
    """{q: (value, standard error)} of an integrator's smallest step in that mode."""
    if test:
        return TEST[scene][label]
    return {q: (v, FULL_ERRORS[scene][q] * (1 if q == "b" else abs(v))) for q, (v, _) in TEST[scene][label].items()}


def relative(q):
    return q != "b"


# ---- expected_check: each quantity of the smallest step against EXPECTED ---------------------------
for test in (False, True):
    mode = "test" if test else "full"
    for scene in SCENES:
        for q in ("nu", "b", "kTwall"):
            B = ws.budget(scene, q, test)
            add = lambda c, v, e, scene=scene, q=q, test=test: ws.expected_check(c, scene, GW, q, v, e, 0.01, test)
            value, error = figures(scene, GW, test)[q]
            scale = abs(value) if relative(q) else 1.0
            if q == "nu":
                ref, margin = ws.EXPECTED[scene][q]
                lo, hi = ref * (1 - margin), ref * (1 + margin)
                out = [("just above the bound", hi + 1e-4), ("just below the bound", lo - 1e-4)]
                inn = [("just within the upper bound", hi - 1e-4), ("just within the lower bound", lo + 1e-4)]
                if margin < 0.1:  # the tunable-slip wall's bound is 10 % itself (its nu over gamma_L)
                    out += [("10 % high", ref * 1.1), ("10 % low", ref * 0.9)]
            elif q == "b":
                ref, margin, budgets = ws.EXPECTED[scene][q]
                bound = margin + budgets * B
                out = [("just above the bound", ref + bound + 0.001), ("just below the bound", ref - bound - 0.001)]
                inn = [("just within the upper bound", ref + bound - 0.001), ("just within the lower bound", ref - bound + 0.001)]
                if ref:  # the tunable-slip wall: 1.02 +- (10 % + 3 budgets), 0.252 full size, 0.732 (coarse) in the test
                    out.append(("the slip of the wrong sign", -value))
                    if not test:
                        out += [("off by 0.3", value + 0.3), ("off by -0.3", value - 0.3)]
                else:
                    out += [("off by 0.2", value + 0.2), ("off by -0.2", value - 0.2)]
            else:
                lo, hi = ws.EXPECTED[scene][q]
                out = [("just above the band", hi + 0.001), ("just below the band", lo - 0.001)]
                inn = [("just within the band's top", hi - 0.001), ("just within the band's bottom", lo + 0.001)]
                if hi - lo < 0.1:  # the tunable-slip wall's band: the bath's kT 1 +- 3 %
                    out += [("3.5 % above the bath's kT", 1.035), ("3.5 % below the bath's kT", 0.965)]
            broken(f"walledStep {mode} {scene} {q} against EXPECTED", add, (value, error),
                   (B + 1e-4) * scale, (B - 1e-4) * scale, out, inn)

# ---- agreement_check: the two integrators at their smallest step ---------------------------------
for test in (False, True):
    mode = "test" if test else "full"
    for scene in SCENES:
        for q in ("nu", "b", "kTwall"):
            B = math.sqrt(2) * ws.budget(scene, q, test)
            bound = max(ws.AGREEMENT[q], 3 * B)
            other = figures(scene, VV, test)[q]
            value, error = figures(scene, GW, test)[q]
            add = lambda c, v, e, scene=scene, q=q, test=test, other=other: ws.agreement_check(
                c, scene, (GW, VV), q, (v, e), other, 0.01, test)
            s = other[0]
            # The error over its budget: GW's own (relative for nu, kT) alone at the combined budget.
            scale = abs(value) if relative(q) else 1.0
            quiet = math.sqrt(max((B - 1e-4) ** 2 - (other[1] / (abs(s) if relative(q) else 1.0)) ** 2, 0.0)) * scale
            if relative(q):
                edge = [s * (1 + bound + 0.0005), s * (1 - bound - 0.0005)]
                within = [s * (1 + bound - 0.0005), s * (1 - bound + 0.0005)]
            else:
                edge, within = [s + bound + 0.001, s - bound - 0.001], [s + bound - 0.001, s - bound + 0.001]
            out = [("just above the bound", edge[0]), ("just below the bound", edge[1])]
            inn = [("just within the upper bound", within[0]), ("just within the lower bound", within[1])]
            if q == "kTwall":
                out += [("kT 3 % high", s * 1.03), ("kT 3 % low", s * 0.97)]
            if q == "nu" and bound < 0.1:  # the test's tunable-slip and random walls: coarse, wider
                out += [("nu 10 % high", s * 1.1), ("nu 10 % low", s * 0.9)]
            if q == "b" and bound < 0.2:
                out += [("b off by 0.2", s + 0.2), ("b of the wrong sign, off by 0.2", s - 0.2)]
            broken(f"walledStep {mode} {scene} {q}, {GW} and {VV} agree", add, (value, error),
                   B * scale, quiet, out, inn)
            for name, bad in (("NaN", NAN), ("empty", ""), ("missing", None)):
                expect(f"walledStep {mode} {scene} {q} agree: the other's value {name}", False,
                       lambda c: ws.agreement_check(c, scene, (GW, VV), q, (value, error), (bad, other[1]), 0.01, test))
                expect(f"walledStep {mode} {scene} {q} agree: the other's error {name}", False,
                       lambda c: ws.agreement_check(c, scene, (GW, VV), q, (value, error), (other[0], bad), 0.01, test))
            if relative(q):  # a ratio to 0 is no number
                expect(f"walledStep {mode} {scene} {q} agree: the other's value 0", False,
                       lambda c: ws.agreement_check(c, scene, (GW, VV), q, (value, error), (0.0, other[1]), 0.01, test))
expect("walledStep agreement of a scene without budgets (NaN fails)", False,
       lambda c: ws.agreement_check(c, "noSuchScene", (GW, VV), "nu", (0.27, 0.001), (0.27, 0.001), 0.01, False))

# ---- checks: the whole study ------------------------------------------------------------------------
# Rows as stepruns.read_runs gives them (the checks read dt, unstable and each q's value and error):
# every scene and integrator at the study's steps, the tunable-slip wall stopped from 0.03 as measured.


def rows_of(test, steps):
    rows = {}
    for scene in SCENES:
        rows[scene] = {}
        for label in (GW, VV):
            values = figures(scene, label, test)
            points = []
            for dt in steps:
                row = {"dt": dt, "unstable": scene == "tunableSlip" and dt > 0.02}
                for q, (v, e) in values.items():
                    row[q + "Value"], row[q + "ValueSe"] = v, e
                points.append(row)
            rows[scene][label] = points
    return rows


TOL = Tolerances(0.02, 0.05, 3, 0.01)
STEPS = {True: [0.01, 0.03, 0.05], False: [0.01, 0.02, 0.03, 0.04, 0.05]}


def study(test, scenes=SCENES, labels=(GW, VV)):
    return Study(list(scenes), list(labels), STEPS[test], TOL)


def whole(test, change=None, of=None):
    """checks() on the study's rows after change(rows) (the study itself: of, when given)."""
    rows = rows_of(test, STEPS[test])
    if change:
        change(rows)
    return lambda c: c.include(ws.checks(rows, test, of or study(test)))


def set_row(scene, label, k, **values):
    return lambda rows: rows[scene][label][k].update(values)


for test in (False, True):
    mode = "test" if test else "full"
    expect(f"walledStep {mode}: the whole study", True, whole(test))
    expect(f"walledStep {mode}: the smallest step of {VV} unstable", False,
           whole(test, set_row("latticeWall", VV, 0, unstable=True)))
    expect(f"walledStep {mode}: the smallest step of the tunable-slip wall unstable", False,
           whole(test, set_row("tunableSlip", GW, 0, unstable=True)))
    for name, bad in (("NaN", NAN), ("inf", INF), ("empty", ""), ("missing", None)):
        for q in ("nuValue", "bValueSe", "kTwallValue"):
            expect(f"walledStep {mode}: randomWall's smallest step's {q} {name}", False,
                   whole(test, set_row("randomWall", GW, 0, **{q: bad})))
    expect(f"walledStep {mode}: a scene missing (randomWall: no runs)", False,
           whole(test, lambda rows: rows.pop("randomWall")))
    expect(f"walledStep {mode}: an integrator missing (tunableSlip {VV})", False,
           whole(test, lambda rows: rows["tunableSlip"].pop(VV)))
    expect(f"walledStep {mode}: an integrator without runs (an empty list)", False,
           whole(test, lambda rows: rows["latticeWall"][GW].clear()))
    expect(f"walledStep {mode}: the smallest step's run missing", False,
           whole(test, lambda rows: rows["latticeWall"][GW].pop(0)))
    expect(f"walledStep {mode}: a middle run missing (dt 0.03)", False,
           whole(test, lambda rows: rows["randomWall"][VV].pop(1 if test else 2)))
    expect(f"walledStep {mode}: the tunable-slip wall's dt 0.05 run missing", False,
           whole(test, lambda rows: rows["tunableSlip"][GW].pop()))
    expect(f"walledStep {mode}: the tunable-slip wall's dt 0.05 run not stopped", False,
           whole(test, set_row("tunableSlip", VV, -1, unstable=False)))
    expect(f"walledStep {mode}: the study asks for a scene with no runs", False,
           whole(test, of=study(test, SCENES + ("noSuchScene",))))
    expect(f"walledStep {mode}: the study asks for an integrator with no runs", False,
           whole(test, of=study(test, labels=(GW, VV, "VelocityVerlet"))))
    expect(f"walledStep {mode}: the test's errors at the full study's budgets", False,
           lambda c: c.include(ws.checks(rows_of(True, STEPS[test]), False, study(test))))
expect("walledStep full: the tunable-slip wall's dt 0.04 run not stopped (the bound is inclusive)", False,
       whole(False, set_row("tunableSlip", GW, 3, unstable=False)))
expect("walledStep full: the tunable-slip wall's dt 0.03 run stable (below MUST_STOP's 0.04: not asked)", True,
       whole(False, set_row("tunableSlip", GW, 2, unstable=False)))
# A copy of the rows is not changed by the checks (they only read).
rows = rows_of(True, STEPS[True])
kept = copy.deepcopy(rows)
ws.checks(rows, True, study(True))
expect("walledStep: checks() leave the rows as they were", True, lambda c: c.add("rows unchanged", rows == kept))
print_summary(count_ok=True)
EOF
)
echo "$out"
echo "$out" | grep -q '^[0-9]* ok, 0 wrong$' || fail "every broken input fails and every good value passes ($(echo "$out" | grep -c '^WRONG') wrong)"
[ "$(echo "$out" | grep -c '^ok ')" -ge 600 ] || fail "fewer expectations ran than written"
finishTests checkBoundsWalledStep
