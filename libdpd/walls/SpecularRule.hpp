#pragma once
// Rule specular: the normal component reversed, the tangential one kept (a perfectly slipping wall).
#include "walls/WallRule.hpp"

namespace dpd {

class SpecularRule : public WallRule {
public:
    std::string description() const override { return "specular"; }
    Eigen::Vector3d atSurface(const Eigen::Vector3d& v, const Eigen::Vector3d& n, const RuleDraw&) const override {
        return v - 2.0 * v.dot(n) * n;
    }
};

}  // namespace dpd
