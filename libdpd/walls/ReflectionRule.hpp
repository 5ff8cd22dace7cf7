#pragma once
// What a wall does to a fluid particle that crossed its surface (docs/walls.md 3.3): one rule for
// planar walls and walls of any shape, which differ only in where the surface and its normal are.
#include "core/Box.hpp"
#include "random/PairRandom.hpp"

#include <Eigen/Core>
#include <cstdint>
#include <string>

namespace dpd {

enum class ReflectionRule {
    none,           // no reflection: the wall's frozen particles alone must keep the fluid out
    specular,       // reverse the normal component (a perfectly slipping wall)
    bounceBack,     // reverse the whole relative velocity (no slip)
    maxwellian,     // diffuse: a new velocity drawn at the wall temperature, leaving the wall
    bounceLayer,    // a layer of thickness alpha r_c in front of the surface turns approaching particles
                    // round (docs/walls.md 3.2 steps 5-6); crossings of the surface are failures, counted
    bounceForward,  // modified bounce-forward (planar walls): mirror the penetrated position and reverse
                    // the velocity the particle has there after the step
};

ReflectionRule reflectionRuleFromName(const std::string& name);  // throws std::invalid_argument
std::string reflectionRuleName(ReflectionRule rule);

// The velocity, relative to the wall, that the rule gives a particle returned across a surface of
// unit normal n (into the fluid). none and bounceForward leave it (bounceForward is finished after the
// step). Random draws are keyed by (step, id, stream).
Eigen::Vector3d reflectedVelocity(ReflectionRule rule, const Eigen::Vector3d& relative, const Eigen::Vector3d& normal,
                                  const Box& box, const PairRandom& random, std::uint64_t step, std::uint64_t id,
                                  double kT, std::uint32_t stream);

}  // namespace dpd
