#!/bin/bash
# hydrodynamicWall reads fitSlipLength's Couette and Poiseuille fits of the same wall settings and
# places the wall: fit.dat files made from a known wall (acting 0.3 inside each geometric plane of a
# channel 10 wide) and known slip lengths 2, 1, 0.4 and 0 must give them back; bad input (unpaired
# runs, a Poiseuille fit given as Couette, a case without a fit) exits 1 naming it.
#   $1: the directory of the executables, $2: the source directory
set -u
bin=$1
. "$2/tests/shellTestFunctions" || exit 1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# fitCase DIR MODE SLIP: a case whose latest fit.dat holds the apparent slip length SLIP at both walls.
fitCase() {
    mkdir -p "$1/postProcessing/fitSlipLength/100"
    cat > "$1/postProcessing/fitSlipLength/100/fit.dat" <<EOD
$header
mode $2;
wallPosition (-5 5);
slipLength ($3 $3);
slipLengthError (0.01 0.01);
EOD
}
h=4.7
couette=() poiseuille=()
for b in 2 1 0.4 0; do
    # Couette reaches the wall's speed at h + b = 5 + beta_c; the parabola's zero squared is
    # h^2 + 2 b h = 25 + 10 beta_p.
    fitCase "$work/c$b" couette "$(awk -v h=$h -v b=$b 'BEGIN { printf "%.12g", h + b - 5 }')"
    fitCase "$work/p$b" poiseuille "$(awk -v h=$h -v b=$b 'BEGIN { printf "%.12g", (h * h + 2 * b * h - 25) / 10 }')"
    couette+=("$work/c$b")
    poiseuille+=("$work/p$b")
done
out=$("$bin/hydrodynamicWall" -couette "${couette[@]}" -poiseuille "${poiseuille[@]}" 2>&1) || fail "hydrodynamicWall failed: $out"
# The entry named exactly $1 (a space after the name: halfWidth is not halfWidthError).
value() { echo "$out" | sed -n "s/^$1  *\([^;]*\);.*/\1/p"; }
closeTo "$(value halfWidth)" 4.7 1e-6 "halfWidth (made with 4.7)"
closeTo "$(value offset)" 0.3 1e-6 "offset (made with 0.3)"
read -r -a slips <<< "$(value slipLength | tr -d '()')"
expected=(2 1 0.4 0)
[ ${#slips[@]} -eq 4 ] || fail "slipLength '$(value slipLength)': four values expected"
for k in 0 1 2 3; do
    closeTo "${slips[k]:-}" "${expected[k]}" 1e-6 "slip length $k (made with ${expected[k]})"
done

log=$work/log
"$bin/hydrodynamicWall" -couette "${couette[@]}" -poiseuille "${poiseuille[@]:0:3}" > "$log" 2>&1
expectError $? "$log" "4 Couette runs and 3 Poiseuille runs"
"$bin/hydrodynamicWall" -couette "${poiseuille[@]}" -poiseuille "${poiseuille[@]}" > "$log" 2>&1
expectError $? "$log" "p2/postProcessing/fitSlipLength/100/fit.dat" "mode" "give the couette runs after -couette"
mkdir -p "$work/empty"
"$bin/hydrodynamicWall" -couette "$work/empty" "${couette[@]:1}" -poiseuille "${poiseuille[@]}" > "$log" 2>&1
expectError $? "$log" "empty/postProcessing/fitSlipLength" "run fitSlipLength"
# -calibration: the same runs as a tunable-slip wall's friction sweep (the stripedWall tutorial's
# calibration case at gamma_L 0.5, 1, 2, 4 for b 2, 1, 0.4, 0) make a slip calibration with the known
# wall offset and slip lengths; a run of another fluid is refused by the entry that differs, and then
# no file is written.
src=$2
gammas=(0.5 1 2 4)
k=0
for b in 2 1 0.4 0; do
    for c in "$work/c$b" "$work/p$b"; do
        cp -r "$src/tutorials/channel/stripedWall/calibration/couette/"{constant,system} "$c/"
        for wall in lower upper; do
            "$bin/dpdDictionary" "$c/constant/dpdProperties" -entry walls/$wall/tunableSlip/gammaL -set "${gammas[k]}" > /dev/null
        done
    done
    k=$((k + 1))
done
calibration=$work/slipCalibration
"$bin/hydrodynamicWall" -couette "${couette[@]}" -poiseuille "${poiseuille[@]}" -calibration "$calibration" > "$log" 2>&1 ||
    fail "hydrodynamicWall -calibration failed: $(cat "$log")"
entry() { sed -n "s/^$1  *\([^;]*\);.*/\1/p" "$calibration"; }
[ "$(entry gammaL)" = "(0.5 1 2 4)" ] || fail "calibration gammaL '$(entry gammaL)', made with (0.5 1 2 4)"
closeTo "$(entry wallOffset)" 0.3 1e-6 "the calibration's wallOffset (made with 0.3)"
read -r -a calibrated <<< "$(entry slipLength | tr -d '()')"
for k in 0 1 2 3; do
    closeTo "${calibrated[k]:-}" "${expected[k]}" 1e-6 "calibrated slip length $k (made with ${expected[k]})"
done
grep -q 'integrator *"GrootWarren lambda 0.65";' "$calibration" || fail "the calibration's integrator: $(grep integrator "$calibration")"
rm "$calibration"
"$bin/dpdDictionary" "$work/p0.4/constant/dpdProperties" -entry pairCoeffs/fluid-fluid/a -set 25 > /dev/null
"$bin/hydrodynamicWall" -couette "${couette[@]}" -poiseuille "${poiseuille[@]}" -calibration "$calibration" > "$log" 2>&1
expectError $? "$log" "p0.4: not the fluid and wall model of" "fluid/a 25 against 0"
[ ! -e "$calibration" ] || fail "a refused calibration left a file"
finishTests hydrodynamicWall
