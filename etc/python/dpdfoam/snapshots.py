"""Reading the solver's snapshots (<time>/particles.h5): the box, whether two hold the same particles,
and the chains' bonds (io/SnapshotBonds.hpp: each bond its two ids, the chain and the vector from its
first bead to its second, followed across the periodic box)."""
import h5py
import numpy as np


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
