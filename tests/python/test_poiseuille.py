"""dpdfoam.poiseuille: scene 1's density flatness error by hand and the alpha sweep's picture.

Beyond one cutoff of the walls at 0 and 10 the largest bin error (0.08, at z = 5.25) over the mean
density there (4) is 0.02; the bins within a cutoff (error 1) do not count. The alpha sweep draws every
quantity of SHOWN, each a key of QUANTITIES, from the runs' q.
"""
import os
import tempfile
import types
import unittest

import numpy as np

from dpdfoam.poiseuille import QUANTITIES, SHOWN, draw_alpha_sweep, flatness_error
from dpdtest_support import working_directory


class FlatnessError(unittest.TestCase):
    def test_largest_error_beyond_a_cutoff(self):
        z = np.arange(0.25, 10.0, 0.5)
        err = np.where(np.minimum(z, 10 - z) < 1.0, 1.0, 0.02)
        err[z == 5.25] = 0.08
        prof = {"z": z, "density": np.full_like(z, 4.0), "densityErr": err}
        self.assertAlmostEqual(flatness_error(prof, (0.0, 10.0)), 0.02, places=12)


class AlphaSweep(unittest.TestCase):
    def test_picture(self):
        self.assertTrue(set(k for k, _ in SHOWN) <= set(QUANTITIES))
        run = lambda v: types.SimpleNamespace(q={k: v for k in QUANTITIES})  # noqa: E731
        sweeps = {"FCC": ([0.1, 1.0], [run(1.0), run(2.0)]), "random": ([0.1, 1.0], [run(1.5), run(2.5)])}
        with tempfile.TemporaryDirectory() as tmp, working_directory(tmp):
            draw_alpha_sweep(sweeps, 0.27)
            self.assertGreater(os.path.getsize("alphaSweep.png"), 0)


if __name__ == "__main__":
    unittest.main()
