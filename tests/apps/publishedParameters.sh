#!/bin/bash
# Every tutorial that reproduces a paper (it ships published.dat) holds the published parameter set
# in its dictionaries by default (calibrated settings are named variants); a case with one parameter
# changed (gamma_fw 36, the couette tutorial's calibrated wall) is caught, naming the entry. Where
# published.dat gives particle counts, the builders make them at full size within 1 % (0/ only), and
# a wall one cutoff deep where the paper's is 1.5 is caught, and so is a contraction of another outline.
#   $1: the directory of the executables, $2: the source directory
set -u
bin=$1
src=$2
. "$src/tests/shellTestFunctions" || exit 1
export PATH="$bin:$PATH"
check="$src/etc/checkPublishedParameters"

cases=$(find "$src/tutorials" -name published.dat -printf '%h\n' | sort)
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

counted=$(grep -l '^count' $(find "$src/tutorials" -name published.dat) | xargs -n 1 dirname | sort)
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
finishTests publishedParameters
