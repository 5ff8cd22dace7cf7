"""dpdfoam.couette: the Couette slip scene's shear-stress flatness by hand.

The checks themselves (stress_flat_check, nu_checks, kT_check, growth_checks) are fed broken inputs by
tests/apps/checkBoundsChannel.sh through the tutorial; here the measure they read: over slabs two cutoffs
thick the stress means 1, 1.2, 1, 1 (mean 1.05), so the largest deviation is 1.2 / 1.05 - 1 = 1 / 7, and
four bins of error 0.1 give a slab's error sqrt(4 x 0.01) / 4 = 0.05, 0.05 / 1.05 of the mean.
"""
import unittest

import numpy as np

from dpdfoam.couette import FLAT_BOUND, KT_BOUND, NU_BOUND, stress_flatness


class StressFlatness(unittest.TestCase):
    def test_slabs_by_hand(self):
        z = np.arange(0.25, 8.0, 0.5)  # 16 bins of 0.5 between the walls at 0 and 8
        sigma = np.where((z > 2) & (z < 4), 1.2, 1.0)
        prof = {"z": z, "sigmaxz": sigma, "sigmaxzErr": np.full_like(z, 0.1)}
        flat, error = stress_flatness(prof, (0.0, 8.0), 1.0)
        self.assertAlmostEqual(flat, 1.0 / 7.0, places=12)
        self.assertAlmostEqual(error, 0.05 / 1.05, places=12)

    def test_flat_profile_and_sign(self):
        z = np.arange(0.25, 8.0, 0.5)
        prof = {"z": z, "sigmaxz": np.full_like(z, -0.3), "sigmaxzErr": np.full_like(z, 0.01)}
        flat, error = stress_flatness(prof, (0.0, 8.0), 1.0)
        self.assertAlmostEqual(flat, 0.0, places=12)
        self.assertAlmostEqual(error, 0.005 / 0.3, places=12)  # relative to |mean|

    def test_bounds(self):
        self.assertEqual((NU_BOUND, FLAT_BOUND, KT_BOUND), (0.05, 0.05, 0.01))


if __name__ == "__main__":
    unittest.main()
