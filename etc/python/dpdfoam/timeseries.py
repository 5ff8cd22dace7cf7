"""Time series of a run (one row per time: snapshots' measures, chain statistics, the log's reports) as
super-block means: the window [start, start + m length) split into m super-blocks of `length` time
units, the same as a profile's (fitSlipLength's superBlocks), so that every mean's error is the spread
of its m super-block means (docs/analysis.md 5.2): SuperBlockWindow reads the window from fit.dat.
Besides: per super-block slopes, values binned by a position, and a solver log's run report."""
import os
import re
import sys
import warnings

import numpy as np

from .io import latest_fit, log_values, read_text, run_finished
from .stats import BlockMean


def block_index(times, start, length, m, closed=True):
    """Each time's super-block, 0 to m - 1, or -1 outside the window. closed: a time at the window's end
    (a snapshot written at endTime) counts in the last super-block."""
    x = (np.asarray(times, dtype=float) - start) / length
    k = np.floor(x).astype(int)
    if closed:  # the end itself (to rounding: 1e-9 of a super-block), not the times after it
        k = np.where((k == m) & (x <= m + 1e-9), m - 1, k)
    return np.where((k >= 0) & (k < m), k, -1)


def rows_in_blocks(rows, start, length, m, closed=True):
    """The rows (first column: time) within the window, and their super-blocks."""
    k = block_index(rows[:, 0], start, length, m, closed)
    return rows[k >= 0], k[k >= 0]


def _mean(values, select):
    return values[select].mean() if np.any(select) else np.nan


def block_means(values, index, m):
    """The mean of values per super-block (index from block_index; -1 leaves a value out), NaN where a
    super-block holds none."""
    values = np.asarray(values)
    return np.array([_mean(values, index == j) for j in range(m)])


def binned_block_means(values, index, bins, n_bins, m):
    """The mean of values per super-block (rows) and bin (columns: bins holds each value's bin), NaN
    where a super-block has none in a bin."""
    values = np.asarray(values)
    return np.array([[_mean(values, (index == j) & (bins == b)) for b in range(n_bins)] for j in range(m)])


def nan_block_mean(means):
    """Per column of super-block means (rows), the mean of those that hold a value and its standard
    error; NaN for a column none holds (and the error of one only one holds)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        return np.nanmean(means, axis=0), np.nanstd(means, axis=0, ddof=1) / np.sqrt(np.sum(np.isfinite(means), axis=0))


def log_series(text, value_pattern, time_pattern=r"^Time = (\S+)"):
    """The solver log's reports as a series: the time and a value (the pattern's group) of each report,
    as far as both lists go."""
    times = log_values(text, time_pattern, flags=re.M)
    values = log_values(text, value_pattern)
    n = min(len(times), len(values))
    return np.array(times[:n]), np.array(values[:n])


def block_slopes(x, y, index, m, minimum=3):
    """Per super-block the least-squares slope of y on x, NaN where it holds fewer than `minimum` points."""
    return [np.polyfit(x[index == j], y[index == j], 1)[0] if np.sum(index == j) >= minimum else np.nan
            for j in range(m)]


def binned_profile(values, positions, edges, index, m):
    """Values binned by position (bin edges) per super-block: the bins' centres, mean and error (nan_block_mean)."""
    means = binned_block_means(values, index, np.digitize(positions, edges) - 1, len(edges) - 1, m)
    return (0.5 * (edges[1:] + edges[:-1]),) + nan_block_mean(means)


class SuperBlockWindow:
    """fitSlipLength's super-blocks of a case (its latest fit.dat) as the window of every other mean: the
    last m super-blocks of `length` time units before the run's end (start = end - m length); exits (run
    longer) where the fit has no super-blocks."""

    def __init__(self, case, end, script="plotResults"):
        self.fit = latest_fit(case)
        if self.fit["errors"] != "jackknife":
            note = self.fit.get("superBlocksNote", "no superBlocks entry in system/fitSlipLengthDict")
            sys.exit(f"{script}: {case}: no super-blocks ({note}): run longer")
        self.per, self.m = int(self.fit["blocksPerSuperBlock"]), int(self.fit["superBlocks"])
        self.length = float(self.fit["superBlockLength"])
        self.start, self.end = end - self.m * self.length, end

    def index(self, times, closed=True):
        """Each time's super-block (block_index), -1 outside the window."""
        return block_index(times, self.start, self.length, self.m, closed)

    def rows(self, rows, closed=True):
        """The rows (first column: time) within the window and their super-blocks (rows_in_blocks)."""
        return rows_in_blocks(rows, self.start, self.length, self.m, closed)

    def mean(self, values, index):
        """The BlockMean of values over the super-blocks (index: each value's, -1 leaves it out)."""
        return BlockMean(block_means(values, index, self.m))

    def column_means(self, rows, columns, closed=True):
        """The BlockMean of each of a table's columns (first column: time) over the window."""
        index = self.index(rows[:, 0], closed)
        return [self.mean(rows[:, column], index) for column in columns]


def run_report(path, value_pattern):
    """A solver log's particles ('Particles : N (M mobile'), run_finished and log_series; 0, NaN, ([], []) without it."""
    if not os.path.exists(path):
        return 0, (float("nan"),) * 3, ([], [])
    text = read_text(path)
    particles = re.search(r"Particles\s*:\s*(\d+)\s*\((\d+) mobile", text)
    return int(particles.group(1)) if particles else 0, run_finished(text), log_series(text, value_pattern)
