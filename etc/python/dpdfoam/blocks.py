"""A 1-D binnedProfile's sampled blocks (<time>/sampling/<name>.h5) joined into super-blocks.

The sampling blocks of a channel (a few time units) are shorter than its slowest hydrodynamic mode
(tau1 = d^2 / (pi^2 nu)), so their spread underestimates the error of a mean: consecutive blocks are
joined into super-blocks about two tau1 long, the latest ones kept (docs/analysis.md 5.2). The sums
per bin follow sampling/BinProfile.cpp: particle-samples, sums of v (3), of v^2 (3), of x, x^2, and
of v x (3) along the bin's axis. Besides: the super-blocks' means over a region of bins (a mean
velocity, kT, a share of the particles within a band) and a channel's asymmetry u(z) - u(-z).
"""
import math
import sys

import h5py
import numpy as np

from .stats import BlockMean, count_weighted_mean


class SampledBins:
    """A 1-D binnedProfile's complete sampled blocks: .blocks (blocks, bins, sums), .z (bin centres),
    .width, .cross_section, .block_samples."""

    def __init__(self, path):
        with h5py.File(path, "r") as f:
            blocks = np.array(f["blocks"])
            samples = np.array(f["samplesPerBlock"])
            self.n = int(f.attrs["nBins"])
            self.lo, self.hi = float(f.attrs["lo"]), float(f.attrs["hi"])
            self.block_samples = int(f.attrs["blockSamples"])
            self.cross_section = float(f.attrs["crossSection"])
        self.blocks = blocks[samples == self.block_samples]
        self.width = (self.hi - self.lo) / self.n
        self.z = self.lo + self.width * (np.arange(self.n) + 0.5)

    def layout(self, block_time, length):
        """(blocks per super-block, super-blocks) for super-blocks of about `length` time units (to the
        nearest sampling block) from sampling blocks of block_time."""
        per = max(1, round(length / block_time))
        return per, len(self.blocks) // per

    def latest(self, per, m):
        """The last m * per sampling blocks, as (m, per, bins, sums)."""
        return self.blocks[len(self.blocks) - m * per:].reshape(m, per, self.n, self.blocks.shape[2])

    def super_blocks(self, per, m):
        """The sums over each of m super-blocks of `per` sampling blocks (the last m * per blocks), and
        the samples in a super-block."""
        return self.latest(per, m).sum(axis=1), per * self.block_samples

    def density(self, sums, samples):
        return sums[..., 0] / (samples * self.width * self.cross_section)


def temperature(sums):
    """kT per bin about a mean velocity varying linearly across the bin (sampling/BinProfile.cpp): the
    variances over the dimension, the y of a 2-D run left out (the solver holds its vy at 0: a bin whose
    sum of vy^2 is 0 is read as 2-D, as the file's dimension says)."""
    with np.errstate(invalid="ignore", divide="ignore"):
        n = sums[..., 0]
        mean_x = sums[..., 7] / n
        var_x = sums[..., 8] / n - mean_x ** 2
        total = 0.0
        for c in range(3):
            mean_v = sums[..., 1 + c] / n
            var_v = sums[..., 4 + c] / n - mean_v ** 2
            cov = sums[..., 9 + c] / n - mean_v * mean_x
            total = total + var_v - cov ** 2 / var_x
        return total / np.where(sums[..., 5] == 0.0, 2.0, 3.0)  # 2-D: the y term is 0


def region_mean(sums, weights, region):
    """Per super-block (rows), a sum over the region's bins over their weights' (a mass-weighted mean
    velocity: the sums of v over the particle-samples)."""
    return sums[:, region].sum(axis=1) / weights[:, region].sum(axis=1)


def region_temperature(sums, region):
    """kT of the region's bins, weighted by their particle-samples: per super-block of sums (blocks,
    bins, sums), or of the whole window from sums (bins, sums)."""
    return count_weighted_mean(temperature(sums)[..., region], sums[..., region, 0])


def overlap(z, width, lo, hi):
    """The share of each bin (centres z, width) that lies in [lo, hi]."""
    return np.clip((np.minimum(z + 0.5 * width, hi) - np.maximum(z - 0.5 * width, lo)) / width, 0.0, 1.0)


def band_share(count, z, width, lo, hi):
    """The share of the particle-samples (count along the last axis: per bin) within [lo, hi], the bins
    straddling an edge by the share of them inside."""
    return (count * overlap(z, width, lo, hi)).sum(axis=-1) / count.sum(axis=-1)


def mirror_asymmetry(z, centre, count, sum_u):
    """A channel's asymmetry from super-block sums (count, sum of u_x: (blocks, bins)) of bins symmetric
    about the centre: u(z) - u(-z) per mirrored pair ("z": the distance from the centre, "du", its
    standard error "err"), the two halves' mean velocities apart ("A" = U(upper) - U(lower), a
    BlockMean), chi^2 per pair against zero ("chi2", over "pairs"), and the pairs' rms ("rms"), the rms
    of their errors ("noise") and the largest ("max")."""
    n, m = len(z), count.shape[0]
    upper = np.arange((n + 1) // 2, n)
    lower = n - 1 - upper
    if not np.allclose(z[upper] - centre, centre - z[lower]):
        sys.exit(f"plotResults: the profile's bins are not symmetric about the channel's centre {centre:g}")
    with np.errstate(invalid="ignore", divide="ignore"):
        u = sum_u / count
    du = u[:, upper] - u[:, lower]
    mean, error = du.mean(axis=0), du.std(axis=0, ddof=1) / math.sqrt(m)
    good = np.isfinite(mean) & (error > 0)
    return {"z": z[upper] - centre, "du": mean, "err": error,
            "A": BlockMean(region_mean(sum_u, count, upper) - region_mean(sum_u, count, lower)),
            "chi2": float(np.mean((mean[good] / error[good]) ** 2)), "pairs": int(good.sum()),
            "rms": float(np.sqrt(np.mean(mean[good] ** 2))), "noise": float(np.sqrt(np.mean(error[good] ** 2))),
            "max": float(np.max(np.abs(mean[good])))}
