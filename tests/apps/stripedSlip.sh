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
close() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= t) }'; }
philip=$(awk 'BEGIN { pi = atan2(0, -1); print 10 / pi * log(1 / cos(pi / 4)) }')
close "$(value slipParallel)" "$philip" 1e-5 || fail "b_par $(value slipParallel), Philip $philip"
close "$(value slipPerpendicular)" "$(awk -v p="$philip" 'BEGIN { print p / 2 }')" 1e-5 || fail "b_perp $(value slipPerpendicular)"
b45=$(echo "$out" | sed -n 's/^angle45 { slip \([^;]*\);.*/\1/p')
close "$b45" "$(awk -v p="$philip" 'BEGIN { print 0.75 * p }')" 1e-5 || fail "b_eff(45) $b45"
out=$("$bin/stripedSlip" -period 10 -slip 2 -height 10 -walls 2 -angles 0,90) || fail "channel: $out"
for a in 0 90; do
    r=$(echo "$out" | sed -n "s/^angle$a { slip [^;]*; transverseFluxRatio \([^;]*\);.*/\1/p")
    close "$r" 0 1e-12 || fail "the flux ratio at $a degrees is '$r', not 0"
done
"$bin/stripedSlip" -gasFraction 2 > "${TMPDIR:-/tmp}/stripedSlip.$$" 2>&1
expectError $? "${TMPDIR:-/tmp}/stripedSlip.$$" "phi2 must lie in \[0, 1\]"
rm -f "${TMPDIR:-/tmp}/stripedSlip.$$"
finishTests stripedSlip
