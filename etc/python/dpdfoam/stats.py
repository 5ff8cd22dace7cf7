"""Means and their standard errors: over independent runs or blocks, inverse-variance and count-weighted
means, the Student-t quantile for errors estimated from few blocks, Welch-Satterthwaite's degrees of
freedom of a combination, the jackknife, chi^2 bounds."""
import math

import numpy as np

Z_SIGMA = 3.0  # "3 standard errors"


def mean_and_error(values):
    """The mean of independent values and its standard error (NaN from a single value)."""
    v = np.asarray(values, dtype=float)
    return np.mean(v), (np.std(v, ddof=1) / math.sqrt(len(v)) if len(v) > 1 else float("nan"))


def inverse_variance_mean(values, errors):
    """The inverse-variance weighted mean of values with standard errors, and its standard error."""
    w = 1.0 / np.asarray(errors) ** 2
    return float(np.sum(w * values) / np.sum(w)), float(1.0 / math.sqrt(np.sum(w)))


def count_weighted_mean(values, weights, axis=-1):
    """Weighted mean along axis, NaN values (empty bins) left out with their weights."""
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.nansum(values * weights, axis=axis) / np.sum(np.where(np.isfinite(values), weights, 0.0), axis=axis)


def student_t(z, dof):
    """The Student-t quantile with the one-sided tail probability of z normal standard deviations
    (Abramowitz and Stegun 26.7.5; good to ~1 % for dof >= 4, ~5 % low at dof 3): the allowance for
    error bars that are themselves estimated from few blocks."""
    g1 = (z ** 3 + z) / 4
    g2 = (5 * z ** 5 + 16 * z ** 3 + 3 * z) / 96
    g3 = (3 * z ** 7 + 19 * z ** 5 + 17 * z ** 3 - 15 * z) / 384
    g4 = (79 * z ** 9 + 776 * z ** 7 + 1482 * z ** 5 - 1920 * z ** 3 - 945 * z) / 92160
    return z + g1 / dof + g2 / dof ** 2 + g3 / dof ** 3 + g4 / dof ** 4


def combined(*terms, z=Z_SIGMA):
    """sigma and the z-sigma allowance of a sum of independent terms (error, degrees of freedom):
    Welch-Satterthwaite degrees of freedom, Student-t quantile. Returns (sigma, allowance, dof)."""
    sigma = math.sqrt(sum(e * e for e, _ in terms))
    denominator = sum(e ** 4 / dof for e, dof in terms if e > 0)
    dof = sigma ** 4 / denominator if denominator > 0 else float("inf")
    return sigma, student_t(z, dof) * sigma, dof


def jackknife_error(leave_one_out, axis=0):
    """The jackknife standard error from the estimates with each of m blocks left out in turn."""
    x = np.asarray(leave_one_out, dtype=float)
    m = x.shape[axis]
    return np.sqrt((m - 1) / m * np.sum((x - np.mean(x, axis=axis)) ** 2, axis=axis))


def chi2_bounds(dof, z=Z_SIGMA):
    """Two-sided z-sigma bounds of chi^2_dof / dof (Wilson-Hilferty)."""
    a = 2.0 / (9.0 * dof)
    return tuple((1.0 - a + s * z * math.sqrt(a)) ** 3 for s in (-1.0, 1.0))


def values_and_errors(*means):
    """The values and standard errors of BlockMeans in turn: [value, error, value, error, ...]."""
    return [x for mean in means for x in (mean.value, mean.error)]


class BlockMean:
    """A mean over blocks (super-blocks of a run), its standard error and its degrees of freedom; the
    value may be given (a ratio of means, a fit) with the blocks giving only the spread."""

    def __init__(self, per_block, value=None):
        per_block = np.asarray(per_block, dtype=float)
        self.blocks = per_block
        self.value = float(np.mean(per_block)) if value is None else float(value)
        self.m = len(per_block)
        self.error = float(np.std(per_block, ddof=1) / math.sqrt(self.m)) if self.m > 1 else float("nan")
        self.dof = self.m - 1

    @classmethod
    def of(cls, value, error, dof):
        """A value with an error from elsewhere (a jackknife)."""
        out = cls([0.0, 0.0], value)
        out.error, out.dof = error, dof
        return out

    def term(self):
        return (self.error, self.dof)

    def allowance(self, z=Z_SIGMA):
        """z standard errors read as the Student-t quantile of the same tail for the blocks' dof; NaN
        without a degree of freedom (a single block: no error to widen)."""
        return student_t(z, self.dof) * self.error if self.dof > 0 else float("nan")

    def fmt(self, digits=4):
        return f"{self.value:.{digits}f} +- {self.error:.{digits}f}"
