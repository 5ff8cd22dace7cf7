#pragma once
// A sweep over all interacting pairs within the cutoff that may change both particles of a pair as
// it goes, so that each pair sees what the pairs before it did (Shardlow's splitting). The result
// depends on the order, so the order is fixed by the cell layout alone, whatever the number of
// threads: the pairs are found as the force loop finds them (forces/PairForceLoop.hpp: a batch per
// row of cells of a slab, cell by cell, run of candidates by run), and the
// slabs are swept in the force loop's colours. A row's pairs touch particles of slabs ix and ix + 1
// only, and two slabs of one colour share no particle, so sweeping them at the same time on different
// threads gives exactly what sweeping them one after the other would.
#include "forces/PairForceLoop.hpp"
#include "neighbour/CellList.hpp"

#include <vector>

namespace dpd {

// Calls visitRow(batch) once per row of cells, in the order above, with the row's pairs in
// batch.i, batch.j, batch.dx, dy, dz (r_i - r_j, single precision) and batch.size; `visitRow` may change velocities
// (never positions: the cell list must stay valid) and use the batch's other arrays as scratch.
template <class VisitRow>
void sweepPairRows(const Particles& p, const CellList& cells, const PairTable& table, double cutoff,
                   const VisitRow& visitRow) {
    // Positions only: the sweep reads the velocities as it changes them, and draws its own numbers.
    detail::forEachPairRowInColours(p, cells, makePairLoopPlan(table, cells), false, false, cutoff, visitRow);
}

}  // namespace dpd
