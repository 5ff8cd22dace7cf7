"""dpdfoam.slip: calibrations, striped walls' references and their checks, a stripeGrid's first layer.

The C++ tools the module runs (slipCalibration, stripedSlip) are replaced by stand-ins printing their
format (tools/SlipCalibrationTool.cpp, tools/StripedSlipTool.cpp) from a known rule, so that what the
module makes of their answers can be computed by hand: the calibrated walls only for asked slips
inside [0, largestSlip], bracketed only from smallestSlip on; the striped reference shifted by the
no-slip sectors' residual slip b0 (b - b0 in a channel 2 b0 higher, plus b0), its anisotropy free of
the added b0, its calibration error the two half-spreads in quadrature (derivatives of the linear rule), b_eff
= b_par cos^2 + b_perp sin^2. The checks built on them pass a value within bound x budget and fail
one just outside, an error at its budget, a NaN and a missing value. The calibration's lines, the
fall of b with gamma_L (one decisive rise fails, a single gamma_L fails), the no-slip friction
(bracketed, saturated or none), the log's slip choices and a slipTensor sweep's walls' mean slips
come out as written. On a stripeGrid table built with a packed first layer, its depth, its
mass-weighted velocity and the planted 20 % excess downstream over the gas sectors are recovered.
"""
import math
import os
import unittest

import numpy as np

from dpdfoam.checks import Checks
from dpdfoam.slip import (StripedReference, anisotropy_check, asked_slip_measured, bracketed_frictions, calibrated_walls,
                          calibration_lines, distance_to_walls, first_layer, first_layers, gas_sectors, near_wall_sectors,
                          no_slip_friction, principal_slip_checks, read_calibration_runs, read_slip_tensor, reference_check,
                          run_force, run_value, same_at_rest_check, slip_choices, slip_not_rising_checks, stiff_end,
                          striped_slip, turn_check, zero_flux_check)
from dpdtest_support import dictionary_text, fake_tool, Temporary, write_fit, write_table, write_text

NAN = float("nan")

# slipCalibration's stand-in: wallOffset 0.4 +- 0.05, range 0.2 .. 3; gamma_L = 2 / b, error 0.01 + 0.02 b,
# the plane at the wall offset; below 0.2 the stiffest friction (gamma_L 10) moved out by 0.2 - b.
SLIP_CALIBRATION = r'''
import sys
args = sys.argv[1:]
if args[:1] != ["-file"] or len(args) < 2:
    sys.exit("usage")
if "broken" in args[1]:
    sys.stderr.write("cannot read " + args[1] + "\n")
    sys.exit(1)
print('calibration     "%s";' % args[1])
print("wallOffset      0.4;\nwallOffsetError 0.05;\nsmallestSlip    0.2;\nlargestSlip     3;")
if len(args) > 2:
    assert args[2] == "-slipLength"
    b = [float(v) for v in args[3:]]
    if any(x < 0 or x > 3 for x in b):
        sys.stderr.write("-slipLength: outside the calibration\n")
        sys.exit(1)
    gamma = [2.0 / x if x >= 0.2 else 10.0 for x in b]
    plane = [0.4 if x >= 0.2 else 0.4 - (0.2 - x) for x in b]
    for name, values in (("slipLength", b), ("gammaL", gamma), ("slipLengthError", [0.01 + 0.02 * x for x in b]),
                         ("planeOffset", plane), ("slipLeft", [x + 0.4 - p for x, p in zip(b, plane)])):
        print("%-16s(%s);" % (name, " ".join(repr(v) for v in values)))
'''

# stripedSlip's stand-in: a rule linear in the local slip s and the height h (f the gas fraction):
# b_par = 0.5 s + 0.02 h + f, b_perp = 0.25 s + 0.01 h, transverse flux ratio 0.001 angle s + 0.0001 h.
STRIPED_SLIP = r'''
import sys
a = dict(zip(sys.argv[1::2], sys.argv[2::2]))
s, h, f = float(a["-slip"]), float(a["-height"]), float(a["-gasFraction"])
assert a["-walls"] == "2"
print("period          %s;\ngasFraction     %s;" % (a["-period"], f))
print("localSlip       %r;\nheight          %r;\nstripedWalls    2;" % (s, h))
par, perp = 0.5 * s + 0.02 * h + f, 0.25 * s + 0.01 * h
print("slipParallel    %r;\nslipPerpendicular %r;" % (par, perp))
for angle in a["-angles"].split(","):
    print("angle%s { slip %r; transverseFluxRatio %r; }" % (angle, par, 0.001 * float(angle) * s + 0.0001 * h))
'''


def par(b, r, height=20.0, f=0.5):
    """The stand-in's b_par of a striped wall of local slip b with residual r (the module's shift)."""
    return 0.5 * (b - r) + 0.02 * (height + 2 * r) + f + r


def perp(b, r, height=20.0):
    return 0.25 * (b - r) + 0.01 * (height + 2 * r) + r


class Calibration(Temporary):
    def test_calibrated_walls(self):
        with fake_tool(self.tmp, "slipCalibration", SLIP_CALIBRATION):
            summary, walls = calibrated_walls("cal.dat", [-0.5, 0.0, 0.1, 1.0, 3.0, 3.5])
            bracketed = bracketed_frictions("cal.dat", [0.1, 0.2, 2.0, 4.0])
        self.assertEqual((summary["smallestSlip"], summary["largestSlip"], summary["wallOffset"]), (0.2, 3.0, 0.4))
        self.assertIsNone(walls[0])
        self.assertIsNone(walls[5])
        self.assertEqual(walls[1]["gammaL"], 10.0)
        self.assertAlmostEqual(walls[2]["slipLeft"], 0.2, places=12)  # the stiffest wall leaves its own slip
        self.assertEqual(sorted(walls[3]), ["gammaL", "planeOffset", "slipLeft", "slipLengthError"])
        for key, value in (("gammaL", 2.0), ("slipLengthError", 0.03), ("planeOffset", 0.4), ("slipLeft", 1.0)):
            self.assertAlmostEqual(walls[3][key], value, places=12)
        self.assertAlmostEqual(walls[4]["gammaL"], 2.0 / 3.0, places=9)
        self.assertIsNone(bracketed[0])
        self.assertEqual(bracketed[1], (10.0, 0.014))
        self.assertEqual(bracketed[2], (1.0, 0.05))
        self.assertIsNone(bracketed[3])

    def test_tool_failure_exits(self):
        with fake_tool(self.tmp, "slipCalibration", SLIP_CALIBRATION):
            with self.assertRaises(SystemExit):
                calibrated_walls("broken.dat", [1.0])

    def test_read_calibration_runs_and_lines(self):
        d = os.path.join(self.tmp, "calibration")
        write_text(os.path.join(d, "hydrodynamicWall.dat"), dictionary_text(
            {"slipLength": [0.5, 2.0, 1.0], "slipLengthError": [0.01, 0.04, 0.02], "apparentSlipCouette": [0.6, 2.1, 1.1],
             "apparentSlipPoiseuille": [0.55, 2.05, 1.05], "chi2PerDof": 1.1, "dof": 12.0}))
        write_text(os.path.join(d, "sweepPoiseuille", "sweep.dat"), "# case walls/lower/tunableSlip/gammaL\nr1 8\nr2 0.5\nr3 2\n")
        fit, gammas = read_calibration_runs(d)
        np.testing.assert_array_equal(gammas, [8.0, 0.5, 2.0])
        self.assertIsInstance(fit["slipLength"], np.ndarray)
        lines = calibration_lines(gammas, fit)
        self.assertEqual(len(lines), 5)
        self.assertEqual([float(line.split()[0]) for line in lines[1:4]], [0.5, 2.0, 8.0])  # by gamma_L
        self.assertEqual(lines[1].split()[1:4], ["+2.0000", "+-", "0.0400"])
        self.assertIn("1.100 (12 dof)", lines[-1])

    def test_slip_not_rising(self):
        gammas, err = [0.5, 2.0, 8.0], [0.01, 0.01, 0.01]
        budget = lambda b: 0.02  # noqa: E731  (both ends: hypot 0.028, bound -0.085)
        c = Checks()
        slip_not_rising_checks(c, gammas, [2.0, 1.0, 0.5], err, budget)
        self.assertEqual((len(c.rows), c.status()), (2, 0))
        c = Checks()
        slip_not_rising_checks(c, gammas, [2.0, 1.0, 1.0 + 0.08], err, budget)  # a rise within the bound
        self.assertEqual(c.status(), 0)
        c = Checks()
        slip_not_rising_checks(c, gammas, [2.0, 1.0, 1.1], err, budget)  # a decisive rise
        self.assertEqual(c.failures(), [c.rows[1][0]])
        c = Checks()
        slip_not_rising_checks(c, gammas, [2.0, NAN, 0.5], err, budget)
        self.assertEqual(len(c.failures()), 2)
        c = Checks()
        slip_not_rising_checks(c, gammas, [2.0, 1.0, 0.5], [0.01, 0.03, 0.01], budget)  # too noisy to decide
        self.assertEqual(len(c.failures()), 2)
        c = Checks()
        slip_not_rising_checks(c, [1.0], [1.0], [0.01], budget)
        self.assertEqual(c.status(), 1)

    def test_stiff_end_and_no_slip_friction(self):
        gammas, b, err = np.array([8.0, 0.5, 2.0]), np.array([0.1, 2.0, 0.15]), np.array([0.02, 0.02, 0.02])
        stiff, step, se = stiff_end(gammas, b, err)
        self.assertEqual(stiff, 0)
        self.assertAlmostEqual(step, 0.05, places=14)
        self.assertAlmostEqual(se, math.hypot(0.02, 0.02), places=14)
        self.assertEqual(no_slip_friction((5.0, 0.03), gammas, b, err), (5.0, 0.0, 0.03))
        self.assertEqual(no_slip_friction(None, gammas, b, err), (8.0, 0.1, 0.02))  # saturated: 0.05 < 3 x 0.028
        self.assertIsNone(no_slip_friction(None, gammas, np.array([0.1, 2.0, 0.3]), err))  # still falling


class Logs(Temporary):
    def case(self):
        case = os.path.join(self.tmp, "case")
        write_text(os.path.join(case, "log.dpdFoamLike"),
                   "Walls          : 2\n"
                   "Slip length    : wall lower: slipLength 0.5 from calibration/slip.dat: gammaL 4 (b +- 0.02 there), acting "
                   "0.35 +- 0.05 behind where the wall was put\n"
                   "Slip length    : wall upper: slipLength 0.1 from calibration/slip.dat: gammaL 10 (b +- 0.01 there), acting "
                   "0.25 +- 0.05 behind where the wall was put (below the calibrated 0.2: the stiffest wall, moved 0.1 out)\n")
        return case

    def test_slip_choices(self):
        self.assertEqual(slip_choices(self.case()), [(4.0, 0.02, 0.35, 0.05), (10.0, 0.01, 0.25, 0.05)])

    def test_asked_slip_measured(self):
        case = self.case()
        write_fit(case, {"slipLength": [0.4, 0.6], "slipLengthError": [0.03, 0.04]})
        b, run_error, calibration_error, walls = asked_slip_measured(case)
        self.assertAlmostEqual(b, 0.5, places=14)
        self.assertAlmostEqual(run_error, 0.025, places=14)
        self.assertEqual(calibration_error, 0.02)
        self.assertEqual(len(walls), 2)

    def test_asked_slip_missing(self):
        case = os.path.join(self.tmp, "other")
        write_text(os.path.join(case, "log.dpdFoamLike"), "no walls asking a slip\n")
        write_fit(case, {"nu": 0.3})
        b, run_error, calibration_error, walls = asked_slip_measured(case)
        self.assertTrue(math.isnan(b) and math.isnan(run_error) and math.isnan(calibration_error))
        self.assertEqual(walls, [])


class SlipTensorSweep(Temporary):
    def test_read_slip_tensor(self):
        path = write_text(os.path.join(self.tmp, "sweep.dat"),
                          "# case theta bodyForce/value slipParallel_0 slipParallel_1 slipParallelError_0 slipParallelError_1 "
                          "slipPerpendicular_0 slipPerpendicular_1 slipPerpendicularError_0 slipPerpendicularError_1 "
                          "slipEffective slipEffectiveError\n"
                          "t0 0 (0.03,0,0) 1.0 1.2 0.06 0.08 0.5 0.7 0.03 0.04 1.1 0.05\n"
                          "t45 44.999999 (0.0212132,0.0212132,0) 1.1 1.3 0.06 0.08 0.6 0.6 0.03 0.04 0.85 0.05\n")
        s = read_slip_tensor(path, offset=0.25)
        np.testing.assert_allclose(s["bParallel"], [1.35, 1.45])
        np.testing.assert_allclose(s["bParallelError"], [0.05, 0.05])
        np.testing.assert_allclose(s["bPerpendicular"], [0.85, 0.85])
        np.testing.assert_allclose(s["bEffective"], [1.35, 1.1])
        self.assertEqual(s["angle"], [0.0, 45.0])
        self.assertEqual(run_value(s, "bPerpendicular", 1), (0.85, 0.025))
        self.assertAlmostEqual(run_force(s, 1), 0.03, places=6)


class Striped(Temporary):
    def reference(self, slip=2.0, slip_error=0.1, residual=(0.3, 0.05)):
        with fake_tool(self.tmp, "stripedSlip", STRIPED_SLIP):
            return StripedReference(0.5, slip, slip_error, 20.0, 4.0, residual, angles=(0.0, 45.0, 90.0))

    def test_striped_slip(self):
        with fake_tool(self.tmp, "stripedSlip", STRIPED_SLIP):
            d = striped_slip(0.5, 1.5, 10.0, 4.0, [0, 45])
        self.assertAlmostEqual(d["slipParallel"], 0.75 + 0.2 + 0.5, places=12)
        self.assertAlmostEqual(d["slipPerpendicular"], 0.375 + 0.1, places=12)
        self.assertEqual(sorted(d["ratio"]), [0.0, 45.0])
        self.assertAlmostEqual(d["ratio"][45.0], 0.045 * 1.5 + 0.001, places=12)

    def test_reference_with_residual(self):
        ref = self.reference()
        self.assertAlmostEqual(ref["slipParallel"], par(2.0, 0.3), places=12)
        self.assertAlmostEqual(ref.at("slipPerpendicular"), perp(2.0, 0.3), places=12)
        self.assertAlmostEqual(ref["anisotropy"], par(2.0, 0.3) - perp(2.0, 0.3), places=12)
        self.assertAlmostEqual(ref.at("ratio", 45.0), 0.045 * 1.7 + 0.0001 * 20.6, places=12)
        # Calibration error: d b_par / d b = 0.5, d b_par / d b0 = -0.5 + 0.04 + 1 = 0.54 (linear: exact).
        self.assertAlmostEqual(ref.error("slipParallel"), math.hypot(0.5 * 0.1, 0.54 * 0.05), places=12)
        # The anisotropy's +b0 shifts cancel; b0 still enters through b - b0 and the height: -0.25 + 0.02.
        self.assertAlmostEqual(ref.error("anisotropy"), math.hypot(0.25 * 0.1, 0.23 * 0.05), places=12)
        self.assertAlmostEqual(ref.error("ratio", 45.0), math.hypot(0.045 * 0.1, (-0.045 + 0.0002) * 0.05), places=12)
        for theta in (0.0, 30.0, 90.0):
            t = math.radians(theta)
            self.assertAlmostEqual(ref.effective(theta), par(2.0, 0.3) * math.cos(t) ** 2 + perp(2.0, 0.3) * math.sin(t) ** 2,
                                   places=12)

    def test_reference_check(self):
        ref = self.reference()
        x, c = ref["slipParallel"], ref.error("slipParallel")
        run, wall, budget = 0.03, 0.02, 0.1
        total = math.sqrt(run ** 2 + wall ** 2 + c ** 2)
        self.assertLess(total, budget)
        for measured, passes in ((x + 0.29, True), (x - 0.29, True), (x + 0.31, False), (NAN, False), (None, False), ("", False)):
            checks = Checks()
            reference_check(checks, "b_par", measured, run, ref, "slipParallel", wall, budget)
            self.assertEqual(checks.status(), 0 if passes else 1, repr(measured))
        checks = Checks()
        reference_check(checks, "b_par", x, 0.1, ref, "slipParallel", wall, budget)  # total error over the budget
        reference_check(checks, "b_par", x, None, ref, "slipParallel", wall, budget)
        reference_check(checks, "b_par", x, run, ref, "slipParallel", NAN, budget)
        self.assertEqual(len(checks.failures()), 3)
        self.assertIn(f"{total:.4f}", self.passing_text(ref, x, run, wall, budget))

    @staticmethod
    def passing_text(ref, x, run, wall, budget):
        checks = Checks()
        reference_check(checks, "b_par", x, run, ref, "slipParallel", wall, budget)
        return checks.rows[0][2]

    def test_principal_and_anisotropy(self):
        ref = self.reference()
        table = {"bParallel": [ref["slipParallel"] + 0.05], "bParallelError": [0.02],
                 "bPerpendicular": [ref["slipPerpendicular"] - 0.5], "bPerpendicularError": [0.02]}
        checks = Checks()
        principal_slip_checks(checks, "L 4", table, [0, 0], ref, 0.01, 0.1)
        self.assertEqual([v for _, v, _ in checks.rows], ["PASS", "FAIL"])
        checks = Checks()
        a = ref["anisotropy"]
        self.assertTrue(anisotropy_check(checks, "anisotropy", (a + 1.0 + 0.2, 0.02), (1.0, 0.02), ref, 0.1))
        self.assertFalse(anisotropy_check(checks, "anisotropy", (a + 1.0 + 0.35, 0.02), (1.0, 0.02), ref, 0.1))
        self.assertFalse(anisotropy_check(checks, "anisotropy", (NAN, 0.02), (1.0, 0.02), ref, 0.1))

    def test_flux_and_rest_checks(self):
        c = Checks()
        self.assertTrue(zero_flux_check(c, 0.0, 0.029, 0.005, 0.01))
        self.assertFalse(zero_flux_check(c, 0.0, 0.031, 0.005, 0.01))
        self.assertFalse(zero_flux_check(c, 90.0, 0.0, 0.01, 0.01))  # error at its budget
        self.assertFalse(zero_flux_check(c, 90.0, None, 0.001, 0.01))
        self.assertTrue(turn_check(c, 0.031, 0.005, 0.01))
        self.assertFalse(turn_check(c, 0.029, 0.005, 0.01))
        self.assertFalse(turn_check(c, NAN, 0.005, 0.01))
        self.assertTrue(same_at_rest_check(c, "density", 3.02, 0.004, 3.0, 0.003, 0.01))
        self.assertFalse(same_at_rest_check(c, "density", 3.04, 0.004, 3.0, 0.003, 0.01))
        self.assertFalse(same_at_rest_check(c, "density", 3.0, 0.008, 3.0, 0.008, 0.01))  # hypot 0.0113 over 0.01
        self.assertFalse(same_at_rest_check(c, "density", 3.0, 0.004, "", 0.003, 0.01))


def stripe_grid(ux=0.3):
    """A stripeGrid between walls at 0 and 10: x bins of 0.5 over two periods of 4 (gas sectors x mod 4
    < 2), z bins of 0.25. The mean density against the distance d from the wall packs at d 0.375 and
    dips at 0.875 (the first layer: d < 0.875); within it the downstream half of each gas sector (x mod
    4 in [1, 2) for ux > 0) holds 1.2 times the density; uy = d, ux given."""
    xs = 0.25 + 0.5 * np.arange(16)
    zs = 0.125 + 0.25 * np.arange(40)
    x, z = np.meshgrid(xs, zs)
    x, z = x.ravel(), z.ravel()
    d = np.minimum(z, 10.0 - z)
    profile = {0.125: 2.0, 0.375: 5.0, 0.625: 3.0, 0.875: 2.5, 1.125: 3.2}
    density = np.array([profile.get(round(v, 3), 3.0) for v in d])
    downstream = (np.mod(x, 4.0) >= 1.0) & (np.mod(x, 4.0) < 2.0)
    if ux < 0:
        downstream = np.mod(x, 4.0) < 1.0
    density = np.where(downstream & (d < 0.8), 1.2 * density, density)
    return {"x": x, "z": z, "density": density, "densityErr": np.full(len(x), 0.1), "ux": np.full(len(x), ux), "uy": d,
            "kT": np.where(np.mod(x, 4.0) < 2.0, 1.1, 1.0), "kTErr": np.full(len(x), 0.01), "count": 100 * density}


class Sectors(unittest.TestCase):
    def test_sectors(self):
        np.testing.assert_array_equal(gas_sectors(np.array([0.0, 1.9, 2.0, 3.9, 4.1, -0.5]), 4.0, 0.5),
                                      [True, True, False, False, True, False])
        np.testing.assert_array_equal(distance_to_walls({"z": np.array([0.5, 4.0, 9.0])}, (0.0, 10.0)), [0.5, 4.0, 1.0])

    def test_near_wall_sectors(self):
        t = stripe_grid()
        out, near = near_wall_sectors(t, (0.0, 10.0), 4.0, 0.5, 0.5)
        self.assertEqual(near.sum(), 2 * 2 * 16)
        self.assertAlmostEqual(out["gas"]["kT"][0], 1.1, places=14)
        self.assertAlmostEqual(out["noSlip"]["kT"][0], 1.0, places=14)
        self.assertAlmostEqual(out["noSlip"]["density"][0], (2.0 * 200 + 5.0 * 500) / 700, places=13)  # weights 100 rho
        # gas: half the bins 1.2 x: sum(w rho) / sum(w) with w = 100 rho
        rho = np.array([2.0, 5.0, 2.4, 6.0])
        self.assertAlmostEqual(out["gas"]["density"][0], np.sum(rho ** 2) / np.sum(rho), places=13)
        n_no_slip = 2 * 2 * 8
        w = 100 * np.array([2.0, 5.0] * (n_no_slip // 2))
        self.assertAlmostEqual(out["noSlip"]["kT"][1], 0.01 * math.sqrt(np.sum(w ** 2)) / w.sum(), places=14)


class FirstLayer(Temporary):
    def test_packed_layer(self):
        for ux in (0.3, -0.3):
            velocity, (excess, error), depth = first_layer(stripe_grid(ux), (0.0, 10.0), 4.0, 0.5, 1.0)
            self.assertAlmostEqual(depth, 0.75, places=12)
            self.assertAlmostEqual(velocity["x"], ux, places=14)
            # uy = d, mass-weighted over the layer's depths 0.125, 0.375, 0.625 (the x means 2.1, 5.25, 3.15)
            self.assertAlmostEqual(velocity["y"], (2.1 * 0.125 + 5.25 * 0.375 + 3.15 * 0.625) / 10.5, places=12)
            self.assertAlmostEqual(excess, 0.2, places=12)
            up = 10.0 * 0.25 * 8  # per x bin 2 + 5 + 3, 8 upstream bins (4 x 2 walls)
            de = ue = 0.1 * 0.25 * math.sqrt(24)
            self.assertAlmostEqual(error, math.hypot(de / up, 1.2 * up * ue / up ** 2), places=12)

    def test_no_packing_gives_none(self):
        # No packed layer: a density that rises gently from the wall to the bulk (as a fluid without
        # conservative force may, the case the docstring names) has its densest depth the last, no minimum.
        t = stripe_grid()
        d = np.minimum(t["z"], 10.0 - t["z"])
        t["density"] = 3.0 - 0.5 * np.exp(-d)
        self.assertIsNone(first_layer(t, (0.0, 10.0), 4.0, 0.5, 1.0))

    def test_no_minimum_near_the_wall(self):
        t = stripe_grid()
        d = np.minimum(t["z"], 10.0 - t["z"])
        t["density"] = np.where(d < 1.0, 2.0 + d, np.where(d < 2.5, 3.0 - 0.1 * (d - 1.0), 2.85 + 0.01 * (d - 2.5)))
        self.assertIsNone(first_layer(t, (0.0, 10.0), 4.0, 0.5, 1.0))  # the density dips only beyond 2 cutoffs

    def test_first_layers(self):
        sweep = os.path.join(self.tmp, "sweep")
        for case, ux in (("run0", 0.3), ("run90", -0.3)):
            write_table(os.path.join(sweep, case, "postProcessing", "profileBins", "400", "stripeGrid.dat"), stripe_grid(ux))
        table = {"angle": [0.0, 90.0], "case": ["run0", "run90"], "bodyForce/value": ["(0.03,0,0)", "(0,0.04,0)"]}
        layers = first_layers(sweep, table, (90.0, 0.0), (0.0, 10.0), 4.0, 0.5, 1.0)
        self.assertAlmostEqual(layers[0.0][0][0]["x"], 0.3, places=12)
        self.assertAlmostEqual(layers[90.0][0][0]["x"], -0.3, places=12)
        self.assertAlmostEqual(layers[90.0][1], 0.04, places=12)


if __name__ == "__main__":
    unittest.main()
