#pragma once
// Rule bounceLayer (docs/walls.md 3.2 steps 5-6): a layer of thickness alpha r_c in front of the surface
// turns approaching particles round (tangential velocity reversed, a normal speed the wall emits);
// a particle that still crosses the surface is a failure of the layer, returned the same way and counted.
#include "walls/WallRule.hpp"
#include "walls/WallVelocityRules.hpp"

namespace dpd {

class BounceLayerRule : public WallRule {
public:
    explicit BounceLayerRule(double layer);

    std::string description() const override;
    double layer() const override { return layer_; }
    Eigen::Vector3d atSurface(const Eigen::Vector3d& v, const Eigen::Vector3d& n, const RuleDraw& d) const override {
        return turnedRound(n, v, d.random, d.step, d.id, d.kT, d.stream);
    }
    Eigen::Vector3d inLayer(const Eigen::Vector3d& v, const Eigen::Vector3d& n, const RuleDraw& d) const override {
        return turnedRound(n, v, d.random, d.step, d.id, d.kT, d.stream);
    }

private:
    double layer_;  // alpha x cutoff
};

}  // namespace dpd
