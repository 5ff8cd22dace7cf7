"""dpdfoam.pair_temperature: single, pair and shared kT against a brute-force reference and known physics.

On a few hundred particles of a periodic box, 3-D and 2-D, the three temperatures equal those of an
independent O(N^2) implementation of the docstring's definitions (minimum-image pairs closer than r_c
with both particles in the slab, velocities about the interpolated mean profile) to rounding. On seeded
fluids, with the mean shear removed by the profile: for independent velocities at kT, single = pair =
kT and shared = 0; for molecules of two particles sharing an extra velocity of variance s^2 per
component, single = kT + s^2, shared = f s^2 and pair = kT + (1 - f) s^2 (the motion a pair shares
cancels in it), f the share of the pairs that lie within a molecule (counted exactly) - each within
five standard errors of the spread over 12 independent snapshots (Student-t, 11 dof). The mean
profile bins the snapshots' velocities; snapshots of a case are read in time order within the window,
frozen particles left out; none in the window raises. The function's window comes from the
controlDict (a stand-in answers it); a bad axis, central fraction or entry raises; the table is
written whole and read back in preference to measuring.
"""
import contextlib
import io
import math
import os
import tempfile
import unittest

import numpy as np

from dpdfoam.pair_temperature import (case_rows, function_window, main, mean_profile, measure_case, pair_temperature,
                                      read_mobile, snapshot_temperatures, snapshot_times, table_path, write_table)
from dpdtest_support import fake_dictionary, write_snapshot


def brute_force(x, v, profile, axis, region, lo, hi, dimension, cutoff=1.0):
    """The docstring's definitions, pair by pair."""
    centres, u = profile
    mean = np.stack([np.interp(x[:, axis], centres, u[:, a]) for a in range(3)], axis=1)
    active = [0, 1, 2] if dimension == 3 else [0, 2]
    dv = (v - mean)[:, active]
    length = (np.asarray(hi) - np.asarray(lo))[active]
    inside = (x[:, axis] >= region[0]) & (x[:, axis] < region[1])
    single = np.mean(np.sum(dv[inside] ** 2, axis=1)) / len(active)
    pair_sum = shared_sum = 0.0
    pairs = 0
    idx = np.flatnonzero(inside)
    for a in range(len(idx)):
        i = idx[a]
        d = x[idx[a + 1:]][:, active] - x[i, active]
        d -= length * np.round(d / length)
        close = idx[a + 1:][np.sum(d * d, axis=1) < cutoff * cutoff]
        pairs += len(close)
        pair_sum += np.sum((dv[close] - dv[i]) ** 2)
        shared_sum += np.sum(dv[close] @ dv[i])
    return single, pair_sum / (2 * len(active) * pairs), shared_sum / (len(active) * pairs), pairs


class AgainstBruteForce(unittest.TestCase):
    def check(self, dimension):
        rng = np.random.default_rng(60 + dimension)
        lo, hi = np.array([0.0, -0.5, 0.0]), np.array([5.0, 0.5 if dimension == 2 else 4.0, 6.0])
        n = 300
        x = rng.uniform(lo, hi, (n, 3))
        if dimension == 2:
            x[:, 1] = 0.0
        x[:5] = hi - 1e-9  # particles at the box's edge pair across it
        centres = np.linspace(0.25, 5.75, 12)
        u = np.column_stack([0.3 * centres, 0.0 * centres, -0.1 * centres])
        v = rng.normal(0.0, 1.0, (n, 3)) + np.stack([np.interp(x[:, 2], centres, u[:, a]) for a in range(3)], axis=1)
        if dimension == 2:
            v[:, 1] = 0.0
        got = snapshot_temperatures(x, v, (centres, u), 2, (1.0, 5.0), lo, hi, dimension)
        want = brute_force(x, v, (centres, u), 2, (1.0, 5.0), lo, hi, dimension)
        self.assertGreater(want[3], 100)
        np.testing.assert_allclose(got, want[:3], rtol=1e-11)

    def test_3d(self):
        self.check(3)

    def test_2d(self):
        self.check(2)

    def test_profile_nan_bins_ignored(self):
        rng = np.random.default_rng(63)
        lo, hi = np.zeros(3), np.array([4.0, 4.0, 4.0])
        x = rng.uniform(lo, hi, (200, 3))
        v = rng.normal(size=(200, 3))
        centres = np.array([0.5, 1.5, 2.5, 3.5])
        u = np.array([[0.0, 0, 0], [np.nan, np.nan, np.nan], [0.2, 0, 0], [0.3, 0, 0]])
        got = snapshot_temperatures(x, v, (centres, u), 2, (0.0, 4.0), lo, hi, 3)
        good = [0, 2, 3]
        want = brute_force(x, v, (centres[good], u[good]), 2, (0.0, 4.0), lo, hi, 3)
        np.testing.assert_allclose(got, want[:3], rtol=1e-11)


class Physics(unittest.TestCase):
    """12 snapshots of 3000 particles (density 3) in a 10 x 10 x 10 box, kT 1.4, shear 0.1 along z."""
    snapshots, n, kT = 12, 3000, 1.4
    lo, hi = np.zeros(3), np.full(3, 10.0)

    def measure(self, molecules_s2=None, seed=64):
        rng = np.random.default_rng(seed)
        centres = np.linspace(0.25, 9.75, 20)
        u = np.column_stack([0.1 * centres, np.zeros(20), np.zeros(20)])
        out, shares = [], []
        for _ in range(self.snapshots):
            x = rng.uniform(self.lo, self.hi, (self.n, 3))
            v = rng.normal(0.0, math.sqrt(self.kT), (self.n, 3))
            if molecules_s2 is not None:
                # particles 2k and 2k + 1 form a molecule: 0.1 apart, one extra velocity
                x[1::2] = np.mod(x[::2] + rng.normal(0.0, 0.1 / math.sqrt(3), (self.n // 2, 3)), 10.0)
                extra = rng.normal(0.0, math.sqrt(molecules_s2), (self.n // 2, 3))
                v[::2] += extra
                v[1::2] += extra
                shares.append(self.molecule_share(x))
            v[:, 0] += 0.1 * x[:, 2]
            out.append(snapshot_temperatures(x, v, (centres, u), 2, (0.0, 10.0), self.lo, self.hi, 3))
        return np.array(out), np.array(shares)

    @staticmethod
    def molecule_share(x):
        """The share of the pairs closer than 1 that are the two particles of one molecule (exact count)."""
        from scipy.spatial import cKDTree

        pairs = cKDTree(x, boxsize=10.0).query_pairs(1.0, output_type="ndarray")
        same = (pairs[:, 0] // 2 == pairs[:, 1] // 2)
        return same.sum() / len(pairs)

    def assert_mean(self, values, expected):
        se = values.std(ddof=1) / math.sqrt(len(values))
        self.assertLess(abs(values.mean() - expected), 5 * se, f"{values.mean()} against {expected} (se {se})")
        return se

    def test_independent_velocities(self):
        t, _ = self.measure()
        self.assertLess(self.assert_mean(t[:, 0], self.kT), 0.01)
        self.assert_mean(t[:, 1], self.kT)
        self.assert_mean(t[:, 2], 0.0)

    def test_shared_motion(self):
        s2 = 0.5
        t, shares = self.measure(molecules_s2=s2, seed=65)
        self.assert_mean(t[:, 0], self.kT + s2)
        self.assert_mean(t[:, 1] - (1 - shares) * s2, self.kT)  # only the pairs of two molecules see the extra motion
        self.assert_mean(t[:, 2] - shares * s2, 0.0)
        self.assertGreater(shares.mean() * s2, 10 * t[:, 2].std(ddof=1) / math.sqrt(self.snapshots))  # decisive


class Case(unittest.TestCase):
    def setUp(self):
        self._tmp = tempfile.TemporaryDirectory()
        self.tmp = self._tmp.name
        self.case = os.path.join(self.tmp, "case")
        rng = np.random.default_rng(66)
        self.data = {}
        for t in (0, 100, 150, 200, 300):
            n_fluid, n_wall = 400, 50
            x = np.vstack([rng.uniform((0, 0, 1), (6, 6, 7), (n_fluid, 3)), rng.uniform((0, 0, 0), (6, 6, 1), (n_wall, 3))])
            v = np.vstack([rng.normal(0.0, 1.0, (n_fluid, 3)), np.full((n_wall, 3), 50.0)])  # frozen: absurd velocities
            species = np.r_[np.zeros(n_fluid, int), np.ones(n_wall, int)]
            write_snapshot(os.path.join(self.case, str(t), "particles.h5"), x, v, species, species_names=("fluid", "wall"),
                           frozen=(0, 1), lo=(0, 0, 0), hi=(6, 6, 8), time=float(t))
            self.data[t] = (x[:n_fluid], v[:n_fluid])
        self.control = os.path.join(self.case, "system", "controlDict")
        self.entries = {(self.control, "functions/channelProfile/axis"): "z", (self.control, "functions/channelProfile/min"): "1",
                        (self.control, "functions/channelProfile/max"): "7",
                        (self.control, "functions/channelProfile/startTime"): "100", (self.control, "endTime"): "200"}

    def tearDown(self):
        self._tmp.cleanup()

    def test_snapshots(self):
        self.assertEqual([t for t, _ in snapshot_times(self.case, 100, 200)], [100.0, 150.0, 200.0])
        x, v, lo, hi, dimension = read_mobile(os.path.join(self.case, "150", "particles.h5"))
        np.testing.assert_array_equal(x, self.data[150][0])
        np.testing.assert_array_equal(v, self.data[150][1])
        self.assertEqual(dimension, 3)
        np.testing.assert_array_equal(hi, [6, 6, 8])

    def test_mean_profile(self):
        x = np.array([[0, 0, 0.5], [0, 0, 1.5], [0, 0, 1.6], [0, 0, 3.0], [0, 0, 9.0]])
        v = np.array([[1.0, 0, 0], [2.0, 0, 0], [4.0, 2, 0], [8.0, 0, 0], [100.0, 0, 0]])
        centres, u = mean_profile([(x, v), (x[:1], 3 * v[:1])], 2, 0.0, 3.0, 3)
        np.testing.assert_array_equal(centres, [0.5, 1.5, 2.5])
        np.testing.assert_allclose(u[:2], [[2.0, 0, 0], [3.0, 1.0, 0]])  # bin 0: 1 and 3; bin 1: 2 and 4
        self.assertTrue(np.isnan(u[2]).all())  # 3.0 is the upper edge, beyond the bins

    def test_pair_temperature(self):
        rows = pair_temperature(self.case, 100, 200, 2, (2.5, 5.5), (1.0, 7.0), 24)
        np.testing.assert_array_equal(rows[:, 0], [100, 150, 200])
        profile = mean_profile([self.data[t] for t in (100, 150, 200)], 2, 1.0, 7.0, 24)
        for row, t in zip(rows, (100, 150, 200)):
            x, v = self.data[t]
            want = brute_force(x, v, (profile[0][np.isfinite(profile[1][:, 0])], profile[1][np.isfinite(profile[1][:, 0])]),
                               2, (2.5, 5.5), (0, 0, 0), (6, 6, 8), 3)
            np.testing.assert_allclose(row[1:], want[:3], rtol=1e-11)
        with self.assertRaises(RuntimeError):
            pair_temperature(self.case, 400, 500, 2, (2.5, 5.5), (1.0, 7.0), 24)

    def test_function_window(self):
        with fake_dictionary(self.tmp, self.entries):
            self.assertEqual(function_window(self.case, "channelProfile", 0.5), ("z", (2.5, 5.5), (1.0, 7.0), (100.0, 200.0)))
            for central in (0.0, 1.5):
                with self.assertRaises(RuntimeError):
                    function_window(self.case, "channelProfile", central)
            with self.assertRaises(RuntimeError):
                function_window(self.case, "otherProfile", 0.5)
        bad = dict(self.entries)
        bad[(self.control, "functions/channelProfile/axis")] = "r"
        with fake_dictionary(self.tmp, bad):
            with self.assertRaises(RuntimeError):
                function_window(self.case, "channelProfile", 0.5)

    def test_measure_case_and_table(self):
        with fake_dictionary(self.tmp, self.entries):
            rows, path = measure_case(self.case, "channelProfile")
            self.assertEqual(path, table_path(self.case, 100.0))
            np.testing.assert_allclose(rows, pair_temperature(self.case, 100, 200, 2, (2.5, 5.5), (1.0, 7.0), 24))
            np.testing.assert_allclose(np.loadtxt(path, ndmin=2), rows, rtol=1e-9)
            self.assertEqual(os.listdir(os.path.dirname(path)), ["pairTemperature.dat"])  # no temporary file left
            write_table(path, np.array([[100.0, 9.0, 9.0, 9.0]]), "time single pair shared")
            np.testing.assert_array_equal(case_rows(self.case, "channelProfile"), [[100.0, 9.0, 9.0, 9.0]])  # the table
            out = io.StringIO()
            with contextlib.redirect_stdout(out):
                self.assertEqual(main(["-case", self.case, "-function", "channelProfile"]), 0)
            self.assertIn("3 snapshots", out.getvalue())
            with self.assertRaises(SystemExit):
                with contextlib.redirect_stderr(io.StringIO()):
                    main(["-case", self.case, "-function", "channelProfile", "-central", "2"])


if __name__ == "__main__":
    unittest.main()
