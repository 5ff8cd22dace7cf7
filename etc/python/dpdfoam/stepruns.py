"""A time-step study of cases run as one copy per integrator and step (<runs>/<scene>-<integrator>-dt<step>/,
tutorials/benchmarks/walledStep): the study's dictionary, what each copy measured and what it cost, the
differences from the smallest step, the largest step that keeps them within tolerances, the tables and
the picture. The rows are dicts in dpdfoam.stepstudy's form ("dt", "unstable", a quantity's difference q
and its standard error q + "se", "cost" in seconds per particle per time unit), so its cost model and
largest_step apply.

    study = read_study("system/walledStepDict")               # scenes, integrators, steps, tolerances
    rows, costs = read_runs("runs", study.scenes, study.integrators, study.tol)  # {scene: {integrator: rows}}
    lines = study_lines("walledStep", False, study.tol, rows, costs)    # the runs' tables, the largest steps
    draw_study(rows, "walledStep.png", "title")                         # per scene four panels

or step by step:

    rows = scene_rows("runs", "latticeWall", ["GrootWarren0.65", "DPDVV"])  # {integrator: [row by dt]}
    for points in rows.values():
        against_smallest(points, Tolerances(0.02, 0.05, 3, 0.01))          # differences and verdicts
    best, why, unstable, speed_up = largest_keeping(points)              # stepstudy.largest_step with keeps

A copy holds its solver log (log.dpdFoamLike: stopped by the run's monitor or finished, the steps, the
threads and particles), its CPU time (log.cpuTime, "dpdFoamLike cpuSeconds <user> <system> wallSeconds
<real>": the Allrun times the solver with bash's `time`; without it the log's wall time times its
threads), fitSlipLength's latest fit.dat (nu, the slip length at each wall, their errors, the walls'
positions) and the profile's sampled blocks (<time>/sampling/<profile>.h5), from which kT within a
cutoff of each wall is taken with its error over ten groups of consecutive blocks.

Cost: CPU seconds (user + system, log.cpuTime) per particle-step of the mobile particles; each
integrator's median over its stable runs of the scene (dpdfoam.stepstudy.apply_cost_model: a step costs
the same at any dt, so one run slowed by other jobs moves nothing) divided by dt gives the cost of one
time unit per particle. The runs' table keeps each run's own cost per particle-step too.
"""
import glob
import math
import os
import re
import subprocess
from collections import namedtuple

from matplotlib.ticker import LogLocator, NullFormatter, ScalarFormatter

from .blocks import SampledBins, region_temperature
from .io import dictionary_number, dictionary_value, latest_fit, read_text, run_finished, write_whole
from .plots import label as label_axes, plt, save
from .snapshots import snapshot_box
from .stats import BlockMean
from .stepstudy import apply_cost_model, first_unstable, largest_step

# What a step must keep against the smallest step: nu within nu (relative), the slip length within the
# larger of b (in cutoffs) and bErrors combined standard errors, kT next to the walls within kT (relative).
Tolerances = namedtuple("Tolerances", "nu b bErrors kT")
# A study's dictionary: the scenes (case directories), the integrators' labels, the steps, the tolerances.
Study = namedtuple("Study", "scenes integrators steps tol")
QUANTITIES = ("nu", "b", "kTwall")
NAMES = {"nu": "nu", "b": "b", "kTwall": "kT next to the walls"}
NAN = float("nan")


def read_study(path):
    """A study's dictionary (tutorials/benchmarks/walledStep/system/walledStepDict): `scenes` and `deltaT`
    (lists), the `integrators` sub-dictionaries' names, nuTolerance, bTolerance, bErrors, kTTolerance."""
    scenes = dictionary_value(path, "scenes").strip("()").split()
    steps = [float(w) for w in dictionary_value(path, "deltaT").strip("()").split()]
    text = subprocess.run(["dpdDictionary", path, "-entry", "integrators", "-value"], check=True, capture_output=True,
                          text=True).stdout
    labels = re.findall(r"^    ([^ {};]+)$", text, re.M)  # dpdDictionary prints the names four spaces in
    tol = Tolerances(*(float(dictionary_value(path, k)) for k in ("nuTolerance", "bTolerance", "bErrors", "kTTolerance")))
    return Study(scenes, labels, steps, tol)


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


def read_runs(directory, scenes, integrators, tol, profile="channelProfile"):
    """Every scene's copies (scene_rows) with the differences from each integrator's smallest step
    (against_smallest) and the cost model applied (stepstudy.apply_cost_model): ({scene: {integrator:
    rows}}, {scene: {integrator: (median, lowest, highest) CPU seconds per particle-step}}); a scene
    without copies is left out of both."""
    rows, costs = {}, {}
    for scene in scenes:
        r = scene_rows(directory, scene, integrators, profile)
        if not r:
            continue
        for points in r.values():
            against_smallest(points, tol)
        costs[scene] = apply_cost_model(r)
        rows[scene] = r
    return rows, costs


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


def largest_keeping(points):
    """The largest measured step up to which every step keeps the reference (stepstudy.largest_step with
    keeps; None when the smallest does not), why the next larger step does not ("-" when it is not
    measured, "unstable at <dt>" when the monitor stopped it, else the quantities it failed "nu,kTwall at
    <dt>"), the first step the monitor stopped (None) and the speed-up: the reference's cost of a time
    unit over the largest step's (NaN without one)."""
    p = largest_step(points, keeps)
    nxt = limiting_step(points)
    why = "-" if nxt is None else (f"unstable at {nxt['dt']:g}" if nxt["unstable"] else
                                   f"{','.join(nxt['limits'])} at {nxt['dt']:g}")
    ref = next((q for q in points if q.get("reference")), None)
    speed = ref["cost"] / p["cost"] if p and ref and math.isfinite(p["cost"]) else NAN
    return p, why, first_unstable(points), speed


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


# ---- Tables --------------------------------------------------------------------------------------------

def pm(value, error, digits=4, sign=""):
    """'value+-error' with digits decimals; '-' for a value that is not a number."""
    if not math.isfinite(value):
        return "-"
    return f"{value:{sign}.{digits}f}+-{error:.{digits}f}"


def difference(p, q, percent):
    """A row's difference from the reference with its error (in % when percent); 'ref', or '-' when
    unstable or not measured."""
    if p["unstable"] or not math.isfinite(p[q]):
        return "-"
    if p.get("reference"):
        return "ref"
    scale = 100.0 if percent else 1.0
    return f"{scale * p[q]:+.2f}+-{scale * p[q + 'se']:.2f}" if percent else f"{p[q]:+.3f}+-{p[q + 'se']:.3f}"


def fmt(x, spec=".3g"):
    """x formatted; '-' for None or a float that is not finite."""
    return "-" if x is None or (isinstance(x, float) and not math.isfinite(x)) else format(x, spec)


def verdict(p):
    """A row's verdict: 'ref', 'yes', 'no' (unstable) or 'no: ' and the quantities it failed."""
    if p.get("reference"):
        return "ref"
    if keeps(p):
        return "yes"
    return "no" if p["unstable"] else "no: " + ",".join(p["limits"])


def scene_lines(scene, r, costs):
    """A scene's table: the scene in words, every run's values, differences, tolerance of b, costs and
    verdict, then each integrator's cost per particle-step (costs: apply_cost_model's)."""
    any_run = next(iter(r.values()))[0]
    lines = ["#", f"# Scene {scene}: " + "; ".join(scene_text(any_run["case"])),
             f"# endTime {any_run['endTime']:g} at every step; fitSlipLength's errors: " +
             ", ".join(sorted({p['errors'] for pts in r.values() for p in pts if p['errors']})),
             "# integrator      dt     run              nu                 b (mean of walls)   kT next to walls    "
             "dnu(%)       db             tol(b)  dkT(%)       CPU s/p-step  CPU s/p/time unit  keeps"]
    for label, points in r.items():
        for p in points:
            run = f"stopped at {p['stoppedAt']:g}" if p["unstable"] else f"{p['steps']} steps"
            lines.append(f"{label:<16} {p['dt']:<6g} {run:<16} {pm(p['nuValue'], p['nuValueSe']):<18} "
                         f"{pm(p['bValue'], p['bValueSe'], 3, '+'):<19} {pm(p['kTwallValue'], p['kTwallValueSe']):<19} "
                         f"{difference(p, 'nu', True):<12} {difference(p, 'b', False):<14} {fmt(p.get('bTol')):<7} "
                         f"{difference(p, 'kTwall', True):<12} {fmt(p['stepCost']):<13} {fmt(p['cost']):<18} "
                         f"{verdict(p)}")
    lines += ["# Cost per particle-step (CPU seconds; median, lowest and highest over the stable runs)"]
    lines += [f"#   {label:<16} {median:.3g} ({low:.3g} to {high:.3g})" for label, (median, low, high) in costs.items()]
    return lines


def largest_lines(rows):
    """Per scene and integrator the largest step (largest_keeping), what limits it, the first unstable
    step, the cost of a time unit there and the speed-up; per scene the cheapest time unit."""
    lines = ["#", "# Largest step: the largest measured step up to which every step keeps nu within the tolerance,",
             "# b within max(tolerance x cutoff, bErrors combined SE) and kT next to the walls within the tolerance of",
             "# the same integrator's smallest step ('-' when the next step is not measured); limitedBy: what the",
             "# next larger step failed (unstable: stopped by the monitor); cost of a time unit at the largest step",
             "# (CPU s per particle, the median step cost / dt) and the speed-up against the smallest step.",
             "# scene           integrator       largestDt  limitedBy             firstUnstable  CPU s/p/time unit  speedUp"]
    for scene, r in rows.items():
        best = None
        for label, points in r.items():
            p, why, u, speed = largest_keeping(points)
            lines.append(f"{scene:<17} {label:<16} {fmt(p and p['dt'], 'g'):<10} {why:<21} {fmt(u, 'g'):<14} "
                         f"{fmt(p['cost'] if p else None):<18} {fmt(speed, '.2f')}")
            if p and math.isfinite(p["cost"]) and (best is None or p["cost"] < best[2]):
                best = (label, p["dt"], p["cost"])
        if best:
            lines.append(f"# {scene}: cheapest time unit within the tolerances: {best[0]} at dt {best[1]:g}, "
                         f"{best[2]:.3g} CPU s per particle")
    return lines


def study_lines(name, test_mode, tol, rows, costs):
    """results.dat's tables: the study's header (name, mode, tolerances), each scene's table
    (scene_lines), the largest steps (largest_lines)."""
    lines = [f"# {name} ({'test mode' if test_mode else 'full study'}): each run the same physical time; against "
             "the same integrator's smallest step: nu within "
             f"{100 * tol.nu:g} %, b within max({tol.b:g} r_c, {tol.bErrors:g} combined SE), kT within one cutoff of "
             f"the walls within {100 * tol.kT:g} %",
             "# (values +- standard errors; differences relative in %, b in length units; CPU s: user + system of the "
             "solver)"]
    for scene, r in rows.items():
        lines += scene_lines(scene, r, costs[scene])
    return lines + largest_lines(rows)


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


def draw_study(rows, path, title):
    """The study's picture: per scene nu, b and kT next to the walls against dt (the tolerance bands of
    nu and kT dotted) and each difference over its tolerance against the cost; saved to path."""
    n = len(rows)
    fig, axes = plt.subplots(n, 4, figsize=(20, 4.3 * n), squeeze=False)
    for (scene, r), ax in zip(rows.items(), axes):
        draw_against_dt(ax[0], r, "nu")
        draw_tolerance_band(ax[0], r, "nu", relative=True)
        label_axes(ax[0], f"{scene}: nu (fitSlipLength)", None, "nu", legend=7)
        draw_against_dt(ax[1], r, "b")
        label_axes(ax[1], f"{scene}: slip length (mean of the walls)", None, "b", legend=7)
        draw_against_dt(ax[2], r, "kTwall")
        draw_tolerance_band(ax[2], r, "kTwall", relative=True)
        label_axes(ax[2], f"{scene}: kT within a cutoff of the walls", None, "kT", legend=7)
        draw_scaled_errors_against_cost(ax[3], r, NAMES)
        ax[3].set_title(f"{scene}: difference / tolerance against cost (labels: dt)", fontsize=10)
        if ax[3].get_legend_handles_labels()[0]:
            ax[3].legend(fontsize=6)
    fig.suptitle(title, fontsize=11)
    save(fig, path, dpi=100)
