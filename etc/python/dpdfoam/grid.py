"""A 2-D binnedProfile's table (profileBins: one row per bin, its two coordinates, density, velocity, kT,
..., count) averaged along one axis, its count-weighted means over a region, and a column as an image."""
import numpy as np


def averaged_along(table, along="x", across="z", weighted=("ux", "kT")):
    """The table averaged along `along`, per bin across: the density (the mean over the bins along),
    the weighted columns (weighted by the particle-samples), the count (their sum), and "n<along>"
    (how many bins along)."""
    positions = np.unique(table[across])
    rows = [table[across] == p for p in positions]
    count = np.array([table["count"][r].sum() for r in rows])
    out = {across: positions, "count": count, "density": np.array([table["density"][r].mean() for r in rows]),
           "n" + along: len(np.unique(table[along]))}
    with np.errstate(invalid="ignore", divide="ignore"):
        for name in weighted:
            out[name] = np.array([np.nansum(table[name][r] * table["count"][r]) for r in rows]) / count
    return out


def weighted_mean(values, weights, region=slice(None)):
    """The weighted mean of values over a region (a mask or an index; all by default), empty bins' NaN
    left out of the sum."""
    return float(np.nansum((values * weights)[region]) / weights[region].sum())


def image(table, column, rows="z", columns="x"):
    """A column of the table as a 2-D array (rows along `rows`; NaN where the table has no bin) and its
    extent for imshow (the outer bins' edges)."""
    ys, xs = np.unique(table[rows]), np.unique(table[columns])
    grid = np.full((len(ys), len(xs)), np.nan)
    grid[np.searchsorted(ys, table[rows]), np.searchsorted(xs, table[columns])] = table[column]
    dy, dx = ys[1] - ys[0], xs[1] - xs[0]
    return grid, [xs[0] - 0.5 * dx, xs[-1] + 0.5 * dx, ys[0] - 0.5 * dy, ys[-1] + 0.5 * dy]
