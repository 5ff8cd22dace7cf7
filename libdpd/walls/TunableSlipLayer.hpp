#pragma once
// The tunable-slip friction layer of Smiatek et al. (walls/TunableSlipParameters.hpp, docs/walls.md
// 3.5) in front of a wall's surface: friction, its random force and the WCA repulsion. With stripes
// (docs/walls.md 3.6) the friction gamma_L alternates along one axis of the plane between the wall's
// gammaL and the gas sectors' gammaGas.
#include "walls/SurfaceForce.hpp"
#include "walls/TunableSlipParameters.hpp"

#include <cstdint>
#include <optional>

namespace dpd {

class TunableSlipLayer : public SurfaceForce {
public:
    // wallIndex: the wall's place in its list, which keeps its random stream apart from other walls'.
    TunableSlipLayer(const TunableSlipParameters& parameters, std::optional<TunableSlipStripes> stripes,
                     std::size_t wallIndex);

    std::string keyword() const override { return "tunableSlip"; }
    std::string description() const override;
    std::string unfitFor(const Box& box) const override;
    void markFlowAxes(const Box& box, std::array<bool, 3>& varies) const override;
    // sigma: there the WCA repulsion is epsilon, diverging nearer.
    double fluidStartsBeyond() const override { return parameters_.sigma; }
    // Adds the force to every mobile particle in front of the surface within its reach (max of z_c and
    // the WCA range). Particles behind the surface feel nothing: the reflection rule returns them.
    void addForces(WallStep& s, const WallShape& shape, const Eigen::Vector3d& wallVelocity) const override;

private:
    // The friction gamma_L in front of the wall at a point (stripes: gammaGas over the gas sectors).
    double frictionAt(double x, double y, double z) const;

    TunableSlipParameters parameters_;
    std::optional<TunableSlipStripes> stripes_;
    std::uint32_t stream_;
};

}  // namespace dpd
