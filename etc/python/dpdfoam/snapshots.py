"""Reading the solver's snapshots (<time>/particles.h5): the box, whether two hold the same particles,
and the chains' bonds (io/SnapshotBonds.hpp: each bond its two ids, the chain and the vector from its
first bead to its second, followed across the periodic box), the chains unwrapped from them and
their shapes; the chains' shapes of every snapshot in a profile's sampled window as a table (the
command tutorials/polymer/channel/chainExtension.py), and that table as super-block means of the
central and the outer chains (extension_by_offset).
"""
import argparse
import glob
import os
import sys

import h5py
import numpy as np

from .io import dictionary_value
from .stats import BlockMean
from .timeseries import binned_profile, block_slopes


def snapshot_box(path):
    """The box's lower and upper corners."""
    with h5py.File(path, "r") as f:
        return np.asarray(f.attrs["boxLo"]), np.asarray(f.attrs["boxHi"])


def same_particles(a, b):
    """Whether two snapshots hold the same particles (positions and species, in id order)."""

    def columns(path):
        with h5py.File(path, "r") as f:
            order = np.argsort(np.array(f["particles/id"]))
            return [np.array(f[f"particles/{k}"])[order] for k in ("position", "species")]

    return all(np.array_equal(x, y) for x, y in zip(columns(a), columns(b)))


def chain_segments(path):
    """A snapshot's beads and bonds: bead positions (species polymer), and each bond as the segment from
    its first bead along its followed vector (drawn without jumps across the periodic box), with its
    chain: {"path", "time", "beads", "starts", "ends", "chain"}."""
    with h5py.File(path, "r") as f:
        names = [n.decode() if isinstance(n, bytes) else str(n) for n in f.attrs["speciesNames"]]
        species = np.array(f["particles/species"])
        position = np.array(f["particles/position"])
        ids = np.array(f["particles/id"])
        pairs = np.array(f["bonds/pairs"]) if "bonds/pairs" in f else np.zeros((0, 2), dtype=np.uint64)
        vector = np.array(f["bonds/vector"]) if "bonds/vector" in f else np.zeros((0, 3))
        chain = np.array(f["bonds/chain"]) if "bonds/chain" in f else np.zeros(0, dtype=int)
        time = float(f.attrs["time"])
    beads = position[species == names.index("polymer")] if "polymer" in names else np.zeros((0, 3))
    index = {int(i): k for k, i in enumerate(ids)}
    starts = np.array([position[index[int(a)]] for a, _ in pairs]).reshape(-1, 3)
    return {"path": path, "time": time, "beads": beads, "starts": starts, "ends": starts + vector, "chain": chain}


def unwrapped_chains(path):
    """Unwrapped bead positions of every chain: {chain: (L, 3) array}, from the first bead's position and
    the bonds' followed vectors."""
    with h5py.File(path, "r") as f:
        if "bonds/pairs" not in f:
            return {}  # no bonds: io/SnapshotBonds.cpp writes the bonds/ datasets only for bonds
        ids, pos = np.array(f["particles/id"]), np.array(f["particles/position"])
        pairs, vec, bond_chain = np.array(f["bonds/pairs"]), np.array(f["bonds/vector"]), np.array(f["bonds/chain"])
    row = {int(i): k for k, i in enumerate(ids)}
    out = {}
    for c in np.unique(bond_chain):
        sel = np.flatnonzero(bond_chain == c)
        # The chain's bonds in order: follow them from the bead that is nobody's second.
        nxt = {int(pairs[b, 0]): (int(pairs[b, 1]), vec[b]) for b in sel}
        seconds = {int(pairs[b, 1]) for b in sel}
        bead = [a for a in nxt if a not in seconds][0]
        points = [pos[row[bead]]]
        while bead in nxt:
            bead, v = nxt[bead]
            points.append(points[-1] + v)
        out[int(c)] = np.array(points)
    return out


def chain_shapes(path, axis, flow=0):
    """Per chain of a snapshot (in chain order), unwrapped: (chain, its centre along `axis` (the mean
    bead coordinate), its extent along `flow` (max - min bead coordinate), R_g^2, and the square of the
    end-to-end vector's `flow` component)."""
    rows = []
    for chain, p in sorted(unwrapped_chains(path).items()):
        d = p - p.mean(axis=0)
        rows.append((chain, p[:, axis].mean(), np.ptp(p[:, flow]), float(np.mean(np.sum(d * d, axis=1))),
                     (p[-1, flow] - p[0, flow]) ** 2))
    return rows


def chains_in_box(path):
    """The box's corners and every chain unwrapped (in chain order), each shifted by whole box lengths
    along x so that its centre lies in the box (for a picture along x)."""
    lo, hi = snapshot_box(path)
    length = hi[0] - lo[0]
    chains = [p - [length * np.floor((p[:, 0].mean() - lo[0]) / length), 0.0, 0.0]
              for _, p in sorted(unwrapped_chains(path).items())]
    return lo, hi, chains


# ---- The chains' shapes over a binnedProfile's sampled window (chainExtension.py) ---------------------

AXES = {"x": 0, "y": 1, "z": 2}
EXTENSION_COLUMNS = "time chain centre spanx Rg2 Reex2"


def extension_window(case, function):
    """A binnedProfile function's axis, its sampled window (its startTime to the run's endTime,
    system/controlDict) and the window's table, postProcessing/chainExtension/<start>/chainExtension.dat."""
    control = os.path.join(case, "system/controlDict")
    axis = dictionary_value(control, f"functions/{function}/axis").strip()
    start = float(dictionary_value(control, f"functions/{function}/startTime"))
    table = os.path.join(case, "postProcessing/chainExtension", f"{start:g}", "chainExtension.dat")
    return AXES[axis], start, float(dictionary_value(control, "endTime")), table


def measure_extension(case, function):
    """One row per chain of every snapshot (<time>/particles.h5) in the window, in time and chain order:
    the time, then chain_shapes' columns (the centre along the profile's axis, the extent along x); and
    the table's path."""
    axis, start, end, table = extension_window(case, function)
    rows = []
    for path in glob.glob(os.path.join(case, "[0-9]*", "particles.h5")):
        t = float(os.path.basename(os.path.dirname(path)))
        if start <= t <= end:
            rows += [(t, *shape) for shape in chain_shapes(path, axis)]
    rows.sort()
    return np.array(rows).reshape(-1, 6), table


def extension_rows(case, function="channelProfile"):
    """The case's table, or the rows measured now from its snapshots (None where it has neither: the
    snapshots go once the table is written)."""
    table = extension_window(case, function)[3]
    if os.path.exists(table):
        return np.loadtxt(table, comments="#", ndmin=2)
    rows, _ = measure_extension(case, function)
    return rows if len(rows) else None


def extension_by_offset(rows, window, centre, central_edge, outer_edge, edges):
    """extension_rows over a SuperBlockWindow: {"central", "outer": spanx, Rg2, chains}, ratio, slope, bins, snapshots."""
    rows, k = window.rows(rows)
    offset, span = np.abs(rows[:, 2] - centre), rows[:, 3]
    snapshots = len(np.unique(rows[:, 0]))
    out = {"snapshots": snapshots}
    for name, chosen in (("central", offset < central_edge), ("outer", offset > outer_edge)):
        index = np.where(chosen, k, -1)
        out[name] = {"spanx": window.mean(span, index), "Rg2": window.mean(rows[:, 4], index),
                     "chains": chosen.sum() / max(snapshots, 1)}
    out["ratio"] = out["outer"]["spanx"].value / out["central"]["spanx"].value
    # The slope of span_x on the chain's distance from the centre, every chain counted, per super-block.
    out["slope"] = BlockMean(block_slopes(offset, span, k, window.m))
    out["bins"] = dict(zip(("z", "spanx", "err"), binned_profile(span, rows[:, 2], edges, k, window.m)))
    return out


def write_extension(case, function):
    """Measures the window's snapshots and writes the table whole (a temporary file, renamed); returns
    what was written, in words. Exits where the snapshots hold no chains."""
    rows, table = measure_extension(case, function)
    if not len(rows):
        sys.exit(f"chainExtension: no chains in the snapshots of {case} in the window of {function}")
    os.makedirs(os.path.dirname(table), exist_ok=True)
    np.savetxt(table + ".tmp", rows, fmt=["%.6g", "%d", "%.6g", "%.6g", "%.6g", "%.6g"], header=EXTENSION_COLUMNS)
    os.replace(table + ".tmp", table)
    return f"chainExtension: {len(np.unique(rows[:, 0]))} snapshots, {len(np.unique(rows[:, 1]))} chains: written {table}"


def extension_command(description, argv=None):
    """chainExtension.py: write_extension of a case's binnedProfile function, from the command line."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("-case", default=".")
    parser.add_argument("-function", default="channelProfile", help="the binnedProfile whose window is measured")
    args = parser.parse_args(argv)
    print(write_extension(args.case, args.function))
    return 0
