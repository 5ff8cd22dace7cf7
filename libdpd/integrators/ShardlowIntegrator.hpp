#pragma once
// Shardlow's S1 splitting (T. Shardlow, SIAM J. Sci. Comput. 24, 1267, 2003; tested for DPD by
// Nikunen, Karttunen and Vattulainen, Comput. Phys. Commun. 153, 407, 2003). Each step:
//   1. the dissipative and random forces, pair after pair, over dt at the current positions, each
//      pair's update solved exactly (integrators/ShardlowSweep.hpp);
//   2. the conservative and body forces by velocity Verlet: v += dt f^C / 2, r += dt v, new f^C,
//      v += dt f^C / 2.
// The stiff dissipative part is then integrated exactly whatever gamma dt is, which keeps kT right at
// steps where the force-based schemes drift; the conservative part limits the step.
//
// The forces of this scheme are the conservative and body forces alone: those are what it leaves in
// the particles at the end of a step. When a step starts on forces it did not leave (the first step
// after the full DPD forces of System::computeForces), it computes the conservative forces first.
#include "integrators/Integrator.hpp"

#include <cstdint>

namespace dpd {

class ShardlowIntegrator : public Integrator {
public:
    // No coefficients.
    static std::unique_ptr<Integrator> New(const Dictionary& coeffs);
    std::string name() const override { return "Shardlow"; }
    // Its sweep goes pair after pair through the whole box, and has no place yet for a force besides
    // the pair force that reads the velocities (the tunable-slip wall's friction, the bonded pairs').
    Capabilities capabilities() const override;
    WallCounters step(System& sys) override;

private:
    std::int64_t forcesStep_ = -1;  // the step whose conservative forces the particles hold
};

}  // namespace dpd
