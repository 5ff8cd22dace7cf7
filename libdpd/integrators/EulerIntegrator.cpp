#include "integrators/EulerIntegrator.hpp"

#include "integrators/StepParts.hpp"
#include "system/System.hpp"

namespace dpd {

std::unique_ptr<Integrator> EulerIntegrator::New(const Dictionary& coeffs) {
    coeffs.checkKeys({"type"});
    return std::make_unique<EulerIntegrator>();
}

WallCounters EulerIntegrator::step(System& sys) {
    drift(sys);            // positions with the old velocities,
    kick(sys, sys.dt());   // velocities with the old forces
    const WallCounters walls = sys.afterMove(SortForces::Leave);  // the forces are computed anew
    sys.computeForces();
    sys.endStep();
    return walls;
}

}  // namespace dpd
