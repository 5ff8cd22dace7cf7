"""A study of the time step: runs of one scene at several steps, per integrator, each row a dict with
"dt", "unstable" (the run's monitor stopped it), the quantities' relative errors and their standard
errors ("<q>se") and "cost" (seconds per particle per time unit). What a user asks of such a study:
where an error passes a level, where a method blows up, the largest step that keeps a property, and
whether a step is as accurate as a baseline (tutorials/benchmarks/speedAccuracy).

    costs = apply_cost_model(rows)                      # median cost per particle-step, per method
    c1 = crossing(points, "kT", 0.01)                   # where |kT error| passes 1 %
    best = largest_step(points, lambda p: as_accurate(p, base, ["kT", "nu"]))
"""
import math

import numpy as np


def measured(p, q):
    """Whether the run is stable and q a number."""
    return not p["unstable"] and not math.isnan(p[q])


def apply_cost_model(rows):
    """Per method: (median, lowest, highest) seconds per particle-step over its stable runs (a step
    costs the same whatever dt, so one run slowed by other jobs moves nothing); each stable run's cost
    replaced by that median over dt."""
    costs = {}
    for label, points in rows.items():
        per_step = sorted(p["cost"] * p["dt"] for p in points if not p["unstable"] and not math.isnan(p["cost"]))
        if per_step:
            costs[label] = (float(np.median(per_step)), per_step[0], per_step[-1])
            for p in points:
                if not p["unstable"]:
                    p["cost"] = costs[label][0] / p["dt"]
    return costs


def crossing(points, q, level):
    """The step at which |error of q| first passes level (points sorted by dt): interpolated between
    the last step below it and the first above it (a blow-up counts as above, a stable run with a NaN
    error, not measured, as neither: skipped); None when never passed,
    '<dt' when already at the smallest step, 'dt0-dt1' when the run above it blew up."""
    previous = None
    for p in points:
        if not p["unstable"] and math.isnan(p[q]):
            continue  # not measured (measured()): neither below nor above the level
        if p["unstable"] or abs(p[q]) > level:
            if previous is None:
                return "<%g" % p["dt"]
            if p["unstable"]:
                return "%.3g-%.3g" % (previous["dt"], p["dt"])
            e0, e1 = abs(previous[q]), abs(p[q])
            return "%.3g" % (previous["dt"] + (level - e0) * (p["dt"] - previous["dt"]) / (e1 - e0))
        previous = p
    return None


def first_unstable(points):
    """The smallest step at which the run's monitor stopped the method; None when it never did."""
    return next((p["dt"] for p in points if p["unstable"]), None)


def largest_step(points, qualifies):
    """The largest measured step up to which every step qualifies; None when the smallest does not."""
    best = None
    for p in points:
        if not qualifies(p):
            break
        best = p
    return best


def as_accurate(p, base, quantities):
    """Whether every error of p is within base's, within two combined standard errors (only an error
    above that bound disqualifies: a NaN standard error does not)."""
    return all(measured(p, q) and not abs(p[q]) > abs(base[q]) + 2 * math.hypot(p[q + "se"], base[q + "se"])
               for q in quantities)


def draw_errors_against_cost(ax, rows, q, levels, markers="osD^v<>"):
    """|error of q| (in %) against the cost, one curve per method with its standard errors, each point
    labelled with its dt; log axes and a dashed line at each (level, colour)."""
    for k, (label, points) in enumerate(rows.items()):
        ok = [p for p in points if measured(p, q)]
        if not ok:
            continue
        cost = np.array([p["cost"] for p in ok])
        err = np.array([max(abs(p[q]), 1e-5) for p in ok])
        se = np.array([p[q + "se"] for p in ok])
        ax.errorbar(cost, 100 * err, yerr=100 * se, marker=markers[k % len(markers)], label=label, capsize=2)
        for p, c, e in zip(ok, cost, err):
            ax.annotate("%g" % p["dt"], (c, 100 * e), fontsize=6, xytext=(3, 3), textcoords="offset points")
    ax.set_xscale("log")
    ax.set_yscale("log")
    for level, colour in levels:
        ax.axhline(100 * level, color=colour, lw=0.8, ls="--")


def draw_stability_map(ax, rows, q, levels):
    """Per method: the measured stable steps, where |error of q| passes each (level, colour), the blow-up."""
    for k, (label, points) in enumerate(rows.items()):
        stable_dt = [p["dt"] for p in points if not p["unstable"]]
        ax.plot(stable_dt, [k] * len(stable_dt), "|", color="grey", markersize=12)
        for level, colour in levels:
            c = crossing(points, q, level)
            if c and not c.startswith("<") and "-" not in c:  # interpolated, not a bound or a bracket
                ax.plot(float(c), k, "o", color=colour)
        u = first_unstable(points)
        if u is not None:
            ax.plot(u, k, "x", color="tab:red", markersize=10, mew=2)
    ax.set_yticks(range(len(rows)))
    ax.set_yticklabels(list(rows.keys()))
    ax.set_xlabel("dt")
