#pragma once
// The velocity a wall gives a particle it returns, for a wall at rest locally with unit normal n
// into the fluid (docs/walls.md 3.2-3.3). Velocities are relative to the wall. Used by the rules
// (walls/*Rule.hpp), whatever the shape of the wall: the shape only says where n comes from.
// Random draws are keyed by (step, particle id, stream), so they do not depend on the thread count;
// `stream` keeps the draws of different kinds of wall apart.
#include "core/Box.hpp"
#include "random/PairRandom.hpp"

#include <Eigen/Core>
#include <cstdint>

namespace dpd {

// The speed, along the normal, of a particle a wall at temperature kT emits: flux-weighted
// (Rayleigh) p(v) = v/kT exp(-v^2 / 2kT), drawn by inverting its distribution function.
double emittedNormalSpeed(const PairRandom& random, std::uint64_t step, std::uint64_t id, double kT,
                          std::uint32_t stream);

// Maxwellian (diffuse) wall: tangential components Gaussian at the wall temperature, the normal one
// what the wall emits.
Eigen::Vector3d diffuseVelocity(const Eigen::Vector3d& normal, const Box& box, const PairRandom& random,
                                std::uint64_t step, std::uint64_t id, double kT, std::uint32_t stream);

// Bounce layer (docs/walls.md 3.2 step 6): the tangential velocity is reversed and the normal one is
// replaced by a speed the wall emits at its temperature, pointing into the fluid.
Eigen::Vector3d turnedRound(const Eigen::Vector3d& normal, const Eigen::Vector3d& relative, const PairRandom& random,
                            std::uint64_t step, std::uint64_t id, double kT, std::uint32_t stream);

}  // namespace dpd
