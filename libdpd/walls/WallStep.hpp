#pragma once
// What a wall acts on in one step, and what it did: the particles, the step's random streams, the
// crossings it leaves for the end of the step, and its counts.
#include "core/Box.hpp"
#include "core/Particles.hpp"
#include "random/PairRandom.hpp"

#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace dpd {

// A crossing whose last part waits for the end of the step (bounce-forward: the velocity is reversed
// once the step's forces have acted on it); WallList completes it through the wall that recorded it.
struct DeferredCrossing {
    std::uint64_t id = 0;
    std::uint32_t wall = 0;             // the wall's index in its WallList
    double x = 0.0, y = 0.0, z = 0.0;  // the position the particle goes to (unwrapped)
};

// One velocity per particle, in the particles' current order, held apart from them (none: null).
struct VelocityColumns {
    const double* x = nullptr;
    const double* y = nullptr;
    const double* z = nullptr;
};

// What a wall acts on in one step. Random draws are keyed by (seed, step, particle id, stream), so
// nothing a wall does depends on the thread count.
struct WallStep {
    Particles& particles;
    const std::vector<std::uint8_t>& frozenOfSpecies;
    const Box& box;
    const PairRandom& random;
    std::uint64_t step;
    double kT;
    double dt;
    std::vector<DeferredCrossing>& deferred;  // crossings to complete at the end of the step
    // The velocities a wall's friction reads, where the integrator gives others than the particles'
    // (Groot-Warren: the half-kicked v + dt f / 2, not its predictor; docs/walls.md 3.5).
    VelocityColumns friction;

    Eigen::Vector3d frictionVelocity(std::size_t i) const {
        if (friction.x) return {friction.x[i], friction.y[i], friction.z[i]};
        return {particles.vx[i], particles.vy[i], particles.vz[i]};
    }
};

// What one wall did to the fluid in one step.
struct WallCount {
    long returned = 0;    // particles its rule turned back into the fluid
    long crossed = 0;     // particles found in its solid after the move
    long leftInside = 0;  // particles still in its solid once it has acted (not counting deferred ones)
};

}  // namespace dpd
