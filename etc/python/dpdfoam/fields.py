"""Fields on an x-z grid of bins (a profileBins table with x and z columns, flowField.dat): the table as
2-D arrays, a continuum solver's cells gathered into the same bins, the relative L2 of one field against
another with its noise, a DPD field beside its continuum twin on the same bins (TwinBins) and the two
compared per class of a bin's measure (pore size, distance to the solid), the bins' temperature with the
flow's share of it beside the solver log's kT series (FlowTemperature), and compareFVM's comparison as
lines of a results file."""
import numpy as np

from .io import foam_latest_time, foam_vector_field, read_table
from .stats import mean_and_error

CLASS_COLUMNS = "lo hi bins L2 noiseL2 meanRatio uFVMmean densityWholeBins"


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
    inside = (column >= 0) & (column < len(xs)) & (row >= 0) & (row < len(zs))  # as BinLayout::binOf: -1 outside
    row, column, values = row[inside], column[inside], np.asarray(values)[inside]
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


class TwinBins:
    """A DPD x-z field on its bins (read_grid: xs, zs, grid) beside its continuum twin gathered into the same
    bins (foam_on_bins): the bins compared (those of the mask `fluid` where the twin has cells), the bins
    wholly fluid in the twin (each of its cells there fluid), the interior ones (compared and wholly fluid),
    and those the maps show (at least `shown` times the median count of the bins holding particles)."""

    def __init__(self, xs, zs, grid, fluid, case="simpleFoam", shown=0.25):
        self.xs, self.zs, self.grid = xs, zs, grid
        self.ufx, self.ufz, cells = foam_on_bins(case, xs, zs)
        self.wholly_fluid = cells / cells.max() == 1
        self.compared = fluid & np.isfinite(self.ufx)
        self.interior = self.compared & self.wholly_fluid
        count = grid["count"]
        self.shown = count >= shown * np.median(count[count > 0])

    def dpd_speed(self):
        """DPD |u| on the bins shown (NaN elsewhere)."""
        return np.where(self.shown, np.hypot(self.grid["ux"], self.grid["uz"]), np.nan)

    def twin_speed(self):
        """The twin's |u| on the bins."""
        return np.hypot(self.ufx, self.ufz)

    def difference(self):
        """DPD ux - the twin's on the bins compared and shown (NaN elsewhere)."""
        return np.where(self.compared & self.shown, self.grid["ux"] - self.ufx, np.nan)

    def interior_l2(self):
        """relative_l2 of DPD ux against the twin's over the interior bins."""
        return relative_l2(self.grid["ux"][self.interior], self.ufx[self.interior], self.grid["uxErr"][self.interior])

    def region_means(self, region):
        """Over a region of bins: the mean DPD and twin ux, the DPD mean's standard error and the bins."""
        se = np.sqrt(np.mean(self.grid["uxErr"][region] ** 2) / region.sum())
        return dict(dpd=self.grid["ux"][region].mean(), fvm=self.ufx[region].mean(), se=se, bins=region.sum())

    def class_table(self, key, edges):
        """class_table over the bins compared, by classes (edges) of key (per bin), density over the interior."""
        c = self.compared
        return class_table(key[c], edges, self.grid["ux"][c], self.ufx[c], self.grid["uxErr"][c],
                           self.grid["density"][c], self.wholly_fluid[c])


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


def class_table(key, edges, ud, uf, err, rho, whole):
    """Per class of key: bins, L2, noise L2, flow ratio DPD/FVM, mean FVM velocity, and the mean DPD
    density of the class's bins that lie wholly in the fluid (whole; nan where none do): a throat the
    walls' repulsion reaches across is depleted, which the continuum does not know."""
    rows = []
    for lo, hi in zip(edges[:-1], edges[1:]):
        sel = (key >= lo) & (key < hi) & np.isfinite(uf) & np.isfinite(ud)
        if sel.sum() < 3:
            continue
        l2, noise = relative_l2(ud[sel], uf[sel], err[sel])
        dense = sel & whole
        density = rho[dense].mean() if dense.any() else float("nan")
        rows.append((lo, hi, int(sel.sum()), l2, noise, ud[sel].sum() / uf[sel].sum(), uf[sel].mean(), density))
    return rows


def class_lines(name, rows):
    """class_table's rows as results lines, each starting with name (columns CLASS_COLUMNS)."""
    return [f"{name} {r[0]:g} {r[1]:g} {r[2]} {r[3]:.4f} {r[4]:.4f} {r[5]:.4f} {r[6]:.5f} {r[7]:.3f}" for r in rows]


def compare_summary(cmp, lines):
    """compareFVM's comparison (read_compare) as results lines: each line's L2, then over the field the mean
    velocity ratio, the superficial velocities and the Darcy permeabilities."""
    return [f"{'L2' + name:<18} {line['L2']:.5f}  (noise {line['noiseL2']:.5f}; Linf {line['Linf']:.4f}; mean ratio "
            f"{line['meanVelocityRatio']:.4f})" for name, line in lines.items()] + [
        f"meanVelocityRatio  {cmp['meanVelocityRatio']:.5f}  (DPD {cmp['meanVelocityDPD']:.5f}, simpleFoam "
        f"{cmp['meanVelocityFVM']:.5f})",
        f"superficialVelocity DPD {cmp['superficialVelocityDPD']:.6f} +- {cmp['superficialVelocityDPDErr']:.6f}  "
        f"simpleFoam {cmp['superficialVelocityFVM']:.6f}",
        f"permeabilityDPD    {cmp['permeabilityDPD']:.5f} +- {cmp['permeabilityDPDErr']:.5f}",
        f"permeabilityFVM    {cmp['permeabilityFVM']:.5f}\npermeabilityRatio  {cmp['permeabilityRatio']:.5f}"]


class FlowTemperature:
    """A flow's kT on its x-z bins and in the solver's log: the bins' kT and the flow's part (bin_temperatures
    over the fluid bins), the log's series (times, kts: arrays) with its mean and standard error from
    `start` (stats.mean_and_error: the reports taken as independent) and its largest deviation from the set
    kT 1 over the whole run."""

    def __init__(self, grid, fluid, times, kts, start):
        self.bins, self.flow = bin_temperatures(grid, fluid)
        self.times, self.series, self.start = times, kts, start
        self.mean, self.error = mean_and_error(kts[times >= start])
        self.worst = int(np.argmax(np.abs(kts - 1.0)))

    def lines(self):
        """The results lines kTSeries, kTLog, kTFlowPart, kTBins and kTMaxDeviation."""
        worst = self.worst
        return [
            "kTSeries           (" + " ".join(f"{t:g}:{k:.4f}" for t, k in zip(self.times, self.series)) + ")",
            f"kTLog              {self.mean:.5f} +- {self.error:.5f}  (mean of the series from t = {self.start:g})",
            f"kTFlowPart         {self.flow:.5f}  (flow's kinetic energy per degree of freedom, from the bins: what a "
            "global mean would add)",
            f"kTBins             {self.bins:.5f}",
            f"kTMaxDeviation     {self.series[worst] - 1:+.5f}  (largest of the log's {len(self.series)} reports over "
            f"the run, at t = {self.times[worst]:g})"]
