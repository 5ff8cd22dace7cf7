"""dpdfoam.checks: the checks' bookkeeping decides as issue 45 says.

A check passes only when its comparison holds and every number it reads is there and finite: a NaN,
an infinity, None, an empty or a non-numeric value fails it, whatever the comparison says. The
statistical form (bounded, within_budgets, near_zero) fails first a standard error at or above its
budget, then a value outside its fixed bounds; the bounds are inclusive and a None bound is open.
Information rows are reported but never fail; the exit status is 1 exactly when a check failed; the
results file holds the lines then the checks' lines. relative_difference and mode_budget turn a
missing number into NaN, which fails the check that reads it.
"""
import contextlib
import io
import math
import os
import tempfile
import unittest

from dpdfoam.checks import (Checks, as_number, bounded_verdict, finite, mode_budget, plus_minus, relative_difference,
                            write_results)

NAN, INF = float("nan"), float("inf")
BROKEN = (NAN, INF, -INF, None, "", "abc")


class Finite(unittest.TestCase):
    def test_numbers(self):
        for v in (0, 1.5, -3, "2.5", True):
            self.assertTrue(finite(v), repr(v))

    def test_broken(self):
        for v in BROKEN + ([1.0, NAN], (None, 1.0), object()):
            self.assertFalse(finite(v), repr(v))

    def test_sequences(self):
        self.assertTrue(finite([1, 2.0, (3, 4)]))
        self.assertFalse(finite([1, 2.0, (3, NAN)]))

    def test_empty_sequence_is_no_measurement(self):
        for v in ([], (), [1.0, ()]):
            self.assertFalse(finite(v), repr(v))
        checks = Checks()
        self.assertFalse(checks.add("reads an empty list", True, "", []))
        self.assertTrue(checks.add("reads no number", True, ""))  # nothing read: the comparison decides


class AsNumber(unittest.TestCase):
    def test_values(self):
        self.assertEqual(as_number("1.25"), 1.25)
        self.assertEqual(as_number(3), 3.0)
        for v in (None, "", "x", [1.0]):
            self.assertTrue(math.isnan(as_number(v)), repr(v))


class BoundedVerdict(unittest.TestCase):
    def test_pass(self):
        ok, why = bounded_verdict(0.02, 0.005, 0.01, -0.03, 0.03)
        self.assertTrue(ok)
        self.assertIn("within", why)

    def test_bounds_are_inclusive(self):
        self.assertTrue(bounded_verdict(0.03, 0.001, 0.01, -0.03, 0.03)[0])
        self.assertTrue(bounded_verdict(-0.03, 0.001, 0.01, -0.03, 0.03)[0])
        self.assertFalse(bounded_verdict(0.0300001, 0.001, 0.01, -0.03, 0.03)[0])
        self.assertFalse(bounded_verdict(-0.0300001, 0.001, 0.01, -0.03, 0.03)[0])

    def test_error_at_or_over_the_budget_fails(self):
        ok, why = bounded_verdict(0.0, 0.01, 0.01, -1, 1)
        self.assertFalse(ok)
        self.assertIn("ABOVE its budget", why)
        self.assertFalse(bounded_verdict(0.0, 0.02, 0.01, -1, 1)[0])

    def test_open_bounds(self):
        self.assertTrue(bounded_verdict(1e6, 0.0, 1.0, None, 0.0 + 1e7)[0])
        self.assertTrue(bounded_verdict(-1e6, 0.0, 1.0, None, 0.0)[0])
        self.assertTrue(bounded_verdict(5.0, 0.0, 1.0, 4.0, None)[0])
        self.assertFalse(bounded_verdict(3.0, 0.0, 1.0, 4.0, None)[0])
        self.assertTrue(bounded_verdict(123.0, 0.1, 1.0)[0])  # no bound at all: the budget alone

    def test_broken_numbers_fail(self):
        good = [0.0, 0.001, 0.01, -0.03, 0.03]
        for position in range(5):
            for bad in BROKEN:
                if bad is None and position >= 3:
                    continue  # a None bound is an open side (test_open_bounds)
                args = list(good)
                args[position] = bad
                ok, why = bounded_verdict(*args)
                self.assertFalse(ok, f"argument {position} = {bad!r}")
                self.assertIn("not a finite number", why)


class ChecksRows(unittest.TestCase):
    def test_add(self):
        c = Checks()
        self.assertTrue(c.add("good", True, "1.0", 1.0))
        self.assertFalse(c.add("false", False, "x"))
        self.assertEqual(c.rows, [("good", "PASS", "1.0"), ("false", "FAIL", "x")])
        self.assertEqual(c.failures(), ["false"])
        self.assertEqual(c.status(), 1)

    def test_a_broken_number_fails_a_true_comparison(self):
        for bad in BROKEN:
            c = Checks()
            self.assertFalse(c.add("nan", True, "", 1.0, bad), repr(bad))
            self.assertEqual(c.status(), 1)

    def test_nan_comparison_fails(self):
        c = Checks()
        c.add("nan below 1", NAN < 1.0, "", NAN)
        c.add("abs(nan) <= 1", abs(NAN) <= 1.0)
        self.assertEqual(c.failures(), ["nan below 1", "abs(nan) <= 1"])

    def test_no_checks_no_failure(self):
        self.assertEqual(Checks().status(), 0)

    def test_bounded_row(self):
        c = Checks()
        self.assertTrue(c.bounded("nu", 0.01, 0.004, 0.01, -0.03, 0.03, text="measured"))
        self.assertFalse(c.bounded("nu noisy", 0.01, 0.011, 0.01, -0.03, 0.03))
        self.assertFalse(c.bounded("nu missing", None, 0.001, 0.01, -0.03, 0.03))
        self.assertEqual([v for _, v, _ in c.rows], ["PASS", "FAIL", "FAIL"])
        self.assertTrue(c.rows[0][2].startswith("measured; "))

    def test_within_budgets(self):
        c = Checks()
        self.assertTrue(c.within_budgets("at 3 budgets", 0.03, 0.009, 0.01))
        self.assertTrue(c.within_budgets("at -3 budgets", -0.03, 0.009, 0.01))
        self.assertFalse(c.within_budgets("past 3 budgets", 0.0301, 0.009, 0.01))
        self.assertTrue(c.within_budgets("open above", 50.0, 0.009, 0.01, lower=3.0, upper=None))
        self.assertFalse(c.within_budgets("open above, too low", 0.029, 0.009, 0.01, lower=3.0, upper=None))
        self.assertFalse(c.within_budgets("nan budget", 0.0, 0.001, NAN))

    def test_near_zero(self):
        c = Checks()
        self.assertTrue(c.near_zero("flux", 0.0299, 0.009, 0.01))
        self.assertFalse(c.near_zero("flux", 0.0301, 0.009, 0.01))
        self.assertFalse(c.near_zero("flux", 0.0, NAN, 0.01))
        self.assertIn("within 3 x 0.01, standard error below 0.01", c.rows[0][0])

    def test_fail_extend_include(self):
        c = Checks()
        c.fail("given up")
        c.extend([("a", True, "1"), ("b", False, "2")])
        other = Checks()
        other.add("c", True)
        c.include(other)
        self.assertEqual([n for n, _, _ in c.rows], ["given up", "a", "b", "c"])
        self.assertEqual(c.failures(), ["given up", "b"])

    def test_inform(self):
        c = Checks()
        c.add("decided", False)
        c.add("reported only", False)
        c.inform(lambda name: name == "decided")
        self.assertEqual(c.rows[1][1], "info")
        self.assertEqual(c.failures(), ["decided"])
        c.inform(lambda name: False)
        self.assertEqual(c.status(), 0)

    def test_lines_and_write(self):
        c = Checks()
        c.add("nu within 3 %", True, "+0.41 %")
        c.add("kT", False, "1.1")
        self.assertEqual(c.lines(), ["check  PASS  nu within 3 %: +0.41 %", "check  FAIL  kT: 1.1"])
        self.assertEqual(c.lines("{verdict}|{name}"), ["PASS|nu within 3 %", "FAIL|kT"])
        out = io.StringIO()
        c.write(out)
        self.assertEqual(out.getvalue(), "check  PASS  nu within 3 %: +0.41 %\ncheck  FAIL  kT: 1.1\n")

    def test_print_failures(self):
        c = Checks()
        c.add("fine", True)
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            c.print_failures()
        self.assertEqual(out.getvalue(), "All checks passed.\n")
        c.add("broken", False)
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            c.print_failures()
        self.assertEqual(out.getvalue(), "CHECK FAILED: broken\n")


class Helpers(unittest.TestCase):
    def test_mode_budget(self):
        budgets = {"kT": (0.001, 0.004)}
        self.assertEqual(mode_budget(budgets, "kT", False), 0.001)
        self.assertEqual(mode_budget(budgets, "kT", True), 0.004)
        self.assertTrue(math.isnan(mode_budget(budgets, "nu", True)))
        self.assertTrue(math.isnan(mode_budget({"nu": (0.01, None)}, "nu", True)))
        # A missing budget fails the check that uses it.
        self.assertFalse(Checks().bounded("x", 0.0, 0.0, mode_budget(budgets, "nu", False), -1, 1))

    def test_plus_minus(self):
        self.assertEqual(plus_minus(1.23456, 0.0012), "1.2346 +- 0.0012")
        self.assertEqual(plus_minus(0.5, 0.25, 2, "+"), "+0.50 +- 0.25")

    def test_relative_difference(self):
        rel, err = relative_difference(1.1, 0.03, 1.0, 0.04)
        self.assertAlmostEqual(rel, 0.1, places=14)
        self.assertAlmostEqual(err, 0.05, places=14)
        rel, err = relative_difference("2.0", "0.1", 4.0, 0.0)
        self.assertAlmostEqual(rel, -0.5, places=14)
        self.assertAlmostEqual(err, 0.025, places=14)

    def test_relative_difference_missing_fails(self):
        for args in ((None, 0.1, 1.0, 0.1), (1.0, "", 1.0, 0.1), (1.0, 0.1, None, 0.1), (1.0, 0.1, 1.0, "none")):
            rel, err = relative_difference(*args)
            self.assertFalse(finite([rel, err]), repr(args))
            self.assertFalse(Checks().bounded("rel", rel, err, 0.01, -0.03, 0.03), repr(args))

    def test_write_results(self):
        c = Checks()
        c.add("ok", True, "1")
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "results.dat")
            out = io.StringIO()
            with contextlib.redirect_stdout(out):
                write_results(path, ["nu 0.31", "b 1.2"], c)
            with open(path) as f:
                text = f.read()
            self.assertEqual(text, "nu 0.31\nb 1.2\ncheck  PASS  ok: 1\n")
            self.assertEqual(out.getvalue(), text)
            with contextlib.redirect_stdout(io.StringIO()):
                write_results(path, ["only lines"])
            with open(path) as f:
                self.assertEqual(f.read(), "only lines\n")


if __name__ == "__main__":
    unittest.main()
