#pragma once
// A planar wall: the solid is the half-space behind the plane, the normal points into the fluid.
// Fluid particles that end a step behind the plane are put back by mirroring their position across
// it, and their velocity, taken relative to the wall's, is changed by the wall's reflection rule
// (METHODS.md section 3.3).
#include <Eigen/Core>
#include <string>

namespace dpd {

enum class ReflectionRule {
    none,        // no reflection: the wall's frozen particles alone must keep the fluid out
    specular,    // reverse the normal component (a perfectly slipping wall)
    bounceBack,  // reverse the whole relative velocity (no slip)
    maxwellian,  // diffuse: a new velocity drawn at the wall temperature, leaving the wall
};

ReflectionRule reflectionRuleFromName(const std::string& name);  // throws std::invalid_argument
std::string reflectionRuleName(ReflectionRule rule);

struct PlanarWall {
    std::string name;
    Eigen::Vector3d point{0, 0, 0};
    Eigen::Vector3d normal{0, 0, 1};  // unit vector into the fluid
    Eigen::Vector3d velocity{0, 0, 0};
    ReflectionRule rule = ReflectionRule::bounceBack;

    // Positive on the fluid side, negative inside the solid.
    double signedDistance(double x, double y, double z) const {
        return (x - point.x()) * normal.x() + (y - point.y()) * normal.y() + (z - point.z()) * normal.z();
    }
    // The axis the normal lies along, or -1 if the wall is oblique.
    int normalAxis() const;
};

}  // namespace dpd
