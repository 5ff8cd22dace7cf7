#include "system/WallForceTerm.hpp"

#include "system/System.hpp"

namespace dpd {

std::unique_ptr<ForceTerm> WallForceTerm::New(const System& system) {
    if (!system.walls.anyActsWithForces()) return nullptr;
    return std::make_unique<WallForceTerm>();
}

void WallForceTerm::add(System& s, const ForcePass& pass) const {
    WallStep step = s.wallStep();
    step.friction = pass.wallFriction;
    s.walls.addForces(step);
}

}  // namespace dpd
