#!/usr/bin/env python3
"""The chains' extension by where they lie across the channel, from a case's snapshots (polymer channel
tutorial; README, "Chain extension across the channel").

For every snapshot (<time>/particles.h5) in the sampled window of a binnedProfile function (its startTime
to the run's endTime, system/controlDict), every chain unwrapped from its bond vectors
(dpdfoam.snapshots.unwrapped_chains) gives one row: its centre across the channel (the mean bead
coordinate along the profile's axis), its extension along the flow (x: max - min bead x), its R_g^2 and
the square of its end-to-end vector's x component. chainStatistics bins the same by the chain's
centre but keeps no block errors per bin; from these rows plotResults.py forms super-block means of the
outer and the central chains, with errors. Written whole or not at all:
    postProcessing/chainExtension/<start>/chainExtension.dat   (time chain centre spanx Rg2 Reex2)

    chainExtension.py [-case DIR] [-function NAME (channelProfile)]
"""
import argparse
import glob
import os
import sys

import numpy as np

from dpdfoam.io import dictionary_value
from dpdfoam.snapshots import unwrapped_chains

AXES = {"x": 0, "y": 1, "z": 2}
COLUMNS = "time chain centre spanx Rg2 Reex2"


def window(case, function):
    """The profile's axis and its sampled window (startTime, endTime)."""
    control = os.path.join(case, "system/controlDict")
    axis = dictionary_value(control, f"functions/{function}/axis").strip()
    return AXES[axis], float(dictionary_value(control, f"functions/{function}/startTime")), float(dictionary_value(control, "endTime"))


def snapshot_rows(path, time, axis):
    """One row per chain of a snapshot."""
    rows = []
    for chain, p in sorted(unwrapped_chains(path).items()):
        d = p - p.mean(axis=0)
        rows.append((time, chain, p[:, axis].mean(), np.ptp(p[:, 0]), float(np.mean(np.sum(d * d, axis=1))),
                     (p[-1, 0] - p[0, 0]) ** 2))
    return rows


def measure(case, function="channelProfile"):
    """The rows of every snapshot in the window, and the table's path."""
    axis, start, end = window(case, function)
    rows = []
    for path in glob.glob(os.path.join(case, "[0-9]*", "particles.h5")):
        t = float(os.path.basename(os.path.dirname(path)))
        if start <= t <= end:
            rows += snapshot_rows(path, t, axis)
    rows.sort()
    return np.array(rows).reshape(-1, 6), os.path.join(case, "postProcessing/chainExtension", f"{start:g}", "chainExtension.dat")


def case_rows(case, function="channelProfile"):
    """The case's table, or the rows measured now from its snapshots (None where it has neither)."""
    _, start, _ = window(case, function)
    path = os.path.join(case, "postProcessing/chainExtension", f"{start:g}", "chainExtension.dat")
    if os.path.exists(path):
        return np.loadtxt(path, comments="#", ndmin=2)
    rows, _ = measure(case, function)
    return rows if len(rows) else None


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-case", default=".")
    parser.add_argument("-function", default="channelProfile", help="the binnedProfile whose window is measured")
    args = parser.parse_args()
    rows, path = measure(args.case, args.function)
    if not len(rows):
        sys.exit(f"chainExtension: no chains in the snapshots of {args.case} in the window of {args.function}")
    os.makedirs(os.path.dirname(path), exist_ok=True)
    tmp = path + ".tmp"
    np.savetxt(tmp, rows, fmt=["%.6g", "%d", "%.6g", "%.6g", "%.6g", "%.6g"], header=COLUMNS)
    os.replace(tmp, path)
    print(f"chainExtension: {len(np.unique(rows[:, 0]))} snapshots, {len(np.unique(rows[:, 1]))} chains: written {path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
