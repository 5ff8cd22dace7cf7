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
    std::vector<long> reflected;  // per wall, particles returned to the fluid in the last call
    long insideAfter = 0;         // particles still behind some wall after the reflections
};

class WallSet {
public:
    void add(const PlanarWall& w) { walls_.push_back(w); }
    bool empty() const { return walls_.empty(); }
    std::size_t size() const { return walls_.size(); }
    const PlanarWall& operator[](std::size_t i) const { return walls_[i]; }
    const std::vector<PlanarWall>& walls() const { return walls_; }

    // The name of the first wall whose solid, within the periodic box, is less than `depth` thick
    // (fluid on one side would then feel the fluid on the other side through the wall); empty if
    // every wall is thick enough.
    std::string thinWall(const Box& box, double depth) const;
    // True if the point is behind any wall (inside the solid).
    bool isInsideSolid(double x, double y, double z) const;
    // Reflect every mobile particle found behind a wall. Random draws are keyed by (seed, step, id),
    // so the outcome does not depend on the thread count.
    WallCounters reflect(Particles& p, const std::vector<std::uint8_t>& frozenOfSpecies, const Box& box,
                         const PairRandom& random, std::uint64_t step, double kT) const;

private:
    std::vector<PlanarWall> walls_;
};

}  // namespace dpd
