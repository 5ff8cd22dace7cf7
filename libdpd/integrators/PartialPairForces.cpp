#include "integrators/PartialPairForces.hpp"

#include "forces/PairForceLoop.hpp"
#include "system/System.hpp"

namespace dpd {

namespace {

PairLoopContext contextOf(const System& sys) {
    return {sys.cells(), sys.pairs, sys.random(), static_cast<std::uint64_t>(sys.step)};
}

}  // namespace

void computeConservativeForces(System& sys) {
    sys.particles.clearForces();
    const PairForceParameters& params = sys.forceParameters;
    if (sys.usesConservativeForce())
        withDpdWeight(params, [&](auto weight) {
            const DpdPairTerms<kConservativeTerm, decltype(weight)> conservative(weight, params);
            accumulatePairForces(sys.particles, contextOf(sys), conservative, params.cutoff);
        });
    sys.bodyForce->apply(sys.particles, sys.frozenOfSpecies(), sys.box);
    sys.addBondForces();
}

void addDissipativeForces(System& sys) {
    const PairForceParameters& params = sys.forceParameters;
    withDpdWeight(params, [&](auto weight) {
        const DpdPairTerms<kDissipativeTerm, decltype(weight)> dissipative(weight, params);
        accumulatePairForces(sys.particles, contextOf(sys), dissipative, params.cutoff);
    });
}

}  // namespace dpd
