"""Reading what the tools write, for the tutorials' plotResults.py scripts.

    import sys, os; sys.path.insert(0, os.path.join(os.environ["DPD_PROJECT_DIR"], "etc"))
    from dpdResults import latest, parse_dict, read_dict, read_sweep, read_table
"""
import glob
import os
import re
import subprocess
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


def dictionary_value(path, entry):
    """An entry of a case dictionary (controlDict, dpdProperties) as dpdDictionary prints it."""
    out = subprocess.run(["dpdDictionary", path, "-entry", entry, "-value"], check=True, capture_output=True, text=True)
    return out.stdout.strip().rstrip(";")


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


def kT_against_shear(periodic, g, nu):
    """kT against the local shear rate in the periodic box without walls (a tutorial's viscosity/ case).

    DPD heats a sheared fluid: the work eta shear^2 is taken out by the pair thermostat only once the
    fluid is warmer than the set kT, and the thermostat relaxes fast enough (a rate of a few per unit
    time against heat diffusion over about one cutoff) for kT to follow the local shear rate. The
    periodic reverse-Poiseuille box covers the same shear rates as the channel (0 at its velocity
    extremes to g L / (4 nu) at the half boundaries, as 0 at the centre to g d / (2 nu) at the walls)
    with no wall to take heat away, so it measures kT(shear) for this fluid. Returns (shear, kT)
    sorted by shear, averaged over the four quarter-periods.
    """
    z, kT = periodic["z"], periodic["kT"]
    lo = z[0] - 0.5 * (z[1] - z[0])
    length = (z[1] - z[0]) * len(z)
    # Distance to the nearest velocity extreme, at a quarter and three quarters of the box.
    x = np.minimum(np.abs(z - (lo + 0.25 * length)), np.abs(z - (lo + 0.75 * length)))
    edges = np.linspace(0.0, 0.25 * length, 21)
    which = np.clip(np.digitize(x, edges) - 1, 0, len(edges) - 2)
    centres = 0.5 * (edges[1:] + edges[:-1])
    means = np.array([np.mean(kT[which == k]) for k in range(len(centres))])
    return g * centres / nu, means


def read_published(path):
    """A tutorial's published.dat: {"source", "scene", "parameters": [(file, entry, value)],
    "tables": {name: {column: array}}, "fits": {quantity: (variable, function of a)}}."""
    out = {"source": "", "scene": "", "parameters": [], "tables": {}, "fits": {}}
    table = None
    with open(path) as f:
        for number, line in enumerate(f, 1):
            words = line.split("#", 1)[0].split(None, 1)
            if not words:
                continue
            key, rest = words[0], (words[1].strip() if len(words) > 1 else "")
            if key in ("source", "scene"):
                out[key] = rest
            elif key == "parameter":
                parts = rest.split(None, 2)
                if len(parts) != 3:
                    sys.exit(f"{path}:{number}: 'parameter' needs a file, an entry and a value")
                out["parameters"].append(tuple(parts))
            elif key == "table":
                table = out["tables"].setdefault(rest, {"columns": [], "rows": []})
            elif key == "columns" and table is not None:
                table["columns"] = rest.split()
            elif key == "row" and table is not None:
                values = [float(v) for v in rest.split()]
                if len(values) != len(table["columns"]):
                    sys.exit(f"{path}:{number}: {len(values)} values for {len(table['columns'])} columns")
                table["rows"].append(values)
            elif key == "count":
                continue  # a builder's particle count: etc/checkPublishedCounts reads it
            elif key == "fit":
                name, expression = rest.split(None, 1)
                quantity, variable = name.split(":")
                out["fits"][quantity] = (variable, lambda a, e=expression: eval(e, {"__builtins__": {}}, {"a": a}))
            else:
                sys.exit(f"{path}:{number}: unknown keyword '{key}'")
    for name, t in out["tables"].items():
        rows = np.array(t["rows"], ndmin=2)
        out["tables"][name] = {c: rows[:, k] for k, c in enumerate(t["columns"])}
    return out


def walls_mean_slip(sweep):
    """Per run of a sweep, the slip length of the two walls' mean and its standard error (a fluctuation
    of the channel's mean velocity moves the two walls' slip in opposite directions and cancels here)."""
    b = 0.5 * (np.asarray(sweep["slipLength_0"]) + np.asarray(sweep["slipLength_1"]))
    return b, 0.5 * np.hypot(sweep["slipLengthError_0"], sweep["slipLengthError_1"])


def compare_with_published(table, key, keys, measured, errors, quantity="slipLength", absolute=0.3, relative=0.30):
    """Each published row whose `key` matches one of `keys` beside the measured value: a list of
    (key, measured, error, published, tolerance, within) with tolerance max(absolute, relative x
    |published|) (issue 25's point-by-point bound)."""
    out = []
    for x, p in zip(table[key], table[quantity]):
        k = np.flatnonzero(np.isclose(keys, x))
        if k.size == 0 or not np.isfinite(p):
            continue
        k = k[0]
        tolerance = max(absolute, relative * abs(p))
        out.append((x, measured[k], errors[k], p, tolerance, bool(abs(measured[k] - p) <= tolerance)))
    return out


def published_checks(comparison, what, key, accounted=None):
    """The checks of compare_with_published's rows, two per point: the measured value's standard error
    within a third of the point's tolerance (the bound is then at least 3 standard errors wide; a run
    too noisy to decide fails), then the value within the tolerance. `what` names the quantity, `key`
    the swept parameter ("a_ww = {:g}").

    accounted = (ingredient, comparison of the named variant that changes it, how to run that variant):
    a point outside the tolerance passes when the variant's point at the same key is decided and
    within the tolerance (issue 25: "or the measured ingredient that accounts for the difference"). It
    is one check, named so, with both values; without the variant's run it fails and says how to run it."""
    variant = {}
    if accounted is not None:
        ingredient, variant_rows, how = accounted
        variant = {x: (m, e, ok) for x, m, e, _, _, ok in variant_rows}
    checks = []
    for x, m, e, p, tolerance, ok in comparison:
        where = key.format(x)
        measured = f"{m:+.4f} +- {e:.4f}, difference {m - p:+.4f} ({(m - p) / e:+.1f} standard errors)"
        if not ok and accounted is not None:
            name = (f"{what} ({where}) outside max(0.3 r_c, 30 %) = {tolerance:.3f} of the published {p:g}: "
                    f"accounted for by {ingredient}")
            if x not in variant:
                checks.append((name, False, f"{measured}; the variant has not run at {where} ({how})"))
                continue
            mv, ev, okv = variant[x]
            decided = ev <= tolerance / 3
            checks.append((name, bool(decided and okv),
                           f"{measured}; the variant {mv:+.4f} +- {ev:.4f}, difference {mv - p:+.4f} "
                           f"({'within' if okv else 'outside'} the tolerance, error "
                           f"{'within' if decided else 'above'} a third of it)"))
            continue
        checks += [
            (f"published comparison: the {what}'s standard error within a third of the tolerance, "
             f"{tolerance / 3:.3f} ({where})", bool(e <= tolerance / 3), f"{e:.4f}"),
            (f"{what} within max(0.3 r_c, 30 %) = {tolerance:.3f} of the published {p:g} ({where})", ok,
             measured),
        ]
    return checks
