"""dpdfoam.contraction: the contraction scenes' measures and checks on sections and logs written here.

A section across the channel with density 3 and ux = 1 - (z / 5)^2 carries the midpoint sum of the
parabola, 3 (20 / 3 + 1 / 120) (the midpoint rule's error for f'' = -2 / 25 is exact), less what the
bins set to reversed flow take away; only bins below zero by more than two standard errors count as
reversed, and only bins the fluid fills count in the means. The upstream difference of two sections
0.01 apart is 0.01 with the noise of the two errors combined. The checks pass a steady scene and fail
a particle inside the solid, a kT off by more than 1 % or too noisy, a NaN or missing kT, a section's
flux off by more than the mode's bound or too noisy, and no flow. The solver log gives the particles
inside at the end, the kT series and the bounce layer's counts; no report stops it; the longest bond
is the largest reported (NaN without one, which fails its check). The chains' rows and checks count
the beads and bonds insertChains made. main() run in a scene directory writes results.dat and the
picture, and exits 1 exactly when a section's flux is off.
"""
import contextlib
import io
import math
import os
import tempfile
import unittest

import numpy as np

from dpdfoam import contraction as c
from dpdfoam.checks import Checks
from dpdtest_support import working_directory, write_table, write_text

NAN = float("nan")


def section(shift=0.0, reversed_bins=True, scale=1.0):
    """20 bins of 0.5 across z in [-5, 5]: density 3, ux = scale (1 - (z / 5)^2) + shift, uxErr 0.01; the
    outermost bins hold 5 particle-samples (not fluid), the others 100 (one 200, kT 1.3; the rest kT 1).
    With reversed_bins the bins at -4.25 and -3.75 flow back at -0.05 and the one at 3.75 at -0.015."""
    z = -5.0 + 0.5 * (np.arange(20) + 0.5)
    ux = scale * (1.0 - (z / 5.0) ** 2) + shift
    if reversed_bins:
        ux[[1, 2, 17]] = [-0.05, -0.05, -0.015]
    count = np.full(20, 100.0)
    count[[0, 19]] = 5.0
    kT = np.ones(20)
    count[10], kT[10] = 200.0, 1.3
    return {"z": z, "density": np.full(20, 3.0), "densityErr": np.zeros(20), "ux": ux, "uxErr": np.full(20, 0.01),
            "count": count, "kT": kT}


def solver_log_text(inside=0, bonds=False):
    text = ""
    for t in (10, 20):
        text += (f"Time = {t}  (step {100 * t})\n    kT = 1.00{t}   momentum = (0 0 0)   meanVelocity = (0.1 0 0)\n"
                 f"    walls since last report: geometry returned {t} crossed {t // 10}; left inside after a step 0; "
                 f"inside walls now {inside if t == 20 else 3}\n")
        if bonds:
            text += f"    bonds: longest {1.5 + t / 100} of rMax 2\n"
    return text + "\nRun finished: 2000 steps in 10 s, 1e+06 particle-steps/s\nEnd\n"


class Sections(unittest.TestCase):
    def test_section_row(self):
        row = c.section_row(-25.5, section())
        x, flux, flux_err, ux_max, density, kT, ux_mean, ux_min, width, reversed_flux = row
        base = 3.0 * (20.0 / 3.0 + 1.0 / 120.0)
        taken = 1.5 * ((0.2775 + 0.05) + (0.4375 + 0.05) + (0.4375 + 0.015))
        self.assertEqual(x, -25.5)
        self.assertAlmostEqual(flux, base - taken, places=12)
        self.assertAlmostEqual(flux_err, 0.5 * math.sqrt(20) * 0.03, places=14)
        self.assertAlmostEqual(ux_max, 0.9975, places=14)
        self.assertEqual(density, 3.0)
        self.assertAlmostEqual(kT, (1700.0 + 260.0) / 1900.0, places=14)
        s = section()
        fluid = slice(1, 19)
        self.assertAlmostEqual(ux_mean, np.sum(s["ux"][fluid] * s["count"][fluid]) / 1900.0, places=14)
        self.assertEqual(ux_min, -0.05)
        self.assertEqual(width, 1.0)  # two bins of 0.5; the one at -0.015 lies within two errors
        self.assertAlmostEqual(reversed_flux, -0.15, places=14)

    def test_no_reversed_flow(self):
        row = c.section_row(0.0, section(reversed_bins=False))
        self.assertAlmostEqual(row[1], 3.0 * (20.0 / 3.0 + 1.0 / 120.0), places=12)
        self.assertEqual((row[8], row[9]), (0.0, 0.0))

    def test_upstream_difference(self):
        sections = [(-25.5, section(reversed_bins=False)), (-16.5, section(shift=0.01, reversed_bins=False))]
        x1, x2, rms, noise = c.upstream_difference(sections)
        self.assertEqual((x1, x2), (-25.5, -16.5))
        self.assertAlmostEqual(rms, 0.01, places=12)
        self.assertAlmostEqual(noise, math.hypot(0.01, 0.01), places=14)


def rows(fluxes, errors):
    return [(x, f, e, 1.0, 3.0, 1.0, 0.5, 0.0, 0.0, 0.0) for x, f, e in zip(range(5), fluxes, errors)]


class FlowChecks(unittest.TestCase):
    def run_checks(self, fluxes=(20.0,) * 5, errors=(0.5,) * 5, mean_kT=1.004, inside=0, kT_error=0.0006, test=True):
        checks = Checks()
        c.flow_checks(checks, rows(fluxes, errors), mean_kT, inside, kT_error, test, "fluid particles")
        return checks

    def test_steady_scene_passes(self):
        checks = self.run_checks()
        self.assertEqual(len(checks.rows), 5)
        self.assertEqual(checks.status(), 0)
        self.assertEqual(self.run_checks(errors=(0.09,) * 5, fluxes=(20.0, 20.09, 19.91, 20.0, 20.0), test=False).status(), 0)

    def test_failures(self):
        for why, kwargs in (
                ("a particle inside the solid", {"inside": 1}),
                ("kT 1.2 % high", {"mean_kT": 1.012}),
                ("kT too noisy", {"kT_error": 0.001}),
                ("kT NaN", {"mean_kT": NAN}),
                ("kT missing", {"mean_kT": None}),
                ("kT error NaN", {"kT_error": NAN}),
                ("a section 2.4 % below the mean (test bound 2 %)", {"fluxes": (20.0, 20.0, 20.0, 20.0, 19.4)}),
                ("a section 0.6 % below the mean at full size (bound 0.5 %)",
                 {"fluxes": (20.0, 20.0, 20.0, 20.0, 19.85), "errors": (0.09,) * 5, "test": False}),
                ("a section too noisy (4 % in the test)", {"errors": (0.5, 0.5, 0.9, 0.5, 0.5)}),
                ("a NaN flux", {"fluxes": (20.0, NAN, 20.0, 20.0, 20.0)}),
                ("a NaN flux error", {"errors": (0.5, 0.5, NAN, 0.5, 0.5)}),
                ("no flow", {"fluxes": (-20.0,) * 5})):
            self.assertEqual(self.run_checks(**kwargs).status(), 1, why)


class Logs(unittest.TestCase):
    def test_solver_log(self):
        with tempfile.TemporaryDirectory() as tmp:
            write_text(os.path.join(tmp, "log.dpdFoamLike"), solver_log_text(inside=2))
            inside, kts, layer = c.solver_log(tmp)
            self.assertEqual((inside, kts, layer), (2, [1.001, 1.002], [(10, 1), (20, 2)]))
            write_text(os.path.join(tmp, "log.dpdFoamLike"), "Time = 1\n")
            with self.assertRaises(SystemExit):
                c.solver_log(tmp)

    def test_longest_bond(self):
        with tempfile.TemporaryDirectory() as tmp:
            write_text(os.path.join(tmp, "log.dpdFoamLike"), solver_log_text(bonds=True))
            self.assertEqual(c.longest_bond(tmp), (1.7, 2.0))
            write_text(os.path.join(tmp, "log.dpdFoamLike"), solver_log_text())
            bond = c.longest_bond(tmp)
            self.assertTrue(math.isnan(bond[0]) and math.isnan(bond[1]))
            checks = Checks()
            c.chain_checks(checks, (2, 3), {"beads": np.zeros((6, 3)), "starts": np.zeros((4, 3)), "path": "p"}, bond)
            self.assertEqual([v for _, v, _ in checks.rows], ["PASS", "PASS", "FAIL"])


class Chains(unittest.TestCase):
    def test_bead_row(self):
        fluid = section(reversed_bins=False)
        beads = {"z": fluid["z"], "density": np.full(20, 0.2), "ux": np.full(20, 0.5), "count": np.full(20, 10.0)}
        beads["count"][5], beads["ux"][5] = 0.0, NAN  # no bead visited: no velocity, no flux
        density, flux = c.bead_row(0.0, beads, fluid)
        self.assertAlmostEqual(density, 0.2, places=14)
        self.assertAlmostEqual(flux, 19 * 0.2 * 0.5 * 0.5, places=14)

    def test_chain_bin_row(self):
        bins = {"x": np.array([-30.0, -20.0, -10.0, 0.0]), "samples": np.array([1, 2, 3, 4]), "Rg2": np.array([1.0, 2, 3, 4]),
                "span": np.array([5.0, 6, 7, 8]), "Rx2": np.array([4.0, 9.0, 16.0, 25.0])}
        self.assertEqual(c.chain_bin_row(bins, -25.5), (1, 1.0, 5.0, 2.0))  # in the bin [-35, -25)
        self.assertEqual(c.chain_bin_row(bins, -24.5), (2, 2.0, 6.0, 3.0))
        self.assertEqual(c.chain_bin_row(bins, 40.0), (4, 4.0, 8.0, 5.0))  # beyond the bins: the last

    def test_chain_checks(self):
        checks = Checks()
        snap = {"beads": np.zeros((30, 3)), "starts": np.zeros((27, 3)), "path": "40/particles.h5"}
        c.chain_checks(checks, (3, 10), snap, (1.9, 2.0))
        self.assertEqual(checks.status(), 0)
        c.chain_checks(checks, (3, 10), {"beads": np.zeros((29, 3)), "starts": np.zeros((26, 3)), "path": "p"}, (2.0, 2.0))
        self.assertEqual(len(checks.failures()), 3)


class Scene(unittest.TestCase):
    """main() in a scene directory: the grid, five sections and the solver's log."""

    def make(self, directory, last_scale=1.0):
        pp = os.path.join(directory, "postProcessing", "profileBins", "50")
        xs, zs = np.linspace(-30.0, 30.0, 7), np.linspace(-4.75, 4.75, 20)
        x, z = np.meshgrid(xs, zs)
        n = x.size
        write_table(os.path.join(pp, "flowField.dat"),
                    {"x": x.ravel(), "z": z.ravel(), "count": np.full(n, 100.0), "density": np.full(n, 3.0),
                     "ux": (1 - (z / 5) ** 2).ravel(), "kT": np.full(n, 1.004), "kTErr": np.full(n, 0.003)})
        for k, xs_ in enumerate((-25.5, -16.5, -5.0, 5.0, 16.5)):
            scale = last_scale if k == 4 else 1.0
            write_table(os.path.join(pp, f"flowField_x{xs_:g}.dat"), section(reversed_bins=False, scale=scale))
        write_text(os.path.join(directory, "log.dpdFoamLike"), solver_log_text())

    def run_main(self, last_scale):
        with tempfile.TemporaryDirectory() as tmp:
            self.make(tmp, last_scale)
            out = io.StringIO()
            with working_directory(tmp), contextlib.redirect_stdout(out):
                try:
                    c.main("Test contraction", ["-test"])
                    code = 0
                except SystemExit as e:
                    code = e.code
                with open("results.dat") as f:
                    results = f.read()
                self.assertTrue(os.path.getsize("contraction.png") > 0)
        return code, results, out.getvalue()

    def test_main(self):
        code, results, out = self.run_main(1.0)
        self.assertEqual(code, 0)
        self.assertIn("# mean kT 1.00400 +- ", results)
        self.assertEqual(len([line for line in results.splitlines() if not line.startswith("#")]), 5)
        self.assertIn("All checks passed.", out)
        code, results, out = self.run_main(0.97)  # the last section's flux 3 % low
        self.assertEqual(code, 1)
        self.assertIn("CHECK FAILED: the flux differs between sections", out)


if __name__ == "__main__":
    unittest.main()
