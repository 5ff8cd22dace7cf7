#pragma once
// Rule maxwellian (diffuse): a new velocity the wall emits at its temperature, leaving the wall.
#include "walls/WallRule.hpp"
#include "walls/WallVelocityRules.hpp"

namespace dpd {

class MaxwellianRule : public WallRule {
public:
    std::string description() const override { return "maxwellian"; }
    Eigen::Vector3d atSurface(const Eigen::Vector3d&, const Eigen::Vector3d& n, const RuleDraw& d) const override {
        return diffuseVelocity(n, d.box, d.random, d.step, d.id, d.kT, d.stream);
    }
};

}  // namespace dpd
