"""The polymer channel (tutorials/polymer/channel, docs/scenes.md scene 7; Zhou, Liu and Chang): FENE
chains in Poiseuille flow between frozen walls, one case of runSweep's sweep of nChain and ChainLen each.

    cases = [Case(path, chains, length) ...]; ref, chain_cases, n_sweep, l_sweep = sweeps(cases)
    heat_checks(checks, chain_cases, ref, budget); depletion_checks(...); deficit_checks(...)
    symmetry_check(...); extension_checks(...)          # each check's budget: the tutorial's
    write_results(path, results_lines(cases, ref, test, name), checks); plot(picture, cases, ref, ...)

A case's flow and heat over fitSlipLength's super-blocks (dpdfoam.channel_blocks.SuperBlockChannel), its
beads, chains and the paper's grid; the checks that a difference is absent (the chains' heat, the
chain-free profile's asymmetry: the difference's standard error first within the tutorial's budget over
MIN_SUPER_BLOCKS super-blocks at least, then within DIFFERENCE_BOUND budgets, a bound no run's noise
widens) and that an effect is present (the deficit's steps, the depletion, the outer chains' extension:
above 3 standard errors of the run, which noise only makes harder); results<variant>.dat's lines and
polymerChannel<variant>.png. Why the errors come from super-blocks of ~2 tau1: the tutorial's
plotResults.py ("Error bars").
"""
import math
import os
import sys

import numpy as np

from .blocks import band_share
from .channel_blocks import SuperBlockChannel
from .checks import as_number, bounded_verdict
from .grid import averaged_along, image
from .io import dictionary_value, latest_dir, latest_profile, read_columns, read_table
from .plots import draw_chains_xz, draw_field, label, label_panels, mark_walls, plt, save, stat_bars
from .snapshots import chains_in_box, extension_by_offset, extension_rows
from .stats import Z_SIGMA, BlockMean as Stat, combined, student_t, values_and_errors
from .sweep import sweep_colours

# The fluid (constant/dpdProperties): kT, a, rho, and Groot and Warren's equation of state
# p = rho kT + alpha a rho^2 (alpha = 0.101), whose isothermal sound speed is c^2 = dp/drho = kT + 2 alpha a rho.
KT_SET, A_FF, RHO, ALPHA_GW = 1.0, 18.75, 4.0, 0.101
SOUND_SPEED = math.sqrt(KT_SET + 2.0 * ALPHA_GW * A_FF * RHO)

# The regions across the channel, as fractions of the half-height h = d / 2 about the centre: the
# published share of beads within |z| <= 10 (h = 15: two thirds of h); the central chains (centre
# within h / 3) against the outer ones (beyond 2 h / 3).
SHARE_FRACTION, CENTRAL_FRACTION, OUTER_FRACTION = 2.0 / 3.0, 1.0 / 3.0, 2.0 / 3.0

# The checks that a difference is absent hold it within DIFFERENCE_BOUND budgets (the tutorial's), fixed.
DIFFERENCE_BOUND = 3.0  # the bounds, in budgets
# The fewest super-blocks a standard error is taken from: from 4 (3 degrees of freedom) it scatters by
# +-41 % and Student's factor for "3 standard errors" is 9.0; fitSlipLengthDict's minimum is 4, the
# runs hold 5 (full size) and 8 (the test and the lattice-wall variant).
MIN_SUPER_BLOCKS = 5


class Case(SuperBlockChannel):
    """One case of the sweep: its flow and heat (SuperBlockChannel), beads, chains and the paper's grid."""

    def __init__(self, path, chains, length):
        super().__init__(path, "channelProfile")
        self.chains, self.length = int(chains), int(length)
        self.beads = self.chains * self.length
        self.label = "no chains" if self.chains == 0 else f"{self.chains}x{self.length}"
        pp = self.profiles
        self.table, self.fluid_table = (read_table(os.path.join(pp, f"{n}Profile.dat")) for n in ("channel", "fluid"))
        self.bead_table = read_table(os.path.join(pp, "beadProfile.dat")) if self.chains else None
        self.snapshot, self.snapshot0 = os.path.join(self.time_dir, "particles.h5"), os.path.join(path, "0", "particles.h5")
        self.measure_flow()
        self.measure_heat()
        _, fluid_bulk, fluid_near, self.kT_fluid = self.regions(self.sampled("fluidProfile"))
        self.fluid_bulk, self.fluid_near = Stat(fluid_bulk), Stat(fluid_near)
        if self.chains:
            self._beads(self.sampled("beadProfile"))
            self._chains(latest_dir(os.path.join(path, "postProcessing/chains/*")))
            self._extension()
        self._paper(os.path.join(path, "system/controlDict"), pp)
        self.read_log()

    def _beads(self, bins):
        sums, bulk_rho, near_rho, self.kT_beads = self.regions(bins)
        self.bead_bulk, self.bead_near = Stat(bulk_rho), Stat(near_rho)
        self.depletion = Stat(near_rho / bulk_rho, near_rho.mean() / bulk_rho.mean())
        count = sums[..., 0]
        # The beads' share within |z| <= 2 h / 3 (10 at h = 15), and in the upper half of the channel.
        self.share_edge = SHARE_FRACTION * self.h
        self.share = Stat(band_share(count, bins.z, bins.width, self.centre - self.share_edge, self.centre + self.share_edge))
        self.upper_share = Stat(count[:, bins.z > self.centre].sum(axis=1) / count.sum(axis=1))

    def _chains(self, directory):
        data = np.loadtxt(os.path.join(directory, "chainStatistics.dat"), comments="#", ndmin=2)
        self.Rg2, self.Ree2, self.Reex2, self.spanx = self.window.column_means(data, (1, 2, 4, 5), closed=False)
        # R_g^2 and span by where the chain's centre lies across the channel (the whole sampling).
        self.chain_bins = read_columns(os.path.join(directory, "chainBins.dat"), ("z", "samples", "Rg2", "spanx"))

    def _extension(self):
        """The chains' extension along the flow (span x) and R_g^2 by where their centre lies, from the
        snapshots (chainExtension.py, dpdfoam.snapshots): the central chains (centre within h / 3 of the channel's centre)
        against the outer ones (beyond 2 h / 3), per super-block, and binned across the channel. The slope of
        span_x on the distance from the centre counts every chain (what the check reads: the outer third
        holds few chains where the beads are depleted at the walls)."""
        rows = extension_rows(self.path, "channelProfile")
        if rows is None:
            sys.exit(f"plotResults: {self.path} has neither postProcessing/chainExtension nor the snapshots to measure it")
        self.central_edge, self.outer_edge = CENTRAL_FRACTION * self.h, OUTER_FRACTION * self.h
        # Binned by the centre (bins of 2, as chainBins), errors over the super-blocks.
        edges = np.arange(self.walls[0], self.walls[1] + 1e-9, 2.0 if self.d > 12 else 1.0)
        self.ext = extension_by_offset(rows, self.window, self.centre, self.central_edge, self.outer_edge, edges)

    def _paper(self, control, pp):
        """The paper's grid over its window (paperField, paperFluid, paperBeads: 200 x 20 bins in the
        z-x plane, the last 400 time units), averaged over x; None where the case has no such grid."""
        self.paper = None
        if not os.path.exists(os.path.join(pp, "paperField.dat")):
            return
        field, fluid, beads = (averaged_along(read_table(os.path.join(pp, f"paper{n}.dat"))) for n in ("Field", "Fluid", "Beads"))
        z = field["z"]
        bulk, near = self.bulk(z), self.near(z)
        p = {"start": float(dictionary_value(control, "functions/paperField/startTime")), "nz": len(z), "nx": field["nx"],
             "field": field, "fluid": fluid, "beads": beads, **self.grid_flow(field),
             "fluid_bulk": float(fluid["density"][bulk].mean()), "fluid_near": float(fluid["density"][near].mean())}
        if self.chains:
            edge = self.share_edge
            p["share"] = float(band_share(beads["count"], z, z[1] - z[0], self.centre - edge, self.centre + edge))
            p["near_bulk"] = float(beads["density"][near].mean() / beads["density"][bulk].mean())
        self.paper = p

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


def enough_blocks(blocks):
    """(passed, why): whether a standard error comes from MIN_SUPER_BLOCKS super-blocks at least."""
    blocks = as_number(blocks)
    if blocks >= MIN_SUPER_BLOCKS:
        return True, ""
    return False, f"{blocks:g} super-blocks, fewer than {MIN_SUPER_BLOCKS}: no verdict on a standard error from so few"


def heat_check(checks, label, pair, pair_error, ref_pair, ref_pair_error, blocks, budget, text=""):
    """The chains add no heat to the bulk, one case (issue 45). The heat is the pair kT (the kT of the
    neighbours' relative velocities, etc/pairTemperature.py): the bins' kT of the bulk rises with chains at
    the published g, but what rises is motion neighbours share (README), and the heat is what the
    thermostat holds. Without chains the flow's viscous heating raises it; the chains slow the flow and
    carry part of the stress, so the heat of a chain case lies between the set kT and the chain-free
    flow's: pair kT - pair kT(no chains) <= 3 budgets and pair kT - kT_set >= -3 budgets, each difference's
    standard error first within the budget (the case's and the chain-free case's errors in quadrature
    above, the case's below), from MIN_SUPER_BLOCKS super-blocks at least. Plain numbers; a NaN, missing
    or empty one fails."""
    pair, pair_error, ref_pair, ref_pair_error = (as_number(v) for v in (pair, pair_error, ref_pair, ref_pair_error))
    bound = DIFFERENCE_BOUND * budget
    above, above_error = pair - ref_pair, math.hypot(pair_error, ref_pair_error)
    below = pair - KT_SET
    up_ok, up = bounded_verdict(above, above_error, budget, None, bound)
    down_ok, down = bounded_verdict(below, pair_error, budget, -bound, None)
    blocks_ok, few = enough_blocks(blocks)
    shown = f"; {text}" if text else ""
    return checks.add(f"the chains add no heat to the bulk, {label}: pair kT - pair kT(no chains) <= {bound:g} and pair kT - "
                      f"kT_set >= -{bound:g} ({DIFFERENCE_BOUND:g} x {budget:g}; standard errors below {budget:g}, "
                      f"{MIN_SUPER_BLOCKS} super-blocks at least)", up_ok and down_ok and blocks_ok,
                      f"pair kT {pair:.5f} +- {pair_error:.5f}: from no chains {up}; from kT_set {down}"
                      f"{'; ' + few if few else ''}{shown}")


def heat_checks(checks, chain_cases, ref, budget):
    """heat_check for every chain case, the bins' kT and the shared motion beside it."""
    for c in chain_cases:
        heat_check(checks, c.label, c.kT_pair.value, c.kT_pair.error, ref.kT_pair.value, ref.kT_pair.error,
                   min(c.window.m, ref.window.m), budget,
                   f"bins' kT {c.kT.value - ref.kT.value:+.5f} from no chains, of which shared motion "
                   f"{c.kT_shared.value - ref.kT_shared.value:+.5f}")


def allowance(error, dof):
    """3 standard errors read as the Student-t quantile of the same tail for dof (BlockMean.allowance); NaN
    (fails) without a degree of freedom."""
    dof = as_number(dof)
    return student_t(Z_SIGMA, dof) * as_number(error) if dof > 0 else float("nan")


def depletion_check(checks, label, ratio, error, dof):
    """Beads depleted at the walls, one case: the bead density within one cutoff of a wall over the bulk's
    (ratio, its standard error over dof + 1 super-blocks), below 1 by more than 3 standard errors."""
    ratio, error = as_number(ratio), as_number(error)
    allow = allowance(error, dof)
    return checks.add(f"beads depleted at the walls, {label}: 1 - rho_near / rho_bulk > 3 sigma", 1.0 - ratio > allow,
                      f"rho_near / rho_bulk = {ratio:.4f} +- {error:.4f}, 1 - ratio = {1 - ratio:.4f}, 3 sigma = {allow:.4f}",
                      ratio, error)


def depletion_checks(checks, chain_cases):
    """depletion_check for every chain case."""
    for c in chain_cases:
        depletion_check(checks, c.label, c.depletion.value, c.depletion.error, c.depletion.dof)


def deficit_step_check(checks, name, prev, nxt):
    """One step of a sweep lowers the flux by more than 3 combined standard errors. prev and nxt: (label,
    U, U's standard error, its degrees of freedom, deficit) of the two cases, plain numbers (the deficits
    differ by (U_prev - U_next) / U0; the error of U0 scales both alike and is left out of the step)."""
    (label_p, u_p, e_p, dof_p, deficit_p), (label_n, u_n, e_n, dof_n, deficit_n) = prev, nxt
    u_p, e_p, u_n, e_n, deficit_p, deficit_n = (as_number(v) for v in (u_p, e_p, u_n, e_n, deficit_p, deficit_n))
    step, dof_p, dof_n = u_p - u_n, as_number(dof_p), as_number(dof_n)
    if dof_p > 0 and dof_n > 0:
        sigma, allow, dof = combined((e_p, dof_p), (e_n, dof_n))
    else:  # no degree of freedom: no error to allow for (fails)
        sigma, allow, dof = math.hypot(e_p, e_n), float("nan"), float("nan")
    with np.errstate(divide="ignore", invalid="ignore"):
        z = np.float64(step) / sigma
    return checks.add(f"velocity deficit grows with {name}: {label_p} -> {label_n}, U drops by more than 3 sigma",
                      step > allow, f"deficit {deficit_p:.4f} -> {deficit_n:.4f}, U {u_p:.4f} -> "
                      f"{u_n:.4f}: drop {step:+.4f} = {z:.1f} sigma, 3 sigma = {allow:.4f} "
                      f"(sigma {sigma:.4f}, dof {dof:.0f})", step, sigma, dof_p, dof_n)


def deficit_checks(checks, n_sweep, l_sweep):
    """The velocity deficit grows with nChain and with ChainLen: deficit_step_check for each step of each
    sweep (a step both sweeps share, once)."""
    done = set()
    for name, series in (("nChain", n_sweep), ("ChainLen", l_sweep)):
        for prev, nxt in zip(series[:-1], series[1:]):
            if (prev.label, nxt.label) in done:
                continue
            done.add((prev.label, nxt.label))
            deficit_step_check(checks, name, *((c.label, c.U.value, c.U.error, c.U.dof, c.deficit) for c in (prev, nxt)))


def symmetry_check(checks, asymmetry, error, u, blocks, budget, text=""):
    """Without chains the channel is symmetric (issue 45): the two halves' mean velocities apart over the
    mean velocity U, its standard error first within the budget (of U) from MIN_SUPER_BLOCKS super-blocks
    at least, then within the fixed bound of 3 budgets. Plain numbers; a NaN, missing or empty one fails."""
    asymmetry, error, u = as_number(asymmetry), as_number(error), as_number(u)
    bound = DIFFERENCE_BOUND * budget
    ok, verdict = bounded_verdict(*(v / u if u != 0 else float("nan") for v in (asymmetry, error)), budget, -bound, bound)
    blocks_ok, few = enough_blocks(blocks)
    shown = f"; {text}" if text else ""
    return checks.add(f"the profile without chains is symmetric: |U(upper half) - U(lower half)| / U <= {bound:g} "
                      f"({DIFFERENCE_BOUND:g} x {budget:g}; standard error below {budget:g}, {MIN_SUPER_BLOCKS} super-blocks at "
                      f"least)", ok and blocks_ok, f"U(upper) - U(lower) = {asymmetry:.5f} +- {error:.5f}: {verdict}"
                      f"{'; ' + few if few else ''}{shown}")


def extension_check(checks, label, slope, error, dof, text=""):
    """The chains' extension along the flow grows towards the walls, one case: the slope of span_x on the
    distance of the chain's centre from the channel's centre (extension_checks: why), above 3 standard
    errors (dof: its degrees of freedom); text: the outer and central chains' spans beside it."""
    slope, error = as_number(slope), as_number(error)
    allow = allowance(error, dof)
    return checks.add(f"the chains' extension along the flow grows towards the walls, {label}: slope of span_x on |z_c| > 3 sigma",
                      slope > allow, f"slope {slope:.4f} +- {error:.4f}, 3 sigma = {allow:.4f}{'; ' + text if text else ''}",
                      slope, error)


def extension_checks(checks, chain_cases):
    """The chains near the walls, in the strongest shear, are more extended along the flow than those
    about the centre, where the shear vanishes: the slope of span_x on the distance of the chain's centre
    from the channel's centre (every chain of every snapshot, fitted per super-block) above 3 standard
    errors (extension_check). The outer third against the central third (the papers' comparison) is
    reported beside it: where the beads are depleted at the walls the outer third holds few chains, too
    few for a check."""
    for c in chain_cases:
        s, e = c.ext["slope"], c.ext
        extension_check(checks, c.label, s.value, s.error, s.dof,
                        f"span_x outer (|z_c| > {c.outer_edge:.3g}) {e['outer']['spanx'].fmt(3)}, "
                        f"central (|z_c| < {c.central_edge:.3g}) {e['central']['spanx'].fmt(3)}")


def case_lines(c):
    """A case's block of results.dat."""
    a = c.asym
    lines = ["", f"case {c.label}  (nChain {c.chains}, ChainLen {c.length}, beads {c.beads}; {c.path})",
             f"  U              {c.U.fmt(4)}", f"  uc             {c.uc.fmt(4)}",
             f"  deficit        {c.deficit:.4f} +- {c.deficit_error:.4f}   (centre velocity: {c.uc_deficit:.4f})",
             f"  asymmetry      U(upper half) - U(lower half) {a['A'].fmt(4)} ({a['A'].value / c.U.value:+.4f} U); "
             f"u(z) - u(-z) over {a['pairs']} pairs of bins: rms {a['rms']:.4f}, its noise {a['noise']:.4f}, "
             f"largest {a['max']:.4f}, chi2/dof {a['chi2']:.2f}",
             f"  nu             {c.nu.value:.4f} +- {c.nu.error:.4f}   (fit chi2/dof {c.fit.get('chi2PerDof', float('nan')):.1f})",
             f"  kT bulk        {c.kT.fmt(5)}   (bins; channel mean {c.kT_mean:.5f})", f"  kT fluid bulk  {c.kT_fluid.fmt(5)}",
             f"  kT split       pair (heat) {c.kT_pair.fmt(5)}, shared by neighbours {c.kT_shared.fmt(5)}, "
             f"single {c.kT_single.fmt(5)}   ({c.snapshots} snapshots)",
             f"  fluid density  bulk {c.fluid_bulk.fmt(4)}, within 1 of a wall {c.fluid_near.fmt(4)}"]
    if c.chains:
        e = c.ext
        lines += [f"  kT beads bulk  {c.kT_beads.fmt(5)}",
                  f"  bead density   bulk {c.bead_bulk.fmt(4)}, within 1 of a wall {c.bead_near.fmt(4)}; near/bulk {c.depletion.fmt(4)}",
                  f"  bead share     within |z| <= {c.share_edge:.3g}: {c.share.fmt(4)} (uniform {c.share_edge / c.h:.4f}); "
                  f"upper half {c.upper_share.fmt(4)}",
                  f"  Rg2            {c.Rg2.fmt(2)}   (R_g {math.sqrt(c.Rg2.value):.3f})", f"  Ree2           {c.Ree2.fmt(1)}",
                  f"  Reex2          {c.Reex2.fmt(1)}", f"  spanx          {c.spanx.fmt(3)}",
                  f"  extension      span_x outer (|z_c| > {c.outer_edge:.3g}) {e['outer']['spanx'].fmt(3)}, central "
                  f"(|z_c| < {c.central_edge:.3g}) {e['central']['spanx'].fmt(3)}: ratio {e['ratio']:.3f}, slope on |z_c| "
                  f"{e['slope'].fmt(4)}; R_g^2 outer "
                  f"{e['outer']['Rg2'].fmt(2)}, central {e['central']['Rg2'].fmt(2)}; chains per snapshot {e['outer']['chains']:.1f} "
                  f"outer, {e['central']['chains']:.1f} central ({e['snapshots']} snapshots)"]
    if c.paper:
        p = c.paper
        line = (f"  paper's grid   {p['nz']} x {p['nx']} (z x), t {p['start']:g}-{c.end:g}: U {p['U']:.4f}, uc {p['uc']:.4f}, "
                f"U(upper) - U(lower) {p['A']:+.4f}, kT bulk {p['kT']:.5f}, fluid density bulk {p['fluid_bulk']:.4f} "
                f"(within 1 of a wall {p['fluid_near']:.4f})")
        if c.chains:
            line += f", bead share within |z| <= {c.share_edge:.3g} {p['share']:.4f}, bead near/bulk {p['near_bulk']:.4f}"
        lines.append(line)
    return lines + [f"  Re {c.reynolds:.0f}  Ma {c.mach:.3f}",
                    f"  run            {c.particles} particles, {c.steps} steps in {c.seconds:.0f} s, {c.rate:.3e} particle-steps/s"]


def table_line(c):
    """A case's row of the table (NaN where a case without chains has no beads or chains, or a case no
    paper's grid)."""
    nan = float("nan")
    row = ([c.chains, c.length, c.beads, *values_and_errors(c.U, c.uc), c.deficit, c.deficit_error,
            *values_and_errors(c.nu, c.kT, c.kT_fluid)] + (values_and_errors(c.kT_beads) if c.chains else [nan] * 2)
           + values_and_errors(c.kT_pair, c.kT_shared)
           + (values_and_errors(c.depletion, c.Rg2, c.Ree2, c.Reex2, c.spanx) if c.chains else [nan] * 10)
           + [c.reynolds, c.mach, c.rate, c.seconds, *values_and_errors(c.asym["A"], c.fluid_bulk, c.fluid_near)]
           + (values_and_errors(c.share, c.ext["outer"]["spanx"], c.ext["central"]["spanx"]) if c.chains else [nan] * 6)
           + ([c.paper["U"], c.paper["A"], c.paper.get("share", nan)] if c.paper else [nan] * 3))
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
                         f"near/bulk {a.depletion.value:.3f} | {b.depletion.value:.3f}; share {a.share.value:.3f} | {b.share.value:.3f}; "
                         f"Rg2 {a.Rg2.value:.1f} | {b.Rg2.value:.1f}; spanx {a.spanx.value:.2f} | {b.spanx.value:.2f}; "
                         f"kT {a.kT.value:.4f} | {b.kT.value:.4f}")
    return lines


def results_lines(cases, ref, test, name):
    c0 = cases[0]
    lines = [f"# FENE chains in Poiseuille flow between frozen walls (docs/scenes.md scene 7){' [test]' if test else ''}"
             f"{f' [{name}]' if name else ''}",
             f"# d = {c0.d:g}, g = {c0.g:g}; sampled {c0.start:g}-{c0.end:g}; errors: standard errors over "
             f"{c0.window.m} super-blocks of {c0.window.length:g} time units",
             "# U: mean velocity of all mobile particles (flux / (rho d)); uc: velocity within 1 of the centre;",
             "# deficit: 1 - U / U(no chains); asymmetry: U(upper half) - U(lower half) and u(z) - u(-z) per pair of bins",
             "#   (rms, its noise = the rms of the pairs' standard errors, largest, chi2/dof against zero);",
             "# nu: fitSlipLength's parabola (effective viscosity), jackknife error;",
             "# kT: bulk (central half of the channel), all mobile particles (fluid and beads) and the beads alone;",
             "# kT split (etc/pairTemperature.py, snapshots): pair = the neighbours' relative velocities (heat),",
             "#   shared = <dv_i . dv_j> / 3 over neighbours (motion they share), single = <dv^2> / 3;",
             "# near/bulk: bead density within 1 of a wall over the bead density of the central half;",
             "# bead share: the beads within two thirds of the half-height of the centre (|z| <= 10 at d = 30);",
             "# Rg2, Ree2, Reex2 (<R_ee,x^2>), spanx (max - min bead x, the extension along the flow): chain means;",
             "# extension: span_x of the chains whose centre lies beyond 2/3 of the half-height (outer) and within 1/3",
             "#   (central), from the snapshots (chainExtension.py);",
             *(["# paper's grid: the 2-D bins of the paper's window averaged along x (no error bar of its own: the window",
                "#   is ~1.2 tau1; the rows above give the errors);"] if c0.paper else []),
             f"# Re = uc d / nu; Ma = uc / c, c = sqrt(kT + 2 alpha a rho) = sqrt(1 + 2 x {ALPHA_GW} x {A_FF:g} x {RHO:g}) = {SOUND_SPEED:.3f}"]
    lines += [line for c in cases for line in case_lines(c)]
    lines += ["", "# table: case nChain ChainLen beads U U_err uc uc_err deficit deficit_err nu nu_err kT kT_err kTfluid "
              "kTfluid_err kTbeads kTbeads_err kTpair kTpair_err kTshared kTshared_err nearOverBulk err Rg2 err Ree2 err "
              "Reex2 err spanx err Re Ma particleSteps/s seconds asymmetry err fluidBulk err fluidNear err share err "
              "spanxOuter err spanxCentral err paperU paperAsymmetry paperShare"] + [table_line(c) for c in cases]
    return lines + same_beads_lines(cases) + [
        "", f"# viscous heating of the bulk without chains (pair kT): H0 = pair kT0 - kT_set = {ref.kT_pair.value - KT_SET:+.5f}",
        f"# cost of the bonds: particle-steps/s without chains {ref.rate:.3e}; "
        + ", ".join(f"{c.label} {c.rate:.3e} ({100 * (c.rate / ref.rate - 1):+.1f} %)" for c in cases if c.chains)]


def draw_profiles(ax, cases, ref, colour):
    """Velocity, density (all mobile particles, the fluid), kT (all, the fluid, the beads), bead density,
    the asymmetry and the chains by where they lie, across the channel, one colour per case; the walls
    dotted, the central half's edges dashed. The paper's grid (its window) dotted over the long window."""
    for c in cases:
        t, f, col, a = c.table, c.fluid_table, colour[c.label], c.asym
        ax[0, 0].errorbar(t["z"], t["ux"], yerr=t["uxErr"], fmt="-", color=col, lw=1.2, label=f"{c.label}: U {c.U.value:.3f}")
        ax[0, 1].plot(t["z"], t["density"], "-", color=col, lw=1.2, label=f"{c.label}: all")
        ax[0, 1].plot(f["z"], f["density"], "--", color=col, lw=1.0, label=f"{c.label}: fluid")
        ax[0, 2].plot(t["z"], t["kT"], "-", color=col, lw=1.2, label=f"{c.label}: bulk {c.kT.value:.4f}")
        # The bulk's heat (pair kT, docs/analysis.md 5.5) over the central half: what the check reads.
        ax[0, 2].plot([c.centre - 0.25 * c.d, c.centre + 0.25 * c.d], [c.kT_pair.value] * 2, "--", color=col, lw=1.0,
                      label=f"{c.label}: heat (pair kT) {c.kT_pair.value:.4f}")
        ax[0, 3].plot(f["z"], f["kT"], "-", color=col, lw=1.2, label=f"{c.label} fluid")
        ax[1, 1].plot(a["z"], a["du"], "-", color=col, lw=1.0, label=f"{c.label}: A {a['A'].value:+.3f} +- {a['A'].error:.3f}")
        ax[1, 1].fill_between(a["z"], -3 * a["err"], 3 * a["err"], color=col, alpha=0.12, lw=0)
        if c.paper:
            ax[0, 0].plot(c.paper["field"]["z"], c.paper["field"]["ux"], ":", color=col, lw=1.0)
        if c.chains:
            b, cb, e = c.bead_table, c.chain_bins, c.ext["bins"]
            ax[0, 3].plot(b["z"][b["count"] > 0], b["kT"][b["count"] > 0], "--", color=col, lw=1.0, label=f"{c.label} beads")
            ax[1, 0].errorbar(b["z"], b["density"], yerr=b["densityErr"], fmt="-", color=col, lw=1.2,
                              label=f"{c.label}: near/bulk {c.depletion.value:.3f}, share {c.share.value:.3f}")
            if c.paper:
                ax[1, 0].plot(c.paper["beads"]["z"], c.paper["beads"]["density"], ":", color=col, lw=1.0)
            ax[1, 2].plot(cb["z"][cb["samples"] > 0], cb["Rg2"][cb["samples"] > 0], "o-", color=col, ms=3, label=c.label)
            ok = np.isfinite(e["spanx"])
            ax[1, 3].errorbar(e["z"][ok], e["spanx"][ok], yerr=e["err"][ok], fmt="o-", color=col, ms=3,
                              label=f"{c.label}: outer / central {c.ext['ratio']:.2f}")
    share = next((c.share_edge for c in cases if c.chains), None)
    dotted = "; dotted: the paper's grid and window" if ref.paper else ""
    across = [ax[0, 0], ax[0, 1], ax[0, 2], ax[0, 3], ax[1, 0], ax[1, 2], ax[1, 3]]
    label_panels(across, [(title, "z", ylabel) for title, ylabel in (
        (f"velocity (fluid and beads){dotted}", "u_x"), ("density: all mobile (solid), the fluid (dashed)", "number density"),
        ("kT about the local flow (fluid and beads); dashed: the bulk's heat", "kT"),
        ("kT of the fluid (solid) and of the beads (dashed)", "kT"),
        (f"bead density{dotted}; dashed: |z| = {share:.3g}" if share else "bead density", "bead number density"),
        ("R_g^2 by where the chain's centre lies (chainStatistics)", "<R_g^2>"),
        ("extension along x (span) by where the chain's centre lies", "span_x"))], legend=7)
    mark_walls(across, ref.walls)
    label(ax[1, 1], "asymmetry u(z) - u(-z); shaded: 3 standard errors", "|z| (distance from the centre)", "u(z) - u(-z)", legend=7)
    ax[1, 1].axhline(0.0, color="k", lw=0.6)
    mark_walls([ax[0, 2], ax[0, 3]], (ref.centre - 0.25 * ref.d, ref.centre + 0.25 * ref.d), color="k", lw=0.6, ls="--")
    if share:
        mark_walls(ax[1, 0], (ref.centre - share, ref.centre + share), color="k", lw=0.6, ls="--")
        c = next(c for c in cases if c.chains)
        mark_walls(ax[1, 3], (c.centre - c.outer_edge, c.centre - c.central_edge, c.centre + c.central_edge, c.centre + c.outer_edge),
                   color="k", lw=0.6, ls="--")
    for a in (ax[0, 2], ax[0, 3]):
        a.axhline(KT_SET, color="k", lw=0.8)
        a.set_ylim(0.97, 1.12)
    ax[1, 2].set_yscale("log")


def draw_sweeps(ax, cases, ref, n_sweep, l_sweep, colour):
    """Chain size against nChain and ChainLen, the deficit against the beads, the start-up."""
    for a, series, key, other, xlabel in ((ax[2, 0], n_sweep, "chains", "length", "nChain"), (ax[2, 1], l_sweep, "length", "chains", "ChainLen")):
        s = [c for c in series if c.chains]
        x = [getattr(c, key) for c in s]
        for size, fmt, name in ((lambda c: c.Rg2, "o-", "R_g = sqrt<R_g^2>"), (lambda c: c.Ree2, "s-", "sqrt<R_ee^2>")):
            a.errorbar(x, [math.sqrt(size(c).value) for c in s], yerr=[0.5 * size(c).error / math.sqrt(size(c).value) for c in s],
                       fmt=fmt, label=name)
        stat_bars(a, x, [c.spanx for c in s], "^-", label="extension along x (span)")
        stat_bars(a, x, [c.ext["outer"]["spanx"] for c in s], "v--", label="span, outer chains")
        stat_bars(a, x, [c.ext["central"]["spanx"] for c in s], "d--", label="span, central chains")
        label(a, f"chain size against {xlabel} ({'ChainLen' if key == 'chains' else 'nChain'} {getattr(s[0], other)})",
              xlabel, "length", legend=8)
    for series, name, marker in ((n_sweep, "nChain sweep", "o-"), (l_sweep, "ChainLen sweep", "s--")):
        ax[2, 2].errorbar([c.beads for c in series], [c.deficit for c in series], yerr=[c.deficit_error for c in series],
                          fmt=marker, label=name)
        for c in series[1:]:
            ax[2, 2].annotate(c.label, (c.beads, c.deficit), fontsize=8, xytext=(4, -10), textcoords="offset points")
    label(ax[2, 2], "velocity deficit", "beads (nChain x ChainLen)", "flux deficit 1 - U / U(no chains)", legend=8)
    for c in cases:  # the log's mean velocity of the mobile particles
        if len(c.history[0]):
            ax[2, 3].plot(*c.history, "-", color=colour[c.label], lw=1, label=c.label)
    ax[2, 3].axvspan(ref.window.start, ref.end, color="0.9", label="sampled")
    if ref.paper:
        ax[2, 3].axvspan(ref.paper["start"], ref.end, color="0.75", label="the paper's window")
    label(ax[2, 3], "start-up (the run's log)", "time", "mean velocity of the mobile particles", legend=7)


def draw_chains(a, show, snapshot):
    """The chains of a case in a snapshot, x-z, each unwrapped from its bond vectors with its centre in the box."""
    draw_chains_xz(a, *chains_in_box(snapshot))
    for zw in show.walls:
        a.axhline(zw, color="gray", ls=":")
    label(a, f"{show.label}: the chains at t = {os.path.basename(os.path.dirname(snapshot))}, x-z projection, one colour per chain",
          "x (each chain unwrapped from its bond vectors, its centre in the box; box edges marked)", "z")
    a.set_aspect("equal", adjustable="datalim")


def draw_bead_map(fig, a, case):
    """The beads' density on the paper's grid (z-x) over its window."""
    grid, extent = image(latest_profile(case.path, "paperBeads"), "density")
    draw_field(fig, a, grid, extent, f"{case.label}: bead density on the paper's grid ({grid.shape[0]} x {grid.shape[1]}, z x), "
               f"t {case.paper['start']:g}-{case.end:g}", "bead density", aspect="auto")
    label(a, None, "x", "z")


def plot(path, cases, ref, n_sweep, l_sweep, name):
    colour = dict(zip((c.label for c in cases), sweep_colours(len(cases))))
    chained = [c for c in cases if c.chains]
    show = max(chained, key=lambda c: (c.length, c.beads))      # the longest chains
    most = max(chained, key=lambda c: (c.chains, c.beads))      # the most chains
    maps = bool(show.paper)
    fig = plt.figure(figsize=(22, 25 if maps else 20))
    grid = fig.add_gridspec(5 if maps else 4, 4)
    ax = np.array([[fig.add_subplot(grid[i, j]) for j in range(4)] for i in range(3)], dtype=object)
    draw_profiles(ax, cases, ref, colour)
    draw_sweeps(ax, cases, ref, n_sweep, l_sweep, colour)
    draw_chains(fig.add_subplot(grid[3, 0:2]), show, show.snapshot0)
    draw_chains(fig.add_subplot(grid[3, 2:4]), show, show.snapshot)
    if maps:
        draw_bead_map(fig, fig.add_subplot(grid[4, 0:2]), show)
        draw_bead_map(fig, fig.add_subplot(grid[4, 2:4]), most)
    fig.suptitle(f"FENE chains in Poiseuille flow, d = {ref.d:g}, g = {ref.g:g}{f' ({name})' if name else ''}: "
                 f"no chains U = {ref.U.value:.3f}, Re = {ref.reynolds:.0f}, Ma = {ref.mach:.2f}")
    save(fig, path, dpi=80, rect=(0, 0, 1, 0.98))
