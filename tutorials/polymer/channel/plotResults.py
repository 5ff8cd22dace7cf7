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
tutorials/channel/poiseuille/latticeWall). Each error comes from M - 1 degrees of freedom, so "3 standard
errors" is read as the Student-t quantile of the same one-sided tail probability (0.135 %) for the
Welch-Satterthwaite degrees of freedom of the combination.
"""
import math
import os
import re
import sys

import numpy as np

from dpdfoam.blocks import SampledBins, temperature
from dpdfoam.channel import fit_weights, leave_one_out_poiseuille
from dpdfoam.checks import Checks, write_results
from dpdfoam.io import dictionary_value, latest_dir, log_values, read_dict, read_sweep, read_table, read_text, run_finished
from dpdfoam.pair_temperature import case_rows
from dpdfoam.plots import label, mark_walls, plt, save
from dpdfoam.snapshots import snapshot_box, unwrapped_chains
from dpdfoam.stats import Z_SIGMA, BlockMean as Stat, combined, count_weighted_mean, jackknife_error, student_t

# The fluid (constant/dpdProperties): kT, a, rho, and Groot and Warren's equation of state
# p = rho kT + alpha a rho^2 (alpha = 0.101), whose isothermal sound speed is c^2 = dp/drho = kT + 2 alpha a rho.
KT_SET, A_FF, RHO, ALPHA_GW = 1.0, 18.75, 4.0, 0.101
SOUND_SPEED = math.sqrt(KT_SET + 2.0 * ALPHA_GW * A_FF * RHO)


def bulk_kT(sums, bulk):
    """kT of the bulk bins per super-block, weighted by their particle-samples."""
    return Stat(count_weighted_mean(temperature(sums)[:, bulk], sums[:, bulk, 0]))


class Case:
    """One case of the sweep: its profiles, fit, chains and log, with super-block statistics."""

    def __init__(self, path, chains, length, super_block):
        self.path, self.chains, self.length = path, int(chains), int(length)
        self.beads = self.chains * self.length
        self.label = "no chains" if self.chains == 0 else f"{self.chains}x{self.length}"
        control = os.path.join(path, "system/controlDict")
        self.start = float(dictionary_value(control, "functions/channelProfile/startTime"))
        self.end = float(dictionary_value(control, "endTime"))
        interval = int(dictionary_value(control, "functions/channelProfile/sampleInterval"))
        self.fit = read_dict(latest_dir(os.path.join(path, "postProcessing/fitSlipLength/*")) + "/fit.dat")
        self.walls, self.g = tuple(self.fit["wallPosition"]), self.fit["g"]
        self.d, self.centre = self.walls[1] - self.walls[0], 0.5 * (self.walls[0] + self.walls[1])
        pp = latest_dir(os.path.join(path, "postProcessing/profileBins/*"))
        self.table = read_table(os.path.join(pp, "channelProfile.dat"))
        self.bead_table = read_table(os.path.join(pp, "beadProfile.dat")) if self.chains else None
        self.fluid_table = read_table(os.path.join(pp, "fluidProfile.dat"))
        time_dir = latest_dir(os.path.join(path, "[0-9]*"))
        self.snapshot = os.path.join(time_dir, "particles.h5")
        self.prof = SampledBins(os.path.join(time_dir, "sampling/channelProfile.h5"))
        self.block_time = self.prof.block_samples * interval * float(dictionary_value(control, "deltaT"))
        self.per, self.m = self.prof.layout(self.block_time, super_block)
        self.super_time = self.per * self.block_time
        # The super-blocks cover [window_start, end): the earliest sampling blocks left out, if any.
        self.window_start = self.end - self.m * self.super_time
        self._flow()
        self._heat()
        self.kT_fluid = bulk_kT(SampledBins(os.path.join(time_dir, "sampling/fluidProfile.h5")).super_blocks(self.per, self.m)[0], self.bulk)
        if self.chains:
            self._beads(SampledBins(os.path.join(time_dir, "sampling/beadProfile.h5")))
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
        self.kT = bulk_kT(sums, self.bulk)
        self.kT_mean = count_weighted_mean(temperature(sums.sum(axis=0))[inside], count.sum(axis=0)[inside])
        # nu: fitSlipLength's, with its error by jackknife over the super-blocks.
        leave = leave_one_out_poiseuille(z, count, sum_u, fit_weights(self.table), self.walls, self.fit["exclude"], self.g)
        self.nu = Stat.of(self.fit["nu"], float(jackknife_error(leave[:, 0])), self.m - 1)
        self.rho_bulk = float(np.mean(self.prof.density(sums.sum(axis=0), self.m * samples)[self.bulk]))

    def _heat(self):
        """The bulk's kT split into heat (pair) and motion neighbours share (shared), per snapshot of the
        sampled window (etc/pairTemperature.py: the case's table, or measured now from its snapshots),
        as super-block means. The region is the central half of channelProfile's range (the walls)."""
        rows = case_rows(self.path, "channelProfile")
        rows = rows[rows[:, 0] >= self.window_start]
        k = np.minimum(np.floor((rows[:, 0] - self.window_start) / self.super_time).astype(int), self.m - 1)
        if np.bincount(k, minlength=self.m).min() < 2:
            sys.exit(f"plotResults: {self.path} has fewer than 2 snapshots in a super-block of {self.super_time:g} "
                     "(writeInterval of system/controlDict): rerun the case")
        self.kT_single, self.kT_pair, self.kT_shared = (Stat([rows[k == j, col].mean() for j in range(self.m)]) for col in (1, 2, 3))
        self.snapshots = len(rows)

    def _beads(self, bins):
        sums, samples = bins.super_blocks(self.per, self.m)
        rho = bins.density(sums, samples)
        near_rho, bulk_rho = rho[:, self.near].mean(axis=1), rho[:, self.bulk].mean(axis=1)
        self.bead_bulk, self.bead_near = Stat(bulk_rho), Stat(near_rho)
        self.depletion = Stat(near_rho / bulk_rho, near_rho.mean() / bulk_rho.mean())
        self.kT_beads = bulk_kT(sums, self.bulk)
        self.bead_fraction_bulk = float(bulk_rho.mean() / self.rho_bulk)

    def _chains(self, directory):
        data = np.loadtxt(os.path.join(directory, "chainStatistics.dat"), comments="#", ndmin=2)
        k = np.floor((data[:, 0] - self.window_start) / self.super_time).astype(int)
        use = (k >= 0) & (k < self.m)
        self.Rg2, self.Ree2, self.Reex2, self.spanx = (Stat([data[use & (k == j), col].mean() for j in range(self.m)])
                                                       for col in (1, 2, 4, 5))
        # R_g^2 and span by where the chain's centre lies across the channel (the whole sampling).
        bins = np.loadtxt(os.path.join(directory, "chainBins.dat"), comments="#", ndmin=2)
        self.chain_bins = {"z": bins[:, 0], "samples": bins[:, 1], "Rg2": bins[:, 2], "spanx": bins[:, 3]}

    def _log(self):
        self.steps = self.seconds = self.rate = float("nan")
        self.particles, self.history = 0, ([], [])
        path = os.path.join(self.path, "log.dpdFoamLike")
        if not os.path.exists(path):
            return
        text = read_text(path)
        m = re.search(r"Particles\s*:\s*(\d+)\s*\((\d+) mobile", text)
        if m:
            self.particles, self.mobile = int(m.group(1)), int(m.group(2))
        self.steps, self.seconds, self.rate = run_finished(text)
        times = log_values(text, r"^Time = (\S+)", flags=re.M)
        velocities = log_values(text, r"meanVelocity = \((\S+)")
        n = min(len(times), len(velocities))
        self.history = np.array(times[:n]), np.array(velocities[:n])

    @property
    def reynolds(self):
        return self.uc.value * self.d / self.nu.value

    @property
    def mach(self):
        return self.uc.value / SOUND_SPEED


def sweeps(cases):
    """The case without chains, and the two sweeps from it: nChain at the shortest ChainLen, ChainLen at
    the fewest chains."""
    ref = [c for c in cases if c.chains == 0]
    if len(ref) != 1:
        sys.exit("plotResults: the sweep needs exactly one case without chains")
    chain_cases = [c for c in cases if c.chains]
    smallest = min(chain_cases, key=lambda c: (c.beads, c.length))
    n_sweep = ref + sorted([c for c in chain_cases if c.length == smallest.length], key=lambda c: c.chains)
    l_sweep = ref + sorted([c for c in chain_cases if c.chains == smallest.chains], key=lambda c: c.length)
    return ref[0], chain_cases, n_sweep, l_sweep


def heat_checks(checks, chain_cases, ref):
    """The chains add no heat. The bins' kT of the bulk rises with chains at the published g, but what
    rises is motion neighbours share (etc/pairTemperature.py; README): the heat, the kT of the
    neighbours' relative velocities, is what the thermostat holds. Without chains the flow's viscous
    heating raises it by H0 = pair kT0 - kT_set; the chains slow the flow and carry part of the
    stress, so the heat of a chain case lies between the set kT and the chain-free flow's:
    kT_set - 3 sigma < pair kT < pair kT0 + 3 sigma (Student-t, combined errors for the upper bound)."""
    for c in chain_cases:
        above, below = c.kT_pair.value - ref.kT_pair.value, c.kT_pair.value - KT_SET
        _, allow_up, dof_up = combined(c.kT_pair.term(), ref.kT_pair.term())
        allow_down = student_t(Z_SIGMA, c.kT_pair.dof) * c.kT_pair.error
        checks.add(f"the chains add no heat to the bulk, {c.label}: kT_set - 3 sigma < pair kT < pair kT(no chains) + 3 sigma",
                   above < allow_up and below > -allow_down,
                   f"pair kT {c.kT_pair.fmt(5)}: {above:+.5f} from no chains (3 sigma {allow_up:.5f}, dof {dof_up:.0f}), "
                   f"{below:+.5f} from kT_set (3 sigma {allow_down:.5f}); bins' kT {c.kT.value - ref.kT.value:+.5f} "
                   f"from no chains, of which shared motion {c.kT_shared.value - ref.kT_shared.value:+.5f}")


def deficit_checks(checks, n_sweep, l_sweep):
    """The velocity deficit grows with nChain and with ChainLen: each step of each sweep lowers the flux
    by more than 3 combined standard errors (the deficits differ by (U_prev - U_next) / U0; the error of
    U0 scales both alike and is left out of the step)."""
    done = set()
    for name, series in (("nChain", n_sweep), ("ChainLen", l_sweep)):
        for prev, nxt in zip(series[:-1], series[1:]):
            if (prev.label, nxt.label) in done:
                continue
            done.add((prev.label, nxt.label))
            step = prev.U.value - nxt.U.value
            sigma, allow, dof = combined(prev.U.term(), nxt.U.term())
            checks.add(f"velocity deficit grows with {name}: {prev.label} -> {nxt.label}, U drops by more than 3 sigma",
                       step > allow, f"deficit {prev.deficit:.4f} -> {nxt.deficit:.4f}, U {prev.U.value:.4f} -> "
                       f"{nxt.U.value:.4f}: drop {step:+.4f} = {step / sigma:.1f} sigma, 3 sigma = {allow:.4f} "
                       f"(sigma {sigma:.4f}, dof {dof:.0f})")


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
    ref, chain_cases, n_sweep, l_sweep = sweeps(cases)
    too_few = [c.label for c in cases if c.m < 4]
    if too_few:
        sys.exit(f"plotResults: fewer than 4 super-blocks of {super_block:g} in {', '.join(too_few)}: run longer")
    # Per case: the deficit of the flux against no chains, and its error.
    for c in cases:
        ratio = c.U.value / ref.U.value
        c.deficit = 1.0 - ratio
        c.deficit_error = 0.0 if c is ref else ratio * math.hypot(c.U.error / c.U.value, ref.U.error / ref.U.value)
        c.uc_deficit = 1.0 - c.uc.value / ref.uc.value

    checks = Checks()
    heat_checks(checks, chain_cases, ref)
    # Beads depleted at the walls: bead density within one cutoff of a wall over the bulk's, below 1 by
    # more than 3 standard errors (of the ratio over the super-blocks).
    for c in chain_cases:
        allow = student_t(Z_SIGMA, c.depletion.dof) * c.depletion.error
        checks.add(f"beads depleted at the walls, {c.label}: 1 - rho_near / rho_bulk > 3 sigma", 1.0 - c.depletion.value > allow,
                   f"rho_near / rho_bulk = {c.depletion.fmt(4)}, 1 - ratio = {1 - c.depletion.value:.4f}, 3 sigma = {allow:.4f}")
    deficit_checks(checks, n_sweep, l_sweep)

    write_results(results, results_lines(cases, ref, test, low_g), checks)
    plot(picture, cases, ref, n_sweep, l_sweep, low_g)
    print(f"Written {picture} and {results}")
    return checks.status()


def case_lines(c):
    """A case's block of results.dat."""
    lines = ["", f"case {c.label}  (nChain {c.chains}, ChainLen {c.length}, beads {c.beads}; {c.path})",
             f"  U              {c.U.fmt(4)}", f"  uc             {c.uc.fmt(4)}",
             f"  deficit        {c.deficit:.4f} +- {c.deficit_error:.4f}   (centre velocity: {c.uc_deficit:.4f})",
             f"  nu             {c.nu.value:.4f} +- {c.nu.error:.4f}   (fit chi2/dof {c.fit.get('chi2PerDof', float('nan')):.1f})",
             f"  kT bulk        {c.kT.fmt(5)}   (channel mean {c.kT_mean:.5f})", f"  kT fluid bulk  {c.kT_fluid.fmt(5)}",
             f"  kT split       pair (heat) {c.kT_pair.fmt(5)}, shared by neighbours {c.kT_shared.fmt(5)}, "
             f"single {c.kT_single.fmt(5)}   ({c.snapshots} snapshots)"]
    if c.chains:
        lines += [f"  kT beads bulk  {c.kT_beads.fmt(5)}",
                  f"  bead density   bulk {c.bead_bulk.fmt(4)}, within 1 of a wall {c.bead_near.fmt(4)}; near/bulk {c.depletion.fmt(4)}",
                  f"  Rg2            {c.Rg2.fmt(2)}   (R_g {math.sqrt(c.Rg2.value):.3f})", f"  Ree2           {c.Ree2.fmt(1)}",
                  f"  Reex2          {c.Reex2.fmt(1)}", f"  spanx          {c.spanx.fmt(3)}"]
    return lines + [f"  Re {c.reynolds:.0f}  Ma {c.mach:.3f}",
                    f"  run            {c.particles} particles, {c.steps} steps in {c.seconds:.0f} s, {c.rate:.3e} particle-steps/s"]


def table_line(c):
    """A case's row of the table (NaN where a case without chains has no beads or chains)."""
    pair = lambda s: [s.value, s.error]  # noqa: E731
    chains = ([*pair(c.depletion), *pair(c.Rg2), *pair(c.Ree2), *pair(c.Reex2), *pair(c.spanx)] if c.chains
              else [float("nan")] * 10)
    row = ([c.chains, c.length, c.beads, *pair(c.U), *pair(c.uc), c.deficit, c.deficit_error, *pair(c.nu), *pair(c.kT),
            *pair(c.kT_fluid)] + (pair(c.kT_beads) if c.chains else [float("nan")] * 2) + [*pair(c.kT_pair), *pair(c.kT_shared)]
           + chains + [c.reynolds, c.mach, c.rate, c.seconds])
    return "table " + c.label.replace(" ", "_") + " " + " ".join(f"{v:.6g}" for v in row)


def same_beads_lines(cases):
    """The pairs of cases with the same number of beads: more chains against longer chains."""
    by_beads = {}
    for c in cases:
        if c.chains:
            by_beads.setdefault(c.beads, []).append(c)
    lines = ["", "# same number of beads, more chains against longer chains"]
    for beads, pair in sorted(by_beads.items()):
        if len(pair) == 2:
            a, b = sorted(pair, key=lambda c: -c.chains)
            lines.append(f"beads {beads}: {a.label} | {b.label}: deficit {a.deficit:.4f} +- {a.deficit_error:.4f} | "
                         f"{b.deficit:.4f} +- {b.deficit_error:.4f}; nu {a.nu.value:.4f} | {b.nu.value:.4f}; "
                         f"near/bulk {a.depletion.value:.3f} | {b.depletion.value:.3f}; Rg2 {a.Rg2.value:.1f} | {b.Rg2.value:.1f}; "
                         f"spanx {a.spanx.value:.2f} | {b.spanx.value:.2f}; kT {a.kT.value:.4f} | {b.kT.value:.4f}")
    return lines


def results_lines(cases, ref, test, low_g):
    c0 = cases[0]
    lines = [f"# FENE chains in Poiseuille flow between frozen walls (docs/scenes.md scene 7){' [test]' if test else ''}"
             f"{' [low-g variant]' if low_g else ''}",
             f"# d = {c0.d:g}, g = {c0.g:g}; sampled {c0.start:g}-{c0.end:g}; errors: standard errors over "
             f"{c0.m} super-blocks of {c0.super_time:g} time units",
             "# U: mean velocity of all mobile particles (flux / (rho d)); uc: velocity within 1 of the centre;",
             "# deficit: 1 - U / U(no chains); nu: fitSlipLength's parabola (effective viscosity), jackknife error;",
             "# kT: bulk (central half of the channel), all mobile particles (fluid and beads) and the beads alone;",
             "# kT split (etc/pairTemperature.py, snapshots): pair = the neighbours' relative velocities (heat),",
             "#   shared = <dv_i . dv_j> / 3 over neighbours (motion they share), single = <dv^2> / 3;",
             "# near/bulk: bead density within 1 of a wall over the bead density of the central half;",
             "# Rg2, Ree2, Reex2 (<R_ee,x^2>), spanx (max - min bead x, the extension along the flow): chain means",
             f"# Re = uc d / nu; Ma = uc / c, c = sqrt(kT + 2 alpha a rho) = sqrt(1 + 2 x {ALPHA_GW} x {A_FF:g} x {RHO:g}) = {SOUND_SPEED:.3f}"]
    lines += [line for c in cases for line in case_lines(c)]
    lines += ["", "# table: case nChain ChainLen beads U U_err uc uc_err deficit deficit_err nu nu_err kT kT_err kTfluid "
              "kTfluid_err kTbeads kTbeads_err kTpair kTpair_err kTshared kTshared_err nearOverBulk err Rg2 err Ree2 err "
              "Reex2 err spanx err Re Ma particleSteps/s seconds"] + [table_line(c) for c in cases]
    return lines + same_beads_lines(cases) + [
        "", f"# viscous heating of the bulk without chains (pair kT): H0 = pair kT0 - kT_set = {ref.kT_pair.value - KT_SET:+.5f}",
        f"# cost of the bonds: particle-steps/s without chains {ref.rate:.3e}; "
        + ", ".join(f"{c.label} {c.rate:.3e} ({100 * (c.rate / ref.rate - 1):+.1f} %)" for c in cases if c.chains)]


def draw_profiles(ax, cases, ref, colour):
    """Velocity, density, kT (all mobile particles, the fluid, the beads), bead density and R_g^2 across
    the channel, one colour per case; the walls dotted, the central half's edges dashed."""
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
            b, cb = c.bead_table, c.chain_bins
            ax[0, 3].plot(b["z"][b["count"] > 0], b["kT"][b["count"] > 0], "--", color=col, lw=1.0, label=f"{c.label} beads")
            ax[1, 0].errorbar(b["z"], b["density"], yerr=b["densityErr"], fmt="-", color=col, lw=1.2,
                              label=f"{c.label}: near/bulk {c.depletion.value:.3f}")
            ax[1, 3].plot(cb["z"][cb["samples"] > 0], cb["Rg2"][cb["samples"] > 0], "o-", color=col, ms=3, label=c.label)
    for a, title, ylabel in ((ax[0, 0], "velocity (fluid and beads)", "u_x"),
                             (ax[0, 1], "density (fluid and beads)", "number density"),
                             (ax[0, 2], "kT about the local flow (fluid and beads); dashed: the bulk's heat", "kT"),
                             (ax[0, 3], "kT of the fluid (solid) and of the beads (dashed)", "kT"),
                             (ax[1, 0], "bead density", "bead number density"),
                             (ax[1, 3], "R_g^2 by where the chain's centre lies", "<R_g^2>")):
        label(a, title, "z", ylabel, legend=7)
        mark_walls(a, ref.walls)
    mark_walls([ax[0, 2], ax[0, 3], ax[1, 0]], (ref.centre - 0.25 * ref.d, ref.centre + 0.25 * ref.d), color="k", lw=0.6, ls="--")
    for a in (ax[0, 2], ax[0, 3]):
        a.axhline(KT_SET, color="k", lw=0.8)
        a.set_ylim(0.97, 1.12)
    ax[1, 3].set_yscale("log")


def draw_sweeps(ax, cases, ref, n_sweep, l_sweep, colour):
    """Chain size against nChain and ChainLen, the deficit against the beads, the start-up."""
    for a, series, key, xlabel in ((ax[1, 1], n_sweep, "chains", "nChain"), (ax[1, 2], l_sweep, "length", "ChainLen")):
        s = [c for c in series if c.chains]
        x = [getattr(c, key) for c in s]
        for get, fmt, name in ((lambda c: c.Rg2, "o-", "R_g = sqrt<R_g^2>"), (lambda c: c.Ree2, "s-", "sqrt<R_ee^2>")):
            a.errorbar(x, [math.sqrt(get(c).value) for c in s], yerr=[0.5 * get(c).error / math.sqrt(get(c).value) for c in s],
                       fmt=fmt, label=name)
        a.errorbar(x, [c.spanx.value for c in s], yerr=[c.spanx.error for c in s], fmt="^-", label="extension along x (span)")
        label(a, f"chain size against {xlabel} ({'ChainLen' if key == 'chains' else 'nChain'} "
                 f"{s[0].length if key == 'chains' else s[0].chains})", xlabel, "length", legend=8)
    for series, name, marker in ((n_sweep, "nChain sweep", "o-"), (l_sweep, "ChainLen sweep", "s--")):
        ax[2, 0].errorbar([c.beads for c in series], [c.deficit for c in series], yerr=[c.deficit_error for c in series],
                          fmt=marker, label=name)
        for c in series[1:]:
            ax[2, 0].annotate(c.label, (c.beads, c.deficit), fontsize=8, xytext=(4, -10), textcoords="offset points")
    label(ax[2, 0], "velocity deficit", "beads (nChain x ChainLen)", "flux deficit 1 - U / U(no chains)", legend=8)
    for c in cases:  # the log's mean velocity of the mobile particles
        if len(c.history[0]):
            ax[2, 1].plot(*c.history, "-", color=colour[c.label], lw=1, label=c.label)
    ax[2, 1].axvspan(ref.window_start, ref.end, color="0.9", label="sampled")
    label(ax[2, 1], "start-up (the run's log)", "time", "mean velocity of the mobile particles", legend=7)


def draw_chains(a, show):
    """The chains of a case, x-z, each unwrapped from its bond vectors with its centre in the box."""
    lo, hi = snapshot_box(show.snapshot)
    length = hi[0] - lo[0]
    for k, (c, p) in enumerate(sorted(unwrapped_chains(show.snapshot).items())):
        shift = length * np.floor((p[:, 0].mean() - lo[0]) / length)  # the chain's centre into the box
        a.plot(p[:, 0] - shift, p[:, 2], "-", color=plt.cm.tab20(k % 20), lw=0.8)
        a.plot(p[:, 0] - shift, p[:, 2], ".", color=plt.cm.tab20(k % 20), ms=2.5)
    a.axvline(lo[0], color="k", lw=0.6); a.axvline(hi[0], color="k", lw=0.6)
    for zw in show.walls:
        a.axhline(zw, color="gray", ls=":")
    label(a, f"{show.label}: the chains at t = {os.path.basename(os.path.dirname(show.snapshot))}, x-z projection, "
             "one colour per chain", "x (each chain unwrapped from its bond vectors, its centre in the box; box edges marked)", "z")
    a.set_aspect("equal", adjustable="datalim")


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
    draw_profiles(ax, cases, ref, colour)
    draw_sweeps(ax, cases, ref, n_sweep, l_sweep, colour)
    draw_chains(ax[2, 2], max((c for c in cases if c.chains), key=lambda c: (c.length, c.beads)))
    fig.suptitle(f"FENE chains in Poiseuille flow, d = {ref.d:g}, g = {ref.g:g}{' (low-g variant)' if low_g else ''}: "
                 f"no chains U = {ref.U.value:.3f}, Re = {ref.reynolds:.0f}, Ma = {ref.mach:.2f}")
    save(fig, path, dpi=90, rect=(0, 0, 1, 0.97))


if __name__ == "__main__":
    sys.exit(main())
