#!/bin/bash
# Domain decomposition (docs/parallel.md): the same case run by dpdFoamLike on one process and under
# `mpirun -np N` for N = 1, 2, 3, 4, each with 1 and 2 threads, must write snapshots identical to the
# bit (every dataset of particles.h5). Scenes: a channel between frozen lattice walls (bounce-back)
# with a binned profile and its stress sampled every step; the same with velocity Verlet; tunable-slip
# walls (forces with random numbers, specular); a Couette channel whose frozen walls move along x
# (frozen particles cross the slabs' faces) with bounce-forward (crossings completed at the end of the
# step, after the particle may have changed rank); a random wall from an image mask (geometry wall,
# bounce layer); polymer chains (three ghost planes, bond vectors travelling with their beads, chain
# statistics, the springs' stress); uneven slabs from system/decomposeParDict; a run written on 3
# ranks and continued on 2.
# Particles cross the slabs' faces thousands of times in each run (the flow is along x), so a rank
# that put a particle in another order than one process would, or lost a force contribution, changes
# the trajectories within a few hundred steps. The profile's counts must agree exactly, its sums to
# rounding. Bad decompositions are refused with the file and keyword named.
#   $1: the directory of the executables, $2: the source directory
set -u
bin=$(cd "$1" && pwd)
src=$(cd "$2" && pwd)
work=$(mktemp -d)
trap '[ -z "${KEEP:-}" ] && rm -rf "$work"' EXIT
. "$src/tests/shellTestFunctions" || exit 1
py=/usr/bin/python3
# mpirun as root needs saying so; --oversubscribe: more ranks than this machine's cores.
mpirun=(mpirun --oversubscribe)
[ "$(id -u)" -eq 0 ] && mpirun+=(--allow-run-as-root)
export OMPI_MCA_rmaps_base_oversubscribe=1
# Shared-memory messages copied through the shared segment, not read across processes (containers
# often forbid the cross-process read, which OpenMPI would otherwise try for large messages).
export OMPI_MCA_btl_vader_single_copy_mechanism=none

command -v mpirun > /dev/null || { echo "mpirun not found (Debian package openmpi-bin)"; exit 1; }

# Two HDF5 files' datasets compared: `exact` every dataset equal to the bit (snapshots); `sums`
# integers equal, floating-point values within 1e-12 of their size (a profile's sums, which the
# ranks add in another order than one process).
compareFiles() {
    "$py" - "$@" <<'EOD'
import sys, h5py, numpy as np
mode, first, second = sys.argv[1:4]
def load(f):
    out = {}
    with h5py.File(f, "r") as h:
        h.visititems(lambda name, obj: out.__setitem__(name, np.asarray(obj[()])) if isinstance(obj, h5py.Dataset) else None)
    return out
a, b = load(first), load(second)
ok = a.keys() == b.keys()
if not ok: print("datasets differ:", sorted(set(a) ^ set(b)))
for k in a.keys() & b.keys():
    x, y = a[k], b[k]
    if x.shape != y.shape: ok = False; print(k, "shape", x.shape, y.shape); continue
    if mode == "sums" and x.dtype.kind == "f" and x.size:
        gap = float(np.max(np.abs(x - y)))
        if gap > 1e-12 * max(1.0, float(np.max(np.abs(x)))): ok = False; print(k, "differs by", gap)
    elif x.tobytes() != y.tobytes(): ok = False; print(k, "differs")
sys.exit(0 if ok else 1)
EOD
}
sameSnapshot() { compareFiles exact "$1" "$2"; }
sameSampling() { compareFiles sums "$1" "$2"; }

# Runs case $1 on $2 ranks (0: no mpirun) with $3 threads; the log in $1/log. These scenes hold a few
# thousand particles, fewer than the thread budget gives a second thread (core/ThreadBudget.hpp):
# DPD_PARTICLES_PER_THREAD=1 makes every rank use the threads asked for, and the log must say so (on two
# ranks or more "on every rank": the line gathers every rank's count).
# Passive waiting: more threads than cores, whose spinning would starve the others.
run() {
    local c=$1 ranks=$2 threads=$3 status expected
    export DPD_PARTICLES_PER_THREAD=1 OMP_WAIT_POLICY=passive
    if [ "$ranks" = 0 ]; then
        OMP_NUM_THREADS=$threads "$bin/dpdFoamLike" -case "$c" > "$c/log" 2>&1
    else
        OMP_NUM_THREADS=$threads "${mpirun[@]}" -np "$ranks" "$bin/dpdFoamLike" -case "$c" > "$c/log" 2>&1
    fi
    status=$?
    expected="^Threads *: $threads of $threads\$"
    [ "$ranks" -le 1 ] || expected="^Threads *: $threads of $threads on every rank\$"
    [ $status -ne 0 ] || grep -q "$expected" "$c/log" ||
        { fail "$c ran on $(sed -n 's/^Threads *: //p' "$c/log" | head -n 1), not $threads threads on each rank"; return 1; }
    return $status
}

controlDict() {  # $1 case, $2 endTime, $3 extra entries
    cat > "$1/system/controlDict" <<EOD
$header
startFrom latestTime;
endTime $2;
deltaT 0.02;
writeInterval 200;
reportInterval 200;
$3
EOD
}

# The reference on one process, then every rank and thread count against it; $4 a binned profile to
# compare (sums), $5 a file of the time directory to compare to the bit.
compareRuns() {
    local name=$1 base=$2 endTime=$3 sampling=${4:-} exact=${5:-}
    local ref=$work/$name.ref
    cp -r "$base" "$ref"
    run "$ref" 0 1 || { fail "$name: the run on one process failed: $(tail -3 "$ref/log")"; return; }
    local ranks threads c
    for ranks in 1 2 3 4; do
        for threads in 1 2; do
            c=$work/$name.$ranks.$threads
            cp -r "$base" "$c"
            run "$c" "$ranks" "$threads" || { fail "$name on $ranks ranks, $threads threads: $(tail -5 "$c/log")"; continue; }
            sameSnapshot "$ref/$endTime/particles.h5" "$c/$endTime/particles.h5" ||
                fail "$name: $ranks ranks x $threads threads differ from one process at time $endTime"
            if [ -n "$sampling" ]; then
                sameSampling "$ref/$endTime/sampling/$sampling.h5" "$c/$endTime/sampling/$sampling.h5" ||
                    fail "$name: the sampling on $ranks ranks x $threads threads differs from one process"
            fi
            if [ -n "$exact" ]; then
                sameSnapshot "$ref/$endTime/$exact" "$c/$endTime/$exact" ||
                    fail "$name: $exact on $ranks ranks x $threads threads differs from one process"
            fi
            rm -rf "$c"
        done
    done
    echo "    $name: 1-4 ranks x 1-2 threads as one process"
}

# 1. A channel between frozen lattice walls, 12 planes of cells along x, body force along x, a binned
#    profile with the stress (each rank traverses its own planes' pairs) every step: 2594 particles,
#    500 steps.
ch=$work/channel
writeChannel "$ch" 3.5 "(-6 -3 -4.5)" "(6 3 4.5)" 5
channelFunctions="functions { channel { type binnedProfile; axis z; nBins 14; min -3.5; max 3.5; samplesPerBlock 50; stress yes; flowAxis x; } }"
controlDict "$ch" 10 "$channelFunctions"
"$bin/blockFrozenWall" -case "$ch" > "$ch/log.blockFrozenWall" 2>&1 || fail "blockFrozenWall: $(cat "$ch/log.blockFrozenWall")"
compareRuns channel "$ch" 10 channel
grep -q "^Ranks" "$work/channel.ref/log" && fail "the run on one process reports ranks"

# 2. Tunable-slip walls (friction and noise from the walls, specular reflection), no frozen particles.
ts=$work/tunable
cp -r "$ch" "$ts"
rm -rf "$ts"/0
"$py" - "$ts/constant/dpdProperties" <<'EOD'
import re, sys
f = sys.argv[1]
s = open(f).read()
s = s.replace("reflection bounceBack;", "reflection specular; tunableSlip { gammaL 1; zc 1; epsilon 1; sigma 0.5; }")
open(f, "w").write(s)
EOD
sed -i -e 's/^wall .*$//' "$ts/system/blockFrozenWallDict"
controlDict "$ts" 8 ""
"$bin/blockFrozenWall" -case "$ts" > "$ts/log.blockFrozenWall" 2>&1 || fail "blockFrozenWall (tunable slip): $(cat "$ts/log.blockFrozenWall")"
compareRuns tunableSlip "$ts" 8

# 3. Couette: the upper wall and its frozen particles move along x at 2, bounce-forward at both walls;
#    the stress profile (one process finds the pairs of the particles whose crossings were completed
#    after the sort where they are now, as the ranks' fresh cell lists do).
co=$work/couette
cp -r "$ch" "$co"
rm -rf "$co"/0
sed -i -e 's/upper { type plane; point (0 0 \([0-9.]*\)); normal (0 0 -1); reflection bounceBack; }/upper { type plane; point (0 0 \1); normal (0 0 -1); velocity (2 0 0); reflection bounceForward; }/' \
    -e 's/lower { type plane; point (0 0 -\([0-9.]*\)); normal (0 0 1); reflection bounceBack; }/lower { type plane; point (0 0 -\1); normal (0 0 1); reflection bounceForward; }/' \
    -e 's/value (0.05 0 0)/value (0 0 0)/' "$co/constant/dpdProperties"
grep -q "velocity (2 0 0); reflection bounceForward" "$co/constant/dpdProperties" || fail "the Couette case was not made"
controlDict "$co" 8 "$channelFunctions"
"$bin/blockFrozenWall" -case "$co" > "$co/log.blockFrozenWall" 2>&1 || fail "blockFrozenWall (Couette): $(cat "$co/log.blockFrozenWall")"
compareRuns couette "$co" 8 channel

# 3a. Velocity Verlet (DPD-VV): a second pair loop in the step, which reads the ghosts' forces.
vv=$work/dpdvv
cp -r "$ch" "$vv"
sed -i -e 's/type GrootWarren; lambda 0.65;/type DPDVV;/' "$vv/constant/dpdProperties"
grep -q "type DPDVV;" "$vv/constant/dpdProperties" || fail "the DPD-VV case was not made"
controlDict "$vv" 6 ""
compareRuns dpdvv "$vv" 6

# 3b. A wall of any shape: the random wall of the poiseuille tutorial's lattice-wall variant, from an
#     image mask (bounce layer on the geometry's surface, frozen particles from randomEquilWall, whose
#     equilibration also runs on 3 ranks), 10 planes, on 2 and 3 ranks.
geo=$work/geometry
mkdir -p "$geo"
cp -r "$src/tutorials/channel/poiseuille/latticeWall/system" "$src/tutorials/channel/poiseuille/latticeWall/randomWalls" \
      "$src/tutorials/channel/poiseuille/latticeWall/randomMask" "$geo/"
(
    cd "$geo" || exit 1
    set_() { "$bin/dpdDictionary" "$1" -entry "$2" -set "$3" > /dev/null || echo "FAIL: dpdDictionary $1 $2"; }
    set_ system/controlDict endTime 10
    set_ system/controlDict writeInterval 500
    set_ system/controlDict functions/channelProfile/min -5
    set_ system/controlDict functions/channelProfile/max 5
    set_ system/controlDict functions/channelProfile/startTime 2
    set_ randomWalls/dpdProperties bodyForce/value "(0.08 0 0)"
    set_ randomWalls/randomEquilWallDict box/min "(-5 -1.5 -7)"
    set_ randomWalls/randomEquilWallDict box/max "(5 1.5 7)"
    set_ randomWalls/randomEquilWallDict fluid/initialFlow/wallPositions "(-5 5)"
    set_ randomMask/constant/dpdProperties geometry/file '"constant/geometry/channelSmall.png"'
    cd randomMask && "$bin/randomEquilWall" > log.randomEquilWall 2>&1 || echo "FAIL: randomEquilWall: $(tail -3 log.randomEquilWall)"
) | grep FAIL && fail "the geometry case was not made"
# randomEquilWall's equilibration on 3 ranks writes the same 0/ as on one process.
cp -r "$geo/randomMask" "$geo/equil3"
rm -rf "$geo/equil3/0"
sed -i "s|#include \"../../|#include \"$geo/|" "$geo/equil3/system/controlDict" "$geo/equil3/system/randomEquilWallDict" \
    "$geo/equil3/constant/dpdProperties"
OMP_NUM_THREADS=1 "${mpirun[@]}" -np 3 "$bin/randomEquilWall" -case "$geo/equil3" > "$geo/equil3/log" 2>&1 ||
    fail "randomEquilWall on 3 ranks: $(tail -5 "$geo/equil3/log")"
grep -q "equilibrated for [1-9][0-9]* steps" "$geo/equil3/log" || fail "randomEquilWall did not equilibrate: $(cat "$geo/equil3/log")"
sameSnapshot "$geo/randomMask/0/particles.h5" "$geo/equil3/0/particles.h5" || fail "randomEquilWall on 3 ranks differs from one process"
for ranks in 0 2 3; do
    c=$geo/run$ranks
    mkdir -p "$c"
    cp -r "$geo/randomMask/0" "$geo/randomMask/constant" "$geo/randomMask/system" "$c/"
    sed -i "s|#include \"../../system/controlDict\"|#include \"$geo/system/controlDict\"|" "$c/system/controlDict"
    run "$c" "$ranks" 2 || fail "geometry wall on $ranks ranks: $(tail -5 "$c/log")"
done
grep -q "geometry: reflection bounceLayer" "$geo/run3/log" || fail "the geometry case has no geometry wall"
for ranks in 2 3; do
    sameSnapshot "$geo/run0/10/particles.h5" "$geo/run$ranks/10/particles.h5" || fail "geometry wall: $ranks ranks differ from one process"
    sameSampling "$geo/run0/10/sampling/channelProfile.h5" "$geo/run$ranks/10/sampling/channelProfile.h5" ||
        fail "geometry wall: the sampling on $ranks ranks differs"
done
echo "    geometry wall: 2 and 3 ranks x 2 threads as one process"

# 3c. Polymer chains: FENE springs with r_max 3, three times the cutoff, so three ghost planes a side;
#     10 chains of 20 beads in a channel 30 x 3 x 24 (30 planes), driven along x: beads and bonds
#     cross the slabs' faces and the periodic boundary. The springs are soft (H 0.5): bonds stretch
#     to ~2.8, so a rank needs all three ghost planes (with two a bond's other bead goes missing
#     within 150 steps), and bond vectors across the 3-thick y reach half its length, where a vector
#     followed from a stale one picks the wrong image (a bead's bond vectors must go with it when it
#     changes rank; without, the runs differ). Chain statistics every 10 steps (gathered on rank 0),
#     the stress with the springs' virial every 5.
#     Then bonded pairs feeling a weighted DPD force (the correction reads the ghosts' velocities),
#     DPD-VV (the ghosts' forces refreshed with their bond forces), a run written on 3 ranks and
#     continued on 2 (the snapshot's bond vectors), and uneven slabs.
pc=$work/chains
writeChannel "$pc" 11 "(-15 -1.5 -12)" "(15 1.5 12)" 3
echo "bonds { type FENE; H 0.5; rMax 3; }" >> "$pc/constant/dpdProperties"
sed -i -e 's/^species .*/species { fluid { frozen no; } polymer { frozen no; } wall { frozen yes; } }/' \
    -e 's/^pairCoeffs .*/pairCoeffs { fluid-fluid { a 18.75; gamma 4.5; } polymer-polymer { a 18.75; gamma 4.5; } fluid-polymer { a 18.75; gamma 4.5; } fluid-wall { a 18.75; gamma 4.5; } polymer-wall { a 18.75; gamma 4.5; } }/' \
    "$pc/constant/dpdProperties"
echo "$header chains 10; length 20; species polymer; replace fluid; clearance 0.5; seed 3;" > "$pc/system/insertChainsDict"
chainFunctions="functions { chains { type chainStatistics; flowAxis x; sampleInterval 10; samplesPerBlock 10; axis x; nBins 6; }
    chainStress { type binnedProfile; axis z; nBins 11; min -11; max 11; sampleInterval 5; samplesPerBlock 20; stress yes; flowAxis x; } }"
controlDict "$pc" 10 "$chainFunctions"
"$bin/blockFrozenWall" -case "$pc" > "$pc/log.blockFrozenWall" 2>&1 || fail "blockFrozenWall (chains): $(tail -3 "$pc/log.blockFrozenWall")"
"$bin/insertChains" -case "$pc" > "$pc/log.insertChains" 2>&1 || fail "insertChains: $(tail -3 "$pc/log.insertChains")"
compareRuns chains "$pc" 10 chainStress chains/chains.h5
grep -q "Bonds          : 190 in 10 chains" "$work/chains.ref/log" || fail "the chain case has no chains: $(grep Bonds "$work/chains.ref/log")"
# A variant of case $2 (sed expression $3 on its dpdProperties, which must then hold $4) named $1,
# run on one process and on $5 ranks x $6 threads: the same to the bit at time 10. $7: its functions,
# if not those of $2.
compareVariant() {
    local name=$1 base=$2 edit=$3 holds=$4 ranks=$5 threads=$6
    local c=$work/$name
    cp -r "$base" "$c"
    sed -i -e "$edit" "$c/constant/dpdProperties"
    [ -n "${7:-}" ] && controlDict "$c" 10 "$7"
    grep -q -- "$holds" "$c/constant/dpdProperties" || { fail "$name: the variant was not made"; return; }
    cp -r "$c" "$c.ref"
    run "$c.ref" 0 1 || fail "$name, one process: $(tail -3 "$c.ref/log")"
    run "$c" "$ranks" "$threads" || fail "$name on $ranks ranks: $(tail -5 "$c/log")"
    sameSnapshot "$c.ref/10/particles.h5" "$c/10/particles.h5" || fail "$name: $ranks ranks differ from one process"
}
compareVariant chainsWeighted "$pc" 's/^bonds .*/bonds { type FENE; H 0.5; rMax 3; bondedPairs { dpd weighted; weight 0.5; } }/' \
    "dpd weighted" 3 2 "functions { }"  # (no stress with the bonded pairs' terms left out)
compareVariant chainsVv "$pc" 's/type GrootWarren; lambda 0.65;/type DPDVV;/' "type DPDVV;" 2 2
pr=$work/chainsRestart
cp -r "$pc" "$pr"
controlDict "$pr" 4 "$chainFunctions"
run "$pr" 3 1 || fail "chains restart, first part: $(tail -5 "$pr/log")"
controlDict "$pr" 10 "$chainFunctions"
echo "$header numberOfSubdomains 2; method slabs; planes (6 24);" > "$pr/system/decomposeParDict"
run "$pr" 2 2 || fail "chains restart, second part: $(tail -5 "$pr/log")"
grep -q "slabs of cell planes along x 0-5 | 6-29 (of 30)" "$pr/log" || fail "chains: uneven slabs not as asked: $(grep Ranks "$pr/log")"
sameSnapshot "$work/chains.ref/10/particles.h5" "$pr/10/particles.h5" || fail "chains: 3 ranks then 2 (uneven) differ from one process"
sameSnapshot "$work/chains.ref/10/chains/chains.h5" "$pr/10/chains/chains.h5" || fail "chains: the restarted chain statistics differ"
echo "$header numberOfSubdomains 2; method slabs; planes (5 25);" > "$pr/system/decomposeParDict"
run "$pr" 2 1
expectError $? "$pr/log" "system/decomposeParDict" "planes" "each of 2 ranks needs at least 6 planes (the 3 ghost planes"
echo "    chains: weighted bonded pairs on 3 ranks, DPD-VV on 2, 3 ranks then 2 on uneven slabs as one process"

# 4. Uneven slabs from system/decomposeParDict: 2, 3 and 7 planes.
un=$work/uneven
cp -r "$ch" "$un.ref"
run "$un.ref" 0 2 || fail "uneven: reference: $(tail -3 "$un.ref/log")"
cp -r "$ch" "$un"
echo "$header numberOfSubdomains 3; method slabs; planes (2 3 7);" > "$un/system/decomposeParDict"
run "$un" 3 1 || fail "uneven slabs: $(tail -5 "$un/log")"
grep -q "slabs of cell planes along x 0-1 | 2-4 | 5-11 (of 12)" "$un/log" || fail "uneven slabs not as asked: $(grep Ranks "$un/log")"
sameSnapshot "$un.ref/10/particles.h5" "$un/10/particles.h5" || fail "uneven slabs differ from one process"

# 5. Written on 3 ranks at time 4, continued on 2 ranks to 10: as one process all the way.
rs=$work/restart
cp -r "$ch" "$rs"
controlDict "$rs" 4 "$channelFunctions"
run "$rs" 3 1 || fail "restart, first part: $(tail -5 "$rs/log")"
controlDict "$rs" 10 "$channelFunctions"
run "$rs" 2 2 || fail "restart, second part: $(tail -5 "$rs/log")"
sameSnapshot "$un.ref/10/particles.h5" "$rs/10/particles.h5" || fail "3 ranks then 2 differ from one process"
sameSampling "$un.ref/10/sampling/channel.h5" "$rs/10/sampling/channel.h5" || fail "the sampling carried across the restart differs"

# 6. Refusals: subdomains other than the ranks; planes that do not add up to the box's; too many
#    ranks for the planes (or a slab too thin); the stress with a bounce-forward wall facing x (its
#    completed crossings move particles along x after the sort); an integrator that cannot run
#    decomposed.
bad=$work/bad
cp -r "$ch" "$bad"
echo "$header numberOfSubdomains 4; method slabs;" > "$bad/system/decomposeParDict"
run "$bad" 2 1
expectError $? "$bad/log" "system/decomposeParDict" "numberOfSubdomains" "4 subdomains, but the run has 2 ranks"
echo "$header numberOfSubdomains 2; method slabs; planes (5 6);" > "$bad/system/decomposeParDict"
run "$bad" 2 1
expectError $? "$bad/log" "system/decomposeParDict" "planes" "add up to 11, but the box has 12 planes"
echo "$header numberOfSubdomains 2; method slabs; planes (1 11);" > "$bad/system/decomposeParDict"
run "$bad" 2 1
expectError $? "$bad/log" "system/decomposeParDict" "planes" "each of 2 ranks needs at least 2 planes"
rm "$bad/system/decomposeParDict"
run "$bad" 13 1
expectError $? "$bad/log" "12 planes of cells along x" "13 ranks need at least 13"
cp "$bad/constant/dpdProperties" "$bad/dpdProperties.kept"
sed -i -e 's/^\( *upper { type plane;.*\)$/\1\n    side { type plane; point (-4.5 0 0); normal (1 0 0); reflection bounceForward; }/' "$bad/constant/dpdProperties"
echo "stability { maxInsideWalls 1000000; }" >> "$bad/constant/dpdProperties"  # the fluid behind it
grep -q "side { type plane" "$bad/constant/dpdProperties" || fail "the x-facing wall was not added"
run "$bad" 2 1
expectError $? "$bad/log" "system/controlDict" "stress" "cannot sample the stress on several ranks" "wall 'side'"
mv "$bad/dpdProperties.kept" "$bad/constant/dpdProperties"
sed -i -e 's/type GrootWarren; lambda 0.65;/type Shardlow;/' "$bad/constant/dpdProperties"
run "$bad" 2 1
expectError $? "$bad/log" "constant/dpdProperties" "Shardlow cannot run on several ranks yet"

finishTests mpiDecomposition
