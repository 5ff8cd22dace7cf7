#!/bin/bash
#------------------------------------------------------------------------------
# runTutorial.sh CASEDIR BUILDDIR
#   Smoke test of a tutorial: copies CASEDIR into a fresh temporary directory,
#   sources etc/bashrc with DPD_BUILD_DIR=BUILDDIR and runs './Allrun -test'
#   there. On failure prints the tail of every log.* and keeps the copy;
#   on success removes it. Exit status: that of Allrun.
#------------------------------------------------------------------------------
set -uo pipefail

if [ $# -ne 2 ]; then
    echo "Usage: $0 CASEDIR BUILDDIR" >&2
    exit 2
fi
[ -d "$1" ] || { echo "runTutorial: no case directory '$1'" >&2; exit 2; }
[ -d "$2" ] || { echo "runTutorial: no build directory '$2'" >&2; exit 2; }
caseDir="$(cd "$1" && pwd)"
buildDir="$(cd "$2" && pwd)"
projectDir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

[ -f "$caseDir/Allrun" ] || { echo "runTutorial: no Allrun in $caseDir" >&2; exit 2; }

# The copy mirrors the repository layout (TMP/tutorials/<family>/<case>, with
# TMP/etc a link to the repository's etc/), so that an Allrun finding
# etc/RunFunctions by a relative path (../../../etc) works as in the source tree.
case "$caseDir" in
    "$projectDir"/*) rel="${caseDir#"$projectDir"/}" ;;
    *) rel="tutorials/$(basename "$caseDir")" ;;
esac
tmpRoot="$(mktemp -d "${TMPDIR:-/tmp}/dpdTutorial.XXXXXX")" || exit 3
work="$tmpRoot/$rel"
mkdir -p "$work" && ln -s "$projectDir/etc" "$tmpRoot/etc" \
    && cp -a "$caseDir/." "$work/" \
    || { echo "runTutorial: cannot copy $caseDir to $work" >&2; exit 3; }

export DPD_BUILD_DIR="$buildDir"
unset DPD_BIN_DIR
. "$projectDir/etc/bashrc"
. "$projectDir/etc/RunFunctions"

cd "$work" || exit 3
# Start from a clean case even if the tutorial was run in the source tree.
if [ -f ./Allclean ]; then
    bash ./Allclean > /dev/null 2>&1 || cleanCase
else
    cleanCase
fi

echo "runTutorial: ${caseDir#"$projectDir"/} in $work"
start=$SECONDS
if [ -x ./Allrun ]; then
    ./Allrun -test
else
    bash ./Allrun -test
fi
status=$?

if [ $status -eq 0 ]; then
    echo "runTutorial: ${caseDir#"$projectDir"/} passed in $((SECONDS - start)) s"
    cd / && rm -rf -- "$tmpRoot"
else
    echo "runTutorial: ${caseDir#"$projectDir"/} FAILED with exit status $status after $((SECONDS - start)) s" >&2
    while IFS= read -r log; do
        echo "==> ${log#./} (last 40 lines) <==" >&2
        tail -n 40 "$log" >&2
    done < <(find . -name 'log.*' -type f | sort)
    echo "runTutorial: case kept in $work" >&2
fi
exit $status
#------------------------------------------------------------------------------
