#pragma once
// A solid of any shape (the `geometry` wall type; docs/walls.md 3.2 steps 5-6): the case's geometry
// block seen through its signed distance field (distance > 0 in the fluid, normal into the fluid),
// built on the run's box. A particle whose path entered the solid goes back to its mirror image across
// the surface where it entered.
//
// The path of each step (from where the particle stood at the start of the step to where it ends)
// is probed at intervals of half a grid cell, so a solid feature the field resolves (at least two
// grid cells thick, e.g. one pixel with gridSpacing half the pixel size) stops a particle even when
// the particle would have stepped right over it. The mirror plane is the surface's tangent plane on
// the side the particle came from, so a particle past the middle of a thin feature still goes back
// the way it came instead of out through the far side.
//
// A surface offset moves the surface that acts that far into the solid (the field's distance plus the
// offset): a wall asking for a slip length puts its friction layer's surface behind the geometry's
// (docs/walls.md 3.9), as a planar wall moves its plane.
#include "geometry/DistanceClearance.hpp"
#include "geometry/SignedDistanceField.hpp"
#include "walls/WallShape.hpp"

#include <memory>

namespace dpd {

class Dictionary;

class GeometryShape : public WallShape {
public:
    // The solid of this field, its surface moved `surfaceOffset` into the solid.
    explicit GeometryShape(SignedDistanceField field, double surfaceOffset = 0.0);
    // The solid of a geometry block, to be built on the run's box (builtOn).
    explicit GeometryShape(std::shared_ptr<const Dictionary> geometryDict, double surfaceOffset = 0.0);

    const SignedDistanceField& field() const;
    std::string description() const override;
    // How far behind the geometry's surface the acting surface lies (0: on it).
    double surfaceOffset() const { return offset_; }
    double signedDistance(const Eigen::Vector3d& r) const override { return field().distance(r) + offset_; }
    SurfaceDistance surfaceAt(const Eigen::Vector3d& r) const override { return shifted(field().at(r)); }
    // A particle is near unless it is frozen, or its step's start is known, the step is short and the
    // clearance of its path exceeds the reach: one lookup in a small table for most particles.
    void markWithin(const Particles& p, long begin, long end, double reach, const std::vector<std::uint8_t>& frozenOfSpecies,
                    std::uint8_t* near) const override;
    // The path probed by distance alone; the normals looked up only where the step entered the solid
    // or ends within normalWithin.
    ShapeCrossing crossing(const Particles& p, std::size_t i, const Box& box, double normalWithin,
                           SurfaceDistance& atEnd) const override;
    // Remembers where every particle stands, in the particles' order, read straight through by the
    // next step's reflections (System records again after any reorder outside a step). A particle
    // whose id differs there has no known start: its path is taken to be its end point.
    void recordPositions(const Particles& p, const std::vector<std::uint8_t>& frozenOfSpecies) override;
    // The flow may vary along every active axis the field resolves.
    void markFlowAxes(const Box& box, std::array<bool, 3>& varies) const override;
    std::uint32_t reflectionStream() const override;
    std::shared_ptr<WallShape> builtOn(const ShapeBuildContext& c) const override;
    // A copy with its own record of the starts (the field and the clearances shared).
    std::shared_ptr<WallShape> ownCopy() const override;

private:
    struct Entry {
        bool found = false;
        Eigen::Vector3d fluidPoint{0, 0, 0};  // last probe on the path still in the fluid
        SurfaceDistance atFluidPoint;         // (with its normal only where the path entered)
        Eigen::Vector3d lastProbe{0, 0, 0};   // the path's end as probed
        double distanceAtEnd = 0.0;           // there (where the path did not enter before it)
    };
    SurfaceDistance shifted(SurfaceDistance s) const {
        s.distance += offset_;
        return s;
    }
    // Where the path from `from` by `delta` first enters the solid, if it does.
    Entry findEntry(const Eigen::Vector3d& from, const Eigen::Vector3d& delta) const;
    // Whether the ordered copy holds particle i's start.
    bool startInOrder(const Particles& p, std::size_t i) const { return i < startId_.size() && startId_[i] == p.id[i]; }
    // Where a particle whose path entered the solid at `entry` and ended at `end` goes back.
    Eigen::Vector3d returnPoint(const Entry& entry, const Eigen::Vector3d& end, const Box& box) const;

    std::shared_ptr<const Dictionary> geometryDict_;  // set while not built on a box
    std::shared_ptr<const SignedDistanceField> field_;
    double offset_ = 0.0;           // the acting surface this far into the solid
    double probeSpacing_ = 0.0;     // half the smallest varying grid cell
    std::shared_ptr<const DistanceClearance> clearance_;
    std::vector<double> startX_, startY_, startZ_;  // the start of the current step, per particle
    std::vector<std::uint64_t> startId_;            // and whose it is
};

}  // namespace dpd
