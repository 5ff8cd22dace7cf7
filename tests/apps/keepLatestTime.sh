#!/bin/bash
# keepLatestTime (etc/RunFunctions): in a case with time directories written in several forms (0,
# integers, decimals, an exponent), only 0/ and the latest by value stay, with every other directory
# and file of the case; in a case without time directories nothing happens.
#   $1: the directory of the executables, $2: the source directory
set -u
src=$2
DPD_PROJECT_DIR="$src"
. "$src/etc/RunFunctions" || exit 1
. "$src/tests/shellTestFunctions" || exit 1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1

mkdir -p case/0 case/5 case/20.5 case/100 case/1e3 case/999 case/constant case/system case/postProcessing/x/100
touch case/log.dpdFoamLike case/1e3/particles.h5
(cd case && keepLatestTime) || fail "keepLatestTime returned non-zero"
got=$(cd case && ls -d */ | tr -d '/' | sort | tr '\n' ' ')
[ "$got" = "0 1e3 constant postProcessing system " ] || fail "expected 0 1e3 constant postProcessing system, got: $got"
[ -f case/1e3/particles.h5 ] && [ -f case/log.dpdFoamLike ] && [ -d case/postProcessing/x/100 ] ||
    fail "the latest time's files, the logs and postProcessing/ stay"

mkdir -p empty/system
(cd empty && keepLatestTime) || fail "keepLatestTime returned non-zero without time directories"
[ -d empty/system ] || fail "nothing removed without time directories"
finishTests keepLatestTime
