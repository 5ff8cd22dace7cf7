"""dpdfoam.sweep: runSweep's sweeps, a profile's measures near its walls, channels with long-block errors.

The sweep's table gives each run's swept value and the two walls' mean slip; the published comparison
uses issue 25's bound max(0.3 r_c, 30 %); a variant that has not run gives no rows. The slip-falls
checks pass a sweep whose slip grows as the parameter falls and fail a real reversal, a rise too small
to be decisive, a step too noisy to decide, a NaN and a sweep of mismatched or too few runs. On
analytic profiles: a density ramping linearly from 0 at each wall to the bulk over one cutoff misses
exactly half a cutoff (the midpoint sum is exact for a line) with its error by hand; slab means,
count-weighted errors, the wall layer's density and kT, the first bins, the flatness and kT over the
no-wall box's kT(shear) are the hand-computed values. A LongBlockRun on sampled blocks built here:
identical sampling blocks within each super-block give the inefficiency (m per - 1) / (m - 1)
exactly, independent ones 1 within five standard errors of the pooled variance ratio; bins in k
groups of identical, mutually orthogonal super-block deviations give the effective number of bins
n^2 / (n + k g (g - 1)(1 - 1/N)); profile chi^2 of two runs apart by delta is delta^2 / (2 e^2);
agreement combines the two jackknife errors with Welch-Satterthwaite's dof; without super-blocks the
run says why and keeps fitSlipLength's errors.
"""
import math
import os
import unittest

import numpy as np

from dpdfoam.checks import Checks
from dpdfoam.stats import combined
from dpdfoam.sweep import (LongBlockRun, accounted_by, agreement, central_density, comparison_line, density_flatness,
                           effective_dof, first_bins_density, kT_over_no_wall, long_block_lines, near_both_walls, per_wall,
                           profile_chi2, published_comparison, published_lines, slab_means, slip_falls_checks, sweep_colours,
                           sweep_slip, variant_of, wall_depletion, wall_distance, wall_layer_density, wall_layer_kT,
                           weighted_error)
from dpdtest_support import jackknife_fit, Temporary, write_fit, write_sampling, write_table, write_text

NAN = float("nan")
SWEEP = ("# case pairCoeffs/wall-wall/a slipLength_0 slipLength_1 slipLengthError_0 slipLengthError_1\n"
         "a10 10 1.9 2.1 0.06 0.08\na20 20 0.45 0.55 0.04 0.04\na40 40 0.1 none 0.03 0.03\n")


class Sweeps(Temporary):
    def test_variant_of(self):
        self.assertEqual(variant_of(["plotResults.py", "-test", "-noSlipWall"], ["-noSlipWall", "-dense"]),
                         ("-noSlipWall", "NoSlipWall"))
        self.assertEqual(variant_of(["plotResults.py", "-test"], ["-noSlipWall"]), (None, ""))
        self.assertEqual(variant_of(["-noSlipWall"], ["-noSlipWall"]), (None, ""))  # argv[0] is the script

    def test_sweep_slip_and_per_wall(self):
        path = write_text(os.path.join(self.tmp, "sweep.dat"), SWEEP)
        sweep, a, b, err = sweep_slip(path, "pairCoeffs/wall-wall/a")
        np.testing.assert_array_equal(a, [10, 20, 40])
        np.testing.assert_allclose(b[:2], [2.0, 0.5])
        self.assertTrue(np.isnan(b[2]))
        np.testing.assert_allclose(err, [0.05, 0.5 * math.hypot(0.04, 0.04), 0.5 * math.hypot(0.03, 0.03)])
        np.testing.assert_allclose(per_wall(sweep, "slipLength")[:2], [[1.9, 2.1], [0.45, 0.55]])

    def test_published_comparison(self):
        table = {"a_ww": np.array([10.0, 20.0]), "slipLength": np.array([2.0, 0.5])}
        rows = published_comparison(table, "a_ww", np.array([10.0, 20.0]), np.array([2.55, 0.75]), np.array([0.05, 0.05]))
        self.assertEqual([(r[4], r[5]) for r in rows], [(0.6, True), (0.3, True)])
        rows = published_comparison(table, "a_ww", np.array([10.0, 20.0]), np.array([2.55, 0.75]), np.array([0.05, 0.05]),
                                    cutoff=0.5)
        self.assertEqual([(r[4], r[5]) for r in rows], [(0.6, True), (0.15, False)])

    def test_accounted_by(self):
        missing = accounted_by("the density", "run -dense", os.path.join(self.tmp, "none.dat"), "a", None)
        self.assertEqual(missing, ("the density", [], "run -dense"))
        path = write_text(os.path.join(self.tmp, "sweep.dat"), SWEEP)
        seen = []
        ingredient, rows, how = accounted_by("the density", "run -dense", path, "pairCoeffs/wall-wall/a",
                                             lambda *args: seen.append(args) or ["rows"])
        self.assertEqual((ingredient, rows, how), ("the density", ["rows"], "run -dense"))
        np.testing.assert_array_equal(seen[0][0], [10, 20, 40])
        np.testing.assert_allclose(seen[0][1][:2], [2.0, 0.5])

    def test_lines(self):
        row = (10.0, 2.1, 0.05, 2.0, 0.6, True)
        self.assertEqual(comparison_line(row), "published    10  +2.1000 +- 0.0500   2.0000   +0.1000  (+2.0)")
        lines = published_lines({"source": "Xu et al."}, [row], ["# header"], note=" (note)", extra=lambda r: " extra")
        self.assertEqual(lines[0], "# published: Xu et al., Table 1 (no errors stated: differences in units of this run's "
                                   "error) (note)")
        self.assertEqual(lines[1:], ["# header", comparison_line(row) + " extra"])

    def test_colours(self):
        self.assertEqual(sweep_colours(5).shape, (5, 4))


class SlipFalls(unittest.TestCase):
    def run_checks(self, values, b, err, step_budget=0.05, rise_budget=0.1):
        checks = Checks()
        slip_falls_checks(checks, "3-D", "gamma_fw", values, b, err, step_budget, rise_budget)
        return checks

    def test_growing_slip_passes(self):
        c = self.run_checks([13.5, 1.0, 4.5, 2.0], [0.0, 1.9, 0.55, 1.1], [0.02] * 4)
        self.assertEqual(len(c.rows), 4)  # three steps and the whole range
        self.assertEqual(c.status(), 0)
        self.assertIn("gamma_fw 1 than at 13.5", c.rows[-1][0])

    def test_a_small_reversal_within_the_bound_passes(self):
        c = self.run_checks([1.0, 2.0, 4.5], [1.0, 1.1, 0.5], [0.02] * 3)  # 1 -> 2 lowers b by 0.1 < 3 x 0.05
        self.assertEqual(c.status(), 0)

    def test_failures(self):
        for values, b, err, why in (
                ([1.0, 2.0, 4.5], [1.0, 1.2, 0.5], [0.02] * 3, "a reversal"),
                ([1.0, 2.0], [0.5, 0.3], [0.02] * 2, "a rise within 3 rise budgets"),
                ([1.0, 2.0], [2.0, 0.3], [0.02, 0.05], "a step too noisy to decide"),
                ([1.0, 2.0], [2.0, NAN], [0.02] * 2, "a NaN slip"),
                ([1.0, 2.0], [2.0, 0.3], [0.02, None], "a missing error"),
                ([1.0, 2.0], [2.0, 0.3, 0.1], [0.02] * 3, "mismatched runs"),
                ([1.0], [2.0], [0.02], "one run")):
            self.assertEqual(self.run_checks(values, b, err).status(), 1, why)


def ramp_profile(cutoff=1.0, dz=0.1):
    """Bins of dz between walls at -5 and 5: density rising linearly from 0 at each wall to 3 at one
    cutoff, 3 beyond; densityErr 0.02; kT 1.2 within a cutoff, 1 beyond; count 100 density."""
    z = -5.0 + dz * (np.arange(int(round(10.0 / dz))) + 0.5)
    d = np.minimum(z + 5.0, 5.0 - z)
    density = np.where(d < cutoff, 3.0 * d / cutoff, 3.0)
    return {"z": z, "density": density, "densityErr": np.full(len(z), 0.02), "kT": np.where(d < cutoff, 1.2, 1.0),
            "count": 100.0 * density, "ux": np.zeros(len(z))}


class NearWalls(unittest.TestCase):
    walls = (-5.0, 5.0)

    def test_distances(self):
        z = np.array([-4.5, 0.0, 4.9])
        np.testing.assert_allclose(wall_distance(z, self.walls), [0.5, 5.0, 0.1])
        dist, values = near_both_walls(z, np.array([1.0, 2.0, 3.0]), self.walls, 1.0)
        np.testing.assert_allclose(dist, [0.5, 0.1])
        np.testing.assert_array_equal(values, [1.0, 3.0])

    def test_wall_depletion(self):
        prof = ramp_profile()
        self.assertEqual(central_density(prof, self.walls), 3.0)
        gap, error = wall_depletion(prof, self.walls)
        self.assertAlmostEqual(gap, 0.5, places=12)  # int_0^1 (1 - d) dd, each wall
        near = prof["density"] < 3.0
        n_near, n_centre = near.sum(), (np.abs(prof["z"]) < 2.5).sum()
        self.assertEqual((n_near, n_centre), (20, 50))
        by_bins = 0.5 * 0.1 / 3.0 * 0.02 * math.sqrt(n_near)
        by_centre = 0.5 * 0.1 * prof["density"][near].sum() / 9.0 * 0.02 * math.sqrt(n_centre) / n_centre
        self.assertAlmostEqual(error, math.hypot(by_bins, by_centre), places=14)

    def test_layer_measures(self):
        prof = ramp_profile()
        self.assertAlmostEqual(wall_layer_density(prof, self.walls), 0.5, places=12)  # mean of the ramp
        self.assertAlmostEqual(wall_layer_kT(prof, self.walls), 1.2, places=14)
        self.assertAlmostEqual(first_bins_density(prof, self.walls), 0.05, places=12)  # 0.15 / 3
        self.assertEqual(density_flatness(prof, self.walls), 0.0)
        prof["density"][50] = 3.3
        self.assertAlmostEqual(density_flatness(prof, self.walls), 3.3 / (3.0 + 0.3 / 80) - 1.0, places=12)  # 80 bins beyond

    def test_slab_means(self):
        z = 0.25 + 0.5 * np.arange(8)  # 0.25 .. 3.75
        values, errors = z.copy(), np.full(8, 0.1)
        means, errs = slab_means(z, values, errors, 0.0, 4.0, 2.0)
        np.testing.assert_allclose(means, [1.0, 3.0])
        np.testing.assert_allclose(errs, [0.05, 0.05])

    def test_weighted_error(self):
        self.assertAlmostEqual(weighted_error(np.array([1.0, 1.0, 1.0, 1.0]), np.full(4, 0.2)), 0.1, places=14)
        self.assertAlmostEqual(weighted_error(np.array([3.0, 1.0]), np.array([0.1, 0.4])), 0.5 / 4, places=14)

    def test_kT_over_no_wall(self):
        # The box's kT(shear) = 1 + 0.5 shear; the channel's kT 0.01 above it at every bin.
        g, nu, centre = 0.02, 0.25, 0.0
        shear_axis = np.linspace(0.0, 1.0, 50)
        z = np.linspace(-4.75, 4.75, 20)
        prof = {"z": z, "kT": 1.01 + 0.5 * g * np.abs(z) / nu, "count": np.arange(1.0, 21.0)}
        bulk = np.abs(z) < 3.0
        self.assertAlmostEqual(kT_over_no_wall(prof, bulk, centre, g, nu, (shear_axis, 1.0 + 0.5 * shear_axis)), 0.01, places=12)


def long_block_case(root, name, per, m, u_blocks, walls=(-5.0, 5.0), exclude=0.5, **fit):
    """A channel case for LongBlockRun: fit.dat (jackknife over m super-blocks of per sampling blocks),
    its profile table and sampled blocks with bin velocities u_blocks (blocks, bins), 100 samples each."""
    case = os.path.join(root, name)
    blocks, bins = u_blocks.shape
    z = walls[0] + (walls[1] - walls[0]) / bins * (np.arange(bins) + 0.5)
    sums = np.zeros((blocks, bins, 12))
    sums[..., 0], sums[..., 1] = 100.0, 100.0 * u_blocks
    write_sampling(os.path.join(case, "500", "sampling", "channelProfile.h5"), sums, [10] * blocks, walls[0], walls[1], 10, 1.0)
    entries = jackknife_fit(m, per, 20.0, wallPosition=list(walls), exclude=exclude, nu=0.3, nuError=0.01,
                            slipLength=[0.1, 0.2], slipLengthError=[0.02, 0.03])
    entries.update(fit)
    write_fit(case, entries)
    density = np.where(np.minimum(z - walls[0], walls[1] - z) < 1.0, 2.5, 3.0)
    write_table(os.path.join(case, "postProcessing", "profileBins", "500", "channelProfile.dat"),
                {"z": z, "ux": u_blocks.mean(axis=0), "uxErr": np.full(bins, 0.01), "density": density})
    return case


class LongBlocks(Temporary):
    def test_identical_blocks_within_super_blocks(self):
        rng = np.random.default_rng(40)
        per, m, bins = 4, 6, 20
        u = np.repeat(rng.normal(0.0, 0.1, (m, bins)), per, axis=0)
        run = LongBlockRun("a", long_block_case(self.tmp, "a", per, m, u), "channelProfile")
        self.assertEqual((run.super_blocks, run.super_block_time, run.too_short), (m, 20.0, ""))
        self.assertAlmostEqual(run.inefficiency, (m * per - 1) / (m - 1), places=10)
        np.testing.assert_allclose(run.ux_error, 0.01 * math.sqrt((m * per - 1) / (m - 1)))
        self.assertEqual(run.fitted.sum(), 18)  # bins of 0.5 from -5: the first and last within 0.5 left out
        np.testing.assert_allclose(run.deviations.std(axis=0, ddof=1), 1.0)

    def test_independent_blocks(self):
        # var_super / m against var_short / (m per): the ratio's relative standard error is that of the
        # super-block variance pooled over 200 bins, sqrt(2 / (m - 1)) / sqrt(200) = 3.8 % (m = 8).
        rng = np.random.default_rng(41)
        per, m, bins = 5, 8, 202
        run = LongBlockRun("b", long_block_case(self.tmp, "b", per, m, rng.normal(0.0, 0.1, (per * m, bins)), exclude=0.03),
                           "channelProfile")
        self.assertEqual(run.fitted.sum(), 200)
        self.assertLess(abs(run.inefficiency - 1.0), 5 * math.sqrt(2 / 7) / math.sqrt(200))

    def test_only_the_latest_blocks(self):
        # Two extra sampling blocks before the window, wildly off: left out.
        rng = np.random.default_rng(42)
        per, m, bins = 2, 5, 20
        u = np.vstack([np.full((2, bins), 50.0), np.repeat(rng.normal(0.0, 0.1, (m, bins)), per, axis=0)])
        run = LongBlockRun("c", long_block_case(self.tmp, "c", per, m, u), "channelProfile")
        self.assertAlmostEqual(run.inefficiency, (m * per - 1) / (m - 1), places=10)

    def test_effective_dof_of_groups(self):
        # m = 8 super-blocks (N = 7): k = 4 groups of g = 3 bins, each group's deviations one column of the
        # Helmert contrasts (zero mean, mutually orthogonal), identical within the group.
        m, k, g = 8, 4, 3
        helmert = np.array([[1.0] * j + [-float(j)] + [0.0] * (m - j - 1) for j in range(1, m)]).T  # (m, m - 1)
        columns = np.repeat(helmert[:, :k], g, axis=1)
        bins = 2 + k * g  # the first and last bins lie outside the fit range
        u = np.zeros((m, bins))
        u[:, 1:-1] = 0.05 * columns
        run = LongBlockRun("d", long_block_case(self.tmp, "d", 1, m, u, exclude=0.5), "channelProfile")
        n, big_n = k * g, m - 1
        self.assertEqual(run.fitted.sum(), n)
        self.assertAlmostEqual(effective_dof([run], n), n * n / (n + k * g * (g - 1) * (1 - 1 / big_n)), places=10)

    def test_values_lines_and_density(self):
        rng = np.random.default_rng(43)
        run = LongBlockRun("fcc", long_block_case(self.tmp, "e", 2, 4, rng.normal(0.0, 0.1, (8, 20))), "channelProfile")
        values, errors = run.values()
        np.testing.assert_array_equal(values, [0.3, 0.1, 0.2])
        np.testing.assert_array_equal(errors, [0.01, 0.02, 0.03])
        bulk, near = run.near_wall_density(1.0)
        self.assertEqual(bulk, 3.0)
        self.assertEqual(near, [(2.5 / 3.0, 2.5 / 3.0), (2.5 / 3.0, 2.5 / 3.0)])
        lines = long_block_lines(run, 1.0)
        self.assertTrue(lines[0].startswith("fcc      nu 0.3000 +- 0.0100  slip +0.1000 +- 0.0200  +0.2000 +- 0.0300  "
                                            "(4 super-blocks of 20, bin-error inefficiency s = "))
        self.assertIn("mean 0.833 / 0.833", lines[1])

    def test_profile_chi2_and_agreement(self):
        rng = np.random.default_rng(44)
        u = rng.normal(0.0, 0.1, (8, 20))
        a = LongBlockRun("a", long_block_case(self.tmp, "a", 2, 4, u), "channelProfile")
        b = LongBlockRun("b", long_block_case(self.tmp, "b", 2, 4, u + 0.02, nu=0.32, nuError=0.02), "channelProfile")
        chi2, bins = profile_chi2(a, b)
        self.assertEqual(bins, 18)
        self.assertAlmostEqual(chi2, 0.02 ** 2 / (2 * (0.01 * math.sqrt(a.inefficiency)) ** 2), places=9)
        diff, sigma, dof = agreement(b, a, 0)
        self.assertAlmostEqual(diff, 0.02, places=14)
        expected = combined((0.02, 3), (0.01, 3))
        self.assertAlmostEqual(sigma, expected[0], places=14)
        self.assertAlmostEqual(dof, expected[2], places=12)

    def test_too_short(self):
        case = long_block_case(self.tmp, "f", 2, 4, np.zeros((8, 20)))
        write_fit(case, {"errors": "blocks", "superBlocksNote": "the run holds 1 super-block", "wallPosition": [-5.0, 5.0],
                         "exclude": 0.5, "nu": 0.3, "nuError": 0.01, "slipLength": [0.1, 0.2], "slipLengthError": [0.02, 0.03]})
        run = LongBlockRun("f", case, "channelProfile")
        self.assertIn("the run holds 1 super-block", run.too_short)
        self.assertEqual((run.super_blocks, run.inefficiency), (0, 1.0))
        np.testing.assert_array_equal(run.ux_error, 0.01)
        self.assertIn("(bin-error inefficiency s = 1.00)", long_block_lines(run, 1.0)[0])


if __name__ == "__main__":
    unittest.main()
