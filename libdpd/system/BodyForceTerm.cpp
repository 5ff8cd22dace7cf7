#include "system/BodyForceTerm.hpp"

#include "system/System.hpp"

namespace dpd {

std::unique_ptr<ForceTerm> BodyForceTerm::New(const System&) {
    // Always: the body force may be set after initialise() (the studies' probes turn one on in a copy
    // of a resting fluid); the one of a scene without (`none`) adds nothing.
    return std::make_unique<BodyForceTerm>();
}

void BodyForceTerm::add(System& s, const ForcePass&) const {
    s.bodyForce->apply(s.particles, s.frozenOfSpecies(), s.box);
}

}  // namespace dpd
