"""dpdfoam.fields on x-z grids and a continuum twin written out by hand.

A profile table becomes 2-D arrays with rows z and columns x; imshow's extent is the outer bins'
edges. Cell centres gather into the bin holding them (mean value, number of cells; NaN for none); an
OpenFOAM case's latest U and C fields give the same, and TwinBins marks as wholly fluid exactly the
bins with every cell of the mesh, compares the bins of the mask where the twin has cells, and shows
those with enough particle-samples. The relative L2 of u = (1 + e) u_ref is |e| and its noise floor
that of the standard errors; classes with fewer than three bins are skipped; the flow's kinetic part of
kT is the count-weighted variance of the bins' velocities per degree of freedom (u^2 / 3 for two equal
bins at +-u). The log's kT series is summarised from its start (mean and standard error of the
reports) with its largest deviation from 1. The results lines carry the numbers given.
"""
import math
import os
import tempfile
import unittest

import numpy as np

from dpdfoam.fields import (CLASS_COLUMNS, FlowTemperature, TwinBins, bin_temperatures, cells_on_bins, class_lines,
                            class_table, compare_summary, extent, foam_on_bins, read_grid, relative_l2)
from dpdtest_support import write_table, write_text


def grid_table(xs, zs, **columns):
    """A profileBins x-z table (x fastest) with the given per-bin columns ((len(zs), len(xs)) arrays)."""
    x, z = np.meshgrid(xs, zs)
    out = {"x": x.ravel(), "z": z.ravel()}
    out.update({k: np.asarray(v, dtype=float).ravel() for k, v in columns.items()})
    return out


def write_vector_field(path, vectors):
    body = "\n".join(f"({a!r} {b!r} {c!r})" for a, b, c in vectors)
    write_text(path, "FoamFile\n{\n    class volVectorField;\n}\n"
                     f"internalField   nonuniform List<vector> \n{len(vectors)}\n(\n{body}\n)\n;\nboundaryField\n{{\n}}\n")


class Grids(unittest.TestCase):
    def test_read_grid(self):
        xs, zs = np.array([0.5, 1.5, 2.5]), np.array([-1.0, 1.0])
        ux = np.array([[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]])
        with tempfile.TemporaryDirectory() as tmp:
            path = write_table(os.path.join(tmp, "flowField.dat"), grid_table(xs, zs, ux=ux))
            gx, gz, grid = read_grid(path)
        np.testing.assert_array_equal(gx, xs)
        np.testing.assert_array_equal(gz, zs)
        np.testing.assert_array_equal(grid["ux"], ux)
        self.assertEqual(extent(gx, gz), [0.0, 3.0, -2.0, 2.0])

    def test_cells_on_bins(self):
        xs, zs = np.array([0.5, 1.5]), np.array([0.5, 1.5, 2.5])
        points = np.array([[0.1, 0, 0.2], [0.9, 0, 0.8], [1.2, 0, 2.9], [1.99, 0, 2.01]])
        means, n = cells_on_bins(points, np.array([1.0, 3.0, 10.0, 20.0]), xs, zs)
        np.testing.assert_array_equal(n, [[2, 0], [0, 0], [0, 2]])
        self.assertEqual(means[0, 0], 2.0)
        self.assertEqual(means[2, 1], 15.0)
        self.assertTrue(np.isnan(means[1]).all() and np.isnan(means[0, 1]))

    def test_cells_outside_the_bins_left_out(self):
        # A cell centre outside the bins (here left of the first) is left out, as the solver's bins leave
        # out a particle outside them (BinLayout::binOf: -1), not averaged into the opposite edge's bin.
        xs, zs = np.array([0.5, 1.5]), np.array([0.5, 1.5])
        points = np.array([[-0.5, 0, 0.5], [1.5, 0, 0.5]])  # the first lies left of the bins
        means, n = cells_on_bins(points, np.array([100.0, 1.0]), xs, zs)
        np.testing.assert_array_equal(n, [[0, 1], [0, 0]])
        self.assertEqual(means[0, 1], 1.0)

    def test_cells_beyond_the_high_side_left_out(self):
        xs, zs = np.array([0.5, 1.5]), np.array([0.5, 1.5])
        points = np.array([[2.5, 0, 0.5], [0.5, 0, 2.5], [0.5, 0, -0.5], [0.5, 0, 1.5]])  # the first three outside
        means, n = cells_on_bins(points, np.array([100.0, 100.0, 100.0, 2.0]), xs, zs)
        np.testing.assert_array_equal(n, [[0, 0], [1, 0]])
        self.assertEqual(means[1, 0], 2.0)


class Twin(unittest.TestCase):
    """3 x 2 bins of width 1; the twin's mesh has 4 cells per bin (quarter points), 2 in the bin (z 0.5,
    x 2.5) (half of it solid) and none in (z 1.5, x 0.5); its ux is the cell's x, uz 0.1."""

    def setUp(self):
        self._tmp = tempfile.TemporaryDirectory()
        self.case = os.path.join(self._tmp.name, "simpleFoam")
        self.xs, self.zs = np.array([0.5, 1.5, 2.5]), np.array([0.5, 1.5])
        centres = []
        for bz in self.zs:
            for bx in self.xs:
                if (bz, bx) == (1.5, 0.5):
                    continue
                quarter = [(-0.25, -0.25), (0.25, -0.25), (-0.25, 0.25), (0.25, 0.25)]
                if (bz, bx) == (0.5, 2.5):
                    quarter = quarter[:2]
                centres += [(bx + dx, 0.0, bz + dz) for dx, dz in quarter]
        for t in ("0", "100", "250"):
            os.makedirs(os.path.join(self.case, t))
        write_vector_field(os.path.join(self.case, "250", "C"), centres)
        write_vector_field(os.path.join(self.case, "250", "U"), [(c[0], 0.0, 0.1) for c in centres])
        write_vector_field(os.path.join(self.case, "100", "U"), [(9.0, 9.0, 9.0)] * len(centres))
        count = np.array([[100.0, 100.0, 50.0], [100.0, 10.0, 100.0]])
        ux = np.array([[0.6, 1.4, 2.5], [0.5, 1.5, 2.6]])
        self.grid = {"count": count, "ux": ux, "uz": np.full((2, 3), 0.1), "uxErr": np.full((2, 3), 0.05),
                     "density": count / 30.0}
        self.centres = centres

    def tearDown(self):
        self._tmp.cleanup()

    def test_foam_on_bins(self):
        ux, uz, n = foam_on_bins(self.case, self.xs, self.zs)
        np.testing.assert_array_equal(n, [[4, 4, 2], [0, 4, 4]])
        np.testing.assert_allclose(ux[0], [0.5, 1.5, 2.5])
        np.testing.assert_allclose(ux[1, 1:], [1.5, 2.5])
        self.assertTrue(np.isnan(ux[1, 0]))
        np.testing.assert_allclose(uz[0], 0.1)

    def test_twin_bins(self):
        fluid = np.ones((2, 3), dtype=bool)
        twin = TwinBins(self.xs, self.zs, self.grid, fluid, case=self.case)
        np.testing.assert_array_equal(twin.wholly_fluid, [[True, True, False], [False, True, True]])
        np.testing.assert_array_equal(twin.compared, [[True, True, True], [False, True, True]])
        np.testing.assert_array_equal(twin.interior, [[True, True, False], [False, True, True]])
        # median of the counts 100: shown from 25 on
        np.testing.assert_array_equal(twin.shown, [[True, True, True], [True, False, True]])
        diff = twin.difference()
        np.testing.assert_allclose(diff[0], [0.1, -0.1, 0.0], atol=1e-14)
        self.assertTrue(np.isnan(diff[1, 0]) and np.isnan(diff[1, 1]))
        self.assertAlmostEqual(diff[1, 2], 0.1, places=14)
        self.assertTrue(np.isnan(twin.dpd_speed()[1, 1]))
        self.assertAlmostEqual(twin.dpd_speed()[0, 0], math.hypot(0.6, 0.1), places=14)
        self.assertAlmostEqual(twin.twin_speed()[0, 1], math.hypot(1.5, 0.1), places=14)
        l2, noise = twin.interior_l2()
        ref = np.array([0.5, 1.5, 1.5, 2.5])
        self.assertAlmostEqual(l2, math.sqrt((0.01 + 0.01 + 0.0 + 0.01) / np.sum(ref ** 2)), places=14)
        self.assertAlmostEqual(noise, 0.05 * math.sqrt(4 / np.sum(ref ** 2)), places=14)
        means = twin.region_means(twin.interior)
        self.assertEqual(means["bins"], 4)
        self.assertAlmostEqual(means["dpd"], (0.6 + 1.4 + 1.5 + 2.6) / 4, places=14)
        self.assertAlmostEqual(means["fvm"], 6.0 / 4, places=14)
        self.assertAlmostEqual(means["se"], 0.05 / 2, places=14)


class Comparisons(unittest.TestCase):
    def test_relative_l2(self):
        ref = np.array([1.0, -2.0, 3.0, 0.5])
        l2, noise = relative_l2(1.03 * ref, ref, np.full(4, 0.1))
        self.assertAlmostEqual(l2, 0.03, places=14)
        self.assertAlmostEqual(noise, 0.1 * 2 / math.sqrt(np.sum(ref ** 2)), places=14)
        l2, _ = relative_l2(np.array([1.0, np.nan]), np.array([1.0, 1.0]), np.zeros(2))
        self.assertTrue(np.isnan(l2))

    def test_class_table(self):
        key = np.array([0.5, 0.6, 0.7, 1.5, 1.6, 2.5, 2.6, 2.7, 2.8])
        uf = np.array([1.0, 2.0, 3.0, 1.0, 1.0, 2.0, 2.0, 2.0, np.nan])
        ud = 1.1 * uf
        err = np.full(9, 0.01)
        rho = np.arange(9.0)
        whole = np.array([True, False, True, True, True, False, False, False, True])
        rows = class_table(key, np.array([0.0, 1.0, 2.0, 3.0]), ud, uf, err, rho, whole)
        self.assertEqual([r[:3] for r in rows], [(0.0, 1.0, 3), (2.0, 3.0, 3)])  # 1-2 has 2 bins; the NaN is left out
        lo, hi, n, l2, noise, ratio, mean_fvm, density = rows[0]
        self.assertAlmostEqual(l2, 0.1, places=13)
        self.assertAlmostEqual(noise, 0.01 * math.sqrt(3 / 14), places=14)
        self.assertAlmostEqual(ratio, 1.1, places=14)
        self.assertAlmostEqual(mean_fvm, 2.0, places=14)
        self.assertEqual(density, 1.0)  # bins 0 and 2 wholly fluid: rho 0, 2
        self.assertTrue(math.isnan(rows[1][7]))  # none wholly fluid
        lines = class_lines("poreSize", rows)
        self.assertEqual(lines[0], "poreSize 0 1 3 0.1000 0.0046 1.1000 2.00000 1.000")
        self.assertEqual(len(lines[1].split()), len(CLASS_COLUMNS.split()) + 1)

    def test_compare_summary(self):
        cmp = {"meanVelocityRatio": 0.97, "meanVelocityDPD": 0.097, "meanVelocityFVM": 0.1, "superficialVelocityDPD": 0.05,
               "superficialVelocityDPDErr": 0.001, "superficialVelocityFVM": 0.052, "permeabilityDPD": 1.5,
               "permeabilityDPDErr": 0.03, "permeabilityFVM": 1.6, "permeabilityRatio": 0.9375}
        lines = {"centre": {"L2": 0.012, "noiseL2": 0.004, "Linf": 0.05, "meanVelocityRatio": 0.99}}
        out = compare_summary(cmp, lines)
        self.assertEqual(out[0], "L2centre           0.01200  (noise 0.00400; Linf 0.0500; mean ratio 0.9900)")
        self.assertIn("meanVelocityRatio  0.97000  (DPD 0.09700, simpleFoam 0.10000)", out)
        self.assertTrue(out[-1].endswith("permeabilityRatio  0.93750"))


class Temperatures(unittest.TestCase):
    def test_bin_temperatures(self):
        grid = {"count": np.array([10.0, 10.0, 0.0]), "kT": np.array([1.0, 1.2, 0.0]), "ux": np.array([0.3, -0.3, 0.0]),
                "uy": np.zeros(3), "uz": np.array([0.1, 0.1, 0.0])}
        kT_bins, flow = bin_temperatures(grid, np.array([True, True, False]))
        self.assertAlmostEqual(kT_bins, 1.1, places=14)
        self.assertAlmostEqual(flow, 0.3 ** 2 / 3, places=14)

    def test_flow_temperature(self):
        grid = {"count": np.array([1.0, 1.0]), "kT": np.array([1.0, 1.0]), "ux": np.zeros(2), "uy": np.zeros(2),
                "uz": np.zeros(2)}
        times = np.array([10.0, 20.0, 30.0, 40.0, 50.0])
        kts = np.array([1.2, 0.99, 1.01, 1.0, 1.02])
        ft = FlowTemperature(grid, np.array([True, True]), times, kts, 30.0)
        self.assertAlmostEqual(ft.mean, 1.01, places=14)
        self.assertAlmostEqual(ft.error, 0.01 / math.sqrt(3), places=14)
        self.assertEqual(ft.worst, 0)
        lines = ft.lines()
        self.assertEqual(lines[0], "kTSeries           (10:1.2000 20:0.9900 30:1.0100 40:1.0000 50:1.0200)")
        self.assertTrue(lines[1].startswith("kTLog              1.01000 +- 0.00577"))
        self.assertTrue(lines[4].startswith("kTMaxDeviation     +0.20000"))
        self.assertIn("at t = 10)", lines[4])

    def test_flow_temperature_one_report(self):
        grid = {"count": np.ones(1), "kT": np.ones(1), "ux": np.zeros(1), "uy": np.zeros(1), "uz": np.zeros(1)}
        ft = FlowTemperature(grid, np.array([True]), np.array([1.0, 2.0]), np.array([1.0, 1.1]), 2.0)
        self.assertTrue(math.isnan(ft.error))  # a single report after the start: no error to pass a check


if __name__ == "__main__":
    unittest.main()
