#include "forces/PairLoopPlan.hpp"

namespace dpd {

PairLoopPlan makePairLoopPlan(const PairTable& table, const CellList& cells) {
    PairLoopPlan plan;
    const int n = table.nSpecies();
    plan.nSpecies = n;
    plan.interacts.assign(static_cast<std::size_t>(n) * n, 0);
    // The layout may skip frozen-frozen pairs only if none of them interacts.
    bool frozenPairsInert = cells.splitsFrozen();
    for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
            const PairCoeffs& c = table(a, b);
            plan.interacts[a * n + b] = c.interact ? 1 : 0;
            if (cells.isFrozenSpecies(a) && cells.isFrozenSpecies(b) && c.interact) frozenPairsInert = false;
        }
    plan.skipFrozenPairs = frozenPairsInert;
    bool first = true;
    for (int a = 0; a < n; ++a)
        for (int b = 0; b < n; ++b) {
            const PairCoeffs& c = table(a, b);
            const bool skippedByLayout = plan.skipFrozenPairs && cells.isFrozenSpecies(a) && cells.isFrozenSpecies(b);
            if (!c.interact) {
                if (!skippedByLayout) plan.filterInteracting = true;
                continue;
            }
            if (first) {
                plan.common = c;
                first = false;
            } else if (c.a != plan.common.a || c.gamma != plan.common.gamma || c.sigma != plan.common.sigma) {
                plan.commonCoefficients = false;
            }
        }
    return plan;
}

}  // namespace dpd
