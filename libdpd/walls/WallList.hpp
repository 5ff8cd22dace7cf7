#pragma once
// The walls of a scene, in the order they act, and what they do together: the forces they add, the
// particles they return after a move (each wall in turn), the crossings they complete at the end of
// the step, and the frozen particles each one carries.
#include "walls/PlanarWallSettings.hpp"
#include "walls/Wall.hpp"

#include <memory>
#include <string>
#include <vector>

namespace dpd {

struct WallCounters {
    // Per wall (in the list's order): particles the wall's rule turned back into the fluid (for
    // bounceLayer: the particles turned round inside the layer, plus those that crossed all the same).
    std::vector<long> returned;
    // Per wall: particles found in its solid after the move. For the rules that act at the surface
    // this is how they work; for bounceLayer every one is a failure of the layer (too thin for the
    // step), mirrored back and counted here so the log shows it.
    std::vector<long> crossed;
    long insideAfter = 0;  // particles the walls left in their solids

    // Adds another step's counts (per wall; the vectors grow to the longer of the two).
    void accumulate(const WallCounters& other);
};

class WallList {
public:
    WallList() = default;
    // A copy holds its own copy of every wall whose shape keeps a record of the run (Wall::ownCopy)
    // and shares the rest: two systems copied from one step apart.
    WallList(const WallList& other);
    WallList& operator=(const WallList& other);
    WallList(WallList&&) = default;
    WallList& operator=(WallList&&) = default;

    void add(std::shared_ptr<Wall> wall) { walls_.push_back(std::move(wall)); }
    // Adds the planar wall of these settings (makePlanarWall).
    void addPlane(const PlanarWallSettings& settings);
    bool empty() const { return walls_.empty(); }
    std::size_t size() const { return walls_.size(); }
    const Wall& operator[](std::size_t i) const { return *walls_[i]; }
    bool anyActsWithForces() const;

    // True if the point is inside any wall's solid.
    bool isInsideSolid(const Eigen::Vector3d& r) const;
    // The name of the first of these planes whose solid (of all the walls), within the periodic box, is
    // less than `depth` thick (fluid on one side would then feel the fluid on the other through the
    // wall), or which lies on a face of the box; empty if none.
    std::string thinWall(const std::vector<const PlanarWallSettings*>& planes, const Box& box, double depth) const;
    // Every frozen particle inside a wall that carries frozen particles takes that wall's velocity:
    // the wall whose surface is nearest among those the particle is inside. Returns how many frozen
    // particles each wall carries.
    std::vector<long> assignFrozenVelocities(Particles& p, const std::vector<std::uint8_t>& frozenOfSpecies) const;

    // The list with every wall whose shape is built on the run's box (a geometry) built on it; the
    // other walls shared.
    WallList builtOn(const ShapeBuildContext& c) const;

    void recordPositions(const Particles& p, const std::vector<std::uint8_t>& frozenOfSpecies);
    void addForces(WallStep& s) const;
    // Each wall in turn returns the particles that crossed into it; deferred crossings are kept for
    // completeStep, sorted by particle id.
    WallCounters reflect(WallStep& s) const;
    // Completes the deferred crossings once the step's velocities are final, then lets the walls
    // record the positions the next step starts from.
    void completeStep(Particles& p, const std::vector<std::uint8_t>& frozenOfSpecies, const Box& box,
                      std::vector<DeferredCrossing>& deferred);

private:
    std::vector<std::shared_ptr<Wall>> walls_;
};

}  // namespace dpd
