"""dpdfoam.porous: the checks' bounds at a tutorial's budgets, the mode make_checks takes, and the
velocity next to the grains.

The tutorial's instance is fed broken inputs by tests/apps/checkBoundsPolymerPorous.sh; here other
budgets and bounds: a bound is the full one, in test mode plus `widen` test budgets (the twin's with the
wall's budget), the crack line's in test mode the given one; make_checks without a mode takes the
instance's (its names carry the test bound). Next to the grains: the region means of the near bins and
the largest continuum peak among the lines, with that line's name.
"""
import types
import unittest

import numpy as np

from dpdfoam.porous import PorousChecks, next_to_grains

BUDGETS = {False: {"line": 0.1, "mean": 0.01, "kT": 0.002, "wall": 0.001},
           True: {"line": 0.2, "mean": 0.02, "kT": 0.004, "wall": 0.005}}
BOUNDS = {"kT": 0.05, "wall": 0.2, "twin": 0.04, "line": 0.15, "mean": 0.12}


class Bounds(unittest.TestCase):
    def test_full_and_test(self):
        pc = PorousChecks(BUDGETS, BOUNDS, 0.3, widen=2.0)
        for kind, full in BOUNDS.items():
            self.assertEqual(pc.bound(kind, False), full)
        self.assertEqual(pc.bound("line", True), 0.3)
        self.assertAlmostEqual(pc.bound("kT", True), 0.05 + 2 * 0.004, places=15)
        self.assertAlmostEqual(pc.bound("twin", True), 0.04 + 2 * 0.005, places=15)
        self.assertAlmostEqual(pc.bound("mean", True), 0.12 + 2 * 0.02, places=15)

    def test_make_checks_takes_the_instance_mode(self):
        cmp = {"superficialVelocityFVM": 0.1, "superficialVelocityDPDErr": 0.0005, "meanVelocityRatio": 1.01,
               "permeabilityRatio": 0.99}
        lines = {"crack": {"L2": 0.05, "noiseL2": 0.02, "points": 40}}
        kT = types.SimpleNamespace(bins=1.001, mean=1.002, error=0.001)
        wall = {"dpd": 0.001, "fvm": 0.0012, "se": 0.0001, "peak": 0.2, "line": "crack", "bins": 100}
        for test, tol in ((False, 0.05), (True, 0.058)):
            checks = PorousChecks(BUDGETS, BOUNDS, 0.3, 2.0, test).make_checks(cmp, lines, kT, 0, wall)
            self.assertEqual(len(checks.rows), 8)
            self.assertFalse(checks.failures())
            self.assertIn(f"within {tol:.3f} of 1", " ".join(checks.lines()))


class NextToGrains(unittest.TestCase):
    def test_peak_line(self):
        bins = types.SimpleNamespace(region_means=lambda near: {"dpd": 0.01, "fvm": 0.012, "se": 0.001,
                                                                "bins": int(near.sum())})
        prof = {"u_crack": np.array([0.0, 0.3, np.nan, 0.1]), "u_side": np.array([0.05, 0.2])}
        wall = next_to_grains(bins, np.array([True, False, True]), prof, ["crack", "side"])
        self.assertEqual((wall["peak"], wall["line"], wall["bins"], wall["dpd"]), (0.3, "crack", 2, 0.01))


if __name__ == "__main__":
    unittest.main()
