"""dpdfoam.slip_length: the channel's middle fifth and the density peak's errors by hand.

Walls put at z = -5 and 5: the middle fifth is |z| < 1. The peak's error is the densest bin's; the
bulk's, the errors of the n bins it averages in quadrature over n: sqrt(4 x 0.01) / 4 = 0.05.
"""
import os
import tempfile
import unittest

import numpy as np

from dpdfoam.slip_length import central, peak_errors
from dpdtest_support import write_text


class Central(unittest.TestCase):
    def test_middle_fifth(self):
        with tempfile.TemporaryDirectory() as tmp:
            case = os.path.join(tmp, "poiseuille")
            write_text(os.path.join(case, "constant", "dpdProperties"),
                       "walls\n{\n    lower { point (0 0 -5); }\n    upper { point (0 0 5); }\n}\n")
            z = np.array([-4.5, -1.5, -0.99, 0.0, 0.99, 1.5, 4.5])
            np.testing.assert_array_equal(central(z, case), [False, False, True, True, True, False, False])


class PeakErrors(unittest.TestCase):
    def test_by_hand(self):
        table = {"density": np.array([3.0, 4.8, 4.0, 4.0, 4.0, 4.0]),
                 "densityErr": np.array([0.3, 0.07, 0.1, 0.1, 0.1, 0.1])}
        bulk = np.array([False, False, True, True, True, True])
        peak, bulk_err = peak_errors(table, bulk)
        self.assertEqual(peak, 0.07)
        self.assertAlmostEqual(bulk_err, 0.05, places=14)


if __name__ == "__main__":
    unittest.main()
