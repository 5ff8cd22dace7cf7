"""dpdfoam.stepstudy on a synthetic study of the time step with known errors.

With errors linear in dt (|e| = 2 dt) the step where |e| passes a level is level / 2, interpolated
exactly between the measured steps; a level already passed at the smallest step reads '<dt', a run
that blew up first brackets it 'dt0-dt1', a level never passed gives None. The cost model's median
cost per particle-step ignores unstable and unmeasured runs and one slow run, and sets every stable
run's cost to that median over its dt. The largest qualifying step stops at the first step that fails;
equal accuracy admits an error within two combined standard errors of the baseline's, never an
unstable run or a NaN error. The stability map marks the interpolated crossings and the blow-up where
they are. A NaN error between two measured steps is skipped, not taken as below the level.
"""
import math
import unittest

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from dpdfoam.stepstudy import (apply_cost_model, as_accurate, crossing, draw_errors_against_cost,  # noqa: E402
                               draw_stability_map, first_unstable, largest_step, measured)

NAN = float("nan")


def point(dt, kT=None, unstable=False, cost=1.0, kTse=0.001):
    return {"dt": dt, "kT": 2 * dt if kT is None else kT, "kTse": kTse, "unstable": unstable, "cost": cost}


def linear(*dts):
    return [point(dt) for dt in dts]


class Crossing(unittest.TestCase):
    def test_interpolated(self):
        points = linear(0.005, 0.01, 0.02, 0.04)
        self.assertEqual(crossing(points, "kT", 0.03), "0.015")
        self.assertEqual(crossing(points, "kT", 0.05), "0.025")
        self.assertAlmostEqual(float(crossing(points, "kT", 0.0123)), 0.00615, places=12)

    def test_negative_errors(self):
        points = [point(dt, kT=-2 * dt) for dt in (0.005, 0.01, 0.02)]
        self.assertEqual(crossing(points, "kT", 0.03), "0.015")

    def test_bounds_and_brackets(self):
        points = linear(0.005, 0.01, 0.02)
        self.assertEqual(crossing(points, "kT", 0.005), "<0.005")
        self.assertIsNone(crossing(points, "kT", 1.0))
        points.append(point(0.04, unstable=True))
        self.assertEqual(crossing(points, "kT", 0.05), "0.02-0.04")
        self.assertEqual(crossing([point(0.01, unstable=True)], "kT", 0.05), "<0.01")

    def test_nan_error_is_no_measurement(self):
        # A stable run whose error is NaN is not measured (measured(), as as_accurate uses it): skipped,
        # the crossing interpolates between the measured steps 0.01 and 0.04:
        # 0.01 + (0.01 - 0.005) (0.04 - 0.01) / (0.02 - 0.005) = 0.02. With every error NaN the level
        # reads as never passed (None, printed '-' "not reached").
        points = [point(0.01, kT=0.005), point(0.02, kT=NAN), point(0.04, kT=0.02)]
        self.assertEqual(crossing(points, "kT", 0.01), "0.02")
        self.assertIsNone(crossing([point(0.01, kT=NAN), point(0.02, kT=NAN)], "kT", 0.01))
        # A NaN before an unstable run: the blow-up brackets from the last measured step.
        self.assertEqual(crossing([point(0.01), point(0.02, kT=NAN), point(0.04, unstable=True)], "kT", 0.05),
                         "0.01-0.04")


class Steps(unittest.TestCase):
    def test_first_unstable(self):
        self.assertEqual(first_unstable(linear(0.01, 0.02) + [point(0.04, unstable=True), point(0.08, unstable=True)]), 0.04)
        self.assertIsNone(first_unstable(linear(0.01, 0.02)))

    def test_largest_step(self):
        points = linear(0.005, 0.01, 0.02, 0.04) + [point(0.05, kT=0.0)]
        best = largest_step(points, lambda p: abs(p["kT"]) <= 0.03)
        self.assertEqual(best["dt"], 0.01)  # 0.05 qualifies again, but 0.02 stopped the run of steps
        self.assertIsNone(largest_step(points, lambda p: False))

    def test_measured(self):
        self.assertTrue(measured(point(0.01), "kT"))
        self.assertFalse(measured(point(0.01, kT=NAN), "kT"))
        self.assertFalse(measured(point(0.01, unstable=True), "kT"))

    def test_as_accurate(self):
        base = point(0.005, kT=0.01, kTse=0.003)
        bound = 0.01 + 2 * math.hypot(0.004, 0.003)  # 0.02
        self.assertTrue(as_accurate(point(0.01, kT=bound - 1e-9, kTse=0.004), base, ["kT"]))
        self.assertTrue(as_accurate(point(0.01, kT=-(bound - 1e-9), kTse=0.004), base, ["kT"]))
        self.assertFalse(as_accurate(point(0.01, kT=bound + 1e-9, kTse=0.004), base, ["kT"]))
        self.assertFalse(as_accurate(point(0.01, kT=NAN, kTse=0.004), base, ["kT"]))
        self.assertFalse(as_accurate(point(0.01, kT=0.0, unstable=True), base, ["kT"]))
        self.assertTrue(as_accurate(point(0.01, kT=0.005, kTse=NAN), base, ["kT"]))  # as documented


class CostModel(unittest.TestCase):
    def test_median_per_step(self):
        # Seconds per particle per time unit = (seconds per particle-step) / dt: 2e-6 per step, one run
        # slowed 5 x by another job, one unstable and one unmeasured.
        points = [point(0.01, cost=2e-4), point(0.02, cost=1e-4), point(0.04, cost=5 * 5e-5), point(0.05, cost=4e-5),
                  point(0.06, cost=NAN), point(0.08, cost=1.0, unstable=True)]
        costs = apply_cost_model({"GW": points, "none": [point(0.01, unstable=True)]})
        self.assertEqual(list(costs), ["GW"])
        median, low, high = costs["GW"]
        self.assertAlmostEqual(median, 2e-6, places=18)
        self.assertAlmostEqual(low, 2e-6, places=18)
        self.assertAlmostEqual(high, 1e-5, places=18)
        for p in points[:5]:
            self.assertAlmostEqual(p["cost"], 2e-6 / p["dt"], places=15)
        self.assertEqual(points[5]["cost"], 1.0)


class Pictures(unittest.TestCase):
    def test_stability_map(self):
        rows = {"GW": linear(0.005, 0.01, 0.02) + [point(0.04, unstable=True)], "VV": linear(0.01, 0.02)}
        fig, ax = plt.subplots()
        try:
            draw_stability_map(ax, rows, "kT", [(0.03, "orange"), (0.05, "red"), (0.001, "blue")])
            circles = [tuple(np.ravel(line.get_data())) for line in ax.lines if line.get_marker() == "o"]
            crosses = [tuple(np.ravel(line.get_data())) for line in ax.lines if line.get_marker() == "x"]
            # 0.03 is crossed at 0.015 by both; 0.05 lies beyond GW's blow-up (bracket) and VV's range; 0.001 '<dt'.
            self.assertEqual(sorted(circles), [(0.015, 0.0), (0.015, 1.0)])
            self.assertEqual(crosses, [(0.04, 0.0)])
            self.assertEqual([t.get_text() for t in ax.get_yticklabels()], ["GW", "VV"])
        finally:
            plt.close(fig)

    def test_errors_against_cost(self):
        rows = {"GW": [point(0.01, cost=3.0), point(0.02, kT=NAN, cost=2.0), point(0.04, cost=1.0)]}
        fig, ax = plt.subplots()
        try:
            draw_errors_against_cost(ax, rows, "kT", [(0.01, "grey")])
            x, y = ax.containers[0].lines[0].get_data()
            np.testing.assert_allclose(x, [3.0, 1.0])  # the unmeasured run left out
            np.testing.assert_allclose(y, [2.0, 8.0])  # in %
            self.assertEqual(ax.get_xscale(), "log")
        finally:
            plt.close(fig)


if __name__ == "__main__":
    unittest.main()
