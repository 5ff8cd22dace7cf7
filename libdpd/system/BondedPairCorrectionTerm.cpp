#include "system/BondedPairCorrectionTerm.hpp"

#include "forces/BondedPairCorrection.hpp"
#include "system/System.hpp"

namespace dpd {

std::unique_ptr<ForceTerm> BondedPairCorrectionTerm::New(const System& system) {
    if (system.bonds.empty() || system.bondedPairs.keepsAll()) return nullptr;
    return std::make_unique<BondedPairCorrectionTerm>(system.bondedPairs.capabilities().features);
}

void BondedPairCorrectionTerm::add(System& s, const ForcePass&) const {
    const BondedPairScene scene{s.pairs, s.forceParameters, s.random(), static_cast<std::uint64_t>(s.step)};
    correctBondedPairs(s.bonds, s.bondedPairs, scene, s.box, s.particles);
}

}  // namespace dpd
