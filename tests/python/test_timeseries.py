"""dpdfoam.timeseries: time series as super-block means.

Times fall in the super-block their time says, the window's start included and its end excluded (or,
closed, the end itself in the last one); anything before, after or NaN is left out. Means per
super-block and bin leave out what is not there (NaN for an empty one) and the mean over super-blocks
that hold a value has the sample standard error of those. Slopes per super-block recover an exact line.
The window comes from fit.dat (the last m super-blocks before the run's end; no super-blocks: exit).
On a seeded AR(1) series (phi 0.9: the mean's variance 19 times the independent one) the super-block
error's mean square is the analytic variance of the mean within five of its standard errors, where the
samples taken as independent would be off by a factor 19. The log's series and run report are parsed
from the lines the solver prints; a missing log gives no numbers.
"""
import math
import os
import tempfile
import unittest

import numpy as np

from dpdfoam.timeseries import (SuperBlockWindow, binned_block_means, binned_profile, block_index, block_means,
                                block_slopes, log_series, nan_block_mean, rows_in_blocks, run_report)
from dpdtest_support import jackknife_fit, write_fit, write_text


class BlockIndex(unittest.TestCase):
    # Window [10, 30): four super-blocks of 5.
    times = np.array([9.99, 10.0, 14.999, 15.0, 24.0, 29.99, 30.0, np.nan])

    def test_open(self):
        with np.errstate(invalid="ignore"):  # the NaN's cast
            np.testing.assert_array_equal(block_index(self.times, 10.0, 5.0, 4, closed=False), [-1, 0, 0, 1, 2, 3, -1, -1])

    def test_closed_takes_the_end(self):
        with np.errstate(invalid="ignore"):
            np.testing.assert_array_equal(block_index(self.times, 10.0, 5.0, 4), [-1, 0, 0, 1, 2, 3, 3, -1])

    def test_closed_leaves_out_times_after_the_end(self):
        # closed takes only the window's end itself into the last super-block: a time after it is outside.
        np.testing.assert_array_equal(block_index([31.0, 100.0], 10.0, 5.0, 4), [-1, -1])

    def test_closed_takes_the_end_to_rounding(self):
        # A window start = end - m length rounds: the end reads 3.0000000000000004 super-blocks in.
        end, length, m = 1.0, 0.1, 3
        np.testing.assert_array_equal(block_index([end, end + 1e-4], end - m * length, length, m), [2, -1])

    def test_rows_in_blocks(self):
        rows = np.column_stack([[5.0, 11.0, 16.0, 29.0, 35.0], [1.0, 2.0, 3.0, 4.0, 5.0]])
        kept, k = rows_in_blocks(rows, 10.0, 5.0, 4, closed=False)
        np.testing.assert_array_equal(kept[:, 1], [2.0, 3.0, 4.0])
        np.testing.assert_array_equal(k, [0, 1, 3])


class Means(unittest.TestCase):
    def test_block_means(self):
        index = np.array([0, 0, 2, 2, 2, -1])
        out = block_means([1.0, 3.0, 4.0, 5.0, 6.0, 100.0], index, 3)
        np.testing.assert_array_equal(out[[0, 2]], [2.0, 5.0])
        self.assertTrue(np.isnan(out[1]))

    def test_binned_block_means(self):
        index = np.array([0, 0, 0, 1, 1])
        bins = np.array([0, 1, 1, 0, 5])  # bin 5 is beyond the 2 bins: left out
        out = binned_block_means([1.0, 2.0, 4.0, 7.0, 9.0], index, bins, 2, 2)
        np.testing.assert_array_equal(out[0], [1.0, 3.0])
        self.assertEqual(out[1, 0], 7.0)
        self.assertTrue(np.isnan(out[1, 1]))

    def test_nan_block_mean(self):
        means = np.array([[1.0, np.nan, np.nan], [3.0, 4.0, np.nan], [8.0, np.nan, np.nan]])
        mean, error = nan_block_mean(means)
        self.assertEqual(mean[0], 4.0)
        self.assertAlmostEqual(error[0], math.sqrt(13.0) / math.sqrt(3.0), places=14)
        self.assertEqual(mean[1], 4.0)
        self.assertTrue(np.isnan(error[1]))  # one super-block: no error
        self.assertTrue(np.isnan(mean[2]) and np.isnan(error[2]))

    def test_block_slopes(self):
        x = np.tile(np.arange(5.0), 3)
        index = np.repeat([0, 1, 2], 5)
        y = np.array([2.0, -1.0, 0.5])[index] * x + 3.0
        index[10:13] = -1  # super-block 2 keeps 2 points: fewer than 3
        slopes = block_slopes(x, y, index, 3)
        self.assertAlmostEqual(slopes[0], 2.0, places=12)
        self.assertAlmostEqual(slopes[1], -1.0, places=12)
        self.assertTrue(np.isnan(slopes[2]))

    def test_binned_profile(self):
        positions = np.array([0.5, 1.5, 0.2, 1.9, 0.7, 2.5, -0.1])
        values = np.array([1.0, 10.0, 3.0, 20.0, 2.0, 99.0, 99.0])
        index = np.array([0, 0, 1, 1, 1, 0, 1])
        centres, mean, error = binned_profile(values, positions, np.array([0.0, 1.0, 2.0]), index, 2)
        np.testing.assert_array_equal(centres, [0.5, 1.5])
        np.testing.assert_allclose(mean, [(1.0 + 2.5) / 2, 15.0])
        np.testing.assert_allclose(error, [np.std([1.0, 2.5], ddof=1) / math.sqrt(2), np.std([10.0, 20.0], ddof=1) / math.sqrt(2)])


class Window(unittest.TestCase):
    def setUp(self):
        self._tmp = tempfile.TemporaryDirectory()
        self.case = os.path.join(self._tmp.name, "case")

    def tearDown(self):
        self._tmp.cleanup()

    def test_from_fit(self):
        write_fit(self.case, jackknife_fit(4, 5, 50.0))
        w = SuperBlockWindow(self.case, 500.0)
        self.assertEqual((w.per, w.m, w.length, w.start, w.end), (5, 4, 50.0, 300.0, 500.0))
        np.testing.assert_array_equal(w.index([299.0, 300.0, 349.9, 350.0, 500.0]), [-1, 0, 0, 1, 3])
        rows = np.column_stack([np.arange(300.0, 500.0, 10.0), np.arange(20.0)])
        kept, k = w.rows(rows)
        self.assertEqual(len(kept), 20)
        means = w.column_means(rows, [1])
        np.testing.assert_allclose(means[0].blocks, [2.0, 7.0, 12.0, 17.0])
        self.assertEqual(w.mean(rows[:, 1], k).value, 9.5)

    def test_without_super_blocks_exits(self):
        write_fit(self.case, {"errors": "blocks", "superBlocksNote": "run shorter than two super-blocks"})
        with self.assertRaises(SystemExit):
            SuperBlockWindow(self.case, 500.0)

    def test_correlated_series(self):
        # AR(1) x_t = phi x_{t-1} + e_t, stationary variance 1: the variance of the mean of n samples is
        # (1 / n)(1 + phi) / (1 - phi), less 2 phi / (n (1 - phi)^2) relative. 8 super-blocks of 2000
        # samples, 300 series: E[error^2] has relative standard error sqrt(2 / 7) / sqrt(300) = 3 %; the
        # neighbouring super-blocks' correlation biases it by 2 phi / (L (1 - phi)^2) = 0.9 % (L = 2000),
        # allowed for with 0.02 beside the five standard errors.
        phi, per_block, m, series = 0.9, 2000, 8, 300
        write_fit(self.case, jackknife_fit(m, 1, float(per_block)))
        w = SuperBlockWindow(self.case, float(per_block * m))
        rng = np.random.default_rng(20)
        n = per_block * m
        x = np.empty((n, series))
        x[0] = rng.normal(size=series)
        noise = rng.normal(0.0, math.sqrt(1 - phi * phi), (n, series))
        for t in range(1, n):
            x[t] = phi * x[t - 1] + noise[t]
        index = w.index(np.arange(n) + 0.5)
        squares = np.array([w.mean(x[:, s], index).error ** 2 for s in range(series)])
        expected = (1 + phi) / (1 - phi) / n
        self.assertLess(abs(squares.mean() / expected - 1.0), 5 * math.sqrt(2 / 7) / math.sqrt(series) + 0.02)
        naive = np.mean([x[:, s].std(ddof=1) ** 2 / n for s in range(series)])
        self.assertGreater(expected / naive, 15.0)


class Logs(unittest.TestCase):
    text = ("Particles      : 1200 (1000 mobile, 200 frozen)\n"
            + "".join(f"Time = {t}  (step {t})\n    kT = 1.0{t}   momentum = (0 0 0)   meanVelocity = ({0.1 * t:g} 0 0)\n"
                      for t in range(1, 4))
            + "Time = 4  (step 4)\n\nRun finished: 4 steps in 2 s, 2000 particle-steps/s\nEnd\n")

    def test_log_series(self):
        times, values = log_series(self.text, r"meanVelocity = \((\S+)")
        np.testing.assert_array_equal(times, [1.0, 2.0, 3.0])  # the fourth time has no value
        np.testing.assert_allclose(values, [0.1, 0.2, 0.3])

    def test_run_report(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = write_text(os.path.join(tmp, "log.dpdFoamLike"), self.text)
            particles, finished, (times, values) = run_report(path, r"kT = (\S+)")
            self.assertEqual((particles, finished), (1200, (4, 2.0, 2000.0)))
            np.testing.assert_allclose(values, [1.01, 1.02, 1.03])
            particles, finished, series = run_report(os.path.join(tmp, "none"), r"kT = (\S+)")
            self.assertEqual((particles, series), (0, ([], [])))
            self.assertTrue(all(math.isnan(v) for v in finished))


if __name__ == "__main__":
    unittest.main()
