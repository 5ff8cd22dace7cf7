#pragma once
// Rule none: the wall returns nothing; its frozen particles alone must keep the fluid out, and the
// particles found in its solid are counted.
#include "walls/WallRule.hpp"

namespace dpd {

class NoReflectionRule : public WallRule {
public:
    std::string description() const override { return "none"; }
    bool returnsFluid() const override { return false; }
    Eigen::Vector3d atSurface(const Eigen::Vector3d& v, const Eigen::Vector3d&, const RuleDraw&) const override { return v; }
};

}  // namespace dpd
