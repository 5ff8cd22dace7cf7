#pragma once
// The awk script a slipping geometry wall's twin runs after subsetMesh (docs/walls.md 3.9): it reads
// constant/staircaseSlip (each staircase face's valueFraction by its centre in half cells, written by
// makeFoamCase), 0/C (postProcess -func writeCellCentres: solidWalls' face centres in the patch's own
// order) and 0/U, and writes 0/U with solidWalls' valueFraction one per face, failing on a face it
// cannot place.

namespace dpd {

const char* staircaseSlipScript();

}  // namespace dpd
