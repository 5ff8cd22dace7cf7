#pragma once
// A wall of any shape (docs/walls.md 3.2 steps 5-6): the solid of the case's `geometry` block, seen
// through its signed distance field (distance > 0 in the fluid, normal into the fluid). After each
// move a fluid particle whose path entered the solid is put back by mirroring it across the surface
// where it entered, and its velocity (relative to the resting wall) is changed by the wall's rule --
// the same rules as planar walls, with the normal from the field. With bounceLayer, particles within
// alpha r_c of the surface moving towards it are turned round first; those that still get in are
// mirrored back and counted as failures of the layer.
//
// The path of each step (from where the particle stood at the start of the step to where it ends)
// is probed at intervals of half a grid cell, so a solid feature the field resolves (at least two
// grid cells thick, e.g. one pixel with gridSpacing half the pixel size) stops a particle even when
// the particle would have stepped right over it. The mirror plane is the surface's tangent plane on
// the side the particle came from, so a particle past the middle of a thin feature still goes back
// the way it came instead of out through the far side.
#include "geometry/SignedDistanceField.hpp"
#include "walls/ReflectionRule.hpp"
#include "walls/Wall.hpp"

#include <cstdint>
#include <vector>

namespace dpd {

class GeometryWall : public Wall {
public:
    // rule: any reflection rule but bounceForward; layer: the bounce layer's thickness (bounceLayer).
    GeometryWall(SignedDistanceField field, ReflectionRule rule, double layer);

    ReflectionRule rule() const { return rule_; }
    double layer() const { return layer_; }
    const SignedDistanceField& field() const { return field_; }
    std::string description() const override;
    double signedDistance(const Eigen::Vector3d& r) const override { return field_.distance(r); }
    // The flow may vary along every active axis the field resolves.
    void markFlowAxes(const Box& box, std::array<bool, 3>& varies) const override;

    // Remembers where every mobile particle stands (by id): the start of the next step's path.
    void recordPositions(const Particles& p, const std::vector<std::uint8_t>& frozenOfSpecies) override;
    // Applies the rule to the mobile particles whose path entered the solid.
    WallCount reflect(WallStep& s, std::uint32_t index) const override;

private:
    struct Entry {
        bool found = false;
        Eigen::Vector3d fluidPoint{0, 0, 0};  // last probe on the path still in the fluid
        SurfaceDistance atFluidPoint;
    };
    // Where the path from `from` by `delta` first enters the solid, if it does.
    Entry findEntry(const Eigen::Vector3d& from, const Eigen::Vector3d& delta, SurfaceDistance& atEnd) const;
    // Puts one particle that entered the solid back and changes its velocity; true if it is out.
    bool returnParticle(Particles& p, std::size_t i, const Entry& entry, const Eigen::Vector3d& end, const Box& box,
                        const PairRandom& random, std::uint64_t step, double kT) const;

    SignedDistanceField field_;
    ReflectionRule rule_;
    double layer_;
    double probeSpacing_;            // half the smallest varying grid cell
    std::vector<double> previous_;   // 3 per particle id: the start of the current step
};

}  // namespace dpd
