#pragma once
// `type uniform; value (gx gy gz);`: the same force per unit mass everywhere (the pressure gradient
// that drives Poiseuille flow).
#include "forces/BodyForce.hpp"

namespace dpd {

class UniformBodyForce : public BodyForce {
public:
    explicit UniformBodyForce(const Eigen::Vector3d& g) : g_(g) {}
    static std::unique_ptr<BodyForce> New(const Dictionary& dict, int dimension);
    std::string typeName() const override { return "uniform"; }
    Eigen::Vector3d value() const override { return g_; }
    void apply(Particles& p, const std::vector<std::uint8_t>& frozenOfSpecies, const Box& box) const override;

private:
    Eigen::Vector3d g_;
};

}  // namespace dpd
