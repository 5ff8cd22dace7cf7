#!/bin/bash
# Every tutorial that reproduces a paper (it ships published.dat) holds the published parameter set
# in its dictionaries by default (calibrated settings are named variants); a case with one parameter
# changed (gamma_fw 36, the couette tutorial's calibrated wall) is caught, naming the entry. Where
# published.dat gives particle counts, the builders make them at full size within 1 % (0/ only), and
# a wall one cutoff deep where the paper's is 1.5 is caught, and so is a contraction of another outline.
# The polymer channel's published cases (its table "sweeps") are built at full size with their chains:
# each holds nChain x ChainLen beads in nChain chains and the published mobile count within 1 %; its
# earlier default (-latticeWall: walls at +-14) is caught short of the published fluid.
#   $1: the directory of the executables, $2: the source directory
set -u
bin=$1
src=$2
. "$src/tests/shellTestFunctions" || exit 1
export PATH="$bin:$PATH"
check="$src/etc/checkPublishedParameters"

# The tutorials' published.dat files: in a git checkout the tracked ones (a tutorial run in the source
# tree leaves copies of its case, published.dat included, that are not tutorials), else every one.
publishedFiles() {
    git -C "$src" ls-files -- 'tutorials/*published.dat' 2>/dev/null | sed "s|^|$src/|" | grep . ||
        find "$src/tutorials" -name published.dat
}
cases=$(publishedFiles | xargs -n 1 dirname | sort)
[ -n "$cases" ] || fail "no tutorial ships a published.dat"
for c in $cases; do
    out=$("$check" "$c" 2>&1) || fail "$c does not hold its published parameters: $(echo "$out" | grep MISMATCH)"
done

tmp=$(mktemp -d "${TMPDIR:-/tmp}/publishedParameters.XXXXXX")
cp -r "$src/tutorials/channel/couetteSlip/"{constant,system,published.dat} "$tmp/"
dpdDictionary "$tmp/constant/dpdProperties" -entry pairCoeffs/fluid-wall/gamma -set 36 > /dev/null
"$check" "$tmp" > "$tmp/log" 2>&1
expectError $? "$tmp/log" "MISMATCH $tmp/constant/dpdProperties: pairCoeffs/fluid-wall/gamma is 36, published 4.5"
[ "$(grep -c MISMATCH "$tmp/log")" -eq 1 ] || fail "one change, $(grep -c MISMATCH "$tmp/log") mismatches: $(cat "$tmp/log")"
rm -rf "$tmp"

counted=$(grep -l '^count' $(publishedFiles) | xargs -n 1 dirname | sort)
[ -n "$counted" ] || fail "no tutorial's published.dat gives particle counts"
for c in $counted; do
    out=$("$src/etc/checkPublishedCounts" "$c" 2>&1) || fail "$c does not build its published counts: $(echo "$out" | grep MISMATCH)"
    echo "$out"
done

tmp=$(mktemp -d "${TMPDIR:-/tmp}/publishedCounts.XXXXXX")
poiseuille="$src/tutorials/channel/poiseuille"
cp -r "$poiseuille/fcc" "$poiseuille/published.dat" "$tmp/"
dpdDictionary "$tmp/fcc/system/blockFrozenWallDict" -entry wall/thickness -set 1 > /dev/null
grep -v '^count *random' "$poiseuille/published.dat" > "$tmp/published.dat"
"$src/etc/checkPublishedCounts" "$tmp" > "$tmp/log" 2>&1
expectError $? "$tmp/log" "MISMATCH $tmp/fcc: wall 1440, published 2160"
rm -rf "$tmp"
# A random wall of the wrong outline: the square contraction with the earlier throat (15 wide, 15
# long) makes 1,575 of flow area and about 2,670 boundary particles 1.5 deep for the published 2,868,
# more than three Poisson deviations short.
tmp=$(mktemp -d "${TMPDIR:-/tmp}/publishedCounts.XXXXXX")
cp -r "$src/tutorials/contraction/squareContraction/"{constant,system,published.dat} "$tmp/"
sed -i 's/^L = 30;  H = 15;  c = 10;  h = 5;$/L = 30;  H = 15;  c = 7.5;  h = 7.5;/' "$tmp/constant/geometry/contraction.geo"
grep -q 'c = 7.5;  h = 7.5;' "$tmp/constant/geometry/contraction.geo" || fail "the square contraction's outline line has changed"
"$src/etc/checkPublishedCounts" "$tmp" > "$tmp/log" 2>&1
expectError $? "$tmp/log" "MISMATCH $tmp/.: fluid" "MISMATCH $tmp/.: wall"
rm -rf "$tmp"

# The polymer channel: every published case built at full size (blockFrozenWall once, then insertChains
# in a copy per case), its snapshot read back: the beads and chains the table gives, every bead
# counted among the published mobile particles (within 1 %, as the count line), the walls unchanged.
polymer="$src/tutorials/polymer/channel"
python=${DPD_PYTHON:-/usr/bin/python3}
requirePython "$python" h5py numpy || finishTests publishedParameters
mobile=$(awk '$1 == "count" && $2 == "channel" && $4 == "fluid" { print $5 }' "$polymer/published.dat")
finiteNumber "$mobile" "the polymer channel's published mobile count" || finishTests publishedParameters
rows=$(awk '$1 == "table" { t = $2 } $1 == "row" && t == "sweeps" { print $2 "x" $3 "x" $4 }' "$polymer/published.dat")
[ "$(echo $rows | wc -w)" -eq 6 ] || fail "the polymer channel's published.dat lists $(echo $rows | wc -w) cases, not the six published"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/publishedChains.XXXXXX")
cp -r "$polymer/channel" "$tmp/base"
blockFrozenWall -case "$tmp/base" > "$tmp/base/log.blockFrozenWall" 2>&1 || fail "blockFrozenWall failed on the polymer channel: $(tail -n 3 "$tmp/base/log.blockFrozenWall")"
for row in $rows; do
    IFS=x read -r n L beads <<< "$row"
    [ "$beads" -eq $((n * L)) ] || fail "the polymer channel's case $n x $L lists $beads beads"
    one="$tmp/chains${n}_length$L"
    cp -r "$tmp/base" "$one"
    if [ "$n" -gt 0 ]; then
        dpdDictionary "$one/system/insertChainsDict" -entry chains -set "$n" > /dev/null
        dpdDictionary "$one/system/insertChainsDict" -entry length -set "$L" > /dev/null
        insertChains -case "$one" > "$one/log.insertChains" 2>&1 || { fail "insertChains failed for $n x $L: $(tail -n 3 "$one/log.insertChains")"; continue; }
    fi
    out=$("$python" - "$one/0/particles.h5" "$n" "$beads" "$mobile" <<'PY'
import sys
import h5py
import numpy as np
path, chains, beads, published = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4])
with h5py.File(path, "r") as f:
    names = [s.decode() if isinstance(s, bytes) else str(s) for s in f.attrs["speciesNames"]]
    frozen = np.asarray(f.attrs["speciesFrozen"]) != 0
    species = np.asarray(f["particles/species"])
    chain = np.asarray(f["particles/chain"]) if "particles/chain" in f else np.full(len(species), -1)
mobile = int(np.sum(~frozen[species]))
polymer = int(np.sum(species == names.index("polymer")))
found = len(np.unique(chain[chain >= 0]))
print(f"{chains} x {beads // chains if chains else 0}: mobile {mobile} (published {published}), beads {polymer}, "
      f"chains {found}, frozen {int(np.sum(frozen[species]))}")
ok = polymer == beads and found == chains and abs(mobile / published - 1) < 0.01
sys.exit(0 if ok else 1)
PY
) || fail "the polymer channel's case $n x $L: $out (the published: $beads beads in $n chains, $mobile mobile within 1 %)"
    echo "ok       polymer channel $out"
done
rm -rf "$tmp"
# Its earlier default, the -latticeWall variant (walls at +-14, d = 28), holds too little fluid.
tmp=$(mktemp -d "${TMPDIR:-/tmp}/publishedCounts.XXXXXX")
cp -r "$polymer/latticeWall" "$tmp/channel"
grep '^count' "$polymer/published.dat" > "$tmp/published.dat"
"$src/etc/checkPublishedCounts" "$tmp" > "$tmp/log" 2>&1
expectError $? "$tmp/log" "MISMATCH $tmp/channel: fluid"
rm -rf "$tmp"
finishTests publishedParameters
