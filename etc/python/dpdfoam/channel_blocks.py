"""A Poiseuille channel case measured over fitSlipLength's super-blocks (timeseries.SuperBlockWindow:
docs/analysis.md 5.2): the flux and the centre velocity, the bulk's kT and its heat apart from the
motion neighbours share (pair_temperature, docs/analysis.md 5.5), nu with the fit's jackknife error,
the two halves' asymmetry, a profile's density in the bulk and at the walls, and the run's log; each
mean a BlockMean over the same super-blocks. Besides, the flow measures of a 2-D grid averaged along x."""
import os
import sys

import numpy as np

from .blocks import SampledBins, mirror_asymmetry, region_mean, region_temperature
from .grid import weighted_mean
from .io import dictionary_value, function_start, latest_dir
from .pair_temperature import case_rows
from .stats import BlockMean
from .timeseries import SuperBlockWindow, run_report


class SuperBlockChannel:
    """A channel case: its walls and g (fit.dat), the window of its profile function's super-blocks, the
    latest profileBins directory (.profiles) and time (.time_dir); the measure_* methods fill the rest."""

    def __init__(self, path, profile="channelProfile"):
        self.path, self.profile = path, profile
        self.start = function_start(path, profile)
        self.end = float(dictionary_value(os.path.join(path, "system/controlDict"), "endTime"))
        # fitSlipLength's super-blocks (its jackknife gives nu's error); every other mean uses the same,
        # over [window.start, end): the earliest sampling blocks left out, if any.
        self.window = SuperBlockWindow(path, self.end)
        self.fit = self.window.fit
        self.walls, self.g = tuple(self.fit["wallPosition"]), self.fit["g"]
        self.d, self.centre = self.walls[1] - self.walls[0], 0.5 * (self.walls[0] + self.walls[1])
        self.h = 0.5 * self.d
        self.profiles = latest_dir(os.path.join(path, "postProcessing/profileBins/*"))
        self.time_dir = latest_dir(os.path.join(path, "[0-9]*"))

    def sampled(self, name):
        """The sampled blocks of the binnedProfile `name` at the latest time."""
        return SampledBins(os.path.join(self.time_dir, f"sampling/{name}.h5"))

    def bulk(self, z):
        """Whether each z lies in the central half of the channel."""
        return np.abs(z - self.centre) < 0.25 * self.d

    def near(self, z, cutoff=1.0):
        """Whether each z lies within cutoff of a wall."""
        return (z - self.walls[0] < cutoff) | (self.walls[1] - z < cutoff)

    def measure_flow(self):
        """From the profile's super-blocks: U, uc, the bulk's kT, the channel's mean kT, nu and the asymmetry."""
        prof = self.sampled(self.profile)
        sums, _ = prof.super_blocks(self.window.per, self.window.m)
        z, count, sum_u = prof.z, sums[..., 0], sums[..., 1]
        inside = (z > self.walls[0]) & (z < self.walls[1])
        # Mass-weighted mean velocity of all mobile particles (flux / (rho d)) and the centre velocity.
        self.U = BlockMean(region_mean(sum_u, count, inside))
        self.uc = BlockMean(region_mean(sum_u, count, np.abs(z - self.centre) < 1.0))
        self.kT = BlockMean(region_temperature(sums, self.bulk(z)))
        self.kT_mean = region_temperature(sums.sum(axis=0), inside)
        self.nu = BlockMean.of(self.fit["nu"], self.fit["nuError"], self.window.m - 1)  # fitSlipLength's jackknife error
        self.asym = mirror_asymmetry(z, self.centre, count, sum_u)

    def measure_heat(self, script="plotResults"):
        """The bulk's kT split into heat (pair) and motion neighbours share (shared), per snapshot of the
        sampled window (etc/pairTemperature.py: the case's table, or measured now from its snapshots,
        over the central half of the profile's range), as super-block means (and .snapshots)."""
        rows, k = self.window.rows(case_rows(self.path, self.profile))
        if np.bincount(k, minlength=self.window.m).min() < 2:
            sys.exit(f"{script}: {self.path} has fewer than 2 snapshots in a super-block of {self.window.length:g} "
                     "(writeInterval of system/controlDict): rerun the case")
        self.kT_single, self.kT_pair, self.kT_shared = (self.window.mean(rows[:, col], k) for col in (1, 2, 3))
        self.snapshots = len(rows)

    def regions(self, bins):
        """A profile's super-block sums, and per super-block its density in the bulk and within one
        cutoff of a wall, and the bulk's kT (a BlockMean)."""
        sums, samples = bins.super_blocks(self.window.per, self.window.m)
        rho = bins.density(sums, samples)
        return (sums, rho[:, self.bulk(bins.z)].mean(axis=1), rho[:, self.near(bins.z)].mean(axis=1),
                BlockMean(region_temperature(sums, self.bulk(bins.z))))

    def grid_flow(self, field):
        """An x-averaged 2-D grid's (grid.averaged_along) U, uc, A = U(upper) - U(lower) and bulk kT, count-weighted."""
        z, n = field["z"], field["count"]
        ux = lambda region=slice(None): weighted_mean(field["ux"], n, region)  # noqa: E731
        return {"U": ux(), "uc": ux(np.abs(z - self.centre) < 1.0), "A": ux(z > self.centre) - ux(z < self.centre),
                "kT": weighted_mean(field["kT"], n, self.bulk(z))}

    def read_log(self):
        """The run's particles, steps, seconds, particle-steps/s and mean velocity against time (run_report)."""
        report = run_report(os.path.join(self.path, "log.dpdFoamLike"), r"meanVelocity = \((\S+)")
        self.particles, (self.steps, self.seconds, self.rate), self.history = report

    @property
    def reynolds(self):
        """uc d / nu."""
        return self.uc.value * self.d / self.nu.value
