#pragma once
// The walls of a scene and what they do to the fluid after each move.
#include "core/Box.hpp"
#include "core/Particles.hpp"
#include "random/PairRandom.hpp"
#include "walls/PlanarWall.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace dpd {

struct WallCounters {
    // Per wall: particles the wall's rule turned back into the fluid (for bounceLayer: the particles
    // turned round inside the layer, plus those that crossed the plane all the same).
    std::vector<long> returned;
    // Per wall: particles found behind the plane after the move. For the rules that act at the plane
    // this is how they work; for bounceLayer every one is a failure of the layer (it is too thin for
    // the step), mirrored back and counted here so the log shows it.
    std::vector<long> crossed;
    long insideAfter = 0;  // particles still behind some wall once the walls have acted

    // Adds another step's counts (per wall; the vectors grow to the longer of the two).
    void accumulate(const WallCounters& other);
};

// A bounce-forward crossing whose velocity is reversed once the step is finished (the force at the
// penetrated position is part of "the velocity the particle has there after the step").
struct DeferredBounce {
    std::uint64_t id = 0;
    std::uint32_t wall = 0;
    double x = 0.0, y = 0.0, z = 0.0;  // the penetrated position mirrored across the plane (unwrapped)
};

class WallSet {
public:
    void add(const PlanarWall& w) { walls_.push_back(w); }
    bool empty() const { return walls_.empty(); }
    std::size_t size() const { return walls_.size(); }
    const PlanarWall& operator[](std::size_t i) const { return walls_[i]; }
    const std::vector<PlanarWall>& walls() const { return walls_; }
    bool anyRule(ReflectionRule rule) const;
    bool anyTunableSlip() const;

    // Adds the forces of the tunable-slip walls to the mobile particles in front of them
    // (walls/TunableSlipWall.hpp); call after the pair forces. Walls without tunable slip add nothing.
    void addTunableSlipForces(Particles& p, const std::vector<std::uint8_t>& frozenOfSpecies, const Box& box,
                              const PairRandom& random, std::uint64_t step, double kT, double dt) const;

    // The name of the first wall whose solid, within the periodic box, is less than `depth` thick
    // (fluid on one side would then feel the fluid on the other side through the wall); empty if
    // every wall is thick enough.
    std::string thinWall(const Box& box, double depth) const;
    // True if the point is behind any wall (inside the solid).
    bool isInsideSolid(double x, double y, double z) const;
    // The wall a point behind the walls belongs to: the one whose plane is nearest among those it is
    // behind; -1 when it is behind none.
    int owningWall(double x, double y, double z) const;
    // Every frozen particle behind a wall takes that wall's velocity (owningWall), so the frozen
    // particles of a moving wall move with it; frozen particles behind no wall keep theirs. Returns
    // how many frozen particles each wall owns.
    std::vector<long> assignFrozenVelocities(Particles& p, const std::vector<std::uint8_t>& frozenOfSpecies) const;

    // Applies every wall's rule to the mobile particles after a move (before positions wrap).
    // Random draws are keyed by (seed, step, id), so the outcome does not depend on the thread count.
    // Bounce-forward crossings are listed in `deferred` (sorted by id) for completeBounceForward.
    WallCounters reflect(Particles& p, const std::vector<std::uint8_t>& frozenOfSpecies, const Box& box,
                         const PairRandom& random, std::uint64_t step, double kT,
                         std::vector<DeferredBounce>& deferred) const;
    // Finishes the deferred bounce-forward crossings once the velocities of the step are complete:
    // the particle goes to its mirrored position and its velocity relative to the wall is reversed.
    void completeBounceForward(Particles& p, const Box& box, const std::vector<DeferredBounce>& deferred) const;

private:
    std::vector<PlanarWall> walls_;
};

}  // namespace dpd
