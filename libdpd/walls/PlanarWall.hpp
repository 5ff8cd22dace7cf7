#pragma once
// A planar wall: the solid is the half-space behind the plane, the normal points into the fluid.
// Fluid particles that end a step behind the plane are put back by mirroring their position across
// it, and their velocity, taken relative to the wall's, is changed by the wall's reflection rule
// (docs/walls.md section 3.3).
//
// A moving wall slides in its own plane (its velocity has no normal component), so the plane maps
// onto itself and only the wall's frozen particles move: they carry the wall's velocity
// (WallSet::assignFrozenVelocities) and drift with it like any particle.
#include "walls/ReflectionRule.hpp"
#include "walls/TunableSlipWall.hpp"

#include <Eigen/Core>
#include <string>

namespace dpd {


struct PlanarWall {
    std::string name;
    Eigen::Vector3d point{0, 0, 0};
    Eigen::Vector3d normal{0, 0, 1};  // unit vector into the fluid
    Eigen::Vector3d velocity{0, 0, 0};
    ReflectionRule rule = ReflectionRule::bounceBack;
    double layer = 0.0;  // bounceLayer: thickness of the layer in front of the plane (alpha x cutoff)
    // A smooth tunable-slip wall (Smiatek et al. 2008) acting on the fluid in front of the plane, in
    // place of frozen particles; the reflection rule stays as a safety net behind its WCA repulsion.
    bool hasTunableSlip = false;
    TunableSlipParameters tunableSlip;

    // Positive on the fluid side, negative inside the solid.
    double signedDistance(double x, double y, double z) const {
        return (x - point.x()) * normal.x() + (y - point.y()) * normal.y() + (z - point.z()) * normal.z();
    }
    // The axis the normal lies along, or -1 if the wall is oblique.
    int normalAxis() const;
};

}  // namespace dpd
