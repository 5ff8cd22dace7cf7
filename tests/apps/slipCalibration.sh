#!/bin/bash
# slipCalibration on the shipped calibration of the standard fluid: a b at a calibrated point takes that
# point's friction and the calibration's offset; no slip (below the range) takes the stiffest friction
# with its plane moved out by the slip it leaves; dpdfoam.slip.calibrated_walls gives the same and
# None outside the range; a b above the range, a missing file and no -file exit 1 naming what is wrong.
#   $1: the directory of the executables, $2: the source directory
set -u
bin=$1
src=$2
. "$src/tests/shellTestFunctions" || exit 1
file="$src/etc/slipCalibrations/standardFluidFluidBehind"
list() { sed -n "s/^$1 *(\([^)]*\));.*/\1/p" "$file" | awk -v k="$2" '{ print $k }'; }
entry() { sed -n "s/^$1[[:space:]]\+\([^;]*\);.*/\1/p"; }
b4=$(list slipLength 4) g4=$(list gammaL 4) e4=$(list slipLengthError 4)
stiffest=$(list gammaL 9) bmin=$(list slipLength 9)
offset=$(entry wallOffset < "$file")
out=$("$bin/slipCalibration" -file "$file" -slipLength "$b4" 0) || fail "slipCalibration failed: $out"
column() { echo "$out" | sed -n "s/^$1 *(\([^)]*\));.*/\1/p" | awk -v k="$2" '{ print $k }'; }
closeTo "$(column gammaL 1)" "$g4" 1e-8 "gamma_L at the calibrated point b = $b4"
closeTo "$(column slipLengthError 1)" "$e4" 1e-8 "its error"
closeTo "$(column planeOffset 1)" "$offset" 1e-8 "its plane offset"
closeTo "$(column gammaL 2)" "$stiffest" 0 "no slip: the stiffest gamma_L"
closeTo "$(column planeOffset 2)" "$(awk -v o="$offset" -v b="$bmin" 'BEGIN { printf "%.12g", o - b }')" 1e-8 "no slip: the plane moved out by $bmin"
closeTo "$(column slipLeft 2)" "$bmin" 1e-8 "no slip: the slip the stiffest friction leaves"
py=$(PATH="$bin:$PATH" PYTHONPATH="$src/etc/python" /usr/bin/python3 -c "
from dpdfoam.slip import calibrated_walls
summary, walls = calibrated_walls('$file', [$b4, 0.0, 1e3])
print(walls[0]['gammaL'], walls[1]['planeOffset'], walls[2], summary['largestSlip'])" 2>&1) || fail "calibrated_walls: $py"
read -r pyGamma pyPlane pyOutside pyLargest <<< "$py"
closeTo "$pyGamma" "$g4" 1e-8 "calibrated_walls: gamma_L at b = $b4"
closeTo "$pyPlane" "$(column planeOffset 2)" 1e-8 "calibrated_walls: no slip's plane"
[ "$pyOutside" = None ] || fail "calibrated_walls: b = 1000 gave $pyOutside, not None"
closeTo "$pyLargest" "$(list slipLength 1)" 1e-8 "calibrated_walls: the largest slip"
log="${TMPDIR:-/tmp}/slipCalibration.$$"
"$bin/slipCalibration" -file "$file" -slipLength 1 1000 > "$log" 2>&1
expectError $? "$log" "-slipLength: slip length 1000 outside the calibrated range 0 to"
"$bin/slipCalibration" -file "$src/noSuchCalibration" > "$log" 2>&1
expectError $? "$log" "noSuchCalibration: cannot open file"
"$bin/slipCalibration" -slipLength 1 > "$log" 2>&1
expectError $? "$log" "file"
rm -f "$log"
finishTests slipCalibration
