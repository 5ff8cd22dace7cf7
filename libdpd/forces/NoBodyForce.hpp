#pragma once
// `type none;`: no body force, and no pass over the particles.
#include "forces/BodyForce.hpp"

namespace dpd {

class NoBodyForce : public BodyForce {
public:
    static std::unique_ptr<BodyForce> New(const Dictionary& dict, int dimension);
    std::string typeName() const override { return "none"; }
    Eigen::Vector3d value() const override { return Eigen::Vector3d::Zero(); }
    void apply(Particles&, const std::vector<std::uint8_t>&, const Box&) const override {}
};

}  // namespace dpd
