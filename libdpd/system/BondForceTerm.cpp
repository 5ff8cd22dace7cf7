#include "system/BondForceTerm.hpp"

#include "parallel/RankChains.hpp"
#include "system/System.hpp"

namespace dpd {

std::unique_ptr<ForceTerm> BondForceTerm::New(const System& system) {
    if (system.bonds.empty()) return nullptr;
    return std::make_unique<BondForceTerm>();
}

void BondForceTerm::add(System& s, const ForcePass&) const {
    BondPassResult found = s.bondPotential->addForces(s.bonds, s.particles, s.box);
    if (s.domain()) found = agreedOverRanks(s.domain()->communicator(), found);
    s.recordBondPass(found);
}

}  // namespace dpd
