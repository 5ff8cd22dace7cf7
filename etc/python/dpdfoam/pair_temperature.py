"""The heat of a flowing fluid apart from the motion neighbours share (docs/analysis.md 5.5).

A bin's kinetic temperature, the variance of the particles' velocities about the bin's mean flow,
counts two things: heat, the velocity each particle has on its own, and motion its neighbours share
(flow structures smaller than the bin's extent along the flow, such as the stirring of strongly
stretched chains). The DPD thermostat acts on the relative velocity of pairs closer than r_c, so it
holds the first and cannot see the second. From the snapshots (<time>/particles.h5) this measures, for
the mobile particles of a slab, with dv = v - u(z) the velocity about the mean profile interpolated at
each particle (which removes the mean shear):
    single      <dv^2> / D                        the bins' kT (D active axes)
    pair        <|dv_i - dv_j|^2> / (2 D)         over pairs closer than r_c: the heat
    shared      <dv_i . dv_j> / D                 over the same pairs: the motion neighbours share
For velocities uncorrelated between particles at a common kT, pair = single = kT and shared = 0
(canonical momenta factorise); motion shared by neighbours raises single and shared alike and
cancels in pair.

As a command (etc/pairTemperature.py), for the sampled window of a case's binnedProfile function (its axis, range and start
time, the run's end time from system/controlDict), over the central part of the range, writes
postProcessing/pairTemperature/<start>/pairTemperature.dat (time single pair shared per snapshot),
whole or not at all:
    pairTemperature.py [-case DIR] -function NAME [-central FRACTION (0.5)]
"""
import argparse
import glob
import os
import subprocess
import sys

import h5py
import numpy as np
from scipy.spatial import cKDTree

from .io import dictionary_value


def snapshot_times(case, start, end):
    """The snapshot times of a case in [start, end], increasing."""
    times = []
    for path in glob.glob(os.path.join(case, "[0-9]*", "particles.h5")):
        t = float(os.path.basename(os.path.dirname(path)))
        if start <= t <= end:
            times.append((t, path))
    return sorted(times)


def read_mobile(path):
    """Positions and velocities of the mobile particles of a snapshot, and its box and dimension."""
    with h5py.File(path, "r") as f:
        frozen = np.asarray(f.attrs["speciesFrozen"]) != 0
        lo, hi = np.asarray(f.attrs["boxLo"], float), np.asarray(f.attrs["boxHi"], float)
        dimension = int(f.attrs["dimension"])
        keep = ~frozen[np.asarray(f["particles/species"])]
        x = np.asarray(f["particles/position"])[keep]
        v = np.asarray(f["particles/velocity"])[keep]
    return x, v, lo, hi, dimension


def mean_profile(snapshots, axis, lo, hi, n_bins):
    """The mean velocity per bin along `axis` over the snapshots [(x, v), ...] (bin centres, (n, 3))."""
    edges = np.linspace(lo, hi, n_bins + 1)
    centres = 0.5 * (edges[1:] + edges[:-1])
    total, count = np.zeros((n_bins, 3)), np.zeros(n_bins)
    for x, v in snapshots:
        k = np.digitize(x[:, axis], edges) - 1
        inside = (k >= 0) & (k < n_bins)
        count += np.bincount(k[inside], minlength=n_bins)
        for a in range(3):
            total[:, a] += np.bincount(k[inside], v[inside, a], minlength=n_bins)
    with np.errstate(invalid="ignore", divide="ignore"):
        return centres, total / count[:, None]


def snapshot_temperatures(x, v, profile, axis, region, box_lo, box_hi, dimension, cutoff=1.0):
    """single, pair and shared kT (module docstring) of one snapshot's particles whose coordinate
    along `axis` lies in region = (lo, hi); pairs with both particles in it."""
    centres, u = profile
    good = np.all(np.isfinite(u), axis=1)
    dv = v - np.stack([np.interp(x[:, axis], centres[good], u[good, a]) for a in range(3)], axis=1)
    inside = (x[:, axis] >= region[0]) & (x[:, axis] < region[1])
    length = box_hi - box_lo
    active = [a for a in range(3) if dimension == 3 or a != 1]
    pos = np.mod(x - box_lo, length)[:, active]
    tree = cKDTree(pos, boxsize=length[active])
    pairs = tree.query_pairs(cutoff, output_type="ndarray")
    i, j = pairs[:, 0], pairs[:, 1]
    both = inside[i] & inside[j]
    i, j = i[both], j[both]
    d = float(len(active))
    dva = dv[:, active]
    single = float(np.mean(np.sum(dva[inside] ** 2, axis=1)) / d)
    pair = float(np.mean(np.sum((dva[i] - dva[j]) ** 2, axis=1)) / (2.0 * d))
    shared = float(np.mean(np.sum(dva[i] * dva[j], axis=1)) / d)
    return single, pair, shared


def pair_temperature(case, start, end, axis, region, profile_range, n_bins, cutoff=1.0):
    """Per snapshot of `case` in [start, end]: (time, single, pair, shared) in the slab `region`
    along `axis`, about the mean profile over those snapshots in n_bins bins over profile_range.
    Returns an array (snapshots, 4)."""
    found = snapshot_times(case, start, end)
    if not found:
        raise RuntimeError(f"pair_temperature: no snapshot of {case} in [{start:g}, {end:g}]")
    data = [(t,) + read_mobile(path) for t, path in found]
    profile = mean_profile([(x, v) for _, x, v, *_ in data], axis, profile_range[0], profile_range[1], n_bins)
    rows = []
    for t, x, v, lo, hi, dimension in data:
        rows.append((t,) + snapshot_temperatures(x, v, profile, axis, region, lo, hi, dimension, cutoff))
    return np.array(rows)


AXES = {"x": 0, "y": 1, "z": 2}
PROFILE_BIN = 0.25  # the mean profile's bins: fine enough that its curvature within one is negligible


def table_path(case, start):
    return os.path.join(case, "postProcessing", "pairTemperature", f"{start:g}", "pairTemperature.dat")


def write_table(path, rows, header):
    """The rows (time single pair shared), written to a temporary file and renamed."""
    os.makedirs(os.path.dirname(path), exist_ok=True)
    tmp = f"{path}.tmp.{os.getpid()}"
    np.savetxt(tmp, rows, fmt="%.10g", header=header)
    os.replace(tmp, path)


def function_window(case, function, central):
    """The axis, the measured region, the profile's range and the sampled window (start, end) of a
    binnedProfile function of the case's controlDict."""
    control = os.path.join(case, "system", "controlDict")
    entry = f"functions/{function}/"
    try:
        axis_name = dictionary_value(control, entry + "axis")
        lo, hi = float(dictionary_value(control, entry + "min")), float(dictionary_value(control, entry + "max"))
        start = float(dictionary_value(control, entry + "startTime"))
        end = float(dictionary_value(control, "endTime"))
    except subprocess.CalledProcessError as e:
        raise RuntimeError(f"pairTemperature: {control}: {e.stderr.strip()}") from None
    if axis_name not in AXES:
        raise RuntimeError(f"pairTemperature: {control}: {entry}axis: expected x, y or z, got {axis_name}")
    if not 0.0 < central <= 1.0:
        raise RuntimeError(f"pairTemperature: the central fraction must lie in (0, 1], got {central:g}")
    centre, half = 0.5 * (lo + hi), 0.5 * central * (hi - lo)
    return axis_name, (centre - half, centre + half), (lo, hi), (start, end)


def measure_case(case, function, central=0.5):
    """Measures the snapshots of the function's window and writes the table; returns (rows, path)."""
    axis_name, region, span, (start, end) = function_window(case, function, central)
    rows = pair_temperature(case, start, end, AXES[axis_name], region, span,
                            max(1, int(round((span[1] - span[0]) / PROFILE_BIN))))
    path = table_path(case, start)
    write_table(path, rows, f"pairTemperature.py -function {function}: {axis_name} in [{region[0]:g}, {region[1]:g}), "
                f"snapshots {start:g}-{end:g} (docs/analysis.md 5.5)\ntime single pair shared")
    return rows, path


def case_rows(case, function, central=0.5):
    """The case's table if written (the snapshots may be gone), else measured from the snapshots."""
    _, _, _, (start, _) = function_window(case, function, central)
    path = table_path(case, start)
    if os.path.exists(path):
        return np.loadtxt(path, comments="#", ndmin=2)
    return measure_case(case, function, central)[0]


def main(argv=None):
    parser = argparse.ArgumentParser(prog="pairTemperature.py", description=__doc__.split("\n\n")[0])
    parser.add_argument("-case", default=".")
    parser.add_argument("-function", required=True, help="a binnedProfile function of system/controlDict")
    parser.add_argument("-central", type=float, default=0.5, help="the central fraction of its range measured")
    args = parser.parse_args(argv)
    try:
        rows, path = measure_case(args.case, args.function, args.central)
    except RuntimeError as e:
        sys.exit(str(e))
    print(f"{len(rows)} snapshots: single {rows[:, 1].mean():.5f}, pair {rows[:, 2].mean():.5f}, "
          f"shared {rows[:, 3].mean():.5f}; written {path}")
    return 0
