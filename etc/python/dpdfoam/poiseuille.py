"""Scene 1 as published (tutorials/channel/poiseuille; Liu and Chang 2010): Poiseuille flow between FCC
and random equilibrated walls with a bounce layer, several seeds of each; and the bounce layer's
thickness study (./Allrun -alphaSweep).

    runs, stats = seed_runs(case, builder, kT_of_shear, g, nu_ref)   # SeedRun per seed, mean +- error
    plot(results, g, nu_ref, kT_set, kT_of_shear)                     # poiseuille.png
    draw_alpha_sweep(sweeps, nu_ref)                                  # alphaSweep.png

Each seed's quantities (QUANTITIES): nu, slip length b (the two walls' mean), density within one cutoff
of the walls and in their first bins over the bulk's, kT within one cutoff, the bulk's kT (beyond 3
cutoffs) minus the no-wall box's at the same shear rate, and the particles the bounce layer turned round
and found behind the wall per unit time and wall area. The seeds are independent runs of the paper's
protocol, so their spread is the error of one run (the tutorial's plotResults.py, "Errors").
"""
import numpy as np

from .channel import wall_event_rates
from .io import function_start, latest_fit, latest_profile, numbered_cases
from .plots import draw_kT_of_shear, draw_no_slip_poiseuille, label, label_panels, plt, save
from .stats import mean_and_error
from .sweep import (density_flatness, first_bins_density, kT_over_no_wall, near_both_walls, wall_distance,
                    wall_layer_density, wall_layer_kT)

QUANTITIES = ("nu", "slip", "rhoNear", "rhoFirst", "kTNear", "kTBulkVsNoWall", "returned", "crossed")
# The alpha sweep's panels: quantity, title.
SHOWN = (("slip", "slip length b"), ("nu", "nu"), ("rhoNear", "density within one cutoff / bulk"),
         ("kTNear", "kT within one cutoff"), ("returned", "returned per unit time and area"),
         ("crossed", "found behind the wall per unit time and area"))


class SeedRun:
    """One seed of one wall: its fit, profile and the quantities of QUANTITIES."""

    def __init__(self, path, builder, kT_of_shear, g, nu_ref):
        self.path = path
        fit, self.table = latest_fit(path), latest_profile(path)
        lo, hi = self.walls = tuple(fit["wallPosition"])
        bulk = wall_distance(self.table["z"], self.walls) > 3.0
        self.q = {
            "nu": fit["nu"],
            "slip": 0.5 * sum(fit["slipLength"]),  # the two walls' mean: their slip is one property
            "rhoNear": wall_layer_density(self.table, self.walls),
            "rhoFirst": first_bins_density(self.table, self.walls),
            "kTNear": wall_layer_kT(self.table, self.walls),  # empty bins read kT 0
            "kTBulkVsNoWall": kT_over_no_wall(self.table, bulk, 0.5 * (lo + hi), g, nu_ref, kT_of_shear),
        }
        self.q["returned"], self.q["crossed"] = wall_event_rates(path, builder, function_start(path, "channelProfile"))
        self.flatness = density_flatness(self.table, self.walls)
        self.flatness_error = flatness_error(self.table, self.walls)


def flatness_error(prof, walls, cutoff=1.0):
    """The largest standard error of a bin's density beyond cutoff of the walls, relative to their mean:
    at most the error of density_flatness's largest deviation."""
    far = wall_distance(prof["z"], walls) > cutoff
    return np.max(prof["densityErr"][far]) / np.mean(prof["density"][far])


def seed_runs(case, builder, kT_of_shear, g, nu_ref):
    runs = [SeedRun(p, builder, kT_of_shear, g, nu_ref) for _, p in numbered_cases(f"runs/{case}_seed", "./Allrun")]
    return runs, {k: mean_and_error([r.q[k] for r in runs]) for k in QUANTITIES}


def plot(results, g, nu_ref, kT_set, kT_of_shear):
    fig, ax = plt.subplots(2, 2, figsize=(13, 9))
    for (name, (runs, s)), marker in zip(results.items(), "osd"):
        t = runs[0].table
        lo, hi = runs[0].walls
        mean = {k: np.mean([r.table[k] for r in runs], axis=0) for k in ("ux", "density", "kT")}
        ax[0, 0].plot(t["z"], mean["ux"], marker, ms=2.5, mfc="none",
                      label=f"{name}: nu {s['nu'][0]:.4f}, b {s['slip'][0]:+.3f} +- {s['slip'][1]:.3f}")
        ax[0, 1].plot(*near_both_walls(t["z"], mean["density"], (lo, hi), 2.0), marker, ms=3, mfc="none", label=name)
        ax[1, 0].plot(t["z"], mean["kT"], marker, ms=2.5, mfc="none", label=name)
        ax[1, 1].errorbar([r.q["slip"] for r in runs], [r.q["nu"] for r in runs], fmt=marker, mfc="none", label=name)
    draw_no_slip_poiseuille(ax[0, 0], (lo, hi), g, nu_ref, f"no slip, nu {nu_ref:.4f} (no-wall box)", lw=1)
    ax[1, 0].axhline(kT_set, color="k", lw=0.8)
    draw_kT_of_shear(ax[1, 0], 0.5 * (lo + hi), kT_of_shear, g, nu_ref, half_width=0.5 * (hi - lo))
    ax[1, 1].axhline(nu_ref, color="k", lw=0.8, label="nu without walls")
    ax[1, 1].axvline(0.0, color="gray", lw=0.8)
    titles = (("velocity (mean over the seeds)", "z", "u_x"), ("density next to the walls", "distance from the wall", "density"),
              ("kT about the local flow", "z", "kT"), ("each seed's fit", "slip length b", "nu"))
    label_panels(ax.flat, titles, legend=7)
    fig.suptitle(f"Scene 1 as published: Poiseuille flow between FCC and random walls with a bounce layer, d = {hi - lo:g}, g = {g:g}")
    save(fig, "poiseuille.png")
    print("Written poiseuille.png and results.dat")


def draw_alpha_sweep(sweeps, nu_ref):
    """alphaSweep.png: each of SHOWN against alpha (log scale), one line per wall; sweeps: {wall: (alphas,
    runs)}, runs SeedRun's; nu without walls marked."""
    fig, ax = plt.subplots(2, 3, figsize=(14, 8))
    for a, (key, title) in zip(ax.flat, SHOWN):
        for (wall, (alphas, runs)), marker in zip(sweeps.items(), "os"):
            a.plot(alphas, [r.q[key] for r in runs], marker + "-", mfc="none", label=wall)
        a.set_xscale("log")
        label(a, title, "alpha", legend=8)
    ax[0, 1].axhline(nu_ref, color="k", lw=0.8)
    fig.suptitle("Scene 1: the bounce layer's thickness alpha r_c")
    save(fig, "alphaSweep.png")
