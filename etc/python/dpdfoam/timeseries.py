"""Time series of a run (one row per time: snapshots' measures, chain statistics, the log's reports) as
super-block means: the window [start, start + m length) split into m super-blocks of `length` time
units, the same as a profile's (fitSlipLength's superBlocks), so that every mean's error is the spread
of its m super-block means (docs/analysis.md 5.2)."""
import re
import warnings

import numpy as np

from .io import log_values


def block_index(times, start, length, m, closed=True):
    """Each time's super-block, 0 to m - 1, or -1 outside the window. closed: a time at the window's end
    (a snapshot written at endTime) counts in the last super-block."""
    k = np.floor((np.asarray(times, dtype=float) - start) / length).astype(int)
    if closed:
        k = np.minimum(k, m - 1)
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
