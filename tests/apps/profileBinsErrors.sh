#!/bin/bash
# profileBins and fitSlipLength as a user runs them: clear messages and non-zero exit status for bad
# input, nothing written then; and a short real run through both tools.
#   $1: the directory of the executables, $2: the source directory
set -u
bin=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. "$src/tests/shellTestFunctions" || exit 1


# A small channel: walls at z = -3 and 3, fluid between, frozen lattice walls behind.
makeCase() {
    local c=$1
    writeChannel "$c" 3 "(-2 -2 -4)" "(2 2 4)" 3
    cat > "$c/system/controlDict" <<EOD
$header
application dpdFoamLike;
startFrom startTime; startTime 0; stopAt endTime; endTime 6; deltaT 0.02;
writeControl timeStep; writeInterval 300; reportInterval 100;
functions { channel { type binnedProfile; axis z; nBins 24; min -3; max 3; startTime 0; samplesPerBlock 20; } }
EOD
    "$bin/blockFrozenWall" -case "$c" > "$c/log.blockFrozenWall" 2>&1 || fail "blockFrozenWall failed: $(cat "$c/log.blockFrozenWall")"
}

# ---- a case whose only later time has particles but no sampling -------------------------------------
c=$work/noSampling
makeCase "$c"
cp -r "$c/0" "$c/10"

"$bin/profileBins" -case "$c" > "$work/log" 2>&1
expectError $? "$work/log" "no sampling files" "10"
"$bin/profileBins" -case "$c" -time 10 > "$work/log" 2>&1
expectError $? "$work/log" "no sampling files" "$c/10"
"$bin/profileBins" -case "$c" -latestTime > "$work/log" 2>&1
expectError $? "$work/log" "$c/10"
[ -e "$c/postProcessing" ] && fail "profileBins wrote $(find "$c/postProcessing") after an error"

# -snapshot needs system/profileBinsDict; an unknown keyword there is named.
"$bin/profileBins" -case "$c" -snapshot -latestTime > "$work/log" 2>&1
expectError $? "$work/log" "profileBinsDict"
printf '%s\naxis z;\nnBins 16;\nmin -3;\nmax 3;\nspecis (fluid);\n' "$header" > "$c/system/profileBinsDict"
"$bin/profileBins" -case "$c" -snapshot -latestTime > "$work/log" 2>&1
expectError $? "$work/log" "profileBinsDict:6" "specis"
[ -e "$c/postProcessing" ] && fail "profileBins -snapshot wrote $(find "$c/postProcessing") after an error"

# A good profileBinsDict: one instantaneous profile, error columns 0.
printf '%s\naxis z;\nnBins 16;\nmin -3;\nmax 3;\nspecies (fluid);\n' "$header" > "$c/system/profileBinsDict"
if "$bin/profileBins" -case "$c" -snapshot -latestTime > "$work/log" 2>&1; then
    table=$c/postProcessing/profileBins/10/snapshot.dat
    [ -f "$table" ] || fail "profileBins -snapshot did not write $table"
    [ "$(head -1 "$table")" = "# z density densityErr ux uxErr uy uyErr uz uzErr kT kTErr count" ] ||
        fail "unexpected header in $table: $(head -1 "$table")"
    [ "$(grep -vc '^#' "$table")" -eq 16 ] || fail "$table should have 16 rows"
    # Every column a finite number: the checks below read only the density and error columns.
    finiteRows "$table"
    awk '!/^#/ && ($3 != 0 || $5 != 0) { bad = 1 } END { exit bad }' "$table" || fail "$table: error columns not 0"
    awk '!/^#/ && ($2 < 2 || $2 > 6) { bad = 1 } END { exit bad }' "$table" || fail "$table: implausible densities"
else
    fail "profileBins -snapshot failed: $(cat "$work/log")"
fi

# ---- fitSlipLength: a bad mode is named with file, line and keyword; nothing written -------------------
printf '%s\nprofile snapshot;\nmode poiseuile;\n' "$header" > "$c/system/fitSlipLengthDict"
"$bin/fitSlipLength" -case "$c" -latestTime > "$work/log" 2>&1
expectError $? "$work/log" "fitSlipLengthDict:3" "'mode'" "poiseuile"
[ -e "$c/postProcessing/fitSlipLength" ] && fail "fitSlipLength wrote $(find "$c/postProcessing/fitSlipLength") after an error"

# A missing keyword and a missing table.
printf '%s\nmode poiseuille;\n' "$header" > "$c/system/fitSlipLengthDict"
"$bin/fitSlipLength" -case "$c" -latestTime > "$work/log" 2>&1
expectError $? "$work/log" "fitSlipLengthDict" "'profile'"
printf '%s\nmode poiseuille;\nprofile nothingHere;\n' "$header" > "$c/system/fitSlipLengthDict"
"$bin/fitSlipLength" -case "$c" -latestTime > "$work/log" 2>&1
expectError $? "$work/log" "nothingHere.dat"
[ -e "$c/postProcessing/fitSlipLength" ] && fail "fitSlipLength wrote $(find "$c/postProcessing/fitSlipLength") after an error"

# ---- a short real run: solver -> profileBins -> fitSlipLength ------------------------------------
r=$work/run
makeCase "$r"
if "$bin/dpdFoamLike" -case "$r" > "$r/log.dpdFoamLike" 2>&1; then
    if "$bin/profileBins" -case "$r" -latestTime > "$work/log" 2>&1; then
        [ -f "$r/postProcessing/profileBins/6/channel.dat" ] || fail "profileBins did not write channel.dat: $(cat "$work/log")"
        finiteRows "$r/postProcessing/profileBins/6/channel.dat"  # every column, errors included
        grep -q "channel" "$work/log" || fail "profileBins printed no summary: $(cat "$work/log")"
    else
        fail "profileBins failed on a real run: $(cat "$work/log")"
    fi
    printf '%s\nmode poiseuille;\nprofile channel;\n' "$header" > "$r/system/fitSlipLengthDict"
    if "$bin/fitSlipLength" -case "$r" -latestTime > "$work/log" 2>&1; then
        fit=$r/postProcessing/fitSlipLength/6/fit.dat
        # nu, its error and both walls' slip lengths each a finite number (a NaN or an empty entry fails).
        finiteNumber "$(sed -n 's/^nu  *\([^;]*\);/\1/p' "$fit")" "fit.dat nu"
        finiteNumber "$(sed -n 's/^nuError  *\([^;]*\);/\1/p' "$fit")" "fit.dat nuError"
        for k in 1 2; do
            finiteNumber "$(sed -n 's/^slipLength  *(\([^;]*\));/\1/p' "$fit" | awk -v k=$k '{ print $k }')" "fit.dat slipLength $k"
        done
    else
        fail "fitSlipLength failed on a real run: $(cat "$work/log")"
    fi
else
    fail "dpdFoamLike failed: $(tail -5 "$r/log.dpdFoamLike")"
fi

finishTests profileBinsErrors
