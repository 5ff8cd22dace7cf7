"""Reading what the tools write: time directories, profile tables, dictionaries (fit.dat, compare.dat,
case dictionaries; setting an entry with dpdDictionary), runSweep's tables, the logs, OpenFOAM fields."""
import glob
import math
import os
import re
import subprocess
import sys

import numpy as np


def _time_of(path):
    return float(os.path.basename(path.rstrip("/")))


def latest(pattern):
    """The path matching pattern (.../<time>/<file>) whose time directory is the latest."""
    paths = glob.glob(pattern)
    if not paths:
        sys.exit(f"plotResults: nothing matches {pattern}")
    return max(paths, key=lambda p: _time_of(os.path.dirname(p)))


def latest_dir(pattern):
    """The time directory matching pattern (.../<time>) that is the latest."""
    paths = glob.glob(pattern)
    if not paths:
        sys.exit(f"plotResults: nothing matches {pattern}")
    return max(paths, key=_time_of)


def latest_sampling(case, name):
    """The latest <case>/<time>/sampling/<name>.h5 (a binnedProfile's sampled blocks)."""
    pattern = os.path.join(case, "*", "sampling", name + ".h5")
    paths = glob.glob(pattern)
    if not paths:
        sys.exit(f"plotResults: nothing matches {pattern}")
    return max(paths, key=lambda p: _time_of(os.path.dirname(os.path.dirname(p))))


def numbered_cases(prefix, command, script="plotResults", placeholder="<n>"):
    """The case directories <prefix><number> as (number, path) sorted by number; exits naming `command` when none."""
    directories = [path for path in glob.glob(glob.escape(prefix) + "*") if os.path.isdir(path)]
    numbered = ((_number_after(prefix, path), path) for path in directories)
    cases = sorted(case for case in numbered if case[0] is not None)
    if not cases:
        sys.exit(f"{script}: no {prefix}{placeholder} (run {command})")
    return cases


def _number_after(prefix, path):
    """The number that follows prefix in path (None when the rest is not a number)."""
    try:
        return float(path[len(prefix):])
    except ValueError:
        return None


def latest_fit(case=".", tool="fitSlipLength"):
    """The latest fit.dat of a case's fitting tool (postProcessing/<tool>/<time>/fit.dat) as a dict."""
    return read_dict(latest(os.path.join(case, "postProcessing", tool, "*", "fit.dat")))


def latest_profile(case=".", name="channelProfile"):
    """The latest profileBins table <name>.dat of a case (postProcessing/profileBins/<time>/)."""
    return read_table(latest(os.path.join(case, "postProcessing", "profileBins", "*", name + ".dat")))


def project_path(*parts):
    """A path in the repository ($DPD_PROJECT_DIR, set by etc/bashrc)."""
    return os.path.join(os.environ["DPD_PROJECT_DIR"], *parts)


def read_table(path):
    """A whitespace table with a '# name name ...' header (profileBins): {name: column}."""
    with open(path) as f:
        header = f.readline().lstrip("#").split()
    data = np.loadtxt(path, comments="#", ndmin=2)
    return {name: data[:, k] for k, name in enumerate(header)}


def read_columns(path, names):
    """A headerless numeric table (chainBins.dat): {name: column} for the first len(names) columns."""
    data = np.loadtxt(path, comments="#", ndmin=2)
    return {name: data[:, k] for k, name in enumerate(names)}


def read_sections(directory, name):
    """The sections profileBins wrote for the function object `name` (<name>_x<x>.dat): [(x, table)]
    along x."""
    paths = glob.glob(os.path.join(directory, f"{name}_x*.dat"))
    positions = [float(re.search(r"_x(.*)\.dat$", p).group(1)) for p in paths]
    return sorted(((x, read_table(p)) for x, p in zip(positions, paths)), key=lambda item: item[0])


def dictionary_value(path, entry):
    """An entry of a case dictionary (controlDict, dpdProperties) as dpdDictionary prints it."""
    out = subprocess.run(["dpdDictionary", path, "-entry", entry, "-value"], check=True, capture_output=True, text=True)
    return out.stdout.strip().rstrip(";")


def dictionary_number(path, entry, default=None):
    """A number of a case dictionary (dpdDictionary's value), or default when the entry is missing."""
    try:
        return float(dictionary_value(path, entry))
    except subprocess.CalledProcessError:
        if default is None:
            raise
        return default


def dictionary_numbers(path, entries, **defaults):
    """Several numbers of a case dictionary: {name: dictionary_number(path, entry, its default)} for
    entries {name: entry}, the defaults given by name (kT=1.0)."""
    return {name: dictionary_number(path, entry, defaults.get(name)) for name, entry in entries.items()}


def function_start(case, function):
    """The startTime of the function object `function` in a case's system/controlDict, as a number."""
    return float(dictionary_value(os.path.join(case, "system/controlDict"), f"functions/{function}/startTime"))


def vector(text):
    """A dictionary's vector '(a b c)' as an array."""
    return np.array([float(v) for v in text.strip("()").split()])


def body_force(case="."):
    """The x component of the case's body force (constant/dpdProperties bodyForce/value)."""
    return float(vector(dictionary_value(os.path.join(case, "constant/dpdProperties"), "bodyForce/value"))[0])


def wall_planes(path="constant/dpdProperties"):
    """The lowest and highest z of the walls' `point (x y z)` entries of a dpdProperties file."""
    with open(path) as f:
        zs = sorted(float(p) for p in re.findall(r"point\s*\(\s*\S+\s+\S+\s+(\S+)\s*\)", f.read()))
    return zs[0], zs[-1]


def set_dictionary_value(path, entry, value):
    """Sets an entry of a case dictionary with dpdDictionary, the file kept first as <path>.orig (what the
    tutorials' Allclean puts back)."""
    if not os.path.exists(path + ".orig"):
        with open(path) as f, open(path + ".orig", "w") as orig:
            orig.write(f.read())
    subprocess.run(["dpdDictionary", path, "-entry", entry, "-set", value], check=True, capture_output=True, text=True)


def vector_text(values):
    """Numbers as a dictionary's list '(a b c)', each written with :g."""
    return "(" + " ".join(f"{v:g}" for v in values) + ")"


def case_line(name, path="system/makeFoamCaseDict"):
    """The start and end (vectors) of the line `name` of makeFoamCaseDict's lines; None without that line."""
    try:
        return tuple(vector(dictionary_value(path, f"lines/{name}/{k}")) for k in ("start", "end"))
    except subprocess.CalledProcessError:
        return None


def set_case_line(name, start, end, n_points, path="system/makeFoamCaseDict"):
    """Sets the line `name` of makeFoamCaseDict's lines (set_dictionary_value: the file kept as .orig)."""
    for key, value in (("start", vector_text(start)), ("end", vector_text(end)), ("nPoints", f"{n_points}")):
        set_dictionary_value(path, f"lines/{name}/{key}", value)


def read_dict(path):
    """The plain `key value;` and `key (a b ...);` entries of a dictionary the tools write (fit.dat,
    compare.dat): numbers as floats, lists as lists of floats, anything else as a string (a quoted one
    without its quotes)."""
    with open(path) as f:
        return parse_dict(f.read())


def parse_dict(text):
    """read_dict on the text of a dictionary (or of one sub-dictionary's body)."""
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)  # the banner (its words would take the first entry)
    text = re.sub(r"//[^\n]*", "", text)
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
            out[key] = value[1:-1] if len(value) > 1 and value[0] == value[-1] == '"' else value
    return out


def read_compare(path):
    """compareFVM's compare.dat: the top-level entries, and each line's sub-dictionary {name: entries}."""
    with open(path) as f:
        head, _, rest = f.read().partition("\nlines")
    return parse_dict(head), {name: parse_dict(body) for name, body in re.findall(r"(\w+)\s*\{([^{}]*)\}", rest)}


def latest_compare_lines(case="."):
    """A case's latest compareFVM output: compare.dat's path, its top-level entries and lines (read_compare),
    and the profiles.dat beside it; exits when it compares no line."""
    path = latest(os.path.normpath(os.path.join(case, "postProcessing", "compareFVM", "*", "compare.dat")))
    top, lines = read_compare(path)
    if not lines:
        sys.exit("plotResults: compare.dat has no line (system/makeFoamCaseDict: lines)")
    return path, top, lines, read_table(os.path.join(os.path.dirname(path), "profiles.dat"))


def latest_compare(case="."):
    """The top-level entries of a case's latest compareFVM compare.dat (read_compare)."""
    return read_compare(latest(os.path.join(case, "postProcessing", "compareFVM", "*", "compare.dat")))[0]


def read_sweep(path):
    """runSweep's table: {column: values}; numbers as arrays ("none", a quantity a run does not measure,
    as NaN), other columns (the run's name, a vector value written as (1,0,0)) as lists of words."""
    with open(path) as f:
        header = f.readline().lstrip("#").split()
        rows = [line.split() for line in f if line.strip()]
    out = {}
    for k, name in enumerate(header):
        words = [r[k] for r in rows]
        try:
            out[name] = np.array([np.nan if w == "none" else float(w) for w in words])
        except ValueError:
            out[name] = words
    return out


def sweep_vector(text):
    """A vector as runSweep's table writes it, '(a,b,c)', as an array."""
    return np.array([float(v) for v in text.strip("()").split(",")])


def header_means(path):
    """{name: (mean, error)} from the '# mean <name> <value> +- <error>' lines (chainStatistics)."""
    with open(path) as f:
        found = re.findall(r"# mean (\S+)\s+(\S+) \+- (\S+)", f.read())
    return {k: (float(m), float(e)) for k, m, e in found}


# ---- Logs ----------------------------------------------------------------------------------------------


def read_text(path):
    with open(path) as f:
        return f.read()


def log_values(text, pattern, kind=float, flags=0):
    """Every match of pattern's group in a log's text, as numbers."""
    return [kind(v) for v in re.findall(pattern, text, flags)]


def run_finished(text):
    """(steps, seconds, particle-steps per second) of the solver's 'Run finished' line; NaN without it."""
    m = re.search(r"Run finished: (\d+) steps in ([0-9.eE+-]+) s, ([0-9.eE+-]+) particle-steps/s", text)
    return (int(m.group(1)), float(m.group(2)), float(m.group(3))) if m else (float("nan"),) * 3


def finished_solver_log(path="log.dpdFoamLike", wall="geometry"):
    """A finished solver log: the report times and kT series (arrays; the times of the last len(kT)
    reports), the particles inside the walls at the end, those the wall `wall` found crossed, summed over
    the run, and run_finished; exits without a report or the run's end."""
    text = read_text(path)
    times, kts = log_values(text, r"^Time = ([-0-9.eE+]+)", flags=re.M), log_values(text, r"kT = ([-0-9.eE+]+)")
    inside = log_values(text, r"inside walls now (\d+)", int)
    crossed = log_values(text, rf"{wall} returned \d+ crossed (\d+);", int)
    if not kts or not inside or "Run finished" not in text:
        sys.exit(f"plotResults: {path} has no report or no end")
    return np.array(times[-len(kts):]), np.array(kts), inside[-1], sum(crossed), run_finished(text)


def built_particles(path="log.randomEquilWall"):
    """The fluid and frozen particles a builder made (its log's Fluid and Frozen particles lines); exits without them."""
    counts = [log_count(path, f"{what} particles") for what in ("Fluid", "Frozen")]
    if not all(isinstance(n, int) for n in counts):
        sys.exit(f"plotResults: {path} gives no particle counts")
    return counts


def log_count(path, label):
    """The number after 'label :' at the start of a line of a tool's log (NaN without it)."""
    m = re.search(rf"^{label}\s*:\s*(\d+)", read_text(path), re.M)
    return int(m.group(1)) if m else float("nan")


# ---- OpenFOAM ------------------------------------------------------------------------------------------


def wall_events(log, start):
    """The particles the walls turned round and those found behind a wall (dpdFoamLike's reports "walls
    since last report: ... returned N crossed M"), summed over the walls and over the reports after time
    `start`, and the time those reports cover (NaN when none)."""
    returned = crossed = 0
    first = last = None
    for t, walls in re.findall(r"^Time = (\S+).*?\n.*?\n\s+walls since last report:([^\n]*)", read_text(log), re.M):
        t = float(t)
        if last is not None and last >= start:
            returned += sum(int(n) for n in re.findall(r"returned (\d+)", walls))
            crossed += sum(int(n) for n in re.findall(r"crossed (\d+)", walls))
            first = last if first is None else first
        last = t
    return returned, crossed, (last - first) if first is not None else float("nan")


def frozen_wall_counts(log):
    """A wall builder's frozen particles from its log: (built, at the full depth). blockFrozenWall
    reports each wall's built particles and, where it built one cutoff only, the lattice's; randomEquilWall
    the frozen particles and those dropped beyond one cutoff."""
    text = read_text(log)
    walls = re.findall(r"^Wall \S+ : (\d+) frozen particles(?: \((\d+) in the lattice)?", text, re.M)
    if walls:
        return sum(int(n) for n, _ in walls), sum(int(m or n) for n, m in walls)
    built = log_count(log, "Frozen particles")
    return built, built + log_count(log, "Dropped")


def run_logged(case, command):
    """Runs a tool's command line with its output in case/log.<tool>; exits naming the log on failure."""
    with open(os.path.join(case, f"log.{os.path.basename(command[0])}"), "w") as log:
        if subprocess.run(command, stdout=log, stderr=subprocess.STDOUT).returncode != 0:
            sys.exit(f"{' '.join(command)} failed (see {log.name})")


def foam_last_residual(case, field):
    """The initial residual of the last solution of `field` (Ux, Uy, p, ...) in case/log.simpleFoam."""
    found = re.findall(rf"Solving for {field}, Initial residual = ([-+0-9.eE]+)", read_text(f"{case}/log.simpleFoam"))
    return float(found[-1]) if found else math.nan


def foam_latest_time(case):
    """The latest time directory (after 0) of an OpenFOAM case, as its name."""
    times = [d for d in os.listdir(case) if re.fullmatch(r"[0-9.eE+-]+", d) and float(d) > 0]
    return max(times, key=float)


def foam_vector_field(path):
    """internalField of an ascii volVectorField (nonuniform List<vector>) as an (n, 3) array."""
    body = read_text(path).split("internalField", 1)[1]
    n = int(re.search(r"List<vector>\s*(\d+)", body).group(1))
    start = body.index("(", body.index("List<vector>")) + 1
    numbers = re.findall(r"[-+0-9.eE]+", body[start:].replace("(", " ").replace(")", " "))
    return np.array(numbers[: 3 * n], dtype=float).reshape(n, 3)


def foam_latest_fields(case, *names):
    """The latest time (after 0) of an OpenFOAM case, as its name, and its ascii vector fields `names`
    there (foam_vector_field)."""
    t = foam_latest_time(case)
    return t, [foam_vector_field(os.path.join(case, t, name)) for name in names]


def write_whole(path, text):
    """text to path through path.tmp, replaced whole: a reader never sees half a file."""
    with open(path + ".tmp", "w") as f:
        f.write(text)
    os.replace(path + ".tmp", path)
