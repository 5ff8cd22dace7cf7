#pragma once
// The System's body force on the mobile particles (forces/BodyForce.hpp), the one it holds at each step.
#include "system/ForceTerm.hpp"

namespace dpd {

class BodyForceTerm : public ForceTerm {
public:
    static std::unique_ptr<ForceTerm> New(const System& system);
    void add(System& system, const ForcePass& pass) const override;
};

}  // namespace dpd
