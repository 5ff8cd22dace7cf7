"""Slip length as the user's input (tutorials/channel/slipLength, docs/walls.md 3.8): the channels' bins
between the points the walls were put at, the density peak's errors and slipLength.png.

    middle = central(z)                       # the middle fifth of the Poiseuille channel
    peak_err, bulk_err = peak_errors(table, middle)
    draw(rows, mask_rows, couette)            # slipLength.png: asked against measured b, the profiles
"""
import numpy as np

from .io import latest_profile, wall_planes
from .plots import label, mark_walls, plt, save


def central(z, case="poiseuille"):
    """The bins of the channel's middle fifth, between the points the walls were put at."""
    lo, hi = wall_planes(f"{case}/constant/dpdProperties")
    return np.abs(z - 0.5 * (lo + hi)) < 0.1 * (hi - lo)


def peak_errors(table, bulk):
    """The standard errors of near_wall_layer's peak (the densest bin's) and bulk density (the mean over
    the bins `bulk` selects)."""
    rho, err = table["density"], table["densityErr"]
    return float(err[np.argmax(rho)]), float(np.sqrt(np.sum(err[bulk] ** 2)) / np.count_nonzero(bulk))


def draw(rows, mask_rows, couette):
    """slipLength.png: each channel's measured b against the asked one (rows and mask_rows: the Poiseuille
    channels' (asked, measured, total error, case, run's error), couette: (asked, measured, total error)) in
    the band of max(0.15, 10 %) of the ask; the Poiseuille channels' profiles and density over the bulk's."""
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.5))
    grid = np.linspace(0, max(max(r[0] for r in rows), 1.0) * 1.1, 50)
    ax[0].fill_between(grid, grid - np.maximum(0.15, 0.1 * grid), grid + np.maximum(0.15, 0.1 * grid), color="0.85",
                       label="max(0.15, 10 %) of the ask")
    ax[0].plot(grid, grid, "k-", lw=0.8)
    for points, fmt, name in ((rows, "o", "Poiseuille"), (mask_rows, "^", "Poiseuille, image mask"), ([couette], "s", "Couette")):
        ax[0].errorbar([r[0] for r in points], [r[1] for r in points], [r[2] for r in points], fmt=fmt, label=name)
    label(ax[0], "asked against measured", "asked b", "measured b (from the wall's point)", 8)
    for asked_b, _, _, case, _ in rows:
        t = latest_profile(case)
        fluid = t["density"] > 0  # bins behind the acting planes hold no fluid and no velocity
        ax[1].plot(t["z"][fluid], t["ux"][fluid], label=f"b {asked_b:g}")
        ax[2].plot(t["z"], t["density"] / np.mean(t["density"][central(t["z"])]), label=f"b {asked_b:g}")
    for a in ax[1:]:
        mark_walls(a, wall_planes("poiseuille/constant/dpdProperties"))
    label(ax[1], "Poiseuille profiles", "z", "u_x", 8)
    label(ax[2], "density over the bulk's", "z", "rho / rho_bulk", 8)
    save(fig, "slipLength.png")
