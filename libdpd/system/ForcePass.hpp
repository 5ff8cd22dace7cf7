#pragma once
// What an integrator asks of System::computeForces: which terms of the DPD pair force, whether the
// rest of the force list joins them (the registered force terms, system/ForceTermTypes.cpp), and how
// the pass meets the forces the particles hold.
#include "forces/DpdPairForce.hpp"
#include "walls/WallStep.hpp"

namespace dpd {

struct ForcePass {
    unsigned pairTerms = kConservativeTerm | kDissipativeTerm | kRandomTerm;  // forces/DpdPairForce.hpp
    bool otherTerms = true;    // the rest of the force list joins the pair terms
    bool addToHeld = false;    // the pass adds to the forces held (else it starts from none)
    // The pair loop reads v + predictorShift f (f the forces held; frozen particles keep theirs) and
    // leaves v alone: only for the whole pair force, and where it is the only force that reads v.
    double predictorShift = 0.0;
    VelocityColumns wallFriction{};  // the velocities the walls' friction reads (none: the particles')
    // In a decomposed run the ghosts then hold the whole forces their owners computed: for a second
    // pair loop in the step that reads what those forces did to the ghosts' velocities.
    bool ghostsHoldOwnersForces = false;

    // Every force of the current state (the Integrator contract's).
    static ForcePass whole() { return {}; }
    // The conservative pair force and every force besides the pair force (Shardlow's splitting).
    static ForcePass conservativeAndOthers() { return {kConservativeTerm, true, false, 0.0, {}, false}; }
    // The dissipative pair force added to the forces held (DPD-VV's correction).
    static ForcePass dissipativeAdded() { return {kDissipativeTerm, false, true, 0.0, {}, false}; }
};

}  // namespace dpd
