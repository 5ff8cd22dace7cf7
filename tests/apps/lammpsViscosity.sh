#!/bin/bash
# The absolute viscosity against an independent code: LAMMPS (2 Aug 2023; pair dpd, fix nve, fix
# ave/chunk) measured the reverse-Poiseuille viscosity of two DPD fluids with this set-up: box 10 x 10
# x 20 periodic, body force +0.02 and -0.02 along x in the two halves along z, plain velocity Verlet
# (Groot-Warren lambda 0.5), dt 0.01, 500 time units to settle, then 2,000 averaged in 0.5-wide bins,
# a parabola fitted to each half:
#   rho 3, a 25,    gamma 4.5: nu = 0.282  (halves 0.2815, 0.2822)
#   rho 4, a 18.75, gamma 4.5: nu = 0.2778 (halves 0.2781, 0.2775)
# This code runs the same set-up three times (three seeds, each LAMMPS's whole protocol), and the mean
# of fitSlipLength's reversePoiseuille nu must lie within 2 % of LAMMPS's, after its standard error is
# found within a third of that, 0.67 % (one run's error is ~0.9 %: 2,000 time units hold few decay
# times of the box's slow modes; three runs make it ~0.5 %). A long test (ctest label long;
# ./Alltest -long and CI run it), one test a fluid so that ctest runs the two side by side with the
# rest: rho 3 about 26 minutes and rho 4 about 35 on one thread of a slow 2-core machine.
#   $1: the directory of the executables, $2: the source directory, $3: the fluid, rho3 or rho4
set -u
bin=$1
src=$2
case ${3-} in
    rho3) fluid="3 25 0.282" ;;
    rho4) fluid="4 18.75 0.2778" ;;
    *) echo "lammpsViscosity: the third argument must be rho3 or rho4, not '${3-}'"; exit 1 ;;
esac
. "$src/tests/shellTestFunctions" || exit 1
work=$(mktemp -d "${TMPDIR:-/tmp}/lammpsViscosity.XXXXXX")
trap 'rm -rf "$work"' EXIT

# A case of the LAMMPS set-up: $1 the directory, $2 rho, $3 a, $4 the seed.
writeCase() {
    local c=$1 rho=$2 a=$3 seed=$4
    mkdir -p "$c/system" "$c/constant"
    cat > "$c/constant/dpdProperties" <<EOD
$header
dimension 3; kT 1; cutoff 1; seed $seed;
species { fluid { frozen no; } }
pairCoeffs { fluid-fluid { a $a; gamma 4.5; } }
integrator { type GrootWarren; lambda 0.5; }
bodyForce { type reversePoiseuille; value (0.02 0 0); gradientAxis z; }
EOD
    cat > "$c/system/blockFrozenWallDict" <<EOD
$header
box { min (0 0 0); max (10 10 20); }
fluid { species fluid; density $rho; }
EOD
    cat > "$c/system/controlDict" <<EOD
$header
application dpdFoamLike;
startFrom startTime; startTime 0; stopAt endTime; endTime 2500; deltaT 0.01;
writeControl runTime; writeInterval 2500; reportInterval 50000;
functions
{
    profile { type binnedProfile; axis z; nBins 40; min 0; max 20; species (fluid);
              startTime 500; sampleInterval 10; samplesPerBlock 200; }
}
EOD
    cat > "$c/system/fitSlipLengthDict" <<EOD
$header
mode reversePoiseuille; profile profile; component x; exclude 1;
EOD
}

# Entry $2 of case $1's latest fit.dat, read by the project's dictionary reader.
fitted() { "$bin/dpdDictionary" "$(ls "$1"/postProcessing/fitSlipLength/*/fit.dat | tail -n 1)" -entry "$2" -value 2>/dev/null; }

# Runs case $1 through the tools; its log files beside.
runCase() {
    local c=$1 tool args
    for tool in blockFrozenWall dpdFoamLike profileBins fitSlipLength; do
        args=(-case "$c")
        case $tool in profileBins|fitSlipLength) args+=(-latestTime) ;; esac
        "$bin/$tool" "${args[@]}" > "$c/log.$tool" 2>&1 || { fail "$c: $tool failed: $(tail -n 3 "$c/log.$tool")"; return 1; }
    done
}

read -r rho a lammps <<< "$fluid"
runs=""
for seed in 11 12 13; do
    c=$work/rho$rho.seed$seed
    writeCase "$c" "$rho" "$a" "$seed"
    runCase "$c" || continue
    echo "rho $rho, seed $seed: nu $(fitted "$c" nu) +- $(fitted "$c" nuError)"
    runs+="$(fitted "$c" nu) $(fitted "$c" nuError)"$'\n'
done
# The mean of the runs and its standard error, from each run's error (empty if a run is missing).
read -r nu error <<< "$(printf '%s' "$runs" | awk 'NF == 2 { n++; s += $1; v += $2 * $2 }
    END { if (n == 3) printf "%.6f %.6f", s / n, sqrt(v) / n }')"
echo "rho $rho, a $a: nu $nu +- $error over three runs (LAMMPS $lammps)"
closeTo "$error" 0 "$(awk -v l="$lammps" 'BEGIN { print 0.02 / 3 * l }')" "rho $rho: nu's standard error (budget a third of 2 %)"
closeTo "$nu" "$lammps" "$(awk -v l="$lammps" 'BEGIN { print 0.02 * l }')" "rho $rho: nu against LAMMPS's (2 %)"
finishTests "lammpsViscosity $3"
