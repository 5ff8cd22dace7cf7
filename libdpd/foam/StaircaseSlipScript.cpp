#include "foam/StaircaseSlipScript.hpp"

namespace dpd {

const char* staircaseSlipScript() {
    return R"(# Gives each face of solidWalls its own partialSlip valueFraction (written by makeFoamCase):
#   awk -f staircaseSlip.awk constant/staircaseSlip 0/C 0/U > U.new
# constant/staircaseSlip lists the staircase's faces by their centres in half cells from the mesh's
# corner; 0/C (postProcess -func writeCellCentres) holds solidWalls' face centres in the patch's order;
# 0/U is copied with solidWalls' valueFraction (uniform, or a list from an earlier run) replaced by
# the faces' own, in that order.
function halfCells(v, a) { v = (v - origin[a]) / half[a]; return v < 0 ? -int(-v + 0.5) : int(v + 0.5) }
function fail(message) { print "staircaseSlip.awk: " message > "/dev/stderr"; failed = 1; exit 1 }
function matchFaces(    t, m, i, key) {
    gsub(/[();]/, " ", centres)
    m = split(centres, t, " ")
    n = t[1] + 0
    if (n < 1 || m != 1 + 3 * n) fail("0/C holds no face centres of solidWalls")
    for (i = 1; i <= n; i++) {
        key = halfCells(t[3 * i - 1], 1) " " halfCells(t[3 * i], 2) " " halfCells(t[3 * i + 1], 3)
        if (!(key in fraction)) fail("face " i " of solidWalls, at (" t[3 * i - 1] " " t[3 * i] " " t[3 * i + 1] "), is not in constant/staircaseSlip")
        list[i] = fraction[key]
    }
}
FNR == 1 { file++ }
file == 1 && $1 == "origin" { origin[1] = $2; origin[2] = $3; origin[3] = $4; next }
file == 1 && $1 == "halfCell" { half[1] = $2; half[2] = $3; half[3] = $4; next }
file == 1 && $1 ~ /^[0-9]+$/ { fraction[$1 " " $2 " " $3] = $4; next }
file == 1 { next }
file == 2 {
    if ($1 == "solidWalls") patch = 1
    if (patch && !listed && index($0, "List<vector>")) { listed = 1; sub(/.*List<vector>/, "") }
    if (listed == 1) { centres = centres " " $0; if (index($0, ";")) listed = 2 }
    next
}
file == 3 && !matched { matched = 1; matchFaces() }
$1 == "solidWalls" { inWalls = 1 }
skipping { if (index($0, ";")) skipping = 0; next }
inWalls && $1 == "valueFraction" {
    print "        valueFraction   nonuniform List<scalar> " n
    print "("
    for (i = 1; i <= n; i++) print list[i]
    print ");"
    inWalls = 0; replaced = 1; skipping = !index($0, ";"); next
}
{ print }
END {
    if (failed) exit 1
    if (!replaced) { print "staircaseSlip.awk: 0/U has no valueFraction on solidWalls" > "/dev/stderr"; exit 1 }
}
)";
}

}  // namespace dpd
