"""A 1-D binnedProfile's sampled blocks (<time>/sampling/<name>.h5) joined into super-blocks.

The sampling blocks of a channel (a few time units) are shorter than its slowest hydrodynamic mode
(tau1 = d^2 / (pi^2 nu)), so their spread underestimates the error of a mean: consecutive blocks are
joined into super-blocks about two tau1 long, the latest ones kept (docs/analysis.md 5.2). The sums
per bin follow sampling/BinProfile.cpp: particle-samples, sums of v (3), of v^2 (3), of x, x^2, and
of v x (3) along the bin's axis.
"""
import h5py
import numpy as np


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
    """kT per bin about a mean velocity varying linearly across the bin (sampling/BinProfile.cpp)."""
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
        return total / 3.0
