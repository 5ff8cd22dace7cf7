"""A tutorial's published.dat (the paper's set-up, tables, fits and particle counts) and the point by
point comparison of a measured slip length with a published table (issue 25's bound)."""
import sys

import numpy as np


def read_published(path):
    """A tutorial's published.dat: {"source", "scene", "parameters": [(file, entry, value)],
    "tables": {name: {column: array}}, "fits": {quantity: (variable, function of a)},
    "counts": {(case, what): value}} (a count line: case, builder, fluid or wall, particles)."""
    out = {"source": "", "scene": "", "parameters": [], "tables": {}, "fits": {}, "counts": {}}
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
                # a builder's particle count (etc/checkPublishedCounts checks the build against it)
                case, _, what, value = rest.split()
                out["counts"][(case, what)] = int(value)
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


def table_value(table, key, x, column):
    """The value of `column` in the row of a published table whose `key` is x."""
    return float(table[column][np.flatnonzero(np.isclose(table[key], x))[0]])


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
