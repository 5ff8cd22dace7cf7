#!/bin/bash
# stripedSlip prints the continuum reference: for shear-free stripes on a single wall the numerical
# b_par and b_perp equal Philip's (L/pi) ln sec(pi phi2 / 2) and half of it; b_eff(45 deg) is their
# mean; a channel's flux ratio vanishes along and across the stripes; bad input exits 1 naming it.
#   $1: the directory of the executables, $2: the source directory
set -u
bin=$1
. "$2/tests/shellTestFunctions" || exit 1
out=$("$bin/stripedSlip" -period 10 -gasFraction 0.5 -angles 0,45,90) || fail "stripedSlip failed: $out"
value() { echo "$out" | sed -n "s/^$1 *\([^;]*\);.*/\1/p"; }
philip=$(awk 'BEGIN { pi = atan2(0, -1); print 10 / pi * log(1 / cos(pi / 4)) }')
closeTo "$(value slipParallel)" "$philip" 1e-5 "b_par (Philip's)"
closeTo "$(value slipPerpendicular)" "$(awk -v p="$philip" 'BEGIN { print p / 2 }')" 1e-5 "b_perp (half of Philip's)"
b45=$(echo "$out" | sed -n 's/^angle45 { slip \([^;]*\);.*/\1/p')
closeTo "$b45" "$(awk -v p="$philip" 'BEGIN { print 0.75 * p }')" 1e-5 "b_eff(45)"
out=$("$bin/stripedSlip" -period 10 -slip 2 -height 10 -walls 2 -angles 0,90) || fail "channel: $out"
for a in 0 90; do
    r=$(echo "$out" | sed -n "s/^angle$a { slip [^;]*; transverseFluxRatio \([^;]*\);.*/\1/p")
    closeTo "$r" 0 1e-12 "the flux ratio at $a degrees"
done
"$bin/stripedSlip" -gasFraction 2 > "${TMPDIR:-/tmp}/stripedSlip.$$" 2>&1
expectError $? "${TMPDIR:-/tmp}/stripedSlip.$$" "phi2 must lie in \[0, 1\]"
rm -f "${TMPDIR:-/tmp}/stripedSlip.$$"
finishTests stripedSlip
