#pragma once
// The chains' bond springs (forces/BondPotential.hpp); what the pass found (the longest bond, a broken
// one) is the System's bondPass(), agreed over the ranks so that every rank stops together.
#include "system/ForceTerm.hpp"

namespace dpd {

class BondForceTerm : public ForceTerm {
public:
    static std::unique_ptr<ForceTerm> New(const System& system);
    void add(System& system, const ForcePass& pass) const override;
};

}  // namespace dpd
