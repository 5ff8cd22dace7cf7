"""A time-step study of cases run as one copy per integrator and step (<runs>/<scene>-<integrator>-dt<step>/,
tutorials/benchmarks/walledStep): what each copy measured and what it cost, the differences from the
smallest step, and the largest step that keeps them within tolerances. The rows are dicts in
dpdfoam.stepstudy's form ("dt", "unstable", a quantity's difference q and its standard error q + "se",
"cost" in seconds per particle per time unit), so its cost model and largest_step apply.

    rows = scene_rows("runs", "latticeWall", ["GrootWarren0.65", "DPDVV"])  # {integrator: [row by dt]}
    for points in rows.values():
        against_smallest(points, Tolerances(0.02, 0.05, 3, 0.01))          # differences and verdicts
    best = largest_step(points, keeps)                                   # stepstudy.largest_step

A copy holds its solver log (log.dpdFoamLike: stopped by the run's monitor or finished, the steps, the
threads and particles), its CPU time (log.cpuTime, "dpdFoamLike cpuSeconds <user> <system> wallSeconds
<real>": the Allrun times the solver with bash's `time`; without it the log's wall time times its
threads), fitSlipLength's latest fit.dat (nu, the slip length at each wall, their errors, the walls'
positions) and the profile's sampled blocks (<time>/sampling/<profile>.h5), from which kT within a
cutoff of each wall is taken with its error over ten groups of consecutive blocks.
"""
import glob
import math
import os
import re
from collections import namedtuple

from matplotlib.ticker import LogLocator, NullFormatter, ScalarFormatter

from .blocks import SampledBins, region_temperature
from .io import dictionary_number, latest_fit, read_text, run_finished
from .plots import plt
from .snapshots import snapshot_box
from .stats import BlockMean

# What a step must keep against the smallest step: nu within nu (relative), the slip length within the
# larger of b (in cutoffs) and bErrors combined standard errors, kT next to the walls within kT (relative).
Tolerances = namedtuple("Tolerances", "nu b bErrors kT")
QUANTITIES = ("nu", "b", "kTwall")
NAN = float("nan")


def solver_run(case):
    """A copy's solver log and CPU time: whether the run's monitor stopped it (and when), the steps it
    made, the mobile and frozen particles, the threads, the CPU and wall seconds, the particles the walls
    found crossed (summed over the reports)."""
    text = read_text(os.path.join(case, "log.dpdFoamLike"))
    out = {"unstable": False, "stoppedAt": NAN}
    stop = re.search(r"went unstable at time (\S+) \(step (\d+)\)", text)
    steps, wall, _ = run_finished(text)
    if stop:
        out.update(unstable=True, stoppedAt=float(stop.group(1)), steps=int(stop.group(2)), wallSeconds=NAN)
    else:
        out.update(steps=steps, wallSeconds=wall)
    m = re.search(r"^Particles\s*:\s*(\d+) \((\d+) mobile, (\d+) frozen\)", text, re.M)
    out["particles"], out["mobile"], out["frozen"] = (int(g) for g in m.groups()) if m else (NAN, NAN, NAN)
    m = re.search(r"^Threads\s*:\s*(\d+)", text, re.M)
    out["threads"] = int(m.group(1)) if m else 1
    out["crossed"] = sum(int(n) for n in re.findall(r"crossed (\d+);", text))
    out["cpuSeconds"] = NAN
    timing = os.path.join(case, "log.cpuTime")
    if os.path.exists(timing):
        m = re.search(r"cpuSeconds (\S+) (\S+) wallSeconds (\S+)", read_text(timing))
        if m:
            out["cpuSeconds"] = float(m.group(1)) + float(m.group(2))
    if math.isnan(out["cpuSeconds"]) and not out["unstable"]:
        out["cpuSeconds"] = out["wallSeconds"] * out["threads"]
    return out


def latest_sampling_of(case, profile):
    """The latest time directory's sampled blocks of the binnedProfile `profile` (None without one)."""
    paths = glob.glob(os.path.join(case, "*", "sampling", profile + ".h5"))
    timed = [p for p in paths if re.fullmatch(r"[0-9.eE+-]+", p.split(os.sep)[-3])]
    return max(timed, key=lambda p: float(p.split(os.sep)[-3])) if timed else None


def near_wall_temperature(path, walls, cutoff=1.0, groups=10):
    """kT within `cutoff` of either wall (bins whose centres lie between a wall and cutoff from it),
    weighted by the particle-samples, from a binnedProfile's sampled blocks (the latest groups x per
    complete blocks, ten groups of consecutive blocks unless fewer): a BlockMean whose value is the
    whole window's and whose error is the groups' spread (kT decorrelates in well under a time unit, a
    group spans tens)."""
    bins = SampledBins(path)
    region = ((bins.z > walls[0]) & (bins.z < walls[0] + cutoff)) | ((bins.z < walls[1]) & (bins.z > walls[1] - cutoff))
    m = min(groups, len(bins.blocks))
    if m < 2 or not region.any():
        return BlockMean([NAN, NAN])
    sums = bins.latest(len(bins.blocks) // m, m).sum(axis=1)
    return BlockMean(region_temperature(sums, region), region_temperature(sums.sum(axis=0), region))


def run_row(case, profile="channelProfile"):
    """One copy as a row: "dt" (its controlDict's deltaT), "endTime", the solver run (solver_run), and,
    when the monitor did not stop it, the fit's nu and slip lengths with their errors ("nuValue",
    "nuValueSe"; "bWalls", "bWallsSe"; "bValue", the mean of the two walls, with "bValueSe" the mean of
    their errors, the walls' errors taken as fully correlated: both move with the fitted curvature),
    kT within a cutoff of the walls ("kTwallValue", "kTwallValueSe"), the fit's kind of errors, and the
    cost: "stepCost" CPU seconds per particle-step, "cost" per particle per time unit."""
    control = os.path.join(case, "system/controlDict")
    row = {"case": case, "dt": dictionary_number(control, "deltaT"), "endTime": dictionary_number(control, "endTime")}
    row.update(solver_run(case))
    # A stopped run's cost is left out: its few steps carry the whole start-up.
    row["stepCost"] = row["cpuSeconds"] / (row["mobile"] * row["steps"]) if row["steps"] and not row["unstable"] else NAN
    row["cost"] = row["stepCost"] / row["dt"]
    for q in QUANTITIES:
        row[q + "Value"] = row[q + "ValueSe"] = NAN
    row["bWalls"] = row["bWallsSe"] = (NAN, NAN)
    row["errors"] = row["errorsNote"] = ""
    if row["unstable"]:
        return row
    cutoff = dictionary_number(os.path.join(case, "constant/dpdProperties"), "cutoff", 1.0)
    fit = latest_fit(case)
    walls = fit.get("wallPosition", [NAN, NAN])
    b, be = fit.get("slipLength", [NAN, NAN]), fit.get("slipLengthError", [NAN, NAN])
    row.update(nuValue=fit.get("nu", NAN), nuValueSe=fit.get("nuError", NAN), bWalls=tuple(b), bWallsSe=tuple(be),
               bValue=0.5 * (b[0] + b[1]), bValueSe=0.5 * (be[0] + be[1]), errors=fit.get("errors", ""),
               errorsNote=fit.get("superBlocksNote", ""), walls=tuple(walls), cutoff=cutoff)
    path = latest_sampling_of(case, profile)
    if path is not None:
        kT = near_wall_temperature(path, walls, cutoff)
        row.update(kTwallValue=kT.value, kTwallValueSe=kT.error)
    return row


def run_name(scene, integrator, dt):
    """The copy's directory name in the study (the Allrun's runs/<scene>-<integrator>-dt<step>)."""
    return f"{scene}-{integrator}-dt{dt}"


def scene_rows(directory, scene, integrators, profile="channelProfile"):
    """{integrator: [run_row of each copy <directory>/<scene>-<integrator>-dt*, by dt]} (an integrator
    without copies is left out)."""
    out = {}
    for label in integrators:
        cases = [c for c in glob.glob(os.path.join(glob.escape(directory), glob.escape(f"{scene}-{label}-dt")) + "*")
                 if os.path.isdir(c)]
        if cases:
            out[label] = sorted((run_row(c, profile) for c in cases), key=lambda r: r["dt"])
    return out


def measured_all(p):
    """Whether the run is stable and nu, the slip length and kT next to the walls are numbers."""
    return not p["unstable"] and all(math.isfinite(p[q + "Value"]) for q in QUANTITIES)


def against_smallest(points, tol):
    """Each row's differences from the reference, the smallest step whose run is stable and measured all
    three quantities (None when none did; then every row's differences are NaN): "nu" and "kTwall"
    relative, "b" in length units, each with its standard error (the two runs' combined; the reference's
    own differences are 0 +- 0), the tolerance of each ("nuTol", "bTol" = max(tol.b x cutoff, tol.bErrors
    x the combined error), "kTwallTol"), "keeps" (every difference within its tolerance) and "limits"
    (the quantities that are not). Returns the reference row."""
    ref = next((p for p in points if measured_all(p)), None)
    for p in points:
        p["reference"] = p is ref
        cutoff = p.get("cutoff", 1.0)
        if ref is None or not measured_all(p):
            for q in QUANTITIES:
                p[q], p[q + "se"], p[q + "Tol"] = NAN, NAN, NAN
        elif p is ref:
            for q in QUANTITIES:
                p[q], p[q + "se"] = 0.0, 0.0
        else:
            for q in ("nu", "kTwall"):
                v, e, r, re_ = p[q + "Value"], p[q + "ValueSe"], ref[q + "Value"], ref[q + "ValueSe"]
                p[q] = v / r - 1.0
                p[q + "se"] = math.hypot(e / r, v * re_ / r ** 2)
            p["b"] = p["bValue"] - ref["bValue"]
            p["bse"] = math.hypot(p["bValueSe"], ref["bValueSe"])
        p["nuTol"], p["kTwallTol"] = tol.nu, tol.kT
        p["bTol"] = max(tol.b * cutoff, tol.bErrors * math.hypot(p["bValueSe"], ref["bValueSe"])) if ref else NAN
        p["limits"] = [q for q in QUANTITIES if not abs(p[q]) <= p[q + "Tol"]]
        p["keeps"] = not p["unstable"] and not p["limits"]
    return ref


def keeps(p):
    """Whether a row keeps every quantity within its tolerance of the reference (stable, all measured)."""
    return p.get("keeps", False)


def limiting_step(points):
    """The first row (by dt) that does not keep the reference's quantities, or None."""
    return next((p for p in points if not keeps(p)), None)


def scene_text(case):
    """A copy's scene in words, from its solver log and its snapshot 0/: the particles, the box, the
    walls and the body force."""
    text = read_text(os.path.join(case, "log.dpdFoamLike"))
    lines = []
    m = re.search(r"^Particles\s*:\s*(.*)$", text, re.M)
    if m:
        lines.append("particles " + m.group(1))
    start = os.path.join(case, "0", "particles.h5")
    if os.path.exists(start):
        lo, hi = snapshot_box(start)
        lines.append("box " + " x ".join(f"{h - l:g}" for l, h in zip(lo, hi)) + " (" +
                     ", ".join(f"{l:g} to {h:g}" for l, h in zip(lo, hi)) + ")")
    lines += ["wall " + w.strip() for w in re.findall(r"^    (\S+: reflection[^\n]*)$", text, re.M)]
    m = re.search(r"^Pair force\s*:\s*(.*)$", text, re.M)
    if m:
        lines.append("pair force " + m.group(1))
    m = re.search(r"^Body force\s*:\s*(.*)$", text, re.M)
    if m:
        lines.append("body force " + m.group(1))
    return lines


# ---- Pictures ------------------------------------------------------------------------------------------

MARKERS = "osD^v<>"
QUANTITY_MARKERS = {"nu": "o", "b": "s", "kTwall": "^"}


def mark_unstable(ax, points, colour, label=None):
    """The steps at which the monitor stopped a run, as crosses along the bottom of the panel."""
    dts = [p["dt"] for p in points if p["unstable"]]
    if dts:
        ax.plot(dts, [0.02] * len(dts), "x", color=colour, ms=9, mew=2, transform=ax.get_xaxis_transform(),
                label=label)


def colours_of(rows):
    """{integrator: colour}, the default colour cycle in the rows' order (every panel alike)."""
    cycle = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    return {label: cycle[k % len(cycle)] for k, label in enumerate(rows)}


def draw_against_dt(ax, rows, q, scale=1.0):
    """A quantity's values (q + "Value", times scale) with their standard errors against the step, one
    curve per integrator; the steps the monitor stopped as crosses along the bottom."""
    colours = colours_of(rows)
    for k, (label, points) in enumerate(rows.items()):
        ok = [p for p in points if not p["unstable"] and math.isfinite(p[q + "Value"])]
        ax.errorbar([p["dt"] for p in ok], [scale * p[q + "Value"] for p in ok], yerr=[scale * p[q + "ValueSe"] for p in ok],
                    marker=MARKERS[k % len(MARKERS)], capsize=2, color=colours[label], label=label)
        mark_unstable(ax, points, colours[label], f"{label}: stopped by the monitor")
    ax.set_xlabel("dt")


def draw_tolerance_band(ax, rows, q, relative):
    """The band a step must keep around each integrator's reference value (dotted, its colour):
    value x (1 +- tolerance) for a relative tolerance, value +- tolerance otherwise."""
    colours = colours_of(rows)
    for label, points in rows.items():
        ref = next((p for p in points if p.get("reference")), None)
        if ref is None:
            continue
        v = ref[q + "Value"]
        widths = [p[q + "Tol"] for p in points if math.isfinite(p.get(q + "Tol", NAN))]
        if not widths:
            continue
        w = min(widths) * (abs(v) if relative else 1.0)
        for s in (-1, 1):
            ax.axhline(v + s * w, color=colours[label], ls=":", lw=0.8)


def draw_scaled_errors_against_cost(ax, rows, names=None):
    """Each step's |difference from the smallest step| / its tolerance against the cost (seconds per
    particle per time unit), one colour per integrator, one marker per quantity (nu o, b s, kT next to the
    walls ^), each point labelled with its dt; 1 (dashed) is the tolerance. The reference steps (zero by
    construction) are left out."""
    names = names or {"nu": "nu", "b": "b", "kTwall": "kT wall"}
    colours = colours_of(rows)
    drawn = False
    for label, points in rows.items():
        colour = colours[label]
        for q in QUANTITIES:
            ok = [p for p in points if not p["unstable"] and not p.get("reference") and math.isfinite(p[q])
                  and math.isfinite(p["cost"])]
            if not ok:
                continue
            x = [1e6 * p["cost"] for p in ok]
            y = [max(abs(p[q]) / p[q + "Tol"], 1e-3) for p in ok]
            ax.plot(x, y, marker=QUANTITY_MARKERS[q], color=colour, ls="-" if q == "nu" else ("--" if q == "b" else ":"),
                    label=f"{label}: {names[q]}")
            drawn = True
            for p, cx, cy in zip(ok, x, y):
                ax.annotate(f"{p['dt']:g}", (cx, cy), fontsize=6, xytext=(3, 3), textcoords="offset points")
    if not drawn:
        ax.text(0.5, 0.6, "no stable, measured step\nbut the smallest", ha="center", transform=ax.transAxes)
    ax.axhline(1.0, color="k", ls="--", lw=0.8)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.xaxis.set_major_locator(LogLocator(subs=(1.0, 2.0, 5.0)))
    ax.xaxis.set_major_formatter(ScalarFormatter())
    ax.xaxis.set_minor_formatter(NullFormatter())
    ax.set_xlabel("cost: CPU microseconds per particle per time unit")
    ax.set_ylabel("|difference from the smallest step| / tolerance")
