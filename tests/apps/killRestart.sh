#!/bin/bash
# Fault injection: a run with frequent writes and sampling is killed with SIGKILL at random moments
# and restarted (startFrom latestTime) until it finishes; then the soak mode (etc/soakRestart). After every kill each time directory must
# be whole and readable; at the end the particles, the sampling and profileBins' table must be the
# same, to the bit, as those of a run never interrupted.
#   $1: the directory of the executables, $2: the source directory
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap '[ -z "${KEEP:-}" ] && rm -rf "$work"' EXIT
. "$src/tests/shellTestFunctions" || exit 1
export OMP_NUM_THREADS=1
export DPD_BUILD_DIR="$(cd "$bin/.." && pwd)"  # etc/soakRestart runs the executables of this build

# A channel of ~3000 particles run for 2000 steps (a few seconds), writing every 20 steps and sampling
# every step.
makeCase() {
    local c=$1
    writeChannel "$c" 3.5 "(-4 -4 -4.5)" "(4 4 4.5)" 5
    cat > "$c/system/controlDict" <<EOD
$header
startFrom latestTime;
endTime 40;
deltaT 0.02;
writeInterval 20;
reportInterval 500;
functions { channel { type binnedProfile; axis z; nBins 14; min -3.5; max 3.5; startTime 2; samplesPerBlock 10; } }
EOD
    "$bin/blockFrozenWall" -case "$c" > "$c/log.blockFrozenWall" 2>&1 || fail "blockFrozenWall failed: $(cat "$c/log.blockFrozenWall")"
}

# Every time directory holds a readable snapshot (a zero-step run from it reads and checks it) and,
# once sampling has started (t >= 2), its sampling file.
checkWhole() {
    local c=$1 t name sampled=0
    for t in "$c"/[0-9]*; do
        name=$(basename "$t")
        [ "$name" = 0 ] && continue
        [ -f "$t/particles.h5" ] || { fail "time $name has no particles.h5"; continue; }
        if awk "BEGIN { exit !($name >= 2.2) }"; then
            [ -f "$t/sampling/channel.h5" ] || fail "time $name has no sampling/channel.h5"
            sampled=1
        fi
    done
    ls -a "$c" | grep -q '^\.writing-' && echo "    (an unfinished .writing- directory was left, as designed)"
    # A kill before the first sampled write leaves nothing for profileBins (it says so and fails, rightly).
    [ "$sampled" = 1 ] || return 0
    "$bin/profileBins" -case "$c" > "$c/log.profileBins.check" 2>&1 || fail "profileBins cannot read the times: $(tail -3 "$c/log.profileBins.check")"
    rm -rf "$c/postProcessing"
}

countTimes() { ls -d "$1"/[0-9]* 2>/dev/null | wc -l; }

# Returns when the case holds $2 time directories or the run $3 has ended.
waitForTimes() {
    while kill -0 "$3" 2>/dev/null && [ "$(countTimes "$1")" -lt "$2" ]; do sleep 0.005; done
}

reference=$work/reference
makeCase "$reference"
start=$(date +%s.%N)
"$bin/dpdFoamLike" -case "$reference" > "$reference/log" 2>&1 || fail "the reference run failed: $(tail -3 "$reference/log")"
seconds=$(echo "$(date +%s.%N) - $start" | bc)
echo "uninterrupted run: $seconds s"

c=$work/killed
makeCase "$c"
RANDOM=12345
kills=0
finished=0
for attempt in $(seq 1 60); do
    before=$(countTimes "$c")
    "$bin/dpdFoamLike" -case "$c" > "$c/log.$attempt" 2>&1 &
    pid=$!
    # Killed after 5 to 30 more writes (of 100) and a moment of up to one write interval, so that
    # kills land both between and inside writes whatever the machine's speed.
    waitForTimes "$c" $((before + 5 + RANDOM % 26)) "$pid"
    sleep "$(echo "scale=3; $seconds / 100 * $RANDOM / 32767" | bc)"
    if kill -9 "$pid" 2>/dev/null; then
        wait "$pid" 2>/dev/null
        kills=$((kills + 1))
        checkWhole "$c"
    else
        wait "$pid" && { finished=1; break; }
        fail "attempt $attempt failed: $(tail -3 "$c/log.$attempt")"
        break
    fi
done
[ "$finished" = 1 ] || fail "the run did not finish in $attempt attempts"
echo "killed $kills times, finished on attempt $attempt"
[ "$kills" -ge 3 ] || fail "only $kills kills: the test did not interrupt the run"
checkWhole "$c"

# The final state and sampling, and the table profileBins makes of them, identical to the bit.
cmp -s "$reference/40/particles.h5" "$c/40/particles.h5" || fail "the final particles differ from the uninterrupted run"
cmp -s "$reference/40/sampling/channel.h5" "$c/40/sampling/channel.h5" || fail "the final sampling differs"
for k in "$reference" "$c"; do "$bin/profileBins" -case "$k" -latestTime > "$k/log.profileBins" 2>&1; done
cmp -s "$reference/postProcessing/profileBins/40/channel.dat" "$c/postProcessing/profileBins/40/channel.dat" ||
    fail "profileBins' table differs"

# The soak mode (etc/soakRestart): restarted from any of its written times, the same case ends the same.
rm -rf "$reference"/[1-9]* "$reference/postProcessing"
"$src/etc/soakRestart" -n 5 "$reference" > "$work/log.soak" 2>&1 || fail "soakRestart: $(cat "$work/log.soak")"
cat "$work/log.soak"
grep -q "every restart (5) identical" "$work/log.soak" || fail "soakRestart did not restart five times"

finishTests killRestart
