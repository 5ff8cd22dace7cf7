"""Channel runs side by side: runSweep's sweeps of a wall parameter (tutorials/channel/couetteSlip,
slipGammaFw: the named variant, each run's slip, the published comparison, the slip's trend, the
profiles' pictures), the profiles' common measures near the walls, and channels compared with long-block
errors (tutorials/channel/poiseuille/latticeWall: LongBlockRun).

    flag, suffix = variant_of(sys.argv, ["-noSlipWall"])           # the named variant, its outputs' suffix
    sweep, a_ww, b, b_err = sweep_slip("sweep/sweep.dat", "pairCoeffs/wall-wall/a")
    comparison = published_comparison(table, "a_ww", a_ww, b, b_err)  # issue 25's bound
"""
import math
import os

import numpy as np

from .blocks import SampledBins
from .channel import walls_mean_slip
from .checks import as_number
from .io import latest_fit, latest_profile, latest_sampling, read_sweep
from .plots import plt
from .published import compare_with_published
from .stats import combined

# Issue 25's bound on a published point: max(0.3 r_c, 30 %) of the published slip length (published_checks
# decides it only when the measured error is within a third of it; the papers state no errors).
PUBLISHED_ABSOLUTE, PUBLISHED_RELATIVE = 0.3, 0.30


# ---- runSweep's sweeps -------------------------------------------------------------------------------


def variant_of(argv, flags):
    """The first of flags (-noSlipWall) on the command line, or None, and its outputs' suffix (NoSlipWall,
    "" for none)."""
    flag = next((a for a in argv[1:] if a in flags), None)
    return flag, (flag[1].upper() + flag[2:] if flag else "")


def sweep_slip(path, key):
    """runSweep's table, the swept entry's values and the slip length of the mean of the walls with its
    standard error."""
    sweep = read_sweep(path)
    return (sweep, sweep[key]) + walls_mean_slip(sweep)


def per_wall(sweep, column):
    """A sweep's column of each wall (<column>_0, <column>_1) as rows (lower, upper), one per run."""
    return np.vstack([sweep[f"{column}_0"], sweep[f"{column}_1"]]).T


def published_comparison(table, key, keys, b, err, cutoff=1.0):
    """compare_with_published with issue 25's bound on the slip length, max(0.3 r_c, 30 %)."""
    return compare_with_published(table, key, keys, b, err, absolute=PUBLISHED_ABSOLUTE * cutoff,
                                  relative=PUBLISHED_RELATIVE)


def accounted_by(ingredient, how, path, key, compare):
    """published_checks' `accounted`: the named variant that changes `ingredient` (its runSweep table at
    path, swept over key) compared with the paper by compare(keys, b, err); no rows when it has not run
    (the check then says `how` to run it)."""
    if not os.path.exists(path):
        return ingredient, [], how
    return ingredient, compare(*sweep_slip(path, key)[1:]), how


def comparison_line(row):
    """A compare_with_published row as a results line: the key, measured +- error, published, the
    difference and the difference in standard errors."""
    x, b, e, p = row[:4]
    return f"published {x:5g}  {b:+.4f} +- {e:.4f}   {p:.4f}   {b - p:+.4f}  ({(b - p) / e:+.1f})"


def published_lines(published, comparison, headers, note="", extra=lambda row: ""):
    """A comparison with the paper's Table 1 as results lines: the paper (note ends its line), the header
    lines, then each point's comparison_line with extra(row) after it."""
    return ([f"# published: {published['source']}, Table 1 (no errors stated: differences in units of this run's "
             f"error){note}"] + list(headers) + [comparison_line(row) + extra(row) for row in comparison])


def slip_falls_checks(checks, label, parameter, values, b, err, step_budget, rise_budget):
    """Slip grows as the swept parameter falls (issue 45). No step down in the parameter may lower the
    slip length by more than 3 step budgets (a real reversal); over the whole range the rise must exceed
    3 rise budgets (decisive); each first with its standard error below its budget. Neighbouring steps
    may differ by less than their errors: their sign alone is not a check."""
    values, b, err = (np.array([as_number(v) for v in x], dtype=float) for x in (values, b, err))
    if len(values) < 2 or len(b) != len(values) or len(err) != len(values):
        checks.fail(f"{label}: slip length against {parameter}: {len(values)} {parameter}, {len(b)} slip lengths, "
                    f"{len(err)} errors (two runs at least, each with its slip and error)")
        return
    order = np.argsort(values)
    for lo, hi in zip(order[:-1], order[1:]):
        step, se = b[lo] - b[hi], math.hypot(err[lo], err[hi])
        checks.bounded(f"{label}: slip length not smaller at {parameter} {values[lo]:g} than at {values[hi]:g} by more "
                       f"than 3 x {step_budget:g} (standard error below {step_budget:g})", step, se, step_budget,
                       lower=-3 * step_budget)
    lo, hi = order[0], order[-1]
    rise, se = b[lo] - b[hi], math.hypot(err[lo], err[hi])
    checks.bounded(f"{label}: slip length larger at {parameter} {values[lo]:g} than at {values[hi]:g} by more than "
                   f"3 x {rise_budget:g} (standard error below {rise_budget:g})", rise, se, rise_budget,
                   lower=3 * rise_budget)


def sweep_colours(n):
    """One colour per run of a sweep, along viridis."""
    return plt.cm.viridis(np.linspace(0, 0.9, n))


def draw_profiles(ax, profiles, names, column="ux", errors=True):
    """A column of each run's profile against z, one colour per run: points with their error bars
    (<column>Err), or lines."""
    for prof, name, colour in zip(profiles, names, sweep_colours(len(profiles))):
        if errors:
            ax.errorbar(prof["z"], prof[column], yerr=prof[column + "Err"], fmt="o", ms=2, color=colour, label=name)
        else:
            ax.plot(prof["z"], prof[column], "-", color=colour, label=name)


def draw_near_walls(ax, profiles, names, walls, column="density"):
    """A column of each run's profile against the distance from the wall, one colour per run: solid at
    the lower wall, dashed at the upper."""
    for prof, name, colour in zip(profiles, names, sweep_colours(len(profiles))):
        z = prof["z"]
        near = wall_distance(z, walls)
        order = np.argsort(near)
        lower = z < 0.5 * (walls[0] + walls[1])
        for side, style in ((lower, "-"), (~lower, "--")):
            o = order[side[order]]
            ax.plot(near[o], prof[column][o], style, color=colour, label=name if style == "-" else None)


# ---- A channel's profile near its walls --------------------------------------------------------------


def wall_distance(z, walls):
    """Each bin's distance from the nearer wall."""
    return np.minimum(z - walls[0], walls[1] - z)


def near_both_walls(z, values, walls, reach):
    """The bins within reach of either wall, the lower wall's first: their distance from it and values."""
    dist = np.concatenate([z - walls[0], walls[1] - z])
    near = dist < reach
    return dist[near], np.concatenate([values, values])[near]


def central_density(prof, walls):
    """The mean density over the channel's central half (the bulk the walls are held to)."""
    z = prof["z"]
    return np.mean(prof["density"][np.abs(z - 0.5 * (walls[0] + walls[1])) < 0.25 * (walls[1] - walls[0])])


def wall_depletion(prof, walls, cutoff=1.0):
    """The gap at the walls: the fluid missing within one cutoff of a wall, as a width (the integral of
    max(0, 1 - rho / rho_centre) dz over the bins there, mean of the two walls), and its standard error
    from the bins' density errors (those bins' and the centre's in quadrature)."""
    z, rho, err = prof["z"], prof["density"], prof["densityErr"]
    dz, centre = z[1] - z[0], np.abs(z - 0.5 * (walls[0] + walls[1])) < 0.25 * (walls[1] - walls[0])
    rho_c, rho_c_err = np.mean(rho[centre]), np.sqrt(np.sum(err[centre] ** 2)) / centre.sum()
    near = (wall_distance(z, walls) < cutoff) & (rho < rho_c)
    gap = 0.5 * dz * np.sum(1.0 - rho[near] / rho_c)
    by_centre = 0.5 * dz * np.sum(rho[near]) / rho_c ** 2
    return gap, float(np.hypot(0.5 * dz / rho_c * np.sqrt(np.sum(err[near] ** 2)), by_centre * rho_c_err))


def slab_means(z, values, errors, low, high, width):
    """Means (and standard errors) of a profile over slabs of the given width from low to high."""
    means, errs = [], []
    for a in np.arange(low, high - 1e-9, width):
        sel = (z > a) & (z < a + width)
        if sel.any():
            means.append(np.mean(values[sel]))
            errs.append(math.sqrt(np.sum(errors[sel] ** 2)) / sel.sum())
    return np.array(means), np.array(errs)


def weighted_error(count, errors):
    """The standard error of a count-weighted mean of bins with independent errors."""
    return np.sqrt(np.sum((count * errors) ** 2)) / np.sum(count)


def kT_over_no_wall(prof, bulk, centre, g, nu, kT_of_shear):
    """The channel's kT minus the box's without walls at the same local shear rate g |z - centre| / nu
    (channel.no_wall_reference's kT_of_shear), count-weighted over the bins of `bulk`."""
    kT_box = np.interp(g * np.abs(prof["z"] - centre) / nu, *kT_of_shear)
    return np.average(prof["kT"][bulk] - kT_box[bulk], weights=prof["count"][bulk])


def wall_layer_density(prof, walls, cutoff=1.0):
    """The mean density within cutoff of either wall over the central density (central_density)."""
    return np.mean(prof["density"][wall_distance(prof["z"], walls) < cutoff]) / central_density(prof, walls)


def first_bins_density(prof, walls):
    """The density of the bin nearest each wall, the two walls' mean, over the central density."""
    z, centre = prof["z"], 0.5 * (walls[0] + walls[1])
    dist = wall_distance(z, walls)
    first = [prof["density"][np.argmin(np.where(side, dist, np.inf))] for side in (z < centre, z > centre)]
    return np.mean(first) / central_density(prof, walls)


def wall_layer_kT(prof, walls, cutoff=1.0):
    """kT within cutoff of either wall, count-weighted (a bin without particles reads kT 0)."""
    near = wall_distance(prof["z"], walls) < cutoff
    return np.average(prof["kT"][near], weights=prof["count"][near])


def density_flatness(prof, walls, cutoff=1.0):
    """The largest relative deviation of the density from its mean over the bins beyond cutoff of the walls."""
    rho = prof["density"][wall_distance(prof["z"], walls) > cutoff]
    return np.max(np.abs(rho / np.mean(rho) - 1.0))


# ---- Channels compared with long-block errors --------------------------------------------------------


class LongBlockRun:
    """One channel run with errors over super-blocks: its profile table, fit, and the bins' long-block
    statistics.

    fitSlipLength's sampling blocks are not enough for error bars: the bin velocities of a channel
    fluctuate with its transverse momentum modes, the slowest of which decays in tau1 = d^2 / (pi^2 nu)
    and carries most of the variance of a time average; blocks shorter than that underestimate the error
    of the mean. Consecutive blocks are joined into super-blocks of about twice tau1 (the superBlocks entry
    of system/fitSlipLengthDict, which fit.dat reports); for an exponentially correlated signal,
    neighbouring means of blocks 2 tau1 long are correlated by about 0.3, so the variance of the mean is
    still underestimated by ~25 % for the slowest mode and much less for the faster ones, which carry the
    rest (~10 % on the variance, 5 % on the errors, in all).
      - nu and the slip lengths: fitSlipLength's jackknife over the super-blocks (each left out in turn,
        the profile refitted);
      - the per-bin errors: the profileBins error times sqrt(s), s the ratio of the super-block variance
        of the bin means to the sampling-block one, pooled over the bins of the fit range (one number per
        run: per bin, M super-blocks would give errors too noisy for a chi^2).
    Without the jackknife (too few super-blocks) .too_short says why, and the errors are fitSlipLength's.
    """

    def __init__(self, label, case, profile):
        self.label, self.case = label, case
        self.table, self.fit = latest_profile(case, profile), latest_fit(case)
        self.walls = tuple(self.fit["wallPosition"])
        z, exclude = self.table["z"], self.fit["exclude"]
        self.fitted = (z >= self.walls[0] + exclude) & (z <= self.walls[1] - exclude)
        self.too_short = ""
        if self.fit["errors"] != "jackknife":
            # No honest error bars: fitSlipLength's (short-block) errors, and no verdict.
            self.too_short = f"{case}: {self.fit.get('superBlocksNote', 'no superBlocks entry in system/fitSlipLengthDict')}"
            self.super_blocks, self.inefficiency, self.ux_error = 0, 1.0, self.table["uxErr"]
            return
        self.super_blocks, self.super_block_time = int(self.fit["superBlocks"]), float(self.fit["superBlockLength"])
        # The super-blocks of the fit: the last superBlocks x blocksPerSuperBlock sampling blocks.
        used = SampledBins(latest_sampling(case, profile)).latest(int(self.fit["blocksPerSuperBlock"]), self.super_blocks)
        self._bin_statistics(used[..., 0], used[..., 1])

    def _bin_statistics(self, count, sum_u):
        m = self.super_blocks
        c_k, s_k = count.sum(axis=1), sum_u.sum(axis=1)
        # Variance of the mean of each bin: from the super-blocks, and from the sampling blocks.
        with np.errstate(invalid="ignore", divide="ignore"):
            u_super = s_k / c_k
            u_short = sum_u.reshape(-1, sum_u.shape[2]) / count.reshape(-1, count.shape[2])
        var_super = np.var(u_super, axis=0, ddof=1) / m
        var_short = np.var(u_short, axis=0, ddof=1) / len(u_short)
        sel = self.fitted & np.isfinite(var_super) & np.isfinite(var_short)
        self.inefficiency = np.sum(var_super[sel]) / np.sum(var_short[sel])
        self.ux_error = self.table["uxErr"] * math.sqrt(self.inefficiency)
        # Normalised super-block deviations of the bin means (for the bins' correlation).
        dev = u_super - u_super.mean(axis=0)
        self.deviations = dev[:, self.fitted] / np.std(u_super[:, self.fitted], axis=0, ddof=1)

    def values(self):
        """nu, slip lower, slip upper and their errors (fitSlipLength's: the jackknife's, when it had
        the super-blocks)."""
        f = self.fit
        return (np.array([f["nu"], f["slipLength"][0], f["slipLength"][1]]),
                np.array([f["nuError"], f["slipLengthError"][0], f["slipLengthError"][1]]))

    def near_wall_density(self, cutoff):
        """Mean density within one cutoff of each wall and the lowest bin there, relative to the
        density of the central half."""
        z, rho = self.table["z"], self.table["density"]
        lo, hi = self.walls
        bulk = central_density(self.table, self.walls)
        nears = ((z > lo) & (z < lo + cutoff), (z < hi) & (z > hi - cutoff))
        return bulk, [(np.mean(rho[near]) / bulk, np.min(rho[near]) / bulk) for near in nears]


def long_block_lines(run, cutoff):
    """A LongBlockRun's results lines: nu and the slip lengths with their errors, the super-blocks and the
    bins' inefficiency; the bulk density and the density within one cutoff of each wall."""
    (v, e), (bulk, near) = run.values(), run.near_wall_density(cutoff)
    blocks = f"{run.super_blocks} super-blocks of {run.super_block_time:g}, " if run.super_blocks else ""
    return [f"{run.label:8s} nu {v[0]:.4f} +- {e[0]:.4f}  slip {v[1]:+.4f} +- {e[1]:.4f}  {v[2]:+.4f} +- {e[2]:.4f}  "
            f"({blocks}bin-error inefficiency s = {run.inefficiency:.2f})",
            f"{run.label:8s} density bulk {bulk:.4f}; within one cutoff of the lower / upper wall: mean "
            f"{near[0][0]:.3f} / {near[1][0]:.3f}, lowest bin {near[0][1]:.3f} / {near[1][1]:.3f} (x bulk)"]


def effective_dof(runs, n):
    """n^2 / sum_ij R_ij^2: the number of independent bins the fit range holds, with R the bins'
    correlation pooled over the runs' super-blocks (off-diagonal R^2 less its noise 1/N)."""
    dev = np.vstack([r.deviations for r in runs])
    samples = sum(r.super_blocks - 1 for r in runs)
    corr = dev.T @ dev / samples
    off = corr ** 2 - np.diag(np.diag(corr) ** 2)
    off = np.clip(off - 1.0 / samples, 0.0, None)
    return n * n / (n + np.sum(off))


def profile_chi2(a, b):
    """chi^2 / dof of the difference of two runs' velocity profiles over the bins both fit, and the bins."""
    sel = a.fitted & b.fitted
    d = a.table["ux"][sel] - b.table["ux"][sel]
    var = a.ux_error[sel] ** 2 + b.ux_error[sel] ** 2
    return np.sum(d * d / var) / np.count_nonzero(sel), np.count_nonzero(sel)


def agreement(a, b, k):
    """Difference of quantity k (LongBlockRun.values) between runs a and b, its combined error, and its
    Welch-Satterthwaite degrees of freedom (each jackknife error has super_blocks - 1)."""
    (va, ea), (vb, eb) = a.values(), b.values()
    sigma, _, dof = combined((ea[k], a.super_blocks - 1), (eb[k], b.super_blocks - 1))
    return va[k] - vb[k], sigma, dof
