#pragma once
// A wall (docs/walls.md 3): a shape (where its solid is: walls/WallShape.hpp) and a reflection rule
// (what it does to the fluid that crosses or approaches the surface: walls/WallRule.hpp), joined here
// once for every shape and rule; optionally a force its surface exerts (walls/SurfaceForce.hpp) and a
// velocity it slides at, carrying its frozen particles. WallList runs the walls of a scene in order.
#include "core/Capabilities.hpp"
#include "walls/SurfaceForce.hpp"
#include "walls/WallRule.hpp"
#include "walls/WallShape.hpp"
#include "walls/WallStep.hpp"

#include <memory>
#include <optional>
#include <string>

namespace dpd {

class Wall {
public:
    Wall(std::string name, std::shared_ptr<WallShape> shape, std::shared_ptr<const WallRule> rule);

    // A wall that slides at `velocity` (in its own surface) and carries the frozen particles inside it.
    Wall& sliding(const Eigen::Vector3d& velocity);
    Wall& withForce(std::shared_ptr<const SurfaceForce> force);
    // The slip length b the wall asked for (`slipLength b;`, docs/walls.md 3.8), measured from where
    // the user put it; its friction and acting surface were chosen for it. Its continuum twin takes b.
    Wall& askingSlipLength(double b);

    const std::string& name() const { return name_; }
    const WallShape& shape() const { return *shape_; }
    const WallRule& rule() const { return *rule_; }
    // The log's account of the wall: its rule, force, shape and velocity, after "name: ".
    std::string description() const;
    // Positive in the fluid, negative inside the solid.
    double signedDistance(const Eigen::Vector3d& r) const { return shape_->signedDistance(r); }
    bool isInsideSolid(const Eigen::Vector3d& r) const { return signedDistance(r) < 0.0; }
    // Why the wall cannot stand in this box (empty when it can): checked when a run is built.
    std::string unfitFor(const Box& box) const { return force_ ? force_->unfitFor(box) : std::string(); }
    // Marks the axes along which the wall makes the mean flow vary (the run monitor's local flow).
    void markFlowAxes(const Box& box, std::array<bool, 3>& varies) const;

    bool carriesFrozenParticles() const { return carries_; }
    const std::optional<double>& askedSlipLength() const { return askedSlipLength_; }
    const Eigen::Vector3d& velocity() const { return velocity_; }

    // Whether the wall acts on the fluid with forces; those forces may depend on the velocities.
    bool actsWithForces() const { return force_ != nullptr; }
    const SurfaceForce* surfaceForce() const { return force_.get(); }
    // Its force reads the velocities; a bounce-forward crossing along x moves a particle after the sort.
    Capabilities capabilities() const;
    // Adds the wall's forces to the mobile particles (after the pair forces).
    void addForces(WallStep& s) const;

    // Before the first step and after every completed step (positions wrapped).
    void recordPositions(const Particles& p, const std::vector<std::uint8_t>& frozenOfSpecies) {
        shape_->recordPositions(p, frozenOfSpecies);
    }
    // After a move, before positions wrap: returns the particles that crossed into the solid and turns
    // round those the rule's layer catches. index: the wall's place in its list.
    WallCount reflect(WallStep& s, std::uint32_t index) const;
    // Completes a crossing this wall deferred (particle i), once the step's velocities are final.
    void completeCrossing(Particles& p, std::size_t i, const DeferredCrossing& d, const Box& box) const;
    // A wall whose shape is built on the run's box, copied with that shape; null when it needs none.
    std::shared_ptr<Wall> builtOn(const ShapeBuildContext& c) const;
    // A copy with its shape's own record of the run (WallShape::ownCopy); null when the shape keeps none.
    std::shared_ptr<Wall> ownCopy() const;

private:
    // This wall with another shape; null for a null shape.
    std::shared_ptr<Wall> withShape(std::shared_ptr<WallShape> shape) const;
    // Applies the rule to mobile particle i; adds to the counts.
    void reflectParticle(WallStep& s, std::uint32_t index, std::size_t i, WallCount& counts) const;

    std::string name_;
    std::shared_ptr<WallShape> shape_;
    std::shared_ptr<const WallRule> rule_;
    std::shared_ptr<const SurfaceForce> force_;
    // The rule's and shape's constants, read once (the reflection asks them for every particle).
    double layer_;
    bool returns_;
    bool defers_;
    std::uint32_t stream_;
    Eigen::Vector3d velocity_{0, 0, 0};
    bool carries_ = false;
    std::optional<double> askedSlipLength_;
};

}  // namespace dpd
