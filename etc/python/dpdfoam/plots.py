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


def draw_map(fig, ax, grid, column, title, cmap="viridis"):
    """A column of a 2-D profile table (x, z, ...) as a picture with its colour bar."""
    xs, zs = np.unique(grid["x"]), np.unique(grid["z"])
    im = ax.imshow(grid[column].reshape(len(zs), len(xs)), origin="lower", extent=[xs[0], xs[-1], zs[0], zs[-1]],
                   aspect="equal", cmap=cmap)
    fig.colorbar(im, ax=ax, label=column)
    ax.set_title(title)


def save(fig, path, dpi=110, **layout):
    fig.tight_layout(**layout)
    fig.savefig(path, dpi=dpi)
