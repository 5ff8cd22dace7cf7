#!/bin/bash
# Polymer chains through the applications: insertChains puts chains into a built channel; the run
# with them is the same to the bit on 1 and 2 threads and when restarted from a written time; an
# overstretched bond stops the run cleanly (exit 2, the bond's particles and length named, the last
# good state kept); bad chain input gets the file and keyword.
#   $1: the directory of the executables, $2: the source directory
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap '[ -z "${KEEP:-}" ] && rm -rf "$work"' EXIT
. "$src/tests/shellTestFunctions" || exit 1

# A channel 30 x 3 x 24 between walls at z = +-11 (the published polymer channel is 3 thick), 10
# chains of 20 beads (200 of ~9000 particles: enough for the run to use two threads).
makeCase() {
    local c=$1
    writeChannel "$c" 11 "(-15 -1.5 -12)" "(15 1.5 12)" 3
    cat >> "$c/constant/dpdProperties" <<EOD
bonds { type FENE; H 6; rMax 3; }
EOD
    sed -i -e 's/^species .*/species { fluid { frozen no; } polymer { frozen no; } wall { frozen yes; } }/' \
        -e 's/^pairCoeffs .*/pairCoeffs { fluid-fluid { a 18.75; gamma 4.5; } polymer-polymer { a 18.75; gamma 4.5; } fluid-polymer { a 18.75; gamma 4.5; } fluid-wall { a 18.75; gamma 4.5; } polymer-wall { a 18.75; gamma 4.5; } }/' \
        "$c/constant/dpdProperties"
    cat > "$c/system/insertChainsDict" <<EOD
$header
chains 10; length 20; species polymer; replace fluid; clearance 0.5; seed 3;
EOD
    cat > "$c/system/controlDict" <<EOD
$header
endTime 10; deltaT 0.02; writeInterval 250; reportInterval 250;
functions { chains { type chainStatistics; flowAxis x; startTime 1; sampleInterval 10; samplesPerBlock 10; axis x; nBins 6; } }
EOD
    "$bin/blockFrozenWall" -case "$c" > "$c/log.blockFrozenWall" 2>&1 || fail "blockFrozenWall: $(tail -3 "$c/log.blockFrozenWall")"
    "$bin/insertChains" -case "$c" > "$c/log.insertChains" 2>&1 || fail "insertChains: $(tail -3 "$c/log.insertChains")"
}

run() { OMP_NUM_THREADS=$2 "$bin/dpdFoamLike" -case "$1" > "$1/log.dpdFoamLike.$3" 2>&1 || fail "run $1 ($3): $(tail -3 "$1/log.dpdFoamLike.$3")"; }

one=$work/one
makeCase "$one"
grep -q "Beads            : 200 " "$one/log.insertChains" || fail "insertChains did not make 200 beads: $(cat "$one/log.insertChains")"
for c in two restarted; do mkdir -p "$work/$c"; cp -r "$one/constant" "$one/system" "$one/0" "$work/$c/"; done
run "$one" 1 a
grep -q "Bonds          : 190 in 10 chains, FENE" "$one/log.dpdFoamLike.a" || fail "the log does not show the bonds"
run "$work/two" 2 a
grep -q "Threads        : 2" "$work/two/log.dpdFoamLike.a" || fail "the two-thread run did not use two threads"
cmp -s "$one/10/particles.h5" "$work/two/10/particles.h5" || fail "1 and 2 threads differ"
"$bin/dpdDictionary" "$work/restarted/system/controlDict" -entry endTime -set 5 > /dev/null
run "$work/restarted" 2 a
"$bin/dpdDictionary" "$work/restarted/system/controlDict" -entry endTime -set 10 > /dev/null
"$bin/dpdDictionary" "$work/restarted/system/controlDict" -entry startFrom -set latestTime > /dev/null
run "$work/restarted" 1 b
cmp -s "$one/10/particles.h5" "$work/restarted/10/particles.h5" || fail "the run restarted at 5 differs from the uninterrupted one"
cmp -s "$one/10/chains/chains.h5" "$work/restarted/10/chains/chains.h5" || fail "the restarted chain statistics differ"
for table in chainStatistics chainBins; do
    cmp -s "$one/postProcessing/chains/10/$table.dat" "$work/restarted/postProcessing/chains/10/$table.dat" || fail "the restarted $table.dat differs"
done
grep -q "^# mean Rg2 " "$one/postProcessing/chains/10/chainStatistics.dat" || fail "chainStatistics.dat has no mean of R_g^2"
/usr/bin/python3 - "$one/10/particles.h5" <<'PY' || fail "h5py cannot read the bonds"
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1])
pairs, chain = f["bonds/pairs"][:], f["particles/chain"][:]
assert pairs.shape == (190, 2) and (chain >= 0).sum() == 200 and chain.max() == 9
PY

# Overstretched: stiff short springs at a large time step.
stretched=$work/stretched
makeCase "$stretched"
sed -i 's/^bonds .*/bonds { type FENE; H 600; rMax 1; }/' "$stretched/constant/dpdProperties"
rm -rf "$stretched/0"
"$bin/blockFrozenWall" -case "$stretched" > /dev/null 2>&1
"$bin/insertChains" -case "$stretched" > /dev/null 2>&1 || fail "insertChains (stiff springs) failed"
"$bin/dpdDictionary" "$stretched/system/controlDict" -entry deltaT -set 0.05 > /dev/null
"$bin/dpdFoamLike" -case "$stretched" > "$stretched/log" 2>&1
status=$?
[ "$status" -eq 2 ] || fail "an overstretched bond should exit 2, not $status"
expectError "$status" "$stretched/log" "the bond between particles [0-9]* and [0-9]* (chain [0-9]*) is [0-9.]* long, not shorter than the spring's maximum 1" \
    "The last good state, time 0, is written"

# Bad input.
bad=$work/bad
makeCase "$bad"
"$bin/dpdDictionary" "$bad/system/insertChainsDict" -entry length -set 1 > /dev/null
"$bin/insertChains" -case "$bad" > "$bad/log" 2>&1
expectError $? "$bad/log" "insertChainsDict" "length" "at least 2"
"$bin/dpdDictionary" "$bad/system/insertChainsDict" -entry length -set 20 > /dev/null
"$bin/insertChains" -case "$bad" > "$bad/log" 2>&1
expectError $? "$bad/log" "already holds chains"
sed -i 's/^bonds .*/bonds { type FENE; H 6; rMax 3; bondedPairs { dpd some; } }/' "$bad/constant/dpdProperties"
"$bin/dpdFoamLike" -case "$bad" > "$bad/log" 2>&1
expectError $? "$bad/log" "dpdProperties" "dpd" "all, none or weighted"
sed -i '/^bonds /d' "$bad/constant/dpdProperties"
"$bin/dpdFoamLike" -case "$bad" > "$bad/log" 2>&1
expectError $? "$bad/log" "holds 190 bonds but constant/dpdProperties has no bonds block"

finishTests chainRun
