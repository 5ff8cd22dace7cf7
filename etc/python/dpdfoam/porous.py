"""The porous medium (tutorials/porous/porousMedium, docs/scenes.md scene 6): the DPD x-z field in a
porous medium against its simpleFoam twin, the checks of the scene at a tutorial's budgets and bounds,
and the pictures.

    pc = PorousChecks(budgets, bounds, test_line_bound, widen, test)     # the tutorial's budgets and bounds
    wall = next_to_grains(bins, near, prof, lines)
    checks = pc.make_checks(cmp, lines, kT, inside, wall)                # kT, inside, grains, lines, means
    plot_fields(bins, kT, inside, directory); plot_comparison(bins, cmp, lines, prof, twin, l2_interior)

What each check holds and why its bound: the tutorial's plotResults.py (its docstring, its budgets).
"""
import numpy as np

from .checks import Checks, as_number, finite
from .fields import extent
from .io import read_sections
from .plots import draw_compare_lines, draw_field, draw_kT_series, draw_sections_twin, draw_twin_fields, label, plt, save


def next_to_grains(bins, near, prof, lines):
    """Over the bins near the grains: the mean DPD and simpleFoam velocities, the DPD mean's standard
    error, and the velocity scale, the continuum's peak along the lines (the crack's), with its line."""
    peaks = {name: np.nanmax(prof["u_" + name]) for name in lines}
    line = max(peaks, key=peaks.get)
    return dict(bins.region_means(near), peak=peaks[line], line=line)


class PorousChecks:
    """The scene's checks at a tutorial's noise budgets and bounds. budgets: {test: {"line", "mean", "kT",
    "wall"}}, the largest noise at which a check still decides; bounds: {"kT", "wall", "twin", "line",
    "mean"}, the full scene's (kT within the bound of 1; next to the grains below the "wall" bound of the
    crack's peak and within the "twin" bound of that peak of simpleFoam's there; the crack line's relative
    L2; the mean and superficial velocities within the bound of simpleFoam's); test_line_bound: the crack
    line's bound in test mode; widen: the test bounds of a mean are the full bound plus `widen` test
    budgets, fixed; test: the mode make_checks takes when given none. Each check (issue 45) first holds
    the noise of its quantity (its standard error; the line's noise L2) within its budget, so that a run
    too noisy to decide fails instead of passing more easily, then the value within a fixed bound; a NaN,
    missing or empty number fails."""

    def __init__(self, budgets, bounds, test_line_bound, widen=3.0, test=False):
        self.budgets, self.bounds, self.test_line_bound = budgets, bounds, test_line_bound
        self.widen, self.test = widen, test

    def bound(self, kind, test):
        """A check's fixed bound: the full scene's, in test mode widened by `widen` test budgets (the crack
        line: test_line_bound)."""
        full = self.bounds[kind]
        if not test:
            return full
        if kind == "line":
            return self.test_line_bound
        return full + self.widen * self.budgets[True]["wall" if kind == "twin" else kind]

    def kT_check(self, checks, what, kT, error, test):
        """The mean kT within the bound of 1, the kT's standard error (the log series') within its budget."""
        budget, tol = self.budgets[test]["kT"], self.bound("kT", test)
        shown = f"{as_number(kT):.4f}" + (f" +- {as_number(error):.4f}" if what != "the bins" else "")
        return checks.bounded(f"mean kT of {what} within {tol:.3f} of 1 (standard error below {budget:g})", kT, error,
                              budget, 1.0 - tol, 1.0 + tol, shown)

    def inside_check(self, checks, inside):
        """No fluid particle inside the solid at the end (the solver's count): exactly 0; a missing count fails."""
        return checks.add("no fluid particle inside the solid at the end", inside == 0 and finite(inside), f"{inside}")

    def wall_checks(self, checks, u_dpd, u_fvm, error, peak, line, bins, test):
        """Velocity near zero next to the grains (the mean DPD velocity over the bins the grains' surface
        passes through, its standard error, the twin's mean there, the crack's peak): below 10 % of the peak,
        and within 3 % of that peak of simpleFoam's there, each in units of the peak, its standard error first
        within the budget. In the test's small mask the bins the grains cut hold more of the flow:
        simpleFoam's own velocity there is ~11 % of the peak (0.0195 of 0.182), so a correct no-slip run would
        sit at the bound; there the first bound is the larger of 10 % and the continuum's value plus the 3 %
        of the second check, plus three test budgets like every test bound of a mean; a slipping wall
        (velocity of the order of the pore's) is still far above it."""
        u_dpd, u_fvm, error, peak = (as_number(v) for v in (u_dpd, u_fvm, error, peak))
        peak = peak if peak > 0 else float("nan")  # no flow to scale by: fails
        budget = self.budgets[test]["wall"]
        wall_bound = self.bounds["wall"]
        if test:
            wall_bound = max(self.bounds["wall"], abs(u_fvm / peak) + self.bounds["twin"]) + self.widen * budget
        twin_bound = self.bound("twin", test)
        ok = checks.bounded(f"velocity next to the grains < {wall_bound:.1%} of the {line}'s peak (standard error below "
                            f"{budget:g} of it)", u_dpd / peak, error / peak, budget, -wall_bound, wall_bound,
                            f"{u_dpd:.4f} (peak {peak:.4f})")
        return checks.bounded(f"velocity next to the grains within {twin_bound:.1%} of the peak of simpleFoam's there "
                              f"(standard error below {budget:g} of it)", (u_dpd - u_fvm) / peak, error / peak, budget,
                              -twin_bound, twin_bound, f"DPD {u_dpd:.4f}, simpleFoam {u_fvm:.4f} over {bins} bins") and ok

    def line_check(self, checks, name, l2, noise, points, test):
        """A line of system/makeFoamCaseDict (the crack's centre line): the relative L2 of DPD against
        simpleFoam below the bound, its noise L2 (what the DPD errors alone give) first within the budget."""
        budget, tol = self.budgets[test]["line"], self.bound("line", test)
        return checks.bounded(f"{name} centre line: relative L2 < {tol:.3f} (noise L2 below {budget:g})", l2, noise, budget,
                              None, tol, f"{as_number(l2):.4f} (noise {as_number(noise):.4f}, "
                              f"{int(as_number(points)) if finite(points) else points} bins)")

    def mean_check(self, checks, what, ratio, error, test):
        """A mean velocity of DPD over simpleFoam's (over the compared bins; the superficial velocity, i.e. the
        permeability): within the bound of 1, the superficial velocity's relative standard error first within
        the budget."""
        budget, tol = self.budgets[test]["mean"], self.bound("mean", test)
        return checks.bounded(f"{what} within {tol:.3f} (standard error below {budget:g})", ratio, error, budget, 1.0 - tol,
                              1.0 + tol, f"{as_number(ratio):.4f} +- {as_number(error):.4f}")

    def make_checks(self, cmp, lines, kT, inside, wall, test=None):
        """The checks (the tutorial's docstring), from compareFVM's summary and lines, the kT (FlowTemperature), the
        particles inside the solid and the velocity next to the grains (next_to_grains)."""
        test = self.test if test is None else test
        twin = as_number(cmp["superficialVelocityFVM"])
        super_err = as_number(cmp["superficialVelocityDPDErr"]) / twin if twin > 0 else float("nan")  # no twin flow: fails
        checks = Checks()
        self.kT_check(checks, "the bins", kT.bins, kT.error, test)
        self.kT_check(checks, "the log's series", kT.mean, kT.error, test)
        self.inside_check(checks, inside)
        self.wall_checks(checks, wall["dpd"], wall["fvm"], wall["se"], wall["peak"], wall["line"], wall["bins"], test)
        for name, line in lines.items():
            self.line_check(checks, name, line["L2"], line["noiseL2"], line["points"], test)
        self.mean_check(checks, "mean velocity over the compared bins", cmp["meanVelocityRatio"], super_err, test)
        self.mean_check(checks, "superficial velocity (permeability)", cmp["permeabilityRatio"], super_err, test)
        return checks


def plot_fields(bins, kT, inside, directory):
    fig, ax = plt.subplots(2, 2, figsize=(13, 11))
    grid, ext = bins.grid, extent(bins.xs, bins.zs)
    draw_field(fig, ax[0, 0], bins.dpd_speed(), ext, "DPD |u| (flowField.vti)", "|u|")
    draw_field(fig, ax[0, 1], np.where(grid["count"] > 0, grid["density"], np.nan), ext, "DPD density", "number density",
               cmap="magma")
    draw_kT_series(ax[1, 0], kT)
    label(ax[1, 0], f"kT series; {inside} particles inside the solid at the end", "time", "kT", legend=8)
    # The sections of system/controlDict (the tutorial's: the crack at its narrowest and widest).
    draw_sections_twin(ax[1, 1], read_sections(directory, "flowField"), bins.xs, bins.zs, bins.ufx)
    label(ax[1, 1], "across the flow at the sections of system/controlDict", "z", "ux", legend=8)
    save(fig, "porousMedium.png")


def plot_comparison(bins, cmp, lines, prof, twin, l2_interior):
    fig, ax = plt.subplots(2, 2, figsize=(13, 11))
    draw_twin_fields(fig, [ax[0, 0], ax[0, 1], ax[1, 0]], bins.dpd_speed(), bins.twin_speed(), bins.difference(), extent(bins.xs, bins.zs),
                     f"difference: L2 field {cmp['L2']:.3f}, interior {l2_interior:.3f}")
    draw_compare_lines(ax[1, 1], prof, lines, twin["nu"])  # each line of system/makeFoamCaseDict
    label(ax[1, 1], "lines of system/makeFoamCaseDict: " + "; ".join(f"{n} L2 {line['L2']:.4f}" for n, line in lines.items())
          + f"; k DPD/FVM {cmp['permeabilityRatio']:.3f}", "position along the line", "ux", legend=8)
    save(fig, "compareFVM.png")
