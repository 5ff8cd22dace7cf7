#pragma once
// `type reversePoiseuille; value (g 0 0); gradientAxis z;`: +g in the lower half of the periodic box
// along gradientAxis, -g in the upper half, so that two opposite Poiseuille flows measure the viscosity
// without walls (docs/analysis.md section 5).
#include "forces/BodyForce.hpp"

namespace dpd {

class ReversePoiseuilleBodyForce : public BodyForce {
public:
    // g must be perpendicular to the gradient axis.
    ReversePoiseuilleBodyForce(const Eigen::Vector3d& g, int gradientAxis);
    static std::unique_ptr<BodyForce> New(const Dictionary& dict, int dimension);
    std::string typeName() const override { return "reversePoiseuille"; }
    Eigen::Vector3d value() const override { return g_; }
    int gradientAxis() const override { return axis_; }
    void apply(Particles& p, const std::vector<std::uint8_t>& frozenOfSpecies, const Box& box) const override;

private:
    Eigen::Vector3d g_;
    int axis_;
};

}  // namespace dpd
