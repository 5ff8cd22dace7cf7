#pragma once
// A reflection rule (docs/walls.md 3.3): what a wall does to a fluid particle that crossed its surface,
// or, for a rule with a layer, that approaches it. A rule knows only the surface's normal at the
// particle, never the wall's shape, so any rule works on any shape (Mirheo's one class per rule).
// Velocities are relative to the wall. Each rule is one small class that reads its own parameters;
// walls/WallRuleTypes.cpp registers it under its name (`reflection <name>;`).
#include "core/Box.hpp"
#include "random/PairRandom.hpp"

#include <Eigen/Core>
#include <cstdint>
#include <string>

namespace dpd {

// Where a rule's random draws come from: keyed by (step, particle id, stream), so they do not depend
// on the thread count.
struct RuleDraw {
    const Box& box;
    const PairRandom& random;
    std::uint64_t step;
    std::uint64_t id;
    double kT;
    std::uint32_t stream;
};

class WallRule {
public:
    virtual ~WallRule() = default;

    // The rule's name and parameters for the log, e.g. "bounceLayer (layer 0.1)".
    virtual std::string description() const = 0;
    // Whether a particle found in the solid is returned (none: the wall's frozen particles must keep
    // the fluid out).
    virtual bool returnsFluid() const { return true; }
    // Whether the return is finished only once the step's forces have acted (bounce-forward).
    virtual bool defersCrossing() const { return false; }
    // How far in front of the surface the rule turns approaching particles round (0: none).
    virtual double layer() const { return 0.0; }

    // The velocity of a particle returned across the surface of unit normal n (into the fluid).
    virtual Eigen::Vector3d atSurface(const Eigen::Vector3d& relative, const Eigen::Vector3d& n, const RuleDraw&) const = 0;
    // The velocity of a particle within layer() of the surface and moving towards it.
    virtual Eigen::Vector3d inLayer(const Eigen::Vector3d& relative, const Eigen::Vector3d&, const RuleDraw&) const {
        return relative;
    }
    // A deferred crossing's velocity once the step is over (v in the lab frame, the wall's velocity u).
    virtual Eigen::Vector3d completed(const Eigen::Vector3d& v, const Eigen::Vector3d&) const { return v; }
};

}  // namespace dpd
