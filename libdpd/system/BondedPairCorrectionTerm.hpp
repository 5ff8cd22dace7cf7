#pragma once
// The part of the DPD pair force that bonded pairs leave out, taken back after the pair loop
// (forces/BondedPairCorrection.hpp); only with chains whose bonded pairs do not keep the whole force.
#include "system/ForceTerm.hpp"

namespace dpd {

class BondedPairCorrectionTerm : public ForceTerm {
public:
    explicit BondedPairCorrectionTerm(Features fromBondedPairs) : ForceTerm(fromBondedPairs) {}
    static std::unique_ptr<ForceTerm> New(const System& system);
    void add(System& system, const ForcePass& pass) const override;
};

}  // namespace dpd
