#pragma once
// A planar wall (docs/walls.md 3.3): the solid is the half-space behind the plane. Fluid particles that
// end a step behind it are mirrored back across the plane, and their velocity, taken relative to the
// wall's, is changed by the wall's reflection rule; with bounceLayer, particles in the layer in front
// of the plane moving towards it are turned round first. A sliding wall carries its frozen particles.
#include "walls/PlanarWallSettings.hpp"
#include "walls/Wall.hpp"

#include <memory>

namespace dpd {

class Dictionary;
struct WallReadContext;

class PlanarWall : public Wall {
public:
    explicit PlanarWall(PlanarWallSettings settings);
    // `type plane;` (walls/PlanarWallDictionary.cpp): point, normal, velocity, reflection, alpha, and
    // with a tunableSlip block a TunableSlipWall.
    static std::unique_ptr<Wall> New(const Dictionary& dict, const WallReadContext& context);

    const PlanarWallSettings& settings() const { return settings_; }
    std::string description() const override;
    double signedDistance(const Eigen::Vector3d& r) const override { return settings_.signedDistance(r.x(), r.y(), r.z()); }
    const PlanarWallSettings* plane() const override { return &settings_; }
    void markFlowAxes(const Box& box, std::array<bool, 3>& varies) const override;
    bool carriesFrozenParticles() const override { return true; }
    Eigen::Vector3d velocity() const override { return settings_.velocity; }
    WallCount reflect(WallStep& s, std::uint32_t index) const override;
    void completeCrossing(Particles& p, std::size_t i, const DeferredCrossing& d, const Box& box) const override;

private:
    PlanarWallSettings settings_;
};

// A planar wall of these settings: a TunableSlipWall when they have tunable slip. index: its place in
// the list of walls.
std::unique_ptr<Wall> makePlanarWall(PlanarWallSettings settings, std::size_t index);

}  // namespace dpd
