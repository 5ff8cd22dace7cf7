#!/bin/bash
# The heat of a flowing fluid apart from the motion neighbours share (etc/python/dpdfoam/pair_temperature.py), on
# synthetic snapshots whose answer is known: particles at random positions (density 4, periodic box
# 20 x 10 x 10) with velocities drawn at kT 1.3 about a mean shear u_x = 0.5 z, frozen particles at rest
# beside them (to be left out).
#   - Velocities independent between particles: single = pair = kT, shared = 0.
#   - Plus a mode shared by neighbours, u_x += A sin(k x) (A 0.6, k = 2 pi / 20): single and shared
#     rise by A^2 / 6 (less the part neighbours do not share, A^2 k^2 <dx^2> / 12 with <dx^2> = 1/5
#     over pairs closer than r_c), pair by that part only.
#   - In 2-D (y inactive, two velocity components): pair = single = kT.
# Each value's standard error over independent snapshots within its budget, then the value within a
# fixed bound of four budgets of its expectation.
#   $1: the directory of the executables, $2: the source directory
set -u
src=$2
. "$src/tests/shellTestFunctions" || exit 1
python=/usr/bin/python3
# Required dependencies: a missing one fails the test (no skip).
requirePython "$python" numpy h5py scipy || finishTests pairTemperature
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

out=$(PYTHONPATH="$src/etc/python" WORK="$work" "$python" - 2>&1 <<'EOF'
import os
import h5py
import numpy as np
from dpdfoam.pair_temperature import pair_temperature

KT, SHEAR, A, SNAPSHOTS = 1.3, 0.5, 0.6, 8
lo, hi = np.array([-10.0, -5.0, -5.0]), np.array([10.0, 5.0, 5.0])
k = 2 * np.pi / (hi[0] - lo[0])
rng = np.random.default_rng(7)

def write_case(name, mode, dimension):
    for s in range(SNAPSHOTS):
        n, frozen = 8000, 500
        x = lo + (hi - lo) * rng.random((n + frozen, 3))
        v = rng.normal(0.0, np.sqrt(KT), (n + frozen, 3))
        v[:, 0] += SHEAR * x[:, 2] + mode * np.sin(k * (x[:, 0] - lo[0]))
        if dimension == 2:
            x[:, 1] = 0.0
            v[:, 1] = 0.0
        species = np.zeros(n + frozen, np.int32)
        species[n:] = 1
        v[n:] = 0.0
        d = os.path.join(os.environ["WORK"], name, f"{s + 1}")
        os.makedirs(d)
        with h5py.File(os.path.join(d, "particles.h5"), "w") as f:
            f.attrs["boxLo"], f.attrs["boxHi"], f.attrs["dimension"] = lo, hi, dimension
            f.attrs["speciesNames"] = np.array(["fluid", "wall"], dtype=h5py.string_dtype())
            f.attrs["speciesFrozen"] = np.array([0, 1])
            f["particles/position"], f["particles/velocity"], f["particles/species"] = x, v, species
    rows = pair_temperature(os.path.join(os.environ["WORK"], name), 0, SNAPSHOTS, 2, (lo[2], hi[2]), (lo[2], hi[2]), 20)
    return rows[:, 1:].mean(axis=0), rows[:, 1:].std(axis=0, ddof=1) / np.sqrt(len(rows))

# Standard-error budgets over the 8 snapshots (measured 0.002-0.008 for the temperatures, 0.0005-0.0015
# for the shared part), then a fixed bound of four budgets: 0.04 keeps pair apart from single in the
# mode case (A^2 / 6 = 0.06 between them), 0.008 the shared part from zero.
BUDGET = {"single": 0.01, "pair": 0.01, "shared": 0.002}

def report(label, got, expected):
    (mean, error) = got
    for name, m, e, x in zip(("single", "pair", "shared"), mean, error, expected):
        ok = e < BUDGET[name] and abs(m - x) < 4 * BUDGET[name]  # NaN fails both
        print(f"{label} {name} {m:.5f} +- {e:.5f} expected {x:.5f} {'ok' if ok else 'off'}")

report("independent", write_case("independent", 0.0, 3), (KT, KT, 0.0))
unshared = A * A * k * k / 5 / 12
report("mode", write_case("mode", A, 3), (KT + A * A / 6, KT + unshared, A * A / 6 - unshared))
report("twoD", write_case("twoD", 0.0, 2), (KT, KT, 0.0))
EOF
)
echo "$out"
[ "$(echo "$out" | grep -c ' ok$')" -eq 9 ] || fail "every value's error within its budget and the value within four budgets of its expectation"
finishTests pairTemperature
