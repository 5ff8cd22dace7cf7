#pragma once
// Rule bounceForward (modified bounce-forward): the particle goes to its position mirrored across the
// surface, and its velocity is reversed once the step's forces have acted on it -- relative to the wall
// (reverseFrame wall, default) or in the lab frame (reverseFrame lab, a reading of the published rule
// that only a moving wall tells apart; tutorials/channel/slipSensitivity).
#include "walls/WallRule.hpp"

namespace dpd {

class BounceForwardRule : public WallRule {
public:
    explicit BounceForwardRule(bool reverseInLabFrame = false) : lab_(reverseInLabFrame) {}

    std::string description() const override { return "bounceForward"; }
    bool defersCrossing() const override { return true; }
    bool reversesInLabFrame() const { return lab_; }
    Eigen::Vector3d atSurface(const Eigen::Vector3d& v, const Eigen::Vector3d&, const RuleDraw&) const override { return v; }
    Eigen::Vector3d completed(const Eigen::Vector3d& v, const Eigen::Vector3d& wallVelocity) const override {
        const Eigen::Vector3d frame = lab_ ? Eigen::Vector3d::Zero() : wallVelocity;
        return frame - (v - frame);
    }

private:
    bool lab_;
};

}  // namespace dpd
