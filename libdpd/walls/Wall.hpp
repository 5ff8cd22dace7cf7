#pragma once
// What every wall does (docs/walls.md section 3): it may act on the fluid in front of it with forces,
// it returns the fluid particles that crossed into its solid after a move, it says which points are
// inside that solid, and it counts what it did. Planar walls, tunable-slip walls and walls of any shape
// (a geometry's distance field) implement it; WallList runs them in order, so a System holds one list.
#include "core/Box.hpp"
#include "core/Particles.hpp"
#include "random/PairRandom.hpp"

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace dpd {

struct PlanarWallSettings;

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

class Wall {
public:
    explicit Wall(std::string name) : name_(std::move(name)) {}
    virtual ~Wall() = default;

    const std::string& name() const { return name_; }
    // The log's account of the wall: its shape, rule and parameters, after "name: ".
    virtual std::string description() const = 0;
    // Positive in the fluid, negative inside the solid (distance to the surface where the wall knows it).
    virtual double signedDistance(const Eigen::Vector3d& r) const = 0;
    bool isInsideSolid(const Eigen::Vector3d& r) const { return signedDistance(r) < 0.0; }
    // The plane of a planar wall (post-processing fits channels between them); null for other shapes.
    virtual const PlanarWallSettings* plane() const { return nullptr; }
    // Why the wall cannot stand in this box (empty when it can), e.g. stripes whose period does not
    // divide the box: checked when a run is built.
    virtual std::string unfitFor(const Box&) const { return {}; }
    // Marks the axes along which the wall makes the mean flow vary (the run monitor's local flow).
    virtual void markFlowAxes(const Box& box, std::array<bool, 3>& varies) const = 0;

    // Frozen particles inside a wall that carries them take its velocity (a sliding wall drags its own).
    virtual bool carriesFrozenParticles() const { return false; }
    virtual Eigen::Vector3d velocity() const { return Eigen::Vector3d::Zero(); }

    // Whether the wall acts on the fluid with forces; those forces may depend on the velocities.
    virtual bool actsWithForces() const { return false; }
    // Adds the wall's forces to the mobile particles (after the pair forces).
    virtual void addForces(WallStep&) const {}

    // Before the first step and after every completed step (positions wrapped): the wall may remember
    // where the particles stand, the start of the next step's path.
    virtual void recordPositions(const Particles&, const std::vector<std::uint8_t>& /*frozenOfSpecies*/) {}
    // After a move, before positions wrap: returns the particles that crossed into the solid.
    virtual WallCount reflect(WallStep& s, std::uint32_t index) const = 0;
    // Completes a crossing this wall deferred (particle i), once the step's velocities are final.
    virtual void completeCrossing(Particles& p, std::size_t i, const DeferredCrossing& d, const Box& box) const;

private:
    std::string name_;
};

}  // namespace dpd
