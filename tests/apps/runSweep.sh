#!/bin/bash
# runSweep (etc/RunFunctions): a sweep over two values of one entry, and of two entries together,
# with a fake case whose "run" writes a fit.dat computed from the values set, so the table's every
# number is known; and the bad inputs a user makes (misspelt entry, missing case, a run that fails,
# a keyword fit.dat lacks), each failing with a message that names it and no table written.
#   $1: the directory of the executables, $2: the source directory
set -u
bin=$1
src=$2
export PATH="$bin:$PATH"
DPD_PROJECT_DIR="$src"
. "$src/etc/RunFunctions" || exit 1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
. "$src/tests/shellTestFunctions" || exit 1

header='FoamFile { version 2.0; format ascii; class dictionary; }'
mkdir -p base/system base/constant base/0 base/250 base/postProcessing/fitSlipLength/250
echo "$header application dpdFoamLike; endTime 100;" > base/system/controlDict
echo "$header pairCoeffs { wall-wall { a 5; gamma 4.5; } } walls { upper { velocity (3 0 0); } }" \
    > base/constant/dpdProperties
echo "an initial state" > base/0/particles.h5
echo "an old result" > base/250/stale
echo "$header slipLength (9 9);" > base/postProcessing/fitSlipLength/250/fit.dat
touch base/log.dpdFoamLike base/old.png

# The fake run: fit.dat at two times (the later one is collected), values from the entries set:
# slipLength (a/10 -a/10), nu = endTime/1000, mode a word; the earlier time holds nonsense.
fakeRun() {
    local a endTime
    a=$(dpdDictionary constant/dpdProperties -entry pairCoeffs/wall-wall/a -value) || return 1
    endTime=$(dpdDictionary system/controlDict -entry endTime -value) || return 1
    [ -f 0/particles.h5 ] || { echo "0/ was not copied"; return 1; }
    for stale in 250 postProcessing/fitSlipLength/250 log.dpdFoamLike old.png; do
        [ -e "$stale" ] && { echo "$stale was copied"; return 1; }
    done
    mkdir -p postProcessing/fitSlipLength/50 postProcessing/fitSlipLength/100
    echo "$header slipLength (7 7); nu 7;" > postProcessing/fitSlipLength/50/fit.dat
    local s nu
    s=$(awk -v a="$a" 'BEGIN { print a / 10 }')
    nu=$(awk -v t="$endTime" 'BEGIN { print t / 1000 }')
    echo "$header mode couette; slipLength ($s -$s); nu $nu;" > postProcessing/fitSlipLength/100/fit.dat
    echo run >> runs
}

# 1. One entry, two values.
runSweep -case base -entry constant/dpdProperties pairCoeffs/wall-wall/a -values 5 15 \
         -collect slipLength nu mode -table one.dat -- fakeRun > log.one 2>&1 || fail "sweep 1 failed: $(cat log.one)"
expected="# case pairCoeffs/wall-wall/a slipLength_0 slipLength_1 nu mode
base_a5 5 0.5 -0.5 0.1 couette
base_a15 15 1.5 -1.5 0.1 couette"
[ "$(cat one.dat 2>/dev/null)" = "$expected" ] || fail "sweep 1 table:
$(cat one.dat 2>/dev/null)
expected
$expected"
[ "$(dpdDictionary sweep/base_a15/constant/dpdProperties -entry pairCoeffs/wall-wall/gamma -value)" = 4.5 ] ||
    fail "the rest of the dictionary was not kept"

# 2. Again: the copies exist, so nothing runs again, and the table is the same.
runSweep -case base -entry constant/dpdProperties pairCoeffs/wall-wall/a -values 5 15 \
         -collect slipLength nu mode -table again.dat -- fakeRun > log.again 2>&1 || fail "sweep 2 failed: $(cat log.again)"
cmp -s one.dat again.dat || fail "the re-collected table differs"
[ "$(cat sweep/base_a5/runs)" = run ] || fail "an existing copy was run again"
grep -q "already run" log.again || fail "no 'already run' message"

# 3. Two entries together (the i-th value of each), a vector value, negative numbers as values.
runSweep -case base -dir pairs -entry constant/dpdProperties pairCoeffs/wall-wall/a -values -2 10 \
         -entry system/controlDict endTime -values 200 300 \
         -entry constant/dpdProperties walls/upper/velocity -values "(1 0 0)" "(-2 0 0)" \
         -collect nu -- fakeRun > log.two 2>&1 || fail "sweep 3 failed: $(cat log.two)"
expected="# case pairCoeffs/wall-wall/a endTime walls/upper/velocity nu
base_a-2_endTime200_velocity1_0_0 -2 200 (1,0,0) 0.2
base_a10_endTime300_velocity-2_0_0 10 300 (-2,0,0) 0.3"
[ "$(cat pairs/sweep.dat 2>/dev/null)" = "$expected" ] || fail "sweep 3 table:
$(cat pairs/sweep.dat 2>/dev/null)
expected
$expected"

# 4. Bad input: each fails, names the problem, and runs nothing.
runSweep -case base -dir bad -entry constant/dpdProperties pairCoeffs/wal-wall/a -values 5 \
         -collect nu -- fakeRun > log.bad1 2>&1
expectError $? log.bad1 "no entry 'pairCoeffs/wal-wall/a'" "base/constant/dpdProperties"
runSweep -case nocase -dir bad -entry constant/dpdProperties pairCoeffs/wall-wall/a -values 5 \
         -collect nu -- fakeRun > log.bad2 2>&1
expectError $? log.bad2 "case 'nocase' not found"
runSweep -case base -dir bad -entry constant/dpdProperties pairCoeffs/wall-wall/a -values 5 10 \
         -entry system/controlDict endTime -values 100 -collect nu -- fakeRun > log.bad3 2>&1
expectError $? log.bad3 "endTime has 1 values"
runSweep -case base -dir bad -entry system/noSuchDict endTime -values 5 -collect nu -- fakeRun > log.bad4 2>&1
expectError $? log.bad4 "no file system/noSuchDict"
runSweep -case base -dir bad -entry system/controlDict endTime -values 5 -collect nu > log.bad5 2>&1
expectError $? log.bad5 "no command given"
[ -d bad ] && [ -n "$(ls bad)" ] && fail "a bad sweep made copies: $(ls bad)"

# 5. A keyword fit.dat lacks, and a run that fails: non-zero, named, no table.
runSweep -case base -dir bad -entry system/controlDict endTime -values 5 -collect nu shearRate \
         -- fakeRun > log.bad6 2>&1
expectError $? log.bad6 "no keyword 'shearRate'" "fit.dat"
[ -f bad/sweep.dat ] && fail "a table was written by a failed sweep"
runSweep -case base -dir bad -entry system/controlDict endTime -values 6 -collect nu -- false > log.bad7 2>&1
expectError $? log.bad7 "the command failed in bad/base_endTime6"

# 6. The case itself as the base (-case .), the copies inside it: named after the case's directory,
# and the copies' directory not copied into them.
( cd base && runSweep -case . -dir copies/nested -entry system/controlDict endTime -values 400 500 -collect nu \
      -- fakeRun ) > log.inside 2>&1 || fail "sweep 6 failed: $(cat log.inside)"
[ "$(tail -n 1 base/copies/nested/sweep.dat 2>/dev/null)" = "base_endTime500 500 0.5" ] ||
    fail "sweep 6 table: $(cat base/copies/nested/sweep.dat 2>/dev/null)"
[ -e base/copies/nested/base_endTime500/copies ] && fail "the copies' directory was copied into a copy"

# 7. A second sweep of the same case: the first sweep's copies (a directory of cases) stay out of it.
( cd base && runSweep -case . -dir second -entry system/controlDict endTime -values 600 -collect nu \
      -- fakeRun ) > log.second 2>&1 || fail "sweep 7 failed: $(cat log.second)"
[ -d base/second/base_endTime600 ] || fail "sweep 7 made no copy: $(cat log.second)"
[ -e base/second/base_endTime600/copies ] && fail "the first sweep's copies were copied into the second's"

# 8. -jobs 2: two runs at once (each waits until the other has started), each told half the cores
# unless OMP_NUM_THREADS is set, its output in its copy's log.runSweep; the table as one at a time.
togetherRun() {
    local mine=$(basename "$PWD")
    echo "$OMP_NUM_THREADS" > threads
    touch "$work/started.$mine"
    for _ in $(seq 100); do
        [ "$(ls "$work"/started.* | wc -l)" -ge 2 ] && break
        sleep 0.1
    done
    [ "$(ls "$work"/started.* | wc -l)" -ge 2 ] || { echo "$mine ran alone"; return 1; }
    echo "output of $mine"
    fakeRun
}
runSweep -case base -dir together -jobs 2 -entry constant/dpdProperties pairCoeffs/wall-wall/a -values 5 15 \
         -collect slipLength nu mode -- togetherRun > log.together 2>&1 || fail "sweep 8 failed: $(cat log.together)"
expected="$(cat one.dat)"
[ "$(cat together/sweep.dat 2>/dev/null)" = "$expected" ] || fail "sweep 8 table: $(cat together/sweep.dat 2>/dev/null)"
half=$(( $(nproc) / 2 > 0 ? $(nproc) / 2 : 1 ))
[ "$(cat together/base_a5/threads 2>/dev/null)" = "$half" ] || fail "a run of two at once got $(cat together/base_a5/threads) threads, not $half"
grep -q "output of base_a15" together/base_a15/log.runSweep 2>/dev/null || fail "no log.runSweep with the run's output"
rm -f "$work"/started.*
OMP_NUM_THREADS=3 runSweep -case base -dir togetherSet -jobs 2 -entry system/controlDict endTime -values 7 8 \
         -collect nu -- togetherRun > log.togetherSet 2>&1 || fail "sweep 8b failed: $(cat log.togetherSet)"
[ "$(cat togetherSet/base_endTime7/threads 2>/dev/null)" = 3 ] || fail "OMP_NUM_THREADS set by the user was not kept"

# 9. -jobs 2 with a run that fails: non-zero, the copy named and its output shown, no table, and no
# run started after it (the last value's copy is not made).
# (10 already run: collected while the others run.)
failSecond() { [ "$(basename "$PWD")" = base_endTime20 ] && { echo "broken on purpose"; return 3; }; sleep 1; fakeRun; }
runSweep -case base -dir badJobs -jobs 1 -entry system/controlDict endTime -values 10 -collect nu -- fakeRun > /dev/null 2>&1
rm -f badJobs/sweep.dat
runSweep -case base -dir badJobs -jobs 2 -entry system/controlDict endTime -values 20 10 30 40 -collect nu \
         -- failSecond > log.badJobs 2>&1
expectError $? log.badJobs "the command failed in badJobs/base_endTime20 (status 3)" "broken on purpose"
[ -f badJobs/sweep.dat ] && fail "a table was written by a failed sweep of -jobs 2"
[ -d badJobs/base_endTime40 ] && fail "a run was started after one failed"
for jobs in 0 two; do
    runSweep -case base -dir bad -jobs $jobs -entry system/controlDict endTime -values 5 -collect nu -- fakeRun > log.badJobs$jobs 2>&1
    expectError $? log.badJobs$jobs "-jobs needs a positive whole number, not '$jobs'"
done

finishTests runSweep
