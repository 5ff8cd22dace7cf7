"""dpdfoam.blocks on sampled blocks built here from particles of known velocities.

A bin's kT from its sums (sampling/BinProfile.cpp: the variance of v about a line across the bin) is
the mean square residual of a least-squares line through the particles' velocities, computed here
independently with numpy's polyfit, to rounding; on a seeded thermal fluid under strong shear it is the
set kT within five standard errors of a variance estimate (the shear removed: without removal it would
lie 8 % high). The sampled-blocks file gives back its complete blocks only, the bins' centres, the
latest super-blocks' sums and the density count / (samples x bin volume). Region means weigh by the
particle-samples and leave empty bins out; a bin's overlap with a band is its exact geometric share.
The mirror asymmetry recovers a planted u(z) - u(-z) = 2 a z and A = U(upper) - U(lower) = a h, and on
pure noise its chi^2 per pair is the Student-t value E[t^2] = (m - 1) / (m - 3) within five standard
errors (2000 pairs); bins not symmetric about the centre stop it.
"""
import math
import os
import tempfile
import unittest

import numpy as np

from dpdfoam.blocks import (SampledBins, band_share, mirror_asymmetry, overlap, region_mean, region_temperature,
                            temperature)
from dpdtest_support import bin_sums, write_sampling


def sheared_particles(rng, n, kT, lo, hi, shear, u0=0.3, dimension=3):
    """n particle-samples uniform in [lo, hi) with vx = u0 + shear x plus thermal velocities of kT
    (vy = 0 in 2-D)."""
    x = rng.uniform(lo, hi, n)
    v = rng.normal(0.0, math.sqrt(kT), (n, 3))
    v[:, 0] += u0 + shear * x
    if dimension == 2:
        v[:, 1] = 0.0
    return x, v


class Temperature(unittest.TestCase):
    def test_is_the_residual_variance_about_a_line(self):
        rng = np.random.default_rng(10)
        for n in (5, 40, 1000):
            x = rng.uniform(2.0, 2.5, n)
            v = rng.normal(0.0, 1.0, (n, 3)) + np.outer(x, [3.0, -1.0, 0.5]) + [1.0, 0.0, -2.0]
            residual = [np.mean((v[:, c] - np.polyval(np.polyfit(x, v[:, c], 1), x)) ** 2) for c in range(3)]
            self.assertAlmostEqual(float(temperature(bin_sums(x, v))) / np.mean(residual), 1.0, places=9)

    def test_thermal_fluid_under_shear(self):
        # 30000 samples, kT 1.3, shear 2 across a bin of width 1 (it would add 2^2 / 12 / 3 = 0.11 to
        # kT if not removed); relative standard error of the mean of three variances sqrt(2 / (3 n)).
        rng = np.random.default_rng(11)
        n, kT = 30000, 1.3
        x, v = sheared_particles(rng, n, kT, 4.0, 5.0, 2.0)
        self.assertLess(abs(float(temperature(bin_sums(x, v))) / kT - 1.0), 5 * math.sqrt(2.0 / (3 * n)))

    def test_blocks_and_bins_at_once(self):
        rng = np.random.default_rng(12)
        sums = np.array([[bin_sums(*sheared_particles(rng, 50, 1.0, b, b + 1.0, 0.5)) for b in range(4)] for _ in range(3)])
        out = temperature(sums)
        self.assertEqual(out.shape, (3, 4))
        self.assertAlmostEqual(out[2, 1], float(temperature(sums[2, 1])), places=14)

    def test_empty_bin_is_nan(self):
        self.assertTrue(np.isnan(temperature(np.zeros(12))))

    def test_two_dimensional_profile(self):
        # sampling/BinProfile.cpp divides the variances by the dimension and leaves the inactive y out in
        # 2-D (vy = 0): a 2-D profile's kT is the true one, not 2/3 of it.
        rng = np.random.default_rng(13)
        n, kT = 30000, 1.0
        x, v = sheared_particles(rng, n, kT, 0.0, 1.0, 1.0, dimension=2)
        with tempfile.TemporaryDirectory() as tmp:
            path = write_sampling(os.path.join(tmp, "p.h5"), [[bin_sums(x, v)], [bin_sums(x, v)]], [n, n], 0.0, 1.0, n, 1.0,
                                  dimension=2)
            bins = SampledBins(path)
            sums, _ = bins.super_blocks(1, 2)
        self.assertLess(abs(float(region_temperature(sums.sum(axis=0), np.array([True]))) / kT - 1.0),
                        5 * math.sqrt(1.0 / n))


class SampledBinsFile(unittest.TestCase):
    def setUp(self):
        self._tmp = tempfile.TemporaryDirectory()
        rng = np.random.default_rng(14)
        self.blocks = rng.uniform(1.0, 2.0, (7, 4, 12))
        self.blocks[:, :, 0] = np.arange(7)[:, None] * 10 + np.arange(4) + 100  # counts telling block and bin
        # The 4th block is incomplete (the run stopped inside it... or a restart): left out.
        samples = [50, 50, 50, 20, 50, 50, 50]
        self.path = write_sampling(os.path.join(self._tmp.name, "channelProfile.h5"), self.blocks, samples, -2.0, 2.0, 50, 6.0)
        self.complete = self.blocks[[0, 1, 2, 4, 5, 6]]

    def tearDown(self):
        self._tmp.cleanup()

    def test_layout(self):
        b = SampledBins(self.path)
        self.assertEqual((b.n, b.lo, b.hi, b.block_samples, b.cross_section), (4, -2.0, 2.0, 50, 6.0))
        np.testing.assert_array_equal(b.blocks, self.complete)
        self.assertEqual(b.width, 1.0)
        np.testing.assert_array_equal(b.z, [-1.5, -0.5, 0.5, 1.5])
        self.assertEqual(b.layout(2.0, 4.2), (2, 3))
        self.assertEqual(b.layout(2.0, 0.3), (1, 6))
        self.assertEqual(b.layout(2.0, 10.0), (5, 1))

    def test_latest_super_blocks(self):
        b = SampledBins(self.path)
        latest = b.latest(2, 2)
        self.assertEqual(latest.shape, (2, 2, 4, 12))
        np.testing.assert_array_equal(latest.reshape(4, 4, 12), self.complete[2:])
        sums, samples = b.super_blocks(2, 2)
        np.testing.assert_allclose(sums, [self.complete[2] + self.complete[3], self.complete[4] + self.complete[5]])
        self.assertEqual(samples, 100)
        np.testing.assert_allclose(b.density(sums, samples), sums[..., 0] / (100 * 1.0 * 6.0))


class Regions(unittest.TestCase):
    def test_region_mean_weighs_by_samples(self):
        count = np.array([[1.0, 3.0, 5.0], [2.0, 2.0, 0.0]])
        sum_u = count * np.array([[1.0, 2.0, 100.0], [4.0, 6.0, 0.0]])
        np.testing.assert_allclose(region_mean(sum_u, count, np.array([True, True, False])), [7.0 / 4.0, 5.0])

    def test_region_temperature(self):
        rng = np.random.default_rng(15)
        bins = [sheared_particles(rng, n, 1.0 + b, b, b + 1.0, 0.0) for b, n in enumerate((30, 90, 60))]
        sums = np.array([bin_sums(*p) for p in bins] + [np.zeros(12)])  # an empty bin: NaN, left out
        each = temperature(sums[:3])
        region = np.array([True, False, True, True])
        expected = (30 * each[0] + 60 * each[2]) / 90
        self.assertAlmostEqual(float(region_temperature(sums, region)), expected, places=12)
        per_block = region_temperature(np.array([sums, sums]), region)
        np.testing.assert_allclose(per_block, [expected, expected], rtol=1e-12)

    def test_overlap(self):
        z, width = np.array([0.5, 1.5, 2.5, 3.5]), 1.0
        np.testing.assert_allclose(overlap(z, width, 1.25, 3.0), [0.0, 0.75, 1.0, 0.0])
        np.testing.assert_allclose(overlap(z, width, 1.2, 1.4), [0.0, 0.2, 0.0, 0.0])
        np.testing.assert_allclose(overlap(z, width, -5.0, 5.0), [1.0] * 4)

    def test_band_share(self):
        z, width = np.array([0.5, 1.5, 2.5, 3.5]), 1.0
        count = np.array([[10.0, 20.0, 30.0, 40.0], [1.0, 1.0, 1.0, 1.0]])
        np.testing.assert_allclose(band_share(count, z, width, 1.5, 3.0), [(0.5 * 20 + 30) / 100, 1.5 / 4])


class MirrorAsymmetry(unittest.TestCase):
    def blocks(self, rng, n, m, sigma, slope, count=100.0):
        z = -0.5 * n * 0.01 + 0.01 * (np.arange(n) + 0.5)  # symmetric about 0, width 0.01
        u = 0.7 + slope * z + rng.normal(0.0, sigma, (m, n))
        counts = np.full((m, n), count)
        return z, counts, counts * u

    def test_noise_only(self):
        # 2000 mirrored pairs over m = 10 super-blocks: each du / err is Student-t with 9 dof, so chi^2
        # per pair has mean 9 / 7 and the mean over the pairs a standard error sqrt(var(t^2) / 2000),
        # var(t^2) = 3 * 81 / (7 * 5) - (9 / 7)^2; err^2 has mean 2 sigma^2 / m.
        rng = np.random.default_rng(16)
        sigma, m = 0.05, 10
        z, count, sum_u = self.blocks(rng, 4000, m, sigma, 0.0)
        a = mirror_asymmetry(z, 0.0, count, sum_u)
        self.assertEqual(a["pairs"], 2000)
        var_t2 = 3 * 81 / 35 - (9 / 7) ** 2
        self.assertLess(abs(a["chi2"] - 9 / 7), 5 * math.sqrt(var_t2 / 2000))
        expected_noise2 = 2 * sigma ** 2 / m
        self.assertLess(abs(a["noise"] ** 2 / expected_noise2 - 1.0), 5 * math.sqrt(2 / 9) / math.sqrt(2000))
        self.assertLess(abs(a["rms"] ** 2 / expected_noise2 - 1.0), 5 * math.sqrt(2 / 2000))
        self.assertLess(abs(a["A"].value), 5 * a["A"].error)
        np.testing.assert_allclose(a["z"], z[2000:])

    def test_planted_asymmetry(self):
        # u = 0.7 + a z: du at distance z is 2 a z, the halves' means differ by a (2 h / 2) = a h.
        rng = np.random.default_rng(17)
        n, m, slope = 200, 8, 0.4
        z, count, sum_u = self.blocks(rng, n, m, 1e-3, slope)
        a = mirror_asymmetry(z, 0.0, count, sum_u)
        h = 0.5 * n * 0.01
        residual = a["du"] - 2 * slope * a["z"]
        self.assertLess(abs(residual.mean()), 5 * a["noise"] / math.sqrt(a["pairs"]))
        self.assertLess(abs(a["A"].value - slope * h), 5 * a["A"].error)
        self.assertGreater(a["chi2"], 1e4)
        self.assertAlmostEqual(a["max"], 2 * slope * a["z"].max(), delta=5 * a["err"].max())

    def test_centre_off_the_bins_exits(self):
        z = np.array([0.5, 1.5, 2.5, 3.5])
        with self.assertRaises(SystemExit):
            mirror_asymmetry(z, 2.1, np.ones((3, 4)), np.ones((3, 4)))


if __name__ == "__main__":
    unittest.main()
