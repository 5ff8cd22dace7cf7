"""dpdfoam.stats against independent results.

The Student-t quantile (Abramowitz and Stegun 26.7.5) and the chi^2 bounds (Wilson-Hilferty) are
compared with exact quantiles computed here from the closed-form distribution functions for integer
degrees of freedom (A&S 26.7.3/26.7.4 for Student-t, the Poisson sum for chi^2 of even dof), which are
themselves checked first against the Cauchy and dof-2 closed forms, tabulated quantiles and a
numerical integration of the density. The means and standard errors are checked on hand-computable
values and on seeded synthetic data of known variance, with tolerances set by the statistics (five
standard errors of the quantity tested, with enough repetitions that a wrong formula lands far
outside): the block error's mean square is sigma^2 / m, the Student-t allowance covers the true mean
as often as the exact t distribution says (and a normal quantile would not), the jackknife of the mean
is the sample standard error exactly, the inverse-variance mean's error is its spread. NaN, a single
value or block give a NaN error, which the checks then fail.
"""
import math
import unittest

import numpy as np

from dpdfoam.stats import (BlockMean, chi2_bounds, combined, count_weighted_mean, inverse_variance_mean,
                           jackknife_error, mean_and_error, student_t, values_and_errors)

TAIL_3_SIGMA = 0.5 * math.erfc(3.0 / math.sqrt(2.0))  # one-sided normal tail beyond 3 sigma


def t_within(t, nu):
    """P(|T| <= t) for Student's t with integer nu degrees of freedom (A&S 26.7.3 odd, 26.7.4 even)."""
    theta = math.atan(t / math.sqrt(nu))
    s, c = math.sin(theta), math.cos(theta)
    if nu % 2 == 1:
        if nu == 1:
            return 2.0 * theta / math.pi
        term = total = c
        for k in range(1, (nu - 3) // 2 + 1):
            term *= c * c * (2 * k) / (2 * k + 1)
            total += term
        return 2.0 / math.pi * (theta + s * total)
    term = total = 1.0
    for k in range(1, (nu - 2) // 2 + 1):
        term *= c * c * (2 * k - 1) / (2 * k)
        total += term
    return s * total


def t_tail(t, nu):
    """One-sided tail P(T > t)."""
    return 0.5 * (1.0 - t_within(t, nu))


def bisect(f, lo, hi, iterations=200):
    """The root of a decreasing f in [lo, hi]."""
    for _ in range(iterations):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if f(mid) > 0 else (lo, mid)
    return 0.5 * (lo + hi)


def t_quantile(tail, nu):
    """t with P(T > t) = tail."""
    return bisect(lambda t: t_tail(t, nu) - tail, 0.0, 1e7)


def chi2_survival(x, k):
    """P(chi^2_k > x) for even k: exp(-x/2) sum_{j < k/2} (x/2)^j / j!."""
    h, term, total = 0.5 * x, 1.0, 1.0
    for j in range(1, k // 2):
        term *= h / j
        total += term
    return math.exp(-h) * total


def chi2_quantile(upper_tail, k):
    return bisect(lambda x: chi2_survival(x, k) - upper_tail, 0.0, 100.0 * k + 100.0)


class ReferenceDistributions(unittest.TestCase):
    """The exact references this file compares with, checked on their own first."""

    def test_t_closed_forms(self):
        for t in (0.3, 1.0, 4.0, 25.0):
            self.assertAlmostEqual(t_tail(t, 1), 0.5 - math.atan(t) / math.pi, places=14)  # Cauchy
            self.assertAlmostEqual(t_tail(t, 2), 0.5 * (1.0 - t / math.sqrt(2.0 + t * t)), places=14)

    def test_t_tabulated_quantiles(self):
        # Two-sided 95 % at 10 dof and 99 % at 5 dof (any statistics table).
        self.assertAlmostEqual(t_quantile(0.025, 10), 2.228138851986, places=9)
        self.assertAlmostEqual(t_quantile(0.005, 5), 4.032142983557, places=9)

    def test_t_against_integrated_density(self):
        for nu in (3, 4, 7, 12):
            t = np.linspace(0.0, 3.5, 20001)
            density = math.gamma((nu + 1) / 2) / (math.sqrt(nu * math.pi) * math.gamma(nu / 2)) * (1 + t * t / nu) ** (-(nu + 1) / 2)
            h = t[1] - t[0]
            simpson = h / 3 * (density[0] + density[-1] + 4 * density[1:-1:2].sum() + 2 * density[2:-1:2].sum())
            self.assertAlmostEqual(t_within(3.5, nu), 2 * simpson, places=10)

    def test_chi2_tabulated_quantile(self):
        self.assertAlmostEqual(chi2_quantile(0.05, 10), 18.307038, places=5)
        self.assertAlmostEqual(chi2_quantile(0.95, 10), 3.940299, places=5)


class StudentT(unittest.TestCase):
    def test_within_one_percent_from_four_dof(self):
        for nu in (4, 5, 6, 8, 10, 15, 20, 50, 100, 200):
            exact = t_quantile(TAIL_3_SIGMA, nu)
            self.assertLess(abs(student_t(3.0, nu) / exact - 1.0), 0.01, f"dof {nu}")

    def test_low_by_under_five_percent_at_three_dof(self):
        exact = t_quantile(TAIL_3_SIGMA, 3)
        ratio = student_t(3.0, 3) / exact
        self.assertLess(ratio, 1.0)
        self.assertGreater(ratio, 0.95)

    def test_other_tails(self):
        # z = 2 (tail 2.3 %) and z = 1 at 10 and 30 dof.
        for z in (1.0, 2.0):
            tail = 0.5 * math.erfc(z / math.sqrt(2.0))
            for nu in (10, 30):
                self.assertLess(abs(student_t(z, nu) / t_quantile(tail, nu) - 1.0), 1e-3, f"z {z}, dof {nu}")

    def test_normal_limit(self):
        self.assertAlmostEqual(student_t(3.0, 1e12), 3.0, places=10)
        self.assertEqual(student_t(3.0, float("inf")), 3.0)


class Chi2Bounds(unittest.TestCase):
    def test_against_exact_quantiles(self):
        # Wilson-Hilferty's error falls faster than 1 / dof: within 0.2 / dof from 50 dof on.
        for k in (50, 100, 400, 1000):
            lo, hi = chi2_bounds(k)
            self.assertLess(abs(lo / (chi2_quantile(1.0 - TAIL_3_SIGMA, k) / k) - 1.0), 0.2 / k, f"lower, dof {k}")
            self.assertLess(abs(hi / (chi2_quantile(TAIL_3_SIGMA, k) / k) - 1.0), 0.2 / k, f"upper, dof {k}")

    def test_bracket_one(self):
        for k in (2, 10, 100):
            lo, hi = chi2_bounds(k)
            self.assertLess(lo, 1.0)
            self.assertGreater(hi, 1.0)
        narrow = chi2_bounds(100, z=1.0)
        wide = chi2_bounds(100, z=3.0)
        self.assertTrue(wide[0] < narrow[0] < 1.0 < narrow[1] < wide[1])


class MeanAndError(unittest.TestCase):
    def test_hand_values(self):
        mean, error = mean_and_error([1.0, 2.0, 3.0, 4.0])
        self.assertEqual(mean, 2.5)
        self.assertAlmostEqual(error, math.sqrt(5.0 / 3.0) / 2.0, places=14)

    def test_single_value_has_no_error(self):
        mean, error = mean_and_error([7.0])
        self.assertEqual(mean, 7.0)
        self.assertTrue(math.isnan(error))

    def test_nan_propagates(self):
        mean, error = mean_and_error([1.0, float("nan"), 3.0])
        self.assertTrue(math.isnan(mean))
        self.assertTrue(math.isnan(error))

    def test_error_is_the_spread_of_the_mean(self):
        # 4000 means of 10 values of sigma 2: E[error^2] = sigma^2 / 10 = 0.4; the mean of error^2 over
        # the repetitions has relative standard error sqrt(2 / 9) / sqrt(4000) = 0.75 %.
        rng = np.random.default_rng(1)
        data = rng.normal(5.0, 2.0, size=(4000, 10))
        squares = np.array([mean_and_error(row)[1] ** 2 for row in data])
        self.assertLess(abs(squares.mean() / 0.4 - 1.0), 5 * math.sqrt(2.0 / 9.0) / math.sqrt(4000))


class InverseVarianceMean(unittest.TestCase):
    def test_two_values(self):
        value, error = inverse_variance_mean(np.array([1.0, 4.0]), np.array([1.0, 2.0]))
        self.assertAlmostEqual(value, (1.0 + 4.0 / 4.0) / 1.25, places=14)
        self.assertAlmostEqual(error, 1.0 / math.sqrt(1.25), places=14)

    def test_error_is_the_spread(self):
        # Three measurements of 0 with errors 0.5, 1, 2, repeated 5000 times: the weighted means'
        # spread is the returned error within 5 standard errors of a standard deviation (1 / sqrt(2 N)).
        rng = np.random.default_rng(2)
        errors = np.array([0.5, 1.0, 2.0])
        draws = rng.normal(0.0, errors, size=(5000, 3))
        values = np.array([inverse_variance_mean(d, errors)[0] for d in draws])
        expected = inverse_variance_mean(draws[0], errors)[1]
        self.assertAlmostEqual(expected, 1.0 / math.sqrt(4 + 1 + 0.25), places=14)
        self.assertLess(abs(values.std(ddof=1) / expected - 1.0), 5 / math.sqrt(2 * 5000))
        self.assertLess(abs(values.mean()), 5 * expected / math.sqrt(5000))

    def test_nan_error_gives_nan(self):
        value, error = inverse_variance_mean(np.array([1.0, 2.0]), np.array([1.0, float("nan")]))
        self.assertTrue(math.isnan(value) and math.isnan(error))


class CountWeightedMean(unittest.TestCase):
    def test_weights(self):
        self.assertAlmostEqual(count_weighted_mean(np.array([1.0, 3.0]), np.array([3.0, 1.0])), 1.5, places=14)

    def test_nan_left_out_with_its_weight(self):
        values = np.array([1.0, float("nan"), 3.0])
        self.assertAlmostEqual(count_weighted_mean(values, np.array([1.0, 100.0, 1.0])), 2.0, places=14)

    def test_all_nan_is_nan(self):
        self.assertTrue(np.isnan(count_weighted_mean(np.array([np.nan, np.nan]), np.array([1.0, 2.0]))))

    def test_along_the_last_axis(self):
        values = np.array([[1.0, 2.0], [np.nan, 5.0]])
        out = count_weighted_mean(values, np.array([[1.0, 1.0], [1.0, 1.0]]))
        np.testing.assert_allclose(out, [1.5, 5.0])


class Combined(unittest.TestCase):
    def test_welch_satterthwaite(self):
        e1, n1, e2, n2 = 0.3, 4, 0.5, 9
        sigma, allowance, dof = combined((e1, n1), (e2, n2))
        self.assertAlmostEqual(sigma, math.hypot(e1, e2), places=14)
        self.assertAlmostEqual(dof, (e1 ** 2 + e2 ** 2) ** 2 / (e1 ** 4 / n1 + e2 ** 4 / n2), places=12)
        self.assertAlmostEqual(allowance, student_t(3.0, dof) * sigma, places=14)

    def test_equal_terms_add_their_dof(self):
        _, _, dof = combined((0.2, 5), (0.2, 5))
        self.assertAlmostEqual(dof, 10.0, places=12)

    def test_a_zero_term_leaves_the_other(self):
        sigma, _, dof = combined((0.0, 3), (0.4, 7))
        self.assertAlmostEqual(sigma, 0.4, places=15)
        self.assertAlmostEqual(dof, 7.0, places=12)

    def test_no_error_at_all(self):
        sigma, allowance, dof = combined((0.0, 3), (0.0, 3))
        self.assertEqual((sigma, allowance), (0.0, 0.0))
        self.assertEqual(dof, float("inf"))

    def test_nan_error_gives_nan(self):
        sigma, allowance, dof = combined((float("nan"), 3), (0.2, 4))
        self.assertTrue(math.isnan(sigma) and math.isnan(allowance))


class Jackknife(unittest.TestCase):
    def test_mean_is_the_sample_standard_error(self):
        # For the mean, the leave-one-out means give exactly std(ddof=1) / sqrt(m).
        x = np.random.default_rng(3).normal(size=17)
        loo = (x.sum() - x) / (len(x) - 1)
        self.assertAlmostEqual(float(jackknife_error(loo)), x.std(ddof=1) / math.sqrt(len(x)), places=13)

    def test_per_column(self):
        x = np.random.default_rng(4).normal(size=(9, 3)) * [1.0, 2.0, 5.0]
        loo = (x.sum(axis=0) - x) / 8
        np.testing.assert_allclose(jackknife_error(loo, axis=0), x.std(axis=0, ddof=1) / 3.0, rtol=1e-12)

    def test_nan_estimate_gives_nan(self):
        self.assertTrue(np.isnan(jackknife_error([1.0, np.nan, 2.0])))


class BlockMeanTest(unittest.TestCase):
    def test_fields(self):
        b = BlockMean([1.0, 2.0, 3.0, 6.0])
        self.assertEqual((b.value, b.m, b.dof), (3.0, 4, 3))
        self.assertAlmostEqual(b.error, np.std([1, 2, 3, 6], ddof=1) / 2.0, places=14)
        self.assertEqual(b.term(), (b.error, 3))
        self.assertEqual(b.fmt(2), f"3.00 +- {b.error:.2f}")
        self.assertAlmostEqual(b.allowance(), student_t(3.0, 3) * b.error, places=14)

    def test_given_value_keeps_the_spread(self):
        b = BlockMean([1.0, 3.0], value=10.0)
        self.assertEqual(b.value, 10.0)
        self.assertAlmostEqual(b.error, 1.0, places=14)

    def test_one_block_has_no_error(self):
        b = BlockMean([4.0])
        self.assertEqual(b.value, 4.0)
        self.assertTrue(math.isnan(b.error))
        # No allowance either (0 dof): a NaN, never a number a check could pass, nor an error raised.
        self.assertTrue(math.isnan(b.allowance()))
        self.assertTrue(math.isnan(BlockMean.of(1.0, 0.1, 0).allowance()))

    def test_nan_block(self):
        b = BlockMean([1.0, np.nan, 2.0])
        self.assertTrue(math.isnan(b.value) and math.isnan(b.error))

    def test_of(self):
        b = BlockMean.of(0.3, 0.01, 7)
        self.assertEqual((b.value, b.error, b.dof), (0.3, 0.01, 7))
        self.assertAlmostEqual(b.allowance(), student_t(3.0, 7) * 0.01, places=15)

    def test_values_and_errors(self):
        a, b = BlockMean.of(1.0, 0.1, 3), BlockMean.of(2.0, 0.2, 3)
        self.assertEqual(values_and_errors(a, b), [1.0, 0.1, 2.0, 0.2])

    def test_error_mean_square(self):
        # m = 8 blocks of sigma 1.5, 3000 repetitions: E[error^2] = sigma^2 / m; relative standard
        # error of its mean sqrt(2 / 7) / sqrt(3000) ~ 1 %.
        rng = np.random.default_rng(5)
        squares = np.array([BlockMean(row).error ** 2 for row in rng.normal(0.0, 1.5, size=(3000, 8))])
        self.assertLess(abs(squares.mean() / (1.5 ** 2 / 8) - 1.0), 5 * math.sqrt(2.0 / 7.0) / math.sqrt(3000))

    def test_allowance_covers_as_student_t_says(self):
        # m = 5 blocks (4 dof): |mean - mu| exceeds the 3-sigma allowance with the exact two-sided t
        # probability at the allowance's quantile (0.28 %); a normal quantile (3 errors) would miss 4 %.
        rng = np.random.default_rng(6)
        n = 10000
        misses = 0
        for row in rng.normal(2.0, 1.0, size=(n, 5)):
            b = BlockMean(row)
            misses += abs(b.value - 2.0) > b.allowance()
        p = 2.0 * t_tail(student_t(3.0, 4), 4)
        self.assertLess(abs(misses - n * p), 5 * math.sqrt(n * p * (1 - p)))
        self.assertGreater(2.0 * t_tail(3.0, 4) * n, n * p + 20 * math.sqrt(n * p))  # the normal quantile is far off


if __name__ == "__main__":
    unittest.main()
