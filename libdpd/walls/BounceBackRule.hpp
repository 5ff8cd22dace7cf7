#pragma once
// Rule bounceBack: the whole velocity relative to the wall reversed (no slip).
#include "walls/WallRule.hpp"

namespace dpd {

class BounceBackRule : public WallRule {
public:
    std::string description() const override { return "bounceBack"; }
    Eigen::Vector3d atSurface(const Eigen::Vector3d& v, const Eigen::Vector3d&, const RuleDraw&) const override { return -v; }
};

}  // namespace dpd
