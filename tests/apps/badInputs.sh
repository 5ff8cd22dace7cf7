#!/bin/bash
# Bad input as a user meets it (docs/guide/errors.md, "Bad input and what it gets"): every case below must end with
# a non-zero exit status and a message naming the file (and keyword, dataset or row), or, for a
# keyword given twice, run with a warning as the log's first line. A runaway leaves no unhealthy
# time directory behind.
#   $1: the directory of the executables, $2: the source directory
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$src/tests/shellTestFunctions" || exit 1
python=/usr/bin/python3
# The snapshot edits and health checks need them: required dependencies, so missing fails (no skip).
requirePython "$python" h5py numpy || finishTests badInputs

# A small channel: walls at z = -3 and 3, fluid between, frozen lattice walls behind.
makeCase() {
    local c=$1
    writeChannel "$c" 3 "(-2 -2 -4)" "(2 2 4)" 3
    cat > "$c/system/controlDict" <<EOD
$header
endTime 0.2;
deltaT 0.02;
writeInterval 10;
EOD
    "$bin/blockFrozenWall" -case "$c" > "$c/log.blockFrozenWall" 2>&1 || fail "blockFrozenWall failed: $(cat "$c/log.blockFrozenWall")"
}

# run NAME EDIT PATTERN...: a fresh case, EDIT (a shell command run in it), then dpdFoamLike must fail
# with a message matching every pattern.
run() {
    local name=$1 edit=$2
    shift 2
    local c=$work/$name
    makeCase "$c"
    (cd "$c" && eval "$edit") || fail "$name: the edit failed"
    "$bin/dpdFoamLike" -case "$c" > "$c/log" 2>&1
    local status=$?
    echo "$name: exit $status: $(grep -m1 -i 'error\|warning' "$c/log")"
    expectError $status "$c/log" "$@"
}

# Dictionaries.
run garbageDict 'head -c 3000 /dev/urandom > constant/dpdProperties' "constant/dpdProperties"
run deepNesting 'for k in $(seq 200); do printf "d {\n"; done >> constant/dpdProperties' \
    "constant/dpdProperties" "nested more than 64"
run unknownKeyword 'echo "gama 4.5;" >> constant/dpdProperties' "constant/dpdProperties:" "gama"
run badNumber 'sed -i "s/^kT 1;/kT 1e999;/" constant/dpdProperties' "constant/dpdProperties:" "kT" "out of range"
run unknownWallType 'sed -i "s/type plane; point (0 0 3)/type sphere; point (0 0 3)/" constant/dpdProperties' \
    "constant/dpdProperties:" "type" "expected plane"
run unknownBodyForce 'sed -i "s/type uniform;/type gravity;/" constant/dpdProperties' \
    "constant/dpdProperties:" "bodyForce" "expected none, uniform or reversePoiseuille"
run reverseFrameWithoutBounceForward 'sed -i "s/reflection bounceBack; }/reflection bounceBack; reverseFrame lab; }/" constant/dpdProperties' \
    "constant/dpdProperties:" "reverseFrame" "only a wall with reflection bounceForward reverses in the lab frame"
# A wall that asks for a slip length its fluid has no calibration for (an empty cache: the user's own
# calibrations cannot answer), or a negative one.
export DPD_SLIP_CALIBRATIONS=$work/emptyCache
mkdir -p "$DPD_SLIP_CALIBRATIONS"
askSlip() { echo "sed -i '0,/reflection bounceBack; }/s//reflection bounceBack; slipLength $1; tunableSlip { zc 1; epsilon 1; sigma 0.5; } }/' constant/dpdProperties"; }
run slipLengthWithoutCalibration "$(askSlip 1)" "constant/dpdProperties:" "slipLength" "no slip calibration" "etc/calibrateWall"
run negativeSlipLength "$(askSlip -1)" "constant/dpdProperties:" "slipLength" "negative"
run hugeEndTime 'sed -i "s/^endTime 0.2;/endTime 1e30;/" system/controlDict' "system/controlDict:" "endTime" "2^53"

# Snapshots.
run truncatedSnapshot 'head -c 3000 0/particles.h5 > x && mv x 0/particles.h5' "0/particles.h5"
run garbageSnapshot 'head -c 30000 /dev/urandom > 0/particles.h5' "0/particles.h5" "HDF5"
edit() { echo "$python -c \"import h5py; f = h5py.File('0/particles.h5', 'r+'); $1\""; }
run farParticle "$(edit "f['particles/position'][5, 2] = 1e6")" "0/particles.h5" "'particles/position' row 5" \
    "more than one box length outside"
run nanVelocity "$(edit "f['particles/velocity'][7, 0] = float('nan')")" "'particles/velocity' row 7" "not a finite"
run particleInWall "$(edit "import numpy as np; s = f['particles/species'][()]; i = int(np.flatnonzero(s == 0)[0]); f['particles/position'][i, 2] = -3.5")" \
    "0/particles.h5" "inside the solid of wall 'lower'"
run repeatedId "$(edit "f['particles/id'][9] = f['particles/id'][2]")" "'particles/id'" "rows 2 and 9"

# A keyword given twice runs, with a warning naming both lines as the log's first line.
c=$work/repeated
makeCase "$c"
echo "seed 4;" >> "$c/constant/dpdProperties"
"$bin/dpdFoamLike" -case "$c" > "$c/log" 2>&1 || fail "repeated keyword: the run failed: $(tail -5 "$c/log")"
first=$(head -n 1 "$c/log")
echo "repeated: $first"
case "$first" in
    "Warning: "*"constant/dpdProperties:"*"keyword 'seed' given twice (lines 3 and "*"): the last one is used") ;;
    *) fail "the log's first line is not the warning: $first" ;;
esac

# A runaway (deltaT 0.5, writing every 2 steps, reporting every 5000): it stops, says so, and every
# time directory it leaves holds a healthy state (read back: finite, inside the box).
c=$work/runaway
makeCase "$c"
sed -i 's/^deltaT 0.02;/deltaT 0.5;/; s/^writeInterval 10;/writeInterval 2;\nreportInterval 5000;/; s/^endTime 0.2;/endTime 100;/' \
    "$c/system/controlDict"
"$bin/dpdFoamLike" -case "$c" > "$c/log" 2>&1
expectError $? "$c/log" "went unstable" "(step " "last good state"
echo "runaway: $(grep -m1 'went unstable' "$c/log" | cut -c1-200)"
for t in "$c"/[0-9]*; do
    name=$(basename "$t")
    sed -i "s/^startTime .*//; s/^endTime .*/endTime $name;\nstartTime $name;/" "$c/system/controlDict"
    "$bin/dpdFoamLike" -case "$c" > "$c/log.read" 2>&1 || fail "time $name left behind cannot be read: $(tail -3 "$c/log.read")"
    "$python" -c "
import h5py, sys
v = h5py.File('$t/particles.h5', 'r')['particles/velocity'][()]
kT = ((v - v.mean(axis=0))**2).sum() / (3 * (len(v) - 1))
sys.exit(0 if kT < 2 else 'kT %g' % kT)" || fail "time $name left behind is not healthy"
done

finishTests badInputs
