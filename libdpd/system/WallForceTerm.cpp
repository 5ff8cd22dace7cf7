#include "system/WallForceTerm.hpp"

#include "system/System.hpp"

namespace dpd {

std::unique_ptr<ForceTerm> WallForceTerm::New(const System& system) {
    if (!system.walls.anyActsWithForces()) return nullptr;
    Features fromWalls;
    for (std::size_t i = 0; i < system.walls.size(); ++i)
        if (system.walls[i].actsWithForces()) fromWalls |= system.walls[i].capabilities().features;
    return std::make_unique<WallForceTerm>(fromWalls);
}

void WallForceTerm::add(System& s, const ForcePass& pass) const {
    WallStep step = s.wallStep();
    step.friction = pass.wallFriction;
    s.walls.addForces(step);
}

}  // namespace dpd
