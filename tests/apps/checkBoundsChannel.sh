#!/bin/bash
# Issue 45's rule on broken inputs, on the check functions of the channel tutorials checkBounds.sh does
# not cover (no simulation, no executables: plain numbers): tutorials/channel/couetteSlip (the shear
# stress flat, nu against the fluid without walls, kT against the set kT plus the viscous heating, the
# slip's growth with a_wf, the calibrated wall's no slip), tutorials/channel/poiseuille (scene 1: nu, the
# bulk kT, the density flat, no slip, the FCC channel against its simpleFoam twin),
# tutorials/channel/slipSensitivity (each ingredient's change decided) and the density peak of
# tutorials/channel/slipLength. Each check must fail for a NaN, an empty or a missing value, a standard
# error over its budget and a value just outside its fixed bound (which a standard error within budget
# no longer widens), and pass for a good value: the full-size numbers the tutorials' READMEs record, at
# the full-size budgets (and the test mode's kept numbers at the test's budgets).
#   $1: the directory of the executables (unused), $2: the source directory
set -u
src=$2
. "$src/tests/shellTestFunctions" || exit 1
python=/usr/bin/python3
# Required dependencies (the tutorials' scripts import them): a missing one fails the test (no skip).
requirePython "$python" numpy matplotlib h5py || finishTests checkBoundsChannel

out=$(PYTHONPATH="$src/tests/apps:$src/etc/python" PYTHONDONTWRITEBYTECODE=1 MPLBACKEND=Agg "$python" - "$src" 2>&1 <<'EOF'
import sys

from boundcheck import NAN, broken, expect, print_summary, tutorial_loader

load = tutorial_loader(sys.argv[1], "channel")
cs, pz = load("couetteSlip", "couetteSlip"), load("poiseuilleScene1", "poiseuille")
ss, sl = load("slipSensitivity", "slipSensitivity"), load("slipLength", "slipLength")


# ---- couetteSlip ------------------------------------------------------------------------------------
# stress_flat_check(checks, a_ww, largest slab deviation, a slab's largest error, budget): the README's
# full-size deviations (published scene 2.1 %, calibrated wall 1.0-1.9 %, no-slip wall 0.7-0.9 %) with
# the slab error the test's (1.5-1.7 %, kept run of 2026-11-30) scales to at full size (~0.65 %); the
# test's kept figures at the test's budget; the bound 5 %.
FB, FT = cs.FLAT_BUDGETS[False], cs.FLAT_BUDGETS[True]
flat = lambda c, f, e, b: cs.stress_flat_check(c, 5, f, e, b)
broken("couetteSlip stress flat (full size)", flat, (0.021, 0.0065, FB), cs.FLAT_BOUND + 0.001, FB + 0.001)
expect("couetteSlip stress flat: the test's 1.34 % +- 1.60 %", True, lambda c: flat(c, 0.0134, 0.0160, FT))
expect("couetteSlip stress flat: the test's no-slip wall 2.63 % +- 1.74 %", True, lambda c: flat(c, 0.0263, 0.0174, FT))
expect("couetteSlip stress flat just inside the bound", True, lambda c: flat(c, cs.FLAT_BOUND - 0.001, 0.0065, FB))
expect("couetteSlip stress flat: 4 % +- 3 % (passed the old rule, no budget)", False, lambda c: flat(c, 0.04, 0.03, FT))
expect("couetteSlip stress flat: budget NaN", False, lambda c: flat(c, 0.021, 0.0065, NAN))
# nu_checks(checks, a_ww, nu, error, nu without walls, error, budget): the published scene at full size
# (README 2026-11-27: 0.2772 +- 0.0019 against 0.2714 +- 0.0037, +2.1 %, combined 1.6 %).
NB = cs.NU_BUDGETS[False]
nu = lambda c, v, e, ref, ref_e, b: cs.nu_checks(c, 5, v, e, ref, ref_e, b)
broken("couetteSlip nu against no walls (full size)", nu, (0.2772, 0.0019, 0.2714, 0.0037, NB),
       0.2714 * (1 + cs.NU_BOUND) + 0.0002, 0.006)
expect("couetteSlip nu just inside the bound", True, lambda c: nu(c, 0.2714 * (1 + cs.NU_BOUND) - 0.0002, 0.0019, 0.2714, 0.0037, NB))
expect("couetteSlip nu 10 % wrong", False, lambda c: nu(c, 0.2714 * 1.1, 0.0019, 0.2714, 0.0037, NB))
expect("couetteSlip nu: nu without walls missing", False, lambda c: nu(c, 0.2772, 0.0019, None, 0.0037, NB))
expect("couetteSlip nu: nu without walls' error NaN", False, lambda c: nu(c, 0.2772, 0.0019, 0.2714, NAN, NB))
expect("couetteSlip nu: the test's +2.99 % (combined 1.86 %)", True,
       lambda c: nu(c, 0.2730, 0.0039, 0.2650, 0.0029, cs.NU_BUDGETS[True]))
# kT_check(checks, a_ww, mean kT, error, expected, its error, heating, budget): the published scene at
# full size (README: 1.0028 against 1.0014; the error the test's 0.0012 scales to, ~0.0002, the heating's
# ~0.00003), bound 1 %; the test's kept figures at the test's budget.
KB = cs.KT_BUDGETS[False]
kT = lambda c, v, e, x, xe, b: cs.kT_check(c, 5, v, e, x, xe, 0.0014, b)
broken("couetteSlip kT against the heating (full size)", kT, (1.0028, 0.0002, 1.0014, 0.00003, KB),
       1.0014 * (1 + cs.KT_BOUND) + 0.0002, 0.0015)
expect("couetteSlip kT just inside the bound", True, lambda c: kT(c, 1.0014 * (1 + cs.KT_BOUND) - 0.0002, 0.0002, 1.0014, 0.00003, KB))
expect("couetteSlip kT just below the bound", False, lambda c: kT(c, 1.0014 * (1 - cs.KT_BOUND) - 0.0002, 0.0002, 1.0014, 0.00003, KB))
expect("couetteSlip kT 2 % off", False, lambda c: kT(c, 1.0214, 0.0002, 1.0014, 0.00003, KB))
expect("couetteSlip kT: expected kT missing", False, lambda c: kT(c, 1.0028, 0.0002, None, 0.00003, KB))
expect("couetteSlip kT: the heating's error over the budget", False, lambda c: kT(c, 1.0028, 0.0002, 1.0014, 0.0015, KB))
expect("couetteSlip kT: the test's 1.0196 +- 0.0012 against 1.0121 +- 0.0004", True,
       lambda c: kT(c, 1.0196, 0.0012, 1.0121, 0.0004, cs.KT_BUDGETS[True]))
expect("couetteSlip kT: 0.9 % off +- 0.5 % (passed the old rule, no budget)", False,
       lambda c: kT(c, 1.0014 * 1.009, 0.005, 1.0014, 0.00003, cs.KT_BUDGETS[True]))
# growth_checks(checks, a_wf, b, errors, step budget, rise budget): the README's full-size sweeps at their
# budgets (growth_budgets): the published scene (2026-11-27), the calibrated wall (2026-11-25), the
# no-slip wall (2026-11-24: 0.066 +- 0.024 at a_ww 5, the steps' errors 0.03-0.04); the test's one step.
A_WF = [9.68, 13.69, 16.77, 19.36, 21.65]
PUB = [0.295, 0.714, 1.543, 2.765, 3.851], [0.033, 0.074, 0.081, 0.204, 0.240]
CAL = [0.219, 0.438, 1.011, 1.840, 2.716], [0.032, 0.058, 0.069, 0.104, 0.104]
NOSLIP = [0.066, 0.110, 0.144, 0.233, 0.366], [0.024, 0.026, 0.026, 0.028, 0.028]
grow = lambda b, e, scene=None, test=False, a_wf=A_WF: (
    lambda c: cs.growth_checks(c, a_wf, b, e, *cs.growth_budgets(scene, test)))
expect("couetteSlip growth: published scene full size", True, grow(*PUB))
expect("couetteSlip growth: calibrated wall full size", True, grow(*CAL, "-calibratedWall"))
expect("couetteSlip growth: no-slip wall full size (a step of 0.034 +- 0.037)", True, grow(*NOSLIP, "-noSlipWall"))
expect("couetteSlip growth: the test's 5 -> 25, +3.255 +- 0.097", True,
       grow([0.1990, 3.4543], [0.0554, 0.0794], test=True, a_wf=[9.68, 21.65]))
expect("couetteSlip growth: the test's variants have no budget (NaN fails)", False,
       grow([0.1990, 3.4543], [0.0554, 0.0794], "-noSlipWall", True, [9.68, 21.65]))


def replaced(values, k, value):
    return values[:k] + [value] + values[k + 1:]


step, rise = cs.growth_budgets(None, False)
for name, value in (("NaN", NAN), ("empty", ""), ("missing", None)):
    expect(f"couetteSlip growth: a slip {name}", False, grow(replaced(PUB[0], 2, value), PUB[1]))
    expect(f"couetteSlip growth: an error {name}", False, grow(PUB[0], replaced(PUB[1], 3, value)))
    expect(f"couetteSlip growth: an a_wf {name}", False, grow(*PUB, a_wf=replaced(A_WF, 1, value)))
expect("couetteSlip growth: no runs", False, grow([], []))
expect("couetteSlip growth: one run", False, grow([0.295], [0.033], a_wf=[9.68]))
expect("couetteSlip growth: a slip length missing from the list", False, grow(PUB[0][:4], PUB[1]))
expect("couetteSlip growth: a step's error over its budget", False, grow(PUB[0], replaced(PUB[1], 3, 0.36)))
expect("couetteSlip growth: the rise's error over its budget", False, grow(PUB[0], replaced(PUB[1], 4, 0.31)))
expect("couetteSlip growth: a step down just beyond 3 budgets", False,
       grow(replaced(PUB[0], 3, 1.543 - 3 * step - 0.001), PUB[1]))
expect("couetteSlip growth: a step down just within 3 budgets", True,
       grow(replaced(PUB[0], 3, 1.543 - 3 * step + 0.001), PUB[1]))
expect("couetteSlip growth: the rise just short of 3 budgets", False,
       grow([0.295, 0.4, 0.6, 0.9, 0.295 + 3 * rise - 0.001], PUB[1]))
expect("couetteSlip growth: the rise just beyond 3 budgets", True,
       grow([0.295, 0.4, 0.6, 0.9, 0.295 + 3 * rise + 0.001], PUB[1]))
expect("couetteSlip growth: the slip falling with a_wf (wrong sign)", False, grow(PUB[0][::-1], PUB[1][::-1]))
expect("couetteSlip growth: the runs in the other order (a_wf falling too)", True, grow(PUB[0][::-1], PUB[1][::-1], a_wf=A_WF[::-1]))
expect("couetteSlip growth: 0.30 -> 0.35 +- 0.3 each (passed the old sign rule)", False,
       grow([0.30, 0.35], [0.3, 0.3], a_wf=[9.68, 21.65]))
# no_slip_checks(checks, a_ww, b, error, (b lower, b upper)): the no-slip wall at full size (README:
# 0.066 +- 0.024, walls 0.051 and 0.081), |b| < 0.1 once the error is within 0.03.
ns = lambda c, b, e: cs.no_slip_checks(c, 5, b, e, (0.051, 0.081))
broken("couetteSlip no-slip wall (full size)", ns, (0.066, 0.024), cs.NO_SLIP_BOUND + 0.001, cs.NO_SLIP_BUDGET + 0.001)
expect("couetteSlip no-slip wall: the wrong sign just outside", False, lambda c: ns(c, -cs.NO_SLIP_BOUND - 0.001, 0.024))
expect("couetteSlip no-slip wall: the test's 0.030 +- 0.024", True, lambda c: ns(c, 0.0303, 0.0236))

# ---- poiseuille (scene 1) ---------------------------------------------------------------------------
# The README's full size (2026-11-27, four seeds): FCC nu 0.27109 +- 0.00011 against 0.27490 +- 0.00091.
pnu = lambda c, v, e, ref, ref_e: pz.nu_check(c, "FCC", v, e, ref, ref_e)
broken("poiseuille FCC nu against no walls (full size)", pnu, (0.27109, 0.00011, 0.27490, 0.00091), 0.27490 * 0.97 - 0.0001, 0.003)
expect("poiseuille random nu (full size)", True, lambda c: pnu(c, 0.27131, 0.00030, 0.27490, 0.00091))
expect("poiseuille nu 10 % wrong", False, lambda c: pnu(c, 0.27490 * 0.9, 0.00011, 0.27490, 0.00091))
expect("poiseuille nu: nu without walls missing", False, lambda c: pnu(c, 0.27109, 0.00011, None, 0.00091))
# Bulk kT minus the no-wall box's: -0.0017 +- 0.0004 (FCC), -0.0020 +- 0.0002 (random); tolerance 1 %.
pkT = lambda c, d, e, kT_set: pz.bulk_kT_check(c, "FCC", d, e, kT_set, 0.01)
broken("poiseuille FCC bulk kT (full size)", pkT, (-0.0017, 0.0004, 1.0), -0.0101, 0.0034)
expect("poiseuille bulk kT: set kT missing", False, lambda c: pkT(c, -0.0017, 0.0004, None))
# The density's largest deviation beyond one cutoff: FCC 4.16 % (a bin's error at most 0.27 %), random
# 2.17 % (0.26 %) at full size; the test's 4.53 % (0.62 %) at its budget.
PB = pz.FLAT_BUDGETS[False]
pflat = lambda c, f, e, b: pz.flat_check(c, "FCC", f, e, b)
broken("poiseuille FCC density flat (full size)", pflat, (0.0416, 0.0027, PB), pz.FLAT_BOUND + 0.0005, PB + 0.0005)
expect("poiseuille random density flat (full size)", True, lambda c: pflat(c, 0.0217, 0.0026, PB))
expect("poiseuille FCC density flat: the test's 4.53 % +- 0.62 %", True, lambda c: pflat(c, 0.0453, 0.0062, pz.FLAT_BUDGETS[True]))
expect("poiseuille density flat: 4.9 % +- 2 % (passed the old rule, no budget)", False,
       lambda c: pflat(c, 0.049, 0.02, pz.FLAT_BUDGETS[True]))
# No slip: FCC -0.0005 +- 0.0046, random +0.0092 +- 0.0041; |b| < 0.1, the error within 0.1 / 3.
pslip = lambda c, b, e: pz.no_slip_check(c, "FCC", b, e)
broken("poiseuille FCC no slip (full size)", pslip, (-0.0005, 0.0046), 0.1001, 0.0334)
expect("poiseuille random no slip (full size)", True, lambda c: pslip(c, 0.0092, 0.0041))
expect("poiseuille no slip: the wrong sign just outside", False, lambda c: pslip(c, -0.1001, 0.0046))
# The FCC channel against its twin: L2 0.0148 (noise 0.0009) at full size, 0.0118 (0.0061) in the test.
TB = pz.TWIN_BUDGETS[False]
twin = lambda c, l2, noise, b: pz.twin_check(c, l2, noise, b)
broken("poiseuille FCC twin (full size)", twin, (0.0148, 0.0009, TB), pz.TWIN_BOUND + 0.0001, TB + 0.0001)
expect("poiseuille FCC twin: the test's 0.0118 (noise 0.0061)", True, lambda c: twin(c, 0.0118, 0.0061, pz.TWIN_BUDGETS[True]))
expect("poiseuille FCC twin: the DPD flux halved (L2 0.5)", False, lambda c: twin(c, 0.5, 0.0009, TB))

# ---- slipSensitivity --------------------------------------------------------------------------------
# decided(checks, name, change, error, budget): found (|change| >= 3 errors) or its error within the
# budget (a third of the difference to explain). The README's full-size changes: scene 3 at 0.15, scene 2
# at scene2_budget (0.485 at gamma_fw 1, 0.094 at 13.5).
D = 0.15
dec = lambda change, error, budget=D: (lambda c: ss.decided(c, "ingredient", change, error, budget))
for name, change, error in (("halfStep", 0.026, 0.134), ("lambda05, 2000 time units", -0.042, 0.113),
                            ("denseWall", 3.050, 0.366), ("sparseWall", -1.386, 0.114), ("layersOnPlane", 0.256, 0.143),
                            ("labFrame", 7.856, 0.221), ("bounceBack", 0.014, 0.144), ("fitRange", 0.050, 0.129)):
    expect(f"slipSensitivity full size {name}: {change:+g} +- {error:g}", True, dec(change, error))
for name, g, change, error in (("specular", 1, 6.296, 0.041), ("specular", 13.5, 0.152, 0.020),
                               ("maxwellian", 1, 0.473, 0.028), ("maxwellian", 13.5, 0.055, 0.021),
                               ("planeOnRow", 1, 2.601, 0.048), ("planeOnRow", 13.5, -0.198, 0.018),
                               ("staggeredRows", 1, 0.007, 0.018), ("staggeredRows", 13.5, 0.038, 0.016)):
    expect(f"slipSensitivity scene 2 full size {name} at gamma_fw {g:g}", True, dec(change, error, ss.scene2_budget(g, False)))
expect("slipSensitivity lambda05 over 800 time units, +0.062 +- 0.181 (README: not decided)", False, dec(0.062, 0.181))
expect("slipSensitivity the test's halfStep +0.172 +- 0.194", True, dec(0.1722, 0.1944, ss.SCENE2_TEST_BUDGET))
for name, value in (("NaN", NAN), ("empty", ""), ("missing", None)):
    expect(f"slipSensitivity change {name}", False, dec(value, 0.134))
    expect(f"slipSensitivity error {name} (a change of 3.05)", False, dec(3.050, value))
    expect(f"slipSensitivity budget {name}", False, dec(0.026, 0.134, value))
expect("slipSensitivity scene 2 at a gamma_fw the study does not state (no budget)", False,
       dec(0.007, 0.018, ss.scene2_budget(4.5, False)))
expect("slipSensitivity error over its budget, the change under 3 errors", False, dec(0.3, D + 0.001))
expect("slipSensitivity error over its budget, the change just short of 3 errors", False, dec(0.599, 0.2))
expect("slipSensitivity error over its budget, the change just beyond 3 errors (found)", True, dec(0.601, 0.2))
expect("slipSensitivity a found change of the wrong sign is still found", True, dec(-0.601, 0.2))

# ---- slipLength's density peak ----------------------------------------------------------------------
# peak_check(checks, where, peak, its error, bulk, its error, budget): full size (2026-11-29, planes
# asking 0): peak 3.305 +- 0.0034 against 3.0155 +- 0.0011, ratio 1.096 +- 0.0012; bound 1.2.
SB = sl.PEAK_BUDGETS[False]
peak = lambda c, p, pe, b, be, budget: sl.peak_check(c, "asking 0", p, pe, b, be, budget)
broken("slipLength density peak (full size)", peak, (3.305, 0.0034, 3.0155, 0.0011, SB),
       sl.PEAK_BOUND * 3.0155 + 0.001, 0.02)
expect("slipLength density peak: Couette at full size, 1.074", True, lambda c: peak(c, 3.2384, 0.0022, 3.0151, 0.0008, SB))
expect("slipLength density peak: the test's 1.096 +- 0.0021", True,
       lambda c: peak(c, 3.3040, 0.0059, 3.0158, 0.0021, sl.PEAK_BUDGETS[True]))
expect("slipLength density peak just inside the bound", True, lambda c: peak(c, sl.PEAK_BOUND * 3.0155 - 0.001, 0.0034, 3.0155, 0.0011, SB))
expect("slipLength density peak: bulk missing", False, lambda c: peak(c, 3.305, 0.0034, None, 0.0011, SB))
expect("slipLength density peak: bulk's error NaN", False, lambda c: peak(c, 3.305, 0.0034, 3.0155, NAN, SB))
expect("slipLength density peak: the bulk halved", False, lambda c: peak(c, 3.305, 0.0034, 1.508, 0.0011, SB))
expect("slipLength density peak: 1.15 +- 0.03 (passed the old rule, no budget)", False,
       lambda c: peak(c, 3.468, 0.09, 3.0155, 0.0011, sl.PEAK_BUDGETS[True]))
print_summary()
EOF
)
echo "$out"
echo "$out" | grep -q '^0 wrong$' || fail "every broken input fails and every good value passes ($(echo "$out" | grep -c '^WRONG') wrong)"
[ "$(echo "$out" | grep -c '^ok ')" -ge 120 ] || fail "fewer expectations ran than written"
finishTests checkBoundsChannel
