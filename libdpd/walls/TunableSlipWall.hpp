#pragma once
// A planar wall with the tunable-slip forces of Smiatek et al. (walls/TunableSlipParameters.hpp,
// docs/walls.md 3.5) on the fluid in front of it; its reflection rule stays as a safety net behind
// the WCA repulsion.
#include "walls/PlanarWall.hpp"

namespace dpd {

class TunableSlipWall : public PlanarWall {
public:
    // index: the wall's place in its list, which keeps its random stream apart from other walls'.
    TunableSlipWall(PlanarWallSettings settings, std::size_t index);

    bool actsWithForces() const override { return true; }
    // Adds the wall's force to every mobile particle in front of it, within its reach (max of z_c and
    // the WCA range). Particles behind the plane feel nothing: the reflection rule returns them.
    void addForces(WallStep& s) const override;

protected:
    // The friction gamma_L in front of the wall at a point (the same everywhere on a plain wall).
    virtual double frictionAt(double /*x*/, double /*y*/, double /*z*/) const { return settings().tunableSlip.gammaL; }

private:
    std::uint32_t stream_;
};

}  // namespace dpd
