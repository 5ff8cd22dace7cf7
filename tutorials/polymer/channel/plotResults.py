#!/usr/bin/env python3
"""Polymer channel tutorial (docs/scenes.md scene 7): picture, results table and checks.

Reads every case of the sweep (sweep/ or, with -lowG, sweepLowG/: runSweep's copies of channel/ and its
sweep.dat), computes per case the flux, the centre velocity, the velocity deficit against the case
without chains, the fitted (effective) viscosity, kT in the bulk (the bins', and from the snapshots its
split into heat and motion neighbours share), the beads' depletion at the walls and the chain shapes, all with errors over super-blocks, draws polymerChannel[LowG].png, writes
results[LowG].dat and exits non-zero when a check fails.

Error bars. The run samples in blocks of 25 time units (test: 10), shorter than the correlation times
of the flow and of the chains: the slowest flow mode decays in tau1 = d^2 / (pi^2 nu) (290 at d = 28,
24 at the test's d = 8; its share dominates the flux's fluctuation without chains), and the flux and
the chain shapes of the 90-bead chains decorrelate within ~300 (measured: their autocorrelation
crosses zero at 250-300, and the standard error over blocks stops growing with the block length from
~300). Consecutive sampling blocks are therefore joined into super-blocks of about 2 tau1 (600; test
50), and every mean's standard error is the spread of its M super-block means over sqrt(M) (M = 8).
For an exponentially correlated signal, neighbouring means of blocks 2 tau1 long are still correlated
by ~0.3, which leaves the slowest mode's share of the error ~15 % low (wallComparison.py of
tutorials/channel/poiseuille). Each error comes from M - 1 degrees of freedom, so "3 standard
errors" is read as the Student-t quantile of the same one-sided tail probability (0.135 %) for the
Welch-Satterthwaite degrees of freedom of the combination.
"""
import glob
import math
import os
import re
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.environ.get("DPD_PROJECT_DIR", os.path.join(os.path.dirname(__file__), "../../..")), "etc"))
from dpdResults import dictionary_value, read_dict, read_sweep, read_table  # noqa: E402
from pairTemperature import case_rows  # noqa: E402

# The fluid (constant/dpdProperties): kT, a, rho, and Groot and Warren's equation of state
# p = rho kT + alpha a rho^2 (alpha = 0.101), whose isothermal sound speed is c^2 = dp/drho = kT + 2 alpha a rho.
KT_SET, A_FF, RHO, ALPHA_GW = 1.0, 18.75, 4.0, 0.101
SOUND_SPEED = math.sqrt(KT_SET + 2.0 * ALPHA_GW * A_FF * RHO)
Z_SIGMA = 3.0  # "3 standard errors"


def student_t(z, dof):
    """The Student-t quantile with the one-sided tail probability of z normal standard deviations
    (Abramowitz and Stegun 26.7.5; good to ~1 % for dof >= 4, ~5 % low at dof 3)."""
    g1 = (z ** 3 + z) / 4
    g2 = (5 * z ** 5 + 16 * z ** 3 + 3 * z) / 96
    g3 = (3 * z ** 7 + 19 * z ** 5 + 17 * z ** 3 - 15 * z) / 384
    g4 = (79 * z ** 9 + 776 * z ** 7 + 1482 * z ** 5 - 1920 * z ** 3 - 945 * z) / 92160
    return z + g1 / dof + g2 / dof ** 2 + g3 / dof ** 3 + g4 / dof ** 4


def combined(*terms):
    """sigma and the 3-sigma allowance of a sum of independent terms (error, degrees of freedom):
    Welch-Satterthwaite degrees of freedom, Student-t quantile."""
    sigma = math.sqrt(sum(e * e for e, _ in terms))
    denominator = sum(e ** 4 / dof for e, dof in terms if e > 0)
    dof = sigma ** 4 / denominator if denominator > 0 else float("inf")
    return sigma, student_t(Z_SIGMA, dof) * sigma, dof


def latest_dir(pattern):
    paths = glob.glob(pattern)
    if not paths:
        sys.exit(f"plotResults: nothing matches {pattern}")
    return max(paths, key=lambda p: float(p.rstrip("/").split("/")[-1]))


class Bins:
    """A 1-D binnedProfile's sampled blocks (<time>/sampling/<name>.h5), complete blocks only."""

    def __init__(self, path):
        with h5py.File(path, "r") as f:
            blocks = np.array(f["blocks"])
            samples = np.array(f["samplesPerBlock"])
            self.n = int(f.attrs["nBins"])
            self.lo, self.hi = float(f.attrs["lo"]), float(f.attrs["hi"])
            self.block_samples = int(f.attrs["blockSamples"])
            self.cross_section = float(f.attrs["crossSection"])
        complete = samples == self.block_samples
        self.blocks = blocks[complete, :, :12]
        self.width = (self.hi - self.lo) / self.n
        self.z = self.lo + self.width * (np.arange(self.n) + 0.5)

    def super_blocks(self, per, m):
        """Sums over m super-blocks of `per` sampling blocks each, the last m * per blocks."""
        used = self.blocks[len(self.blocks) - m * per:]
        return used.reshape(m, per, self.n, 12).sum(axis=1), per * self.block_samples


def density(sums, samples, bins):
    return sums[..., 0] / (samples * bins.width * bins.cross_section)


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


def weighted_mean(values, weights, axis=-1):
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.nansum(values * weights, axis=axis) / np.sum(np.where(np.isfinite(values), weights, 0.0), axis=axis)


class Stat:
    """A mean over the super-blocks, its standard error and its degrees of freedom."""

    def __init__(self, per_block, value=None):
        per_block = np.asarray(per_block, dtype=float)
        self.blocks = per_block
        self.value = float(np.mean(per_block)) if value is None else float(value)
        self.m = len(per_block)
        self.error = float(np.std(per_block, ddof=1) / math.sqrt(self.m)) if self.m > 1 else float("nan")
        self.dof = self.m - 1

    def term(self):
        return (self.error, self.dof)

    def fmt(self, digits=4):
        return f"{self.value:.{digits}f} +- {self.error:.{digits}f}"


def fit_parabola_nu(z, u, sigma, walls, exclude, g):
    """nu of the weighted parabola fitted to the bins at least `exclude` from the walls (fitSlipLength)."""
    lo, hi = walls
    sel = (z >= lo + exclude) & (z <= hi - exclude) & np.isfinite(u) & (sigma > 0)
    c2 = np.polyfit(z[sel], u[sel], 2, w=1.0 / sigma[sel])[0]
    return -g / (2.0 * c2)


class Case:
    """One case of the sweep: its profiles, fit, chains and log, with super-block statistics."""

    def __init__(self, path, chains, length, super_block):
        self.path, self.chains, self.length = path, int(chains), int(length)
        self.beads = self.chains * self.length
        self.label = "no chains" if self.chains == 0 else f"{self.chains}x{self.length}"
        control = os.path.join(path, "system/controlDict")
        self.dt = float(dictionary_value(control, "deltaT"))
        self.start = float(dictionary_value(control, "functions/channelProfile/startTime"))
        self.end = float(dictionary_value(control, "endTime"))
        interval = int(dictionary_value(control, "functions/channelProfile/sampleInterval"))
        self.fit = read_dict(latest_dir(os.path.join(path, "postProcessing/fitSlipLength/*")) + "/fit.dat")
        self.walls = tuple(self.fit["wallPosition"])
        self.g = self.fit["g"]
        self.d = self.walls[1] - self.walls[0]
        self.centre = 0.5 * (self.walls[0] + self.walls[1])
        pp = latest_dir(os.path.join(path, "postProcessing/profileBins/*"))
        self.table = read_table(os.path.join(pp, "channelProfile.dat"))
        self.bead_table = read_table(os.path.join(pp, "beadProfile.dat")) if self.chains else None
        self.fluid_table = read_table(os.path.join(pp, "fluidProfile.dat"))
        time_dir = latest_dir(os.path.join(path, "[0-9]*"))
        self.snapshot = os.path.join(time_dir, "particles.h5")
        self.prof = Bins(os.path.join(time_dir, "sampling/channelProfile.h5"))
        self.block_time = self.prof.block_samples * interval * self.dt
        self.per = max(1, round(super_block / self.block_time))
        self.m = len(self.prof.blocks) // self.per
        self.super_time = self.per * self.block_time
        # The super-blocks cover [window_start, end): the earliest sampling blocks left out, if any.
        self.window_start = self.end - self.m * self.super_time
        self._flow()
        self._heat()
        fluid = Bins(os.path.join(time_dir, "sampling/fluidProfile.h5"))
        sums, _ = fluid.super_blocks(self.per, self.m)
        self.kT_fluid = Stat(weighted_mean(temperature(sums)[:, self.bulk], sums[:, self.bulk, 0]))
        if self.chains:
            self._beads(Bins(os.path.join(time_dir, "sampling/beadProfile.h5")))
            self._chains(latest_dir(os.path.join(path, "postProcessing/chains/*")))
        self._log()

    def _flow(self):
        sums, samples = self.prof.super_blocks(self.per, self.m)
        z = self.prof.z
        inside = (z > self.walls[0]) & (z < self.walls[1])
        centre = np.abs(z - self.centre) < 1.0
        self.bulk = np.abs(z - self.centre) < 0.25 * self.d  # the central half of the channel
        self.near = (z - self.walls[0] < 1.0) | (self.walls[1] - z < 1.0)  # within one cutoff of a wall
        count, sum_u = sums[..., 0], sums[..., 1]
        # Mass-weighted mean velocity of all mobile particles (flux / (rho d)) and the centre velocity.
        self.U = Stat(sum_u[:, inside].sum(axis=1) / count[:, inside].sum(axis=1))
        self.uc = Stat(sum_u[:, centre].sum(axis=1) / count[:, centre].sum(axis=1))
        kT = temperature(sums)
        self.kT = Stat(weighted_mean(kT[:, self.bulk], count[:, self.bulk]))
        self.kT_mean = weighted_mean(temperature(sums.sum(axis=0))[inside], count.sum(axis=0)[inside])
        # nu: fitSlipLength's, with its error by jackknife over the super-blocks.
        sigma = np.where(self.table["uxErr"] > 0, self.table["uxErr"], np.inf)
        total_c, total_s = count.sum(axis=0), sum_u.sum(axis=0)
        with np.errstate(invalid="ignore", divide="ignore"):
            leave = np.array([fit_parabola_nu(z, (total_s - sum_u[k]) / (total_c - count[k]), sigma, self.walls,
                                              self.fit["exclude"], self.g) for k in range(self.m)])
        jack = math.sqrt((self.m - 1) / self.m * np.sum((leave - leave.mean()) ** 2))
        self.nu = Stat([0.0, 0.0], self.fit["nu"])
        self.nu.error, self.nu.dof = jack, self.m - 1
        self.rho_bulk = float(np.mean(density(sums.sum(axis=0), self.m * samples, self.prof)[self.bulk]))

    def _heat(self):
        """The bulk's kT split into heat (pair) and motion neighbours share (shared), per snapshot of the
        sampled window (etc/pairTemperature.py: the case's table, or measured now from its snapshots),
        as super-block means. The region is the central half of channelProfile's range (the walls)."""
        rows = case_rows(self.path, "channelProfile")
        rows = rows[rows[:, 0] >= self.window_start]
        k = np.minimum(np.floor((rows[:, 0] - self.window_start) / self.super_time).astype(int), self.m - 1)
        per_block = np.bincount(k, minlength=self.m)
        if per_block.min() < 2:
            sys.exit(f"plotResults: {self.path} has fewer than 2 snapshots in a super-block of {self.super_time:g} "
                     "(writeInterval of system/controlDict): rerun the case")
        means = [[rows[k == j, col].mean() for j in range(self.m)] for col in (1, 2, 3)]
        self.kT_single, self.kT_pair, self.kT_shared = (Stat(m) for m in means)
        self.snapshots = len(rows)

    def _beads(self, bins):
        sums, samples = bins.super_blocks(self.per, self.m)
        rho = density(sums, samples, bins)
        near_rho = rho[:, self.near].mean(axis=1)
        bulk_rho = rho[:, self.bulk].mean(axis=1)
        self.bead_bulk = Stat(bulk_rho)
        self.bead_near = Stat(near_rho)
        self.depletion = Stat(near_rho / bulk_rho, near_rho.mean() / bulk_rho.mean())
        count = sums[..., 0]
        self.kT_beads = Stat(weighted_mean(temperature(sums)[:, self.bulk], count[:, self.bulk]))
        self.bead_fraction_bulk = float(bulk_rho.mean() / self.rho_bulk)

    def _chains(self, directory):
        data = np.loadtxt(os.path.join(directory, "chainStatistics.dat"), comments="#", ndmin=2)
        t = data[:, 0]
        k = np.floor((t - self.window_start) / self.super_time).astype(int)
        use = (k >= 0) & (k < self.m)
        means = {}
        for col, name in ((1, "Rg2"), (2, "Ree2"), (4, "Reex2"), (5, "spanx")):
            means[name] = Stat([data[use & (k == j), col].mean() for j in range(self.m)])
        self.Rg2, self.Ree2, self.Reex2, self.spanx = means["Rg2"], means["Ree2"], means["Reex2"], means["spanx"]
        # R_g^2 and span by where the chain's centre lies across the channel (the whole sampling).
        bins = np.loadtxt(os.path.join(directory, "chainBins.dat"), comments="#", ndmin=2)
        self.chain_bins = {"z": bins[:, 0], "samples": bins[:, 1], "Rg2": bins[:, 2], "spanx": bins[:, 3]}

    def _log(self):
        self.steps = self.seconds = self.rate = float("nan")
        self.particles = 0
        self.history = [], []
        path = os.path.join(self.path, "log.dpdFoamLike")
        if not os.path.exists(path):
            return
        text = open(path).read()
        m = re.search(r"Particles\s*:\s*(\d+)\s*\((\d+) mobile", text)
        if m:
            self.particles, self.mobile = int(m.group(1)), int(m.group(2))
        m = re.search(r"Run finished: (\d+) steps in ([0-9.eE+-]+) s, ([0-9.eE+-]+) particle-steps/s", text)
        if m:
            self.steps, self.seconds, self.rate = int(m.group(1)), float(m.group(2)), float(m.group(3))
        times = [float(x) for x in re.findall(r"^Time = (\S+)", text, re.M)]
        velocities = [float(x) for x in re.findall(r"meanVelocity = \((\S+)", text)]
        n = min(len(times), len(velocities))
        self.history = np.array(times[:n]), np.array(velocities[:n])

    @property
    def reynolds(self):
        return self.uc.value * self.d / self.nu.value

    @property
    def mach(self):
        return self.uc.value / SOUND_SPEED


def chain_positions(snapshot):
    """Unwrapped bead positions of every chain: {chain: (L, 3) array}, from the first bead's position and
    the bonds' followed vectors (io/SnapshotBonds.hpp)."""
    with h5py.File(snapshot, "r") as f:
        ids = np.array(f["particles/id"])
        pos = np.array(f["particles/position"])
        pairs = np.array(f["bonds/pairs"])
        vec = np.array(f["bonds/vector"])
        bond_chain = np.array(f["bonds/chain"])
    row = {int(i): k for k, i in enumerate(ids)}
    out = {}
    for c in np.unique(bond_chain):
        sel = np.flatnonzero(bond_chain == c)
        # The chain's bonds in order: follow them from the bead that is nobody's second.
        nxt = {int(pairs[b, 0]): (int(pairs[b, 1]), vec[b]) for b in sel}
        seconds = {int(pairs[b, 1]) for b in sel}
        first = [a for a in nxt if a not in seconds][0]
        points = [pos[row[first]]]
        bead = first
        while bead in nxt:
            bead, v = nxt[bead]
            points.append(points[-1] + v)
        out[int(c)] = np.array(points)
    return out


def main():
    test = "-test" in sys.argv[1:]
    low_g = "-lowG" in sys.argv[1:]
    sweep_dir = "sweepLowG" if low_g else "sweep"
    results = "resultsLowG.dat" if low_g else "results.dat"
    picture = "polymerChannelLowG.png" if low_g else "polymerChannel.png"
    # Super-blocks (module docstring): ~2 tau1, 600 time units at full size, 50 in the test.
    super_block = 50.0 if test else 600.0

    sweep = read_sweep(os.path.join(sweep_dir, "sweep.dat"))
    cases = [Case(os.path.join(sweep_dir, name), n, L, super_block)
             for name, n, L in zip(sweep["case"], sweep["chains"], sweep["length"])]
    ref = [c for c in cases if c.chains == 0]
    if len(ref) != 1:
        sys.exit("plotResults: the sweep needs exactly one case without chains")
    ref = ref[0]
    chain_cases = [c for c in cases if c.chains]
    smallest = min(chain_cases, key=lambda c: (c.beads, c.length))
    n_sweep = [ref] + sorted([c for c in chain_cases if c.length == smallest.length], key=lambda c: c.chains)
    l_sweep = [ref] + sorted([c for c in chain_cases if c.chains == smallest.chains], key=lambda c: c.length)
    too_few = [c.label for c in cases if c.m < 4]
    if too_few:
        sys.exit(f"plotResults: fewer than 4 super-blocks of {super_block:g} in {', '.join(too_few)}: run longer")

    # Per case: the deficit of the flux against no chains, and its error.
    for c in cases:
        ratio = c.U.value / ref.U.value
        c.deficit = 1.0 - ratio
        c.deficit_error = 0.0 if c is ref else ratio * math.hypot(c.U.error / c.U.value, ref.U.error / ref.U.value)
        c.uc_deficit = 1.0 - c.uc.value / ref.uc.value

    checks = []
    # The chains add no heat. The bins' kT of the bulk rises with chains at the published g, but what
    # rises is motion neighbours share (etc/pairTemperature.py; README): the heat, the kT of the
    # neighbours' relative velocities, is what the thermostat holds. Without chains the flow's viscous
    # heating raises it by H0 = pair kT0 - kT_set; the chains slow the flow and carry part of the
    # stress, so the heat of a chain case lies between the set kT and the chain-free flow's:
    # kT_set - 3 sigma < pair kT < pair kT0 + 3 sigma (Student-t, combined errors for the upper bound).
    heating = ref.kT_pair.value - KT_SET
    for c in chain_cases:
        above = c.kT_pair.value - ref.kT_pair.value
        sigma_up, allow_up, dof_up = combined(c.kT_pair.term(), ref.kT_pair.term())
        below = c.kT_pair.value - KT_SET
        allow_down = student_t(Z_SIGMA, c.kT_pair.dof) * c.kT_pair.error
        checks.append((f"the chains add no heat to the bulk, {c.label}: kT_set - 3 sigma < pair kT < pair kT(no chains) + 3 sigma",
                       above < allow_up and below > -allow_down,
                       f"pair kT {c.kT_pair.fmt(5)}: {above:+.5f} from no chains (3 sigma {allow_up:.5f}, dof {dof_up:.0f}), "
                       f"{below:+.5f} from kT_set (3 sigma {allow_down:.5f}); bins' kT {c.kT.value - ref.kT.value:+.5f} "
                       f"from no chains, of which shared motion {c.kT_shared.value - ref.kT_shared.value:+.5f}"))
    # Beads depleted at the walls: bead density within one cutoff of a wall over the bulk's, below 1 by
    # more than 3 standard errors (of the ratio over the super-blocks).
    for c in chain_cases:
        allow = student_t(Z_SIGMA, c.depletion.dof) * c.depletion.error
        checks.append((f"beads depleted at the walls, {c.label}: 1 - rho_near / rho_bulk > 3 sigma",
                       1.0 - c.depletion.value > allow,
                       f"rho_near / rho_bulk = {c.depletion.fmt(4)}, 1 - ratio = {1 - c.depletion.value:.4f}, "
                       f"3 sigma = {allow:.4f}"))
    # The velocity deficit grows with nChain and with ChainLen: each step of each sweep lowers the flux
    # by more than 3 combined standard errors (the deficits differ by (U_prev - U_next) / U0; the
    # error of U0 scales both alike and is left out of the step).
    done = set()
    for name, series in (("nChain", n_sweep), ("ChainLen", l_sweep)):
        for prev, nxt in zip(series[:-1], series[1:]):
            if (prev.label, nxt.label) in done:
                continue
            done.add((prev.label, nxt.label))
            step = prev.U.value - nxt.U.value
            sigma, allow, dof = combined(prev.U.term(), nxt.U.term())
            checks.append((f"velocity deficit grows with {name}: {prev.label} -> {nxt.label}, "
                           f"U drops by more than 3 sigma",
                           step > allow,
                           f"deficit {prev.deficit:.4f} -> {nxt.deficit:.4f}, U {prev.U.value:.4f} -> {nxt.U.value:.4f}: "
                           f"drop {step:+.4f} = {step / sigma:.1f} sigma, 3 sigma = {allow:.4f} (sigma {sigma:.4f}, dof {dof:.0f})"))

    write_results(results, cases, ref, n_sweep, l_sweep, checks, test, low_g, heating)
    print(open(results).read(), end="")
    plot(picture, cases, ref, n_sweep, l_sweep, low_g)
    print(f"Written {picture} and {results}")
    return 0 if all(ok for _, ok, _ in checks) else 1


def write_results(path, cases, ref, n_sweep, l_sweep, checks, test, low_g, heating):
    c0 = cases[0]
    with open(path, "w") as f:
        f.write(f"# FENE chains in Poiseuille flow between frozen walls (docs/scenes.md scene 7){' [test]' if test else ''}"
                f"{' [low-g variant]' if low_g else ''}\n")
        f.write(f"# d = {c0.d:g}, g = {c0.g:g}; sampled {c0.start:g}-{c0.end:g}; errors: standard errors over "
                f"{c0.m} super-blocks of {c0.super_time:g} time units\n")
        f.write("# U: mean velocity of all mobile particles (flux / (rho d)); uc: velocity within 1 of the centre;\n"
                "# deficit: 1 - U / U(no chains); nu: fitSlipLength's parabola (effective viscosity), jackknife error;\n"
                "# kT: bulk (central half of the channel), all mobile particles (fluid and beads) and the beads alone;\n"
                "# kT split (etc/pairTemperature.py, snapshots): pair = the neighbours' relative velocities (heat),\n"
                "#   shared = <dv_i . dv_j> / 3 over neighbours (motion they share), single = <dv^2> / 3;\n"
                "# near/bulk: bead density within 1 of a wall over the bead density of the central half;\n"
                "# Rg2, Ree2, Reex2 (<R_ee,x^2>), spanx (max - min bead x, the extension along the flow): chain means\n")
        f.write(f"# Re = uc d / nu; Ma = uc / c, c = sqrt(kT + 2 alpha a rho) = sqrt(1 + 2 x {ALPHA_GW} x {A_FF:g} x {RHO:g}) = {SOUND_SPEED:.3f}\n")
        for c in cases:
            f.write(f"\ncase {c.label}  (nChain {c.chains}, ChainLen {c.length}, beads {c.beads}; {c.path})\n")
            f.write(f"  U              {c.U.fmt(4)}\n")
            f.write(f"  uc             {c.uc.fmt(4)}\n")
            f.write(f"  deficit        {c.deficit:.4f} +- {c.deficit_error:.4f}   (centre velocity: {c.uc_deficit:.4f})\n")
            f.write(f"  nu             {c.nu.value:.4f} +- {c.nu.error:.4f}   (fit chi2/dof {c.fit.get('chi2PerDof', float('nan')):.1f})\n")
            f.write(f"  kT bulk        {c.kT.fmt(5)}   (channel mean {c.kT_mean:.5f})\n")
            f.write(f"  kT fluid bulk  {c.kT_fluid.fmt(5)}\n")
            f.write(f"  kT split       pair (heat) {c.kT_pair.fmt(5)}, shared by neighbours {c.kT_shared.fmt(5)}, "
                    f"single {c.kT_single.fmt(5)}   ({c.snapshots} snapshots)\n")
            if c.chains:
                f.write(f"  kT beads bulk  {c.kT_beads.fmt(5)}\n")
                f.write(f"  bead density   bulk {c.bead_bulk.fmt(4)}, within 1 of a wall {c.bead_near.fmt(4)}; "
                        f"near/bulk {c.depletion.fmt(4)}\n")
                f.write(f"  Rg2            {c.Rg2.fmt(2)}   (R_g {math.sqrt(c.Rg2.value):.3f})\n")
                f.write(f"  Ree2           {c.Ree2.fmt(1)}\n")
                f.write(f"  Reex2          {c.Reex2.fmt(1)}\n")
                f.write(f"  spanx          {c.spanx.fmt(3)}\n")
            f.write(f"  Re {c.reynolds:.0f}  Ma {c.mach:.3f}\n")
            f.write(f"  run            {c.particles} particles, {c.steps} steps in {c.seconds:.0f} s, {c.rate:.3e} particle-steps/s\n")
        f.write("\n# table: case nChain ChainLen beads U U_err uc uc_err deficit deficit_err nu nu_err kT kT_err kTfluid kTfluid_err kTbeads kTbeads_err "
                "kTpair kTpair_err kTshared kTshared_err nearOverBulk err Rg2 err Ree2 err Reex2 err spanx err Re Ma particleSteps/s seconds\n")
        nan = float("nan")
        for c in cases:
            row = [c.chains, c.length, c.beads, c.U.value, c.U.error, c.uc.value, c.uc.error, c.deficit, c.deficit_error,
                   c.nu.value, c.nu.error, c.kT.value, c.kT.error, c.kT_fluid.value, c.kT_fluid.error]
            row_heat = [c.kT_pair.value, c.kT_pair.error, c.kT_shared.value, c.kT_shared.error]
            if c.chains:
                row += [c.kT_beads.value, c.kT_beads.error] + row_heat + [c.depletion.value, c.depletion.error, c.Rg2.value, c.Rg2.error,
                        c.Ree2.value, c.Ree2.error, c.Reex2.value, c.Reex2.error, c.spanx.value, c.spanx.error]
            else:
                row += [nan] * 2 + row_heat + [nan] * 10
            row += [c.reynolds, c.mach, c.rate, c.seconds]
            f.write("table " + c.label.replace(" ", "_") + " " + " ".join(f"{v:.6g}" for v in row) + "\n")
        # The pairs with the same number of beads.
        f.write("\n# same number of beads, more chains against longer chains\n")
        by_beads = {}
        for c in cases:
            if c.chains:
                by_beads.setdefault(c.beads, []).append(c)
        for beads, pair in sorted(by_beads.items()):
            if len(pair) < 2:
                continue
            a, b = sorted(pair, key=lambda c: -c.chains)
            f.write(f"beads {beads}: {a.label} | {b.label}: deficit {a.deficit:.4f} +- {a.deficit_error:.4f} | "
                    f"{b.deficit:.4f} +- {b.deficit_error:.4f}; nu {a.nu.value:.4f} | {b.nu.value:.4f}; "
                    f"near/bulk {a.depletion.value:.3f} | {b.depletion.value:.3f}; Rg2 {a.Rg2.value:.1f} | {b.Rg2.value:.1f}; "
                    f"spanx {a.spanx.value:.2f} | {b.spanx.value:.2f}; kT {a.kT.value:.4f} | {b.kT.value:.4f}\n")
        f.write(f"\n# viscous heating of the bulk without chains (pair kT): H0 = pair kT0 - kT_set = {heating:+.5f}\n")
        f.write(f"# cost of the bonds: particle-steps/s without chains {ref.rate:.3e}; "
                + ", ".join(f"{c.label} {c.rate:.3e} ({100 * (c.rate / ref.rate - 1):+.1f} %)" for c in cases if c.chains)
                + "\n")
        for name, ok, value in checks:
            f.write(f"check  {'PASS' if ok else 'FAIL'}  {name}: {value}\n")


def plot(path, cases, ref, n_sweep, l_sweep, low_g):
    colours = plt.cm.viridis(np.linspace(0.0, 0.9, len(cases)))
    colour = {c.label: colours[k] for k, c in enumerate(cases)}
    fig = plt.figure(figsize=(22, 15))
    grid = fig.add_gridspec(3, 4)
    ax = np.empty((3, 4), dtype=object)
    for i in range(3):
        for j in range(4):
            if not (i == 2 and j == 3):
                ax[i, j] = fig.add_subplot(grid[i, j] if not (i == 2 and j == 2) else grid[2, 2:])
    chain_cases = [c for c in cases if c.chains]
    for c in cases:
        t, col = c.table, colour[c.label]
        ax[0, 0].errorbar(t["z"], t["ux"], yerr=t["uxErr"], fmt="-", color=col, lw=1.2, label=f"{c.label}: U {c.U.value:.3f}")
        ax[0, 1].plot(t["z"], t["density"], "-", color=col, lw=1.2, label=c.label)
        ax[0, 2].plot(t["z"], t["kT"], "-", color=col, lw=1.2, label=f"{c.label}: bulk {c.kT.value:.4f}")
        # The bulk's heat (pair kT, docs/analysis.md 5.5) over the central half: what the check reads.
        ax[0, 2].plot([c.centre - 0.25 * c.d, c.centre + 0.25 * c.d], [c.kT_pair.value] * 2, "--", color=col, lw=1.0,
                      label=f"{c.label}: heat (pair kT) {c.kT_pair.value:.4f}")
        ax[0, 3].plot(c.fluid_table["z"], c.fluid_table["kT"], "-", color=col, lw=1.2, label=f"{c.label} fluid")
        if c.chains:
            b = c.bead_table
            good = b["count"] > 0
            ax[0, 3].plot(b["z"][good], b["kT"][good], "--", color=col, lw=1.0, label=f"{c.label} beads")
            ax[1, 0].errorbar(b["z"], b["density"], yerr=b["densityErr"], fmt="-", color=col, lw=1.2,
                              label=f"{c.label}: near/bulk {c.depletion.value:.3f}")
            cb = c.chain_bins
            ok = cb["samples"] > 0
            ax[1, 3].plot(cb["z"][ok], cb["Rg2"][ok], "o-", color=col, ms=3, label=c.label)
    for a, title, ylabel in ((ax[0, 0], "velocity (fluid and beads)", "u_x"),
                             (ax[0, 1], "density (fluid and beads)", "number density"),
                             (ax[0, 2], "kT about the local flow (fluid and beads); dashed: the bulk's heat", "kT"),
                             (ax[0, 3], "kT of the fluid (solid) and of the beads (dashed)", "kT"),
                             (ax[1, 0], "bead density", "bead number density"),
                             (ax[1, 3], "R_g^2 by where the chain's centre lies", "<R_g^2>")):
        a.set_title(title); a.set_xlabel("z"); a.set_ylabel(ylabel); a.legend(fontsize=7)
        for zw in ref.walls:
            a.axvline(zw, color="gray", ls=":")
    for a in (ax[0, 2], ax[0, 3], ax[1, 0]):
        for zb in (ref.centre - 0.25 * ref.d, ref.centre + 0.25 * ref.d):
            a.axvline(zb, color="k", lw=0.6, ls="--")
    for a in (ax[0, 2], ax[0, 3]):
        a.axhline(KT_SET, color="k", lw=0.8)
        a.set_ylim(0.97, 1.12)
    ax[1, 3].set_yscale("log")

    # Chain size against nChain and ChainLen.
    for a, series, key, xlabel in ((ax[1, 1], n_sweep, "chains", "nChain"), (ax[1, 2], l_sweep, "length", "ChainLen")):
        s = [c for c in series if c.chains]
        x = [getattr(c, key) for c in s]
        a.errorbar(x, [math.sqrt(c.Rg2.value) for c in s], yerr=[0.5 * c.Rg2.error / math.sqrt(c.Rg2.value) for c in s],
                   fmt="o-", label="R_g = sqrt<R_g^2>")
        a.errorbar(x, [math.sqrt(c.Ree2.value) for c in s], yerr=[0.5 * c.Ree2.error / math.sqrt(c.Ree2.value) for c in s],
                   fmt="s-", label="sqrt<R_ee^2>")
        a.errorbar(x, [c.spanx.value for c in s], yerr=[c.spanx.error for c in s], fmt="^-", label="extension along x (span)")
        a.set_xlabel(xlabel); a.set_ylabel("length")
        a.set_title(f"chain size against {xlabel} ({'ChainLen' if key == 'chains' else 'nChain'} "
                    f"{s[0].length if key == 'chains' else s[0].chains})")
        a.legend(fontsize=8)
    # Deficit against the number of beads, both sweeps.
    for series, name, marker in ((n_sweep, "nChain sweep", "o-"), (l_sweep, "ChainLen sweep", "s--")):
        ax[2, 0].errorbar([c.beads for c in series], [c.deficit for c in series], yerr=[c.deficit_error for c in series],
                          fmt=marker, label=name)
        for c in series[1:]:
            ax[2, 0].annotate(c.label, (c.beads, c.deficit), fontsize=8, xytext=(4, -10), textcoords="offset points")
    ax[2, 0].set_xlabel("beads (nChain x ChainLen)"); ax[2, 0].set_ylabel("flux deficit 1 - U / U(no chains)")
    ax[2, 0].set_title("velocity deficit"); ax[2, 0].legend(fontsize=8)
    # Start-up: the log's mean velocity of the mobile particles.
    for c in cases:
        t, u = c.history
        if len(t):
            ax[2, 1].plot(t, u, "-", color=colour[c.label], lw=1, label=c.label)
    ax[2, 1].axvspan(ref.window_start, ref.end, color="0.9", label="sampled")
    ax[2, 1].set_xlabel("time"); ax[2, 1].set_ylabel("mean velocity of the mobile particles")
    ax[2, 1].set_title("start-up (the run's log)"); ax[2, 1].legend(fontsize=7)
    # Snapshot: the chains of the case with the longest chains, x-z, unwrapped and coloured by chain.
    show = max(chain_cases, key=lambda c: (c.length, c.beads))
    a = ax[2, 2]
    chains = chain_positions(show.snapshot)
    cmap = plt.cm.tab20
    with h5py.File(show.snapshot, "r") as f:
        lo, hi = f.attrs["boxLo"], f.attrs["boxHi"]
    length = hi[0] - lo[0]
    for k, (c, p) in enumerate(sorted(chains.items())):
        shift = length * np.floor((p[:, 0].mean() - lo[0]) / length)  # the chain's centre into the box
        a.plot(p[:, 0] - shift, p[:, 2], "-", color=cmap(k % 20), lw=0.8)
        a.plot(p[:, 0] - shift, p[:, 2], ".", color=cmap(k % 20), ms=2.5)
    a.axvline(lo[0], color="k", lw=0.6); a.axvline(hi[0], color="k", lw=0.6)
    for zw in show.walls:
        a.axhline(zw, color="gray", ls=":")
    a.set_xlabel("x (each chain unwrapped from its bond vectors, its centre in the box; box edges marked)")
    a.set_ylabel("z")
    a.set_title(f"{show.label}: the chains at t = {os.path.basename(os.path.dirname(show.snapshot))}, x-z projection, "
                "one colour per chain")
    a.set_aspect("equal", adjustable="datalim")
    fig.suptitle(f"FENE chains in Poiseuille flow, d = {ref.d:g}, g = {ref.g:g}{' (low-g variant)' if low_g else ''}: "
                 f"no chains U = {ref.U.value:.3f}, Re = {ref.reynolds:.0f}, Ma = {ref.mach:.2f}")
    fig.tight_layout(rect=(0, 0, 1, 0.97))
    fig.savefig(path, dpi=90)


def chain_cases_of(cases):
    return [c for c in cases if c.chains]


if __name__ == "__main__":
    sys.exit(main())
