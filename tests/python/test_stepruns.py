"""dpdfoam.stepruns on a study's runs built here: logs, fits and sampled blocks of known values.

A run's cost is its CPU seconds (user + system of log.cpuTime, or the log's wall time times its threads
without one) over its mobile particles times its steps: the walled study's latticeWall run at dt 0.01
(13.348 + 0.128 s, 1196 mobile particles, 30000 steps) costs 3.7559e-7 s per particle-step, as its
table says (3.76e-07). A run the monitor stopped has no cost and no measures. kT within a cutoff of
the walls comes from bins whose sums give their kT exactly (particle-samples at rest on average, spread
evenly over the bin, no velocity-position correlation): near the lower wall kT 1 + 0.01 k in the
window's block k = 0..19 (100 samples a bin), near the upper 2 (300 samples a bin), far from the walls
5 (left out); of 21 blocks in ten groups the latest 20 count (the first, at kT 50, not), so the window's
kT is (200 x 1.095 + 1200) / 800 = 1.77375 and its error the groups' spread (group j: 0.25 (1 + 0.01 (2j
+ 0.5)) + 1.5), 0.25 x 0.02 x sqrt(55/6) / sqrt(10). b is the mean of the
two walls' slip lengths, its error the mean of their errors. Against the smallest stable step: nu and
kT relative (v / r - 1, error hypot(e / r, v e_r / r^2)), b in length units (error in quadrature), the
b tolerance max(0.05 x cutoff, 3 combined errors); the largest step that keeps them is the last of the
unbroken run of steps that do, whatever a larger step does; its speed-up over the smallest step, with
the cost model (a time unit costs the median step cost over dt), is the ratio of the steps.
"""
import math
import os
import tempfile
import unittest

import numpy as np

from dpdfoam.stepruns import (Study, Tolerances, against_smallest, draw_study, largest_keeping, largest_lines,
                              near_wall_temperature, read_runs, read_study, run_row, scene_rows, solver_run, verdict,
                              write_whole)
from dpdfoam.stepstudy import apply_cost_model
from dpdtest_support import fake_dictionary, write_fit, write_sampling, write_text

NAN = float("nan")
TOL = Tolerances(0.02, 0.05, 3, 0.01)
LOG_HEAD = ("Threads        : {threads} of {threads}\n"
            "Particles      : 1556 (1196 mobile, 360 frozen)\n"
            "Pair force     : dissipative + random + conservative\n"
            "Walls          :\n"
            "    lower: reflection bounceBack, velocity (0 0 0), 180 frozen particles moving with it\n"
            "    upper: reflection bounceBack, velocity (0 0 0), 180 frozen particles moving with it\n"
            "Body force     : (0.08 0 0)\n"
            "    walls since last report: lower returned 4460 crossed 3; upper returned 4413 crossed 2; left inside 0\n"
            "    walls since last report: lower returned 4414 crossed 0; upper returned 4448 crossed 1; left inside 0\n")
FINISHED = "Run finished: 30000 steps in 31.18 s, 1.151e+06 particle-steps/s\n"
STOPPED = ("dpdFoamLike: the run went unstable at time 246 (step 8200): non-finite positions, velocities or forces "
           "(NaN or infinity). The last good state, time 243, is written to ./243\n")
CPU = "dpdFoamLike cpuSeconds 13.348 0.128 wallSeconds 31.702\n"

# The sampled profile: walls at -5 and 5, 20 bins of 0.5; a cutoff of 1 holds the bins centred at -4.75,
# -4.25 (lower) and 4.25, 4.75 (upper).
LO, HI, BINS = -5.0, 5.0, 20
WIDTH = (HI - LO) / BINS
BLOCKS = 21


def bin_sums_of(n, kT, zc):
    """A bin's 12 sums (sampling/BinProfile.cpp's order) for n samples of mean velocity 0 and kT per
    component, spread evenly over the bin: temperature() reads kT."""
    return [n, 0.0, 0.0, 0.0, n * kT, n * kT, n * kT, n * zc, n * (zc ** 2 + WIDTH ** 2 / 12), 0.0, 0.0, 0.0]


def sampled_blocks():
    z = LO + WIDTH * (np.arange(BINS) + 0.5)
    blocks = []
    for k in range(BLOCKS):
        # Block 0 is before the window (the latest 20 of 21 make ten groups of 2): its kT 50 must not count.
        lower = 50.0 if k == 0 else 1.0 + 0.01 * (k - 1)
        blocks.append([bin_sums_of(100, lower, zc) if zc < -4 else bin_sums_of(300, 2.0, zc) if zc > 4 else
                       bin_sums_of(100, 5.0, zc) for zc in z])
    return np.array(blocks)


def window_kT():
    """The latest 20 blocks' kT near the walls and its error over ten groups, by hand (see the docstring)."""
    value = (200 * (1.0 + 0.01 * 9.5) + 1200) / 800
    error = 0.25 * 0.02 * math.sqrt(55 / 6) / math.sqrt(10)
    return value, error


def make_run(case, entries, dt, end=300.0, stopped=False, cpu=True, threads=1, nu=0.27, b=(0.03, 0.04),
             be=(0.02, 0.01), kT_blocks=True):
    """A copy as the Allrun leaves it: controlDict entries (for the stand-in dpdDictionary), the solver's
    log, log.cpuTime, fit.dat and the profile's sampled blocks (not for a stopped run)."""
    entries[(os.path.join(case, "system/controlDict"), "deltaT")] = repr(dt)
    entries[(os.path.join(case, "system/controlDict"), "endTime")] = repr(end)
    write_text(os.path.join(case, "system", "controlDict"), "// the stand-in dpdDictionary answers\n")
    write_text(os.path.join(case, "log.dpdFoamLike"), LOG_HEAD.format(threads=threads) + (STOPPED if stopped else FINISHED))
    if cpu:
        write_text(os.path.join(case, "log.cpuTime"), CPU)
    if stopped:
        return
    write_fit(case, {"errors": "blocks", "nu": nu, "nuError": 0.002, "wallPosition": [LO, HI], "slipLength": list(b),
                     "slipLengthError": list(be)}, time="300")
    if kT_blocks:
        write_sampling(os.path.join(case, "300", "sampling", "channelProfile.h5"), sampled_blocks(), [10] * BLOCKS, LO, HI,
                       10, 30.0)


def row(dt, nu=0.27, nuse=0.002, b=0.03, bse=0.015, kT=1.03, kTse=0.002, unstable=False, cost=1e-5):
    """A row as run_row gives it, of these values."""
    return {"dt": dt, "unstable": unstable, "nuValue": nu, "nuValueSe": nuse, "bValue": b, "bValueSe": bse,
            "kTwallValue": kT, "kTwallValueSe": kTse, "cost": cost, "cutoff": 1.0}


class SolverRun(unittest.TestCase):
    def test_finished_with_cpu_time(self):
        with tempfile.TemporaryDirectory() as tmp:
            make_run(tmp, {}, 0.01)
            out = solver_run(tmp)
        self.assertFalse(out["unstable"])
        self.assertTrue(math.isnan(out["stoppedAt"]))
        self.assertEqual((out["steps"], out["particles"], out["mobile"], out["frozen"], out["threads"]), (30000, 1556, 1196, 360, 1))
        self.assertEqual(out["crossed"], 3 + 2 + 0 + 1)
        self.assertAlmostEqual(out["cpuSeconds"], 13.348 + 0.128, places=12)
        self.assertEqual(out["wallSeconds"], 31.18)

    def test_without_cpu_time_the_wall_time_times_threads(self):
        with tempfile.TemporaryDirectory() as tmp:
            make_run(tmp, {}, 0.01, cpu=False, threads=4)
            out = solver_run(tmp)
        self.assertEqual(out["threads"], 4)
        self.assertAlmostEqual(out["cpuSeconds"], 4 * 31.18, places=12)

    def test_stopped(self):
        with tempfile.TemporaryDirectory() as tmp:
            make_run(tmp, {}, 0.03, stopped=True)
            out = solver_run(tmp)
            self.assertTrue(out["unstable"])
            self.assertEqual((out["stoppedAt"], out["steps"]), (246.0, 8200))
            self.assertTrue(math.isnan(out["wallSeconds"]))
            os.remove(os.path.join(tmp, "log.cpuTime"))
            self.assertTrue(math.isnan(solver_run(tmp)["cpuSeconds"]))  # no wall time to stand in


class NearWallTemperature(unittest.TestCase):
    def test_by_hand(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = write_sampling(os.path.join(tmp, "p.h5"), sampled_blocks(), [10] * BLOCKS, LO, HI, 10, 30.0)
            kT = near_wall_temperature(path, (LO, HI), 1.0)
            value, error = window_kT()
            self.assertAlmostEqual(kT.value, value, places=12)
            self.assertAlmostEqual(kT.error, error, places=12)
            self.assertEqual(kT.m, 10)
            # The walls moved in by 1: the bins within a cutoff of them are the next pairs, all at kT 5.
            self.assertAlmostEqual(near_wall_temperature(path, (LO + 1, HI - 1), 1.0).value, 5.0, places=12)
            # No bin within the cutoff, or a single block: no measure.
            self.assertTrue(math.isnan(near_wall_temperature(path, (LO, HI), 0.2).value))
            one = write_sampling(os.path.join(tmp, "one.h5"), sampled_blocks()[:1], [10], LO, HI, 10, 30.0)
            self.assertTrue(math.isnan(near_wall_temperature(one, (LO, HI), 1.0).value))


class RunRow(unittest.TestCase):
    def test_finished_run(self):
        with tempfile.TemporaryDirectory() as tmp:
            entries = {}
            make_run(tmp, entries, 0.01)
            with fake_dictionary(tmp, entries):  # no cutoff in dpdProperties: 1
                r = run_row(tmp)
        self.assertEqual((r["dt"], r["endTime"], r["cutoff"], r["errors"]), (0.01, 300.0, 1.0, "blocks"))
        self.assertEqual((r["nuValue"], r["nuValueSe"]), (0.27, 0.002))
        self.assertEqual((r["bWalls"], r["bWallsSe"], r["walls"]), ((0.03, 0.04), (0.02, 0.01), (LO, HI)))
        self.assertAlmostEqual(r["bValue"], 0.035, places=15)
        self.assertAlmostEqual(r["bValueSe"], 0.015, places=15)
        value, error = window_kT()
        self.assertAlmostEqual(r["kTwallValue"], value, places=12)
        self.assertAlmostEqual(r["kTwallValueSe"], error, places=12)
        # The cost per particle-step: CPU seconds over mobile particles x steps; per time unit over dt.
        self.assertAlmostEqual(r["stepCost"], 13.476 / (1196 * 30000), delta=1e-20)
        self.assertEqual(f"{r['stepCost']:.3g}", "3.76e-07")
        self.assertAlmostEqual(r["cost"], r["stepCost"] / 0.01, delta=1e-18)

    def test_stopped_run(self):
        with tempfile.TemporaryDirectory() as tmp:
            entries = {}
            make_run(tmp, entries, 0.05, stopped=True)
            with fake_dictionary(tmp, entries):
                r = run_row(tmp)
        self.assertTrue(r["unstable"])
        for key in ("stepCost", "cost", "nuValue", "bValue", "kTwallValueSe"):
            self.assertTrue(math.isnan(r[key]), key)

    def test_without_sampled_blocks_no_kT(self):
        with tempfile.TemporaryDirectory() as tmp:
            entries = {}
            make_run(tmp, entries, 0.01, kT_blocks=False)
            with fake_dictionary(tmp, entries):
                r = run_row(tmp)
        self.assertEqual(r["nuValue"], 0.27)
        self.assertTrue(math.isnan(r["kTwallValue"]))


class Study_(unittest.TestCase):
    def test_read_study(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = write_text(os.path.join(tmp, "system", "walledStepDict"), "// the stand-in answers\n")
            integrators = ("{\n    GrootWarren0.65\n    {\n        type            GrootWarren;\n        lambda          0.65;\n"
                           "    }\n\n    DPDVV\n    {\n        type            DPDVV;\n    }\n}")
            entries = {(path, "scenes"): "(latticeWall tunableSlip)", (path, "deltaT"): "(0.01 0.03 0.05)",
                       (path, "integrators"): integrators, (path, "nuTolerance"): "0.02", (path, "bTolerance"): "0.05",
                       (path, "bErrors"): "3", (path, "kTTolerance"): "0.01"}
            with fake_dictionary(tmp, entries):
                study = read_study(path)
        self.assertEqual(study, Study(["latticeWall", "tunableSlip"], ["GrootWarren0.65", "DPDVV"], [0.01, 0.03, 0.05], TOL))

    def test_scene_rows_and_read_runs(self):
        # Copies of two integrators at three steps (made out of order); a file and another scene's copy
        # beside them are no copies of the scene; the cost model's median over the stable runs.
        with tempfile.TemporaryDirectory() as tmp:
            runs, entries = os.path.join(tmp, "runs"), {}
            for label, dts in (("GW", (0.03, 0.01, 0.05)), ("VV", (0.01,))):
                for dt in dts:
                    make_run(os.path.join(runs, f"wall-{label}-dt{dt}"), entries, dt, stopped=dt == 0.05)
            make_run(os.path.join(runs, "wallB-GW-dt0.01"), entries, 0.01)
            write_text(os.path.join(runs, "wall-GW-dt0.02"), "a file\n")
            with fake_dictionary(tmp, entries):
                rows = scene_rows(runs, "wall", ["GW", "VV", "none"])
                read, costs = read_runs(runs, ["wall", "missing"], ["GW", "VV"], TOL)
        self.assertEqual(list(rows), ["GW", "VV"])
        self.assertEqual([r["dt"] for r in rows["GW"]], [0.01, 0.03, 0.05])
        self.assertEqual([r["unstable"] for r in rows["GW"]], [False, False, True])
        self.assertEqual(list(read), ["wall"])
        step = 13.476 / (1196 * 30000)
        self.assertAlmostEqual(costs["wall"]["GW"][0], step, delta=1e-20)
        gw = read["wall"]["GW"]
        self.assertAlmostEqual(gw[1]["cost"], step / 0.03, delta=1e-18)
        self.assertTrue(gw[0]["reference"] and not gw[1]["reference"])
        self.assertEqual(gw[1]["nu"], 0.0)  # the same fit at both steps: no difference
        self.assertTrue(gw[1]["keeps"])
        self.assertFalse(gw[2]["keeps"])


class AgainstSmallest(unittest.TestCase):
    def test_differences_by_hand(self):
        points = [row(0.01, nu=0.25, nuse=0.0025, b=0.03, bse=0.012, kT=1.0, kTse=0.002),
                  row(0.02, nu=0.26, nuse=0.0026, b=0.05, bse=0.016, kT=1.005, kTse=0.001),
                  row(0.03, nu=0.2449, b=0.10, bse=0.01, kT=1.02)]
        ref = against_smallest(points, TOL)
        self.assertIs(ref, points[0])
        p = points[1]
        self.assertAlmostEqual(p["nu"], 0.04, places=14)
        self.assertAlmostEqual(p["nuse"], math.hypot(0.0026 / 0.25, 0.26 * 0.0025 / 0.25 ** 2), places=14)
        self.assertAlmostEqual(p["b"], 0.02, places=14)
        self.assertAlmostEqual(p["bse"], 0.02, places=14)  # hypot(0.016, 0.012)
        self.assertAlmostEqual(p["kTwall"], 0.005, places=14)
        self.assertAlmostEqual(p["bTol"], 0.06, places=14)  # 3 x 0.02 > 0.05
        self.assertEqual(p["limits"], ["nu"])  # 4 % against 2 %
        q = points[2]
        self.assertAlmostEqual(q["nu"], -0.0204, places=14)
        self.assertAlmostEqual(q["bTol"], 0.05, places=14)  # 3 x hypot(0.01, 0.012) = 0.047 < 0.05
        self.assertEqual(q["limits"], ["nu", "b", "kTwall"])
        self.assertEqual((points[0]["nu"], points[0]["nuse"], points[0]["keeps"]), (0.0, 0.0, True))
        self.assertEqual([verdict(x) for x in points], ["ref", "no: nu", "no: nu,b,kTwall"])

    def test_reference_is_the_smallest_stable_measured_step(self):
        points = [row(0.01, unstable=True), row(0.02, kT=NAN), row(0.03), row(0.04, nu=0.2727)]
        self.assertIs(against_smallest(points, TOL), points[2])
        self.assertTrue(math.isnan(points[1]["nu"]) and not points[1]["keeps"])
        self.assertEqual(verdict(points[0]), "no")
        self.assertTrue(points[3]["keeps"])  # +1.0 %

    def test_no_reference(self):
        points = [row(0.01, unstable=True), row(0.02, nu=NAN)]
        self.assertIsNone(against_smallest(points, TOL))
        for p in points:
            self.assertTrue(math.isnan(p["nu"]) and math.isnan(p["bTol"]) and not p["keeps"])


class LargestStep(unittest.TestCase):
    def study(self, *rows_):
        points = list(rows_)
        against_smallest(points, TOL)
        apply_cost_model({"GW": points})
        return points

    def test_broken_run_of_steps(self):
        # 0.02 keeps, 0.03 does not (nu +3 %), 0.04 keeps again: the largest is 0.02, limited by nu at 0.03.
        points = self.study(row(0.01), row(0.02, nu=0.2727), row(0.03, nu=0.2781), row(0.04, nu=0.27))
        best, why, unstable, speed = largest_keeping(points)
        self.assertEqual((best["dt"], why, unstable), (0.02, "nu at 0.03", None))
        self.assertAlmostEqual(speed, 2.0, places=12)  # the cost model: a time unit at 0.02 costs half

    def test_limited_by_a_blow_up(self):
        points = self.study(row(0.01), row(0.02), row(0.03), row(0.05, unstable=True), row(0.06, unstable=True))
        best, why, unstable, speed = largest_keeping(points)
        self.assertEqual((best["dt"], why, unstable), (0.03, "unstable at 0.05", 0.05))
        self.assertAlmostEqual(speed, 3.0, places=12)

    def test_every_step_keeps(self):
        best, why, unstable, speed = largest_keeping(self.study(row(0.01), row(0.05, kT=1.035)))
        self.assertEqual((best["dt"], why, unstable), (0.05, "-", None))
        self.assertAlmostEqual(speed, 5.0, places=12)

    def test_smallest_unstable(self):
        best, why, unstable, speed = largest_keeping(self.study(row(0.01, unstable=True), row(0.02)))
        self.assertEqual((best, why, unstable), (None, "unstable at 0.01", 0.01))
        self.assertTrue(math.isnan(speed))

    def test_table_and_cheapest(self):
        gw = self.study(row(0.01, cost=4e-5), row(0.03, cost=1.3e-5), row(0.05, kT=1.1, cost=8e-6))
        vv = self.study(row(0.01, cost=7e-5), row(0.03, kT=1.0, cost=2.2e-5))
        lines = largest_lines({"wall": {"GW": gw, "VV": vv}})
        self.assertEqual(lines[-3].split(), ["wall", "GW", "0.03", "kTwall", "at", "0.05", "-", "1.33e-05", "3.00"])
        # The median step costs: GW 4e-7 (of 4e-7, 3.9e-7, 4e-7), over 0.03; VV 6.8e-7 (of 7e-7, 6.6e-7), over 0.01.
        self.assertEqual(lines[-2].split(), ["wall", "VV", "0.01", "kTwall", "at", "0.03", "-", "6.8e-05", "1.00"])
        self.assertTrue(lines[-1].startswith("# wall: cheapest time unit within the tolerances: GW at dt 0.03, 1.33e-05"))


class Files(unittest.TestCase):
    def test_write_whole_and_picture(self):
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "results.dat")
            write_text(path, "old\n")
            write_whole(path, "new\n")
            with open(path) as f:
                self.assertEqual(f.read(), "new\n")
            self.assertFalse(os.path.exists(path + ".tmp"))
            points = [row(0.01), row(0.03, nu=0.28), row(0.05, unstable=True)]
            against_smallest(points, TOL)
            picture = os.path.join(tmp, "study.png")
            draw_study({"wall": {"GW": points}}, picture, "a study")
            with open(picture, "rb") as f:
                self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")


if __name__ == "__main__":
    unittest.main()
