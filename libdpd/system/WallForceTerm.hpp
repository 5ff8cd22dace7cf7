#pragma once
// The forces walls put on the fluid (the tunable-slip wall's friction layer and its WCA repulsion;
// walls/SurfaceForce.hpp); only where a wall acts with forces. The friction reads the velocities the
// pass names (an integrator's predicted ones) or the particles' own.
#include "system/ForceTerm.hpp"

namespace dpd {

class WallForceTerm : public ForceTerm {
public:
    explicit WallForceTerm(Features fromWalls) : ForceTerm(fromWalls) {}
    static std::unique_ptr<ForceTerm> New(const System& system);
    void add(System& system, const ForcePass& pass) const override;
};

}  // namespace dpd
