"""Fields on an x-z grid of bins (a profileBins table with x and z columns, flowField.dat): the table as
2-D arrays, a continuum solver's cells gathered into the same bins, the relative L2 of one field against
another with its noise, and the bins' temperature with the flow's share of it."""
import numpy as np

from .io import foam_latest_time, foam_vector_field, read_table


def read_grid(path):
    """An x-z profile table as 2-D arrays (rows z, columns x): (bin centres x, bin centres z, {column: array})."""
    table = read_table(path)
    xs, zs = np.unique(table["x"]), np.unique(table["z"])
    return xs, zs, {name: column.reshape(len(zs), len(xs)) for name, column in table.items()}


def extent(xs, zs):
    """imshow's extent of the bins centred on xs and zs (their outer edges)."""
    hx, hz = (xs[1] - xs[0]) / 2, (zs[1] - zs[0]) / 2
    return [xs[0] - hx, xs[-1] + hx, zs[0] - hz, zs[-1] + hz]


def cells_on_bins(points, values, xs, zs):
    """The mean of values (one per cell) over the cells whose centres (points, (n, 3)) fall in each x-z
    bin centred on xs and zs (NaN where none does), and the number of cells in each bin."""
    wx, wz = xs[1] - xs[0], zs[1] - zs[0]
    column = np.floor((points[:, 0] - (xs[0] - wx / 2)) / wx).astype(int)
    row = np.floor((points[:, 2] - (zs[0] - wz / 2)) / wz).astype(int)
    n, total = np.zeros((len(zs), len(xs))), np.zeros((len(zs), len(xs)))
    np.add.at(n, (row, column), 1)
    np.add.at(total, (row, column), values)
    return np.where(n > 0, total / np.maximum(n, 1), np.nan), n


def foam_on_bins(case, xs, zs, field="U"):
    """An OpenFOAM case's latest vector field (ascii) gathered into the x-z bins: the means of its x and
    z components (cells_on_bins) and the number of cells in each bin (a mesh with its solid cells cut
    out: n / n.max() is the share of a bin that is fluid)."""
    t = foam_latest_time(case)
    centres, vectors = foam_vector_field(f"{case}/{t}/C"), foam_vector_field(f"{case}/{t}/{field}")
    ux, n = cells_on_bins(centres, vectors[:, 0], xs, zs)
    uz, _ = cells_on_bins(centres, vectors[:, 2], xs, zs)
    return ux, uz, n


def relative_l2(u, reference, error):
    """The relative L2 norm of u - reference, and that of u's standard errors (the first's noise floor)."""
    scale = np.sum(reference ** 2)
    return np.sqrt(np.sum((u - reference) ** 2) / scale), np.sqrt(np.sum(error ** 2) / scale)


def bin_temperatures(grid, fluid):
    """The count-weighted kT of the fluid bins (each bin's about its own mean velocity), and the flow's
    kinetic energy per degree of freedom over all bins about their mean velocity (what a kT about one
    global mean velocity would add)."""
    count = grid["count"]
    kT_bins = np.sum(grid["kT"][fluid] * count[fluid]) / np.sum(count[fluid])
    w = count / count.sum()
    mean_u = [np.sum(w * grid[c]) for c in ("ux", "uy", "uz")]
    flow_kT = sum(np.sum(w * (grid[c] - m) ** 2) for c, m in zip(("ux", "uy", "uz"), mean_u)) / 3
    return kT_bins, flow_kT
