#!/bin/bash
# Every tutorial that reproduces a paper (it ships published.dat) holds the published parameter set
# in its dictionaries by default (calibrated settings are named variants); a case with one parameter
# changed (gamma_fw 36, the couette tutorial's calibrated wall) is caught, naming the entry. Where
# published.dat gives particle counts, the builders make them at full size within 1 % (0/ only), and
# a wall one cutoff deep where the paper's is 1.5 is caught.
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
finishTests publishedParameters
