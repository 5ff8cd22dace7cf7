"""dpdfoam.io reads what the tools write, on files built here in the tools' formats.

Time directories are ordered by their number, not their name (9 < 10 < 100, 1e-05 < 0.5); profile
tables, headerless tables, sections, dictionaries (the banner and FoamFile header ignored, lists as
numbers, quoted strings unquoted), compareFVM's sub-dictionaries and runSweep's tables ("none" a NaN,
words kept) give back the numbers written. The solver's log is parsed in the lines Runner.cpp prints:
the report series, the particles inside the walls, the bounce counts summed over exactly the reports
after a start time and the time they cover, the run's end (NaN without it); the builders' logs give
their particle counts (blockFrozenWall per wall with its lattice, randomEquilWall with its dropped
ones). OpenFOAM ascii vector fields and the latest time are read back. A missing file, match or report
exits or gives NaN (never a number). dpdDictionary is replaced by a stand-in that answers the entries a
test gives (and fails for others as the tool does): the entry asked for, the trailing ';' removed,
defaults only for a missing entry, and set_dictionary_value keeps the original once as .orig.
"""
import math
import os
import subprocess
import sys
import unittest

import numpy as np

from dpdfoam import io as dio
from dpdtest_support import dictionary_text, fake_dictionary, Temporary, write_table, write_text

BANNER = ("/*--------------------------------*- C++ -*----------------------------------*\\\n"
          "  Written by the dpd toolkit\n"
          "\\*---------------------------------------------------------------------------*/\n"
          "FoamFile\n{\n    version     2.0;\n    format      ascii;\n    class       dictionary;\n"
          "    object      fit.dat;\n}\n// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //\n\n")


def report(time, step, kT, walls=None, inside=0, bonds=None):
    """One report of the solver's log (tools/Runner.cpp printReport)."""
    text = f"Time = {time}  (step {step})\n    kT = {kT}   momentum = (0 0 0)   meanVelocity = (0.1 0 0)\n"
    if walls is not None:
        text += "    walls since last report:" + "".join(f" {n} returned {r} crossed {c};" for n, r, c in walls)
        text += f" left inside after a step 0; inside walls now {inside}\n"
    if bonds is not None:
        text += f"    bonds: longest {bonds[0]} of rMax {bonds[1]}\n"
    return text + "    ExecutionTime = 1.5 s   steps/s = 100   particle-steps/s = 1e+06   time left = 1 s\n\n"


class LatestTimes(Temporary):
    def setUp(self):
        super().setUp()
        for t in ("9", "10", "100", "1e-05", "0.5"):
            write_text(self.path("pp", t, "fit.dat"), f"t {t};\n")

    def test_latest_is_by_number(self):
        self.assertEqual(dio.latest(self.path("pp", "*", "fit.dat")), self.path("pp", "100", "fit.dat"))
        self.assertEqual(dio.latest_dir(self.path("pp", "*")), self.path("pp", "100"))

    def test_nothing_matches_exits(self):
        with self.assertRaises(SystemExit):
            dio.latest(self.path("none", "*", "fit.dat"))
        with self.assertRaises(SystemExit):
            dio.latest_dir(self.path("none", "*"))
        with self.assertRaises(SystemExit):
            dio.latest_sampling(self.tmp, "channelProfile")

    def test_latest_sampling(self):
        for t in ("50", "200", "75"):
            write_text(self.path("case", t, "sampling", "channelProfile.h5"), "")
        write_text(self.path("case", "300", "sampling", "other.h5"), "")
        self.assertEqual(dio.latest_sampling(self.path("case"), "channelProfile"),
                         self.path("case", "200", "sampling", "channelProfile.h5"))

    def test_latest_fit_and_profile(self):
        write_text(self.path("case", "postProcessing", "fitSlipLength", "20", "fit.dat"), "nu 0.2;\n")
        write_text(self.path("case", "postProcessing", "fitSlipLength", "100", "fit.dat"), "nu 0.3;\n")
        self.assertEqual(dio.latest_fit(self.path("case")), {"nu": 0.3})
        write_table(self.path("case", "postProcessing", "profileBins", "7", "channelProfile.dat"), {"z": [1.0], "ux": [2.0]})
        write_table(self.path("case", "postProcessing", "profileBins", "70", "channelProfile.dat"), {"z": [1.0], "ux": [3.0]})
        self.assertEqual(dio.latest_profile(self.path("case"))["ux"].tolist(), [3.0])

    def test_numbered_cases(self):
        for name in ("run2", "run10", "run0.5", "runX", "run3.orig"):
            os.makedirs(self.path("sweep", name))
        write_text(self.path("sweep", "run7"), "a file, not a case")
        cases = dio.numbered_cases(self.path("sweep", "run"), "Allrun")
        self.assertEqual(cases, [(0.5, self.path("sweep", "run0.5")), (2.0, self.path("sweep", "run2")),
                                 (10.0, self.path("sweep", "run10"))])
        with self.assertRaises(SystemExit):
            dio.numbered_cases(self.path("sweep", "none"), "Allrun")


class Tables(Temporary):
    def test_read_table(self):
        path = write_table(self.path("t.dat"), {"z": [0.5, 1.5, 2.5], "density": [3.0, 3.1, 2.9], "ux": [0.0, -1e-3, 2.5e-7]})
        t = dio.read_table(path)
        self.assertEqual(list(t), ["z", "density", "ux"])
        np.testing.assert_array_equal(t["ux"], [0.0, -1e-3, 2.5e-7])

    def test_one_row(self):
        t = dio.read_table(write_table(self.path("t.dat"), {"z": [0.5], "kT": [1.0]}))
        self.assertEqual(t["kT"].shape, (1,))

    def test_read_columns(self):
        write_text(self.path("chainBins.dat"), "# chains binned\n1 10 2.5 3 4\n2 12 2.7 3.1 4.2\n")
        t = dio.read_columns(self.path("chainBins.dat"), ("x", "samples", "Rg2"))
        self.assertEqual(sorted(t), ["Rg2", "samples", "x"])
        np.testing.assert_array_equal(t["samples"], [10, 12])

    def test_read_sections(self):
        for x in (-25.5, 3, -16.5):
            write_table(self.path(f"flowField_x{x:g}.dat"), {"z": [0.5, 1.5], "ux": [x, x]})
        write_table(self.path("beadField_x0.dat"), {"z": [0.5], "ux": [9.0]})
        sections = dio.read_sections(self.tmp, "flowField")
        self.assertEqual([x for x, _ in sections], [-25.5, -16.5, 3.0])
        self.assertEqual([t["ux"][0] for _, t in sections], [-25.5, -16.5, 3.0])

    def test_read_sweep(self):
        write_text(self.path("sweep.dat"), "# case pairCoeffs/wall-wall/a slipLength_0 bodyForce/value\n"
                                           "run1 10 1.5 (0.01,0,0)\nrun2 20 none (0.02,0,0)\n\n")
        s = dio.read_sweep(self.path("sweep.dat"))
        self.assertEqual(s["case"], ["run1", "run2"])
        np.testing.assert_array_equal(s["pairCoeffs/wall-wall/a"], [10.0, 20.0])
        self.assertEqual(s["slipLength_0"][0], 1.5)
        self.assertTrue(np.isnan(s["slipLength_0"][1]))
        np.testing.assert_array_equal(dio.sweep_vector(s["bodyForce/value"][1]), [0.02, 0.0, 0.0])

    def test_header_means(self):
        write_text(self.path("chainStatistics.dat"), "# chainStatistics\n# mean Rg2 4.25 +- 0.03\n# mean Ree2 25.5 +- 0.4\n"
                                                     "1 2 3\n")
        self.assertEqual(dio.header_means(self.path("chainStatistics.dat")), {"Rg2": (4.25, 0.03), "Ree2": (25.5, 0.4)})


class Dictionaries(Temporary):
    def test_parse_dict(self):
        text = BANNER + ("mode                poiseuille;\nnu                  0.3125;\nwallPosition        (-5 5.5);\n"
                         "profile             \"postProcessing/profileBins/100/channelProfile.dat\";\n"
                         "nuKineticTheory     none;\ng  1e-2; // a comment\nbad  nan;\n")
        d = dio.parse_dict(text)
        self.assertEqual(d["mode"], "poiseuille")
        self.assertEqual(d["nu"], 0.3125)
        self.assertEqual(d["wallPosition"], [-5.0, 5.5])
        self.assertEqual(d["profile"], "postProcessing/profileBins/100/channelProfile.dat")
        self.assertEqual(d["nuKineticTheory"], "none")
        self.assertEqual(d["g"], 0.01)
        self.assertTrue(math.isnan(d["bad"]))
        for header_word in ("Written", "version", "format", "class", "object", "FoamFile"):
            self.assertNotIn(header_word, d)

    def test_read_dict(self):
        path = write_text(self.path("fit.dat"), BANNER + dictionary_text({"nu": 0.25, "slipLength": [0.1, 0.2]}))
        self.assertEqual(dio.read_dict(path), {"nu": 0.25, "slipLength": [0.1, 0.2]})

    def test_read_compare(self):
        text = (BANNER + "time 100;\nmeanVelocityRatio 0.98;\n\nlines\n{\n    centre\n    {\n        L2 0.012;\n"
                "        noiseL2 0.004;\n    }\n\n    inlet\n    {\n        L2 0.03;\n    }\n}\n")
        path = write_text(self.path("compare.dat"), text)
        top, lines = dio.read_compare(path)
        self.assertEqual(top, {"time": 100.0, "meanVelocityRatio": 0.98})
        self.assertEqual(lines, {"centre": {"L2": 0.012, "noiseL2": 0.004}, "inlet": {"L2": 0.03}})

    def test_latest_compare_lines(self):
        d = self.path("case", "postProcessing", "compareFVM", "50")
        write_text(os.path.join(d, "compare.dat"), "time 50;\nlines\n{\n    a\n    {\n        L2 0.5;\n    }\n}\n")
        write_table(os.path.join(d, "profiles.dat"), {"z": [1.0, 2.0], "uDPD": [0.1, 0.2]})
        path, top, lines, profiles = dio.latest_compare_lines(self.path("case"))
        self.assertEqual((path, top, lines), (os.path.join(d, "compare.dat"), {"time": 50.0}, {"a": {"L2": 0.5}}))
        np.testing.assert_array_equal(profiles["uDPD"], [0.1, 0.2])
        self.assertEqual(dio.latest_compare(self.path("case")), {"time": 50.0})
        write_text(os.path.join(d, "compare.dat"), "time 50;\n")
        with self.assertRaises(SystemExit):
            dio.latest_compare_lines(self.path("case"))

    def test_vectors(self):
        np.testing.assert_array_equal(dio.vector("(1 -2.5 3e-1)"), [1.0, -2.5, 0.3])
        self.assertEqual(dio.vector_text([1.0, 0.5, -2e-7]), "(1 0.5 -2e-07)")

    def test_wall_planes(self):
        path = write_text(self.path("dpdProperties"), "walls\n{\n    upper { point (0 0 7.5); normal (0 0 -1); }\n"
                                                       "    lower { point (1 2 -7.25); normal (0 0 1); }\n}\n")
        self.assertEqual(dio.wall_planes(path), (-7.25, 7.5))


class DictionaryTool(Temporary):
    """The entries dpdDictionary gives, through a stand-in on PATH."""

    def entries(self):
        control, props = self.path("case", "system", "controlDict"), self.path("case", "constant", "dpdProperties")
        return {(control, "endTime"): "500", (control, "functions/channelProfile/startTime"): "100",
                (props, "bodyForce/value"): "(0.02 0 0)",
                (self.path("case", "system", "makeFoamCaseDict"), "lines/centre/start"): "(0 0 -5)",
                (self.path("case", "system", "makeFoamCaseDict"), "lines/centre/end"): "(0 0 5)"}

    def test_values(self):
        with fake_dictionary(self.tmp, self.entries()):
            control = self.path("case", "system", "controlDict")
            self.assertEqual(dio.dictionary_value(control, "endTime"), "500")
            self.assertEqual(dio.dictionary_number(control, "endTime"), 500.0)
            self.assertEqual(dio.function_start(self.path("case"), "channelProfile"), 100.0)
            self.assertEqual(dio.body_force(self.path("case")), 0.02)
            self.assertEqual(dio.dictionary_numbers(control, {"end": "endTime", "kT": "kT"}, kT=1.0), {"end": 500.0, "kT": 1.0})
            start, end = dio.case_line("centre", self.path("case", "system", "makeFoamCaseDict"))
            np.testing.assert_array_equal(start, [0, 0, -5])
            np.testing.assert_array_equal(end, [0, 0, 5])
            self.assertIsNone(dio.case_line("inlet", self.path("case", "system", "makeFoamCaseDict")))

    def test_missing_entry_without_default_raises(self):
        with fake_dictionary(self.tmp, self.entries()):
            with self.assertRaises(subprocess.CalledProcessError):
                dio.dictionary_number(self.path("case", "system", "controlDict"), "deltaT")
            with self.assertRaises(subprocess.CalledProcessError):
                dio.function_start(self.path("case"), "other")

    def test_set_keeps_the_original_once(self):
        path = write_text(self.path("case", "system", "makeFoamCaseDict"), "original\n")
        with fake_dictionary(self.tmp, {}) as calls:
            dio.set_dictionary_value(path, "cells", "(10 1 20)")
            write_text(path, "changed\n")
            dio.set_case_line("centre", [0, 0, -1.5], [0, 0, 1.5], 40, path)
            with open(path + ".orig") as f:
                self.assertEqual(f.read(), "original\n")
            real = os.path.abspath(path)
            self.assertEqual(calls(), [(real, "cells", "(10 1 20)"), (real, "lines/centre/start", "(0 0 -1.5)"),
                                       (real, "lines/centre/end", "(0 0 1.5)"), (real, "lines/centre/nPoints", "40")])


class Logs(Temporary):
    def solver_log(self):
        walls = lambda r, c: [("lower", r, c), ("upper", 2 * r, c + 1)]  # noqa: E731
        text = ("Particles      : 1200 (1000 mobile, 200 frozen)\n\n"
                + "".join(report(t, 100 * t, 1.0 + 0.001 * t, walls(t, 0), inside=t % 2) for t in range(1, 6))
                + "\nRun finished: 500 steps in 12.5 s, 4.0e+04 particle-steps/s\nEnd\n")
        return write_text(self.path("log.dpdFoamLike"), text)

    def test_log_values(self):
        text = dio.read_text(self.solver_log())
        self.assertEqual(dio.log_values(text, r"kT = (\S+)"), [1.001, 1.002, 1.003, 1.004, 1.005])
        self.assertEqual(dio.log_values(text, r"inside walls now (\d+)", int), [1, 0, 1, 0, 1])

    def test_run_finished(self):
        self.assertEqual(dio.run_finished(dio.read_text(self.solver_log())), (500, 12.5, 40000.0))
        self.assertTrue(all(math.isnan(v) for v in dio.run_finished("Time = 1\n")))

    def test_finished_solver_log(self):
        times, kts, inside, crossed, finished = dio.finished_solver_log(self.solver_log(), wall="upper")
        np.testing.assert_array_equal(times, [1, 2, 3, 4, 5])
        np.testing.assert_allclose(kts, [1.001, 1.002, 1.003, 1.004, 1.005])
        self.assertEqual((inside, crossed, finished), (1, 5, (500, 12.5, 40000.0)))

    def test_unfinished_log_exits(self):
        write_text(self.path("log.dpdFoamLike"), report(1, 100, 1.0, [("w", 0, 0)]))
        with self.assertRaises(SystemExit):
            dio.finished_solver_log(self.path("log.dpdFoamLike"))

    def test_wall_events(self):
        # Reports at t = 1..5, the one at t with t + 2 t returned and 0 + 1 crossed over the two walls;
        # after start = 2 the reports at 3, 4, 5 count (each covers the time since the one before, from 2).
        self.assertEqual(dio.wall_events(self.solver_log(), 2.0), (9 + 12 + 15, 3, 3.0))
        returned, crossed, span = dio.wall_events(self.solver_log(), 10.0)
        self.assertEqual((returned, crossed), (0, 0))
        self.assertTrue(math.isnan(span))

    def test_builders(self):
        write_text(self.path("log.randomEquilWall"), "Filled           : 100 particles\nFluid particles  : 900 (porosity 0.7)\n"
                                                     "Frozen particles : 300 (200 in the wall's thickness)\nDropped          : 40\n")
        self.assertEqual(dio.built_particles(self.path("log.randomEquilWall")), [900, 300])
        self.assertEqual(dio.frozen_wall_counts(self.path("log.randomEquilWall")), (300, 340))
        write_text(self.path("log.blockFrozenWall"), "Fluid particles  : 500 (volume 10)\n"
                                                     "Wall lower : 120 frozen particles (240 in the lattice's thickness; those deeper)\n"
                                                     "Wall upper : 100 frozen particles\n")
        self.assertEqual(dio.frozen_wall_counts(self.path("log.blockFrozenWall")), (220, 340))
        self.assertTrue(math.isnan(dio.log_count(self.path("log.blockFrozenWall"), "Frozen particles")))
        with self.assertRaises(SystemExit):
            dio.built_particles(self.path("log.blockFrozenWall"))

    def test_run_logged(self):
        dio.run_logged(self.tmp, [sys.executable, "-c", "print('hello')"])
        with open(self.path(f"log.{os.path.basename(sys.executable)}")) as f:
            self.assertEqual(f.read(), "hello\n")
        with self.assertRaises(SystemExit):
            dio.run_logged(self.tmp, [sys.executable, "-c", "import sys; sys.exit(3)"])


class OpenFoam(Temporary):
    def field(self, name, vectors):
        body = "\n".join(f"({a:g} {b:g} {c:g})" for a, b, c in vectors)
        return write_text(self.path("foam", "200", name),
                          f"FoamFile\n{{\n    class volVectorField;\n    object {name};\n}}\ndimensions [0 1 -1 0 0 0 0];\n\n"
                          f"internalField   nonuniform List<vector> \n{len(vectors)}\n(\n{body}\n)\n;\n\n"
                          "boundaryField\n{\n    wall { type noSlip; }\n    inlet { type fixedValue; value uniform (9 9 9); }\n}\n")

    def test_vector_field(self):
        vectors = [(0.5, 0.0, -0.25), (1e-3, 2.0, 3.5), (-1.5e-5, 0.0, 4.0)]
        np.testing.assert_allclose(dio.foam_vector_field(self.field("U", vectors)), vectors)

    def test_latest_time_and_fields(self):
        for t in ("0", "50", "200", "1e2"):
            os.makedirs(self.path("foam", t), exist_ok=True)
        os.makedirs(self.path("foam", "constant"))
        self.field("U", [(1, 2, 3)])
        self.field("C", [(0.5, 0.5, 0.5)])
        self.assertEqual(dio.foam_latest_time(self.path("foam")), "200")
        t, (u, c) = dio.foam_latest_fields(self.path("foam"), "U", "C")
        self.assertEqual(t, "200")
        np.testing.assert_array_equal(u, [[1, 2, 3]])
        np.testing.assert_array_equal(c, [[0.5, 0.5, 0.5]])

    def test_last_residual(self):
        write_text(self.path("foam", "log.simpleFoam"),
                   "smoothSolver:  Solving for Ux, Initial residual = 0.5, Final residual = 0.01, No Iterations 2\n"
                   "smoothSolver:  Solving for Ux, Initial residual = 2.5e-06, Final residual = 1e-08, No Iterations 1\n")
        self.assertEqual(dio.foam_last_residual(self.path("foam"), "Ux"), 2.5e-06)
        self.assertTrue(math.isnan(dio.foam_last_residual(self.path("foam"), "p")))


if __name__ == "__main__":
    unittest.main()
