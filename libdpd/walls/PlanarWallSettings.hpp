#pragma once
// What a planar wall is (the `plane` type of constant/dpdProperties' walls): the plane, the normal
// into the fluid, its velocity, its reflection rule and, for a tunable-slip wall, its parameters.
// Post-processing reads channels from it; makePlanarWall (walls/PlanarWallDictionary.hpp) makes the
// Wall that acts on the fluid: a PlaneShape, the rule and, with tunable slip, a TunableSlipLayer.
//
// A moving wall slides in its own plane (its velocity has no normal component), so the plane maps
// onto itself and only the wall's frozen particles move: they carry the wall's velocity
// (WallList::assignFrozenVelocities) and drift with it like any particle.
#include "walls/BounceBackRule.hpp"
#include "walls/TunableSlipParameters.hpp"

#include <Eigen/Core>
#include <memory>
#include <string>

namespace dpd {

struct PlanarWallSettings {
    std::string name;
    Eigen::Vector3d point{0, 0, 0};
    Eigen::Vector3d normal{0, 0, 1};  // unit vector into the fluid
    Eigen::Vector3d velocity{0, 0, 0};
    std::shared_ptr<const WallRule> rule = std::make_shared<BounceBackRule>();
    // A smooth tunable-slip wall (Smiatek et al. 2008) acting on the fluid in front of the plane, in
    // place of frozen particles; the reflection rule stays as a safety net behind its WCA repulsion.
    bool hasTunableSlip = false;
    TunableSlipParameters tunableSlip;
    // Striped: gamma_L of the gas sectors, where it differs from tunableSlip.gammaL (the other sectors).
    bool hasStripes = false;
    TunableSlipStripes stripes;
    // A wall that asks for a slip length (docs/walls.md 3.8): `point` is where the user put the wall,
    // and where the flow sees it (the hydrodynamic wall); the tunable-slip plane that acts lies
    // planeOffset behind it, its gammaL from the calibration.
    bool asksSlipLength = false;
    double slipLength = 0.0;
    double planeOffset = 0.0;

    // Where the plane that acts on the fluid passes: `point`, moved back by planeOffset.
    Eigen::Vector3d actingPoint() const { return point - planeOffset * normal; }
    // From the acting plane: positive on the fluid side, negative inside the solid.
    double signedDistance(double x, double y, double z) const {
        const Eigen::Vector3d p = actingPoint();
        return (x - p.x()) * normal.x() + (y - p.y()) * normal.y() + (z - p.z()) * normal.z();
    }
    // The axis the normal lies along, or -1 if the wall is oblique.
    int normalAxis() const;
};

}  // namespace dpd
