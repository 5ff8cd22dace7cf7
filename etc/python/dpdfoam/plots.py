"""The figures' common parts. Importing this module selects matplotlib's Agg backend (files, no
display): `from dpdfoam.plots import plt`."""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402,F401
import numpy as np  # noqa: E402

from .channel import poiseuille_velocity  # noqa: E402


def label(ax, title=None, xlabel=None, ylabel=None, legend=None):
    """Title, axis labels and (legend: its font size) a legend."""
    if title is not None:
        ax.set_title(title)
    if xlabel is not None:
        ax.set_xlabel(xlabel)
    if ylabel is not None:
        ax.set_ylabel(ylabel)
    if legend is not None:
        ax.legend(fontsize=legend)


def label_panels(axes, panels, legend=None):
    """Each of axes labelled (label) with its (title, xlabel, ylabel) of panels, and a legend of that font size."""
    for ax, (title, xlabel, ylabel) in zip(axes, panels):
        label(ax, title, xlabel, ylabel, legend)


def mark_walls(axes, walls, **style):
    """A dotted grey line at each wall position on each of axes."""
    for ax in np.atleast_1d(axes):
        for w in walls:
            ax.axvline(w, **{"color": "gray", "ls": ":", **style})


def draw_no_slip_poiseuille(ax, walls, g, nu, label, **style):
    """The analytic no-slip Poiseuille profile between the walls."""
    zz = np.linspace(walls[0], walls[1], 400)
    ax.plot(zz, poiseuille_velocity(zz, walls[0], walls[1], g, nu), **{"color": "k", "ls": "-", "lw": 1.2, **style},
            label=label)


def draw_kT_of_shear(ax, centre, kT_of_shear, g, nu, half_width=None, label="no-wall box at the same shear rate"):
    """kT of the box without walls at the channel's local shear rate g |z - centre| / nu, both sides."""
    shear, kT_box = kT_of_shear
    inside = np.ones_like(shear, dtype=bool) if half_width is None else shear * nu / g <= half_width
    for side in (1, -1):
        ax.plot(centre + side * shear[inside] * nu / g, kT_box[inside], "k--", lw=0.8, label=label if side == 1 else None)


def draw_field(fig, ax, field, extent, title, bar_label, title_size=None, **style):
    """A 2-D field (rows z, columns x) as a picture over extent with its colour bar (viridis unless style
    says otherwise) and its title."""
    im = ax.imshow(field, origin="lower", extent=extent, **{"cmap": "viridis", **style})
    fig.colorbar(im, ax=ax, label=bar_label)
    ax.set_title(title, **({} if title_size is None else {"fontsize": title_size}))


def draw_map(fig, ax, grid, column, title, cmap="viridis"):
    """A column of a 2-D profile table (x, z, ...) as a picture with its colour bar."""
    xs, zs = np.unique(grid["x"]), np.unique(grid["z"])
    draw_field(fig, ax, grid[column].reshape(len(zs), len(xs)), [xs[0], xs[-1], zs[0], zs[-1]], title, column,
               aspect="equal", cmap=cmap)


def draw_compare_lines(ax, profiles, lines, nu):
    """compareFVM's lines (its profiles.dat: x z uDPD uDPDErr uFVM u_<line>): on each line the DPD bins
    with their errors and the continuum's velocity, against the position along the line's longer extent."""
    for name in lines:
        on = np.isfinite(profiles["u_" + name])
        along = "x" if np.ptp(profiles["x"][on]) >= np.ptp(profiles["z"][on]) else "z"
        dots = ax.errorbar(profiles[along][on], profiles["uDPD"][on], yerr=profiles["uDPDErr"][on], fmt="o", ms=2,
                           label=f"DPD (bins on the line {name}, {on.sum()})")
        ax.plot(profiles[along][on], profiles["u_" + name][on], "-", color=dots[0].get_color(), lw=1.2,
                label=f"simpleFoam, nu = {nu:.4f}")


def draw_twin_fields(fig, axes, speed_dpd, speed_fvm, difference, extent, title):
    """DPD |u| and simpleFoam |u| on the bins, one colour scale (0 to the continuum's peak), and the
    difference of their ux (titled title) over its 99th percentile, on three of axes."""
    vmax = np.nanmax(speed_fvm)
    draw_field(fig, axes[0], speed_dpd, extent, "DPD |u|", "|u|", vmin=0, vmax=vmax)
    draw_field(fig, axes[1], speed_fvm, extent, "simpleFoam |u| (on the DPD bins)", "|u|", vmin=0, vmax=vmax)
    lim = np.nanpercentile(np.abs(difference), 99)
    draw_field(fig, axes[2], difference, extent, title, "ux DPD - ux simpleFoam", title_size=10, cmap="RdBu_r",
               vmin=-lim, vmax=lim)


def draw_sections_twin(ax, sections, xs, zs, ufx, fluid_count=10):
    """profileBins' sections (io.read_sections) across the flow, DPD ux with its errors over the bins with at
    least fluid_count samples, and the continuum's ux (on the bins: rows zs, columns xs) in the column nearest each."""
    for x, s in sections:
        col = int(np.argmin(np.abs(xs - x)))
        ok = s["count"] >= fluid_count
        line = ax.errorbar(s["z"][ok], s["ux"][ok], yerr=s["uxErr"][ok], fmt="o", ms=2, label=f"DPD x = {x:g}")
        ax.plot(zs, ufx[:, col], "-", color=line[0].get_color(), lw=1, label=f"simpleFoam x = {x:g}")


def draw_kT_series(ax, kT):
    """A flow's kT (fields.FlowTemperature): the log's series (about the local flow) against 1 + the flow's
    part (what a global mean would read) and the bins' kT, the set kT and the start of the sampling."""
    ax.plot(kT.times, kT.series, "o-", ms=3, label="log: kT about the local flow")
    ax.axhline(1 + kT.flow, color="gray", ls=":", label=f"1 + flow part {kT.flow:.4f} (a global mean)")
    ax.axhline(kT.bins, color="r", ls="--", label=f"bins (about local flow): {kT.bins:.4f}")
    ax.axhline(1, color="k", lw=0.8)
    ax.axvline(kT.start, color="k", ls=":", lw=0.8)


def stat_bars(ax, x, stats, fmt, **style):
    """BlockMeans (stats.BlockMean: .value, .error) against x, their standard errors as error bars."""
    ax.errorbar(x, [s.value for s in stats], yerr=[s.error for s in stats], fmt=fmt, **style)


def column_bars(ax, x, table, key, fmt, **style):
    """A table's column (runSweep's, slipTensor's) against x, its <column>Error as error bars."""
    ax.errorbar(x, table[key], yerr=table[key + "Error"], fmt=fmt, **style)


def legend_or_hide(axes, fontsize):
    """A legend of that font size on each of axes that holds data; an empty one hidden."""
    for ax in np.ravel(axes):
        if ax.has_data():
            ax.legend(fontsize=fontsize)
        else:
            ax.set_visible(False)


def draw_chains_xz(ax, lo, hi, chains):
    """Chains (snapshots.chains_in_box) in the x-z plane, one colour each, and the box's x edges lo, hi."""
    for k, p in enumerate(chains):
        ax.plot(p[:, 0], p[:, 2], "-", color=plt.cm.tab20(k % 20), lw=0.8)
        ax.plot(p[:, 0], p[:, 2], ".", color=plt.cm.tab20(k % 20), ms=2.5)
    ax.axvline(lo[0], color="k", lw=0.6)
    ax.axvline(hi[0], color="k", lw=0.6)


def save(fig, path, dpi=110, **layout):
    fig.tight_layout(**layout)
    fig.savefig(path, dpi=dpi)
