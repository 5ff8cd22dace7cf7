"""dpdfoam.polymer_channel: the sweeps from the case without chains, each deficit step checked once, the
allowance of 3 standard errors and the fewest super-blocks.

The checks of one case (heat_check, depletion_check, deficit_step_check, symmetry_check, extension_check)
are fed broken inputs by tests/apps/checkBoundsPolymerPorous.sh through the tutorial; here what joins
them: the nChain sweep at the shortest ChainLen and the ChainLen sweep at the fewest chains, both from
the one case without chains (two such cases stop the script); the step no chains -> 12x10 that both
sweeps share is checked once (5 steps, not 6); 3 standard errors are Student's quantile of the same
tail for the degrees of freedom (NaN without one); 5 super-blocks at least.
"""
import math
import types
import unittest

from dpdfoam.checks import Checks
from dpdfoam.polymer_channel import MIN_SUPER_BLOCKS, allowance, deficit_checks, enough_blocks, sweeps
from dpdfoam.stats import Z_SIGMA, student_t


def case(chains, length, u=1.0):
    return types.SimpleNamespace(chains=chains, length=length, beads=chains * length,
                                 label="no chains" if chains == 0 else f"{chains}x{length}",
                                 U=types.SimpleNamespace(value=u, error=0.001, dof=7), deficit=1.0 - u)


class Sweeps(unittest.TestCase):
    def test_two_sweeps_from_no_chains(self):
        cases = [case(0, 0), case(12, 10), case(24, 10), case(36, 10), case(12, 20), case(12, 30)]
        ref, chained, n_sweep, l_sweep = sweeps(cases)
        self.assertIs(ref, cases[0])
        self.assertEqual(len(chained), 5)
        self.assertEqual([c.label for c in n_sweep], ["no chains", "12x10", "24x10", "36x10"])
        self.assertEqual([c.label for c in l_sweep], ["no chains", "12x10", "12x20", "12x30"])

    def test_one_case_without_chains(self):
        with self.assertRaises(SystemExit):
            sweeps([case(0, 0), case(0, 0), case(12, 10)])


class DeficitChecks(unittest.TestCase):
    def test_shared_step_once(self):
        u = {"no chains": 1.0, "12x10": 0.95, "24x10": 0.9, "36x10": 0.85, "12x20": 0.9, "12x30": 0.85}
        cs = {k: case(int(k.split("x")[0]), int(k.split("x")[1]), v) if "x" in k else case(0, 0, v) for k, v in u.items()}
        checks = Checks()
        deficit_checks(checks, [cs[k] for k in ("no chains", "12x10", "24x10", "36x10")],
                       [cs[k] for k in ("no chains", "12x10", "12x20", "12x30")])
        self.assertEqual(len(checks.rows), 5)
        self.assertFalse(checks.failures())


class Allowance(unittest.TestCase):
    def test_student(self):
        self.assertAlmostEqual(allowance(0.01, 4), student_t(Z_SIGMA, 4) * 0.01, places=15)
        self.assertTrue(math.isnan(allowance(0.01, 0)))

    def test_enough_blocks(self):
        self.assertEqual(enough_blocks(MIN_SUPER_BLOCKS), (True, ""))
        ok, why = enough_blocks(MIN_SUPER_BLOCKS - 1)
        self.assertFalse(ok)
        self.assertIn("fewer than", why)
        self.assertFalse(enough_blocks(float("nan"))[0])


if __name__ == "__main__":
    unittest.main()
