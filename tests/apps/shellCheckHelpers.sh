#!/bin/bash
# The checks of tests/shellTestFunctions fail on what proves nothing: finiteNumber, closeTo and
# finiteRows on nan, inf, an empty value, text, a value just outside the tolerance (each counted once,
# status 1), and pass on a value inside; requirePython fails on a missing module; skipTest exits 77.
#   $1: the directory of the executables (unused), $2: the source directory
set -u
src=$2
. "$src/tests/shellTestFunctions" || exit 1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# "FAILURES STATUS" of one check, run in a subshell so that this script's own count stays apart.
outcome() { ( failures=0; "$@" > /dev/null; status=$?; echo "$failures $status" ); }

rejects() {
    local got
    got=$(outcome "$@")
    [ "$got" = "1 1" ] || fail "$(printf '[%s] ' "$@")should fail once with status 1; failures, status: $got"
}

accepts() {
    local got
    got=$(outcome "$@")
    [ "$got" = "0 0" ] || fail "$(printf '[%s] ' "$@")should pass; failures, status: $got"
}

# ---- finiteNumber ----------------------------------------------------------------------------------
for v in nan NaN -nan inf -inf Infinity 1e999 "" abc 1.5x "1 2" " 1" . e5 0x10; do
    rejects finiteNumber "$v" "a value"
done
for v in 0 -1.5 +2. .5 2.5e-3 1E+3 -1.7e308; do
    accepts finiteNumber "$v" "a value"
done

# ---- closeTo: every argument finite, the value within the tolerance -------------------------------
for v in nan inf -inf "" abc 2.0000011 1.9999989; do
    rejects closeTo "$v" 2 1e-6 "b_par"
done
rejects closeTo 2 nan 1e-6
rejects closeTo 2 "" 1e-6
rejects closeTo 2 2 nan
rejects closeTo 2 2 ""
rejects closeTo 2
rejects closeTo "" 0 1e-12 "the flux ratio"
for v in 2 2.0000009 1.9999991; do
    accepts closeTo "$v" 2 1e-6 "b_par"
done
accepts closeTo 0 0 1e-12
# The message names the quantity and the offending value.
message=$(closeTo nan 2 1e-6 "b_par (Philip's)")
case "$message" in *"b_par (Philip's)"*nan*) ;; *) fail "closeTo's message names neither quantity nor value: $message" ;; esac

# ---- finiteRows: every field of every row not a comment ---------------------------------------------
table() { printf '# z density kT count\n-1.5 3.9 1.01 120\n%s\n1.5 4.1 0.99 131\n' "$1" > "$work/$2"; }
table "0 4.0 1.00 125" good
accepts finiteRows "$work/good"
for bad in "0 4.0 nan 125" "0 4.0 -nan 125" "0 inf 1.00 125" "0 4.0 1.00 -inf" "0 4.0 1.00 12x"; do
    table "$bad" bad
    rejects finiteRows "$work/bad"
done
printf '# z density\n\n' > "$work/commentsOnly"
rejects finiteRows "$work/commentsOnly"
rejects finiteRows "$work/none"
message=$(finiteRows "$work/bad" "the table")
case "$message" in *"the table"*"line 3 column 4"*12x*) ;; *) fail "finiteRows's message does not place the field: $message" ;; esac

# ---- requirePython, skipTest ------------------------------------------------------------------------
rejects requirePython /usr/bin/python3 noSuchModuleOfShellCheckHelpers
rejects requirePython "$work/noPython" sys
accepts requirePython /usr/bin/python3 sys os
message=$(requirePython /usr/bin/python3 noSuchModuleOfShellCheckHelpers)
case "$message" in *"python3-noSuchModuleOfShellCheckHelpers"*) ;; *) fail "requirePython's message names no package: $message" ;; esac
message=$(skipTest "no optional tool")
[ $? -eq 77 ] || fail "skipTest should exit 77"
[ "$message" = "SKIP: no optional tool" ] || fail "skipTest printed '$message'"

finishTests shellCheckHelpers
