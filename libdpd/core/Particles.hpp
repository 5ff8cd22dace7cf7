#pragma once
// Particles as a structure of arrays: each component is contiguous, so the pair loop and the
// integrators stream through memory and the compiler can vectorise them.
#include "core/HugePageAllocator.hpp"

#include <cstdint>
#include <vector>

namespace dpd {

struct Particles {
    ParticleArray<double> rx, ry, rz;  // positions
    ParticleArray<double> vx, vy, vz;  // velocities
    ParticleArray<double> fx, fy, fz;  // forces (per unit mass: all masses are 1)
    ParticleArray<std::uint64_t> id;   // permanent identity: keys the random numbers, survives sorting
    ParticleArray<std::uint8_t> species;

    std::size_t size() const { return id.size(); }
    // The positions along one axis (0 x, 1 y, 2 z).
    const ParticleArray<double>& position(int axis) const { return axis == 0 ? rx : (axis == 1 ? ry : rz); }
    void resize(std::size_t n);
    void reserve(std::size_t n);
    void add(std::uint64_t particleId, int speciesIndex, double x, double y, double z,
             double ux = 0.0, double uy = 0.0, double uz = 0.0);
    // Appends the other's particles after these.
    void append(const Particles& other);
    // Keeps the first n particles; with keepForces the force arrays keep their length.
    void shorten(std::size_t n, bool keepForces);
    // A copy with particles [first, size) then [0, first).
    Particles rotated(std::size_t first) const;
    // Reorder every array so that new index k holds the particle that was at order[k].
    void permute(const std::vector<std::uint32_t>& order);
    void clearForces();
};

}  // namespace dpd
