#pragma once
// Where a wall's solid is (docs/walls.md 3.3): the surface, its normal into the fluid, and how a
// particle's step is found to have entered the solid and where it goes back. A shape knows nothing of
// what the wall does to the particle (walls/WallRule.hpp); Wall joins the two.
#include "core/Box.hpp"
#include "core/Particles.hpp"
#include "geometry/SolidGeometry.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace dpd {

// A step that entered the solid, and the point it is returned to.
struct ShapeCrossing {
    bool found = false;
    Eigen::Vector3d back{0, 0, 0};    // the returned position (not wrapped)
    Eigen::Vector3d normal{0, 0, 0};  // the surface's normal there (zero where the shape could not tell)
};

// What a shape that is built on the run's box (a geometry's distance field) needs.
struct ShapeBuildContext {
    const Box& box;
    std::string caseDir;  // a geometry's files are relative to it
    double cutoff;
};

class WallShape {
public:
    virtual ~WallShape() = default;

    // The shape's part of the log's account of the wall (empty: nothing to add).
    virtual std::string description() const { return {}; }
    // Positive in the fluid, negative inside the solid.
    virtual double signedDistance(const Eigen::Vector3d& r) const = 0;
    // The distance and the unit normal into the fluid (a zero normal where the shape cannot tell).
    virtual SurfaceDistance surfaceAt(const Eigen::Vector3d& r) const = 0;
    // For particles begin..end, whether each may lie less than `reach` in front of the surface or
    // behind it, or have stepped through such a place (near[i - begin]): passes over the particles
    // look one by one only at those. A shape may mark the particles of frozen species
    // (frozenOfSpecies[s] != 0) as not near without looking: no pass acts on them.
    virtual void markWithin(const Particles&, long begin, long end, double /*reach*/,
                            const std::vector<std::uint8_t>& /*frozenOfSpecies*/, std::uint8_t* near) const {
        std::fill(near, near + (end - begin), std::uint8_t{1});
    }
    // Whether particle i's step (ending where it stands) entered the solid, and where it goes back.
    // Where it did not, atEnd receives the surface distance where the step ends, with the normal there
    // where that distance is below normalWithin (a shape whose normal costs a lookup leaves it zero beyond).
    virtual ShapeCrossing crossing(const Particles& p, std::size_t i, const Box& box, double normalWithin,
                                   SurfaceDistance& atEnd) const = 0;
    // Whether returning a particle can move it along the axis (a plane: only along its normal).
    virtual bool returnsAlong(int /*axis*/) const { return true; }
    // The position a returned particle is put at (a plane wraps its mirror image into the box at once).
    virtual Eigen::Vector3d placed(const Eigen::Vector3d& back, const Box&) const { return back; }
    // Before the first step, after every completed step and whenever the particles are reordered
    // outside a step: a shape that follows particles' paths remembers where they stand, in their
    // order, the start of the next step's path.
    virtual void recordPositions(const Particles&, const std::vector<std::uint8_t>& /*frozenOfSpecies*/) {}
    // Marks the axes along which the shape makes the mean flow vary (the run monitor's local flow).
    virtual void markFlowAxes(const Box& box, std::array<bool, 3>& varies) const = 0;
    // The random stream of the reflections at this shape (PairRandom.hpp's RandomStream).
    virtual std::uint32_t reflectionStream() const = 0;
    // A shape built on the run's box (a geometry's field) is a copy made here; null for a shape that
    // needs no box.
    virtual std::shared_ptr<WallShape> builtOn(const ShapeBuildContext&) const { return nullptr; }
    // A shape that keeps a record of the run (where the particles stood) gives every wall list that
    // holds it a copy of its own, so that two systems copied from one never share a record; null for
    // a shape with nothing of the run in it.
    virtual std::shared_ptr<WallShape> ownCopy() const { return nullptr; }
};

}  // namespace dpd
