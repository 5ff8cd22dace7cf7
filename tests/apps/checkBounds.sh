#!/bin/bash
# Issue 45's rule on broken inputs, on the check functions of these tutorials (no simulation, no
# executables: plain numbers): tutorials/channel/tunableSlip (the slip length against the prediction
# from the layer's density, the ideal gas's Boltzmann layer, no crossing), tutorials/channel/stripedWall
# (the slip tensor against the continuum reference, the flux's turn, zero flux, linearity in the force,
# the fluid at rest; its calibration's fall of b with gamma_L), tutorials/channel/slipGammaFw (the
# slip's rise with falling gamma_fw, the variants' gap at the wall), tutorials/channel/slipLength (the measured slip length against
# the asked one), tutorials/channel/poiseuille/latticeWall (walls compared pair by pair, no slip, nu
# against the fluid without walls, and the missing verdict of too few super-blocks),
# tutorials/benchmarks/speedAccuracy (each scheme's errors at its smallest step, the blow-up) and the
# contractions (kT, a flux equal at every section, nothing inside the solid). Each
# check must fail for a NaN, an empty or a missing value, a standard error over its budget and a value
# just outside its fixed bound (which a standard error within budget no longer widens), and pass for a
# good value: the full-size numbers the tutorials' READMEs record, at the full-size budgets.
#   $1: the directory of the executables (unused), $2: the source directory
set -u
src=$2
. "$src/tests/shellTestFunctions" || exit 1
python=/usr/bin/python3
# Required dependencies (the tutorials' scripts import them): a missing one fails the test (no skip).
requirePython "$python" numpy matplotlib || finishTests checkBounds

out=$(PYTHONPATH="$src/tests/apps:$src/etc/python" PYTHONDONTWRITEBYTECODE=1 "$python" - "$src" 2>&1 <<'EOF'
import sys
import types

from boundcheck import NAN, broken, expect, print_summary, tutorial_loader
from dpdfoam.slip import reference_check, same_at_rest_check, turn_check, zero_flux_check

load = tutorial_loader(sys.argv[1], "channel")
sw, sg, lw = load("stripedWall", "stripedWall"), load("slipGammaFw", "slipGammaFw"), load("latticeWall", "poiseuille/latticeWall")
ts = load("tunableSlip", "tunableSlip")
sc = load("stripedCalibration", "stripedWall", "calibrate.py")
sa = load("speedAccuracy", "speedAccuracy", group="benchmarks")
wc = sys.modules["wallComparison"]


# stripedWall (its plotResults.py's budgets, BOUND and linear; the checks it runs from dpdfoam.slip).
# reference_check(checks, label, measured, run error, reference, key, wall error, budget, bound), here
# through cmp(checks, measured, run error, reference value, calibration error, wall error, budget): the angle sweep's b_par at full size (README 2026-11-27: 1.143 +- 0.029 against 1.0486,
# calibration 0.098, wall 0.091), budget 0.16, bound 3 x 0.16 = 0.48.
class Reference:
    """A reference of one value and its calibration error (stripedSlip's, fixed)."""
    def __init__(self, value, error):
        self.value, self.err = value, error

    def at(self, key, angle=None):
        return self.value

    def error(self, key, angle=None):
        return self.err


def compare(c, label, m, e, ref, ce, we, budget):
    return reference_check(c, label, m, e, Reference(ref, ce), "slipParallel", we, budget, bound=sw.BOUND)


B = sw.budget("b, angle sweep", test=False, fluid="a25")
cmp = lambda c, m, e, *rest: compare(c, "b_par", m, e, *rest)
broken("stripedWall b_par", cmp, (1.143, 0.029, 1.0486, 0.098, 0.091, B), 1.0486 + 3 * B + 0.001, 0.12)
expect("stripedWall b_par just inside the bound", True, lambda c: cmp(c, 1.0486 + 3 * B - 0.001, 0.029, 1.0486, 0.098, 0.091, B))
# The old bound, max(3 standard errors, 5 %), let a noisy run pass further off: 0.6 from the reference
# with a run error of 0.2 passed (bound 0.71); now it fails twice over.
expect("stripedWall b_par: noisy and far off (passed the old bound)", False,
       lambda c: cmp(c, 1.0486 + 0.6, 0.2, 1.0486, 0.098, 0.091, B))
expect("stripedWall b_par: reference NaN", False, lambda c: cmp(c, 1.143, 0.029, NAN, 0.098, 0.091, B))
expect("stripedWall b_par: calibration error missing", False, lambda c: cmp(c, 1.143, 0.029, 1.0486, None, 0.091, B))
# The README's full-size values at the full-size budgets (reference and calibration error: stripedSlip
# at the README's calibration), each check's largest standard error or difference.
full = [("b, angle sweep", 0.724, 0.021, 0.6520, 0.0995, 0.091), ("b, one run", 1.318, 0.099, 1.0486, 0.0985, 0.091),
        ("b, one run", 0.770, 0.108, 0.6521, 0.0995, 0.091), ("b, one run", 1.536, 0.062, 1.4104, 0.0981, 0.091),
        ("b, one run", 2.340, 0.103, 2.2770, 0.0964, 0.091), ("b_par - b_perp, angle sweep", 0.419, 0.036, 0.3965, 0.0045, 0),
        ("b_par - b_perp, L 40", 1.138, 0.100, 1.0287, 0.0332, 0), ("flux ratio, angle sweep", 0.044, 0.011, 0.0378, 0.0006, 0),
        ("flux ratio, one run", 0.027, 0.017, 0.0161, 0.0002, 0), ("flux ratio, one run", 0.053, 0.006, 0.0396, 0.0011, 0)]
for kind, m, e, ref, ce, we in full:
    expect(f"stripedWall full size, {kind}: {m} +- {e} against {ref}", True,
           lambda c: compare(c, kind, m, e, ref, ce, we, sw.budget(kind, test=False, fluid="a25")))
# The review's fluid (a = 0, the default since 2026-11-29): its full-size values at its own budgets
# (README: b_par 1.7313 +- 0.0619 against 1.4795, calibration 0.0935, wall 0.0832; b_perp 1.2194 +-
# 0.0570 against 1.0885; b_par - b_perp 0.5119 +- 0.0841 against 0.3910), and b_par just beyond its bound.
A0 = sw.budget("b, angle sweep", test=False, fluid="a0")
for kind, m, e, ref, ce, we in (("b, angle sweep", 1.7313, 0.0619, 1.4795, 0.0935, 0.0832),
                                ("b, angle sweep", 1.2194, 0.0570, 1.0885, 0.0941, 0.0832),
                                ("b_par - b_perp, angle sweep", 0.5119, 0.0841, 0.3910, 0.0083, 0)):
    expect(f"stripedWall a = 0 full size, {kind}: {m} +- {e} against {ref}", True,
           lambda c: compare(c, kind, m, e, ref, ce, we, sw.budget(kind, test=False, fluid="a0")))
expect("stripedWall a = 0 b_par just beyond its bound", False,
       lambda c: cmp(c, 1.4795 + 3 * A0 + 0.001, 0.0619, 1.4795, 0.0935, 0.0832, A0))
expect("stripedWall a = 0 has no budget for a study it does not run (NaN fails)", False,
       lambda c: cmp(c, 1.4795, 0.0619, 1.4795, 0.0935, 0.0832, sw.budget("the flow turns", test=False, fluid="a0")))
Z = sw.budget("zero flux", test=False, fluid="a25")
broken("stripedWall zero flux at theta 90", lambda c, r, e, b: zero_flux_check(c, 90, r, e, b, sw.BOUND), (-0.008, 0.009, Z), -3 * Z - 0.001, 0.02)
T = sw.budget("the flow turns", test=False, fluid="a25")
broken("stripedWall the flow turns at theta 45", lambda c, r, e, b: turn_check(c, r, e, b, sw.BOUND), (0.050, 0.007, T), 3 * T - 0.001, 0.011)
L = sw.budget("flux linear", test=False, fluid="a25")
lin = lambda c, q2, e2, q1, e1, b: sw.linear(c, "along the stripes", q1, e1, q2, e2, b)
broken("stripedWall flux linear in the force", lin, (7.546, 0.088, 7.625, 0.056, L), 7.625 * (1 - 3 * L) - 0.01, 0.2)
expect("stripedWall flux linear: flux at g zero", False, lambda c: lin(c, 7.546, 0.088, 0.0, 0.056, L))
R = sw.budget("at rest, kT", test=False, fluid="a25")
rest = lambda c, g, ge, n, ne, b: same_at_rest_check(c, "kT", g, ge, n, ne, b, sw.BOUND)
broken("stripedWall kT at rest", rest, (1.0008, 0.0015, 1.0019, 0.0015, R), 1.0019 + 3 * R + 0.001, 0.003)

# slipGammaFw. monotonic_checks(checks, label, gammas, b, errors, step budget, rise budget): the
# full-size 2-D, 3-D and plane-near-the-row sweeps (README) at their full-size budgets.
G = [1, 2, 4.5, 13.5]
mono = lambda label, b, e: (lambda c: sg.slip_falls_checks(c, label, "gamma_fw", G, b, e, *sg.MONOTONIC_BUDGETS[label]["full"]))
two, two_e = [0.4850, 0.4399, 0.4047, 0.2828], [0.013, 0.023, 0.013, 0.011]
expect("slipGammaFw 2-D full size", True, mono("2-D", two, two_e))
expect("slipGammaFw 3-D full size (1 and 2 the same within 0.0106)", True,
       mono("3-D", [0.3928, 0.3946, 0.3758, 0.3166], [0.0075] * 4))
expect("slipGammaFw plane near the row full size", True,
       mono("2-D, plane near the row", [1.909, 1.298, 0.756, 0.207], [0.029, 0.025, 0.015, 0.012]))
step, rise = sg.MONOTONIC_BUDGETS["2-D"]["full"]
for name, value in (("NaN", NAN), ("empty", ""), ("missing", None)):
    expect(f"slipGammaFw 2-D: a slip {name}", False, mono("2-D", [two[0], value] + two[2:], two_e))
    expect(f"slipGammaFw 2-D: an error {name}", False, mono("2-D", two, [two_e[0], value] + two_e[2:]))
expect("slipGammaFw 2-D: no runs", False, mono("2-D", [], []))
expect("slipGammaFw 2-D: a step's error over its budget", False, mono("2-D", two, [0.013, 0.035, 0.013, 0.011]))
expect("slipGammaFw 2-D: the rise's error over its budget", False, mono("2-D", two, [0.02, 0.023, 0.013, 0.02]))
expect("slipGammaFw 2-D: a step down just beyond 3 budgets", False,
       mono("2-D", [0.4850, 0.4399, 0.4399 + 3 * step + 0.001, 0.2828], two_e))
expect("slipGammaFw 2-D: the rise just short of 3 budgets", False,
       mono("2-D", [0.2828 + 3 * rise - 0.001, 0.30, 0.29, 0.2828], two_e))

# slipGammaFw's gap at the wall. gap_checks(checks, [(gap, error)] a variant, (gap, error) standard): the
# full-size depletions of the README (0.354, 0.358 against 0.031; errors ~0.003), then broken.
gaps = lambda variants, standard=(0.031, 0.003): (lambda c: sg.gap_checks(c, variants, standard))
GAPS = [(0.354, 0.003), (0.358, 0.003)]
expect("slipGammaFw gaps full size", True, gaps(GAPS))
for name, value in (("NaN", NAN), ("empty", ""), ("missing", None)):
    expect(f"slipGammaFw gap {name}", False, gaps([(value, 0.003), GAPS[1]]))
    expect(f"slipGammaFw gap error {name}", False, gaps([GAPS[0], (0.358, value)]))
    expect(f"slipGammaFw standard wall's gap {name}", False, gaps(GAPS, (value, 0.003)))
expect("slipGammaFw gap: a variant missing", False, gaps(GAPS[:1]))
expect("slipGammaFw gap: an error over its budget", False, gaps([(0.354, sg.GAP_BUDGET), GAPS[1]]))
expect("slipGammaFw gap: just short of the margin", False, gaps([(0.031 + sg.GAP_MARGIN - 0.001, 0.003), GAPS[1]]))
expect("slipGammaFw gap: just beyond the margin", True, gaps([(0.031 + sg.GAP_MARGIN + 0.001, 0.003), GAPS[1]]))

# dpdfoam.sweep.wall_depletion, the gap those checks read, on a profile built for it: walls at 0 and 10,
# density 3 but half that within 0.5 of each wall, so 0.25 of fluid missing at each; every bin +- 0.03.
import numpy as np  # noqa: E402
from dpdfoam.sweep import wall_depletion  # noqa: E402
z = np.arange(0.025, 10, 0.05)
made = {"z": z, "density": np.where(np.minimum(z, 10 - z) < 0.5, 1.5, 3.0), "densityErr": np.full(z.size, 0.03)}
gap, gap_err = wall_depletion(made, (0.0, 10.0))
# Error: the 10 depleted bins a wall, each 0.5 * 0.05 / 3 * 0.03, in quadrature over 20; the centre's
# 0.03 / 10 (100 bins), times 0.5 * 0.05 * (20 * 1.5) / 3^2.
by_bins, by_centre = 0.5 * 0.05 / 3 * 0.03 * np.sqrt(20), 0.5 * 0.05 * 30 / 9 * 0.003
expect("wall_depletion of the profile made for it", True,
       lambda c: c.add("gap 0.25 and its error", abs(gap - 0.25) < 1e-12 and abs(gap_err - np.hypot(by_bins, by_centre)) < 1e-12,
                       f"{gap} +- {gap_err}", gap, gap_err))

# stripedWall/calibrate.py. rise_checks(checks, gammas, b, err, test): the full-size calibration of the
# README (2026-11-27), then broken: a NaN or missing b or error, an error over its budget, b at the
# stiffest gamma_L just beyond (and just within) 3 budgets above the one before, a sweep of one gamma_L.
CG = [0.05, 0.1, 0.2, 0.5, 1, 2, 4, 8, 16]
CB = [48.31, 25.26, 11.83, 4.66, 2.52, 1.23, 0.66, 0.30, 0.16]
CE = [6.36, 1.21, 0.42, 0.19, 0.14, 0.12, 0.12, 0.10, 0.10]


def replaced(values, k, value):
    return values[:k] + [value] + values[k + 1:]


def rise_bound(b_lo):
    """The stiffer b whose step from b_lo is exactly -3 budgets (bisection: the budget grows with b)."""
    lo, hi = b_lo, b_lo + 100.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        budget = (sc.slip_budget(b_lo, False) ** 2 + sc.slip_budget(mid, False) ** 2) ** 0.5
        lo, hi = (mid, hi) if b_lo - mid > -3 * budget else (lo, mid)
    return lo


rise = sc.rise_checks
expect("stripedWall calibration: b falls with gamma_L (full size)", True, lambda c: rise(c, CG, CB, CE, False))
expect("stripedWall calibration: the same at the test's budgets", True, lambda c: rise(c, CG, CB, CE, True))
for name, value in (("NaN", NAN), ("missing", None)):
    expect(f"stripedWall calibration: b {name}", False, lambda c: rise(c, CG, replaced(CB, 4, value), CE, False))
    expect(f"stripedWall calibration: error {name}", False, lambda c: rise(c, CG, CB, replaced(CE, 5, value), False))
expect("stripedWall calibration: error over its budget", False, lambda c: rise(c, CG, CB, replaced(CE, 0, 30.0), False))
edge = rise_bound(CB[7])
expect("stripedWall calibration: b rises just beyond 3 budgets", False,
       lambda c: rise(c, CG, replaced(CB, 8, edge + 0.001), CE, False))
expect("stripedWall calibration: b rises just within 3 budgets", True,
       lambda c: rise(c, CG, replaced(CB, 8, edge - 0.001), CE, False))
expect("stripedWall calibration: one gamma_L", False, lambda c: rise(c, CG[:1], CB[:1], CE[:1], False))

# speedAccuracy. checks(rows, reference, test): each Verlet-type scheme at its smallest step (standard
# errors within budget, kT within 3 %, pressure within 0.5 % and nu within 10 % plus 4 budgets) and stopped at a
# step of 0.15 or more. Good: two schemes with standard errors in the ranges the full study measured
# (plotResults.py's BUDGETS comment) and errors of the same size.


def study(**changes):
    """Rows of two schemes at dt 0.005 (stable) and 0.15 (stopped); changes: column -> value of DPD-VV's
    smallest step, and stable=True: the largest steps' runs not stopped."""
    rows = {}
    for name in ("GrootWarren0.65", "DPD-VV"):
        small = {"dt": 0.005, "unstable": False, "kT": 0.004, "kTse": 0.003, "P": 0.001, "Pse": 0.0006,
                 "nu": 0.03, "nuse": 0.05, "cost": 1e-6}
        rows[name] = [small, dict(small, dt=0.15, unstable=not changes.get("stable", False))]
    for key, value in changes.items():
        if key != "stable":
            rows["DPD-VV"][0][key] = value
    return rows


REF = ("GrootWarren0.65", 0.0025, 23.6, 0.01, 0.28, 0.005)
expect("speedAccuracy: the full study's numbers", True, lambda c: c.rows.extend(sa.checks(study(), REF, False).rows))
expect("speedAccuracy: the same in test mode", True, lambda c: c.rows.extend(sa.checks(study(), REF, True).rows))
for q, value in (("nu", NAN), ("nuse", NAN), ("kT", NAN), ("Pse", NAN)):
    expect(f"speedAccuracy: {q} NaN", False, lambda c: c.rows.extend(sa.checks(study(**{q: value}), REF, False).rows))
expect("speedAccuracy: nu's error over its budget", False,
       lambda c: c.rows.extend(sa.checks(study(nuse=0.09), REF, False).rows))
for test in (False, True):
    mode = "test mode" if test else "full study"
    for q in ("kT", "P", "nu"):
        edge = sa.BOUNDS[test][q]
        for sign in (1, -1):
            expect(f"speedAccuracy ({mode}): {q} error {sign * (edge + 0.001):+.4f}, just beyond its bound", False,
                   lambda c: c.rows.extend(sa.checks(study(**{q: sign * (edge + 0.001)}), REF, test).rows))
        expect(f"speedAccuracy ({mode}): {q} error {edge - 0.001:+.4f}, just within its bound", True,
               lambda c: c.rows.extend(sa.checks(study(**{q: edge - 0.001}), REF, test).rows))
# The old bounds (level + 4 budgets) let these pass: kT 6 % off, pressure 2 % off.
expect("speedAccuracy: kT 6 % off", False, lambda c: c.rows.extend(sa.checks(study(kT=0.06), REF, False).rows))
expect("speedAccuracy: pressure 2 % off", False, lambda c: c.rows.extend(sa.checks(study(P=0.02), REF, True).rows))
expect("speedAccuracy: the smallest step blew up", False,
       lambda c: c.rows.extend(sa.checks(study(unstable=True), REF, False).rows))
expect("speedAccuracy: dt 0.15 not stopped", False, lambda c: c.rows.extend(sa.checks(study(stable=True), REF, False).rows))
expect("speedAccuracy: no reference run", False, lambda c: c.rows.extend(sa.checks(study(), None, False).rows))

# latticeWall. agreement_check(checks, name, a, b, difference, its error, budget); no_slip_check and
# nu_check; wall_pairs with a run of too few super-blocks.
agree = lambda c, d, s, b: wc.agreement_check(c, "nu", "mask", "lattice", d, s, b)
P = wc.PAIR_BUDGETS["nu"]
broken("latticeWall nu, mask and lattice walls", agree, (0.0027, 0.0027, P), 3 * P + 0.0001, 0.006)
S = wc.SLIP_BOUND
slip = lambda c, b, e, budget: wc.no_slip_check(c, "lower mask wall", b, e, budget)
broken("latticeWall no slip (full size, lattice)", slip, (0.0162, 0.0091, lw.LATTICE_SLIP_BUDGET[0]), S + 0.001, 0.04)
nu = lambda c, v, e, ref, ref_e, b: wc.nu_check(c, "lattice walls", v, e, ref, ref_e, b)
broken("latticeWall nu against no walls (full size)", nu, (0.27376, 0.00021, 0.27490, 0.00091, 0.01), 0.27490 * 1.0301, 0.003)
expect("latticeWall nu: nu without walls missing", False, lambda c: nu(c, 0.27376, 0.00021, None, 0.00091, 0.01))
short = types.SimpleNamespace(too_short="runs sampled 40 blocks of 25: fewer than 5 super-blocks of 2 tau1 = 1200")
expect("latticeWall too few super-blocks: no verdict fails", False, lambda c: wc.wall_pairs(c, [], [short] * 3, 600.0))
# tunableSlip. check(rows, test): the README's full-size rows (a = 0, 2026-11-28); each broken row
# must fail a check: a NaN slip, error or layer density, a slip error over its budget, a slip just
# outside the prediction's bound, a slip of the wrong sign, a halved layer density, no alpha_eff.
TS_FULL = [(0.25, 11.97, 0.17, 0.147, 13.14, 1.4828, 1.4800), (0.5, 5.68, 0.09, 0.295, 6.30, 1.4834, 1.4797),
           (1, 2.71, 0.07, 0.574, 3.01, 1.4858, 1.4779), (2, 1.02, 0.03, 1.168, 1.23, 1.4827, 1.4793),
           (4, 0.30, 0.02, 2.324, 0.37, 1.4776, 1.4796)]


def ts_rows(**changed):
    """The full-size rows, with row gamma_L 0.25's entries replaced by `changed` (key: value)."""
    rows = [dict(gammaL=g, bMeasured=b, bError=e, alphaEff=al, bPredictedEff=bp, rhoNearWall=layer,
                 rhoNearWallIdeal=ideal, rhoNearWallError=0.0021, crossed=0, a=0.0)
            for g, b, e, al, bp, layer, ideal in TS_FULL]
    rows[0].update(changed)
    return rows


def ts_check(rows):
    return lambda c: c.include(ts.check(rows, test=False))


expect("tunableSlip full size", True, ts_check(ts_rows()))
TS_BUDGET = ts.b_error_budget(13.14, test=False)
TS_BOUND = 0.15 * 13.14 + 3 * TS_BUDGET
for what, changed in (("slip NaN", dict(bMeasured=NAN)), ("slip missing", dict(bMeasured=None)),
                      ("slip error NaN", dict(bError=NAN)), ("slip error over its budget", dict(bError=TS_BUDGET + 0.01)),
                      ("slip just below the prediction's bound", dict(bMeasured=13.14 - TS_BOUND - 0.01)),
                      ("slip just above the prediction's bound", dict(bMeasured=13.14 + TS_BOUND + 0.01)),
                      ("slip of the wrong sign", dict(bMeasured=-11.97)), ("alpha_eff NaN", dict(alphaEff=NAN)),
                      ("layer density NaN", dict(rhoNearWall=NAN)), ("layer density halved", dict(rhoNearWall=0.74)),
                      ("layer's error over its budget", dict(rhoNearWallError=0.01)),
                      ("a particle crossed the wall", dict(crossed=1))):
    expect(f"tunableSlip gamma_L 0.25: {what}", False, ts_check(ts_rows(**changed)))
expect("tunableSlip slip just inside the prediction's bound", True,
       ts_check(ts_rows(bMeasured=13.14 - TS_BOUND + 0.01)))
# slipLength. asked_check(checks, where, asked, measured, run error, calibration error): an asked b of
# 1 (bound max(0.15, 10 %) = 0.15, budget 0.075) and of 5 (bound 0.5, budget 0.25) at full size.
sl = load("slipLength", "slipLength")
asked = lambda b: (lambda c, v, e, cal: sl.asked_check(c, f"asking {b}", b, v, e, cal))
broken("slipLength asking 1", asked(1.0), (0.98, 0.03, 0.05), 1.0 + 0.15 + 0.001, 0.1)
broken("slipLength asking 5", asked(5.0), (5.2, 0.1, 0.1), 5.0 - 0.5 - 0.001, 0.3)
expect("slipLength asking 0: just inside the bound", True, lambda c: asked(0.0)(c, -0.149, 0.03, 0.05))
expect("slipLength asking 0: calibration error NaN", False, lambda c: asked(0.0)(c, 0.0, 0.03, NAN))
# contraction (tutorials/contraction, dpdfoam.contraction.flow_checks(checks, rows, mean kT, inside,
# kT error, test mode, what)): the ramp at full size (README: fluxes 52.64-52.68 +- 0.06-0.12, kT
# 1.0041) and its test mode (2026-11-30: 11.52-11.62 +- 0.14-0.24, kT 1.00423 +- 0.00057).
from dpdfoam import contraction as ct
FULL = [52.65, 52.65, 52.66, 52.64, 52.68], [0.12, 0.12, 0.06, 0.11, 0.12]
TEST = [11.6077, 11.6204, 11.5204, 11.5888, 11.591], [0.241, 0.229, 0.135, 0.231, 0.231]
flow = lambda fluxes, errors, kT=1.0041, kT_error=0.0002, inside=0, test=False: (
    lambda c: ct.flow_checks(c, [(0.0, f, e) for f, e in zip(fluxes, errors)], kT, inside, kT_error, test, "fluid"))
expect("contraction full size", True, flow(*FULL))
expect("contraction test mode", True, flow(*TEST, kT=1.00423, kT_error=0.00057, test=True))
for name, value in (("NaN", NAN), ("missing", None)):
    expect(f"contraction kT {name}", False, flow(*FULL, kT=value))
    expect(f"contraction kT error {name}", False, flow(*FULL, kT_error=value))
expect("contraction kT error over its budget", False, flow(*FULL, kT_error=ct.KT_BUDGET + 0.0001))
expect("contraction kT just above its bound", False, flow(*FULL, kT=1.0 + ct.KT_BOUND + 0.0005))
expect("contraction kT just below its bound", False, flow(*FULL, kT=1.0 - ct.KT_BOUND - 0.0005))
expect("contraction kT 2 % off (passed the old 3 % bound)", False, flow(*FULL, kT=1.02))
expect("contraction a section's flux halved", False, flow([52.65, 26.3, 52.66, 52.64, 52.68], FULL[1]))
expect("contraction a section's flux NaN", False, flow([52.65, NAN, 52.66, 52.64, 52.68], FULL[1]))
expect("contraction full size: a section 1 % off", False, flow([52.65, 53.18, 52.66, 52.64, 52.68], FULL[1]))
expect("contraction test: a section 3 % off (passed the old 25 %)", False,
       flow([11.6, 11.95, 11.6, 11.6, 11.6], TEST[1], kT=1.004, kT_error=0.0006, test=True))
expect("contraction test: a section's error over its budget", False,
       flow(TEST[0], [0.241, 0.229, 0.135, 0.5, 0.231], kT=1.004, kT_error=0.0006, test=True))
expect("contraction a particle inside the solid", False, flow(*FULL, inside=1))
expect("contraction no flow", False, flow([-0.01] * 5, [0.001] * 5))
print_summary()
EOF
)
echo "$out"
echo "$out" | grep -q '^0 wrong$' || fail "every broken input fails and every good value passes ($(echo "$out" | grep -c '^WRONG') wrong)"
[ "$(echo "$out" | grep -c '^ok ')" -ge 80 ] || fail "fewer expectations ran than written"
finishTests checkBounds
