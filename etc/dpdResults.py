"""Reading what the tools write, for the tutorials' plotResults.py scripts.

    import sys, os; sys.path.insert(0, os.path.join(os.environ["DPD_PROJECT_DIR"], "etc"))
    from dpdResults import latest, parse_dict, read_dict, read_sweep, read_table
"""
import glob
import os
import re
import sys

import numpy as np


def latest(pattern):
    """The path matching pattern (.../<time>/<file>) whose time directory is the latest."""
    paths = glob.glob(pattern)
    if not paths:
        sys.exit(f"plotResults: nothing matches {pattern}")
    return max(paths, key=lambda p: float(os.path.basename(os.path.dirname(p))))


def read_table(path):
    """A whitespace table with a '# name name ...' header (profileBins): {name: column}."""
    with open(path) as f:
        header = f.readline().lstrip("#").split()
    data = np.loadtxt(path, comments="#", ndmin=2)
    return {name: data[:, k] for k, name in enumerate(header)}


def read_dict(path):
    """The plain `key value;` and `key (a b ...);` entries of a dictionary the tools write (fit.dat,
    compare.dat): numbers as floats, lists as lists of floats, anything else as a string."""
    with open(path) as f:
        return parse_dict(f.read())


def parse_dict(text):
    """read_dict on the text of a dictionary (or of one sub-dictionary's body)."""
    text = re.sub(r"FoamFile\s*\{[^}]*\}", "", text)
    out = {}
    for key, value in re.findall(r"^\s*(\w+)\s+([^;]+);", text, re.M):
        value = value.strip()
        try:
            if value.startswith("("):
                out[key] = [float(v) for v in value.strip("()").split()]
            else:
                out[key] = float(value)
        except ValueError:
            out[key] = value
    return out


def read_sweep(path):
    """runSweep's table: {column: values}; numbers as arrays, other columns (the run's name, a
    vector value written as (1,0,0)) as lists of words."""
    with open(path) as f:
        header = f.readline().lstrip("#").split()
        rows = [line.split() for line in f if line.strip()]
    out = {}
    for k, name in enumerate(header):
        words = [r[k] for r in rows]
        try:
            out[name] = np.array([float(w) for w in words])
        except ValueError:
            out[name] = words
    return out


def read_blocks(path):
    """The sampled bins of a 1-D binnedProfile (<time>/sampling/<name>.h5) block by block, complete
    blocks only: {"count", "sumU" (per block and bin: particle-samples and the sums of vx, vy, vz),
    "samples" (per block), "centres", "width", "crossSection", "blockSamples"}."""
    import h5py

    with h5py.File(path, "r") as f:
        blocks = np.array(f["blocks"])
        samples = np.array(f["samplesPerBlock"])
        attrs = {k: f.attrs[k] for k in ("nBins", "lo", "hi", "blockSamples", "crossSection")}
    complete = samples == attrs["blockSamples"]
    n = int(attrs["nBins"])
    width = (float(attrs["hi"]) - float(attrs["lo"])) / n
    return {
        "count": blocks[complete, :, 0],
        "sumU": blocks[complete, :, 1:4],
        "samples": samples[complete],
        "centres": float(attrs["lo"]) + width * (np.arange(n) + 0.5),
        "width": width,
        "crossSection": float(attrs["crossSection"]),
        "blockSamples": int(attrs["blockSamples"]),
    }
