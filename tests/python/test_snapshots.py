"""dpdfoam.snapshots on solver snapshots written here (io/Snapshot.cpp's layout) with known chains.

Two snapshots hold the same particles whatever their row order (compared in id order), and not when a
position or a species differs. A chain written wrapped across the periodic box, its bonds listed out of
order and its ids not in row order, unwraps to the straight line it is: its span (L - 1) b, R_g^2 =
b^2 (L^2 - 1) / 12 (a rod of L beads), its end-to-end extent; its segments start at the first bead of
each bond; shifted whole box lengths, its centre lies in the box. Over a super-block window the
extension table's central and outer chains, their ratio, the per-super-block slope of span on the
distance from the centre (planted exactly) and the binned profile are recovered; the table is measured
from the snapshots of the function's window (the dictionary answered by a stand-in), written whole and
read back in preference to the snapshots.
"""
import io
import os
import contextlib
import unittest

import numpy as np

from dpdfoam.snapshots import (EXTENSION_COLUMNS, chain_segments, chain_shapes, chains_in_box, extension_by_offset,
                               extension_command, extension_rows, measure_extension, same_particles, snapshot_box,
                               unwrapped_chains, write_extension)
from dpdfoam.timeseries import SuperBlockWindow
from dpdtest_support import fake_dictionary, jackknife_fit, Temporary, write_fit, write_snapshot

BOX_LO, BOX_HI = (0.0, 0.0, 0.0), (10.0, 4.0, 6.0)


def chain_snapshot(path, time=0.0, shift=0.0):
    """Two fluid particles and two chains of polymer beads (species 1) in a 10 x 4 x 6 box:
    chain 7: 5 beads along x, spacing 0.9, from x = 8.5 (wrapped: 8.5 9.4 0.3 1.2 2.1), at z = 2 + shift;
    chain 3: 3 beads along z, spacing 0.5, from (5, 1, 1).
    Rows are in no particular order of id; the bonds are listed out of order."""
    rows = [  # (id, species, position)
        (40, 0, (1.0, 1.0, 1.0)), (12, 1, (0.3, 2.0, 2.0 + shift)), (11, 1, (9.4, 2.0, 2.0 + shift)),
        (30, 1, (5.0, 1.0, 1.5)), (14, 1, (2.1, 2.0, 2.0 + shift)), (10, 1, (8.5, 2.0, 2.0 + shift)),
        (29, 1, (5.0, 1.0, 1.0)), (13, 1, (1.2, 2.0, 2.0 + shift)), (31, 1, (5.0, 1.0, 2.0)), (41, 0, (3.0, 3.0, 3.0))]
    ids, species, position = zip(*rows)
    bonds = ([(12, 13), (29, 30), (10, 11), (30, 31), (13, 14), (11, 12)],
             [(0.9, 0, 0), (0, 0, 0.5), (0.9, 0, 0), (0, 0, 0.5), (0.9, 0, 0), (0.9, 0, 0)], [7, 3, 7, 3, 7, 7])
    return write_snapshot(path, position, ids=ids, species=species, species_names=("fluid", "polymer"), frozen=(0, 0),
                          lo=BOX_LO, hi=BOX_HI, time=time, bonds=bonds)


class Particles(Temporary):
    def test_box(self):
        lo, hi = snapshot_box(chain_snapshot(self.path("a.h5")))
        np.testing.assert_array_equal(lo, BOX_LO)
        np.testing.assert_array_equal(hi, BOX_HI)

    def test_same_particles(self):
        rng = np.random.default_rng(50)
        x = rng.uniform(0, 5, (20, 3))
        species = rng.integers(0, 2, 20)
        a = write_snapshot(self.path("a.h5"), x, species=species, species_names=("fluid", "wall"), frozen=(0, 1))
        order = rng.permutation(20)
        b = write_snapshot(self.path("b.h5"), x[order], species=species[order], ids=np.arange(20)[order],
                           species_names=("fluid", "wall"), frozen=(0, 1), velocity=rng.normal(size=(20, 3)))
        self.assertTrue(same_particles(a, b))
        moved = x.copy()
        moved[5, 2] += 1e-9
        c = write_snapshot(self.path("c.h5"), moved, species=species, species_names=("fluid", "wall"), frozen=(0, 1))
        self.assertFalse(same_particles(a, c))
        other = species.copy()
        other[3] = 1 - other[3]
        d = write_snapshot(self.path("d.h5"), x, species=other, species_names=("fluid", "wall"), frozen=(0, 1))
        self.assertFalse(same_particles(a, d))
        e = write_snapshot(self.path("e.h5"), x[:19], species=species[:19], species_names=("fluid", "wall"), frozen=(0, 1))
        self.assertFalse(same_particles(a, e))


class Chains(Temporary):
    def test_segments(self):
        s = chain_segments(chain_snapshot(self.path("c.h5"), time=12.5))
        self.assertEqual(s["time"], 12.5)
        self.assertEqual(len(s["beads"]), 8)
        self.assertEqual(len(s["starts"]), 6)
        # the bond (10, 11) starts at bead 10, (8.5, 2, 2); the bond (11, 12) at bead 11, (9.4, 2, 2), and ends
        # outside the box at 10.3 (drawn without the jump)
        np.testing.assert_allclose(s["starts"][2], [8.5, 2.0, 2.0])
        np.testing.assert_allclose(s["ends"][5], [10.3, 2.0, 2.0])
        np.testing.assert_array_equal(s["chain"], [7, 3, 7, 3, 7, 7])

    def test_no_bonds(self):
        path = write_snapshot(self.path("f.h5"), [(1, 1, 1)], species_names=("fluid",))
        s = chain_segments(path)
        self.assertEqual((s["beads"].shape, s["starts"].shape, s["ends"].shape), ((0, 3), (0, 3), (0, 3)))

    def test_unwrapped(self):
        chains = unwrapped_chains(chain_snapshot(self.path("c.h5")))
        self.assertEqual(sorted(chains), [3, 7])
        np.testing.assert_allclose(chains[7][:, 0], [8.5, 9.4, 10.3, 11.2, 12.1])
        np.testing.assert_allclose(chains[3], [[5, 1, 1], [5, 1, 1.5], [5, 1, 2]])

    def test_shapes(self):
        rows = chain_shapes(chain_snapshot(self.path("c.h5")), axis=2)
        self.assertEqual([r[0] for r in rows], [3, 7])
        chain, centre, span, rg2, reex2 = rows[1]
        self.assertAlmostEqual(centre, 2.0, places=12)
        self.assertAlmostEqual(span, 4 * 0.9, places=12)
        self.assertAlmostEqual(rg2, 0.81 * (25 - 1) / 12, places=12)
        self.assertAlmostEqual(reex2, (4 * 0.9) ** 2, places=12)
        _, centre, span, rg2, reex2 = rows[0]
        self.assertAlmostEqual(centre, 1.5, places=12)
        self.assertAlmostEqual(span, 0.0, places=12)
        self.assertAlmostEqual(rg2, 0.25 * (9 - 1) / 12, places=12)
        self.assertAlmostEqual(reex2, 0.0, places=12)

    def test_chains_in_box(self):
        lo, hi, chains = chains_in_box(chain_snapshot(self.path("c.h5")))
        self.assertEqual(len(chains), 2)
        np.testing.assert_allclose(chains[1][:, 0], [-1.5, -0.6, 0.3, 1.2, 2.1])  # centre 10.3 - 10 = 0.3
        np.testing.assert_allclose(chains[0][:, 0], [5.0, 5.0, 5.0])


def extension_table(times, centre, offsets, slope_by_block, window):
    """Rows (time chain centre spanx Rg2 Reex2): per time, one chain per offset, span 1 + slope |offset|
    (the slope of the time's super-block), Rg2 = 2 + |offset|."""
    rows = []
    for t in times:
        k = window.index([t])[0]
        slope = slope_by_block[k] if k >= 0 else 99.0
        for c, off in enumerate(offsets):
            rows.append((t, c, centre + off, 1.0 + slope * abs(off), 2.0 + abs(off), 0.0))
    return np.array(rows)


class Extension(Temporary):
    def window(self, case):
        write_fit(case, jackknife_fit(3, 2, 100.0))
        return SuperBlockWindow(case, 400.0)  # [100, 400)

    def test_by_offset(self):
        case = self.path("case")
        window = self.window(case)
        offsets = [-4.5, -3.0, -0.5, 0.0, 0.5, 3.5, 4.5]
        times = np.arange(50.0, 401.0, 25.0)  # 50 and 75 lie before the window
        rows = extension_table(times, 1.0, offsets, [0.2, 0.3, 0.4], window)
        out = extension_by_offset(rows, window, 1.0, 1.0, 3.25, np.array([-4.0, -2.0, 0.0, 2.0, 4.0, 6.0]))
        self.assertEqual(out["snapshots"], 13)  # 100 .. 400, the end in the last super-block
        self.assertAlmostEqual(out["central"]["chains"], 3.0, places=12)
        self.assertAlmostEqual(out["outer"]["chains"], 3.0, places=12)  # 4.5, 3.5 and 4.5 beyond 3.25
        slope = out["slope"]
        np.testing.assert_allclose(slope.blocks, [0.2, 0.3, 0.4])
        central = out["central"]["spanx"]
        np.testing.assert_allclose(central.blocks, 1.0 + np.array([0.2, 0.3, 0.4]) * (1.0 / 3.0))
        outer = out["outer"]["spanx"]
        np.testing.assert_allclose(outer.blocks, 1.0 + np.array([0.2, 0.3, 0.4]) * (12.5 / 3.0))
        self.assertAlmostEqual(out["ratio"], outer.value / central.value, places=14)
        np.testing.assert_allclose(out["outer"]["Rg2"].blocks, 2.0 + 12.5 / 3.0)
        z, span, err = out["bins"]["z"], out["bins"]["spanx"], out["bins"]["err"]
        np.testing.assert_array_equal(z, [-3.0, -1.0, 1.0, 3.0, 5.0])
        # the bin [-4, -2) holds the chain at 1 - 4.5 = -3.5 only: span 1 + slope 4.5, mean over the blocks
        self.assertAlmostEqual(span[0], 1.0 + 0.3 * 4.5, places=12)
        self.assertAlmostEqual(err[0], 0.1 * 4.5 / np.sqrt(3.0), places=12)

    def test_measured_from_snapshots(self):
        case = self.path("case")
        control = os.path.join(case, "system", "controlDict")
        for t, shift in ((0, 0.0), (100, 0.5), (200, 1.0), (300, 1.5)):
            chain_snapshot(os.path.join(case, str(t), "particles.h5"), time=t, shift=shift)
        entries = {(control, "functions/channelProfile/axis"): "z", (control, "functions/channelProfile/startTime"): "100",
                   (control, "endTime"): "250"}
        with fake_dictionary(self.tmp, entries):
            rows, table = measure_extension(case, "channelProfile")
            self.assertEqual(table, os.path.join(case, "postProcessing/chainExtension", "100", "chainExtension.dat"))
            self.assertEqual(rows.shape, (4, 6))  # two chains at 100 and 200 (300 after the end, 0 before the start)
            np.testing.assert_array_equal(rows[:, 0], [100, 100, 200, 200])
            np.testing.assert_array_equal(rows[:, 1], [3, 7, 3, 7])
            np.testing.assert_allclose(rows[:, 2], [1.5, 2.5, 1.5, 3.0])
            np.testing.assert_allclose(rows[1, 3:5], [3.6, 0.81 * 2])
            self.assertEqual(extension_rows(case).shape, (4, 6))  # no table yet: measured
            message = write_extension(case, "channelProfile")
            self.assertIn("2 snapshots, 2 chains", message)
            with open(table) as f:
                self.assertEqual(f.readline().strip(), "# " + EXTENSION_COLUMNS)
            out = io.StringIO()
            with contextlib.redirect_stdout(out):
                self.assertEqual(extension_command("chainExtension", ["-case", case]), 0)
            self.assertIn("written", out.getvalue())
            for t in (100, 200):
                os.remove(os.path.join(case, str(t), "particles.h5"))
            np.testing.assert_allclose(extension_rows(case), rows, rtol=1e-5)  # the table, the snapshots gone

    def no_chain_case(self):
        case = self.path("case")
        control = os.path.join(case, "system", "controlDict")
        entries = {(control, "functions/channelProfile/axis"): "z", (control, "functions/channelProfile/startTime"): "0",
                   (control, "endTime"): "10"}
        return case, entries

    def test_neither_table_nor_snapshots(self):
        case, entries = self.no_chain_case()
        with fake_dictionary(self.tmp, entries):
            self.assertIsNone(extension_rows(case))

    def test_snapshots_without_chains_exit(self):
        # A snapshot without bonds has no bonds/ datasets (io/SnapshotBonds.cpp writes them only for
        # bonds): it holds no chains, and write_extension exits "no chains in the snapshots".
        case, entries = self.no_chain_case()
        write_snapshot(os.path.join(case, "5", "particles.h5"), [(1, 1, 1)], time=5.0)
        with fake_dictionary(self.tmp, entries):
            with self.assertRaises(SystemExit):
                write_extension(case, "channelProfile")


if __name__ == "__main__":
    unittest.main()
