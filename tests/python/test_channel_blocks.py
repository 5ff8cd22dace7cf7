"""dpdfoam.channel_blocks on a Poiseuille channel case built here from particles of known velocities.

The case's walls, g and window come from its fit.dat and controlDict (a stand-in answers dpdDictionary):
the last m super-blocks before endTime, the latest profile and time directories. Its sampled blocks hold
particle-samples uniform across the channel, moving with the no-slip Poiseuille profile of the fit's g
and nu plus thermal velocities of kT 1; two earlier sampling blocks, moved by +10, lie before the window
and must be left out. From them the mass-weighted mean velocity is g d^2 / (12 nu), the centre's (|z| <
1) g (d^2 / 4 - 1 / 3) / (2 nu), the bulk's and the channel's kT 1, the halves' asymmetry 0, each within
five thermal standard errors of the samples used (known: kT / N); nu carries the fit's jackknife error
with m - 1 dof, and the Reynolds number is uc d / nu. The bulk's and the walls' densities, the
pair-temperature table's super-block means (a super-block with fewer than two snapshots stops it), an
x-averaged grid's flow measures and the run's log come out as written.
"""
import math
import os
import tempfile
import unittest

import numpy as np

from dpdfoam.channel_blocks import SuperBlockChannel
from dpdfoam.channel import poiseuille_velocity
from dpdtest_support import bin_sums, fake_dictionary, jackknife_fit, write_fit, write_sampling, write_text

G, NU, WALLS, KT = 0.02, 0.3, (-4.0, 4.0), 1.0
BINS, WIDTH, PER_BIN = 16, 0.5, 1000  # particle-samples per bin and sampling block
M, PER, BLOCK_SAMPLES, EARLY = 4, 2, 10, 2


def sampled_channel(rng, count_of_bin=lambda z: PER_BIN):
    """(blocks, bins, 12) sums: EARLY blocks before the window moved by +10 along x, then M x PER blocks."""
    edges = WALLS[0] + WIDTH * np.arange(BINS + 1)
    blocks = []
    for k in range(EARLY + M * PER):
        row = []
        for b in range(BINS):
            n = count_of_bin(0.5 * (edges[b] + edges[b + 1]))
            z = rng.uniform(edges[b], edges[b + 1], n)
            v = rng.normal(0.0, math.sqrt(KT), (n, 3))
            v[:, 0] += poiseuille_velocity(z, WALLS[0], WALLS[1], G, NU) + (10.0 if k < EARLY else 0.0)
            row.append(bin_sums(z, v))
        blocks.append(row)
    return np.array(blocks)


class Channel(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls._tmp = tempfile.TemporaryDirectory()
        cls.tmp = cls._tmp.name
        cls.case = os.path.join(cls.tmp, "case")
        rng = np.random.default_rng(70)
        blocks = EARLY + M * PER
        write_sampling(os.path.join(cls.case, "400", "sampling", "channelProfile.h5"), sampled_channel(rng),
                       [BLOCK_SAMPLES] * blocks, WALLS[0], WALLS[1], BLOCK_SAMPLES, 20.0)
        near_half = lambda z: PER_BIN // 2 if abs(z) > 3.0 else PER_BIN  # noqa: E731
        write_sampling(os.path.join(cls.case, "400", "sampling", "fluidProfile.h5"), sampled_channel(rng, near_half),
                       [BLOCK_SAMPLES] * blocks, WALLS[0], WALLS[1], BLOCK_SAMPLES, 20.0)
        os.makedirs(os.path.join(cls.case, "0"))
        os.makedirs(os.path.join(cls.case, "postProcessing", "profileBins", "100"))
        os.makedirs(os.path.join(cls.case, "postProcessing", "profileBins", "400"))
        write_fit(cls.case, jackknife_fit(M, PER, 50.0, wallPosition=list(WALLS), g=G, nu=NU, nuError=0.01))
        control = os.path.join(cls.case, "system", "controlDict")
        cls.entries = {(control, "endTime"): "400", (control, "functions/channelProfile/startTime"): "100",
                       (control, "functions/channelProfile/axis"): "z", (control, "functions/channelProfile/min"): "-4",
                       (control, "functions/channelProfile/max"): "4"}
        with fake_dictionary(cls.tmp, cls.entries):
            cls.channel = SuperBlockChannel(cls.case)
            cls.channel.measure_flow()
        # The window's particle-samples: all bins, the centre's 4 bins, the bulk's 8, one half's 8.
        cls.samples = M * PER * BINS * PER_BIN

    @classmethod
    def tearDownClass(cls):
        cls._tmp.cleanup()

    def test_case(self):
        c = self.channel
        self.assertEqual((c.start, c.end, c.walls, c.g), (100.0, 400.0, WALLS, G))
        self.assertEqual((c.d, c.centre, c.h), (8.0, 0.0, 4.0))
        self.assertEqual((c.window.start, c.window.m, c.window.per), (200.0, M, PER))
        self.assertEqual(c.profiles, os.path.join(self.case, "postProcessing", "profileBins", "400"))
        self.assertEqual(c.time_dir, os.path.join(self.case, "400"))
        np.testing.assert_array_equal(c.bulk(np.array([-2.1, -1.9, 0.0, 1.99, 2.0])), [False, True, True, True, False])
        np.testing.assert_array_equal(c.near(np.array([-3.5, -2.9, 3.2, 2.5])), [True, False, True, False])

    def test_flow(self):
        c = self.channel
        n = self.samples
        self.assertEqual(c.U.m, M)
        # U's samples spread by kT and by u(z) over the channel (variance (g / 2 nu)^2 (4096 / 180) = 0.025)
        self.assertLess(abs(c.U.value - G * 64 / (12 * NU)), 5 * math.sqrt((KT + 0.03) / n))
        self.assertLess(abs(c.uc.value - G * (16 - 1 / 3) / (2 * NU)), 5 * math.sqrt(KT / (n / 4)))
        self.assertLess(abs(c.kT.value - KT), 5 * KT * math.sqrt(2 / (3 * n / 2)))
        self.assertLess(abs(c.kT_mean - KT), 5 * KT * math.sqrt(2 / (3 * n)))
        self.assertLess(abs(c.asym["A"].value), 5 * math.sqrt(2 * KT / (n / 2)))
        self.assertEqual(c.asym["pairs"], BINS // 2)
        self.assertEqual((c.nu.value, c.nu.error, c.nu.dof), (NU, 0.01, M - 1))
        self.assertAlmostEqual(c.reynolds, c.uc.value * 8.0 / NU, places=14)

    def test_regions(self):
        c = self.channel
        sums, bulk, near, kT = c.regions(c.sampled("fluidProfile"))
        self.assertEqual(sums.shape, (M, BINS, 12))
        samples = PER * BLOCK_SAMPLES
        np.testing.assert_allclose(bulk, PER * PER_BIN / (samples * WIDTH * 20.0))
        np.testing.assert_allclose(near, PER * PER_BIN / 2 / (samples * WIDTH * 20.0))
        self.assertLess(abs(kT.value - KT), 5 * KT * math.sqrt(2 / (3 * self.samples / 2)))

    def test_heat(self):
        # The pair-temperature table: snapshots every 10 from 150 (before the window) to 400, single 1 + 0.01 k
        # in super-block k (and 0.5 before), pair 1, shared 0.01 k - 0.005 (t / 10 odd) or + 0.005.
        times = np.arange(150.0, 401.0, 10.0)
        k = np.minimum(np.floor((times - 200.0) / 50.0), M - 1)
        single = np.where(k >= 0, 1.0 + 0.01 * k, 0.5)
        shared = 0.01 * k + np.where((times / 10) % 2 == 1, -0.005, 0.005)
        table = os.path.join(self.case, "postProcessing", "pairTemperature", "100", "pairTemperature.dat")
        os.makedirs(os.path.dirname(table), exist_ok=True)
        np.savetxt(table, np.column_stack([times, single, np.ones(len(times)), shared]), header="time single pair shared")
        c = SuperBlockChannel.__new__(SuperBlockChannel)
        c.path, c.profile, c.window = self.case, "channelProfile", self.channel.window
        with fake_dictionary(self.tmp, self.entries):
            c.measure_heat()
        np.testing.assert_allclose(c.kT_single.blocks, [1.0, 1.01, 1.02, 1.03])
        np.testing.assert_allclose(c.kT_pair.blocks, 1.0)
        # Snapshots 20-24 (x 10) in super-block 0: +, -, +, -, + 0.005 -> +0.001; 25-29: -0.001; 30-34: +0.001;
        # 35-40 (the end in the last): three of each, 0.
        np.testing.assert_allclose(c.kT_shared.blocks, [0.001, 0.009, 0.021, 0.03], atol=1e-15)
        self.assertEqual(c.snapshots, 21)
        np.savetxt(table, np.column_stack([[210.0, 220.0, 260.0, 270.0, 310.0, 360.0, 370.0], np.ones((7, 3))]))
        with fake_dictionary(self.tmp, self.entries):
            with self.assertRaises(SystemExit):
                c.measure_heat()

    def test_grid_flow(self):
        z = np.array([-3.0, -1.0, -0.5, 0.5, 1.0, 3.0])
        field = {"z": z, "count": np.array([1.0, 2.0, 1.0, 1.0, 2.0, 3.0]), "ux": np.array([0.1, 0.4, 0.5, 0.7, 0.4, 0.2]),
                 "kT": np.array([2.0, 1.1, 1.0, 1.2, 0.9, 3.0])}
        out = self.channel.grid_flow(field)
        self.assertAlmostEqual(out["U"], (0.1 + 0.8 + 0.5 + 0.7 + 0.8 + 0.6) / 10, places=14)
        self.assertAlmostEqual(out["uc"], (0.5 + 0.7) / 2, places=14)
        self.assertAlmostEqual(out["A"], (0.7 + 0.8 + 0.6) / 6 - (0.1 + 0.8 + 0.5) / 4, places=14)
        self.assertAlmostEqual(out["kT"], (2.2 + 1.0 + 1.2 + 1.8) / 6, places=14)

    def test_read_log(self):
        c = SuperBlockChannel.__new__(SuperBlockChannel)
        c.path = os.path.join(self.tmp, "logcase")
        write_text(os.path.join(c.path, "log.dpdFoamLike"),
                   "Particles      : 5000 (4000 mobile, 1000 frozen)\n"
                   + "".join(f"Time = {t}  (step {t})\n    kT = 1   momentum = (0 0 0)   meanVelocity = ({t / 100} 0 0)\n"
                             for t in (100, 200))
                   + "Run finished: 200 steps in 4 s, 2e+05 particle-steps/s\n")
        c.read_log()
        self.assertEqual((c.particles, c.steps, c.seconds, c.rate), (5000, 200, 4.0, 2e5))
        np.testing.assert_array_equal(c.history[0], [100, 200])
        np.testing.assert_allclose(c.history[1], [1.0, 2.0])


if __name__ == "__main__":
    unittest.main()
