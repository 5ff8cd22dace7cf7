"""The Poiseuille channel between lattice walls (.) and random equilibrated walls from a mask
(randomMask/) and a gmsh file (randomGmsh/): fits with honest error bars, the profile differences and
the density at each wall type. Used by plotResults.py.

Why the sampling blocks are not enough for error bars: the bin velocities of a channel fluctuate
with its transverse momentum modes, the slowest of which decays in tau1 = d^2 / (pi^2 nu) (37 time
units for d = 10, 600 for d = 40) and carries most of the variance of a time average. The blocks the
run samples in (25 time units) are shorter than that, so their spread underestimates the error of
the mean. Here consecutive blocks are joined into super-blocks of twice tau1 (to the nearest
sampling block; the test's 25 make 75 for 2 tau1 = 75.2); for an
exponentially correlated signal, neighbouring means of blocks 2 tau1 long are correlated by about
0.3, so the variance of the mean is still underestimated by ~25 % for the slowest mode and much less
for the faster ones, which carry the rest (~10 % on the variance, 5 % on the errors, in all).
  - nu and the slip lengths: jackknife over the super-blocks (each left out in turn, the profile
    refitted as fitSlipLength fits it);
  - the per-bin errors: the profileBins error times sqrt(s), s the ratio of the super-block variance
    of the bin means to the sampling-block one, pooled over the bins of the fit range (one number per
    run: per bin, M super-blocks would give errors too noisy for a chi^2).
"""
import glob
import math
import os

import numpy as np

from dpdResults import latest, read_blocks, read_dict, read_table

# Super-blocks this many slowest-mode decay times long, and at least this many of them.
SUPER_BLOCK_TAUS = 2.0
MIN_SUPER_BLOCKS = 5


def latest_sampling(case, name):
    """The latest <case>/<time>/sampling/<name>.h5."""
    paths = glob.glob(os.path.join(case, "*", "sampling", name + ".h5"))
    if not paths:
        raise SystemExit(f"plotResults: no {case}/<time>/sampling/{name}.h5")
    return max(paths, key=lambda p: float(p.split(os.sep)[-3]))


def fit_parabola(z, u, sigma, walls, exclude, g):
    """nu and the slip lengths (lower, upper) of the weighted parabola fitted to the bins at least
    `exclude` from the walls, as fitSlipLength fits them (slip = u / du/dn at the wall)."""
    lo, hi = walls
    sel = (z >= lo + exclude) & (z <= hi - exclude)
    c2, c1, c0 = np.polyfit(z[sel], u[sel], 2, w=1.0 / sigma[sel])
    value = lambda x: c0 + c1 * x + c2 * x * x  # noqa: E731
    slope = lambda x: c1 + 2.0 * c2 * x  # noqa: E731
    return np.array([-g / (2.0 * c2), value(lo) / slope(lo), -value(hi) / slope(hi)])


class WallRun:
    """One channel: its profile table, fit, sampled blocks and the long-block statistics."""

    def __init__(self, label, case, profile, sample_time, tau1):
        self.label, self.case = label, case
        self.table = read_table(latest(os.path.join(case, "postProcessing/profileBins/*", profile + ".dat")))
        self.fit = read_dict(latest(os.path.join(case, "postProcessing/fitSlipLength/*/fit.dat")))
        self.walls = tuple(self.fit["wallPosition"])
        self.exclude = self.fit["exclude"]
        self.g = self.fit["g"]
        z = self.table["z"]
        self.fitted = (z >= self.walls[0] + self.exclude) & (z <= self.walls[1] - self.exclude)
        blocks = read_blocks(latest_sampling(case, profile))
        block_time = blocks["blockSamples"] * sample_time
        per = max(1, round(SUPER_BLOCK_TAUS * tau1 / block_time))  # to the nearest sampling block
        self.super_blocks = len(blocks["count"]) // per
        self.super_block_time = per * block_time
        self.too_short = ""
        if self.super_blocks < MIN_SUPER_BLOCKS:
            # No honest error bars: fitSlipLength's own (short-block) errors, and no verdict.
            self.too_short = (f"{case} sampled {len(blocks['count'])} blocks of {block_time:g}: fewer than "
                              f"{MIN_SUPER_BLOCKS} super-blocks of {SUPER_BLOCK_TAUS:g} tau1 = {SUPER_BLOCK_TAUS * tau1:.0f}")
            self.jackknife_error = np.array([self.fit["nuError"]] + list(self.fit["slipLengthError"]))
            self.inefficiency, self.ux_error = 1.0, self.table["uxErr"]
            return
        # The last super_blocks * per blocks (the earliest, closest to the start, are left out).
        used = slice(len(blocks["count"]) - self.super_blocks * per, None)
        count = blocks["count"][used].reshape(self.super_blocks, per, -1)
        sum_u = blocks["sumU"][used, :, 0].reshape(self.super_blocks, per, -1)
        self._statistics(count, sum_u)

    def _statistics(self, count, sum_u):
        m = self.super_blocks
        sigma = np.where(self.table["uxErr"] > 0, self.table["uxErr"], np.inf)
        z = self.table["z"]
        # Jackknife of the fit over the super-blocks.
        total_c, total_s = count.sum(axis=(0, 1)), sum_u.sum(axis=(0, 1))
        c_k, s_k = count.sum(axis=1), sum_u.sum(axis=1)
        with np.errstate(invalid="ignore", divide="ignore"):
            leave_out = [fit_parabola(z, (total_s - s_k[k]) / (total_c - c_k[k]), sigma, self.walls, self.exclude, self.g)
                         for k in range(m)]
            self.jackknife_error = np.sqrt((m - 1) / m * np.sum((leave_out - np.mean(leave_out, axis=0)) ** 2, axis=0))
            # Variance of the mean of each bin: from the super-blocks, and from the sampling blocks.
            u_super = s_k / c_k
            short_c, short_s = count.reshape(-1, count.shape[2]), sum_u.reshape(-1, sum_u.shape[2])
            u_short = short_s / short_c
        var_super = np.var(u_super, axis=0, ddof=1) / m
        var_short = np.var(u_short, axis=0, ddof=1) / len(u_short)
        sel = self.fitted & np.isfinite(var_super) & np.isfinite(var_short)
        self.inefficiency = np.sum(var_super[sel]) / np.sum(var_short[sel])
        self.ux_error = self.table["uxErr"] * math.sqrt(self.inefficiency)
        # Normalised super-block deviations of the bin means (for the bins' correlation).
        dev = u_super - u_super.mean(axis=0)
        self.deviations = dev[:, self.fitted] / np.std(u_super[:, self.fitted], axis=0, ddof=1)

    def values(self):
        """nu, slip lower, slip upper (fitSlipLength's) and their jackknife errors."""
        slip = self.fit["slipLength"]
        return np.array([self.fit["nu"], slip[0], slip[1]]), self.jackknife_error

    def near_wall_density(self, cutoff):
        """Mean density within one cutoff of each wall and the lowest bin there, relative to the
        density of the central half."""
        z, rho = self.table["z"], self.table["density"]
        lo, hi = self.walls
        centre = np.abs(z - 0.5 * (lo + hi)) < 0.25 * (hi - lo)
        bulk = np.mean(rho[centre])
        out = []
        for near in ((z > lo) & (z < lo + cutoff), (z < hi) & (z > hi - cutoff)):
            out.append((np.mean(rho[near]) / bulk, np.min(rho[near]) / bulk))
        return bulk, out


def effective_dof(runs, n):
    """n^2 / sum_ij R_ij^2: the number of independent bins the fit range holds, with R the bins'
    correlation pooled over the runs' super-blocks (off-diagonal R^2 less its noise 1/N)."""
    dev = np.vstack([r.deviations for r in runs])
    samples = sum(r.super_blocks - 1 for r in runs)
    corr = dev.T @ dev / samples
    off = corr ** 2 - np.diag(np.diag(corr) ** 2)
    off = np.clip(off - 1.0 / samples, 0.0, None)
    return n * n / (n + np.sum(off))


def chi2_bounds(dof, z=3.0):
    """Two-sided z-sigma bounds of chi^2_dof / dof (Wilson-Hilferty)."""
    a = 2.0 / (9.0 * dof)
    return tuple((1.0 - a + s * z * math.sqrt(a)) ** 3 for s in (-1.0, 1.0))


def profile_chi2(a, b):
    """chi^2 / dof of the difference of two profiles over the bins both fit."""
    sel = a.fitted & b.fitted
    d = a.table["ux"][sel] - b.table["ux"][sel]
    var = a.ux_error[sel] ** 2 + b.ux_error[sel] ** 2
    return np.sum(d * d / var) / np.count_nonzero(sel), np.count_nonzero(sel)


def student_t(z, dof):
    """The Student-t quantile with the tail probability of z normal standard deviations
    (Abramowitz and Stegun 26.7.5, good to ~1 % for dof >= 4): the allowance for error bars that are
    themselves estimated from few blocks."""
    g1 = (z ** 3 + z) / 4
    g2 = (5 * z ** 5 + 16 * z ** 3 + 3 * z) / 96
    g3 = (3 * z ** 7 + 19 * z ** 5 + 17 * z ** 3 - 15 * z) / 384
    g4 = (79 * z ** 9 + 776 * z ** 7 + 1482 * z ** 5 - 1920 * z ** 3 - 945 * z) / 92160
    return z + g1 / dof + g2 / dof ** 2 + g3 / dof ** 3 + g4 / dof ** 4


def agreement(a, b, k, z=3.0):
    """Difference of quantity k between runs a and b, its combined error, and the allowed deviation:
    z standard errors, widened to the Student-t quantile of the same tail probability for the
    errors' Welch-Satterthwaite degrees of freedom (each jackknife error has super_blocks - 1)."""
    va, ea = a.values()
    vb, eb = b.values()
    sigma = math.hypot(ea[k], eb[k])
    dof = sigma ** 4 / (ea[k] ** 4 / (a.super_blocks - 1) + eb[k] ** 4 / (b.super_blocks - 1))
    return va[k] - vb[k], sigma, student_t(z, dof) * sigma
