"""The striped-wall scene (tutorials/channel/stripedWall, docs/walls.md 3.6): the calibration's choice of
gamma_L for the stripes (which gamma_L gives which local slip length; gammaL.dat and its picture), and the
striped channel's studies of the slip tensor against the continuum reference (stripedSlip at the
calibrated slips, dpdfoam.slip), each adding its checks and its results lines.

    study = StripedStudy(cal, walls, gas_fraction, budget, bound, coarse)   # budget(kind): this mode's
    study.header(a); ref = study.angle_study(sweep); ...; study.draw(...)    # stripedWall.png
    picks, others = pick_frictions(checks, "calibration/slipCalibration", gammas, hw, slip, slips)
"""
import math
import os

import numpy as np

from .checks import Checks, as_number, plus_minus as pm, print_file
from .io import latest, read_table, sweep_vector
from .plots import column_bars, label, legend_or_hide, plt, save
from .slip import (PRINCIPAL_SLIPS, StripedReference, anisotropy_check, bracketed_frictions, first_layers,
                   near_wall_sectors, no_slip_friction, principal_slip_checks, read_slip_tensor, reference_check,
                   run_value as run, same_at_rest_check, stiff_end, turn_check, zero_flux_check)
from .stats import inverse_variance_mean

# zc: the depth of the fluid layer next to the walls that the studies at rest and of the first layer read.
ZC = 1.0


def reference(cal, gas_fraction, slip, slip_error, height, angles=(45.0,), period=None, label=None):
    """stripedSlip's reference (dpdfoam.slip) with the calibration's no-slip sectors' residual slip."""
    return StripedReference(gas_fraction, slip, slip_error, height, period or cal["period"],
                            (cal["gammaNoSlipSlip"], cal["gammaNoSlipSlipError"]), angles, label)


def linear(checks, name, q1, e1, q2, e2, limit, bound=3.0):
    """The flux per unit force at g / 2 (q2) as at g (q1): their relative difference within `bound`
    budgets (relative) of 0."""
    q1, e1, q2, e2 = (as_number(v) for v in (q1, e1, q2, e2))
    rel = q2 / q1 - 1.0 if q1 else float("nan")
    se = math.hypot(e1, e2) / abs(q1) if q1 else float("nan")
    return checks.within_budgets(f"flux {name} linear in the force: per unit force at g / 2 as at g, within "
                                 f"{100 * bound * limit:g} % (standard error below {100 * limit:g} %)", rel, se, limit,
                                 f"{q2:.4f} against {q1:.4f}, difference {100 * rel:+.2f} +- {100 * se:.2f} %",
                                 -bound, bound)


class StripedStudy:
    """The striped channel against the continuum reference: cal the calibration (calibration/gammaL.dat),
    walls the planes, gas_fraction the stripes', budget(kind) a kind of check's standard-error budget in
    this mode, bound the fixed bound in budgets (issue 45: a value within `bound` budgets of its
    expectation), coarse a suffix for the names of the checks that mode cannot decide finely. Each study
    adds its checks to .checks and its results lines to .out."""

    def __init__(self, cal, walls, gas_fraction, budget, bound=3.0, coarse=""):
        self.cal, self.walls, self.gas_fraction, self.budget, self.bound, self.coarse = (cal, walls, gas_fraction, budget,
                                                                                          bound, coarse)
        self.height = walls[1] - walls[0] - 2.0 * cal["offset"]  # between the hydrodynamic walls
        self.checks, self.out = Checks(), []

    def header(self, a):
        """The results' first lines: the fluid (a), the stripes, the channel and the calibration."""
        cal, period, offset = self.cal, self.cal["period"], self.cal["offset"]
        self.out += [f"# Striped walls in the fluid of a = {a:g} ({'the review' if a == 0 else 'the standard fluid'}), "
                     f"period L = {period:g}, phi2 {self.gas_fraction:g}, local slip b = {cal['gammaGasSlip']:g} "
                     f"(b/L {cal['gammaGasSlip'] / period:g}), two walls in phase, H = {self.height:.3f} between the "
                     "hydrodynamic walls",
                     f"# calibration: gamma_L no slip {cal['gammaNoSlip']:.4f} (b0 "
                     f"{pm(cal['gammaNoSlipSlip'], cal['gammaNoSlipSlipError'])}), gas {cal['gammaGas']:.4f} (b "
                     f"{pm(cal['gammaGasSlip'], cal['gammaGasSlipError'])}); the wall acts "
                     f"{pm(offset, cal['halfWidthError'])} in front of each plane"]

    def rest_study(self):
        """The fluid at rest over the stripes (rest/): the layer within zc of the walls holds the same
        density and kT over the gas and the no-slip sectors. Returns the stripeGrid and its layer's bins."""
        grid = read_table(latest("rest/postProcessing/profileBins/*/stripeGrid.dat"))
        layer, near = near_wall_sectors(grid, self.walls, self.cal["period"], self.gas_fraction, ZC)
        self.out += [f"# at rest, within zc of the walls over the {where} sectors: density {pm(*layer[where]['density'])}, "
                     f"kT {pm(*layer[where]['kT'])}" for where in ("gas", "noSlip")]
        for q in ("density", "kT"):
            same_at_rest_check(self.checks, q, *layer["gas"][q], *layer["noSlip"][q], self.budget(f"at rest, {q}"),
                               self.bound)
        return grid, near

    def layer_study(self, sweep, s, ref, period):
        """The first layer in a sweep's runs at 0 and 90 degrees (information, README): against smooth walls
        alone it moves across the stripes at a smaller share of its speed along them than the continuum's
        b_perp / b_par and piles up downstream; with the fluid behind the walls it follows the continuum."""
        out = self.out
        if 0.0 not in s["angle"] or 90.0 not in s["angle"]:
            return
        layers = first_layers(sweep, s, (0.0, 90.0), self.walls, period, self.gas_fraction, ZC)
        if any(layer is None for layer, _ in layers.values()):
            out.append(f"# L {period:g}: no first fluid layer (no density minimum within two cutoffs of the plane: "
                       "nothing packs against the wall, as in a fluid without conservative force)")
            return
        (along_layer, along_force), (across_layer, across_force) = layers[0.0], layers[90.0]
        # Per unit force: in the continuum the mean slip velocity is b_eff times the wall's shear rate, the
        # same for both at the same force, so the ratio is b_perp / b_par.
        along, across = along_layer[0]["y"] / along_force, across_layer[0]["x"] / across_force
        out.append(f"# L {period:g}, the first fluid layer (from the plane to {along_layer[2]:.2f}): its mean velocity "
                   f"per unit force, along the stripes at theta 0 {along:.2f}, across them at theta 90 {across:.2f}: "
                   f"ratio {across / along:.3f}, against the continuum's b_perp / b_par "
                   f"{ref['slipPerpendicular'] / ref['slipParallel']:.3f}")
        out += [f"# L {period:g}, the first layer's areal density over the gas sectors, downstream half against "
                f"upstream half, theta {a:g}: {pm(*layers[a][0][1], sign='+')}" for a in (0.0, 90.0)]

    def period_study(self, sp):
        """The same stripes at a larger period L (the same local slip and channel), along and across them."""
        cal, checks, out, budget, bound = self.cal, self.checks, self.out, self.budget, self.bound
        period = float(sp["walls/lower/tunableSlip/stripes/period"][0])
        ref = reference(cal, self.gas_fraction, cal["gammaGasSlip"], cal["gammaGasSlipError"], self.height, period=period)
        out.append(f"# period L {period:g} (b/L {cal['gammaGasSlip'] / period:.3f}): b_par at theta 0, b_perp at theta "
                   "90 (reference)")
        rows = [sp["angle"].index(a) for a in (0.0, 90.0)]  # b_par from the run along the stripes, b_perp across
        principal_slip_checks(checks, f"L {period:g}", sp, rows, ref, cal["halfWidthError"], budget("b, one run"), bound)
        par, perp = (run(sp, "b" + key, k) for (key, _), k in zip(PRINCIPAL_SLIPS, rows))
        out += [f"{name}  {pm(*b)} ({ref['slip' + key]:.4f})" for (key, name), b in zip(PRINCIPAL_SLIPS, (par, perp))]
        anisotropy_check(checks, f"b_par - b_perp at L {period:g} (the wall's position cancels)", par, perp, ref,
                         budget("b_par - b_perp, L 40"), bound)
        self.layer_study("sweepPeriod", sp, ref, period)

    def angle_study(self, s):
        """The angle sweep: each run's row, b_par and b_perp weighted over the runs that drive each, b_par -
        b_perp, and the transverse flux ratio at each angle."""
        cal, checks, out, budget, bound = self.cal, self.checks, self.out, self.budget, self.bound
        ref = reference(cal, self.gas_fraction, cal["gammaGasSlip"], cal["gammaGasSlipError"], self.height, s["angle"])
        out.append("# theta  b_par +- err   b_perp +- err   b_eff(theta) +- err   nu_par nu_perp   flux along, across the "
                   "stripes   transverse flux ratio +- err   reference b_eff, ratio")
        for k, a in enumerate(s["angle"]):
            row = [f"{a:6g}"] + [pm(*run(s, key, k), sign="+") for key in ("bParallel", "bPerpendicular", "bEffective")]
            row += [f"{s['nuParallel'][k]:.4f} {s['nuPerpendicular'][k]:.4f}", pm(*run(s, "fluxParallel", k)),
                    pm(*run(s, "fluxPerpendicular", k)), pm(*run(s, "transverseFluxRatio", k), 5, "+")]
            out.append("  ".join(row) + f"   {ref.effective(a):.4f} {ref.at('ratio', a):.5f}")
        wall_error, means = cal["halfWidthError"], {}
        for key, name in PRINCIPAL_SLIPS:
            runs = np.isfinite(s["b" + key])
            mean, err = means[key] = inverse_variance_mean(s["b" + key][runs], s["b" + key + "Error"][runs])
            reference_check(checks, f"{name} (angle sweep, weighted over {int(runs.sum())} runs){self.coarse}", mean, err,
                            ref, "slip" + key, wall_error, budget("b, angle sweep"), bound=bound)
            out.append(f"# {name}: {pm(mean, err)} (runs; wall +- {wall_error:.4f}), reference {ref['slip' + key]:.4f}")
        anisotropy_check(checks, f"b_par - b_perp (angle sweep; the wall's position cancels){self.coarse}",
                         means["Parallel"], means["Perpendicular"], ref, budget("b_par - b_perp, angle sweep"), bound)
        for k, a in enumerate(s["angle"]):
            ratio, err = run(s, "transverseFluxRatio", k)
            if a == 45.0:
                turn_check(checks, ratio, err, budget("the flow turns"), bound)
            if a % 90 == 0:
                zero_flux_check(checks, a, ratio, err, budget("zero flux"), bound)
            else:
                reference_check(checks, f"transverse flux ratio at theta {a:g}", ratio, err, ref, "ratio", 0.0,
                                budget("flux ratio, angle sweep"), a, bound)
        return ref

    def tensor_rows(self, s, title, parameter, references):
        """Per run at 45 degrees: b_par, b_perp and the flux ratio against their references."""
        checks, out, budget, bound = self.checks, self.out, self.budget, self.bound
        out.append(f"# {title}: {parameter}  b_par +- err (reference)  b_perp +- err (reference)  flux ratio +- err "
                   "(reference)")
        for k, ref in enumerate(references):
            where = f"{parameter} {ref.label:g}"
            principal_slip_checks(checks, where, s, (k, k), ref, self.cal["halfWidthError"], budget("b, one run"), bound)
            reference_check(checks, f"transverse flux ratio at {where}", *run(s, "transverseFluxRatio", k), ref, "ratio",
                            0.0, budget("flux ratio, one run"), 45.0, bound)
            out.append(f"{ref.label:8g}  {pm(*run(s, 'bParallel', k))} ({ref['slipParallel']:.4f})  "
                       f"{pm(*run(s, 'bPerpendicular', k))} ({ref['slipPerpendicular']:.4f})  "
                       f"{pm(*run(s, 'transverseFluxRatio', k), 5, '+')} ({ref.at('ratio', 45.0):.5f})")

    def force_study(self, s, k45):
        """The flux per unit force at theta 45: at half the force (sweepHalfForce/) it must equal the
        standard force's, which is then on the linear (Stokes) branch; at twice the force (sweepForce/) it
        shows where that branch ends (information: inertia takes a part in g^2, README)."""
        for path, factor, what in (("sweepHalfForce/sweep.dat", 0.5, "half the force"),
                                   ("sweepForce/sweep.dat", 2.0, "twice the force")):
            if not os.path.exists(path):
                continue
            sf = read_slip_tensor(path)
            self.out.append(f"# flux per unit force at theta 45: the standard force, {what}")
            for key, name in (("fluxParallel", "along the stripes"), ("fluxPerpendicular", "across them")):
                q1, e1 = run(s, key, k45)
                q2, e2 = sf[key][0] / factor, sf[key + "Error"][0] / factor
                self.out.append(f"{name}: {pm(q1, e1)}, {pm(q2, e2)} (difference {100 * (q2 / q1 - 1):+.1f} "
                                f"+- {100 * math.hypot(e1, e2) / q1:.1f} %)")
                if factor < 1.0:
                    linear(self.checks, name, q1, e1, q2, e2, self.budget("flux linear"), self.bound)

    def sweep_studies(self):
        """The full size's sweeps at 45 degrees (gas fraction, local slip, channel height), where they ran."""
        cal, height, gas_fraction = self.cal, self.height, self.gas_fraction
        offset, b, e = cal["offset"], cal["gammaGasSlip"], cal["gammaGasSlipError"]
        studies = {}
        for key, path, title in (("phi2", "sweepGasFraction", "against the gas fraction (theta 45)"),
                                 ("b", "sweepLocalSlip", "against the local slip (theta 45)"),
                                 ("H", "sweepHeight", "against the channel's height (theta 45)")):
            if not os.path.exists(f"{path}/sweep.dat"):
                continue
            s = read_slip_tensor(f"{path}/sweep.dat", offset)
            if key == "phi2":
                refs = [reference(cal, f, b, e, height, label=f) for f in s["walls/lower/tunableSlip/stripes/gasFraction"]]
            elif key == "b":
                refs = [reference(cal, gas_fraction, bo, eo, height, label=bo)
                        for bo, eo in zip(cal["slipTargets"], cal["gammaGasSlipErrorOf"])]
            else:
                planes = 2.0 * np.abs(np.array([sweep_vector(p)[2] for p in s["walls/lower/point"]]))
                refs = [reference(cal, gas_fraction, b, e, p - 2 * offset, label=p - 2 * offset) for p in planes]
            self.tensor_rows(s, title, key, refs)
            studies[key] = (s, refs)
        return studies

    def draw(self, s, ref, studies, grid, near):
        """stripedWall.png: b_eff and the transverse flux ratio against the angle (s: the angle sweep, ref its
        reference), b_par and b_perp against phi2 and the local slip, the flux ratio against H (studies),
        density and kT at rest across the stripes within zc of the walls (grid, near: rest_study's)."""
        cal, height, gas_fraction = self.cal, self.height, self.gas_fraction
        period = cal["period"]
        fig, ax = plt.subplots(2, 3, figsize=(16, 9))
        ax = ax.ravel()
        fine = np.linspace(0, 90, 91)
        ax[0].plot(fine, ref.effective(fine), "k-", label="continuum reference")
        column_bars(ax[0], s["theta"], s, "bEffective", "o", label="DPD (slipTensor)")
        label(ax[0], f"effective slip: phi2 {gas_fraction:g}, b/L {cal['gammaGasSlip'] / period:g}, H/L {height / period:.2f}",
              "theta (degrees from the stripes)", "b_eff(theta)")
        curve = reference(cal, gas_fraction, cal["gammaGasSlip"], 0.0, height, range(0, 91, 5))["ratio"]
        ax[1].plot(list(curve), list(curve.values()), "k-", label="continuum reference")
        column_bars(ax[1], s["theta"], s, "transverseFluxRatio", "o", label="DPD")
        ax[1].axhline(0, color="gray", ls=":")
        label(ax[1], "transverse flux, H = %.2f" % height, "theta (degrees)", "flux across the force / along it")
        for panel, key, xlabel in ((2, "phi2", "gas fraction phi2"), (3, "b", "local slip b of the gas sectors")):
            if key in studies:
                runs, refs = studies[key]
                x = [r.label for r in refs]
                for name, style, colour in (("Parallel", "o", "C0"), ("Perpendicular", "s", "C1")):
                    column_bars(ax[panel], x, runs, "b" + name, style, color=colour, label=f"b_{name[:4].lower()} DPD")
                    ax[panel].plot(x, [r["slip" + name] for r in refs], "-", color=colour, label=f"b_{name[:4].lower()} reference")
                label(ax[panel], f"theta 45: against {key}", xlabel, "slip length")
        if "H" in studies:
            runs, refs = studies["H"]
            column_bars(ax[4], [r.label for r in refs], runs, "transverseFluxRatio", "o", label="DPD")
            ax[4].plot([r.label for r in refs], [r.at("ratio", 45.0) for r in refs], "k-", label="continuum reference")
            label(ax[4], "theta 45, L = b: the flux ratio against H", "H (between the hydrodynamic walls)", "transverse flux ratio")
        for q, style in (("density", "o-"), ("kT", "s-")):
            col = [np.average(grid[q][near & (grid["x"] == x)], weights=grid["count"][near & (grid["x"] == x)]) for x in np.unique(grid["x"])]
            ax[5].plot(np.unique(grid["x"]), np.asarray(col) / np.mean(col), style, label=f"{q} / its mean")
        ax[5].axvspan(0, gas_fraction * period, color="lightblue", alpha=0.4, label="gas sector")
        label(ax[5], "at rest, within zc of the walls", "x (across the stripes)")
        legend_or_hide(ax, 8)  # the default's studies fill three panels; -a25's every one
        save(fig, "stripedWall.png", dpi=100)


# ---- The calibration: which gamma_L gives which local slip length -------------------------------------


def pick_frictions(checks, path, gammas, hw, slip, slips):
    """The gas sectors' gamma_L (b = slip; and each of the other local slip lengths, slips) as a wall asking
    that slip length takes it from the sweep's calibration (path, through the slipCalibration tool: b linear
    in 1/gamma_L between the two sweep points that bracket it, with the interpolated error), and the no-slip
    gamma_L the same way at b = 0 or, where the friction saturates before b reaches 0, the stiffest gamma_L
    with the slip it leaves; hw hydrodynamicWall's fit of the sweep at gammas. Each not found is a failed
    check. Returns picks {gammaGas, gammaNoSlip: (gamma_L, b, error of b)} and others [(b, (gamma_L, error)
    or None)]."""
    b, err = hw["slipLength"], hw["slipLengthError"]
    span = f"b from {b.min():.3f} to {b.max():.3f}"
    # Each asked slip length's friction and error as dpdFoamLike's walls would take them; bracketed
    # where it lies within the calibrated range (below it the stiffest friction leaves its own slip).
    gas, at_zero, *other_gases = bracketed_frictions(path, [slip, 0.0] + slips)
    picks = {}
    if checks.add(f"the sweep brackets b = {slip:g} (gammaGas)", gas is not None, span):
        picks["gammaGas"] = (gas[0], slip, gas[1])
    # The other local slip lengths the study sweeps (-slips): their gas gamma_L as lists.
    others = list(zip(slips, other_gases))
    for b_other, found_other in others:
        checks.add(f"the sweep brackets b = {b_other:g} (gammaGasOf)", found_other is not None, span)
    # No slip: where b crosses 0, or, where the friction saturates first (the stiffest step of the sweep
    # no longer lowers b decisively), the stiffest gamma_L with the slip it leaves, b0 (the striped
    # channel's reference takes that residual slip: reference).
    last_step = stiff_end(gammas, b, err)[1]
    no_slip = no_slip_friction(at_zero, gammas, b, err)
    if no_slip:
        picks["gammaNoSlip"] = no_slip
    checks.add("the sweep brackets b = 0, or b saturates at the stiff end (gammaNoSlip)", "gammaNoSlip" in picks,
               f"{span}; last step {last_step:+.3f}")
    return picks, others


def write_calibration(hw, period, slip_target, picks, others):
    """calibration/gammaL.dat: the wall's position (hydrodynamicWall), the stripes' period and target, each
    pick's gamma_L with its b and error, and the other targets' gas gamma_L as lists (others)."""
    with open("calibration/gammaL.dat", "w") as f:
        f.write("FoamFile { version 2.0; format ascii; class dictionary; object gammaL; }\n\n")
        f.write("// The striped wall's calibration (calibrate.py from calibration/hydrodynamicWall.dat): the wall acts\n"
                "// `offset` in front of each plane; b from there, interpolated in 1/gamma_L.\n")
        f.write(f"halfWidth       {hw['halfWidth']:.6f};\nhalfWidthError  {hw['halfWidthError']:.6f};\n"
                f"offset          {hw['offset']:.6f};\nperiod          {period:g};\nslipTarget      {slip_target:g};\n")
        for name, (gamma, slip, e) in picks.items():
            f.write(f"{name:<17} {gamma:.6f};\n{name + 'Slip':<17} {slip:.6f};\n{name + 'SlipError':<17} {e:.6f};\n")
        found = [(b_other, g) for b_other, g in others if g]
        if found:
            f.write(f"slipTargets       ({' '.join(f'{b_other:g}' for b_other, _ in found)});\n"
                    f"gammaGasOf        ({' '.join(f'{g[0]:.6f}' for _, g in found)});\n"
                    f"gammaGasSlipErrorOf ({' '.join(f'{g[1]:.6f}' for _, g in found)});\n")
    print_file("calibration/gammaL.dat")


def draw_calibration(hw, gammas, picks):
    """calibration.png: the uniform wall's b against gamma_L, each picked gamma_L starred."""
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    ax.errorbar(gammas, hw["slipLength"], yerr=hw["slipLengthError"], fmt="o-",
                label="uniform wall: b from the hydrodynamic wall")
    for name, (gamma, slip, e) in picks.items():
        ax.plot(gamma, slip, "r*", ms=12)
        ax.annotate(f"{name} {gamma:.3g} (b {slip:.2f})", (gamma, slip), textcoords="offset points", xytext=(-60, 12))
    ax.axhline(0.0, color="gray", ls=":")
    ax.set_xscale("log")
    label(ax, f"calibration: the wall acts {hw['offset']:.3f} in front of its plane", "gamma_L", "slip length b", legend=8)
    save(fig, "calibration.png", dpi=100)
