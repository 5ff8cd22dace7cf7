#pragma once
// A term of a run's force list after the DPD pair force (the bonded pairs' share of the pair force
// taken back, the body force, the bonds' springs, the walls' forces). Each type registers once, in the
// order its forces are added (system/ForceTermTypes.cpp); its maker reads the System and makes no term
// where the scene has nothing for it to do, so that a scene pays only for the terms it has.
#include "core/Registry.hpp"

#include <memory>
#include <string>

namespace dpd {

class System;
struct ForcePass;

class ForceTerm {
public:
    virtual ~ForceTerm() = default;
    // Whether the term reads the particles' velocities: the pair loop cannot then predict them.
    virtual bool readsVelocities() const = 0;
    // Adds the term's forces to those the particles hold (the pass: the velocities walls' friction reads).
    virtual void add(System& system, const ForcePass& pass) const = 0;
};

// Makers return null where the system needs no such term.
using ForceTermRegistry = Registry<ForceTerm, const System&>;
const ForceTermRegistry& forceTermRegistry();

}  // namespace dpd
