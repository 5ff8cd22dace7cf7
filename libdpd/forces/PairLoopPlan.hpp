#pragma once
// What the pair loop decides once per call from the pair table and the cell list: whether it can pass
// frozen-frozen pairs by the cell layout alone, whether it must still look up which pairs interact,
// and whether every interacting pair has the same coefficients (the common case, which lets the
// force loop keep them in registers).
#include "core/Species.hpp"
#include "neighbour/CellList.hpp"

#include <vector>

namespace dpd {

struct PairLoopPlan {
    // Frozen i meets only the mobile part of a cell (frozen-frozen pairs are never visited).
    bool skipFrozenPairs = false;
    // Some pair the layout does not already skip is marked non-interacting, so every candidate's
    // species must be checked.
    bool filterInteracting = false;
    // Every interacting pair has the coefficients `common`.
    bool commonCoefficients = true;
    PairCoeffs common;
    int nSpecies = 0;
    std::vector<std::uint8_t> interacts;  // nSpecies x nSpecies
};

PairLoopPlan makePairLoopPlan(const PairTable& table, const CellList& cells);

}  // namespace dpd
