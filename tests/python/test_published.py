"""dpdfoam.published: a tutorial's published.dat and the point-by-point comparison (issue 25's bound).

A published.dat written here gives back its source, scene, parameters, tables (columns of the rows
written, nan kept), counts and fits (the expression evaluated at a, with no builtins to reach); a row
of the wrong length, a malformed parameter or an unknown keyword stops it. Every tutorial's own
published.dat parses, its tables' columns of one length and its fits numbers. The comparison keeps
the published rows that were measured and have a number, with the tolerance max(absolute, relative x
|published|) inclusive; its checks fail a point whose error is above a third of the tolerance, a NaN
measurement or error, and a point outside the tolerance unless the named variant has a decided point
within it (a missing variant run fails, saying how to run it).
"""
import glob
import os
import tempfile
import unittest

import numpy as np

from dpdfoam.published import compare_with_published, published_checks, read_published, table_value
from dpdtest_support import write_text

SOURCE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")

EXAMPLE = """# a comment line
source      Someone et al. (2020): a paper   # trailing comment
scene       60 x 5 x 30, walls at z = +-15
parameter   constant/dpdProperties   kT                            1
parameter   system/controlDict       functions/channelProfile/startTime  300

table       Table 1
columns     a_wf  slipLength  slipVelocity
row         2     1.25        nan
row         4.5   0.5         0.3
table       Table 2
columns     x  y
row         1  2
count       fcc          blockFrozenWall   fluid   21600
count       fcc          blockFrozenWall   wall    2160
fit         slipLength:a_wf    0.0147 * a**2 - 0.2343 * a + 0.8958
"""


class Read(unittest.TestCase):
    def setUp(self):
        self._tmp = tempfile.TemporaryDirectory()
        self.path = os.path.join(self._tmp.name, "published.dat")

    def tearDown(self):
        self._tmp.cleanup()

    def read(self, text):
        return read_published(write_text(self.path, text))

    def test_example(self):
        p = self.read(EXAMPLE)
        self.assertEqual(p["source"], "Someone et al. (2020): a paper")
        self.assertEqual(p["scene"], "60 x 5 x 30, walls at z = +-15")
        self.assertEqual(p["parameters"], [("constant/dpdProperties", "kT", "1"),
                                           ("system/controlDict", "functions/channelProfile/startTime", "300")])
        t = p["tables"]["Table 1"]
        np.testing.assert_array_equal(t["a_wf"], [2.0, 4.5])
        np.testing.assert_array_equal(t["slipLength"], [1.25, 0.5])
        self.assertTrue(np.isnan(t["slipVelocity"][0]))
        np.testing.assert_array_equal(p["tables"]["Table 2"]["y"], [2.0])
        self.assertEqual(p["counts"], {("fcc", "fluid"): 21600, ("fcc", "wall"): 2160})
        variable, fit = p["fits"]["slipLength"]
        self.assertEqual(variable, "a_wf")
        for a in (0.0, 3.0, 10.0):
            self.assertAlmostEqual(fit(a), 0.0147 * a * a - 0.2343 * a + 0.8958, places=14)
        self.assertEqual(table_value(t, "a_wf", 4.5, "slipVelocity"), 0.3)

    def test_fit_has_no_builtins(self):
        p = self.read("fit  q:a  open('x') if a else a\n")
        with self.assertRaises(NameError):
            p["fits"]["q"][1](1.0)

    def test_broken_files_stop(self):
        for text in ("table T\ncolumns a b\nrow 1 2 3\n", "parameter constant/dpdProperties kT\n", "colour blue\n"):
            with self.assertRaises(SystemExit, msg=text):
                self.read(text)

    def test_tutorials_files(self):
        paths = glob.glob(os.path.join(SOURCE, "tutorials", "*", "*", "published.dat"))
        self.assertGreaterEqual(len(paths), 5)
        for path in paths:
            p = read_published(path)
            self.assertTrue(p["source"], path)
            for table in p["tables"].values():
                self.assertEqual(len({len(c) for c in table.values()}), 1, path)
            for quantity, (variable, fit) in p["fits"].items():
                for a in (1.0, 10.0):
                    self.assertTrue(np.isfinite(fit(a)), f"{path}: fit {quantity}:{variable} at {a}")


TABLE = {"a_ww": np.array([10.0, 20.0, 30.0, 40.0]), "slipLength": np.array([2.0, 0.5, np.nan, 0.2])}


class Compare(unittest.TestCase):
    def test_rows_and_tolerance(self):
        keys = np.array([40.0, 10.0, 20.0, 30.0, 50.0])
        measured = np.array([0.45, 2.5, 0.79, 1.0, 9.0])
        errors = np.array([0.05, 0.1, 0.1, 0.1, 0.1])
        rows = compare_with_published(TABLE, "a_ww", keys, measured, errors)
        # 10: tolerance 0.3 x 2 = 0.6, |2.5 - 2| = 0.5 inside; 20: max(0.3, 0.15), 0.29 inside; 30: nan
        # published, left out; 40: 0.3, 0.25 inside; 50: not published.
        self.assertEqual([r[0] for r in rows], [10.0, 20.0, 40.0])
        self.assertEqual([r[1:4] for r in rows], [(2.5, 0.1, 2.0), (0.79, 0.1, 0.5), (0.45, 0.05, 0.2)])
        np.testing.assert_allclose([r[4] for r in rows], [0.6, 0.3, 0.3])
        self.assertEqual([r[5] for r in rows], [True, True, True])
        rows = compare_with_published(TABLE, "a_ww", keys, measured + [0.0, 0.11, 0.02, 0.0, 0.0], errors)
        self.assertEqual([r[5] for r in rows], [False, False, True])

    def test_tolerance_is_inclusive(self):
        table = {"a": np.array([1.0]), "slipLength": np.array([0.5])}
        for m, within in ((0.75, True), (0.25, True), (0.7500001, False)):
            rows = compare_with_published(table, "a", np.array([1.0]), np.array([m]), np.array([0.01]), absolute=0.25,
                                          relative=0.0)
            self.assertEqual(rows[0][5], within, m)

    def test_nan_measurement_is_outside(self):
        rows = compare_with_published(TABLE, "a_ww", np.array([10.0]), np.array([np.nan]), np.array([0.1]))
        self.assertFalse(rows[0][5])


class Checks(unittest.TestCase):
    def test_two_checks_per_point(self):
        rows = [(10.0, 2.1, 0.15, 2.0, 0.6, True), (20.0, 0.6, 0.11, 0.5, 0.3, True), (40.0, 0.9, 0.05, 0.2, 0.3, False)]
        checks = published_checks(rows, "slip length", "a_ww = {:g}")
        self.assertEqual(len(checks), 6)
        self.assertEqual([c[1] for c in checks], [True, True, False, True, True, False])
        self.assertIn("a_ww = 20", checks[2][0])
        self.assertEqual(checks[2][2], "0.1100")

    def test_nan_fails(self):
        rows = [(10.0, np.nan, 0.1, 2.0, 0.6, False), (20.0, 0.5, np.nan, 0.5, 0.3, True)]
        verdicts = [c[1] for c in published_checks(rows, "b", "a = {:g}")]
        self.assertEqual(verdicts, [True, False, False, True])

    def test_accounted_by_a_variant(self):
        rows = [(10.0, 3.0, 0.1, 2.0, 0.6, False), (20.0, 0.5, 0.05, 0.5, 0.3, True), (40.0, 0.9, 0.05, 0.2, 0.3, False)]
        variant = [(10.0, 2.2, 0.1, 2.0, 0.6, True), (40.0, 0.6, 0.2, 0.2, 0.3, False)]
        checks = published_checks(rows, "b", "a = {:g}", ("the wall's density", variant, "run ./Allrun -dense"))
        names = [c[0] for c in checks]
        self.assertEqual(len(checks), 4)  # one check per point accounted for, two for the point within
        self.assertIn("accounted for by the wall's density", names[0])
        self.assertTrue(checks[0][1])
        self.assertEqual([c[1] for c in checks[1:3]], [True, True])
        self.assertFalse(checks[3][1])  # the variant is outside there too (and its error above a third)

    def test_variant_not_run(self):
        rows = [(10.0, 3.0, 0.1, 2.0, 0.6, False)]
        checks = published_checks(rows, "b", "a = {:g}", ("the wall's density", [], "run ./Allrun -dense"))
        self.assertEqual(len(checks), 1)
        self.assertFalse(checks[0][1])
        self.assertIn("run ./Allrun -dense", checks[0][2])

    def test_undecided_variant_fails(self):
        rows = [(10.0, 3.0, 0.1, 2.0, 0.6, False)]
        variant = [(10.0, 2.1, 0.25, 2.0, 0.6, True)]  # within, but its error 0.25 above a third of 0.6
        checks = published_checks(rows, "b", "a = {:g}", ("x", variant, "how"))
        self.assertFalse(checks[0][1])
        self.assertIn("above a third of it", checks[0][2])


if __name__ == "__main__":
    unittest.main()
