#pragma once
// Initial positions and velocities: fluid filling a region at a density, Maxwellian velocities.
// Draws are keyed by (seed, particle id), so a case built twice with the same seed is identical.
#include "core/Box.hpp"
#include "core/Particles.hpp"
#include "random/PairRandom.hpp"

#include <cstdint>
#include <functional>

namespace dpd {

// Accepts a point if it belongs to the region being filled.
using RegionTest = std::function<bool(double x, double y, double z)>;

// Places particles uniformly at random in the part of [lo, hi] (a sub-box of `box`) where `inside`
// holds, at `density` per volume (per area in 2-D), with ids from firstId on. The count is
// density x (accepted volume), estimated by rejection and rounded, so the density comes out exact
// to within one particle. Returns the number added.
std::size_t fillRandom(Particles& p, const Box& box, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                       double density, int species, const RegionTest& inside, const PairRandom& random,
                       std::uint64_t firstId);

// Maxwell-Boltzmann velocities at kT (unit mass) for particles [begin, end), then the mean of that
// range removed and the rest rescaled so that its kinetic temperature is exactly kT.
void maxwellVelocities(Particles& p, std::size_t begin, std::size_t end, int dimension, double kT,
                       const PairRandom& random);

}  // namespace dpd
