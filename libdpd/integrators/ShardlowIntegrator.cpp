#include "integrators/ShardlowIntegrator.hpp"

#include "integrators/PartialPairForces.hpp"
#include "integrators/ShardlowSweep.hpp"
#include "integrators/StepParts.hpp"
#include "system/System.hpp"

namespace dpd {

std::unique_ptr<Integrator> ShardlowIntegrator::New(const Dictionary& coeffs) {
    coeffs.checkKeys({"type"});
    return std::make_unique<ShardlowIntegrator>();
}

std::string ShardlowIntegrator::unsupported(const WallList& walls) const {
    // The sweep updates velocities pair by pair; a wall force that depends on them is not in it.
    if (!walls.anyActsWithForces()) return {};
    return "the Shardlow integrator does not support walls that act with forces (tunableSlip) yet: use GrootWarren, DPDVV or Euler";
}

WallCounters ShardlowIntegrator::step(System& sys) {
    if (forcesStep_ != sys.step) computeConservativeForces(sys);
    const double dt = sys.dt();
    shardlowSweep(sys, dt, 0);
    halfKickAndDrift(sys);
    // Its conservative forces are cleared and made again, but not by System::computeForces, the one
    // that takes back forces a sort left behind: they are moved.
    const WallCounters walls = endMove(sys, SortForces::Move);
    computeConservativeForces(sys);
    kick(sys, 0.5 * dt);
    forcesStep_ = sys.step;
    sys.completeWalls();
    return walls;
}

}  // namespace dpd
