#pragma once
// A term of a run's force list after the DPD pair force (the bonded pairs' share of the pair force
// taken back, the body force, the bonds' springs, the walls' forces). Each type registers once, in the
// order its forces are added (system/ForceTermTypes.cpp); its maker reads the System and makes no term
// where the scene has nothing for it to do, so that a scene pays only for the terms it has.
#include "core/Capabilities.hpp"
#include "core/Registry.hpp"

#include <memory>
#include <string>

namespace dpd {

class System;
struct ForcePass;

class ForceTerm {
public:
    virtual ~ForceTerm() = default;
    // What the parts the term applies declare (their capabilities, core/Capabilities.hpp), one
    // declaration for the run's check pass and the System: with Feature::velocityForce the term reads
    // the particles' velocities, and the pair loop cannot then predict them.
    const Features& features() const { return features_; }
    // Adds the term's forces to those the particles hold (the pass: the velocities walls' friction reads).
    virtual void add(System& system, const ForcePass& pass) const = 0;

protected:
    explicit ForceTerm(Features fromParts = {}) : features_(fromParts) {}

private:
    Features features_;
};

// Makers return null where the system needs no such term.
using ForceTermRegistry = Registry<ForceTerm, const System&>;
const ForceTermRegistry& forceTermRegistry();

}  // namespace dpd
