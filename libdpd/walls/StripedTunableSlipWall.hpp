#pragma once
// A tunable-slip wall with stripes (docs/walls.md 3.6): the friction gamma_L alternates along one axis
// of the wall's plane between the wall's gammaL and the gas sectors' gammaGas, so that the local slip
// length alternates too. Written in the tunableSlip block:
//
//   tunableSlip { gammaL 4; zc 1; epsilon 1; sigma 0.5;
//                 stripes { axis x; period 10; gasFraction 0.5; gammaGas 0.1; offset 0; } }
//
// The stripes run across `axis` (along the other axis of the plane); the box length along `axis` must
// hold a whole number of periods. To drive the flow at an angle to the stripes, turn the body force.
#include "walls/TunableSlipWall.hpp"

namespace dpd {

class StripedTunableSlipWall : public TunableSlipWall {
public:
    StripedTunableSlipWall(PlanarWallSettings settings, std::size_t index);

    std::string description() const override;
    std::string unfitFor(const Box& box) const override;
    // The mean flow also varies across the stripes.
    void markFlowAxes(const Box& box, std::array<bool, 3>& varies) const override;

protected:
    double frictionAt(double x, double y, double z) const override;
};

}  // namespace dpd
