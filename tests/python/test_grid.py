"""dpdfoam.grid on a small 2-D profile table written out by hand.

Averaged along x, each z row gives the plain mean density of its bins, the particle-sample weighted
velocity and kT (an empty bin's NaN left out), the summed count and the number of bins along x; the
weighted mean over a region (mask, index or all) is the hand-computed one; a column as an image puts
each bin at its (z, x) cell, NaN where the table has no bin, with the outer bins' edges as extent.
"""
import unittest

import numpy as np

from dpdfoam.grid import averaged_along, image, weighted_mean


def table():
    """3 rows (z 0.5, 1.5, 2.5) of 4 bins (x 1, 3, 5, 7), in x-fastest order as profileBins writes."""
    x = np.tile([1.0, 3.0, 5.0, 7.0], 3)
    z = np.repeat([0.5, 1.5, 2.5], 4)
    count = np.array([1.0, 2.0, 3.0, 4.0, 10.0, 10.0, 10.0, 10.0, 0.0, 5.0, 5.0, 0.0])
    ux = np.array([4.0, 3.0, 2.0, 1.0, 0.1, 0.2, 0.3, 0.4, np.nan, 1.0, 3.0, np.nan])
    kT = np.array([1.0, 1.0, 1.0, 2.0, 1.0, 1.0, 1.0, 1.0, np.nan, 0.9, 1.1, np.nan])
    density = count / 10.0
    return {"x": x, "z": z, "count": count, "ux": ux, "kT": kT, "density": density}


class AveragedAlong(unittest.TestCase):
    def test_rows(self):
        out = averaged_along(table())
        np.testing.assert_array_equal(out["z"], [0.5, 1.5, 2.5])
        self.assertEqual(out["nx"], 4)
        np.testing.assert_array_equal(out["count"], [10.0, 40.0, 10.0])
        np.testing.assert_allclose(out["density"], [0.25, 1.0, 0.25])
        np.testing.assert_allclose(out["ux"], [(4 + 6 + 6 + 4) / 10.0, 0.25, 2.0])
        np.testing.assert_allclose(out["kT"], [1.4, 1.0, 1.0])

    def test_along_z(self):
        out = averaged_along(table(), along="z", across="x", weighted=("ux",))
        np.testing.assert_array_equal(out["x"], [1.0, 3.0, 5.0, 7.0])
        self.assertEqual(out["nz"], 3)
        np.testing.assert_allclose(out["ux"], [(4 + 1) / 11.0, (6 + 2 + 5) / 17.0, (6 + 3 + 15) / 18.0, (4 + 4) / 14.0])


class WeightedMean(unittest.TestCase):
    def test_regions(self):
        values, weights = np.array([1.0, 2.0, np.nan, 4.0]), np.array([1.0, 1.0, 0.0, 2.0])
        self.assertAlmostEqual(weighted_mean(values, weights), 11.0 / 4.0, places=14)
        self.assertAlmostEqual(weighted_mean(values, weights, np.array([True, False, True, True])), 9.0 / 3.0, places=14)
        self.assertAlmostEqual(weighted_mean(values, weights, slice(0, 2)), 1.5, places=14)

    def test_nothing_weighs(self):
        with np.errstate(invalid="ignore", divide="ignore"):
            self.assertTrue(np.isnan(weighted_mean(np.array([1.0]), np.array([0.0]))))


class Image(unittest.TestCase):
    def test_cells_and_extent(self):
        t = table()
        keep = np.arange(12) != 6  # the bin (z 1.5, x 5) missing from the table
        grid, extent = image({k: v[keep] for k, v in t.items()}, "count")
        self.assertEqual(grid.shape, (3, 4))
        np.testing.assert_array_equal(grid[0], [1.0, 2.0, 3.0, 4.0])
        self.assertTrue(np.isnan(grid[1, 2]))
        self.assertEqual(grid[2, 1], 5.0)
        self.assertEqual(extent, [0.0, 8.0, 0.0, 3.0])

    def test_order_does_not_matter(self):
        t = table()
        order = np.random.default_rng(30).permutation(12)
        shuffled, _ = image({k: v[order] for k, v in t.items()}, "ux")
        straight, _ = image(t, "ux")
        np.testing.assert_array_equal(shuffled, straight)


if __name__ == "__main__":
    unittest.main()
